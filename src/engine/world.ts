import { handleSlot, MAX_SLOTS, type Handle } from './handles.js';
import { ParticleFlag, type ParticleStore } from './particles.js';
import type { Column } from './table.js';
import { signedAngle, type AngleConstraints } from './constraints/angle.js';
import { loopArea, type AreaConstraints } from './constraints/area.js';
import { stretchOf, type DistanceConstraints } from './constraints/distance.js';
import type { PinConstraints } from './constraints/pin.js';
import type { Springs } from './constraints/spring.js';
import { grabLag, type GrabConstraints } from './constraints/grab.js';
import { shiftVerletVelocities, type Integrator } from './integrate.js';
import type { Bounds } from './bounds.js';
import { hashColumns } from './hash.js';
import { GridBroadPhase, makeBroadPhase, type PairList } from './pipeline/broadphase.js';
import { ColliderKind, type Colliders } from './pipeline/colliders.js';
import type { Contacts } from './pipeline/contacts.js';
import type { CollisionEvents } from './pipeline/events.js';
import type { NarrowPhase } from './pipeline/narrowphase.js';
import { bodiesAtPoint, bodiesInBox, rayCast } from './pipeline/queries.js';
import { StepContext } from './pipeline/context.js';
import { advance, isSettled, step } from './pipeline/step.js';
import { ensureTopology, topologyChanged, wakeAll, wakeParticle } from './pipeline/topology.js';
import { pickGrabPoint } from './pipeline/pick.js';
import { Kind } from './constraint-registry.js';
import { applyImpulseByMass, centroid, softRingLength } from './body-registry.js';
import { BODY_KINDS, DEFAULT_LIMITS, OPTION_NAMES, resolveCollider, type ResolvedCollider } from './options.js';
import type { AngleOptions, AreaOptions, BodyKind, ColliderOptions, ConstraintKind, DistanceOptions, GrabOptions } from './options.js';
import type { JointOptions, Limits, MassInfo, ParticleOptions, PinOptions, Pose, RayCastHit, RigidBodyOptions, SpringOptions, SubstepChoice, Vec2, WorldOptions } from './options.js';
import { BROAD_PHASES, CHECK, checkedSettings, DEFAULTS, MAX_STEP_SECONDS, NARROW_PHASES, stepLength, verletReferenceHalf, substepCount, type StepSettings } from './settings.js';
import { restoreContext, snapshotContext, type WorldSnapshot } from './snapshot.js';
import type { KernelOptions, WorldDiagnostics } from './kernel/choice.js';
import { BodyType, type BodyTypeName } from './rigid/shapes.js';
import { initRigidRow } from './rigid/bodies.js';
import { jointRow } from './rigid/joint-setup.js';
import * as api from './rigid/body-api.js';
import { compliance as complianceOf, flag, MAX_PRESSURE, mass as massOf, coordinate, describeValue, stiffness as stiffnessOf, finite, integer, knownNames, knownOptions, objectOf, nonNegative, nonNegativeOrInfinity, oneOf, positive, pushSpeed, unit, speed, FORCE_SPEED, IMPULSE_SPEED } from './validate.js';

export type { Handle } from './handles.js';
export type { Integrator } from './integrate.js';
export type { Bounds } from './bounds.js';
export type { WorldSnapshot } from './snapshot.js';
export type { Vec2, WorldOptions, Limits, GrabOptions, RayCastHit, ColliderOptions, ParticleOptions } from './options.js';
export type { RigidBodyOptions, Pose, MassInfo, JointOptions, JointType } from './options.js';
export type { DistanceOptions, AngleOptions, SpringOptions, PinOptions, AreaOptions, BodyKind, ConstraintKind } from './options.js';
export { BODY_KINDS, COLLIDER_SHAPES, DEFAULT_LIMITS } from './options.js';

export { MAX_STEP_SECONDS, MIN_STEP_SECONDS } from './settings.js';

/** The names `new World(options)` takes: the settings, their limits and the solver kernel. */
const WORLD_OPTIONS = [...Object.keys(DEFAULTS), 'limits', 'kernel'];

/**
 * The headless engine: Verlet particles, constraints relaxed by Gauss–Seidel (XPBD) iterations inside substeps,
 * bodies as groups of particles and constraints. No DOM: runs in Node, a worker or the main thread.
 *
 * A facade: it checks the arguments of its public API and delegates to the parts of its StepContext (the tables, the
 * body and constraint registries, the collision pipeline, sleep). The step itself is pipeline/step.ts; snapshot and
 * restore are snapshot.ts.
 */
export class World {
  /** Everything the world holds. */
  private readonly ctx: StepContext;

  constructor(options: WorldOptions & KernelOptions = {}) {
    if (typeof options !== 'object') throw new TypeError(`options must be an object, got ${describeValue(options)}`);
    options ??= {};
    knownOptions('World option', options, WORLD_OPTIONS);
    if (options.limits != null) knownOptions('limits option', objectOf('limits', options.limits), Object.keys(DEFAULT_LIMITS));
    const o = { ...DEFAULTS, ...options };
    const settings = checkedSettings(o);
    const ctx = new StepContext(settings, makeBroadPhase(oneOf('broadphase', o.broadphase, BROAD_PHASES), nonNegative('cellSize', o.cellSize)), options.kernel);
    ctx.narrowPhase.mode = oneOf('narrowphase', o.narrowphase, NARROW_PHASES);
    ctx.sleep.enabled = flag('sleeping', o.sleeping);
    const limits = { ...DEFAULT_LIMITS, ...options.limits };
    ctx.particleIds.limit = integer('limits.particles', limits.particles, 1, MAX_SLOTS);
    ctx.constraints.ids.limit = integer('limits.constraints', limits.constraints, 1, MAX_SLOTS);
    ctx.bodies.ids.limit = integer('limits.bodies', limits.bodies, 1, MAX_SLOTS);
    this.ctx = ctx;
  }

  // ---- the state, to read (renderers, diagnostics, tests): typed arrays per field, indexed by storage slot ----

