// Bodies as drawn, from a hand-made frame: the hit test (inside, within the slop, outside, the include filter, the
// last of overlapping bodies), the box around a body (particle loops, rigid outlines turned by their angle, ropes as
// thick as drawn) and the velocity from the two newest frames. The mapping is world × 10 + (5, 5) CSS pixels.
import { expect } from '@open-wc/testing';
import { BodyOutlines } from '../../../src/elements/physics-scene/outlines.js';
import type { FrameSource } from '../../../src/render/renderer.js';
import { FrameStore } from '../../../src/worker/client.js';
import { F, HEADER, POSE, frameLength, poseOffset, type Topology } from '../../../src/worker/protocol.js';

const VIEW = { scale: 10, offsetX: 5, offsetY: 5 };

/**
 * Particles: 0–3 a particle box from (1, 1) to (3, 2), 4–6 a rope (10, 1) → (12, 1) → (12, 3), 7 a rigid box's centre
 * of mass, 8 a rigid disc's. Bodies in that order; the rigid box is 2 × 1 about (6, 6) turned by `angle`.
 */
function frame(step: number, dx = 0, angle = 0): Float64Array {
  const particles = [1, 1, 3, 1, 3, 2, 1, 2, 10, 1, 12, 1, 12, 3, 6, 6, 20, 5].map((v, i) => (i % 2 === 0 ? v + dx : v));
  const poses = [2 + dx, 1.5, 0, 12 + dx, 2, 0, 6 + dx, 6, angle, 20 + dx, 5, 0];
  const n = particles.length / 2;
  const b = poses.length / POSE;
  const f = new Float64Array(frameLength(n, b, 0, false));
  f[F.seq] = step + 1;
  f[F.topology] = 1;
  f[F.stepCount] = step;
  f[F.time] = step / 60;
  f[F.particles] = n;
  f[F.bodies] = b;
  f[F.running] = 1;
  f.set(particles, HEADER);
  f.set(poses, poseOffset(n));
  return f;
}

const TOPOLOGY: Topology = {
  version: 1,
  bodies: [
    { key: 11, type: 'box', kind: 'particle', indices: Int32Array.of(0, 1, 2, 3) },
    { key: 12, type: 'rope', kind: 'rope', indices: Int32Array.of(4, 5, 6), radius: 0.1 },
    { key: 13, type: 'box', kind: 'rigid', indices: Int32Array.of(7), rigid: true, outline: Float64Array.of(-1, -0.5, 1, -0.5, 1, 0.5, -1, 0.5), center: [0, 0] },
    { key: 14, type: 'circle', kind: 'rigid', indices: Int32Array.of(8), rigid: true, radius: 1, center: [0, 0] },
  ],
  links: [],
} as Topology;

function source(...frames: Float64Array[]): FrameSource {
  const store = new FrameStore();
  for (const f of frames) store.accept(f);
  return { frames: store, topology: TOPOLOGY, poll() {} };
}

/** Canvas pixels of world point (x, y). */
const px = (x: number, y: number): [number, number] => [VIEW.offsetX + x * VIEW.scale, VIEW.offsetY + y * VIEW.scale];

