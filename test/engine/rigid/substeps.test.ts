// The substep choice: `substeps: 'auto'` (the default) takes AUTO_SUBSTEPS.rigid substeps while every body that moves
// is a rigid body, AUTO_SUBSTEPS.particles as soon as a particle-built body moves; an explicit count always wins.
import { expect } from 'chai';
import { createBox, createCloth, createRope, World } from '../../../src/engine/index.js';
import { AUTO_SUBSTEPS } from '../../../src/engine/settings.js';
import { box } from '../helpers.js';


describe('rigid bodies: the substep choice', () => {
  it("'auto' is the default: rigid, static and kinematic bodies and joints take the rigid count; a moving particle body the particle count", () => {
    expect(AUTO_SUBSTEPS.rigid).to.be.lessThan(AUTO_SUBSTEPS.particles);
    const world = new World({ sleeping: false });
    expect(world.substeps).to.equal('auto');
    world.addRigidBody({ points: box(10, 0.5), x: 0, y: 0.5, type: 'static' });
    const a = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -2 });
    world.addRigidBody({ points: box(1, 0.1), x: 5, y: -1, type: 'kinematic', angularVelocity: 1 });
    world.addJoint({ type: 'revolute', a, anchor: { x: 0, y: -3 } });
    // A static particle frame does not move: still rigid only.
    createBox(world, { x: -5, y: -1, width: 1, height: 1, model: 'particles', static: true });
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.rigid);
    expect(world.substepDt).to.be.closeTo(1 / 60 / AUTO_SUBSTEPS.rigid, 1e-15);
    // The motion follows: after one step of free fall from rest a body's velocity (the mean over the last substep)
    // is g·(dt − h/2), which tells the substep h the step really took; it has fallen g·dt²/2 exactly.
    const free = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
    const b = free.addRigidBody({ points: box(0.5, 0.5), x: 0, y: 0, collide: false });
    free.step();
    const n = AUTO_SUBSTEPS.rigid;
    expect(free.bodyVelocity(b).y).to.be.closeTo(10 * (1 / 60 - 1 / 120 / n), 1e-12);
    expect(free.bodyPose(b).y).to.be.closeTo(5 / 3600, 1e-12);
    // A rope joins: the particle count, until it is removed again.
    const rope = createRope(world, { from: { x: 8, y: -5 }, to: { x: 10, y: -5 }, segments: 4 });
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.particles);
    world.removeBody(rope.body);
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.rigid);
    const cloth = createCloth(world, { origin: { x: 12, y: -5 }, columns: 3, rows: 3, spacing: 0.5, pins: 'none' });
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.particles);
    world.removeBody(cloth.body);
    const particle = world.addParticle({ x: 20, y: -5 });
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.particles);
    world.removeParticle(particle);
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.rigid);
  });

  it("building under 'auto' does not rebuild the topology for every particle, and a thrown particle keeps its exact path", () => {
    // Every particle a builder adds gets a velocity, which depends on the substep length; reading the count through
    // the topology made building a 600 × 400 cloth take minutes (a rebuild per particle).
    const world = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
    const sleep = (world as unknown as { ctx: { sleep: { rebuild: (...a: unknown[]) => void } } }).ctx.sleep;
    const rebuild = sleep.rebuild.bind(sleep);
    let rebuilds = 0;
    sleep.rebuild = (...a: unknown[]) => {
      rebuilds++;
      rebuild(...a);
    };
    createCloth(world, { origin: { x: 0, y: 0 }, columns: 30, rows: 30, spacing: 0.1, pins: [0, 29] });
    expect(rebuilds).to.be.at.most(1);
    // x0 + v0·t + ½·g·t² exactly, at the particle count 'auto' takes once a particle moves.
    const thrown = world.addParticle({ x: 10, y: 0, vx: 2, vy: -3 });
    for (let k = 0; k < 30; k++) world.step();
    const t = 30 / 60;
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.particles);
    expect(world.getPosition(thrown).x).to.be.closeTo(10 + 2 * t, 1e-9);
    expect(world.getPosition(thrown).y).to.be.closeTo(-3 * t + 5 * t * t, 1e-9);
  });

  it('an explicit count wins, in the constructor or set later; snapshots keep the choice; bad values throw', () => {
    const world = new World({ substeps: 3 });
    world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: 0 });
    expect(world.substepCount).to.equal(3);
    world.substeps = 12;
    expect(world.substepCount).to.equal(12);
    world.substeps = 'auto';
    expect(world.substepCount).to.equal(AUTO_SUBSTEPS.rigid);
    const copy = new World();
    copy.restore(world.snapshot());
    expect(copy.substeps).to.equal('auto');
    world.substeps = 7;
    copy.restore(world.snapshot());
    expect(copy.substeps).to.equal(7);
    for (const bad of [0, 2.5, -1, 'fast', null]) {
      expect(() => new World({ substeps: bad as never }), String(bad)).to.throw(/substeps/);
      expect(() => (world.substeps = bad as never), String(bad)).to.throw(/substeps/);
    }
    expect(world.substeps).to.equal(7);
  });
});
