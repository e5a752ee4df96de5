// The step's last phase (pipeline/guard.ts): no row leaves a step with a value that is not finite or a runaway speed,
// and the rest of the world keeps running. First the phase alone, on rows broken by hand; then 60 random tangles of
// joints that the solver cannot resolve (limits, motors, welds, sliders and rods, kinematic and static members, loops,
// masses 10⁶ apart, anchors up to 3 sizes off): without the guard 15 to 21 of them reached NaN within 300 steps.
import { expect } from 'chai';
import { World, type Handle } from '../../../src/engine/index.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import { keepRowsFinite, RUNAWAY_SPEED } from '../../../src/engine/pipeline/guard.js';
import { handleSlot } from '../../../src/engine/handles.js';
import { rng } from '../collision/helpers.js';
import { box } from '../helpers.js';

function contextOf(world: World): StepContext {
  return (world as unknown as { ctx: StepContext }).ctx;
}


/** Every row's position, angle and velocities finite. */
function rowsFinite(world: World): boolean {
  const p = world.particles;
  for (const column of [p.x, p.y, p.px, p.py, p.vx, p.vy, p.angle, p.omega, p.rc, p.rs]) {
    for (let i = 0; i < p.count; i++) if (!Number.isFinite(column[i])) return false;
  }
  return true;
}

/** A random tangle of `count` bodies and their joints (see the file's head), its seed `seed`. */
function tangle(world: World, seed: number): Handle[] {
  const rnd = rng(seed);
  const bodies: Handle[] = [];
  const count = 2 + Math.floor(rnd() * 11);
  for (let k = 0; k < count; k++) {
    const size = 0.1 + rnd() * 2;
    const x = (rnd() * 2 - 1) * 4;
    const y = (rnd() * 2 - 1) * 4;
    const t = rnd();
    const type = t < 0.1 ? 'static' : t < 0.2 ? 'kinematic' : 'dynamic';
    const body = world.addRigidBody({
      ...(rnd() < 0.4 ? { radius: size / 2 } : { points: box(size / 2, size / (2 + rnd() * 6)) }),
      x, y, angle: rnd() * 6, density: 10 ** (rnd() * 6 - 3) / (size * size), collide: rnd() < 0.3, type,
      ...(type === 'kinematic' ? { vx: rnd() - 0.5, angularVelocity: rnd() * 2 - 1 } : {}),
    });
    const reach = [0, size / 2, 2 * size, 3 * size][Math.floor(rnd() * 4)];
    const anchor = { x: x + (rnd() * 2 - 1) * reach, y: y + (rnd() * 2 - 1) * reach };
    for (let j = rnd() < 0.3 ? 2 : 1; j > 0; j--) {
      const b = bodies.length === 0 || rnd() < 0.15 ? null : bodies[Math.floor(rnd() * bodies.length)];
      const kind = rnd();
      const soft = rnd() < 0.2 ? { compliance: 10 ** (-6 + rnd() * 4) } : {};
      if (kind < 0.55) {
        const limit = rnd() < 0.4 ? { lowerAngle: -rnd(), upperAngle: rnd() } : {};
        const motor = rnd() < 0.3 ? { motorSpeed: (rnd() * 2 - 1) * 5, maxMotorTorque: 10 ** (rnd() * 6 - 2) } : {};
        world.addJoint({ type: 'revolute', a: body, b, anchor, ...limit, ...motor, ...soft });
      } else if (kind < 0.7) world.addJoint({ type: 'weld', a: body, b, anchor, ...soft });
      else if (kind < 0.85) world.addJoint({ type: 'prismatic', a: body, b, anchor, axis: { x: rnd() - 0.5, y: rnd() - 0.5 }, ...(rnd() < 0.5 ? { lower: -1, upper: 1 } : {}) });
      else world.addJoint({ type: 'distance', a: body, b, anchorA: anchor, ...(rnd() < 0.5 ? { lower: 0.5, upper: 2 } : {}), ...soft });
    }
    bodies.push(body);
  }
  return bodies;
}

