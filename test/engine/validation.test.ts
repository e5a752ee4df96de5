import { expect } from 'chai';
import { World, buildBody, buildScene, createBox, createCircle, createCloth, createPolygon, createRagdoll, createRope, createSoftBody, ragdollJoints } from '../../src/engine/index.js';
import { allFinite } from './helpers.js';

function throwsNaming(fn: () => unknown, type: typeof RangeError | typeof TypeError, ...words: string[]) {
  let caught: unknown;
  try {
    fn();
  } catch (e) {
    caught = e;
  }
  expect(caught, `expected ${type.name} naming ${words.join(', ')}`).to.be.instanceOf(type);
  for (const w of words) expect((caught as Error).message).to.include(w);
}

describe('bad input', () => {
  const world = new World();
  const a = world.addParticle({ x: 0, y: 0 });
  const b = world.addParticle({ x: 1, y: 0 });

  it('NaN and Infinity in positions, velocities and forces throw naming the argument and value', () => {
    throwsNaming(() => world.addParticle({ x: NaN, y: 0 }), RangeError, 'x', 'NaN');
    throwsNaming(() => world.addParticle({ x: 0, y: Infinity }), RangeError, 'y', 'Infinity');
    throwsNaming(() => world.addParticle({ x: 0, y: 0, vx: -Infinity }), RangeError, 'vx', '-Infinity');
    throwsNaming(() => world.addParticle({ x: '3' as unknown as number, y: 0 }), TypeError, 'x', '"3"');
    throwsNaming(() => world.setPosition(a, 0, NaN), RangeError, 'y', 'NaN');
    throwsNaming(() => world.applyForce(a, NaN, 0), RangeError, 'fx', 'NaN');
    throwsNaming(() => world.applyImpulse(a, 0, Infinity), RangeError, 'iy', 'Infinity');
    throwsNaming(() => world.setGravity(NaN, 0), RangeError, 'gravity.x', 'NaN');
    throwsNaming(() => new World({ timestep: 0 }), RangeError, 'timestep', '0');
    throwsNaming(() => new World({ substeps: 2.5 }), RangeError, 'substeps', '2.5');
    throwsNaming(() => new World({ integrator: 'rk4' as never }), RangeError, 'integrator', '"rk4"');
    throwsNaming(() => world.step(-1), RangeError, 'dt', '-1');
    throwsNaming(() => world.advance(NaN), RangeError, 'elapsed', 'NaN');
    throwsNaming(() => new World({ bounds: { minX: 1, minY: 0, maxX: 0, maxY: 1 } }), RangeError, 'minX < maxX');
  });

  it('a misspelt or unknown World option throws naming it and the one meant; a step of a minute is refused', () => {
    throwsNaming(() => new World({ substepz: 3 } as never), TypeError, 'unknown World option "substepz"', 'did you mean substeps?');
    throwsNaming(() => new World({ gravty: { x: 0, y: 1 } } as never), TypeError, '"gravty"', 'did you mean gravity?');
    throwsNaming(() => new World({ limits: { particle: 5 } } as never), TypeError, 'unknown limits option "particle"', 'did you mean particles?');
    // Far from every name: no guess, the list of names.
    throwsNaming(() => new World({ speed: 2 } as never), TypeError, '"speed"', 'the World options are gravity, timestep, substeps');
    throwsNaming(() => new World(5 as never), TypeError, 'options', '5');
    // The error for a bad substep count names both forms it takes.
    throwsNaming(() => new World({ substeps: 'many' as never }), TypeError, "substeps must be 'auto' or a whole number from 1 to 1000", '"many"');
    // World.step takes a length: step(60), written as an element's step(60) (sixty steps), would be one 60 s step.
    const w = new World();
    const p = w.addParticle({ x: 0, y: 0 });
    throwsNaming(() => w.step(60), RangeError, 'dt', 'from 1e-6 to 1', '60', 'call step() n times');
    w.step(1);
    expect(w.time).to.equal(1);
    expect(allFinite(w)).to.equal(true);
    expect(w.particles.y[w.particleIndex(p)]).to.be.above(0);
    // Every name the options type has is accepted, and no options at all.
    expect(() => new World({ gravity: { x: 0, y: 1 }, timestep: 1 / 30, substeps: 'auto', iterations: 2, damping: 0, sleeping: true, kernel: 'js', limits: { particles: 10 } })).not.to.throw();
    expect(() => new World(undefined)).not.to.throw();
  });

  it('builders refuse option names they do not take, naming the name and the one meant, and leave the world as it was', () => {
    const w = new World();
    const cases: [string, () => unknown, string[]][] = [
      ['box', () => createBox(w, { x: 0, y: 0, width: 1, height: 1, density: 5 } as never), ['unknown box option "density"', 'mass']],
      ['circle', () => createCircle(w, { x: 0, y: 0, radius: 1, restitiution: 0.5 } as never), ['"restitiution"', 'did you mean restitution?']],
      ['polygon', () => createPolygon(w, { points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], angel: 1 } as never), ['"angel"', 'did you mean angle?']],
      ['rope', () => createRope(w, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, pinned: true } as never), ['unknown rope option "pinned"']],
      ['cloth', () => createCloth(w, { origin: { x: 0, y: 0 }, columns: 3, rows: 3, spacing: 1, colums: 4 } as never), ['"colums"', 'did you mean columns?']],
      ['soft body', () => createSoftBody(w, { center: { x: 0, y: 0 }, radius: 1, presure: 2 } as never), ['unknown soft body option "presure"', 'did you mean pressure?']],
      ['ragdoll', () => createRagdoll(w, { x: 0, y: 0, heigth: 2 } as never), ['"heigth"', 'did you mean height?']],
      ['not an object', () => createBox(w, 'big' as never), ['box options must be an object', '"big"']],
    ];
    for (const [, build, words] of cases) throwsNaming(build, TypeError, ...words);
    expect(w.particleCount).to.equal(0);
    // Every name each options type has is taken.
    const material = { static: false, collide: true, friction: 0.3, restitution: 0.1, category: 1, mask: 0xffff, group: 0 };
    const motion = { ...material, kinematic: false, vx: 1, vy: 0, angularVelocity: 0 };
    expect(() => createBox(w, { ...motion, model: 'rigid', x: 0, y: 0, width: 1, height: 1, angle: 0, mass: 1, compliance: 0 })).not.to.throw();
    expect(() => createCircle(w, { ...motion, model: 'rigid', x: 3, y: 0, radius: 1, angle: 1, mass: 1 })).not.to.throw();
    expect(() => createPolygon(w, { ...motion, model: 'particles', points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], x: 6, y: 0, angle: 0, mass: 1, compliance: 0 })).not.to.throw();
    const rope = { ...material, from: { x: 0, y: -5 }, to: { x: 2, y: -5 }, segments: 4, mass: 1, slack: 1, ropeLike: true, pinStart: true, pinEnd: false, compliance: 0, radius: 0.1, tethers: true };
    expect(() => createRope(w, rope)).not.to.throw();
    const cloth = { ...material, origin: { x: 0, y: -9 }, columns: 3, rows: 3, spacing: 1, mass: 1, structural: 0, shear: null, bend: null, pins: 'top' as const, radius: 0, tethers: true, tear: 0.5 };
    expect(() => createCloth(w, cloth)).not.to.throw();
    const soft = { ...material, center: { x: 9, y: 0 }, radius: 1, segments: 8, mass: 1, model: 'springs' as const, pressure: 1, compliance: 0, areaCompliance: 0, stiffness: 10, damping: 1 };
    expect(() => createSoftBody(w, soft)).not.to.throw();
    expect(() => createRagdoll(w, { ...material, x: 12, y: 0, height: 1.8, mass: 70, jointCompliance: 0 })).not.to.throw();
  });

  it("the World's methods refuse option names they do not take, naming the name and the one meant", () => {
    const w = new World();
    const [p, q, r] = [w.addParticle({ x: 0, y: 0 }), w.addParticle({ x: 1, y: 0 }), w.addParticle({ x: 1, y: 1 })];
    const box = createBox(w, { x: 5, y: 5, width: 1, height: 1 }).body;
    const cases: [() => unknown, string[]][] = [
      [() => w.addParticle({ x: 0, y: 0, radus: 1 } as never), ['unknown particle option "radus"', 'did you mean radius?']],
      [() => w.addDistance(p, q, { stiffness: 5 } as never), ['unknown distance option "stiffness"', 'the distance options are length']],
      [() => w.addDistance(p, q, 7 as never), ['distance options must be an object', '7']],
      [() => w.addAngleLimit(p, q, r, { min: 0, max: 1, compliace: 0 } as never), ['"compliace"', 'did you mean compliance?']],
      [() => w.addSpring(p, q, { stiffness: 1, dampng: 1 } as never), ['unknown spring option "dampng"', 'did you mean damping?']],
      [() => w.addPin(p, { X: 1 } as never), ['unknown pin option "X"', 'did you mean x?']],
      [() => w.addAreaConstraint([p, q, r], { presure: 1 } as never), ['"presure"', 'did you mean pressure?']],
      [() => w.addBody('particle', [p], [], { shape: 'none', frictoin: 1 } as never), ['unknown collider option "frictoin"', 'did you mean friction?']],
      [() => w.setCollider(box, { restitutoin: 1 } as never), ['"restitutoin"', 'did you mean restitution?']],
      [() => w.addRigidBody({ x: 0, y: 0, radius: 1, angularVelocty: 1 } as never), ['unknown rigid body option "angularVelocty"', 'did you mean angularVelocity?']],
      [() => w.addJoint({ type: 'revolute', a: box, anchr: { x: 5, y: 5 } } as never), ['unknown joint option "anchr"', 'did you mean anchor?']],
      [() => w.grab(5, 5, { stifness: 10 } as never), ['unknown grab option "stifness"', 'did you mean stiffness?']],
    ];
    const before = [w.particleCount, w.constraintCount];
    for (const [call, words] of cases) throwsNaming(call, TypeError, ...words);
    expect([w.particleCount, w.constraintCount]).to.deep.equal(before);
    for (let k = 0; k < 10; k++) w.step();
    expect(allFinite(w)).to.equal(true);
  });

  it('a particle frame spun past the speed limit is refused before anything is built', () => {
    const w = new World();
    const before = [w.particleCount, w.constraintCount];
    throwsNaming(() => createBox(w, { x: 0, y: 0, width: 4, height: 4, model: 'particles', angularVelocity: 6e8 }), RangeError, 'within ±1e9');
    throwsNaming(() => createBox(w, { x: 0, y: 0, width: 1, height: 1, vx: 5e9 }), RangeError, 'vx', '5000000000');
    throwsNaming(() => w.addParticle({ x: 0, y: 0, vy: -2e9 }), RangeError, 'vy');
    expect([w.particleCount, w.constraintCount]).to.deep.equal(before);
    const frame = createBox(w, { x: 0, y: 0, width: 1, height: 1, model: 'particles' });
    // The frame that follows has its own four particles and is the only body (no orphan of the refused one).
    expect(w.bodyParticleIndices(frame.body).length).to.equal(4);
    expect([...w.bodies()]).to.deep.equal([frame.body]);
  });

  it('a particle frame starts with its vx, vy and angularVelocity, as a rigid body would', () => {
    const w = new World({ gravity: { x: 0, y: 0 } });
    const frame = createBox(w, { model: 'particles', x: 0, y: 0, width: 2, height: 2, vx: 3, vy: -1, angularVelocity: 2 });
    const rigid = createBox(w, { x: 10, y: 0, width: 2, height: 2, vx: 3, vy: -1, angularVelocity: 2 });
    for (let k = 0; k < 60; k++) w.step();
    const c = w.bodyCentroid(frame.body);
    const r = w.bodyPose(rigid.body);
    expect(c.x).to.be.closeTo(3, 1e-6);
    expect(c.y).to.be.closeTo(-1, 1e-6);
    expect(r.x - 10).to.be.closeTo(c.x, 1e-6);
    // The frame turned by about ω·t = 2 rad, as the rigid box did (its sticks hold the corners' distance).
    const [p0, p1] = [w.getPosition(frame.particles[0]), w.getPosition(frame.particles[1])];
    const turned = Math.atan2(p1.y - p0.y, p1.x - p0.x);
    expect(turned).to.be.closeTo(r.angle, 0.05);
    expect(r.angle).to.be.closeTo(2, 1e-9);
  });

  it('settings set as properties are checked as the options are; a timestep over 1 s is refused as a step is', () => {
    const w = new World();
    const p = w.addParticle({ x: 0, y: 0 });
    createBox(w, { x: 5, y: 5, width: 1, height: 1 });
    w.addRigidBody({ x: 10, y: 0, radius: 0.5 });
    throwsNaming(() => (w.gravity = { x: NaN, y: 0 }), RangeError, 'gravity.x', 'NaN');
    throwsNaming(() => (w.gravity = { x: '1', y: 0 } as never), TypeError, 'gravity.x', '"1"');
    throwsNaming(() => (w.bounds = { minX: -10, minY: -10, maxX: 10 } as never), TypeError, 'maxY');
    throwsNaming(() => (w.bounds = { minX: 10, minY: 0, maxX: 0, maxY: 1 }), RangeError, 'minX');
    // The gravity read is a copy: changing it changes nothing unchecked.
    w.gravity.x = NaN;
    expect(w.gravity.x).to.equal(0);
    throwsNaming(() => new World({ timestep: 100 }), RangeError, 'timestep', 'from 1e-6 to 1', '100');
    throwsNaming(() => (w.timestep = 5), RangeError, 'timestep', '5');
    w.gravity = { x: 1, y: 2 };
    for (let k = 0; k < 30; k++) w.step();
    expect(allFinite(w)).to.equal(true);
    expect(w.getPosition(p).x).to.be.above(0);
  });

  it('speeds past ±1e9 units/s, given or added by an impulse or a step\'s force, are refused; the world keeps stepping', () => {
    const w = new World();
    createBox(w, { x: 0, y: 10, width: 20, height: 1, static: true });
    const box = createBox(w, { x: 0, y: 0, width: 1, height: 1 });
    const blob = createSoftBody(w, { center: { x: 4, y: 0 }, radius: 1 });
    const p = w.addParticle({ x: -4, y: 0 });
    throwsNaming(() => w.setBodyVelocity(box.body, 1e200, 0), RangeError, 'vx', '1e+200');
    throwsNaming(() => w.setBodyAngularVelocity(box.body, -2e9), RangeError, 'angularVelocity');
    throwsNaming(() => w.applyBodyImpulse(box.body, 1e308, 0), RangeError, 'ix / mass');
    throwsNaming(() => w.applyBodyImpulse(box.body, 0, 1e9, 1e6, 0), RangeError, 'turn');
    throwsNaming(() => w.applyBodyImpulse(blob.body, 0, 1e300), RangeError, 'iy / mass');
    throwsNaming(() => w.setVelocity(p, 0, 1e10), RangeError, 'vy');
    throwsNaming(() => w.applyImpulse(p, 1e300, 0), RangeError, 'ix / mass');
    throwsNaming(() => w.applyForce(p, 0, 1e300), RangeError, 'fy');
    throwsNaming(() => w.applyBodyForce(box.body, 1e300, 0), RangeError, 'fx · timestep / mass');
    // Up to the limit, and a large impulse on a heavy body, are fine.
    w.setBodyVelocity(box.body, 1e9, 0);
    const heavy = createBox(w, { x: 0, y: -5, width: 1, height: 1, mass: 1e6 });
    w.applyBodyImpulse(heavy.body, 1e12, 0);
    for (let k = 0; k < 60; k++) w.step();
    expect(allFinite(w)).to.equal(true);
  });

  it('a value of any kind is shown as it was given: a BigInt with its n, an empty array as []', () => {
    const w = new World();
    throwsNaming(() => w.getPosition(5n as never), TypeError, 'handle', '5n');
    throwsNaming(() => w.getPosition([] as never), TypeError, 'handle', 'got []');
    throwsNaming(() => w.addParticle({ x: 1n as never, y: 0 }), TypeError, 'x', '1n');
    throwsNaming(() => ragdollJoints(null as never), TypeError, 'ragdollJoints', 'createRagdoll');
    throwsNaming(() => ragdollJoints({} as never), TypeError, 'ragdollJoints', '{}');
  });

  it('a force or torque on a body that cannot move is dropped, not kept to act in full once the body is freed before the step', () => {
    const w = new World({ gravity: { x: 0, y: 0 } });
    const b = w.addRigidBody({ x: 0, y: 0, radius: 1, type: 'static' });
    w.applyBodyForce(b, 1e13, 0);
    w.applyBodyTorque(b, 1e13);
    w.setBodyType(b, 'dynamic');
    const p = w.addParticle({ x: 5, y: 0 });
    const pin = w.addPin(p);
    w.applyForce(p, 1e300, 0);
    w.removeConstraint(pin);
    w.step();
    w.step();
    expect(w.bodyVelocity(b).x).to.equal(0);
    expect(w.bodyAngularVelocity(b)).to.equal(0);
    expect(w.getVelocity(p).x).to.equal(0);
    expect(w.diagnostics().rowsRepaired).to.equal(0);
    // Once movable, a force acts: F/m · dt over a step.
    w.applyBodyForce(b, Math.PI * 60, 0);
    w.step();
    expect(w.bodyVelocity(b).x).to.be.closeTo(1, 1e-9);
  });

  it('pushes add up under the speed limit: a second force or impulse that takes the sum past ±1e9 is refused', () => {
    const w = new World({ gravity: { x: 0, y: 0 } });
    const box = createBox(w, { x: 0, y: 0, width: 1, height: 1, mass: 1 });
    const p = w.addParticle({ x: 5, y: 0, mass: 1 });
    const h = w.timestep;
    // Each force alone gives 0.6e9 units/s over a step; two give 1.2e9.
    w.applyForce(p, 0.6e9 / h, 0);
    throwsNaming(() => w.applyForce(p, 0.6e9 / h, 0), RangeError, 'fx · timestep / mass', 'since the last step');
    w.applyForce(p, -0.5e9 / h, 0); // the other way takes the sum down: fine
    w.applyBodyForce(box.body, 0, 0.6e9 / h);
    throwsNaming(() => w.applyBodyForce(box.body, 0, 0.6e9 / h), RangeError, 'fy · timestep / mass');
    const inertia = w.bodyMassInfo(box.body).inertia;
    w.applyBodyTorque(box.body, (0.6e9 * inertia) / h);
    throwsNaming(() => w.applyBodyTorque(box.body, (0.6e9 * inertia) / h), RangeError, 'torque · timestep / inertia');
    w.step();
    expect(allFinite(w)).to.equal(true);
    // Forces are cleared by the step: the same force is fine again.
    w.applyForce(p, 0.6e9 / h, 0);
    // Impulses are checked with the velocity they add to.
    w.setVelocity(p, 0.9e9, 0);
    throwsNaming(() => w.applyImpulse(p, 0.2e9, 0), RangeError, 'vx + ix / mass', '1100000000');
    w.applyImpulse(p, -0.2e9, 0);
    expect(w.getVelocity(p).x).to.be.closeTo(0.7e9, 1);
    w.setBodyVelocity(box.body, 0, -0.9e9);
    throwsNaming(() => w.applyBodyImpulse(box.body, 0, -0.2e9), RangeError, 'vy + iy / mass');
    w.setBodyAngularVelocity(box.body, 0.9e9);
    throwsNaming(() => w.applyBodyImpulse(box.body, 0, 0.2e9 * inertia, 1, 0), RangeError, 'the turn the impulse leaves');
    // A body of particles: every particle keeps within the limit.
    const blob = createSoftBody(w, { center: { x: 20, y: 0 }, radius: 1 });
    const ring = w.bodyParticleHandles(blob.body);
    for (const q of ring) w.setVelocity(q, 0.9e9, 0);
    const mass = ring.reduce((m, q) => m + w.getMass(q), 0);
    throwsNaming(() => w.applyBodyImpulse(blob.body, 0.2e9 * mass, 0), RangeError, 'vx + ix / mass');
    w.applyBodyImpulse(blob.body, -0.2e9 * mass, 0);
    w.step();
    expect(allFinite(w)).to.equal(true);
    // A body past the limit (gravity took it there) may still be slowed, or pushed along another axis.
    const fast = new World({ gravity: { x: 0, y: 10 } });
    const q = fast.addParticle({ x: 0, y: 0, mass: 1, vy: 1e9 });
    const wheel = createBox(fast, { x: 5, y: 0, width: 1, height: 1, mass: 1 });
    fast.step();
    expect(fast.getVelocity(q).y).to.be.above(1e9);
    fast.applyImpulse(q, 1, 0);
    fast.applyImpulse(q, 0, -1);
    throwsNaming(() => fast.applyImpulse(q, 0, 1), RangeError, 'vy + iy / mass');
    fast.setBodyAngularVelocity(wheel.body, 1e9);
    const spinInertia = fast.bodyMassInfo(wheel.body).inertia;
    fast.applyBodyImpulse(wheel.body, 0, -spinInertia, 5.5, 0); // slows the spin
    throwsNaming(() => fast.applyBodyImpulse(wheel.body, 0, 10 * spinInertia, 5.5, 0), RangeError, 'the turn the impulse leaves');
  });

  it('negative mass, length, radius or stiffness throw', () => {
    throwsNaming(() => world.addParticle({ x: 0, y: 0, mass: -1 }), RangeError, 'mass', '-1');
    throwsNaming(() => world.addParticle({ x: 0, y: 0, mass: 0 }), RangeError, 'mass', '0');
    throwsNaming(() => world.addParticle({ x: 0, y: 0, radius: -2 }), RangeError, 'radius', '-2');
    throwsNaming(() => world.addDistance(a, b, { length: -1 }), RangeError, 'length', '-1');
    throwsNaming(() => world.addDistance(a, b, { minLength: 2, maxLength: 1 }), RangeError, 'minLength', 'maxLength');
    throwsNaming(() => world.addDistance(a, b, { compliance: -1 }), RangeError, 'compliance', '-1');
    throwsNaming(() => world.addSpring(a, b, { stiffness: -5 }), RangeError, 'stiffness', '-5');
    throwsNaming(() => createRope(world, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, segments: 0 }), RangeError, 'segments', '0');
    throwsNaming(() => createCloth(world, { origin: { x: 0, y: 0 }, columns: 3, rows: 3, spacing: -1 }), RangeError, 'spacing', '-1');
    throwsNaming(() => createPolygon(world, { points: [{ x: 0, y: 0 }, { x: 1, y: 0 }] }), RangeError, 'points', '2');
    throwsNaming(() => createPolygon(world, { points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 2, y: 0 }] }), RangeError, 'points', 'area');
  });

  it('unknown or removed handles and self-constraints throw', () => {
    throwsNaming(() => world.addDistance(a, a), RangeError, 'a and b', 'different');
    throwsNaming(() => world.addAngleLimit(a, b, a, { min: 0, max: 1 }), RangeError, 'a and c');
    throwsNaming(() => world.getPosition(123456), RangeError, 'particle', '123456');
    throwsNaming(() => world.getPosition(-1), TypeError, 'particle', '-1');
    throwsNaming(() => world.getPosition(1.5), TypeError, 'particle', '1.5');
    const c = world.addParticle({ x: 5, y: 5 });
    world.removeParticle(c);
    throwsNaming(() => world.addDistance(a, c), RangeError, 'b', String(c), 'not a live particle');
    const d = world.addParticle({ x: 6, y: 6 }); // reuses c's slot with a new generation
    expect(d).to.not.equal(c);
    expect(world.hasParticle(c)).to.equal(false);
    expect(world.hasParticle(d)).to.equal(true);
    throwsNaming(() => world.removeConstraint(999), RangeError, 'constraint');
  });

  it('coordinates beyond ±1e9 (here 1e12) throw a RangeError naming the argument and value, at every entry point; the world is left as it was', () => {
    const w = new World({ gravity: { x: 0, y: 0 } });
    const p = w.addParticle({ x: 0, y: 0 });
    const q = w.addParticle({ x: 1, y: 0 });
    const pin = w.addPin(q, { compliance: 0.1 });
    const grab = w.grab(0, 0)!;
    // What was there stays as it was (a builder that failed half-way leaves nothing behind, though the handles it took
    // and gave back are spent: the state hash, which covers them, moves on).
    const state = () => ({ p: w.getPosition(p), q: w.getPosition(q), particles: w.particleCount, constraints: w.constraintCount, bodies: [...w.bodies()].length });
    const before = state();
    const far = 1e12;
    const cases: [() => unknown, string][] = [
      [() => w.addParticle({ x: far, y: 0 }), 'x'],
      [() => w.addParticle({ x: 0, y: -far }), 'y'],
      [() => w.addParticle({ x: 0, y: 0, radius: far }), 'radius'],
      [() => w.setPosition(p, far, 0), 'x'],
      [() => w.setPosition(p, 0, -far), 'y'],
      [() => w.addDistance(p, q, { length: far }), 'length'],
      [() => w.addDistance(p, q, { minLength: far, maxLength: Infinity }), 'minLength'],
      [() => w.addSpring(p, q, { length: far, stiffness: 1 }), 'length'],
      [() => w.addPin(p, { x: far }), 'x'],
      [() => w.addPin(p, { y: -far }), 'y'],
      [() => w.setPinTarget(pin, far, 0), 'x'],
      [() => w.grab(far, 0), 'x'],
      [() => w.grab(0, 0, { pickRadius: far }), 'pickRadius'],
      [() => w.moveGrab(grab, 0, far), 'y'],
      [() => w.bodiesAtPoint(0, -far), 'y'],
      [() => w.bodiesInBox(-far, 0, 1, 1), 'minX'],
      [() => w.rayCast(0, 0, far, 0), 'x1'],
      [() => w.setBounds({ minX: -far, minY: 0, maxX: 1, maxY: 1 }), 'bounds.minX'],
      [() => new World({ bounds: { minX: 0, minY: 0, maxX: 1, maxY: far } }), 'bounds.maxY'],
      [() => createRope(w, { from: { x: far, y: 0 }, to: { x: 1, y: 0 } }), 'from.x'],
      [() => createRope(w, { from: { x: 0, y: 0 }, to: { x: 1, y: far } }), 'to.y'],
      [() => createRope(w, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, radius: far }), 'radius'],
      [() => createCloth(w, { origin: { x: 0, y: -far }, columns: 3, rows: 3, spacing: 1 }), 'origin.y'],
      [() => createCloth(w, { origin: { x: 0, y: 0 }, columns: 3, rows: 3, spacing: far }), 'spacing'],
      [() => createSoftBody(w, { center: { x: far, y: 0 }, radius: 1 }), 'center.x'],
      [() => createSoftBody(w, { center: { x: 0, y: 0 }, radius: far }), 'radius'],
      [() => createCircle(w, { x: far, y: 0, radius: 1 }), 'x'],
      [() => createCircle(w, { x: 0, y: 0, radius: far, model: 'particles' }), 'radius'],
      [() => createBox(w, { x: 0, y: far, width: 1, height: 1 }), 'y'],
      [() => createBox(w, { x: 0, y: 0, width: far, height: 1 }), 'width'],
      [() => createBox(w, { x: 0, y: 0, width: 1, height: far, model: 'particles' }), 'height'],
      [() => createPolygon(w, { points: [{ x: 0, y: 0 }, { x: far, y: 0 }, { x: 0, y: 1 }] }), 'points[1].x'],
      [() => createPolygon(w, { x: -far, points: [{ x: 0, y: 0 }, { x: 1, y: 0 }, { x: 0, y: 1 }], model: 'particles' }), 'x'],
      [() => createRagdoll(w, { x: far, y: 0 }), 'x'],
      [() => createRagdoll(w, { x: 0, y: 0, height: far }), 'height'],
    ];
    for (const [call, name] of cases) {
      throwsNaming(call, RangeError, `${name} must be within ±1e9`);
      let message = '';
      try {
        call();
      } catch (e) {
        message = (e as Error).message;
      }
      expect(message, message).to.match(/got -?[0-9]+$/);
    }
    // Each number within the limit, the cloth's far corner beyond it.
    throwsNaming(() => createCloth(w, { origin: { x: 9e8, y: 0 }, columns: 3, rows: 3, spacing: 1e8 }), RangeError, 'spacing must keep the cloth within ±1e9', '(1100000000, 200000000)', 'got 100000000');
    throwsNaming(() => w.setPosition(p, far, 0), RangeError, 'x', '1000000000000');
    throwsNaming(() => w.setPosition(p, 0, -far), RangeError, 'y', '-1000000000000');
    expect(state()).to.deep.equal(before);
    // ±1e9 itself is taken.
    const edge = new World({ bounds: null });
    const r = createRope(edge, { from: { x: 1e9 - 4, y: -1e9 }, to: { x: 1e9, y: -1e9 }, segments: 4 });
    // An upper bound moves nothing: any is taken, as Infinity is.
    edge.addDistance(r.particles[0], r.particles[4], { minLength: 0, maxLength: 1e12 });
    expect(edge.bodiesAtPoint(-1e9, 1e9)).to.deep.equal([]);
    for (let k = 0; k < 60; k++) edge.step();
    expect(allFinite(edge)).to.equal(true);
    // The rope hangs from its pinned start: its free end fell (y grows downwards) and stays within its length of the pin.
    const end = edge.getPosition(r.particles[4]);
    expect(end.y + 1e9).to.be.within(1, 4.1);
  });

  it('a failed builder leaves nothing behind, and the world keeps running', () => {
    const before = world.particleCount;
    throwsNaming(() => createCloth(world, { origin: { x: 0, y: 0 }, columns: 3, rows: 3, spacing: 1, pins: [0, 7] }), RangeError, 'pins[1]', '7');
    expect(world.particleCount).to.equal(before);
    for (let k = 0; k < 10; k++) world.step();
    expect(allFinite(world)).to.equal(true);
  });

  it('a zero-length distance never yields NaN', () => {
    const w = new World({ gravity: { x: 0, y: 0 } });
    const p = w.addParticle({ x: 1, y: 1 });
    const q = w.addParticle({ x: 1, y: 1 });
    w.addDistance(p, q, { length: 0 });
    w.addDistance(p, q, { minLength: 0.5, maxLength: 0.5 }); // coincident particles that must separate
    w.addSpring(p, q, { length: 0, stiffness: 10 });
    for (let k = 0; k < 10; k++) w.step();
    expect(allFinite(w)).to.equal(true);
  });
});

