// The step, as a short list of named phases over a StepContext (the layout of Box2D v3's b2World_Step):
//
//   prepare → detect collisions (bounding boxes, broad phase, narrow phase) → accelerate (gravity and forces, once)
//   → per substep: (accelerate again only when springs add to it) → integrate (positions; rigid bodies' angles; kinematic bodies) → place pins → aim grabs → reset
//     multipliers → relax (constraints, grabs, joints, contacts, rigid contacts, bounds) × iterations → derive
//     velocities (linear, angular) → contact velocities (particle, walls, rigid) → particle frames' bounces
//   → free bodies' spin, area loops' damping (spin.ts) → keep rows finite (guard.ts) → store contact anchors → break links → collision events → sleep → clear forces → advance the clock
//
// Each phase is a plain function over the context's typed arrays, called in the order written here: to add a phase
// (a table of rigid bodies, joints), write it as such a function and call it at its place. Nothing here allocates.
//
// With the WebAssembly kernel (World option kernel, ctx.kernel), integration (with the accelerations, unless springs
// add to them), velocities and the distance sweep run in it, over the same columns (kernel/wasm-kernel.ts), while the
// world has links to sweep (kernelAtWork); every other phase is the same JS function either way. Its rigid contact
// lanes have their own gate: a step whose rigid contacts are single points or two-point manifolds between rigid
// bodies or with the world, restitution 0 and no shock sweep (disc piles, box piles, pyramids) sweeps them there
// (kernel.beginRigid after the first substep's prepare, endRigid after the substeps); any other step, the JS solver.
// While the lanes hold a step's contacts the kernel also integrates positions and derives velocities (from the first
// substep's velocities on), links or not: the columns are in its memory then anyway.
import { breakOverstretched, solveDistances } from '../constraints/distance.js';
import { solveAngles } from '../constraints/angle.js';
import { placeRigidPins, solveSoftPins } from '../constraints/pin.js';
import { solveAreas } from '../constraints/area.js';
import { accumulateSprings } from '../constraints/spring.js';
import { aimGrabs, beginGrabStep, solveGrabs } from '../constraints/grab.js';
import { integrate, shiftVerletVelocities, updateVelocities, verletHalfSubstep } from '../integrate.js';
import { bounceOffBounds, keepInBounds } from '../bounds.js';
import { solveContacts, solveContactVelocities } from './contacts.js';
import { solveFrameBounces } from './frame-bounces.js';
import { detectCollisions } from './collide.js';
import { keepRowsFinite } from './guard.js';
import { dampLoops, keepFreeSpin, recordFreeSpin } from './spin.js';
import { ensureTopology } from './topology.js';
import type { StepContext } from './context.js';
import { MAX_STEP_SECONDS, MIN_STEP_SECONDS, substepCount, verletReferenceHalf } from '../settings.js';
import { integrateKinematic, integrateRotation, resyncRotation, syncRotation, updateAngularVelocity } from '../rigid/rows.js';
import { applySpringForces, hasSprings, holdWelded, solveJoints } from '../rigid/joints.js';
import { prepareRigidContacts, shockSweep, solveRigidContacts, solveRigidContactVelocities } from '../rigid/contact-solver.js';

