// Pointer drag (constraints/grab.ts): a damped soft pin. The held point follows a moving pointer without swinging
// about it, a throw leaves at about the pointer's speed, a jump to a still pointer is met with little overshoot, and
// however far the pointer jumps the point speeds up no faster than GRAB_SPEED_LIMIT. Zero gravity unless said, so the
// numbers are the grab's alone.
import { expect } from 'chai';
import { World, createBox, createCircle, createCloth } from '../../src/engine/index.js';
import { GRAB_SPEED_LIMIT } from '../../src/engine/constraints/grab.js';
import type { Handle } from '../../src/engine/handles.js';

/** The held point of the world's one grab, in world coordinates (as the solver sees it). */
function heldPoint(world: World): { x: number; y: number } {
  const g = world.grabs;
  const p = world.particles;
  const a = g.p0[0];
  if (p.invInertia[a] !== 0) return { x: p.x[a] + p.rc[a] * g.rx[0] - p.rs[a] * g.ry[0], y: p.y[a] + p.rs[a] * g.rx[0] + p.rc[a] * g.ry[0] };
  const rows = [g.p0[0], g.p1[0], g.p2[0]];
  const weights = [g.w0[0], g.w1[0], g.w2[0]];
  let x = 0;
  let y = 0;
  for (let k = 0; k < 3; k++) {
    x += weights[k] * p.x[rows[k]];
    y += weights[k] * p.y[rows[k]];
  }
  return { x, y };
}

interface Subject {
  world: World;
  /** Where the pointer presses. */
  at: { x: number; y: number };
  /** The velocity the subject leaves with once let go (read right after the release). */
  leaving: () => number;
}

/** 1 × 1 boxes and a disc of radius 0.5 at the origin, held at their centres; a 6 × 6 cloth held at a corner. */
const SUBJECTS: Record<string, () => Subject> = {
  'rigid box': () => {
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    const body = createBox(world, { x: 0, y: 0, width: 1, height: 1 }).body;
    return { world, at: { x: 0, y: 0 }, leaving: afterRelease(world, body) };
  },
  'rigid disc': () => {
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    const body = createCircle(world, { x: 0, y: 0, radius: 0.5 }).body;
    return { world, at: { x: 0, y: 0 }, leaving: afterRelease(world, body) };
  },
  'particle-frame box': () => {
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    const body = createBox(world, { x: 0, y: 0, width: 1, height: 1, model: 'particles' }).body;
    return { world, at: { x: 0, y: 0 }, leaving: afterRelease(world, body) };
  },
  'cloth particle': () => {
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    // The cloth lies in x, y ≥ 0: dragged toward −x it trails behind its held corner.
    const cloth = createCloth(world, { origin: { x: 0, y: 0 }, columns: 6, rows: 6, spacing: 0.2, pins: 'none' });
    const corner = cloth.particles[0];
    // A cloth is floppy: its centre keeps sloshing about the held corner, so what leaves at the pointer's speed is
    // the held particle itself, at the moment it is let go.
    return { world, at: { x: 0, y: 0 }, leaving: () => world.getVelocity(corner).x };
  },
};

/** A body's speed along x over the two steps after the release. */
function afterRelease(world: World, body: Handle): () => number {
  return () => {
    const x0 = world.bodyCentroid(body).x;
    world.step();
    world.step();
    return (world.bodyCentroid(body).x - x0) / (2 * world.timestep);
  };
}

/** Drags toward −x at `v` for 0.5 s (one move a step, as a pointer at 60 Hz), lets go, returns the leaving speed. */
function throwAt(make: () => Subject, v: number): { leave: number; lag: number } {
  const s = make();
  const g = s.world.grab(s.at.x, s.at.y)!;
  expect(g).to.not.equal(null);
  for (let k = 1; k <= 30; k++) {
    s.world.moveGrab(g, s.at.x - (v * k) / 60, s.at.y);
    s.world.step();
  }
  const lag = heldPoint(s.world).x - (s.at.x - v / 2);
  s.world.release(g);
  return { leave: -s.leaving(), lag };
}

