import { expect } from 'chai';
import { createBox, World } from '../../../src/engine/index.js';
import { boxOutline, deepestPenetration, scene } from './scene-helpers.js';

// Sleeping is off in these tests: a stack that fell asleep would pass without being stable.
describe('pipeline: stacking', () => {
  it('deepestPenetration measures the overlap of rigid boxes and of particle frames, turned or not', () => {
    for (const model of ['rigid', 'particles'] as const) {
      for (const angle of [0, 0.3]) {
        const world = new World({ gravity: { x: 0, y: 0 } });
        // B's corner is 0.3 inside A's right edge and 0.4 inside its bottom one, in A's frame.
        const [c, s] = [Math.cos(angle), Math.sin(angle)];
        const [a, b] = [{ x: 0, y: 0 }, { x: 0.7 * c - 0.6 * s, y: 0.7 * s + 0.6 * c }];
        const boxes = [a, b].map((p) => ({ type: 'box' as const, x: p.x, y: p.y, width: 1, height: 1, angle, model }));
        const built = boxes.map(({ type: _type, ...options }) => createBox(world, options));
        const deepest = deepestPenetration(built.map((k, i) => boxOutline(world, k.body, boxes[i])));
        expect(deepest, `${model}, angle ${angle}`).to.be.closeTo(0.3, 1e-9);
      }
    }
  });

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

  it('a base-20 pyramid (210 boxes) stands 10 s: top drift < 0.1, deepest penetration < 1% of a box', () => {
    const { world, bodies, description } = scene('pyramid', { sleeping: false });
    const top = bodies[bodies.length - 1].body;
    const start = world.bodyCentroid(top);
    const outlines = () => bodies.map((b, k) => boxOutline(world, b.body, description.bodies[k]));
    let deepest = 0;
    for (let k = 0; k < 600; k++) {
      world.step();
      if (k % 60 === 59) deepest = Math.max(deepest, deepestPenetration(outlines()));
    }
    const end = world.bodyCentroid(top);
    const drift = Math.hypot(end.x - start.x, end.y - start.y);
    console.log(`pyramid 20, 10 s: top drift ${drift.toFixed(4)}, deepest penetration ${(deepest * 100).toFixed(3)}% of a box`);
    expect(drift).to.be.below(0.1);
    expect(deepest).to.be.below(0.01);
  });
});