/** One step of `dt` seconds in substepCount() substeps (settings.substeps, or by what moves under 'auto'). */
export function step(ctx: StepContext, dt: number): void {
  ensureTopology(ctx);
  if (isSettled(ctx)) {
    // Everything sleeps: nothing moves, nothing to compute.
    ctx.events.count = 0;
    ctx.breaks.count = 0;
    advanceClock(ctx, dt);
    return;
  }
  const t0 = ctx.measureTimings ? performance.now() : 0;
  const n = substepCount(ctx.settings, ctx.particleRows);
  const h = dt / n;
  // Between steps every movable row's stored velocity is v − ½·g·h for its reference substep (verletReferenceHalf); a
  // step of another substep (variableStep, World.step(dt), rigid bodies among moving particles under 'auto') holds it
  // for its own meanwhile, so a thrown particle or body keeps to its parabola through any of them. Detection and the
  // sleep test read the step's own (the mean over its last substep).
  const shifted = shiftVerletOffsets(ctx, h, 1);
  ctx.pinMoved = false;
  recordStartPositions(ctx);
  // Gravity and the substep, for the bounces (impact.ts): the particle contacts' approach speeds are taken in detection.
  const g = ctx.settings.gravity;
  const motion = ctx.substepMotion;
  motion[0] = g.x;
  motion[1] = g.y;
  motion[2] = h;
  motion[3] = verletHalfSubstep(ctx.settings.integrator, h);
  if (ctx.settings.bounds) ctx.wallHits.reserve(ctx.particles.count);
  ctx.wallHits.beginStep();
  if (ctx.eventTracker.active) ctx.eventTracker.recordStartVelocities(ctx.particles);
  detectCollisions(ctx, dt);
  recordFreeSpin(ctx);
  kernelAtWork(ctx)?.beginStep(ctx);
  // The rigid lanes are taken (or not) in this step's first substep (a step that threw may have left them on).
  if (ctx.kernel) ctx.kernel.rigidLanes = false;
  const t1 = ctx.measureTimings ? performance.now() : 0;
  // Gravity and the user's forces hold for the whole step: their accelerations once, unless springs add to them.
  if (!perSubstepAccelerations(ctx) && !fusedAccelerations(ctx)) accelerate(ctx, h);
  if (ctx.constraints.grabs.count > 0) beginGrabStep(ctx.constraints.grabs, dt);
  for (let s = 0; s < n; s++) substep(ctx, h);
  if (ctx.kernel?.rigidLanes) ctx.kernel.endRigid(ctx.rigidContacts);
  if (ctx.measureTimings) {
    ctx.timings.detect = t1 - t0;
    ctx.timings.solve = performance.now() - t1;
  }
  ctx.anchors.store(ctx.contacts);
  // The rotations follow the last substep's corrections before anything outside the solver reads them.
  if (ctx.rigidCount > 0) syncRotation(ctx.particles, ctx.rigidRows, ctx.rigidCount);
  // Bodies of particles that nothing outside touched turn on as they began the step (spin.ts: v from the moves lost it).
  keepFreeSpin(ctx, n, 1 / (1 + h * ctx.settings.damping));
  // Soft bodies' material damping (the pressure model's), on the step's velocities.
  if (ctx.constraints.areas.count > 0) dampLoops(ctx, dt);
  keepRowsFinite(ctx);
  ctx.rigidAnchors.store(ctx.rigidContacts, ctx.particles);
  breakLinks(ctx);
  if (ctx.eventTracker.active) ctx.eventTracker.update(ctx.contacts, ctx.rigidContacts, ctx.wallHits, ctx.particles, ctx.substepMotion, ctx.bodies, ctx.bodyHandleOf, ctx.bodyAlive, ctx.bodyResting, ctx.events);
  updateSleep(ctx, dt);
  if (shifted) shiftVerletOffsets(ctx, h, -1);
  clearForces(ctx);
  advanceClock(ctx, dt);
}

