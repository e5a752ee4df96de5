// The World's calls on a rigid body, behind its facade: each checks its arguments, finds the body's row and shape,
// and reads or writes the row (rigid/bodies.ts); anything it does to a body wakes it.
import type { Handle } from '../handles.js';
import { OPTION_NAMES, resolveCollider, type MassInfo, type Pose, type ResolvedCollider, type RigidBodyOptions, type Vec2 } from '../options.js';
import { knownNames, mass as massOf, MIN_INERTIA, objectOf, positive } from '../validate.js';
import { circleShape, compoundShape, polygonShape, withDensity } from './outline.js';
import type { StepContext } from '../pipeline/context.js';
import { ParticleFlag } from '../particles.js';
import { substepCount, verletReferenceHalf } from '../settings.js';
import { verletHalfSubstep } from '../integrate.js';
import { topologyChanged } from '../pipeline/topology.js';
import { angleOf, coordinate, finite, flag, FORCE_SPEED, IMPULSE_SPEED, oneOf, pushedSpeed, pushSpeed, speed } from '../validate.js';
import { applyForceAt, applyImpulseAt, poseOf, setPose, setType } from './bodies.js';
import type { JointSide } from './joint-setup.js';
import { BODY_TYPES, type BodyType, type BodyTypeName, type RigidShapeSource } from './shapes.js';

/** What addRigidBody makes, checked before anything is made: a TypeError/RangeError naming the option otherwise. */
export function rigidBodyPlan(o: RigidBodyOptions): {
  source: RigidShapeSource; type: BodyType; collider: ResolvedCollider; x: number; y: number; angle: number; vx: number; vy: number; w: number;
} {
  knownNames('rigid body option', objectOf('rigid body options', o), OPTION_NAMES.rigidBody);
  if ([o.points, o.radius, o.outlines].filter((v) => v !== undefined).length !== 1) throw new TypeError('a rigid body needs one of points (an outline), radius (a disc) or outlines');
  const shape = o.points !== undefined ? polygonShape(o.points) : o.outlines !== undefined ? compoundShape(o.outlines) : circleShape(o.radius as number);
  const type = BODY_TYPES.indexOf(oneOf('type', o.type ?? 'dynamic', BODY_TYPES)) as BodyType;
  if (o.mass !== undefined && o.density !== undefined) throw new TypeError('give a rigid body either mass or density, not both');
  const density = o.mass !== undefined ? positive('mass', o.mass) / shape.source.mass : positive('density', o.density ?? 1);
  const source = withDensity(shape, density);
  // Heavy and large enough that the inverse mass and inertia stay finite (a tiny outline's inertia underflows to 0),
  // whatever its type now (setBodyType may make it dynamic later).
  massOf('mass', source.mass, o.mass === undefined ? 'density × area' : '');
  if (!(source.inertia >= MIN_INERTIA)) throw new RangeError(`the body's moment of inertia must be at least 1e-30 (a larger outline or mass), got ${source.inertia}`);
  return {
    source,
    type,
    collider: resolveCollider({ ...o, shape: flag('collide', o.collide ?? true) ? 'polygon' : 'none', parts: undefined }, 3),
    x: coordinate('x', o.x),
    y: coordinate('y', o.y),
    angle: angleOf('angle', o.angle ?? 0),
    vx: speed('vx', o.vx ?? 0),
    vy: speed('vy', o.vy ?? 0),
    w: speed('angularVelocity', o.angularVelocity ?? 0),
  };
}

/** A rigid body's row, slot and shape; a RangeError naming `what` for any other body. */
export function rigidOf(ctx: StepContext, body: Handle, what = 'body'): { i: number; slot: number; source: RigidShapeSource } {
  const slot = ctx.bodies.slotOf(body, what);
  const source = ctx.rigidShapes.source(slot);
  if (!source) {
    // A particle frame's kind is 'rigid' (the thesis' rigid frame), which read "it is a rigid built of particles".
    const kind = ctx.bodies.kind[slot];
    const built = kind === 'rigid' ? "a frame of particles and sticks (model: 'particles')" : `a ${kind} built of particles`;
    throw new RangeError(`${what} ${body} is not a rigid body (it is ${built}: read or move its particles)`);
  }
  return { i: ctx.bodies.particles[slot][0], slot, source };
}

function wake(ctx: StepContext, slot: number): void {
  ctx.sleep.wakeBody(slot, ctx.bodies.particles[slot], ctx.particles);
}

export function bodyPose(ctx: StepContext, body: Handle): Pose {
  const r = rigidOf(ctx, body);
  return poseOf(ctx.particles, r.i, r.source);
}

