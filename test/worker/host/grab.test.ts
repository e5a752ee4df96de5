// The host's grab policy (src/worker/host/grab.ts): a press inside a soft ring that the engine's own pick does not
// take (a ring that does not collide has no collision shape to find, and its particles are farther than the pick
// radius, 0.5) falls back to the ring's particle nearest the press, held at the pressed point.
import { expect } from 'chai';
import type { BodyDescription } from '../../../src/engine/index.js';
import { decode, makeHost } from './harness.js';

/** Ring of radius 1.5 about (10, 4), 16 particles: particle k at angle 2πk/16. */
const CENTER = { x: 10, y: 4 };
const R = 1.5;
const N = 16;
/** Pressed 0.63 from the centre, 0.8703 from the nearest ring particle (k = 1, at 22.5°) and 0.92 from the next (k = 0). */
const PRESS = { x: 10.6, y: 4.2 };

function ringAt(k: number): [number, number] {
  const t = (2 * Math.PI * k) / N;
  return [CENTER.x + R * Math.cos(t), CENTER.y + R * Math.sin(t)];
}

describe('EngineHost grab: a press inside a soft ring the engine does not pick', () => {
  // The nearest particle, found by brute force over the ring, and its distance: past the engine's pick radius.
  const dist = (k: number) => Math.hypot(ringAt(k)[0] - PRESS.x, ringAt(k)[1] - PRESS.y);
  const nearest = Array.from({ length: N }, (_, k) => k).reduce((a, b) => (dist(b) < dist(a) ? b : a));

  it('the setting: the nearest ring particle is k = 1, 0.87 away (more than the pick radius 0.5)', () => {
    expect(nearest).to.equal(1);
    expect(dist(1)).to.be.closeTo(0.8703, 1e-4);
    expect(Math.hypot(PRESS.x - CENTER.x, PRESS.y - CENTER.y)).to.be.greaterThan(0.5);
  });

  for (const model of ['pressure', 'springs'] as const) {
    it(`${model} ring without collisions: the press takes its nearest ring particle and pulls it to the pointer`, () => {
      const h = makeHost();
      const desc: BodyDescription = { type: 'softbody', center: CENTER, radius: R, segments: N, model, collide: false };
      h.host.load({ world: { gravity: { x: 0, y: 0 }, bounds: null, sleeping: false }, bodies: [{ key: 1, desc }], links: [] });
      // The engine alone finds nothing there: no body at the point.
      expect(h.host.bodiesAt(PRESS.x, PRESS.y)).to.deep.equal([]);
      const g = h.host.grab(PRESS.x, PRESS.y);
      expect(g, 'a grab').to.be.a('number');
      const indices = h.topology.bodies[0].indices;
      const held = () => decode(h.frame).positions[indices[nearest]];
      // Held still at the press: ring particle 1 (not the springs model's hub, nearer) is pulled the 0.87 to the
      // pointer, the ring with it (in zero gravity it goes on turning about the held particle).
      h.host.step(60);
      expect(Math.hypot(held()[0] - PRESS.x, held()[1] - PRESS.y), 'particle 1 at the pointer').to.be.below(0.02);
      // Dragged 2 down over 40 steps, then held: the particle at the pointer.
      for (let k = 1; k <= 40; k++) {
        h.host.moveGrab(g!, PRESS.x, PRESS.y + (2 * k) / 40);
        h.host.step(1);
      }
      h.host.step(60);
      expect(Math.hypot(held()[0] - PRESS.x, held()[1] - (PRESS.y + 2)), 'particle 1 at the dragged pointer').to.be.below(0.02);
      h.host.release(g!);
    });
  }

  it('a press outside the ring, or on nothing, takes nothing', () => {
    const h = makeHost();
    const desc: BodyDescription = { type: 'softbody', center: CENTER, radius: R, segments: N, collide: false };
    h.host.load({ world: { gravity: { x: 0, y: 0 }, bounds: null, sleeping: false }, bodies: [{ key: 1, desc }], links: [] });
    // 0.6 outside the ring's rightmost particle: past the pick radius, outside the loop.
    expect(h.host.grab(CENTER.x + R + 0.6, CENTER.y)).to.equal(null);
    expect(h.host.grab(0, 0)).to.equal(null);
  });
});
