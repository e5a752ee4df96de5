// A body asleep (at rest long enough, so the engine stopped simulating it) moves when the page kicks it: setVelocity
// and applyImpulse by key wake a rigid body and a body of particles alike.
import { expect } from 'chai';
import type { WorldSnapshot } from '../../../src/engine/index.js';
import { decode, makeHost } from './harness.js';

/** Bodies asleep now, from the host's snapshot of its world. */
function asleep(h: ReturnType<typeof makeHost>): number {
  return (h.host.snapshot().world as WorldSnapshot & { sleep: { asleepCount: number } }).sleep.asleepCount;
}

describe('EngineHost: kicks wake sleeping bodies', () => {
  for (const kick of ['setVelocity', 'applyImpulse'] as const) {
    it(`${kick} moves a rigid ball and a box of particles that have fallen asleep on the floor`, () => {
      const h = makeHost();
      h.host.load({
        world: { bounds: { minX: 0, minY: -1000, maxX: 16, maxY: 9 } },
        bodies: [
          { key: 1, desc: { type: 'box', x: 8, y: 8.5, width: 16, height: 1, static: true } },
          { key: 2, desc: { type: 'circle', x: 3, y: 7.5, radius: 0.5 } },
          { key: 3, desc: { type: 'box', x: 10, y: 7.5, width: 1, height: 1, model: 'particles' } },
        ],
        links: [],
      });
      h.host.step(240);
      expect(asleep(h), 'both bodies asleep after 4 s at rest').to.equal(2);
      const rest = decode(h.frame).poses;
      h.host.step(10);
      expect(decode(h.frame).poses, 'asleep: nothing moves').to.deep.equal(rest);
      // Upward at 3 units/s (an impulse of mass x 3): 6 steps later each is well above where it slept.
      if (kick === 'setVelocity') {
        h.host.setVelocity(2, 0, -3);
        h.host.setVelocity(3, 0, -3);
      } else {
        h.host.applyImpulse(2, 0, -3 * Math.PI * 0.25);
        h.host.applyImpulse(3, 0, -3);
      }
      h.host.step(6);
      const poses = decode(h.frame).poses;
      for (const k of [1, 2]) expect(rest[k][1] - poses[k][1], `body ${k + 1} rose`).to.be.within(3 * 0.1 - 9.81 * 0.01 - 0.02, 3 * 0.1 + 0.02);
      expect(asleep(h)).to.equal(0);
    });
  }
});
