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
    let deepest = 0;
    for (let a = 0; a < centres.length; a++) {
      for (let b = a + 1; b < centres.length; b++) {
        const d = Math.hypot(x[centres[a]] - x[centres[b]], y[centres[a]] - y[centres[b]]);
        deepest = Math.max(deepest, 1 - d);
      }
    }
    console.log(`2000 circles, 15 s: escaped ${escaped(world, balls)}, deepest overlap ${(deepest * 100).toFixed(2)}% of a diameter`);
    expect(escaped(world, balls)).to.equal(0);
    expect(deepest).to.be.below(0.04);
  });
});