describe('handles', () => {
  it('stay valid while others are removed, and removing a particle removes its constraints', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const ps = Array.from({ length: 10 }, (_, k) => world.addParticle({ x: k, y: 0 }));
    const links = ps.slice(1).map((p, k) => world.addDistance(ps[k], p));
    world.removeParticle(ps[4]);
    expect(world.hasConstraint(links[3])).to.equal(false); // 3–4
    expect(world.hasConstraint(links[4])).to.equal(false); // 4–5
    expect(world.constraintCount).to.equal(7);
    for (const [k, p] of ps.entries()) if (k !== 4) expect(world.getPosition(p).x).to.equal(k);
    expect(world.distanceError(links[8])).to.equal(0);
  });

  it('removing a body removes its particles and constraints', () => {
    const world = new World();
    const keep = createRope(world, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, segments: 4 });
    const gone = createCloth(world, { origin: { x: 5, y: 0 }, columns: 4, rows: 4, spacing: 0.5 });
    world.removeBody(gone.body);
    expect(world.hasBody(gone.body)).to.equal(false);
    expect(world.particleCount).to.equal(5);
    expect(gone.constraints.some((c) => world.hasConstraint(c))).to.equal(false);
    expect(keep.constraints.every((c) => world.hasConstraint(c))).to.equal(true);
    expect([...world.bodies()]).to.deep.equal([keep.body]);
  });
});

