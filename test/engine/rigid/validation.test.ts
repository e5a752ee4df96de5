// Bad input to the rigid-body and joint API: a TypeError/RangeError naming the argument and its value, and the world
// untouched (no half-made body, no NaN in the state).
import { expect } from 'chai';
import { createCloth, World, type Vec2 } from '../../../src/engine/index.js';
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
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: [{ x: 0, y: 0 }, { x: 1e200, y: 0 }, { x: 0, y: 1e200 }] }), RangeError, 'area');
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
    throwsNaming(() => world.setBodyVelocity(box, Number.NaN, 0), RangeError, 'vx', 'NaN');
    throwsNaming(() => world.setBodyAngularVelocity(box, Infinity), RangeError, 'angularVelocity');
    throwsNaming(() => world.setBodyPose(box, 0, 0, Number.NaN), RangeError, 'angle');
    throwsNaming(() => world.applyBodyForce(box, 1, Number.NaN), RangeError, 'fy');
    throwsNaming(() => world.applyBodyForce(box, 1, 1, Infinity, 0), RangeError, 'x');
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
    throwsNaming(() => world.addJoint({ type: 'prismatic', a, b, axis: { x: 0, y: 0 } }), RangeError, 'axis');
    throwsNaming(() => world.addJoint({ type: 'distance', a, b, lower: 3, upper: 1 }), RangeError, 'lower', 'upper');
    throwsNaming(() => world.addJoint({ type: 'spring', a, b, stiffness: 0 }), RangeError, 'stiffness', '0');
    throwsNaming(() => world.addJoint({ type: 'spring', a, b, stiffness: 10, damping: -1 }), RangeError, 'damping', '-1');
    throwsNaming(() => world.addJoint({ type: 'weld', a, b, compliance: -1 }), RangeError, 'compliance', '-1');
    throwsNaming(() => world.addJoint({ type: 'weld', a, particleB: 99999 }), RangeError, 'particleB', '99999');
    expect(world.constraintCount).to.equal(count);
  });
});
