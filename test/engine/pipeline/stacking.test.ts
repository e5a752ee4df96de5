import { expect } from 'chai';
import { deepestPenetration, scene } from './scene-helpers.js';

// Sleeping is off in these tests: a stack that fell asleep would pass without being stable.
describe('pipeline: stacking', () => {
  it('a vertical stack of 10 boxes stands 10 s with the top box drifting < 0.05', () => {
    const { world, bodies } = scene('stack', { sleeping: false });
    const top = bodies[bodies.length - 1].body;
    const start = world.bodyCentroid(top);
    for (let k = 0; k < 600; k++) world.step();
    const end = world.bodyCentroid(top);
    console.log(`stack of 10, 10 s: top drift x ${(end.x - start.x).toFixed(4)}, y ${(end.y - start.y).toFixed(4)}`);
    expect(Math.abs(end.x - start.x)).to.be.below(0.05);
    expect(Math.abs(end.y - start.y)).to.be.below(0.05);
  });

  it('a base-20 pyramid (210 boxes) stands 10 s: top drift < 0.1, deepest penetration < 2% of a box', () => {
    const { world, bodies } = scene('pyramid', { sleeping: false });
    const top = bodies[bodies.length - 1].body;
    const start = world.bodyCentroid(top);
    const outlines = bodies.map((b) => world.bodyParticleIndices(b.body));
    let deepest = 0;
    for (let k = 0; k < 600; k++) {
      world.step();
      if (k % 60 === 59) deepest = Math.max(deepest, deepestPenetration(world, outlines));
    }
    const end = world.bodyCentroid(top);
    const drift = Math.hypot(end.x - start.x, end.y - start.y);
    console.log(`pyramid 20, 10 s: top drift ${drift.toFixed(4)}, deepest penetration ${(deepest * 100).toFixed(3)}% of a box`);
    expect(drift).to.be.below(0.1);
    expect(deepest).to.be.below(0.02);
  });
});