describe('limits', () => {
  it('creating more than the caps allow throws a RangeError naming the limit, and the world keeps working', () => {
    const world = new World({ limits: { particles: 50, bodies: 3 } });
    expect(world.limits).to.deep.equal({ particles: 50, constraints: 1_000_000, bodies: 3 });
    throwsNaming(() => createCloth(world, { origin: { x: 0, y: 0 }, columns: 10, rows: 10, spacing: 0.1 }), RangeError, 'too many particles', 'limits.particles', '50');
    expect(world.particleCount).to.equal(0); // the failed cloth left nothing behind
    for (let k = 0; k < 3; k++) createRope(world, { from: { x: k, y: 0 }, to: { x: k, y: 1 }, segments: 2 });
    throwsNaming(() => createRope(world, { from: { x: 9, y: 0 }, to: { x: 9, y: 1 }, segments: 2 }), RangeError, 'too many bodies', 'limits.bodies');
    world.removeBody([...world.bodies()][0]);
    createRope(world, { from: { x: 9, y: 0 }, to: { x: 9, y: 1 }, segments: 2 }); // room again
    world.step();
    expect(allFinite(world)).to.equal(true);
    throwsNaming(() => new World({ limits: { bodies: 0 } }), RangeError, 'limits.bodies', '0');
  });
});