export function setBodyPose(ctx: StepContext, body: Handle, x: number, y: number, angle: number): void {
  const r = rigidOf(ctx, body);
  setPose(ctx.particles, r.i, r.source, coordinate('x', x), coordinate('y', y), angleOf('angle', angle));
  wake(ctx, r.slot);
  wakeNear(ctx, r.slot);
}

/**
 * Wakes the bodies whose last bounding boxes meet body `slot`'s (where it was): what rested on a body that is moved
 * away (or a ground lowered under it) falls, where it stayed asleep in mid-air, no contact with a moving body left to
 * wake it. (Where the body arrives, its contacts wake what they touch.)
 */
function wakeNear(ctx: StepContext, slot: number): void {
  const { colliders: c, bodies } = ctx;
  if (slot >= c.minX.length) return;
  const margin = 0.01;
  const x0 = c.minX[slot] - margin;
  const y0 = c.minY[slot] - margin;
  const x1 = c.maxX[slot] + margin;
  const y1 = c.maxY[slot] + margin;
  for (let s = 0, n = Math.min(bodies.ids.high, c.minX.length); s < n; s++) {
    if (s === slot || !bodies.ids.alive[s] || c.minX[s] > x1 || c.maxX[s] < x0 || c.minY[s] > y1 || c.maxY[s] < y0) continue;
    wake(ctx, s);
  }
}

/**
 * The velocity a rigid body's row holds: the mean over the last substep (0 at rest; in free flight g·h/2 behind g·t).
 * Stored for the reference substep (verletReferenceHalf), it is read for the substep the world takes.
 */
export function bodyVelocity(ctx: StepContext, body: Handle): Vec2 {
  const { i } = rigidOf(ctx, body);
  const p = ctx.particles;
  const s = ctx.settings;
  const d = p.invMass[i] === 0 ? 0 : verletReferenceHalf(s, true) - verletHalfSubstep(s.integrator, s.timestep / substepCount(s, ctx.particleRows));
  return { x: p.vx[i] + s.gravity.x * d, y: p.vy[i] + s.gravity.y * d };
}

export function setBodyVelocity(ctx: StepContext, body: Handle, vx: number, vy: number): void {
  const r = rigidOf(ctx, body);
  const [x, y] = [speed('vx', vx), speed('vy', vy)];
  wake(ctx, r.slot);
  writeRowVelocity(ctx, r.i, x, y);
}

/**
 * Stores a row's velocity (a particle's or a rigid body's) as position Verlet's mean over the substep to come,
 * v − ½·g·h for its reference substep (verletReferenceHalf), so that a thrown body follows x0 + v0·t + ½·g·t²
 * exactly. A row that gravity does not move (static, kinematic, pinned, asleep: inverse mass 0) stores v itself.
 */
export function writeRowVelocity(ctx: StepContext, i: number, vx: number, vy: number): void {
  const half = rowHalf(ctx, i);
  ctx.particles.vx[i] = vx - ctx.settings.gravity.x * half;
  ctx.particles.vy[i] = vy - ctx.settings.gravity.y * half;
}

/** A row's velocity as writeRowVelocity was given it. */
function rowVelocity(ctx: StepContext, i: number): Vec2 {
  const half = rowHalf(ctx, i);
  return { x: ctx.particles.vx[i] + ctx.settings.gravity.x * half, y: ctx.particles.vy[i] + ctx.settings.gravity.y * half };
}

function rowHalf(ctx: StepContext, i: number): number {
  const p = ctx.particles;
  return p.invMass[i] === 0 ? 0 : verletReferenceHalf(ctx.settings, (p.flags[i] & ParticleFlag.Rigid) !== 0);
}

export function setBodyAngularVelocity(ctx: StepContext, body: Handle, w: number): void {
  const r = rigidOf(ctx, body);
  ctx.particles.omega[r.i] = speed('angularVelocity', w);
  wake(ctx, r.slot);
}

