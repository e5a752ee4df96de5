// The renderer on its own, fed hand-made frames: batched drawing (one path per style), interpolation between
// the two newest frames, and drawing only when something changes.
import { expect } from '@open-wc/testing';
import { SceneRenderer, type DrawView } from '../../src/render/renderer.js';
import { FrameStore } from '../../src/worker/client.js';
import { F, HEADER, POSE, type Topology, type TopologyBody } from '../../src/worker/protocol.js';
import { frames as animationFrames, waitFor } from '../elements/helpers.js';

function frame(seq: number, time: number, running: boolean, xy: number[], bodies: number, poses: number[] = []): Float64Array {
  const n = xy.length / 2;
  const f = new Float64Array(HEADER + 2 * n + POSE * bodies);
  f.set(poses, HEADER + 2 * n);
  f[F.seq] = seq;
  f[F.topology] = 1;
  f[F.time] = time;
  f[F.particles] = n;
  f[F.bodies] = bodies;
  f[F.running] = running ? 1 : 0;
  f.set(xy, HEADER);
  return f;
}

describe('SceneRenderer', () => {
  let box: HTMLDivElement;
  let renderer: SceneRenderer | null = null;
  beforeEach(() => {
    box = document.createElement('div');
    box.style.cssText = 'width: 300px; height: 300px';
    document.body.append(box);
  });
  afterEach(() => {
    renderer?.dispose();
    box.remove();
  });

  it('draws in batches: one fill per style, whatever the number of bodies', async () => {
    // 30 boxes (4 particles each) and 5 circles; two fill styles, no strokes.
    const xy: number[] = [];
    const bodies: TopologyBody[] = [];
    for (let k = 0; k < 30; k++) {
      const x = 1 + (k % 6) * 1.5;
      const y = 1 + Math.floor(k / 6) * 1.5;
      const first = xy.length / 2;
      xy.push(x, y, x + 1, y, x + 1, y + 1, x, y + 1);
      bodies.push({ key: k, type: 'box', kind: 'rigid', indices: Int32Array.of(first, first + 1, first + 2, first + 3) });
    }
    for (let k = 0; k < 5; k++) {
      bodies.push({ key: 30 + k, type: 'circle', kind: 'particle', indices: Int32Array.of(xy.length / 2), radius: 0.4 });
      xy.push(1.5 + k * 1.5, 9);
    }
    const topology: Topology = { version: 1, bodies, links: [] };
    const frames = new FrameStore();
    frames.accept(frame(1, 0, false, xy, bodies.length));
    renderer = new SceneRenderer(box, () => ({ frames, topology, poll: () => {} }));
    renderer.viewWidth = 10;
    renderer.viewHeight = 10;
    bodies.forEach((b) => renderer!.setStyle(b.key, { fill: b.key % 2 ? '#ff0000' : '#0000ff', stroke: null, lineWidth: 1 }));
    const proto = CanvasRenderingContext2D.prototype;
    const fill = proto.fill;
    const stroke = proto.stroke;
    let fills = 0;
    let strokes = 0;
    const perFrame: [number, number][] = [];
    proto.fill = function (this: CanvasRenderingContext2D, ...args: unknown[]) {
      fills++;
      return (fill as (...a: unknown[]) => void).apply(this, args);
    } as typeof proto.fill;
    proto.stroke = function (this: CanvasRenderingContext2D, ...args: unknown[]) {
      strokes++;
      return (stroke as (...a: unknown[]) => void).apply(this, args);
    } as typeof proto.stroke;
    try {
      // The frame never changes: the hook asks to be drawn again.
      renderer.hook = (view) => {
        perFrame.push([fills, strokes]);
        fills = 0;
        strokes = 0;
        view.requestDraw();
      };
      await waitFor(() => perFrame.length >= 4, 'four drawn frames');
    } finally {
      proto.fill = fill;
      proto.stroke = stroke;
    }
    // The first entry counts whatever ran before the hook was set; every later frame is one draw.
    for (const [f, s] of perFrame.slice(1)) {
      expect(f).to.equal(2);
      expect(s).to.equal(0);
    }
  });

  it('interpolates between the two newest frames while running, and shows the newest when paused', async () => {
    const topology: Topology = { version: 1, bodies: [{ key: 1, type: 'circle', kind: 'particle', indices: Int32Array.of(0), radius: 0.5 }], links: [] };
    const frames = new FrameStore();
    frames.accept(frame(1, 0, true, [0, 5], 1));
    frames.accept(frame(2, 1, true, [10, 5], 1));
    const views: { x: number; alpha: number }[] = [];
    renderer = new SceneRenderer(box, () => ({ frames, topology, poll: () => {} }));
    renderer.viewWidth = 10;
    renderer.viewHeight = 10;
    renderer.hook = (v: DrawView) => views.push({ x: v.positions[0], alpha: v.alpha });
    // A second of simulated time between the two frames: a draw a quarter of a second after the newest frame arrived
    // shows a quarter of the way from the previous one (x = 10 · alpha), on a clock the test holds.
    let elapsed = 250;
    renderer.now = () => frames.currAt + elapsed;
    await waitFor(() => views.length > 0, 'a frame drawn');
    for (const v of views) {
      expect(v.alpha).to.equal(0.25);
      expect(v.x).to.be.closeTo(2.5, 1e-9);
    }
    elapsed = 600;
    await waitFor(() => views.at(-1)!.alpha !== 0.25, 'a draw later in the second');
    expect(views.at(-1)!.alpha).to.equal(0.6);
    expect(views.at(-1)!.x).to.be.closeTo(6, 1e-9);
    elapsed = 1500;
    await waitFor(() => views.at(-1)!.alpha === 1, 'a frame drawn at the newest state');
    expect(views.at(-1)!.x).to.equal(10);
    // Paused frames are drawn as they are, once.
    views.length = 0;
    frames.accept(frame(3, 2, false, [3, 5], 1));
    await waitFor(() => views.length >= 1, 'the paused frame drawn');
    await animationFrames(10);
    expect(views.map((v) => v.x)).to.deep.equal([3]);
  });

  it('blends poses too, angles the short way round (from 3 to -3 rad through pi, not through 0)', async () => {
    const body: TopologyBody = { key: 1, type: 'box', kind: 'rigid', indices: Int32Array.of(0), rigid: true, outline: Float64Array.of(-1, -1, 1, -1, 1, 1, -1, 1), center: [0, 0] };
    const topology: Topology = { version: 1, bodies: [body], links: [] };
    const frames = new FrameStore();
    frames.accept(frame(1, 0, true, [0, 5], 1, [0, 5, 3]));
    frames.accept(frame(2, 1, true, [10, 5], 1, [10, 5, -3]));
    const views: { x: number; angle: number; alpha: number }[] = [];
    renderer = new SceneRenderer(box, () => ({ frames, topology, poll: () => {} }));
    renderer.viewWidth = 10;
    renderer.viewHeight = 10;
    renderer.hook = (v: DrawView) => views.push({ x: v.poses[0], angle: v.poses[2], alpha: v.alpha });
    await waitFor(() => views.some((v) => v.alpha === 1), 'a frame drawn at the newest state');
    const between = views.filter((v) => v.alpha < 1);
    expect(between.length).to.be.greaterThan(0);
    for (const v of between) {
      expect(v.x).to.be.closeTo(10 * v.alpha, 1e-9);
      // 3 + (2π − 6)·alpha: the turn of 0.28 rad across pi, not the 6 rad back through 0.
      expect(v.angle).to.be.closeTo(3 + (2 * Math.PI - 6) * v.alpha, 1e-9);
    }
    expect(views.at(-1)!.angle).to.equal(-3);
  });
});