describe('values that used to overflow to NaN', () => {
  /** A box on a floor, stepped: the world that each refused call below must leave able to step. */
  function pile() {
    const world = new World();
    createBox(world, { x: 0, y: 10, width: 40, height: 1, static: true });
    const box = createBox(world, { x: 0, y: 9, width: 1, height: 1 });
    return { world, box };
  }
  function stepsOn(world: World, steps = 5) {
    for (let k = 0; k < steps; k++) world.step();
    expect(allFinite(world)).to.equal(true);
    const p = world.particles;
    for (let i = 0; i < p.count; i++) expect(Number.isFinite(p.angle[i]) && Number.isFinite(p.omega[i])).to.equal(true);
  }

  it('steps shorter than a microsecond are refused; variableStep gathers them into one', () => {
    const { world } = pile();
    throwsNaming(() => world.step(1e-308), RangeError, 'dt', 'from 1e-6', '1e-308');
    throwsNaming(() => new World({ timestep: 1e-320 }), RangeError, 'timestep', '1e-320');
    throwsNaming(() => (world.timestep = 1e-9), RangeError, 'timestep', '1e-9');
    stepsOn(world);
    world.step(1e-6); // the shortest step taken
    stepsOn(world);
    const v = new World({ variableStep: true });
    const p = v.addParticle({ x: 0, y: 0 });
    for (let k = 0; k < 1000; k++) expect(v.advance(1e-9)).to.equal(0);
    expect(v.advance(1e-9)).to.equal(1); // 1001 ns make a step
    expect(v.time).to.be.closeTo(1.001e-6, 1e-15);
    expect(Number.isFinite(v.getPosition(p).y)).to.equal(true);
  });

  it('a sleeping body is held to the speed limit as an awake one is (its mass is parked while it sleeps)', () => {
    const { world, box } = pile();
    for (let k = 0; k < 200; k++) world.step();
    expect(world.isAwake(box.body)).to.equal(false);
    const hash = world.stateHash();
    throwsNaming(() => world.applyBodyImpulse(box.body, 1.7e308, 0), RangeError, 'ix / mass', '±1e9');
    throwsNaming(() => world.applyBodyForce(box.body, 0, 1e300), RangeError, 'fy · timestep / mass');
    throwsNaming(() => world.applyBodyTorque(box.body, 1e300), RangeError, 'torque · timestep / inertia');
    expect(world.stateHash()).to.equal(hash);
    expect(world.isAwake(box.body)).to.equal(false);
    const soft = new World({ bounds: { minX: -5, minY: -10, maxX: 5, maxY: 0 } });
    const q = soft.addParticle({ x: 0, y: -0.5, radius: 0.5 });
    const ball = soft.addBody('particle', [q], [], { shape: 'particles' });
    for (let k = 0; k < 300; k++) soft.step();
    expect(soft.isAwake(ball)).to.equal(false);
    throwsNaming(() => soft.applyImpulse(q, 1e300, 0), RangeError, 'ix / mass');
    throwsNaming(() => soft.applyForce(q, 1e300, 0), RangeError, 'fx · timestep / mass');
    throwsNaming(() => soft.applyBodyImpulse(ball, 0, 1e300), RangeError, 'iy / mass');
    stepsOn(soft);
  });

  it('compliance above 1e9, a stiffness below 1e-9 and pressure above 1e6 are refused, by every builder too', () => {
    const world = new World();
    const a = world.addParticle({ x: 0, y: 0, mass: Infinity });
    const b = world.addParticle({ x: 1, y: 0 });
    const c = world.addParticle({ x: 1, y: 1 });
    throwsNaming(() => world.addDistance(a, b, { compliance: 1e303 }), RangeError, 'compliance', '1e+303');
    throwsNaming(() => world.addAngleLimit(a, b, c, { min: 0, max: 1, compliance: 1e308 }), RangeError, 'compliance');
    throwsNaming(() => world.addPin(b, { x: 0, y: 0, compliance: 1e308 }), RangeError, 'compliance');
    throwsNaming(() => world.addAreaConstraint([a, b, c], { compliance: 1e308 }), RangeError, 'compliance');
    throwsNaming(() => world.addAreaConstraint([a, b, c], { pressure: 1e308 }), RangeError, 'pressure', '1e+308');
    throwsNaming(() => world.grab(1, 0, { stiffness: 1e-300 }), RangeError, 'stiffness', '1e-300');
    const o = { x: 0, y: 0 };
    throwsNaming(() => createCloth(world, { origin: o, columns: 3, rows: 3, spacing: 1, structural: 1e308 }), RangeError, 'structural');
    throwsNaming(() => createCloth(world, { origin: o, columns: 3, rows: 3, spacing: 1, shear: 1e308 }), RangeError, 'shear');
    throwsNaming(() => createCloth(world, { origin: o, columns: 3, rows: 3, spacing: 1, bend: 1e308 }), RangeError, 'bend');
    throwsNaming(() => createRope(world, { from: o, to: { x: 1, y: 0 }, compliance: 1e308 }), RangeError, 'compliance');
    throwsNaming(() => createSoftBody(world, { center: o, radius: 1, areaCompliance: 1e308 }), RangeError, 'areaCompliance');
    throwsNaming(() => createSoftBody(world, { center: o, radius: 1, compliance: 1e308 }), RangeError, 'compliance');
    throwsNaming(() => createRagdoll(world, { x: 0, y: 0, jointCompliance: 1e308 }), RangeError, 'jointCompliance');
    throwsNaming(() => createBox(world, { x: 0, y: 0, width: 1, height: 1, model: 'particles', compliance: 1e308 }), RangeError, 'compliance');
    const ground = createBox(world, { x: 0, y: 10, width: 40, height: 1, static: true }).body;
    const box = createBox(world, { x: 0, y: 7, width: 1, height: 1 }).body;
    throwsNaming(() => world.addJoint({ type: 'revolute', a: box, b: ground, anchor: { x: 0.5, y: 7.5 }, compliance: 1e303 }), RangeError, 'compliance');
    throwsNaming(() => world.addJoint({ type: 'spring', a: box, b: ground, anchorA: { x: 0, y: 7 }, anchorB: { x: 0, y: 9 }, stiffness: 1e-310 }), RangeError, 'stiffness');
    // At the limits, it steps on.
    world.addDistance(a, b, { compliance: 1e9 });
    world.addJoint({ type: 'spring', a: box, b: ground, anchorA: { x: 0, y: 7 }, anchorB: { x: 0, y: 9 }, stiffness: 1e-9 });
    stepsOn(world, 20);
  });

  it('masses below 1e-12 and bodies too small for a finite inertia are refused, whoever computes the mass', () => {
    const world = new World();
    throwsNaming(() => world.addParticle({ x: 0, y: 0, mass: 1e-310 }), RangeError, 'mass', '1e-310');
    throwsNaming(() => createRope(world, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 }, mass: 1e-320 }), RangeError, 'mass');
    throwsNaming(() => createCloth(world, { origin: { x: 0, y: 0 }, columns: 2, rows: 2, spacing: 1, mass: 1e-320 }), RangeError, 'mass');
    throwsNaming(() => createRagdoll(world, { x: 0, y: 0, mass: 1e-320 }), RangeError, 'mass');
    throwsNaming(() => createSoftBody(world, { center: { x: 0, y: 0 }, radius: 1e-300 }), RangeError, 'mass', 'π · radius²');
    throwsNaming(() => createCircle(world, { x: 0, y: 0, radius: 1e-200, model: 'particles' }), RangeError, 'mass', 'π · radius²');
    throwsNaming(() => createCircle(world, { x: 0, y: 0, radius: 1e-160 }), RangeError, 'mass', 'density × area');
    throwsNaming(() => createBox(world, { x: 0, y: 0, width: 1e-100, height: 1e-100, mass: 1 }), RangeError, 'moment of inertia');
    throwsNaming(() => createBox(world, { x: 0, y: 0, width: 1, height: 1, mass: 1e-320 }), RangeError, 'mass');
    throwsNaming(() => createPolygon(world, { x: 0, y: 0, points: [{ x: 0, y: 0 }, { x: 1e-100, y: 0 }, { x: 0, y: 1e-100 }], mass: 1 }), RangeError);
    expect(world.particleCount).to.equal(0);
    createCircle(world, { x: 0, y: 0, radius: 1e-3 });
    stepsOn(world);
  });

  it('gravity beyond ±1e9 is refused; a world whose box went NaN no longer breaks every later step', () => {
    throwsNaming(() => new World({ gravity: { x: 0, y: 1e200 } }), RangeError, 'gravity.y', '1e+200');
    throwsNaming(() => new World({ gravity: 0 as never }), TypeError, 'gravity', '0');
    const { world, box } = pile();
    throwsNaming(() => world.setGravity(-1e10, 0), RangeError, 'gravity.x');
    // NaN put in by hand (no call lets it in): the broad phase pairs it with nothing instead of throwing.
    const i = world.particleIndex(box.particles[0]);
    world.particles.x[i] = NaN;
    world.step();
    world.step();
    expect(world.stepCount).to.equal(2);
  });

  it("a body's particle is removed with its body only; restore() is all or nothing and refuses NaN", () => {
    const world = new World();
    const box = createBox(world, { x: 0, y: 0, width: 1, height: 1 });
    throwsNaming(() => world.removeParticle(box.particles[0]), RangeError, `particle ${box.particles[0]}`, `body ${box.body}`, 'removeBody');
    const frame = createBox(world, { x: 3, y: 0, width: 1, height: 1, model: 'particles' });
    throwsNaming(() => world.removeParticle(frame.particles[2]), RangeError, 'removeBody');
    expect(world.bodyPose(box.body)).to.deep.equal({ x: 0, y: 0, angle: 0 });
    world.removeBody(frame.body);
    expect(world.particleCount).to.equal(1);

    const other = new World();
    createRope(other, { from: { x: 0, y: 0 }, to: { x: 1, y: 0 } });
    const damaged = other.snapshot();
    (damaged.particles.columns[0] as Float64Array)[3] = NaN;
    const hash = world.stateHash();
    const gravity = world.gravity;
    throwsNaming(() => world.restore(damaged), RangeError, 'snapshot particles.x[3]', 'NaN');
    expect(world.stateHash()).to.equal(hash);
    const early = other.snapshot();
    early.time = -1;
    early.settings.gravity = { x: 5, y: 5 };
    throwsNaming(() => world.restore(early), RangeError, 'time');
    expect(world.gravity).to.deep.equal(gravity);
    expect(() => world.restore({ ...other.snapshot(), particleIds: {} } as never)).to.throw();
    expect(world.stateHash()).to.equal(hash);
    stepsOn(world);
  });

  it('a refused setter or argument changes nothing: time, stepCount, alpha, setPosition and setVelocity of a sleeping body', () => {
    const { world, box } = pile();
    throwsNaming(() => (world.time = NaN), RangeError, 'time', 'NaN');
    throwsNaming(() => (world.time = -5), RangeError, 'time', '-5');
    throwsNaming(() => (world.stepCount = 'x' as never), TypeError, 'stepCount', '"x"');
    throwsNaming(() => (world.alpha = 2), RangeError, 'alpha', '2');
    throwsNaming(() => new World({ sleeping: 'false' as never }), TypeError, 'sleeping', '"false"');
    throwsNaming(() => new World({ variableStep: 1 as never }), TypeError, 'variableStep', '1');
    throwsNaming(() => new World({ limits: 5 as never }), TypeError, 'limits', '5');
    throwsNaming(() => world.particleHandle(-1), RangeError, 'index', '-1');
    throwsNaming(() => world.particleHandle('3' as never), TypeError, 'index', '"3"');
    // A twin that got none of the refused calls ends in the same state.
    const twin = pile().world;
    for (let k = 0; k < 200; k++) [world, twin].forEach((w) => w.step());
    const p = box.particles[0];
    throwsNaming(() => world.setPosition(p, NaN, 0), RangeError, 'x');
    throwsNaming(() => world.setVelocity(p, 0, Infinity), RangeError, 'vy');
    expect(world.isAwake(box.body)).to.equal(false);
    for (let k = 0; k < 30; k++) [world, twin].forEach((w) => w.step());
    expect(world.stateHash()).to.equal(twin.stateHash());
    expect(world.time).to.equal(twin.time);
  });
});

