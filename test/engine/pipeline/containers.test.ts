import { expect } from 'chai';
import { boxOutline, deepestPenetration, scene } from './scene-helpers.js';

function escaped(world: import('../../../src/engine/index.js').World, handles: number[]): number {
  // The container is 30 wide inside (x in [−15, 15]) with its floor's top at y = 0.
  let n = 0;
  for (const h of handles) {
    const c = world.bodyCentroid(h);
    if (Math.abs(c.x) > 15 || c.y > 0) n++;
  }
  return n;
}

describe('pipeline: containers', () => {
  it('1000 boxes dropped into a U container: none escapes; deepest penetration < 4% after settling', () => {
    const { world, bodies, description } = scene('boxes');
    const boxes = bodies.slice(3).map((b) => b.body);
    for (let k = 0; k < 900; k++) world.step();
    const deepest = deepestPenetration(bodies.map((b, k) => boxOutline(world, b.body, description.bodies[k])));
    let top = Infinity;
    for (const h of boxes) top = Math.min(top, world.bodyCentroid(h).y);
    console.log(`1000 boxes, 15 s: escaped ${escaped(world, boxes)}, deepest penetration ${(deepest * 100).toFixed(2)}%, pile height ${(-top + 0.5).toFixed(1)}`);
    expect(escaped(world, boxes)).to.equal(0);
    expect(deepest).to.be.below(0.04);
    expect(-top + 0.5).to.be.within(36, 41); // 1000 unit boxes over a width of 30, loosely packed
  });

  it('2000 circles dropped into the same container: none escapes, overlaps stay small', () => {
    const { world, bodies } = scene('circles');
    const balls = bodies.slice(3).map((b) => b.body);
    for (let k = 0; k < 900; k++) world.step();
    const { x, y } = world.particles;
    const centres = balls.map((h) => world.bodyParticleIndices(h)[0]);
    const overlaps: number[] = [];
    for (let a = 0; a < centres.length; a++) {
      for (let b = a + 1; b < centres.length; b++) {
        const d = Math.hypot(x[centres[a]] - x[centres[b]], y[centres[a]] - y[centres[b]]);
        if (d < 1) overlaps.push(1 - d);
      }
    }
    overlaps.sort((p, q) => q - p);
    const deepest = overlaps[0];
    const deepest50 = overlaps.slice(0, 50).reduce((s, v) => s + v, 0) / 50;
    const mean = overlaps.reduce((s, v) => s + v, 0) / overlaps.length;
    console.log(`2000 circles, 15 s: escaped ${escaped(world, balls)}, overlaps (% of a diameter): deepest ${(deepest * 100).toFixed(2)}, the 50 deepest ${(deepest50 * 100).toFixed(2)}, all ${(mean * 100).toFixed(3)}`);
    expect(escaped(world, balls)).to.equal(0);
    // The deepest single overlap is a tail of the pile's chance arrangement: over 70 piles, both kernels, from gravities
    // 10⁻⁹ apart, it ranged 2.0–4.6% (the 50 deepest 1.4–2.2%, all of them 0.29–0.37%). A single pile's deepest point
    // against 4% failed on one pile in five; the 50 deepest and the mean tell how deep a pile sits.
    expect(deepest).to.be.below(0.06);
    expect(deepest50).to.be.below(0.025);
    expect(mean).to.be.below(0.005);
  });
});
