import { expect } from 'chai';
import { createRope, World, INTEGRATORS } from '../../src/engine/index.js';
import { AUTO_SUBSTEPS } from '../../src/engine/settings.js';
import { box, totalEnergy } from './helpers.js';

describe('integrators', () => {
  it('position Verlet follows y0 + v0·t + ½·g·t² exactly for constant gravity', () => {
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    const p = world.addParticle({ x: 0, y: 2, vx: 3, vy: -4 });
    for (let k = 0; k < 120; k++) world.step();
    const t = world.time;
    const pos = world.getPosition(p);
    expect(t).to.be.closeTo(2, 1e-12);
    expect(pos.x).to.be.closeTo(3 * t, 1e-9);
    expect(pos.y).to.be.closeTo(2 - 4 * t + 0.5 * 9.81 * t * t, 1e-9);
  });

  it('a particle at rest in the air stays there when gravity is switched off (setter and setGravity)', () => {
    for (const change of ['setGravity', 'setter'] as const) {
      const world = new World({ gravity: { x: 0, y: 9.81 } });
      const p = world.addParticle({ x: 1, y: 2 });
      if (change === 'setGravity') world.setGravity(0, 0);
      else world.gravity = { x: 0, y: 0 };
      for (let k = 0; k < 600; k++) world.step();
      // It drifted by ½·g·h·t = 0.5 · 9.81 · (1/600) · 10 ≈ 0.08 before the stored velocity was shifted.
      expect(world.getPosition(p).y, change).to.be.closeTo(2, 1e-9);
      expect(world.getPosition(p).x, change).to.be.closeTo(1, 1e-12);
    }
  });

  it('a gravity change keeps rigid bodies\' and pinned particles\' velocities, wakes sleeping bodies at rest, and keeps a velocity across Euler → Verlet', () => {
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    const ball = world.addRigidBody({ x: 0, y: 0, radius: 0.5 });
    const pinned = world.addParticle({ x: 5, y: 0 });
    world.addPin(pinned);
    const free = world.addParticle({ x: 10, y: 0 });
    for (let k = 0; k < 30; k++) world.step();
    world.setGravity(0, 0);
    const [ballAt, freeAt] = [world.bodyPose(ball).y, world.getPosition(free).y];
    for (let k = 0; k < 30; k++) world.step();
    // The rigid ball keeps the g·t it had when gravity went (its stored v − ½·g·h shifted to v), and goes on at that
    // speed, as the free particle does.
    expect(world.bodyVelocity(ball).y).to.be.closeTo(9.81 * 0.5, 1e-9);
    expect(world.bodyPose(ball).y - ballAt).to.be.closeTo(9.81 * 0.5 * 0.5, 1e-9);
    expect(world.getPosition(free).y - freeAt).to.be.closeTo(9.81 * 0.5 * 0.5, 1e-9);
    expect(world.getPosition(pinned)).to.deep.equal({ x: 5, y: 0 });
    expect(world.getVelocity(pinned)).to.deep.equal({ x: 0, y: 0 });
    // A particle set moving under semi-implicit Euler keeps that velocity on the switch to Verlet.
    const euler = new World({ gravity: { x: 0, y: 9.81 }, integrator: 'semi-implicit-euler' });
    const p = euler.addParticle({ x: 0, y: 0, vx: 2 });
    euler.integrator = 'verlet';
    for (let k = 0; k < 60; k++) euler.step();
    expect(euler.getPosition(p).x).to.be.closeTo(2, 1e-9);
    expect(euler.getPosition(p).y).to.be.closeTo(0.5 * 9.81, 1e-9);
    // A sleeping body's rows hold no velocity: the change wakes it at rest, and it falls the new way from there.
    const pile = new World({ gravity: { x: 0, y: 9.81 }, bounds: { minX: -5, minY: -10, maxX: 5, maxY: 0 } });
    const rest = pile.addParticle({ x: 0, y: -0.5, radius: 0.5 });
    pile.addBody('particle', [rest], [], { shape: 'particles' });
    for (let k = 0; k < 600; k++) pile.step();
    const before = pile.getPosition(rest);
    pile.gravity = { x: 0, y: -9.81 };
    // (Its stored velocity is v − ½·g·h: within a substep's gravity of rest.)
    expect(Math.abs(pile.getVelocity(rest).y)).to.be.at.most(9.81 / 600 + 1e-12);
    for (let k = 0; k < 60; k++) pile.step();
    expect(pile.getPosition(rest).y).to.be.closeTo(before.y - 0.5 * 9.81, 0.02);
  });

  it('position Verlet follows the exact path when gravity changes in flight', () => {
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    const p = world.addParticle({ x: 0, y: 0, vx: 2, vy: -5 });
    for (let k = 0; k < 30; k++) world.step();
    const t1 = world.time;
    const y1 = -5 * t1 + 0.5 * 9.81 * t1 * t1;
    const vy1 = -5 + 9.81 * t1;
    world.setGravity(3, -2);
    for (let k = 0; k < 60; k++) world.step();
    const t = world.time - t1;
    const pos = world.getPosition(p);
    expect(pos.x).to.be.closeTo(2 * (t1 + t) + 0.5 * 3 * t * t, 1e-9);
    expect(pos.y).to.be.closeTo(y1 + vy1 * t - 0.5 * 2 * t * t, 1e-9);
  });

  it('a thrown rigid body follows x0 + v0·t + ½·g·t² exactly, as a particle does, alone (the rigid substeps) or beside particles', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      for (const withParticles of [false, true]) {
        const name = `${kernel}, ${withParticles ? 'beside a particle' : 'rigid bodies alone'}`;
        const world = new World({ gravity: { x: 1, y: 10 }, kernel, sleeping: false });
        const disc = world.addRigidBody({ radius: 0.5, x: 0, y: 0, vx: 3, vy: -8, angularVelocity: 2, collide: false });
        const plate = world.addRigidBody({ points: box(1, 0.25), x: 5, y: 0, vx: -2, vy: -4, collide: false });
        const p = withParticles ? world.addParticle({ x: 10, y: 0, vx: 3, vy: -8 }) : null;
        for (let k = 0; k < 90; k++) world.step();
        const t = world.time;
        expect(world.substepCount, name).to.equal(withParticles ? AUTO_SUBSTEPS.particles : AUTO_SUBSTEPS.rigid);
        // Storing v itself, as rigid rows did, led the path by ½·g·h·t: 0.0125 units here after 1.5 s at 6 substeps.
        const d = world.bodyPose(disc);
        expect(d.x, name).to.be.closeTo(3 * t + 0.5 * t * t, 1e-9);
        expect(d.y, name).to.be.closeTo(-8 * t + 5 * t * t, 1e-9);
        expect(d.angle, name).to.be.closeTo(2 * t, 1e-9);
        const b = world.bodyPose(plate);
        expect(b.x, name).to.be.closeTo(5 - 2 * t + 0.5 * t * t, 1e-9);
        expect(b.y, name).to.be.closeTo(-4 * t + 5 * t * t, 1e-9);
        // The particle thrown alike is where the disc is, 10 to its right.
        if (p) expect(world.getPosition(p).x - 10, name).to.be.closeTo(d.x, 1e-9);
        if (p) expect(world.getPosition(p).y, name).to.be.closeTo(d.y, 1e-9);
      }
    }
  });

  it('a rigid body in flight keeps to its exact path through changes of gravity, timestep and substeps, particles joining and leaving, steps of any length, a throw, a kinematic spell and a snapshot', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ gravity: { x: 0, y: 10 }, kernel, sleeping: false, variableStep: true });
      const ball = world.addRigidBody({ radius: 0.5, x: 0, y: 0, collide: false });
      // The exact path, phase by phase: position and velocity under a constant gravity g for a time τ.
      const at = { x: 0, y: 0, vx: 0, vy: 0 };
      const fly = (tau: number, g: { x: number; y: number }) => {
        at.x += at.vx * tau + 0.5 * g.x * tau * tau;
        at.y += at.vy * tau + 0.5 * g.y * tau * tau;
        at.vx += g.x * tau;
        at.vy += g.y * tau;
      };
      const phase = (name: string, steps: number, take: (k: number) => number = () => (world.step(), world.timestep)) => {
        const g = { ...world.gravity };
        for (let k = 0; k < steps; k++) fly(take(k), world.bodyType(ball) === 'kinematic' ? { x: 0, y: 0 } : g);
        const pose = world.bodyPose(ball);
        expect(pose.x, `${kernel}: ${name}`).to.be.closeTo(at.x, 1e-9);
        expect(pose.y, `${kernel}: ${name}`).to.be.closeTo(at.y, 1e-9);
      };
      phase('falling from rest', 30);
      world.setGravity(1, 4);
      phase('gravity changed', 30);
      const rope = createRope(world, { from: { x: 100, y: 0 }, to: { x: 104, y: 0 }, segments: 4 });
      phase('a rope joined: the particle substeps', 30);
      expect(world.substepCount).to.equal(AUTO_SUBSTEPS.particles);
      world.removeBody(rope.body);
      phase('the rope gone: the rigid substeps again', 20);
      expect(world.substepCount).to.equal(AUTO_SUBSTEPS.rigid);
      world.timestep = 1 / 90;
      phase('timestep 1/90', 45);
      world.substeps = 7;
      phase('7 substeps', 30);
      const lengths = [1 / 60, 1 / 30, 1 / 120, 1 / 45, 1 / 24, 1 / 90];
      phase('steps of varying length', 18, (k) => (world.step(lengths[k % 6]), lengths[k % 6]));
      world.setBodyVelocity(ball, 2, -3);
      [at.vx, at.vy] = [2, -3];
      phase('thrown again', 30);
      world.setBodyType(ball, 'kinematic');
      phase('kinematic: straight on at its speed', 30);
      world.setBodyType(ball, 'dynamic');
      phase('dynamic again', 30);
      const copy = new World({ kernel });
      copy.restore(world.snapshot());
      phase('the original after a snapshot', 30);
      for (let k = 0; k < 30; k++) copy.step();
      expect(copy.bodyPose(ball), `${kernel}: the copy`).to.deep.equal(world.bodyPose(ball));
    }
  });

  it('a falling particle keeps to ½·g·t² when the timestep or the substeps change, and reads g·t on leaving Verlet', () => {
    const changes: [string, (w: World) => void][] = [
      ['substeps 10 → 3', (w) => (w.substeps = 3)],
      ['substeps auto → 25', (w) => (w.substeps = 25)],
      ['timestep 1/60 → 1/90', (w) => (w.timestep = 1 / 90)],
    ];
    for (const [name, change] of changes) {
      const world = new World({ gravity: { x: 0, y: 9.81 }, substeps: name.startsWith('substeps 10') ? 10 : 'auto' });
      const p = world.addParticle({ x: 0, y: 0 });
      for (let k = 0; k < 30; k++) world.step();
      change(world);
      for (let k = 0; k < 45; k++) world.step();
      const t = world.time;
      expect(world.getPosition(p).y, name).to.be.closeTo(0.5 * 9.81 * t * t, 1e-9);
    }
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    const p = world.addParticle({ x: 0, y: 0 });
    for (let k = 0; k < 30; k++) world.step();
    world.integrator = 'semi-implicit-euler';
    expect(world.getVelocity(p).y).to.be.closeTo(9.81 * world.time, 1e-9);
  });

  it('a thrown particle keeps to its parabola through steps of varying length (variableStep, step(dt))', () => {
    // Frame times of a page that stutters: from 1/120 to 1/24 of a second.
    const lengths = [1 / 60, 1 / 30, 1 / 120, 1 / 45, 1 / 60, 1 / 24, 1 / 90, 1 / 60];
    const runs: [string, (w: World, dt: number) => void][] = [
      ['variableStep advance()', (w, dt) => w.advance(dt)],
      ['step(dt)', (w, dt) => w.step(dt)],
    ];
    for (const [name, take] of runs) {
      const world = new World({ gravity: { x: 1, y: 10 }, variableStep: true, sleeping: false });
      const p = world.addParticle({ x: 0, y: 0, vx: 3, vy: -20 });
      let t = 0;
      for (let k = 0; k < 80; k++) {
        const dt = lengths[k % lengths.length];
        take(world, dt);
        t += dt;
      }
      const at = world.getPosition(p);
      expect(at.x, name).to.be.closeTo(3 * t + 0.5 * t * t, 1e-9);
      expect(at.y, name).to.be.closeTo(-20 * t + 5 * t * t, 1e-9);
      // Back on the fixed step, it goes on along the same parabola.
      for (let k = 0; k < 30; k++) world.step();
      const t2 = t + 30 / 60;
      expect(world.getPosition(p).y, name).to.be.closeTo(-20 * t2 + 5 * t2 * t2, 1e-9);
    }
  });

  it('damping keeps 1/(1 + h·c) of a free particle\'s velocity each substep, with every integrator', () => {
    // Only Verlet's damping was measured (spin.test.ts, constraints.test.ts): either Euler could leave it out.
    for (const integrator of ['verlet', 'semi-implicit-euler', 'explicit-euler'] as const) {
      const world = new World({ integrator, gravity: { x: 0, y: 0 }, damping: 0.5, substeps: 10, sleeping: false, bounds: null });
      const p = world.addParticle({ x: 0, y: 0, vx: 3, vy: -2 });
      for (let k = 0; k < 60; k++) world.step();
      const kept = (1 / (1 + (0.5 * 1) / 600)) ** 600;
      expect(kept, 'the case: a tenth or more gone').to.be.below(0.9);
      const v = world.getVelocity(p);
      expect(v.x, integrator).to.be.closeTo(3 * kept, 1e-9);
      expect(v.y, integrator).to.be.closeTo(-2 * kept, 1e-9);
    }
  });

  it('the Euler variants drift from the analytic free fall by O(h), Verlet does not', () => {
    const errors = INTEGRATORS.map((integrator) => {
      const world = new World({ gravity: { x: 0, y: 10 }, integrator, substeps: 1 });
      const p = world.addParticle({ x: 0, y: 0 });
      for (let k = 0; k < 60; k++) world.step();
      return Math.abs(world.getPosition(p).y - 5);
    });
    expect(errors[0]).to.be.below(1e-9);
    // ½·g·h·t = 0.5 · 10 · (1/60) · 1 for both Euler variants, with opposite signs.
    expect(errors[1]).to.be.closeTo(1 / 12, 1e-9);
    expect(errors[2]).to.be.closeTo(1 / 12, 1e-9);
  });

  it('explicit Euler gains energy on an undamped spring; Verlet and semi-implicit Euler stay bounded', () => {
    const drift: Record<string, number> = {};
    for (const integrator of INTEGRATORS) {
      const world = new World({ gravity: { x: 0, y: 0 }, integrator, substeps: 1, timestep: 1 / 60 });
      const anchor = world.addParticle({ x: 0, y: 0, mass: Infinity });
      const bob = world.addParticle({ x: 1.2, y: 0, mass: 1 });
      world.addSpring(anchor, bob, { length: 1, stiffness: 100 });
      const energy = () => {
        const v = world.getVelocity(bob);
        const d = world.getPosition(bob).x;
        return 0.5 * (v.x ** 2 + v.y ** 2) + 0.5 * 100 * (d - 1) ** 2;
      };
      const e0 = energy();
      let worst = 0;
      for (let k = 0; k < 600; k++) {
        world.step();
        worst = Math.max(worst, energy() / e0);
      }
      drift[integrator] = worst;
    }
    expect(drift['explicit-euler']).to.be.above(10); // grows without bound (≈ (1 + ω²h²)^(n/2))
    expect(drift['verlet']).to.be.below(1.2);
    expect(drift['semi-implicit-euler']).to.be.below(1.2);
  });

  it('linear damping removes energy from a thrown particle', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, damping: 1 });
    const p = world.addParticle({ x: 0, y: 0, vx: 10 });
    for (let k = 0; k < 60; k++) world.step();
    // v(t) ≈ v0·e^(−t) for small h.
    expect(world.getVelocity(p).x).to.be.closeTo(10 * Math.exp(-1), 0.01);
    expect(totalEnergy(world)).to.be.below(0.5 * 100);
  });

  it('forces and impulses change motion by F/m and J/m', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const a = world.addParticle({ x: 0, y: 0, mass: 2 });
    world.applyImpulse(a, 4, 0);
    expect(world.getVelocity(a).x).to.equal(2);
    const b = world.addParticle({ x: 0, y: 0, mass: 2 });
    world.applyForce(b, 0, 12); // for one step only: Δv = F/m · dt
    world.step();
    expect(world.getVelocity(b).y).to.be.closeTo(6 / 60, 1e-12);
    world.step();
    expect(world.getVelocity(b).y).to.be.closeTo(6 / 60, 1e-12);
  });
});