describe('SceneRenderer draws only what changes', () => {
  let box: HTMLDivElement;
  let renderer: SceneRenderer | null = null;
  const topology: Topology = { version: 1, bodies: [{ key: 1, type: 'circle', kind: 'particle', indices: Int32Array.of(0), radius: 0.5 }], links: [] };
  beforeEach(() => {
    box = document.createElement('div');
    box.style.cssText = 'width: 200px; height: 200px';
    document.body.append(box);
  });
  afterEach(() => {
    renderer?.dispose();
    renderer = null;
    box.remove();
  });

  /** A renderer drawing `frames` (its drawn count settled after the first drawing). */
  async function start(frames: FrameStore): Promise<SceneRenderer> {
    const r = new SceneRenderer(box, () => ({ frames, topology, poll: () => {} }));
    r.viewWidth = 10;
    r.viewHeight = 10;
    renderer = r;
    await waitFor(() => r.drawn >= 1, 'the first drawing');
    await animationFrames(3);
    return r;
  }

  /** Draws made over `n` animation frames. */
  async function drawsOver(r: SceneRenderer, n = 20): Promise<number> {
    const before = r.drawn;
    await animationFrames(n);
    return r.drawn - before;
  }

  it('a paused frame is drawn once; a new frame that moves something, a style, the view or a resize draw once more', async () => {
    const frames = new FrameStore();
    frames.accept(frame(1, 0, false, [5, 5], 1));
    const r = await start(frames);
    expect(await drawsOver(r)).to.equal(0);
    const drawn = r.drawn;
    frames.accept(frame(2, 1 / 60, false, [5, 6], 1));
    await waitFor(() => r.drawn > drawn, 'the moved frame drawn');
    expect(await drawsOver(r)).to.equal(0);
    for (const change of [
      () => r.setStyle(1, { fill: '#ff0000', stroke: null, lineWidth: 1 }),
      () => (r.viewWidth = 12),
      () => (r.background = 'transparent'),
      () => (r.debug = true),
      () => (box.style.width = '150px'),
      () => r.requestDraw(),
    ]) {
      const before = r.drawn;
      change();
      await waitFor(() => r.drawn > before, `a drawing after ${change}`);
      expect(await drawsOver(r), `${change}`).to.equal(0);
    }
  });

  it('frames that repeat what is drawn (a settled world still stepping) are not drawn; a hook is given every new frame', async () => {
    const frames = new FrameStore();
    frames.accept(frame(1, 0, true, [5, 5], 1));
    frames.accept(frame(2, 1 / 60, true, [5, 6], 1));
    const r = await start(frames);
    // Running frames, the same positions: a new step count and time each, nothing to draw.
    let drawsWhileRepeating = 0;
    for (let k = 3; k < 23; k++) {
      const before = r.drawn;
      frames.accept(frame(k, k / 60, true, [5, 6], 1));
      await animationFrames(1);
      drawsWhileRepeating += r.drawn - before;
    }
    expect(drawsWhileRepeating).to.equal(0);
    const hooked: number[] = [];
    r.hook = (v) => hooked.push(v.frame[F.seq]);
    await waitFor(() => hooked.length >= 1, 'the hook drawn');
    frames.accept(frame(30, 30 / 60, false, [5, 6], 1));
    await waitFor(() => hooked.includes(30), 'the hook given the new frame');
  });

  it("a hook's p5 fill and stroke colours are drawn in every frame, not only the first (p5 caches the colour it set last)", async () => {
    const frames = new FrameStore();
    frames.accept(frame(1, 0, false, [5, 5], 1));
    const r = await start(frames);
    r.setStyle(1, { fill: '#00ff00', stroke: '#0000ff', lineWidth: 1 });
    // No push()/pop(): p5's pop() puts back the colour cache it had, which hid the stale cache.
    r.hook = ({ p }) => {
      p.resetMatrix();
      p.noStroke();
      p.fill('#ff0000');
      p.rect(0, 0, 10, 10);
      p.noFill();
      p.stroke('#ff00ff');
      p.strokeWeight(4);
      p.line(0, 30, 40, 30);
    };
    const ctx = r.canvas!.getContext('2d')!;
    const density = r.canvas!.width / r.canvas!.getBoundingClientRect().width;
    const at = (x: number, y: number) => Array.from(ctx.getImageData(Math.floor(x * density), Math.floor(y * density), 1, 1).data).slice(0, 3);
    // Each new frame moves the disc (drawn green with a blue outline, on the context directly) and draws the hook again.
    for (let k = 2; k < 6; k++) {
      const drawn = r.drawn;
      frames.accept(frame(k, k / 60, false, [5, 5 + k / 10], 1));
      await waitFor(() => r.drawn > drawn, `frame ${k} drawn`);
      expect(at(3, 3), `the hook's fill in frame ${k}`).to.deep.equal([255, 0, 0]);
      expect(at(20, 30), `the hook's stroke in frame ${k}`).to.deep.equal([255, 0, 255]);
    }
  });

  it('far from the viewport gives its pixels back (0 × 0, same CSS box); near again draws the newest frame at once, context state kept', async () => {
    const frames = new FrameStore();
    frames.accept(frame(1, 0, false, [5, 5], 1));
    const r = await start(frames);
    r.setStyle(1, { fill: '#00ff00', stroke: null, lineWidth: 1 });
    await waitFor(() => !r.drawPending, 'the style drawn');
    const canvas = r.canvas!;
    const size = [canvas.width, canvas.height];
    const css = canvas.getBoundingClientRect();
    expect(size[0] * size[1]).to.be.greaterThan(0);
    // State a draw hook may have set once and count on (p5 caches its fill and stroke and does not set them again).
    const ctx = canvas.getContext('2d')!;
    ctx.miterLimit = 7;
    r.setLooping(false);
    r.setNear(false);
    expect(r.isReleased).to.equal(true);
    expect([canvas.width, canvas.height]).to.deep.equal([0, 0]);
    const now = canvas.getBoundingClientRect();
    expect([now.width, now.height]).to.deep.equal([css.width, css.height]);
    // Moved while far away, and resized: drawn at the new place and size when near again, before any animation frame.
    frames.accept(frame(2, 1 / 60, false, [2, 2], 1));
    const drawn = r.drawn;
    r.setNear(true);
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect(r.drawn).to.equal(drawn + 1);
    expect([canvas.width, canvas.height]).to.deep.equal(size);
    expect(ctx.miterLimit).to.equal(7);
    const density = canvas.width / css.width;
    const at = (x: number, y: number) => Array.from(ctx.getImageData(Math.floor(x * 20 * density), Math.floor(y * 20 * density), 1, 1).data);
    expect(at(2, 2).slice(0, 3)).to.deep.equal([0, 255, 0]);
    expect(at(5, 5).slice(0, 3)).to.not.deep.equal([0, 255, 0]);
    // A resize while far away is taken with the pixels.
    r.setNear(false);
    box.style.width = '150px';
    await animationFrames(3);
    expect([canvas.width, canvas.height]).to.deep.equal([0, 0]);
    r.setNear(true);
    expect(canvas.width).to.equal(Math.round(150 * density));
  });

    it('draws nothing while not looping (off screen), and what changed meanwhile once it loops again', async () => {
    const frames = new FrameStore();
    frames.accept(frame(1, 0, false, [5, 5], 1));
    const r = await start(frames);
    r.setLooping(false);
    frames.accept(frame(2, 1 / 60, false, [2, 2], 1));
    r.setStyle(1, { fill: '#00ff00', stroke: null, lineWidth: 1 });
    expect(await drawsOver(r)).to.equal(0);
    const drawn = r.drawn;
    r.setLooping(true);
    await waitFor(() => r.drawn > drawn, 'the change drawn');
    expect(await drawsOver(r)).to.equal(0);
  });
});