  get particles(): ParticleStore { return this.ctx.particles; }
  get distances(): DistanceConstraints { return this.ctx.constraints.distances; }
  get angles(): AngleConstraints { return this.ctx.constraints.angles; }
  get pins(): PinConstraints { return this.ctx.constraints.pins; }
  get springs(): Springs { return this.ctx.constraints.springs; }
  get areas(): AreaConstraints { return this.ctx.constraints.areas; }
  get grabs(): GrabConstraints { return this.ctx.constraints.grabs; }
  /** Begin/end collision events of the last step (collected from the first time they are read); WORLD_BOUNDS as a body: the bounds. */
  get events(): CollisionEvents { this.ctx.eventTracker.activate(this.ctx.contacts, this.ctx.rigidContacts, this.ctx.wallHits, this.ctx.bodies); return this.ctx.events; }
  /** Handles of the distance constraints that broke in the last step (see DistanceOptions.breakStrain). */
  get breaks(): { count: number; handles: Float64Array } { return this.ctx.breaks; }
  /** Collision state: per body slot colliders, the last step's candidate pairs and contacts. */
  get colliders(): Colliders { return this.ctx.colliders; }
  get contacts(): Contacts { return this.ctx.contacts; }
  get pairs(): PairList { return this.ctx.pairs; }
  get narrowPhase(): NarrowPhase { return this.ctx.narrowPhase; }
  /** When true, each step records how long collision detection and the substeps took (ms) in `timings`. */
  get measureTimings(): boolean { return this.ctx.measureTimings; }
  set measureTimings(v: boolean) { this.ctx.measureTimings = flag('measureTimings', v); }
  get timings(): { detect: number; solve: number } { return this.ctx.timings; }
  /** Which solver kernel runs (WorldOptions kernel: 'js' | 'wasm' | 'auto'), and why not WebAssembly if it does not. */
  diagnostics(): WorldDiagnostics { return { ...this.ctx.kernelDiagnostics, rowsRepaired: this.ctx.rowsRepaired }; }

  /** Simulated seconds. */
  get time(): number { return this.ctx.time; }
  set time(v: number) { this.ctx.time = nonNegative('time', v); }
  /** Steps taken. */
  get stepCount(): number { return this.ctx.stepCount; }
  set stepCount(v: number) { this.ctx.stepCount = integer('stepCount', v, 0); }
  /** Fraction of a step left in the accumulator after advance(): blend the two newest states by it to render. */
  get alpha(): number { return this.ctx.alpha; }
  set alpha(v: number) { this.ctx.alpha = unit('alpha', v); }

  // ---- settings (validated) ----------------------------------------------------------------------------------

  private get settings(): StepSettings {
    return this.ctx.settings;
  }
  /** Acceleration of gravity, a copy. Set it (or call setGravity()): checked, and every body wakes to feel it. */
  get gravity(): Vec2 { return { ...this.settings.gravity }; }
  set gravity(v: Vec2) {
    const gravity = CHECK.gravity(v);
    wakeAll(this.ctx);
    this.keepingVelocities(() => (this.settings.gravity = gravity));
  }
  /** A box the particles cannot leave, or null (checked when set, as by setBounds()). */
  get bounds(): Bounds | null { return this.settings.bounds; }
  set bounds(v: Bounds | null) { this.settings.bounds = CHECK.bounds(v); }
  get variableStep(): boolean { return this.settings.variableStep; }
  set variableStep(v: boolean) { this.settings.variableStep = CHECK.variableStep(v); }
  get timestep(): number { return this.settings.timestep; }
  set timestep(v: number) {
    const timestep = CHECK.timestep(v);
    this.keepingVelocities(() => (this.settings.timestep = timestep));
  }
  /** The substeps option: a count, or 'auto' (see WorldOptions.substeps; substepCount is the count it gives now). */
  get substeps(): SubstepChoice { return this.settings.substeps; }
  set substeps(v: SubstepChoice) {
    const substeps = CHECK.substeps(v);
    this.keepingVelocities(() => (this.settings.substeps = substeps));
  }
  /** The substeps the next step takes: the count set, or under 'auto' AUTO_SUBSTEPS.rigid (6) for a world of rigid bodies, else AUTO_SUBSTEPS.particles (10). */
  get substepCount(): number {
    ensureTopology(this.ctx);
    return substepCount(this.settings, this.ctx.particleRows);
  }
  get iterations(): number { return this.settings.iterations; }
  set iterations(v: number) { this.settings.iterations = CHECK.iterations(v); }
  get damping(): number { return this.settings.damping; }
  set damping(v: number) { this.settings.damping = CHECK.damping(v); }
  get integrator(): Integrator { return this.settings.integrator; }
  set integrator(v: Integrator) {
    const integrator = CHECK.integrator(v);
    this.keepingVelocities(() => (this.settings.integrator = integrator));
  }
  get boundsFriction(): number { return this.settings.boundsFriction; }
  set boundsFriction(v: number) { this.settings.boundsFriction = CHECK.boundsFriction(v); }
  get maxCatchUpSteps(): number { return this.settings.maxCatchUpSteps; }
  set maxCatchUpSteps(v: number) { this.settings.maxCatchUpSteps = CHECK.maxCatchUpSteps(v); }
  get maxPushSpeed(): number { return this.settings.maxPushSpeed; }
  set maxPushSpeed(v: number) { this.settings.maxPushSpeed = CHECK.maxPushSpeed(v); }
  get contactSlop(): number { return this.settings.contactSlop; }
  set contactSlop(v: number) { this.settings.contactSlop = CHECK.contactSlop(v); }

  setGravity(x: number, y: number): void {
    this.gravity = { x, y };
  }
  setBounds(bounds: Bounds | null): void {
    this.settings.bounds = CHECK.bounds(bounds);
  }

  /** The substep length h = timestep / substepCount. */
  get substepDt(): number {
    return this.settings.timestep / this.substepCount;
  }

  /** The caps in force. */
  get limits(): Limits {
    const ctx = this.ctx;
    return { particles: ctx.particleIds.limit, constraints: ctx.constraints.ids.limit, bodies: ctx.bodies.ids.limit };
  }

