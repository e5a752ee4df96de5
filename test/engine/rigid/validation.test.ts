// Bad input to the rigid-body and joint API: a TypeError/RangeError naming the argument and its value, and the world
// untouched (no half-made body, no NaN in the state).
import { expect } from 'chai';
import { buildBody, createBox, createCloth, World, type Vec2 } from '../../../src/engine/index.js';
import { throwsNaming } from '../collision/helpers.js';

const square: Vec2[] = [
  { x: -0.5, y: -0.5 },
  { x: 0.5, y: -0.5 },
  { x: 0.5, y: 0.5 },
  { x: -0.5, y: 0.5 },
];

describe('rigid bodies: bad input', () => {
  it('addRigidBody names the option at fault and leaves the world as it was', () => {
    const world = new World();
    const before = world.stateHash();
    throwsNaming(() => world.addRigidBody(null as never), TypeError, 'rigid body options');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0 }), TypeError, 'points', 'radius', 'outlines');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, points: square }), TypeError, 'one of');
    throwsNaming(() => world.addRigidBody({ x: Number.NaN, y: 0, radius: 1 }), RangeError, 'x', 'NaN');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: -1 }), RangeError, 'radius', '-1');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: square.slice(0, 2) }), RangeError, 'points', '2');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }] }), RangeError, 'points', 'area');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: [{ x: 0, y: 0 }, { x: 1e200, y: 0 }, { x: 0, y: 1e200 }] }), RangeError, 'points[1].x', '1e+200');
    // Coordinates beyond ±1e9: the position, an outline point, a radius.
    throwsNaming(() => world.addRigidBody({ x: 1e12, y: 0, radius: 1 }), RangeError, 'x must be within ±1e9', '1000000000000');
    throwsNaming(() => world.addRigidBody({ x: 0, y: -1e12, radius: 1 }), RangeError, 'y must be within ±1e9', '-1000000000000');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1e12 }), RangeError, 'radius must be within ±1e9', '1000000000000');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: [...square.slice(0, 3), { x: -0.5, y: 1e12 }] }), RangeError, 'points[3].y must be within ±1e9');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, outlines: [square, [{ x: 1e12, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }]] }), RangeError, 'outlines[1][0].x must be within ±1e9');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, type: 'floating' as never }), RangeError, 'type', 'floating');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, density: 0 }), RangeError, 'density', '0');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, mass: 1, density: 1 }), TypeError, 'mass', 'density');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, restitution: 2 }), RangeError, 'restitution', '2');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, angularVelocity: Infinity }), RangeError, 'angularVelocity');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, outlines: [square, [{ x: 0, y: 0 }]] }), RangeError, 'outlines[1]');
    expect(world.stateHash()).to.equal(before);
    expect([...world.bodies()]).to.deep.equal([]);
    expect(world.particleCount).to.equal(0);
  });

  it('the body calls refuse a particle-built body, a stale handle and non-finite values; the state stays finite', () => {
    const world = new World();
    const box = world.addRigidBody({ x: 0, y: 0, points: square });
    const cloth = createCloth(world, { origin: { x: 5, y: 0 }, columns: 3, rows: 3, spacing: 0.5 });
    throwsNaming(() => world.bodyPose(cloth.body), RangeError, `${cloth.body}`, 'not a rigid body', 'cloth');
    // A particle frame's kind is 'rigid' internally: the message says what it is (it read "it is a rigid built of particles").
    const frame = buildBody(world, { type: 'box', x: 0, y: -5, width: 1, height: 1, model: 'particles' });
    throwsNaming(() => world.setBodyAngularVelocity(frame.body, 2), RangeError, `${frame.body}`, 'not a rigid body', "frame of particles and sticks (model: 'particles')");
    throwsNaming(() => world.setBodyVelocity(box, Number.NaN, 0), RangeError, 'vx', 'NaN');
    throwsNaming(() => world.setBodyAngularVelocity(box, Infinity), RangeError, 'angularVelocity');
    throwsNaming(() => world.setBodyPose(box, 0, 0, Number.NaN), RangeError, 'angle');
    throwsNaming(() => world.applyBodyForce(box, 1, Number.NaN), RangeError, 'fy');
    throwsNaming(() => world.applyBodyForce(box, 1, 1, Infinity, 0), RangeError, 'x');
    throwsNaming(() => world.setBodyPose(box, 1e12, 0, 0), RangeError, 'x must be within ±1e9', '1000000000000');
    throwsNaming(() => world.setBodyPose(box, 0, -1e12, 0), RangeError, 'y must be within ±1e9', '-1000000000000');
    throwsNaming(() => world.applyBodyForce(box, 1, 1, 1e12, 0), RangeError, 'x must be within ±1e9', '1000000000000');
    throwsNaming(() => world.applyBodyImpulse(box, 1, 1, 0, 1e12), RangeError, 'y must be within ±1e9', '1000000000000');
    throwsNaming(() => world.applyBodyTorque(box, Number.NaN), RangeError, 'torque');
    throwsNaming(() => world.applyBodyImpulse(box, 1, 1, 0, Number.NaN), RangeError, 'y');
    throwsNaming(() => world.setBodyType(box, 'ghost' as never), RangeError, 'type', 'ghost');
    throwsNaming(() => world.bodyVelocity(123456789), RangeError, 'body', '123456789');
    throwsNaming(() => world.bodyMassInfo('a' as never), TypeError, 'body');
    world.removeBody(box);
    throwsNaming(() => world.bodyPose(box), RangeError, `${box}`, 'not a live body');
    for (let k = 0; k < 10; k++) world.step();
    const p = world.particles;
    for (let i = 0; i < p.count; i++) for (const col of [p.x, p.y, p.angle, p.omega]) expect(Number.isFinite(col[i])).to.equal(true);
  });

  it('addJoint names the option at fault and makes nothing', () => {
    const world = new World();
    const a = world.addRigidBody({ x: 0, y: 0, points: square });
    const b = world.addRigidBody({ x: 2, y: 0, points: square });
    const cloth = createCloth(world, { origin: { x: 5, y: 0 }, columns: 3, rows: 3, spacing: 0.5 });
    const count = world.constraintCount;
    throwsNaming(() => world.addJoint(null as never), TypeError, 'joint options');
    throwsNaming(() => world.addJoint({ type: 'hinge' as never, a }), RangeError, 'type', 'hinge');
    throwsNaming(() => world.addJoint({ type: 'revolute' }), TypeError, 'side a');
    throwsNaming(() => world.addJoint({ type: 'revolute', a, b: a }), RangeError, 'different');
    throwsNaming(() => world.addJoint({ type: 'revolute', a, b, particleB: cloth.particles[0] }), TypeError, 'b', 'particleB');
    throwsNaming(() => world.addJoint({ type: 'revolute', a: cloth.body }), RangeError, 'a', 'particles', 'particleA');
    throwsNaming(() => world.addJoint({ type: 'revolute', a, anchor: { x: Number.NaN, y: 0 } }), RangeError, 'anchor.x');
    throwsNaming(() => world.addJoint({ type: 'revolute', a, lowerAngle: 1, upperAngle: -1 }), RangeError, 'lowerAngle', 'upperAngle');
    throwsNaming(() => world.addJoint({ type: 'revolute', a, maxMotorTorque: -5 }), RangeError, 'maxMotorTorque', '-5');
    // A motor's speed is a speed: within ±1e9, as angularVelocity is (1e300 spun the body to 1e300 rad/s).
    throwsNaming(() => world.addJoint({ type: 'revolute', a, motorSpeed: 1e300 }), RangeError, 'motorSpeed', '1e+300');
    throwsNaming(() => world.addJoint({ type: 'prismatic', a, b, axis: { x: 0, y: 0 } }), RangeError, 'axis');
    // A switch is true or false: the string 'false' is not a truthy yes.
    throwsNaming(() => world.addJoint({ type: 'revolute', a, b, collideConnected: 'false' as never }), TypeError, 'collideConnected', 'false');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, collide: 'false' as never }), TypeError, 'collide', 'false');
    throwsNaming(() => (world.measureTimings = 'no' as never), TypeError, 'measureTimings', 'no');
    throwsNaming(() => world.addJoint({ type: 'distance', a, b, lower: 3, upper: 1 }), RangeError, 'lower', 'upper');
    throwsNaming(() => world.addJoint({ type: 'spring', a, b, stiffness: 0 }), RangeError, 'stiffness', '0');
    throwsNaming(() => world.addJoint({ type: 'spring', a, b, stiffness: 10, damping: -1 }), RangeError, 'damping', '-1');
    throwsNaming(() => world.addJoint({ type: 'weld', a, b, compliance: -1 }), RangeError, 'compliance', '-1');
    throwsNaming(() => world.addJoint({ type: 'weld', a, particleB: 99999 }), RangeError, 'particleB', '99999');
    // Anchors and lengths beyond ±1e9 (an axis is a direction, a limit above or a translation limit a bound that moves
    // nothing: any finite one will do).
    throwsNaming(() => world.addJoint({ type: 'revolute', a, anchor: { x: 1e12, y: 0 } }), RangeError, 'anchor.x must be within ±1e9', '1000000000000');
    throwsNaming(() => world.addJoint({ type: 'weld', a, b, anchor: { x: 0, y: -1e12 } }), RangeError, 'anchor.y must be within ±1e9', '-1000000000000');
    throwsNaming(() => world.addJoint({ type: 'distance', a, b, anchorA: { x: 1e12, y: 0 } }), RangeError, 'anchorA.x must be within ±1e9');
    throwsNaming(() => world.addJoint({ type: 'spring', a, b, stiffness: 1, anchorB: { x: 0, y: 1e12 } }), RangeError, 'anchorB.y must be within ±1e9');
    throwsNaming(() => world.addJoint({ type: 'distance', a, b, length: 1e12 }), RangeError, 'length must be within ±1e9');
    throwsNaming(() => world.addJoint({ type: 'distance', a, b, lower: 1e12, upper: Infinity }), RangeError, 'lower must be within ±1e9');
    throwsNaming(() => world.addJoint({ type: 'distance', a, particleB: cloth.particles[0], anchorA: { x: 0, y: 1e12 } }), RangeError, 'anchorA.y');
    expect(world.constraintCount).to.equal(count);
    world.addJoint({ type: 'prismatic', a, b, axis: { x: 1e12, y: 0 }, lower: -1e12, upper: Infinity });
    world.addJoint({ type: 'distance', a, b, lower: 0, upper: 1e12 });
    expect(world.constraintCount).to.equal(count + 2);
  });

  it('an angle beyond ±1e9 rad is refused where it is given (rounding ate the turn: a disc at angle 1e16 could not spin)', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, radius: 1, angle: 1e16 }), RangeError, 'angle', '10000000000000000');
    throwsNaming(() => createBox(world, { x: 0, y: 0, width: 1, height: 1, angle: -1e12 }), RangeError, 'angle', '-1000000000000');
    const b = world.addRigidBody({ x: 0, y: 0, radius: 1, angle: 1e9, angularVelocity: 2 });
    throwsNaming(() => world.setBodyPose(b, 0, 0, 2e9), RangeError, 'angle', '2000000000');
    for (let k = 0; k < 60; k++) world.step();
    // At 1e9 a double's spacing is 1.2e-7 rad: the spin keeps to 1e-4.
    expect(world.bodyAngularVelocity(b)).to.be.closeTo(2, 2e-4);
    expect(world.bodyPose(b).angle - 1e9).to.be.closeTo(2, 1e-3);
  });

  it('a prismatic axis is a direction at any scale: (1e200, 1e200) and (1e-200, 1e-200) slide as (1, 1) does', () => {
    const slid = (axis: Vec2) => {
      const world = new World({ bounds: null });
      const b = world.addRigidBody({ x: 0, y: 0, radius: 1 });
      world.addJoint({ type: 'prismatic', a: b, axis });
      for (let k = 0; k < 60; k++) world.step();
      return world.bodyPose(b);
    };
    const unit = slid({ x: 1, y: 1 });
    expect(unit.x).to.be.closeTo(2.45, 0.01);
    for (const axis of [{ x: 1e200, y: 1e200 }, { x: 1e-200, y: 1e-200 }, { x: -3e300, y: -3e300 }]) {
      const at = slid(axis);
      expect(at.x, JSON.stringify(axis)).to.be.closeTo(unit.x, 1e-9);
      expect(at.y, JSON.stringify(axis)).to.be.closeTo(unit.y, 1e-9);
    }
  });

  it('within ±1e9 the same jointed pendulum swings alike: moved next to (1e9, 1e9) it ends 2 s later within 1e-3 of where it ends at the origin', () => {
    const pendulum = (X: number) => {
      const world = new World({ sleeping: false, bounds: null });
      const box = world.addRigidBody({ x: X, y: X, points: square });
      const ball = world.addRigidBody({ x: X + 3, y: X + 2, radius: 0.5 });
      world.addJoint({ type: 'revolute', a: box, anchor: { x: X + 1, y: X } });
      world.addJoint({ type: 'distance', a: ball, b: box, anchorA: { x: X + 3, y: X + 2 }, anchorB: { x: X, y: X } });
      for (let k = 0; k < 120; k++) world.step();
      const [p, q] = [world.bodyPose(box), world.bodyPose(ball)];
      return [p.x - X, p.y - X, q.x - X, q.y - X];
    };
    const home = pendulum(0);
    const far = pendulum(1e9 - 10);
    // It swung (the ball ends well away from where it started) ...
    expect(Math.hypot(home[2] - 3, home[3] - 2)).to.be.above(1);
    // ... and the same way 1e9 away (3e-4 off here; at 1e10 it is 2e-2 off, at 1e12 0.9).
    for (let k = 0; k < 4; k++) expect(far[k]).to.be.closeTo(home[k], 1e-3);
  });
});