/** One substep of length h. */
export function substep(ctx: StepContext, h: number): void {
  const { settings, particles } = ctx;
  const kernel = kernelAtWork(ctx);
  const damp = 1 / (1 + h * settings.damping);
  // The kernel's Verlet step computes the accelerations itself (gravity and forces) unless springs add to them;
  // without springs, step() computed them once for all substeps.
  const fused = fusedAccelerations(ctx);
  if (perSubstepAccelerations(ctx)) accelerate(ctx, h);
  // While the rigid lanes hold this step's contacts (every substep after the first) the columns live in the kernel's
  // memory: its Verlet step (the same arithmetic, two rows a lane) runs then too, on the accelerations step() computed
  // (fused is false without links).
  const positionKernel = kernel ?? lanesKernel(ctx);
  if (positionKernel && settings.integrator === 'verlet') positionKernel.integrateVerlet(particles, h, damp, fused ? settings.gravity : null);
  else integrate(particles, h, damp, settings.integrator);
  // Where each particle integrated to, before any contact: a particle frame bounces from that motion (frame-bounces.ts).
  if (ctx.frameBounces.anyFrame) {
    particles.qx.set(particles.x);
    particles.qy.set(particles.y);
  }
  const sub = ctx.substepReals;
  sub[0] = h;
  sub[1] = damp;
  // integrateRotation also brings every rigid row's rotation (rc, rs) up to its angle: the last substep's corrections
  // and this substep's turn (no separate syncRotation pass).
  if (ctx.rigidCount > 0) integrateRotation(particles, particles.torque, ctx.rigidRows, ctx.rigidCount, sub);
  if (ctx.kinematicCount > 0) integrateKinematic(particles, ctx.kinematicRows, ctx.kinematicCount, sub);
  // The rigid contacts' substep start (no correction yet, allowances shrink) is part of their prepare pass.
  const rigid = ctx.rigidContacts;
  if (rigid.count > 0) {
    if (ctx.kernel?.rigidLanes) ctx.kernel.rigidBeginSubstep(settings.maxPushSpeed * h);
    else {
      // The step's first substep (the contacts are not yet ordered): the kernel may take them into its lanes.
      const first = !rigid.shockReady;
      prepareRigidContacts(rigid, particles, settings.maxPushSpeed * h, ctx.constraints.joints);
      if (first && ctx.kernel) ctx.kernel.beginRigid(ctx);
    }
  }
  placeRigidPins(ctx.constraints.pins, particles);
  if (ctx.constraints.grabs.count > 0) aimGrabs(ctx.constraints.grabs, h);
  resetMultipliers(ctx);
  ctx.contacts.beginSubstep(settings.maxPushSpeed * h);
  for (let k = 0; k < settings.iterations; k++) relax(ctx, h);
  // Likewise v = (x − px)/h, once the lanes are taken (in this substep's prepare or before).
  const velocityKernel = kernel ?? lanesKernel(ctx);
  if (velocityKernel && settings.integrator !== 'explicit-euler') velocityKernel.updateVelocities(particles, h);
  else updateVelocities(particles, h, settings.integrator);
  if (ctx.rigidCount > 0) updateAngularVelocity(particles, ctx.rigidRows, ctx.rigidCount, sub);
  const bounces = ctx.frameBounces;
  if (ctx.contacts.count > 0) solveContactVelocities(ctx.contacts, particles, h, bounces);
  if (ctx.wallHits.count > 0) bounceOffBounds(ctx.wallHits, particles, ctx.bodies, ctx.colliders.restitution, settings.boundsFriction, ctx.substepMotion, bounces);
  if (rigid.count > 0) {
    if (ctx.kernel?.rigidLanes) ctx.kernel.rigidVelocities();
    else solveRigidContactVelocities(rigid, particles, h, bounces);
  }
  // The bounces again, with each particle frame in them as one rigid body.
  if (bounces.count > 0) solveFrameBounces(bounces, particles, ctx.bodies, h);
}

/** The stored v − ½·g·h made for substeps of length h instead of the reference ones (sign 1), or back (−1); false when both are h. */
function shiftVerletOffsets(ctx: StepContext, h: number, sign: 1 | -1): boolean {
  const s = ctx.settings;
  const half = verletHalfSubstep(s.integrator, h);
  // Only kinds of rows the world has (a world of rigid bodies alone steps at its rigid rows' reference: no pass).
  const dp = ctx.particleRows > 0 ? sign * (verletReferenceHalf(s, false) - half) : 0;
  const dr = ctx.rigidCount > 0 ? sign * (verletReferenceHalf(s, true) - half) : 0;
  if (dp === 0 && dr === 0) return false;
  shiftVerletVelocities(ctx.particles, s.gravity.x * dp, s.gravity.y * dp, s.gravity.x * dr, s.gravity.y * dr);
  return true;
}

