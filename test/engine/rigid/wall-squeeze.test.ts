// A light rigid disc near a wall of the world's bounds, hit by a fast, heavy particle frame (fuzz seed 1826: a kicked
// ragdoll drove a 0.06 disc through the left wall). Contacts are found once a step, with a margin of each body's own
// motion; the disc was slow, so it had no wall point when the hit came mid-step, and it was driven through.
import { expect } from 'chai';
import { createBox, World } from '../../../src/engine/index.js';

describe('rigid bodies: a light disc squeezed against a wall by a fast, heavy body', () => {
  const r = 1.5;
  for (const kernel of ['js', 'wasm'] as const) {
    it(`stays inside the bounds (${kernel} kernel)`, () => {
      // Hammer speeds of 100-500 units/s (1.7-8.3 units a step) against gaps of 0.5-2.5 between disc and wall.
      // Without wall points for the disc, its left edge reached -0.83 (100 u/s, gap 0.5), -1.66 (250) and -5.83
      // (500): past the wall by up to two diameters, and still 1.9 past it a second later.
      for (const speed of [100, 250, 500]) {
        for (const gap of [0.5, 1.1, 2.5]) {
          const world = new World({ gravity: { x: 0, y: 0 }, bounds: { minX: 0, minY: -20, maxX: 40, maxY: 20 }, sleeping: false, kernel });
          expect(world.diagnostics().kernel).to.equal(kernel);
          const disc = world.addRigidBody({ x: r + gap, y: 0, radius: r, mass: 0.06 });
          // A 1×1 frame of particles, 500 times the disc's mass, 2 units to its right, thrown at it.
          const hammer = createBox(world, { x: r + gap + r + 2.5, y: 0, width: 1, height: 1, model: 'particles', mass: 30 });
          world.applyBodyImpulse(hammer.body, -speed * 30, 0);
          let leftmost = Infinity;
          for (let k = 0; k < 60; k++) {
            world.step();
            leftmost = Math.min(leftmost, world.bodyPose(disc).x - r);
          }
          // The wall holds it to within the solver's tolerance (it ends a step on the wall, not past it).
          expect(leftmost, `speed ${speed}, gap ${gap}`).to.be.greaterThan(-0.01);
        }
      }
    });
  }

  for (const model of ['rigid', 'particles'] as const) {
    it(`a static rigid wall holds the disc against a ${model === 'rigid' ? 'rigid' : 'particle-built'} hammer of 1-500× its mass at 100-500 units/s`, () => {
      // The disc's AABB grows by its fastest partner's motion (growPushedBodies in collide.ts), so its pair with the
      // wall exists when the hit comes, and contacts with a static body are solved last in each sweep (the order
      // rigid-narrowphase.ts writes them in). Before the first: at 500 u/s the disc went through the 1-thick wall
      // for mass ratios 1, 3 and 10 (rigid hammer); before the second, ratio 10 at 500 u/s still did, and a
      // particle-built hammer 100× heavier drove it through at 100 u/s.
      for (const ratio of [1, 3, 10, 30, 100, 500]) {
        for (const speed of [100, 250, 500]) {
          let deepest = Infinity;
          for (const gap of [0.5, 1.1, 2.5]) {
            const world = new World({ gravity: { x: 0, y: 0 }, bounds: { minX: -50, minY: -20, maxX: 40, maxY: 20 }, sleeping: false });
            world.addRigidBody({ x: -0.5, y: 0, points: [{ x: -0.5, y: -10 }, { x: 0.5, y: -10 }, { x: 0.5, y: 10 }, { x: -0.5, y: 10 }], type: 'static' });
            const disc = world.addRigidBody({ x: r + gap, y: 0, radius: r, mass: 0.06 });
            const hammer = createBox(world, { x: r + gap + r + 2.5, y: 0, width: 1, height: 1, model, mass: 0.06 * ratio });
            world.applyBodyImpulse(hammer.body, -speed * 0.06 * ratio, 0);
            for (let k = 0; k < 60; k++) {
              world.step();
              deepest = Math.min(deepest, world.bodyPose(disc).x - r);
            }
            expect(world.bodyPose(disc).x, `ratio ${ratio}, ${speed} u/s, gap ${gap}: ends on the near side`).to.be.greaterThan(r - 0.01);
          }
          expect(deepest, `ratio ${ratio}, ${speed} u/s`).to.be.greaterThan(-0.01);
        }
      }
    });
  }
});