describe('builders check everything before they make anything', () => {
  it('a refused collider option, switch or full body registry leaves the world exactly as it was (hash, handles, substeps)', () => {
    const world = new World({ limits: { bodies: 1 } });
    createBox(world, { x: 0, y: 0, width: 1, height: 1 });
    const hash = world.stateHash();
    const before = { particles: world.particles.count, substeps: world.substepCount };
    throwsNaming(() => createBox(world, { x: 3, y: 0, width: 1, height: 1 }), RangeError, 'too many bodies', 'limits.bodies');
    throwsNaming(() => world.addRigidBody({ x: 3, y: 0, radius: 1 }), RangeError, 'too many bodies');
    throwsNaming(() => createRope(world, { from: { x: 0, y: 0 }, to: { x: 3, y: 0 } }), RangeError, 'too many bodies');
    const roomy = new World();
    const roomyHash = roomy.stateHash();
    const from = { x: 0, y: 0 };
    const to = { x: 3, y: 0 };
    throwsNaming(() => createRope(roomy, { from, to, segments: 5, friction: -1 }), RangeError, 'friction', '-1');
    throwsNaming(() => createCloth(roomy, { origin: from, columns: 3, rows: 3, spacing: 1, restitution: 2 }), RangeError, 'restitution');
    throwsNaming(() => createSoftBody(roomy, { center: from, radius: 1, category: -1 }), RangeError, 'category');
    throwsNaming(() => createBox(roomy, { x: 0, y: 0, width: 1, height: 1, static: 'false' as never }), TypeError, 'static', '"false"');
    throwsNaming(() => createRope(roomy, { from, to, pinStart: 'no' as never }), TypeError, 'pinStart', '"no"');
    throwsNaming(() => createCloth(roomy, { origin: from, columns: 3, rows: 3, spacing: 1, tethers: 1 as never }), TypeError, 'tethers');
    expect(roomy.stateHash()).to.equal(roomyHash);
    expect(roomy.particles.count).to.equal(0);
    expect(roomy.addParticle({ x: 0, y: 0 })).to.equal(createRope(new World(), { from, to }).particles[0]); // the first handle, unspent
    expect(world.stateHash()).to.equal(hash);
    expect({ particles: world.particles.count, substeps: world.substepCount }).to.deep.equal(before);
  });

  it('a static rope or cloth does not move; a self-crossing outline is refused as the collision module refuses it', () => {
    const world = new World();
    const rope = createRope(world, { from: { x: 0, y: 0 }, to: { x: 4, y: 0 }, static: true });
    const cloth = createCloth(world, { origin: { x: 10, y: 0 }, columns: 4, rows: 4, spacing: 0.5, static: true });
    const at = [...rope.particles, ...cloth.particles].map((p) => world.getPosition(p));
    for (let k = 0; k < 60; k++) world.step();
    expect([...rope.particles, ...cloth.particles].map((p) => world.getPosition(p))).to.deep.equal(at);
    // A pentagram: each point joined to the second next.
    const star = [0, 2, 4, 1, 3].map((k) => ({ x: Math.cos((2 * Math.PI * k) / 5), y: Math.sin((2 * Math.PI * k) / 5) }));
    throwsNaming(() => createPolygon(world, { x: 0, y: 0, points: star }), RangeError, 'points', 'simple polygon', 'meets edge');
    throwsNaming(() => createPolygon(world, { x: 0, y: 0, points: star, model: 'particles' }), RangeError, 'simple polygon');
    const bowTie = [{ x: 0, y: 0 }, { x: 2, y: 2 }, { x: 2, y: 0 }, { x: 0, y: 1 }]; // two triangles of different areas
    throwsNaming(() => createPolygon(world, { x: 0, y: 0, points: bowTie }), RangeError, 'simple polygon');
    throwsNaming(() => world.addRigidBody({ x: 0, y: 0, points: bowTie }), RangeError, 'simple polygon');
    // A concave simple outline (an L) and the star's convex hull are still taken.
    createPolygon(world, { x: 5, y: 5, points: [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 2 }, { x: 0, y: 2 }] });
    createPolygon(world, { x: 8, y: 5, points: [0, 1, 2, 3, 4].map((k) => ({ x: Math.cos((2 * Math.PI * k) / 5), y: Math.sin((2 * Math.PI * k) / 5) })) });
  });

  it('a particle is in one body at most; a refused springs soft body takes its hub back; an SVG-closed outline builds', () => {
    const world = new World();
    const a = world.addParticle({ x: 0, y: 0 });
    const b = world.addParticle({ x: 1, y: 0 });
    const one = world.addBody('particle', [a]);
    throwsNaming(() => world.addBody('rope', [a, b]), RangeError, 'particles[0]', `already belongs to body ${one}`);
    throwsNaming(() => world.addBody('rope', [b, b]), RangeError, 'particles[1]', 'listed twice');
    const two = world.addBody('particle', [b]);
    world.removeBody(one);
    const c = world.addParticle({ x: 50, y: 50 }); // takes a's slot
    expect(world.bodyParticleHandles(two)).to.deep.equal([b]);
    world.removeParticle(c); // in no body
    throwsNaming(() => world.removeParticle(b), RangeError, `body ${two}`);
    // The owners survive a snapshot.
    const copy = new World();
    copy.restore(world.snapshot());
    throwsNaming(() => copy.removeParticle(b), RangeError, `body ${two}`);

    const tight = new World({ limits: { constraints: 20 } });
    throwsNaming(() => createSoftBody(tight, { center: { x: 0, y: 0 }, radius: 1, segments: 16, model: 'springs' }), RangeError, 'too many constraints');
    expect(tight.particleCount).to.equal(0);

    const square = [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 2 }, { x: 0, y: 2 }, { x: 0, y: 0 }];
    const frame = createPolygon(world, { x: 5, y: 5, points: square, model: 'particles' });
    expect(frame.particles.length).to.equal(4);
    const rigid = createPolygon(world, { x: 9, y: 5, points: square });
    expect(world.bodyMassInfo(rigid.body).mass).to.be.closeTo(4, 1e-12);
  });

  it('scene descriptions and bodies that are not objects or lists are TypeErrors naming what they are', () => {
    throwsNaming(() => buildScene(undefined as never), TypeError, 'scene description', 'undefined');
    throwsNaming(() => buildScene({} as never), TypeError, 'bodies', 'undefined');
    throwsNaming(() => buildScene({ bodies: {} } as never), TypeError, 'bodies', '{}');
    throwsNaming(() => buildBody(null as never, { type: 'box', x: 0, y: 0, width: 1, height: 1 }), TypeError, 'World', 'null');
    throwsNaming(() => createBox(undefined as never, { x: 0, y: 0, width: 1, height: 1 }), TypeError, 'World', 'undefined');
    const world = new World();
    const p = world.addParticle({ x: 0, y: 0 });
    throwsNaming(() => world.addBody('custom', [p], null as never), TypeError, 'constraints', 'null');
    throwsNaming(() => world.addBody('custom', [p], 5 as never), TypeError, 'constraints', '5');
  });
});