/** The kernel's Verlet step computes the accelerations itself (gravity and forces) when no springs add to them. */
function fusedAccelerations(ctx: StepContext): boolean {
  return kernelAtWork(ctx) !== null && ctx.settings.integrator === 'verlet' && !perSubstepAccelerations(ctx);
}

/** Springs (particle springs, spring joints) change the accelerations from substep to substep. */
function perSubstepAccelerations(ctx: StepContext): boolean {
  const { springs, joints } = ctx.constraints;
  return springs.count > 0 || (joints.count > 0 && hasSprings(joints));
}

/**
 * The WebAssembly kernel when it has links to sweep. Without any (a world of rigid bodies, free particles) the JS
 * loops integrate: the same doubles (position Verlet is the same arithmetic either way), and the rigid solver's loops
 * ran slower between the kernel's calls (S2, 1000 boxes: 2.6 against 2.2 ms per step), except while the rigid lanes
 * hold the step's contacts (substep above: their columns are in the kernel's memory already).
 */
function kernelAtWork(ctx: StepContext) {
  return ctx.kernel !== null && ctx.constraints.distances.count > 0 ? ctx.kernel : null;
}

/** The WebAssembly kernel while its rigid lanes hold this step's contacts. */
function lanesKernel(ctx: StepContext) {
  return ctx.kernel !== null && ctx.kernel.rigidLanes ? ctx.kernel : null;
}

/**
 * Real time has passed: take as many fixed steps as fit (at most maxCatchUpSteps; an older backlog is dropped so a
 * stalled tab does not spiral), calling `afterStep` after each, and leave the remainder's fraction in `alpha`. In
 * variableStep mode, take one step of the elapsed time instead. Returns the steps taken.
 */
export function advance(ctx: StepContext, elapsed: number, afterStep?: () => void): number {
  const { timestep, maxCatchUpSteps } = ctx.settings;
  if (ctx.settings.variableStep) {
    // Elapsed times shorter than a step can be are gathered until they make one.
    ctx.accumulator += elapsed;
    if (ctx.accumulator < MIN_STEP_SECONDS) return 0;
    step(ctx, Math.min(ctx.accumulator, timestep * maxCatchUpSteps, MAX_STEP_SECONDS));
    ctx.accumulator = 0;
    ctx.alpha = 1;
    afterStep?.();
    return 1;
  }
  ctx.accumulator += elapsed;
  let taken = 0;
  while (ctx.accumulator >= timestep && taken < maxCatchUpSteps) {
    step(ctx, timestep);
    ctx.accumulator -= timestep;
    taken++;
    afterStep?.();
  }
  if (ctx.accumulator >= timestep) ctx.accumulator %= timestep;
  ctx.alpha = ctx.accumulator / timestep;
  return taken;
}

/** True when every body is asleep and no free particle moves: a step then does no work. */
export function isSettled(ctx: StepContext): boolean {
  const sleep = ctx.sleep;
  return !ctx.topologyDirty && !ctx.pinMoved && sleep.enabled && sleep.awakeCount === 0 && ctx.freeMovableParticles === 0 && ctx.constraints.grabs.count === 0;
}

/**
 * Where each particle starts the step (sleeping judges motion over whole steps, not substep jitter); one rigid row in
 * RESYNC_STEPS has its cos/sin taken afresh from its angle (the substeps turn them incrementally: resyncRotation).
 */
function recordStartPositions(ctx: StepContext): void {
  const p = ctx.particles;
  const { x, y, sx, sy, angle, sangle } = p;
  for (let i = 0, n = p.count; i < n; i++) {
    sx[i] = x[i];
    sy[i] = y[i];
    sangle[i] = angle[i];
  }
  if (ctx.rigidCount > 0) resyncRotation(p, ctx.rigidRows, ctx.rigidCount, ctx.stepCount);
}