describe('the step guard: no row leaves a step with a value that is not finite', () => {
  it('puts a row that is not finite or runs away back where the step started, at rest; counts them; leaves sound rows alone', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    const disc = world.addRigidBody({ radius: 0.5, x: 0, y: 0, angularVelocity: 2 });
    const fast = world.addRigidBody({ radius: 0.5, x: 5, y: 0 });
    const spun = world.addRigidBody({ radius: 0.5, x: 10, y: 0 });
    const sound = world.addRigidBody({ radius: 0.5, x: 15, y: 0, vx: 3 });
    const quick = world.addRigidBody({ radius: 0.5, x: 20, y: 0, angularVelocity: 2 });
    world.step();
    const p = world.particles;
    const [d, f, s, o, q] = [disc, fast, spun, sound, quick].map((h) => handleSlot(world.bodyParticleHandles(h)[0]));
    const before = (i: number): number[] => [p.x[i], p.y[i], p.angle[i], p.vx[i], p.vy[i], p.omega[i]];
    const started = (i: number): number[] => [p.sx[i], p.sy[i], p.sangle[i], 0, 0, 0];
    const sound0 = before(o);
    p.x[d] = NaN;
    p.omega[d] = Infinity;
    p.vx[f] = 3e15;
    p.vy[f] = -4e15;
    p.omega[s] = -NaN;
    p.vx[s] = 7;
    // Past MAX_SPEED (what the API accepts) but within RUNAWAY_SPEED: a body gravity took past the limit keeps going.
    p.vy[q] = RUNAWAY_SPEED / 2;
    p.omega[q] = -RUNAWAY_SPEED / 2;
    const quick0 = before(q);
    const ctx = contextOf(world);
    expect(keepRowsFinite(ctx)).to.equal(3);
    for (const i of [d, f, s]) expect(before(i), `row ${i}`).to.deep.equal(started(i));
    expect([p.rc[d], p.rs[d]]).to.deep.equal([Math.cos(p.sangle[d]), Math.sin(p.sangle[d])]);
    expect(before(o)).to.deep.equal(sound0);
    expect(before(q)).to.deep.equal(quick0);
    expect(world.diagnostics().rowsRepaired).to.equal(3);
    p.vy[q] = 0;
    p.omega[q] = 0;
    expect(keepRowsFinite(ctx), 'nothing left to repair').to.equal(0);
    for (let k = 0; k < 10; k++) world.step();
    expect(rowsFinite(world)).to.equal(true);
    expect(world.diagnostics().rowsRepaired).to.equal(3);
  });

  it('60 random tangles of driven and looped joints stay finite in both kernels, and a body beside them falls as if alone', () => {
    let repaired = 0;
    const speeds: number[] = [];
    for (let scene = 0; scene < 60; scene++) {
      const kernel = scene % 2 ? 'wasm' : 'js';
      const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false });
      const bodies = tangle(world, 777 + scene);
      // Far from the tangle, touching nothing: it must fall on its parabola whatever the tangle does.
      const bystander = world.addRigidBody({ radius: 0.5, x: 1000, y: 0, collide: false });
      let fastest = 0;
      for (let s = 0; s < 300; s++) {
        world.step();
        expect(rowsFinite(world), `scene ${scene} (${kernel}), step ${s}`).to.equal(true);
        for (const h of bodies) fastest = Math.max(fastest, Math.abs(world.bodyAngularVelocity(h)), Math.hypot(world.bodyVelocity(h).x, world.bodyVelocity(h).y));
      }
      speeds.push(fastest);
      // 300 steps of 1/60 s from rest: y = g·t²/2 (position Verlet's substeps keep to it within rounding).
      const t = 300 / 60;
      expect(world.bodyPose(bystander).y, `scene ${scene} (${kernel}): the bystander`).to.be.closeTo((10 * t * t) / 2, 0.01 * t * t);
      for (const h of bodies) expect(Number.isFinite(world.bodyPose(h).x), `scene ${scene} (${kernel})`).to.equal(true);
      if (world.diagnostics().rowsRepaired > 0) repaired++;
    }
    // The tangles are real: bodies in a third of them pass 1,000 units/s (or rad/s), and until the forests' turns were
    // capped (joint-tree.ts, TREE_MAX_TURN) the guard had rows to put back in 4 or 5 of them (15 before the lopsided
    // retry and the loop solve, 4 with the retry alone, 6 before its retry took half-way levers in the subtree); now in
    // none.
    const violent = speeds.filter((v) => v > 1000).length;
    console.log(`      bodies passed 1,000 units/s in ${violent} of 60 tangles; the guard put rows back in ${repaired}`);
    expect(violent).to.be.above(10);
  });
});