  get broadphase(): 'grid' | 'brute' {
    return this.ctx.broadPhase.name;
  }
  set broadphase(v: 'grid' | 'brute') {
    this.ctx.broadPhase = makeBroadPhase(oneOf('broadphase', v, BROAD_PHASES), this.cellSize);
  }
  get narrowphase(): 'sat' | 'gjk' {
    return this.ctx.narrowPhase.mode;
  }
  set narrowphase(v: 'sat' | 'gjk') {
    this.ctx.narrowPhase.mode = oneOf('narrowphase', v, NARROW_PHASES);
  }
  get cellSize(): number {
    return this.ctx.broadPhase instanceof GridBroadPhase ? this.ctx.broadPhase.cellSize : 0;
  }
  set cellSize(v: number) {
    nonNegative('cellSize', v);
    if (this.ctx.broadPhase instanceof GridBroadPhase) this.ctx.broadPhase.cellSize = v;
  }
  /** The cell size the grid used in the last step (after the automatic choice). */
  get gridCellSize(): number {
    return this.ctx.broadPhase instanceof GridBroadPhase ? this.ctx.broadPhase.lastCellSize : 0;
  }

  // ---- sleep -------------------------------------------------------------------------------------------------

  /** Whether bodies at rest fall asleep. Turning it off wakes everything. */
  get sleeping(): boolean {
    return this.ctx.sleep.enabled;
  }
  set sleeping(v: boolean) {
    this.ctx.sleep.enabled = flag('sleeping', v);
    if (!v) this.wakeAll();
  }

  /** Whether a body is being simulated (false once it has fallen asleep). */
  isAwake(body: Handle): boolean {
    return this.ctx.sleep.asleep[this.ctx.bodies.slotOf(body)] !== 1;
  }

  /** Wakes a sleeping body (its island wakes with it on contact). */
  wake(body: Handle): void {
    const slot = this.ctx.bodies.slotOf(body);
    this.ctx.sleep.wakeBody(slot, this.ctx.bodies.particles[slot], this.ctx.particles);
  }

  wakeAll(): void {
    wakeAll(this.ctx);
  }

  /** True when every body is asleep and no free particle moves: a step then does no work. */
  get settled(): boolean {
    return isSettled(this.ctx);
  }

  // ---- particles ---------------------------------------------------------------------------------------------

  addParticle(options: ParticleOptions): Handle {
    knownNames('particle option', objectOf('particle options', options), OPTION_NAMES.particle);
    const x = coordinate('x', options.x);
    const y = coordinate('y', options.y);
    const mass = options.mass === undefined ? 1 : options.mass;
    if (mass !== Infinity) massOf('mass', mass);
    const radius = coordinate('radius', nonNegative('radius', options.radius ?? 0));
    const vx = speed('vx', options.vx ?? 0);
    const vy = speed('vy', options.vy ?? 0);

    const handle = this.ctx.particleIds.allocate();
    const slot = handleSlot(handle);
    const p = this.ctx.particles;
    if (slot >= p.count) p.pushRow();
    for (const name of p.columns) (p as unknown as Record<string, Column>)[name][slot] = 0;
    p.x[slot] = p.px[slot] = p.qx[slot] = x;
    p.y[slot] = p.py[slot] = p.qy[slot] = y;
    p.invMass[slot] = mass === Infinity ? 0 : 1 / mass;
    p.radius[slot] = radius;
    p.alive[slot] = 1;
    p.rc[slot] = 1; // a particle's frame is the world's (angle 0)
    p.flags[slot] = mass === Infinity ? ParticleFlag.Static : 0;
    api.writeRowVelocity(this.ctx, slot, vx, vy);
    topologyChanged(this.ctx);
    return handle;
  }

  /** Removes a particle and every constraint that uses it. */
  removeParticle(handle: Handle): void {
    const { ctx } = this;
    const slot = ctx.particleIds.slotOf(handle, 'particle');
    // A body keeps its particles by storage index (a rigid body's row, a frame's corners, its parts): one removed
    // alone would leave the body holding whatever particle takes the slot next.
    const owner = ctx.bodies.ownerOf(slot);
    if (owner >= 0) throw new RangeError(`particle ${handle} belongs to body ${ctx.bodies.ids.handleOf(owner)}: remove the body (removeBody) instead`);
    this.releaseParticle(handle, slot);
  }

  /** Removes a live particle and the constraints that use it (its body, if any, is being removed). */
  private releaseParticle(handle: Handle, slot: number): void {
    const { ctx } = this;
    topologyChanged(ctx);
    for (const c of ctx.constraints.using(slot)) this.removeConstraint(c);
    const p = ctx.particles;
    p.alive[slot] = 0;
    p.invMass[slot] = 0;
    p.flags[slot] = 0;
    ctx.particleIds.release(handle);
  }

  hasParticle(handle: unknown): boolean { return this.ctx.particleIds.isValid(handle); }
  /** The storage index of a live particle handle (index into world.particles' arrays). */
  particleIndex(handle: Handle): number { return this.ctx.particleIds.slotOf(handle, 'particle'); }
  /** The handle of the particle stored at `index`. */
  particleHandle(index: number): Handle {
    const i = integer('index', index, 0);
    if (i >= this.particles.count || this.particles.alive[i] === 0) throw new RangeError(`index ${i} holds no live particle`);
    return this.ctx.particleIds.handleOf(i);
  }
  /** Live particle count. */
  get particleCount(): number { return this.particles.alive.subarray(0, this.particles.count).reduce((n, a) => n + a, 0); }

  getPosition(handle: Handle): Vec2 {
    const i = this.particleIndex(handle);
    return { x: this.particles.x[i], y: this.particles.y[i] };
  }

  /** Moves a particle (teleport: its velocity is kept). */
  setPosition(handle: Handle, x: number, y: number): void {
    const i = this.particleIndex(handle);
    const nx = coordinate('x', x);
    const ny = coordinate('y', y);
    wakeParticle(this.ctx, i);
    const p = this.particles;
    p.px[i] += nx - p.x[i];
    p.py[i] += ny - p.y[i];
    p.x[i] = nx;
    p.y[i] = ny;
  }