/** Gravity, the user's forces and the springs' forces, as accelerations. */
function accelerate(ctx: StepContext, h: number): void {
  const p = ctx.particles;
  const { ax, ay, fx, fy, invMass } = p;
  const gx = ctx.settings.gravity.x;
  const gy = ctx.settings.gravity.y;
  for (let i = 0, n = p.count; i < n; i++) {
    ax[i] = gx + fx[i] * invMass[i];
    ay[i] = gy + fy[i] * invMass[i];
  }
  const { springs, joints } = ctx.constraints;
  if (springs.count > 0) accumulateSprings(springs, p, ax, ay, h);
  if (joints.count > 0) applySpringForces(joints, p, ax, ay, h);
}

/** XPBD multipliers start each substep at zero. */
function resetMultipliers(ctx: StepContext): void {
  const { distances, angles, areas, pins, grabs, joints } = ctx.constraints;
  if (joints.count > 0) joints.beginSubstep();
  // The kernel keeps the distance multipliers in its own lanes (and starts them at zero itself).
  const kernel = kernelAtWork(ctx);
  if (kernel) kernel.resetLambdas();
  else if (distances.count > 0) distances.lambda.fill(0, 0, distances.count);
  // Only the tables in use: each fill is a call, and most worlds use one or two kinds (a fixed cost of every substep).
  if (angles.count > 0) angles.lambda.fill(0, 0, angles.count);
  if (areas.count > 0) areas.lambda.fill(0, 0, areas.count);
  if (pins.count > 0) {
    pins.lambdaX.fill(0, 0, pins.count);
    pins.lambdaY.fill(0, 0, pins.count);
  }
  if (grabs.count > 0) {
    grabs.lambdaX.fill(0, 0, grabs.count);
    grabs.lambdaY.fill(0, 0, grabs.count);
  }
}

/** One Gauss–Seidel sweep over every constraint, then the joints, the contacts and the bounds. */
function relax(ctx: StepContext, h: number): void {
  const p = ctx.particles;
  const h2 = h * h;
  const { distances, angles, areas, pins, grabs, joints } = ctx.constraints;
  const kernel = kernelAtWork(ctx);
  if (kernel) kernel.solveDistances(h2);
  else if (distances.count > 0) solveDistances(distances, p, h2);
  if (angles.count > 0) solveAngles(angles, p, h2);
  if (areas.count > 0) solveAreas(areas, p, h2);
  if (pins.count > 0) solveSoftPins(pins, p, h2);
  if (grabs.count > 0) solveGrabs(grabs, p, h2);
  if (joints.count > 0) solveJoints(joints, p, h);
  if (ctx.contacts.count > 0) solveContacts(ctx.contacts, p, ctx.substepMotion);
  if (ctx.rigidContacts.count > 0) {
    if (ctx.kernel?.rigidLanes) ctx.kernel.rigidSweep();
    else solveRigidContacts(ctx.rigidContacts, p);
    if (ctx.rigidContacts.shockCount > 0) {
      if (joints.count > 0) holdWelded(joints, p);
      shockSweep(ctx.rigidContacts, p);
    }
  }
  const bounds = ctx.settings.bounds;
  if (bounds) keepInBounds(p, bounds, ctx.settings.boundsFriction, ctx.wallHits);
}

/** Tearing: links stretched past their breakStrain break; their handles go to `breaks`. */
function breakLinks(ctx: StepContext): void {
  ctx.breaks.count = 0;
  if (ctx.hasBreakableLinks) breakOverstretched(ctx.constraints.distances, ctx.particles, ctx.recordBreak);
  if (ctx.breaks.count > 0) ctx.kernel?.distanceLimitsChanged();
}

function updateSleep(ctx: StepContext, dt: number): void {
  ctx.sleep.update(ctx.bodies.ids.high, ctx.bodies.ids.alive, ctx.bodyParticlesOf, ctx.particles, ctx.contacts, ctx.rigidContacts, dt);
}

/** The user's forces act for one step. */
function clearForces(ctx: StepContext): void {
  const p = ctx.particles;
  p.fx.fill(0, 0, p.count);
  p.fy.fill(0, 0, p.count);
  p.torque.fill(0, 0, p.count);
}

function advanceClock(ctx: StepContext, dt: number): void {
  ctx.time += dt;
  ctx.stepCount++;
}