/** The pointer jumps by `jump` along +x and stays: the held point's farthest reach past it, and its top speed. */
function jumpTo(make: () => Subject, jump: number): { overshoot: number; settled: number; topSpeed: number } {
  const s = make();
  const g = s.world.grab(s.at.x, s.at.y)!;
  const start = heldPoint(s.world).x;
  s.world.moveGrab(g, s.at.x + jump, s.at.y);
  let far = -Infinity;
  let topSpeed = 0;
  let last = start;
  for (let k = 0; k < 180; k++) {
    s.world.step();
    const x = heldPoint(s.world).x;
    far = Math.max(far, x - start);
    topSpeed = Math.max(topSpeed, Math.abs(x - last) / s.world.timestep);
    last = x;
  }
  return { overshoot: far - jump, settled: heldPoint(s.world).x - start - jump, topSpeed };
}

describe('pointer drag: a damped grab', () => {
  for (const [name, make] of Object.entries(SUBJECTS)) {
    it(`${name}: dragged at constant speed then let go, it leaves at the pointer's speed; a jump is met without swinging`, () => {
      for (const v of [3, 10, 35]) {
        const { leave, lag } = throwAt(make, v);
        expect(leave / v, `leaving speed / pointer speed at ${v} u/s`).to.be.within(0.95, 1.05); // measured 0.99-1.01 (the brief asked 15%)
        // Trailing the pointer by lag × speed (2ζ/ω = 0.0358 s at the default stiffness), never ahead of it.
        expect(lag / v, `trail / speed at ${v} u/s`).to.be.closeTo(0.0358, 0.002);
      }
      for (const jump of [1, 5]) {
        const { overshoot, settled } = jumpTo(make, jump);
        expect(overshoot / jump, `overshoot / jump of ${jump}`).to.be.below(0.1);
        expect(Math.abs(settled), `rest offset after a jump of ${jump}`).to.be.below(0.03 * jump);
      }
    });
  }

  it('however far the pointer jumps, the held point speeds up no faster than GRAB_SPEED_LIMIT', () => {
    for (const name of ['rigid box', 'particle-frame box']) {
      const { topSpeed, overshoot, settled } = jumpTo(SUBJECTS[name], 60);
      expect(topSpeed, name).to.be.within(0.8 * GRAB_SPEED_LIMIT, 1.02 * GRAB_SPEED_LIMIT);
      expect(overshoot / 60, name).to.be.below(0.1);
      expect(Math.abs(settled), name).to.be.below(0.01);
    }
  });

  it('a body 100 times heavier follows the same drag as a light one (the pull scales with the mass)', () => {
    const drag = (mass: number) => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
      createBox(world, { x: 0, y: 0.5, width: 60, height: 1, static: true });
      const box = createBox(world, { x: 0, y: -0.5, width: 1, height: 1, mass }).body;
      const g = world.grab(0, -0.5)!;
      // Lift it 1 unit and carry it 6 units right in 2 s at 3 u/s.
      for (let k = 1; k <= 120; k++) {
        world.moveGrab(g, (3 * k) / 60, -0.5 - Math.min(1, k / 30));
        world.step();
      }
      const held = heldPoint(world);
      const trail = Math.hypot(held.x - 6, held.y + 1.5);
      world.release(g);
      const x0 = world.bodyCentroid(box).x;
      world.step();
      return { trail, leave: (world.bodyCentroid(box).x - x0) * 60, mass: world.bodyMassInfo(box).mass };
    };
    const light = drag(1);
    const heavy = drag(100);
    expect(heavy.mass / light.mass).to.be.closeTo(100, 1e-9);
    for (const r of [light, heavy]) {
      expect(r.trail).to.be.below(0.15); // 3 u/s × 0.036 s, and the sag under its weight, g/ω² = 0.005
      expect(r.leave).to.be.within(3 * 0.85, 3 * 1.15);
    }
    expect(heavy.trail).to.be.closeTo(light.trail, 0.01);
  });

  it('the same drag twice gives the same doubles', () => {
    const run = () => {
      const s = SUBJECTS['particle-frame box']();
      const g = s.world.grab(0.2, 0.1)!;
      for (let k = 1; k <= 40; k++) {
        s.world.moveGrab(g, 0.2 + Math.sin(k / 5), 0.1 + k / 30);
        s.world.step();
      }
      s.world.release(g);
      s.world.step();
      return s.world.stateHash();
    };
    expect(run()).to.equal(run());
  });

  it('what a press takes: the very point pressed of a turned rigid body, the movable body behind a static one, the nearest free particle within the pick radius and never a pinned one', () => {
    // A 2 × 1 rigid box turned by 0.7 rad, pressed 0.6 along its length and 0.2 across from its centre: the grab
    // holds that point of it (at 0 rad, as every other grab here is taken, a wrong sign in the turn into the body's
    // frame holds the same point). Held still, nothing moves.
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
    const turn = 0.7;
    const box = createBox(world, { x: 1, y: 2, width: 2, height: 1, angle: turn }).body;
    const at = { x: 1 + 0.6 * Math.cos(turn) - 0.2 * Math.sin(turn), y: 2 + 0.6 * Math.sin(turn) + 0.2 * Math.cos(turn) };
    const g = world.grab(at.x, at.y)!;
    expect(g).to.not.equal(null);
    const held = heldPoint(world);
    expect(held.x).to.be.closeTo(at.x, 1e-12);
    expect(held.y).to.be.closeTo(at.y, 1e-12);
    for (let k = 0; k < 60; k++) world.step();
    expect(world.bodyCentroid(box).x).to.be.closeTo(1, 1e-9);
    expect(world.bodyCentroid(box).y).to.be.closeTo(2, 1e-9);
    expect(world.bodyPose(box).angle).to.be.closeTo(turn, 1e-9);
    world.release(g);

    // A static box drawn over a movable one (created after it): the press takes the movable one; on the static one
    // alone, nothing.
    const stack = new World({ gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
    const crate = createBox(stack, { x: 0, y: 0, width: 1, height: 1 }).body;
    createBox(stack, { x: 0.5, y: 0, width: 1, height: 1, static: true });
    expect(stack.grab(1.7, 0), 'on nothing').to.equal(null);
    expect(stack.grab(0.9, 0), 'on the static box alone').to.equal(null);
    const under = stack.grab(0.2, 0)!;
    expect(under, 'on the crate under the static box').to.not.equal(null);
    stack.moveGrab(under, 0.2, 3);
    for (let k = 0; k < 120; k++) stack.step();
    // The pressed point of the crate follows the pointer 3 down (the crate swinging about it), the crate with it.
    expect(Math.hypot(heldPoint(stack).x - 0.2, heldPoint(stack).y - 3), 'the held point at the pointer').to.be.below(0.05);
    expect(stack.bodyCentroid(crate).y, 'the crate pulled down').to.be.closeTo(3, 0.5);

    // Particles: a pinned one is never taken; the nearest free one within the pick radius (0.5 unless said) is.
    const free = new World({ gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
    const pinned = free.addParticle({ x: 0, y: 0 });
    free.addPin(pinned);
    const loose = free.addParticle({ x: 0.4, y: 0 });
    const first = free.grab(0, 0)!;
    expect(first, 'the free particle 0.4 away').to.not.equal(null);
    expect(heldPoint(free)).to.deep.equal({ x: 0.4, y: 0 });
    free.release(first);
    expect(free.grab(-0.11, 0), 'the free particle 0.51 away').to.equal(null);
    expect(free.grab(0.4, 0.6), '0.6 away').to.equal(null);
    expect(free.grab(0.4, 0.6, { pickRadius: 0.61 }), '0.6 away, picked within 0.61').to.not.equal(null);
    expect(free.getPosition(loose)).to.deep.equal({ x: 0.4, y: 0 });
  });
});