  /** Velocity over the last substep. */
  getVelocity(handle: Handle): Vec2 {
    const i = this.particleIndex(handle);
    return { x: this.particles.vx[i], y: this.particles.vy[i] };
  }

  setVelocity(handle: Handle, vx: number, vy: number): void {
    const i = this.particleIndex(handle);
    const [sx, sy] = [speed('vx', vx), speed('vy', vy)];
    wakeParticle(this.ctx, i);
    api.writeRowVelocity(this.ctx, i, sx, sy);
  }

  /** Adds a force for the next step (cleared after it). */
  applyForce(handle: Handle, fx: number, fy: number): void {
    const i = this.particleIndex(handle);
    const [gx, gy] = [finite('fx', fx), finite('fy', fy)];
    // A sleeping body's inverse mass is parked at 0: the speed is checked against the one it wakes with.
    const invMass = this.ctx.sleep.awakeInvMass(i, this.particles);
    pushSpeed(FORCE_SPEED, this.particles.fx[i] + gx, this.particles.fy[i] + gy, invMass, this.settings.timestep);
    // Dropped on a particle that cannot move (static or pinned): it would act in full once freed before the step.
    if (invMass === 0) return;
    wakeParticle(this.ctx, i);
    this.particles.fx[i] += gx;
    this.particles.fy[i] += gy;
  }

  /** Changes the velocity by impulse / mass at once. */
  applyImpulse(handle: Handle, ix: number, iy: number): void {
    const i = this.particleIndex(handle);
    const [jx, jy] = [finite('ix', ix), finite('iy', iy)];
    pushSpeed(IMPULSE_SPEED, jx, jy, this.ctx.sleep.awakeInvMass(i, this.particles), 1, this.particles.vx[i], this.particles.vy[i]);
    wakeParticle(this.ctx, i);
    const w = this.particles.invMass[i];
    this.particles.vx[i] += jx * w;
    this.particles.vy[i] += jy * w;
  }

  getMass(handle: Handle): number {
    const i = this.particleIndex(handle);
    const p = this.particles;
    const w = p.flags[i] & ParticleFlag.Pinned ? this.ctx.constraints.pinnedInvMass(i) : this.ctx.sleep.awakeInvMass(i, p);
    return w === 0 ? Infinity : 1 / w;
  }

  /**
   * A stored velocity is v − ½·g·h under the gravity, reference substep and integrator of the moment
   * (verletReferenceHalf), so a change of any of them shifts the stored velocity of every movable row by the
   * difference of that term (its own, for particles and rigid rows): without it a particle at rest in the air drifted
   * at ½·g·h (0.008 units/s under 9.81) once gravity was switched off. A sleeping body's rows are at rest (invMass 0
   * while parked: they wake at rest).
   */
  private keepingVelocities(change: () => void): void {
    const s = this.settings;
    const { gravity: g0 } = s;
    const [p0, r0] = [verletReferenceHalf(s, false), verletReferenceHalf(s, true)];
    change();
    const { gravity: g1 } = s;
    const [p1, r1] = [verletReferenceHalf(s, false), verletReferenceHalf(s, true)];
    shiftVerletVelocities(this.particles, g0.x * p0 - g1.x * p1, g0.y * p0 - g1.y * p1, g0.x * r0 - g1.x * r1, g0.y * r0 - g1.y * r1);
  }

  // ---- constraints -------------------------------------------------------------------------------------------

  /** A distance constraint (stick, slack rope link or minimum distance) between particles a and b. */
  addDistance(a: Handle, b: Handle, options: DistanceOptions = {}): Handle {
    knownNames('distance option', objectOf('distance options', options), OPTION_NAMES.distance);
    const [ia, ib] = this.pair(a, b);
    const p = this.particles;
    const current = Math.sqrt((p.x[ib] - p.x[ia]) ** 2 + (p.y[ib] - p.y[ia]) ** 2);
    const length = options.length === undefined ? current : coordinate('length', nonNegative('length', options.length));
    const minLength = options.minLength === undefined ? length : coordinate('minLength', nonNegative('minLength', options.minLength));
    // An upper bound moves nothing (a particle only ever reaches it from within): any, as Infinity is.
    const maxLength = options.maxLength === undefined ? length : nonNegativeOrInfinity('maxLength', options.maxLength);
    if (minLength > maxLength) throw new RangeError(`minLength (${minLength}) must be <= maxLength (${maxLength})`);
    const compliance = complianceOf('compliance', options.compliance ?? 0);
    const breakStrain = options.breakStrain === undefined ? 0 : positive('breakStrain', options.breakStrain);
    if (breakStrain > 0 && !(maxLength > 0 && maxLength < Infinity)) throw new RangeError(`breakStrain needs a finite, positive maxLength, got ${maxLength}`);
    const handle = this.ctx.constraints.add(this.distances, { a: ia, b: ib, minLength, maxLength, compliance, breakStrain });
    if (breakStrain > 0) this.ctx.hasBreakableLinks = true;
    return this.added(handle);
  }

  /** An angle limit at vertex b over the particles a, b, c. */
  addAngleLimit(a: Handle, b: Handle, c: Handle, options: AngleOptions): Handle {
    const [ia, ib] = this.pair(a, b, 'a', 'b');
    const [, ic] = this.pair(b, c, 'b', 'c');
    if (ia === ic) throw new RangeError(`a and c must be different particles, got ${a} twice`);
    if (options == null) throw new TypeError('angle options {min, max} are required');
    knownNames('angle limit option', objectOf('angle limit options', options), OPTION_NAMES.angle);
    const min = finite('min', options.min);
    const max = finite('max', options.max);
    if (!(min <= max && max - min <= 2 * Math.PI)) throw new RangeError(`angle limits must satisfy min <= max <= min + 2π, got min ${min}, max ${max}`);
    const compliance = complianceOf('compliance', options.compliance ?? 0);
    return this.added(this.ctx.constraints.add(this.angles, { a: ia, b: ib, c: ic, min, max, compliance }));
  }