describe('BodyOutlines', () => {
  it('finds the body drawn at a point, within the slop, not outside it; include() leaves bodies out', () => {
    const o = new BodyOutlines(() => source(frame(1)), () => VIEW);
    const keyAt = (x: number, y: number, slop = 0, include?: (b: { key: number }) => boolean) => o.bodyAt(...px(x, y), slop, include)?.body.key ?? null;
    expect(keyAt(2, 1.5)).to.equal(11);
    // 0.5 world units = 5 px right of the particle box's edge: out without slop, in with 8 px of it, out with 4.
    expect([keyAt(3.5, 1.5), keyAt(3.5, 1.5, 8), keyAt(3.5, 1.5, 4)]).to.deep.equal([null, 11, null]);
    // The rope is drawn 2 px wide (radius 0.1 × 10 × 2): on it, and 3 px off it with and without slop.
    expect([keyAt(11, 1), keyAt(11, 1.3), keyAt(11, 1.3, 8)]).to.deep.equal([12, null, 12]);
    expect([keyAt(20.9, 5), keyAt(21.2, 5), keyAt(6.9, 6.4)]).to.deep.equal([14, null, 13]);
    expect(keyAt(2, 1.5, 0, (b) => b.key !== 11)).to.equal(null);
    expect(keyAt(30, 30, 8)).to.equal(null);
    // Where to take it: the point itself when it is on the body; from within the slop, a point inside the body (not
    // on its outline's stroke) near it: here 5 px right of the box's right edge at x = 35 px, so a point with x < 35,
    // 5 to 10 px away (the probes go a ring of 2 px deeper when they can).
    expect(o.bodyAt(...px(2, 1.5), 8)).to.deep.include({ x: 25, y: 20 });
    const near = o.bodyAt(...px(3.5, 1.5), 8)!;
    expect(near.x).to.be.below(35);
    expect(Math.hypot(near.x - 40, near.y - 20)).to.be.within(5, 10);
    expect(o.bodyAt(near.x, near.y, 0)?.body.key).to.equal(11);
    expect(o.bodyAt(NaN, 3, 8)).to.equal(null);
  });

  it('a rigid body is hit where its outline is turned to: its corner moves with the angle', () => {
    const straight = new BodyOutlines(() => source(frame(1)), () => VIEW);
    const turned = new BodyOutlines(() => source(frame(1, 0, Math.PI / 2)), () => VIEW);
    // (6.9, 6.4) is inside the unturned 2 × 1 box about (6, 6); turned a quarter it is 1 × 2: (6.9, 6.4) is out,
    // (6.4, 6.9) in.
    expect([straight.bodyAt(...px(6.9, 6.4), 0)?.body.key, turned.bodyAt(...px(6.9, 6.4), 0)?.body.key ?? null]).to.deep.equal([13, null]);
    expect(turned.bodyAt(...px(6.4, 6.9), 0)?.body.key).to.equal(13);
  });

  it('the box around a body as drawn, in canvas pixels', () => {
    const o = new BodyOutlines(() => source(frame(1, 0, Math.PI / 2)), () => VIEW);
    const round = (b: { left: number; top: number; right: number; bottom: number } | null) => b && [b.left, b.top, b.right, b.bottom].map((v) => Math.round(v * 100) / 100);
    // Filled and stroked 1 px wide: half a pixel beyond the loop.
    expect(round(o.bounds(11))).to.deep.equal([14.5, 14.5, 35.5, 25.5]);
    // The rope, 2 px wide.
    expect(round(o.bounds(12))).to.deep.equal([104, 14, 126, 36]);
    // The rigid box turned a quarter: 1 wide and 2 high about (6, 6) → 60..70 × 50..70 px (+ 5 offset, + 0.5 stroke).
    expect(round(o.bounds(13))).to.deep.equal([59.5, 54.5, 70.5, 75.5]);
    expect(round(o.bounds(14))).to.deep.equal([194.5, 44.5, 215.5, 65.5]);
    expect(o.bounds(99)).to.equal(null);
  });

  it('velocity from the poses of the two newest frames; null from one frame or without a canvas', () => {
    const two = new BodyOutlines(() => source(frame(1), frame(3, 0.5)), () => VIEW);
    const v = two.velocity(13)!;
    // 0.5 world units in 2 steps of 1/60 s.
    expect([Math.round(v.x * 1000) / 1000, v.y]).to.deep.equal([15, 0]);
    expect(new BodyOutlines(() => source(frame(1)), () => VIEW).velocity(13)).to.equal(null);
    expect(new BodyOutlines(() => source(frame(1), frame(3)), () => null).velocity(13)).to.equal(null);
    expect(new BodyOutlines(() => null, () => VIEW).bodyAt(20, 20, 8)).to.equal(null);
  });

  it('2,000 bodies are hit-tested within a touch (counted, not timed: each body traced once)', () => {
    const n = 2000;
    const particles = new Float64Array(2 * n);
    const bodies: Topology['bodies'] = [];
    for (let k = 0; k < n; k++) {
      particles[2 * k] = (k % 50) * 0.5 + 0.25;
      particles[2 * k + 1] = Math.floor(k / 50) * 0.5 + 0.25;
      bodies.push({ key: k, type: 'circle', kind: 'rigid', indices: Int32Array.of(k), rigid: true, radius: 0.2, center: [0, 0] });
    }
    const f = new Float64Array(frameLength(n, n, 0, false));
    f[F.seq] = 1;
    f[F.topology] = 2;
    f[F.particles] = n;
    f[F.bodies] = n;
    f.set(particles, HEADER);
    for (let k = 0; k < n; k++) f.set([particles[2 * k], particles[2 * k + 1], 0], poseOffset(n) + POSE * k);
    const store = new FrameStore();
    store.accept(f);
    const o = new BodyOutlines(() => ({ frames: store, topology: { version: 2, bodies, links: [] }, poll() {} }), () => VIEW);
    let asked = 0;
    const hit = o.bodyAt(...px(0.25 + 7 * 0.5, 0.25 + 3 * 0.5), 0, () => (asked++, true));
    expect([hit?.body.key, asked]).to.deep.equal([157, n]);
  });
});
