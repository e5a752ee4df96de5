// What the canvas shows: body colours where the bodies are, the viewBox fit, and a box falling onto a floor.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, drawn, mount, pixelAt, rgb, unmount } from './helpers.js';

const WHITE = rgb('#ffffff');

describe('<physics-scene> canvas', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('paints each body in its fill colour where the body is, and the background elsewhere', async () => {
    scene = await mount(
      'width="10" height="10" paused background="#ffffff"',
      `<physics-box x="5" y="9.5" width="10" height="1" static fill="#0000ff" stroke="none"></physics-box>
       <physics-box x="3" y="3" width="2" height="2" angle="0" fill="#ff0000" stroke="none"></physics-box>
       <physics-circle x="7" y="3" radius="1" fill="#00ff00" stroke="none"></physics-circle>
       <physics-polygon x="5" y="6.5" points="-1,1 1,1 0,-1" fill="#ffff00" stroke="none"></physics-polygon>`,
    );
    await drawn(scene, 3);
    expect(colourDistance(pixelAt(scene, 3, 3), rgb('#ff0000'))).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 2.2, 2.2), rgb('#ff0000'))).to.be.below(8);
    // The ball is a rigid disc: its radius line runs from its centre along its angle (0: to the right), so sample off it.
    expect(colourDistance(pixelAt(scene, 7, 3.3), rgb('#00ff00'))).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 7.6, 3.6), rgb('#00ff00'))).to.be.below(8);
    // Edges, 0.1 units (4 px) inside and outside: the shapes are where the bodies are, not just near.
    for (const [x, y, inside, colour] of [
      [3, 2.1, true, '#ff0000'], [3, 1.9, false, '#ff0000'], [3.9, 3, true, '#ff0000'], [4.1, 3, false, '#ff0000'],
      [7, 2.1, true, '#00ff00'], [7, 1.9, false, '#00ff00'], [7, 3.9, true, '#00ff00'], [7, 4.1, false, '#00ff00'],
    ] as const) {
      expect(colourDistance(pixelAt(scene, x, y), inside ? rgb(colour) : WHITE), `${x}, ${y}`).to.be.below(8);
    }
    expect(colourDistance(pixelAt(scene, 5, 9.5), rgb('#0000ff'))).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 5, 7), rgb('#ffff00'))).to.be.below(8);
    // Outside every body: background.
    for (const [x, y] of [[3, 1.7], [1.7, 3], [7, 1.8], [8.3, 3], [5, 8.8], [3.9, 7.4]]) {
      expect(colourDistance(pixelAt(scene, x, y), WHITE), `background at ${x}, ${y}`).to.be.below(8);
    }
  });

  it('draws a soft body resting on the floor touching it (its ring\'s particles collide as discs: drawn around them)', async () => {
    // 40 px per unit; the floor's top at y = 9; a ring of radius 1 and 12 particles (each a disc of 1 · sin(π/12) =
    // 0.26 units, 10 px: drawn through their centres, the ring hovered 10 px above the floor).
    scene = await mount(
      'width="10" height="10" paused background="#ffffff"',
      `<physics-box x="5" y="9.5" width="10" height="1" static fill="#0000ff" stroke="none"></physics-box>
       <physics-softbody x="5" y="7" radius="1" segments="12" fill="#ff0000" stroke="none"></physics-softbody>`,
    );
    await scene.step(180);
    await drawn(scene, 3);
    const canvas = scene.canvas!;
    const ratio = canvas.width / canvas.getBoundingClientRect().width;
    const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
    const red = (x: number, y: number) => colourDistance(Array.from(data.subarray(4 * (y * canvas.width + x), 4 * (y * canvas.width + x) + 3)), rgb('#ff0000')) < 40;
    // The lowest red pixel in the body's middle columns, and the floor's first blue row, in canvas pixels.
    const floorTop = Math.round(9 * 40 * ratio);
    let lowest = -1;
    for (let y = 0; y < floorTop; y++) for (let x = Math.round(4.5 * 40 * ratio); x < Math.round(5.5 * 40 * ratio); x++) if (red(x, y)) lowest = y;
    expect(floorTop - 1 - lowest, `gap between the soft body and the floor (canvas px, ${ratio} per CSS px)`).to.be.at.most(2 * ratio);
  });

  it('under a CSS zoom on an ancestor the canvas has the pixels it shows: zoom 2, twice the CSS width (it was drawn at half and blurred)', async () => {
    scene = await mount('width="10" height="10" paused background="#ffffff"', `<physics-box x="5" y="5" width="2" height="2" fill="#ff0000" stroke="none"></physics-box>`, {
      width: 200,
      height: 200,
      before: (s) => ((s.parentElement as HTMLElement).style.zoom = '2'),
    });
    await drawn(scene, 3);
    const canvas = scene.canvas!;
    const shown = canvas.getBoundingClientRect().width;
    expect(shown).to.be.closeTo(400, 1);
    expect(canvas.width / window.devicePixelRatio).to.be.closeTo(400, 2);
    expect(colourDistance(pixelAt(scene, 5, 5), rgb('#ff0000'))).to.be.below(8);
  });

  it('fits the viewBox into the element keeping its aspect ratio (centred, letterboxed)', async () => {
    // A 400×200 element showing a 10×10 world: 20 px per unit, the world spans x = 100..300 px.
    scene = await mount(
      'width="10" height="10" paused background="#ffffff" bounds="none"',
      `<physics-box x="5" y="5" width="10" height="10" static fill="#ff0000" stroke="none"></physics-box>`,
      { width: 400, height: 200 },
    );
    await drawn(scene, 3);
    const canvas = scene.canvas!;
    const ratio = canvas.width / 400;
    expect(canvas.getBoundingClientRect().width).to.equal(400);
    expect(canvas.getBoundingClientRect().height).to.equal(200);
    expect(canvas.height).to.equal(Math.round(200 * ratio));
    const ctx = canvas.getContext('2d')!;
    const at = (x: number, y: number) => Array.from(ctx.getImageData(Math.floor(x * ratio), Math.floor(y * ratio), 1, 1).data);
    expect(colourDistance(at(95, 100), WHITE)).to.be.below(8);
    expect(colourDistance(at(104, 100), rgb('#ff0000'))).to.be.below(8);
    expect(colourDistance(at(296, 100), rgb('#ff0000'))).to.be.below(8);
    expect(colourDistance(at(305, 100), WHITE)).to.be.below(8);
    expect(colourDistance(at(200, 2), rgb('#ff0000'))).to.be.below(8);
  });

  it('debug draws each body\'s axis-aligned bounding box', async () => {
    // A 2×2 box turned 45° at (5, 5): its AABB spans 5 ± √2; at 40 px per unit the top edge is the row y = 143.4 px.
    const markup = `<physics-box x="5" y="5" width="2" height="2" angle="45" fill="#ffffff" stroke="none"></physics-box>`;
    scene = await mount('width="10" height="10" paused bounds="none" gravity="0 0" background="#ffffff" debug', markup);
    await drawn(scene, 3);
    const canvas = scene.canvas!;
    const ratio = canvas.width / canvas.getBoundingClientRect().width;
    const ctx = canvas.getContext('2d')!;
    const magenta = (x: number, y0: number, y1: number) => {
      let best = 0;
      for (let y = y0; y <= y1; y++) {
        const [r, g, b] = ctx.getImageData(Math.floor(x * ratio), Math.floor(y * ratio), 1, 1).data;
        best = Math.max(best, Math.min(r, b) - g);
      }
      return best;
    };
    const top = (5 - Math.SQRT2) * 40;
    // Along the AABB's top edge, left of the box's corner (which is at x = 200 px): magenta; well below it: nothing.
    expect(magenta(152, Math.floor(top) - 1, Math.ceil(top) + 1)).to.be.above(80);
    expect(magenta(248, Math.floor(top) - 1, Math.ceil(top) + 1)).to.be.above(80);
    expect(magenta(152, Math.floor(top) + 6, Math.floor(top) + 12)).to.equal(0);
    scene.debug = false;
    await drawn(scene, 3);
    expect(magenta(152, Math.floor(top) - 1, Math.ceil(top) + 1)).to.equal(0);
  });

  it('a box dropped onto a static floor moves down, then rests on it', async () => {
    // Paused and sampled every 2 steps: the samples do not depend on how fast the machine runs.
    scene = await mount(
      'width="10" height="10" gravity="0 30" background="#ffffff" paused',
      `<physics-box x="5" y="9.5" width="10" height="1" static fill="#0000ff" stroke="none"></physics-box>
       <physics-box id="crate" x="5" y="5" width="1" height="1" fill="#ff0000" stroke="none"></physics-box>`,
    );
    const crate = scene.querySelector<PhysicsBoxElement>('physics-box#crate')!;
    const ys = [crate.y];
    let still = 0;
    while (still < 10 && ys.length < 300) {
      await scene.step(2);
      ys.push(crate.y);
      const n = ys.length;
      still = Math.abs(ys[n - 1] - ys[n - 2]) < 1e-4 && ys[n - 1] > 8 ? still + 1 : 0;
    }
    expect(still, 'samples at rest').to.equal(10);
    expect(ys[0]).to.equal(5);
    // It moved down: the samples increase until it lands (3.4 units at g = 30 take about 0.48 s, 14 samples).
    const landed = ys.findIndex((y) => y > 8.4);
    expect(landed).to.be.within(10, 20);
    for (let k = 1; k <= landed; k++) expect(ys[k]).to.be.at.least(ys[k - 1] - 1e-9);
    // Never through the floor (top at y = 9, centre at most 8.5 plus the solver's slop), and rests on it.
    expect(Math.max(...ys)).to.be.below(8.56);
    expect(crate.y).to.be.closeTo(8.5, 0.03);
    expect(crate.x).to.be.closeTo(5, 0.02);
    expect(crate.angle).to.be.closeTo(0, 1);
    await drawn(scene, 2);
    expect(colourDistance(pixelAt(scene, 5, 8.5), rgb('#ff0000'))).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 5, 7.8), WHITE)).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 5, 9.5), rgb('#0000ff'))).to.be.below(8);
  });
});