  /** The current signed angle at b from (a − b) to (c − b), in (−π, π]. */
  angleAt(a: Handle, b: Handle, c: Handle): number {
    const p = this.particles;
    const ia = this.particleIndex(a);
    const ib = this.particleIndex(b);
    const ic = this.particleIndex(c);
    return signedAngle(p.x[ia] - p.x[ib], p.y[ia] - p.y[ib], p.x[ic] - p.x[ib], p.y[ic] - p.y[ib]);
  }

  addSpring(a: Handle, b: Handle, options: SpringOptions): Handle {
    const [ia, ib] = this.pair(a, b);
    if (options == null) throw new TypeError('spring options {stiffness} are required');
    knownNames('spring option', objectOf('spring options', options), OPTION_NAMES.spring);
    const p = this.particles;
    const current = Math.sqrt((p.x[ib] - p.x[ia]) ** 2 + (p.y[ib] - p.y[ia]) ** 2);
    const restLength = options.length === undefined ? current : coordinate('length', nonNegative('length', options.length));
    const stiffness = nonNegative('stiffness', options.stiffness);
    const damping = nonNegative('damping', options.damping ?? 0);
    return this.added(this.ctx.constraints.add(this.springs, { a: ia, b: ib, restLength, stiffness, damping }));
  }

  /** Pins a particle to a world point (its current position by default). */
  addPin(particle: Handle, options: PinOptions = {}): Handle {
    const i = this.particleIndex(particle);
    knownNames('pin option', objectOf('pin options', options), OPTION_NAMES.pin);
    const p = this.particles;
    if (p.flags[i] & ParticleFlag.Pinned) throw new RangeError(`particle ${particle} is already rigidly pinned`);
    const tx = options.x === undefined ? p.x[i] : coordinate('x', options.x);
    const ty = options.y === undefined ? p.y[i] : coordinate('y', options.y);
    const compliance = complianceOf('compliance', options.compliance ?? 0);
    const rigid = compliance === 0;
    // A rigid pin makes the particle kinematic: its inverse mass is parked in the pin while the pin lives.
    const handle = this.ctx.constraints.add(this.pins, { p: i, tx, ty, compliance, savedInvMass: rigid ? p.invMass[i] : 0 });
    if (rigid) {
      p.invMass[i] = 0;
      p.flags[i] |= ParticleFlag.Pinned;
      p.x[i] = p.px[i] = tx;
      p.y[i] = p.py[i] = ty;
      p.vx[i] = p.vy[i] = 0;
    }
    return this.added(handle);
  }

  /** Moves a pin's target (a dragged or animated anchor). */
  setPinTarget(pin: Handle, x: number, y: number): void {
    const row = this.ctx.constraints.rowOf(pin, Kind.Pin, 'pin');
    wakeParticle(this.ctx, this.pins.p[row]);
    // A particle of no body has no body to wake: a settled world would not step, and it would stay where it was.
    this.ctx.pinMoved = true;
    this.pins.tx[row] = coordinate('x', x);
    this.pins.ty[row] = coordinate('y', y);
  }

  /** Keeps the area of the closed loop of particles (in order) at pressure × its current area. */
  addAreaConstraint(loop: readonly Handle[], options: AreaOptions = {}): Handle {
    if (!Array.isArray(loop) || loop.length < 3) throw new RangeError(`an area constraint needs a loop of at least 3 particles, got ${Array.isArray(loop) ? loop.length : String(loop)}`);
    const slots = loop.map((h, k) => this.ctx.particleIds.slotOf(h, `loop[${k}]`));
    if (new Set(slots).size !== slots.length) throw new RangeError('an area constraint loop must not repeat a particle');
    knownNames('area option', objectOf('area options', options), OPTION_NAMES.area);
    const pressure = positive('pressure', options.pressure ?? 1);
    if (pressure > MAX_PRESSURE) throw new RangeError(`pressure must be at most ${MAX_PRESSURE} (times the rest area), got ${describeValue(pressure)}`);
    const t = this.areas;
    const compliance = complianceOf('compliance', options.compliance ?? 0);
    const damping = nonNegative('damping', options.damping ?? 0);
    const start = t.appendLoop(slots);
    const restArea = loopArea(t.pool, start, slots.length, this.particles.x, this.particles.y) * pressure;
    return this.added(this.ctx.constraints.add(t, { start, length: slots.length, restArea, compliance, damping }));
  }

  removeConstraint(handle: Handle): void {
    this.ctx.constraints.ids.slotOf(handle, 'constraint');
    topologyChanged(this.ctx);
    this.ctx.constraints.remove(handle, this.particles);
  }

  /** Which kind of constraint a handle names. */
  constraintKindOf(handle: Handle): ConstraintKind { return this.ctx.constraints.kindOf(handle); }
  hasConstraint(handle: unknown): boolean { return this.ctx.constraints.ids.isValid(handle); }
  get constraintCount(): number { return this.ctx.constraints.count; }

  /** Length error of a distance constraint: how far the current length is outside [minLength, maxLength]. */
  distanceError(handle: Handle): number { return stretchOf(this.distances, this.distanceRow(handle), this.particles, false); }
  /** The particle indices (slots in the state arrays) a distance constraint joins. */
  distanceParticleIndices(handle: Handle): [number, number] {
    const row = this.distanceRow(handle);
    return [this.distances.a[row], this.distances.b[row]];
  }
  /** How many distance constraints have broken (torn) so far. */
  get brokenLinkCount(): number { return this.distances.broken.subarray(0, this.distances.count).reduce((n, b) => n + b, 0); }
  /** Whether a distance constraint made with breakStrain has broken (it then no longer acts). */
  isBroken(handle: Handle): boolean { return this.distances.broken[this.distanceRow(handle)] === 1; }
  /** The largest relative stretch |d − L| / L over all distance constraints with L > 0 (0 when none). */
  maxStrain(): number {
    let worst = 0;
    for (let i = 0; i < this.distances.count; i++) worst = Math.max(worst, stretchOf(this.distances, i, this.particles, true));
    return worst;
  }
  private distanceRow(handle: Handle): number { return this.ctx.constraints.rowOf(handle, Kind.Distance, 'distance constraint'); }