/** A force (or with `impulse`, an impulse) at a world point, by default the centre of mass. */
export function pushBody(ctx: StepContext, body: Handle, fx: number, fy: number, x: number | undefined, y: number | undefined, impulse: boolean): void {
  const r = rigidOf(ctx, body);
  const p = ctx.particles;
  const names = impulse ? ['ix', 'iy'] : ['fx', 'fy'];
  const [jx, jy] = [finite(names[0], fx), finite(names[1], fy)];
  const [px, py] = [x === undefined ? p.x[r.i] : coordinate('x', x), y === undefined ? p.y[r.i] : coordinate('y', y)];
  // The speeds it adds, along and around (a heavy body may take a large push): at once, or over a step.
  const seconds = impulse ? 1 : ctx.settings.timestep;
  // Checked against what the body wakes with (a sleeping body's inverse mass and inertia are parked at 0).
  const sleep = ctx.sleep;
  // Pushes add up: an impulse is checked with the velocity it adds to, a force with the step's earlier forces.
  const turn = (px - p.x[r.i]) * jy - (py - p.y[r.i]) * jx;
  if (impulse) {
    pushSpeed(IMPULSE_SPEED, jx, jy, sleep.awakeInvMass(r.i, p), 1, p.vx[r.i], p.vy[r.i]);
    pushedSpeed('the turn the impulse leaves (angularVelocity + its turn / inertia)', p.omega[r.i], p.omega[r.i] + turn * sleep.awakeInvInertia(r.i, p));
  } else {
    pushSpeed(FORCE_SPEED, p.fx[r.i] + jx, p.fy[r.i] + jy, sleep.awakeInvMass(r.i, p), seconds);
    speed('the turn the force adds (with the step\'s earlier torques) · timestep / inertia', (p.torque[r.i] + turn) * sleep.awakeInvInertia(r.i, p) * seconds);
  }
  // A force on a body that cannot move (static, kinematic) is dropped: kept, it was checked against no mass and acted
  // in full if the body was made dynamic before the step (1e13 gave 5e10 units/s).
  if (!impulse && sleep.awakeInvMass(r.i, p) === 0 && sleep.awakeInvInertia(r.i, p) === 0) return;
  wake(ctx, r.slot);
  if (impulse) applyImpulseAt(p, r.i, jx, jy, px, py);
  else applyForceAt(p, r.i, jx, jy, px, py);
}

export function applyBodyTorque(ctx: StepContext, body: Handle, torque: number): void {
  const r = rigidOf(ctx, body);
  const t = finite('torque', torque);
  // With the step's earlier torques: they add up.
  const invInertia = ctx.sleep.awakeInvInertia(r.i, ctx.particles);
  speed('torque · timestep / inertia (with the torques given since the last step)', (ctx.particles.torque[r.i] + t) * invInertia * ctx.settings.timestep);
  // Dropped on a body that cannot turn (as pushBody drops a force).
  if (invInertia === 0) return;
  ctx.particles.torque[r.i] += t;
  wake(ctx, r.slot);
}

export function bodyMassInfo(ctx: StepContext, body: Handle): MassInfo {
  const r = rigidOf(ctx, body);
  return { mass: r.source.mass, inertia: r.source.inertia, centerX: ctx.particles.x[r.i], centerY: ctx.particles.y[r.i] };
}

export function bodyType(ctx: StepContext, body: Handle): BodyTypeName {
  return BODY_TYPES[ctx.rigidShapes.type[rigidOf(ctx, body).slot]];
}

export function setBodyType(ctx: StepContext, body: Handle, type: BodyTypeName): void {
  const r = rigidOf(ctx, body);
  const t = BODY_TYPES.indexOf(oneOf('type', type, BODY_TYPES)) as BodyType;
  wake(ctx, r.slot);
  // A kinematic body keeps its velocity as a dynamic one and back: read and written as the row's kind stores it.
  const p = ctx.particles;
  const v = rowVelocity(ctx, r.i);
  ctx.rigidShapes.set(r.slot, r.i, r.source, t);
  setType(p, r.i, r.source, t);
  if (!(p.flags[r.i] & ParticleFlag.Static)) writeRowVelocity(ctx, r.i, v.x, v.y);
  ctx.collidersDirty = true;
  topologyChanged(ctx);
}

/** One side of a joint: a rigid body (or a body of one particle), a particle, or the world (row −1). */
export function jointSide(ctx: StepContext, body: Handle | null | undefined, particle: Handle | undefined, bodyName: string, particleName: string): JointSide {
  if (body != null && particle !== undefined) throw new TypeError(`give ${bodyName} or ${particleName}, not both`);
  if (particle !== undefined) return { row: ctx.particleIds.slotOf(particle, particleName), rigid: false };
  if (body == null) return { row: -1, rigid: false };
  const slot = ctx.bodies.slotOf(body, bodyName);
  const rigid = ctx.rigidShapes.source(slot) !== undefined;
  const members = ctx.bodies.particles[slot];
  if (!rigid && members.length !== 1) throw new RangeError(`${bodyName} ${body} is built of ${members.length} particles: join it by one of them (${particleName})`);
  return { row: members[0], rigid };
}