  private pair(a: Handle, b: Handle, nameA = 'a', nameB = 'b'): [number, number] {
    const ia = this.ctx.particleIds.slotOf(a, nameA);
    const ib = this.ctx.particleIds.slotOf(b, nameB);
    if (ia === ib) throw new RangeError(`${nameA} and ${nameB} must be different particles, got ${a} twice`);
    return [ia, ib];
  }

  /** A constraint was added: the bookkeeping follows. */
  private added(handle: Handle): Handle {
    topologyChanged(this.ctx);
    return handle;
  }

  // ---- bodies ------------------------------------------------------------------------------------------------

  /** Groups particles and constraints into one body (the builders call this), colliding as `collider` says. */
  addBody(kind: BodyKind, particles: readonly Handle[], constraints: readonly Handle[] = [], collider: ColliderOptions = { shape: 'none' }): Handle {
    oneOf('kind', kind, BODY_KINDS);
    if (!Array.isArray(particles) || particles.length === 0) throw new RangeError(`a body needs at least one particle, got ${String(particles)}`);
    const slots = Int32Array.from(particles, (h, k) => this.ctx.particleIds.slotOf(h, `particles[${k}]`));
    // A particle is in one body at most: removing one body must not take another's particles, nor leave it holding
    // slots that later particles reuse.
    const listed = new Set<number>();
    slots.forEach((slot, k) => {
      const owner = this.ctx.bodies.ownerOf(slot);
      if (owner >= 0) throw new RangeError(`particles[${k}] (${particles[k]}) already belongs to body ${this.ctx.bodies.ids.handleOf(owner)}`);
      if (listed.has(slot)) throw new RangeError(`particles[${k}] (${particles[k]}) is listed twice`);
      listed.add(slot);
    });
    if (!Array.isArray(constraints)) throw new TypeError(`constraints must be a list of constraint handles, got ${describeValue(constraints)}`);
    constraints.forEach((h, k) => this.ctx.constraints.ids.slotOf(h, `constraints[${k}]`));
    knownNames('collider option', objectOf('collider options', collider), OPTION_NAMES.collider);
    const resolved = resolveCollider(collider, slots.length);
    const handle = this.ctx.bodies.add(kind, slots, constraints);
    this.writeCollider(handleSlot(handle), resolved);
    topologyChanged(this.ctx);
    return handle;
  }

  /**
   * Changes how a body collides (any subset of the options; the rest keep their values). A rigid body collides with
   * its own outline: its shape is 'none' (no collisions) or 'polygon' (its outline), and it takes no parts.
   */
  setCollider(body: Handle, options: ColliderOptions): void {
    const { bodies, colliders } = this.ctx;
    const slot = bodies.slotOf(body);
    knownNames('collider option', objectOf('collider options', options), OPTION_NAMES.collider);
    if (!this.ctx.rigidShapes.source(slot)) {
      this.writeCollider(slot, resolveCollider({ ...colliders.optionsOf(slot, bodies.parts[slot]), ...options }, bodies.particles[slot].length));
      return;
    }
    if (options.parts !== undefined) throw new RangeError(`parts: a rigid body collides with its own outline, got ${JSON.stringify(options.parts)}`);
    if (options.shape !== undefined && options.shape !== 'none' && options.shape !== 'polygon') {
      throw new RangeError(`shape of a rigid body must be "polygon" (its outline) or "none", got ${describeValue(options.shape)}`);
    }
    // Its collider reads as 'none' until a step has made it a rigid one (Polygon before that, as addRigidBody writes it).
    const off = colliders.kind[slot] === ColliderKind.None;
    const now = { ...colliders.optionsOf(slot, undefined), shape: off ? 'none' : 'polygon', parts: undefined } as const;
    this.writeCollider(slot, resolveCollider({ ...now, ...options }, 3));
    // Collisions switched on again must find what it now overlaps.
    this.ctx.sleep.wakeBody(slot, bodies.particles[slot], this.particles);
  }

  private writeCollider(slot: number, o: ResolvedCollider): void {
    const { bodies, colliders } = this.ctx;
    // A soft ring is picked and queried by its inside, not only by its particles' circles.
    colliders.write(slot, o, bodies.kind[slot] === 'soft' ? softRingLength(bodies.particles[slot], this.springs) : 0);
    bodies.parts[slot] = o.parts;
    this.ctx.collidersDirty = true;
  }

  /** Removes a body with its particles and constraints. */
  removeBody(handle: Handle): void {
    const { ctx } = this;
    const slot = ctx.bodies.slotOf(handle);
    topologyChanged(ctx);
    for (const c of ctx.bodies.constraints[slot]) if (ctx.constraints.ids.isValid(c)) this.removeConstraint(c);
    for (const i of ctx.bodies.particles[slot]) {
      const h = ctx.particleIds.handleOf(i);
      if (ctx.particleIds.isValid(h)) this.releaseParticle(h, i);
    }
    ctx.eventTracker.bodyRemoved(slot, ctx.bodyHandleOf);
    ctx.bodies.remove(handle);
    ctx.rigidShapes.clear(slot);
    ctx.colliders.kind[slot] = ColliderKind.None;
    ctx.collidersDirty = true;
  }

  hasBody(handle: unknown): boolean {
    return this.ctx.bodies.ids.isValid(handle);
  }

  bodyKindOf(handle: Handle): BodyKind {
    return this.ctx.bodies.kind[this.ctx.bodies.slotOf(handle)];
  }

  /** Storage indices of a body's particles (a view: do not modify). */
  bodyParticleIndices(handle: Handle): Int32Array {
    return this.ctx.bodies.particles[this.ctx.bodies.slotOf(handle)];
  }

  bodyParticleHandles(handle: Handle): Handle[] {
    return Array.from(this.bodyParticleIndices(handle), (i) => this.ctx.particleIds.handleOf(i));
  }

  bodyConstraintHandles(handle: Handle): Handle[] {
    return this.ctx.bodies.constraints[this.ctx.bodies.slotOf(handle)].slice();
  }

  /** Mean position of a body's particles. */
  bodyCentroid(handle: Handle): Vec2 {
    return centroid(this.particles, this.bodyParticleIndices(handle));
  }

  /**
   * Changes a body's velocity by impulse / mass at once: spread over its particles by mass, or for a rigid body at a
   * world point (default its centre of mass), which also turns it.
   */
  applyBodyImpulse(handle: Handle, ix: number, iy: number, x?: number, y?: number): void {
    const idx = this.bodyParticleIndices(handle);
    const jx = finite('ix', ix);
    const jy = finite('iy', iy);
    if (this.ctx.rigidShapes.source(this.ctx.bodies.slotOf(handle))) return api.pushBody(this.ctx, handle, jx, jy, x, y, true);
    let mass = 0;
    for (const i of idx) {
      // Checked against the masses the body wakes with (a sleeping body's are parked at infinity).
      const w = this.ctx.sleep.awakeInvMass(i, this.particles);
      if (w > 0) mass += 1 / w;
    }
    // Every movable particle gains impulse / mass: each must stay within the speed limit.
    for (const i of idx) if (this.ctx.sleep.awakeInvMass(i, this.particles) > 0) pushSpeed(IMPULSE_SPEED, jx, jy, mass > 0 ? 1 / mass : 0, 1, this.particles.vx[i], this.particles.vy[i]);
    this.wake(handle);
    applyImpulseByMass(this.particles, idx, jx, jy);
  }

  *bodies(): IterableIterator<Handle> {
    const ids = this.ctx.bodies.ids;
    for (let slot = 0; slot < ids.high; slot++) if (ids.alive[slot]) yield ids.handleOf(slot);
  }

  // ---- rigid bodies ------------------------------------------------------------------------------------------

  /**
   * A rigid body (Müller et al. 2020): one row of the particle store at its centre of mass, with an angle and a
   * moment of inertia from its shape's area and density, colliding by its outline or disc. Returns its body handle;
   * its one particle (bodyParticleHandles) is its centre of mass.
   */
  addRigidBody(o: RigidBodyOptions): Handle {
    const plan = api.rigidBodyPlan(o);
    this.ensureBodyRoom();
    const particle = this.addParticle({ x: plan.x, y: plan.y });
    const i = this.particleIndex(particle);
    initRigidRow(this.particles, i, plan.source, plan.type, plan.x, plan.y, plan.angle);
    const body = this.addBody('rigid', [particle], [], { shape: 'none' });
    this.ctx.rigidShapes.set(handleSlot(body), i, plan.source, plan.type);
    this.writeCollider(handleSlot(body), plan.collider);
    if (plan.type !== BodyType.Static) {
      api.writeRowVelocity(this.ctx, i, plan.vx, plan.vy);
      this.particles.omega[i] = plan.w;
    }
    return body;
  }

  /** @internal Throws the `limits.bodies` RangeError now unless `n` more bodies fit (builders check before making anything). */
  ensureBodyRoom(n = 1): void {
    this.ctx.bodies.ids.ensureRoom(n);
  }

  /** A rigid body's origin (where its points were placed) and angle. */
  bodyPose(body: Handle): Pose { return api.bodyPose(this.ctx, body); }
  /** Moves and turns a rigid body to a pose (its velocities are kept). */
  setBodyPose(body: Handle, x: number, y: number, angle: number): void { api.setBodyPose(this.ctx, body, x, y, angle); }
  /** Velocity of a rigid body's centre of mass: the mean over the last substep (0 at rest; in free flight g·h/2 behind g·t). */
  bodyVelocity(body: Handle): Vec2 { return api.bodyVelocity(this.ctx, body); }
  setBodyVelocity(body: Handle, vx: number, vy: number): void { api.setBodyVelocity(this.ctx, body, vx, vy); }
  /** Angular velocity (rad/s; positive turns x toward y). */
  bodyAngularVelocity(body: Handle): number { return this.particles.omega[api.rigidOf(this.ctx, body).i]; }
  setBodyAngularVelocity(body: Handle, w: number): void { api.setBodyAngularVelocity(this.ctx, body, w); }
  /** A force for the next step at a world point (default the centre of mass), with the torque it makes there. */
  applyBodyForce(body: Handle, fx: number, fy: number, x?: number, y?: number): void { api.pushBody(this.ctx, body, fx, fy, x, y, false); }
  /** A torque for the next step. */
  applyBodyTorque(body: Handle, torque: number): void { api.applyBodyTorque(this.ctx, body, torque); }
  /** Mass, moment of inertia about the centre of mass, and that centre now. */
  bodyMassInfo(body: Handle): MassInfo { return api.bodyMassInfo(this.ctx, body); }
  bodyType(body: Handle): BodyTypeName { return api.bodyType(this.ctx, body); }
  /** Makes a rigid body dynamic, static (it stops) or kinematic (it keeps its velocities and moves by them). */
  setBodyType(body: Handle, type: BodyTypeName): void { api.setBodyType(this.ctx, body, type); }

  /** A joint between two bodies, a body and the world, or a body and a particle (see JointOptions). */
  addJoint(o: JointOptions): Handle {
    knownNames('joint option', objectOf('joint options', o), OPTION_NAMES.joint);
    const A = api.jointSide(this.ctx, o.a, o.particleA, 'a', 'particleA');
    const B = api.jointSide(this.ctx, o.b, o.particleB, 'b', 'particleB');
    if (A.row < 0) throw new TypeError('a joint needs side a: a body (a) or a particle (particleA)');
    if (A.row === B.row) throw new RangeError('a joint must join two different bodies or particles');
    return this.added(this.ctx.constraints.add(this.ctx.constraints.joints, jointRow(o, A, B, this.particles)));
  }

  // ---- pointer drag and queries ------------------------------------------------------------------------------

  /**
   * Grabs whatever is at (x, y): a body whose shape contains the point (held at that very point of the body), else
   * the nearest movable particle within `pickRadius` (cloth, rope). Returns a grab handle for moveGrab/release, or
   * null when nothing movable is there.
   */
  grab(x: number, y: number, options: GrabOptions = {}): Handle | null {
    this.query(['x', 'y'], x, y);
    knownNames('grab option', objectOf('grab options', options), OPTION_NAMES.grab);
    const stiffness = stiffnessOf('stiffness', options.stiffness ?? 2000);
    const pickRadius = coordinate('pickRadius', nonNegative('pickRadius', options.pickRadius ?? 0.5));
    const g = pickGrabPoint(this.ctx, x, y, pickRadius);
    if (!g) return null;
    wakeParticle(this.ctx, g.p0);
    const compliance = 1 / (stiffness * g.mass);
    const lag = grabLag(stiffness);
    return this.added(this.ctx.constraints.add(this.grabs, { p0: g.p0, p1: g.p1, p2: g.p2, w0: g.w0, w1: g.w1, w2: g.w2, tx: x, ty: y, aimX: x, aimY: y, compliance, rx: g.rx, ry: g.ry, lag }));
  }

  /** Moves a grab's target (the pointer). */
  moveGrab(grab: Handle, x: number, y: number): void {
    const row = this.ctx.constraints.rowOf(grab, Kind.Grab, 'grab');
    this.grabs.tx[row] = coordinate('x', x);
    this.grabs.ty[row] = coordinate('y', y);
    wakeParticle(this.ctx, this.grabs.p0[row]);
  }

  /** Lets go: the body keeps the velocity the drag gave it (a throw). */
  release(grab: Handle): void {
    this.ctx.constraints.rowOf(grab, Kind.Grab, 'grab');
    this.removeConstraint(grab);
  }

  /** Bodies whose collision shape contains (x, y), the last created first. */
  bodiesAtPoint(x: number, y: number): Handle[] {
    this.query(['x', 'y'], x, y);
    return bodiesAtPoint(this.colliders, this.particles, this.ctx.rigidShapes, x, y).map(this.ctx.bodyHandleOf);
  }

  /** Bodies whose collision shape overlaps the box. */
  bodiesInBox(minX: number, minY: number, maxX: number, maxY: number): Handle[] {
    this.query(['minX', 'minY', 'maxX', 'maxY'], minX, minY, maxX, maxY);
    return bodiesInBox(this.colliders, this.particles, this.ctx.rigidShapes, minX, minY, maxX, maxY).map(this.ctx.bodyHandleOf);
  }

  /** The nearest body hit by the segment from (x0, y0) to (x1, y1), or null. */
  rayCast(x0: number, y0: number, x1: number, y1: number): RayCastHit | null {
    this.query(['x0', 'y0', 'x1', 'y1'], x0, y0, x1, y1);
    const hit = rayCast(this.colliders, this.particles, this.ctx.rigidShapes, x0, y0, x1, y1);
    if (!hit) return null;
    const { slot, ...where } = hit;
    return { body: this.ctx.bodyHandleOf(slot), ...where };
  }

  /** Checks a query's numbers (by name), then brings the bookkeeping and rigid shapes to where the bodies are now. */
  private query(names: readonly string[], ...values: number[]): void {
    values.forEach((v, k) => coordinate(names[k], v));
    ensureTopology(this.ctx);
    if (this.ctx.rigidShapes.polygonCount > 0) this.ctx.rigidShapes.updateWorld(this.particles);
  }

  // ---- time --------------------------------------------------------------------------------------------------

  /**
   * One step of `dt` seconds (the fixed timestep by default), in `substepCount` substeps (see pipeline/step.ts). For
   * n steps, call it n times (an element's `step(n)` counts steps; this one takes a length, so `step(60)` would be one
   * step of a minute: refused, as any step longer than MAX_STEP_SECONDS).
   */
  step(dt: number = this.settings.timestep): void {
    if (dt !== this.settings.timestep) stepLength('dt', dt, typeof dt === 'number' && dt > MAX_STEP_SECONDS ? ': one step\'s length; for n steps, call step() n times' : '');
    step(this.ctx, dt);
  }

  /**
   * Real time has passed: take as many fixed steps as fit (at most maxCatchUpSteps; an older backlog is dropped
   * so a stalled tab does not spiral) and leave the remainder's fraction in `alpha` for interpolated rendering.
   * In variableStep mode, take one step of the elapsed time instead. `afterStep` runs after each step taken (read
   * that step's collision events and breaks there: the next step overwrites them). Returns the steps taken.
   */
  advance(elapsed: number, afterStep?: () => void): number {
    nonNegative('elapsed', elapsed);
    if (afterStep !== undefined && typeof afterStep !== 'function') throw new TypeError(`afterStep must be a function, got ${String(afterStep)}`);
    return advance(this.ctx, elapsed, afterStep);
  }

  // ---- determinism -------------------------------------------------------------------------------------------

  /** A hash of the full simulation state (positions, angles, velocities, masses): equal states give equal hashes. */
  stateHash(): string {
    const p = this.particles;
    return hashColumns([p.x, p.y, p.px, p.py, p.vx, p.vy, p.invMass, p.alive, p.angle, p.omega, p.invInertia], p.count, [this.stepCount, this.constraintCount]);
  }

  /** The whole state as plain data (structured-cloneable: a worker can post it). */
  snapshot(): WorldSnapshot {
    return snapshotContext(this.ctx);
  }

  /** Puts back a state from snapshot() (of this world or another); anything else is refused with a TypeError. */
  restore(s: WorldSnapshot): void {
    // All or nothing: a snapshot refused part-way through leaves the world as it was.
    const before = snapshotContext(this.ctx);
    try {
      restoreContext(this.ctx, s);
    } catch (error) {
      restoreContext(this.ctx, before);
      // A part of it that is not what snapshot() makes fails inside (reading a field of undefined): said as such.
      throw error instanceof TypeError && !/snapshot/.test(error.message) ? new TypeError(`snapshot is not one World.snapshot() made: ${error.message}`) : error;
    }
    // Only a restore that happened forgets which pairs touch (they begin again): a refused one keeps the events going.
    this.ctx.eventTracker.clear();
  }
}
