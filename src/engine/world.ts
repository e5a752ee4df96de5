import { handleSlot, HandleRegistry, MAX_SLOTS, type Handle, type RegistrySnapshot } from './handles.js';
import { ParticleFlag, ParticleStore } from './particles.js';
import type { Column, Table } from './table.js';
import { breakOverstretched, DistanceConstraints, solveDistances } from './constraints/distance.js';
import { AngleConstraints, signedAngle, solveAngles } from './constraints/angle.js';
import { PinConstraints, placeRigidPins, solveSoftPins } from './constraints/pin.js';
import { AreaConstraints, loopArea, solveAreas } from './constraints/area.js';
import { accumulateSprings, Springs } from './constraints/spring.js';
import { integrate, INTEGRATORS, updateVelocities, type Integrator } from './integrate.js';
import { keepInBounds, type Bounds } from './bounds.js';
import { hashColumns } from './hash.js';
import { ColliderKind, Colliders } from './pipeline/colliders.js';
import { BruteForceBroadPhase, GridBroadPhase, PairList, type BroadPhase } from './pipeline/broadphase.js';
import { NarrowPhase } from './pipeline/narrowphase.js';
import { AnchorCache, Contacts, recordApproachSpeeds, solveContacts, solveContactVelocities } from './pipeline/contacts.js';
import { grown } from './table.js';
import { GrabConstraints, solveGrabs } from './constraints/grab.js';
import { CollisionEvents, EventTracker } from './pipeline/events.js';
import { Sleep } from './pipeline/sleep.js';
import { bodiesAtPoint, bodiesInBox, rayCast } from './pipeline/queries.js';
import { finite, integer, nonNegative, nonNegativeOrInfinity, oneOf, positive } from './validate.js';

export type { Handle } from './handles.js';
export type { Integrator } from './integrate.js';
export type { Bounds } from './bounds.js';

export interface Vec2 {
  x: number;
  y: number;
}

export interface WorldOptions {
  /** Acceleration of gravity. Default {x: 0, y: 9.81}: y grows downward, as on a canvas or in SVG. */
  gravity?: Vec2;
  /** The fixed step in seconds. Default 1/60. */
  timestep?: number;
  /** Substeps per step. Default 10 (substeps buy more stiffness per cost than iterations). */
  substeps?: number;
  /** Gauss–Seidel iterations per substep. Default 1. */
  iterations?: number;
  /** Linear damping per second (velocity shrinks by 1/(1 + h·damping) each substep). Default 0. */
  damping?: number;
  integrator?: Integrator;
  /** A box the particles cannot leave; null for none (default). */
  bounds?: Bounds | null;
  /** Coulomb friction of the bounds' walls. Default 0.5. */
  boundsFriction?: number;
  /** The most steps advance() takes to catch up with real time; the rest of the backlog is dropped. Default 5. */
  maxCatchUpSteps?: number;
  /** advance(elapsed) takes one step of the elapsed time instead of fixed steps (seed 5.3's comparison). */
  variableStep?: boolean;
  /** Broad phase: 'grid' (default, uniform grid with radix sort) or 'brute' (every pair; for tests and comparison). */
  broadphase?: 'grid' | 'brute';
  /** Narrow phase for polygon pairs: 'sat' (default) or 'gjk' (GJK distance / GJK + EPA). */
  narrowphase?: 'sat' | 'gjk';
  /** Grid cell size; 0 (default) picks twice the median body size. */
  cellSize?: number;
  /** Extra gap within which contacts are created before bodies touch. Default 0.02. */
  contactSlop?: number;
  /** Bodies at rest fall asleep and cost nothing until woken. Default true. */
  sleeping?: boolean;
  /** The fastest an overlap that already exists is pushed apart (units/s). Default 4. */
  maxPushSpeed?: number;
  /** Caps on live objects; creating more throws a RangeError. Defaults: DEFAULT_LIMITS. */
  limits?: Partial<Limits>;
}

export interface Limits {
  particles: number;
  constraints: number;
  bodies: number;
}

/** Default caps: far above what a page can simulate at 60 steps a second, low enough to fail fast on a runaway loop. */
export const DEFAULT_LIMITS: Limits = { particles: 200_000, constraints: 1_000_000, bodies: 100_000 };

export interface GrabOptions {
  /** Pull per unit of distance and of mass (1/s²): how tightly the body follows. Default 2000. */
  stiffness?: number;
  /** How far from the point a particle may be picked when no body contains the point. Default 0.5. */
  pickRadius?: number;
}

/** Where a ray first hits a body. */
export interface RayCastHit {
  body: Handle;
  x: number;
  y: number;
  normalX: number;
  normalY: number;
  distance: number;
}

/** How a body collides. Builders pass these through. */
export interface ColliderOptions {
  /**
   * 'polygon': convex parts whose vertices are the body's particles (default: one part, all particles in order);
   * 'particles': each particle is a circle of its radius; 'none': no collisions.
   */
  shape?: 'polygon' | 'particles' | 'none';
  /** Convex parts as lists of indices into the body's particle list (concave outlines). */
  parts?: number[][];
  /** Coulomb friction coefficient (>= 0). Pairs use √(μa·μb). Default 0.6. */
  friction?: number;
  /** Restitution in [0, 1]. Pairs use the larger. Default 0. */
  restitution?: number;
  /** Collision filtering: bodies collide when (catA & maskB) && (catB & maskA), unless they share a group:
   *  a shared positive group always collides, a shared negative group never does. */
  category?: number;
  mask?: number;
  group?: number;
}

export const COLLIDER_SHAPES = ['polygon', 'particles', 'none'] as const;

export interface ParticleOptions {
  x: number;
  y: number;
  /** Mass (> 0). Infinity makes the particle immovable. Default 1. */
  mass?: number;
  /** Collision radius (>= 0). Default 0. */
  radius?: number;
  vx?: number;
  vy?: number;
}

export interface DistanceOptions {
  /** Rest length; default the particles' current distance. Sets both minLength and maxLength. */
  length?: number;
  /** Lower limit (default = length). 0 with maxLength = L makes a slack rope link. */
  minLength?: number;
  /** Upper limit (default = length). Infinity with minLength = L keeps particles at least L apart. */
  maxLength?: number;
  /** Inverse stiffness (length per unit force); 0 = rigid. Default 0. */
  compliance?: number;
  /**
   * Tearing: the link breaks for good once stretched past maxLength by this fraction (0.5 = half again as long).
   * Default: unbreakable. Needs a finite maxLength.
   */
  breakStrain?: number;
}

export interface AngleOptions {
  /** Lower limit of the signed angle from (a − b) to (c − b), radians. */
  min: number;
  /** Upper limit, radians; min <= max <= min + 2π. Limits beyond ±π are fine (the angle is measured from the centre of the range). */
  max: number;
  compliance?: number;
}

export interface SpringOptions {
  /** Rest length; default the current distance. */
  length?: number;
  /** Hooke constant k (force per unit length, >= 0). */
  stiffness: number;
  /** Damping constant c (force per unit relative speed, >= 0). Default 0. */
  damping?: number;
}

export interface PinOptions {
  /** Target point; default the particle's current position. */
  x?: number;
  y?: number;
  /** 0 (default) holds the particle exactly; > 0 pulls it like a zero-length spring. */
  compliance?: number;
}

export interface AreaOptions {
  /** Rest area as a multiple of the loop's current area (a soft body's pressure). Default 1. */
  pressure?: number;
  compliance?: number;
}

export type BodyKind = 'particle' | 'rope' | 'cloth' | 'rigid' | 'soft' | 'ragdoll' | 'custom';
export const BODY_KINDS: readonly BodyKind[] = ['particle', 'rope', 'cloth', 'rigid', 'soft', 'ragdoll', 'custom'];

export type ConstraintKind = 'distance' | 'angle' | 'pin' | 'spring' | 'area' | 'grab';
/** Indexed by Kind. */
const CONSTRAINT_KINDS: readonly ConstraintKind[] = ['distance', 'angle', 'pin', 'spring', 'area', 'grab'];

const enum Kind {
  Distance,
  Angle,
  Pin,
  Spring,
  Area,
  Grab,
}

const DEFAULTS = {
  gravity: { x: 0, y: 9.81 },
  timestep: 1 / 60,
  substeps: 10,
  iterations: 1,
  damping: 0,
  integrator: 'verlet' as Integrator,
  boundsFriction: 0.5,
  maxCatchUpSteps: 5,
  variableStep: false,
  broadphase: 'grid' as 'grid' | 'brute',
  narrowphase: 'sat' as 'sat' | 'gjk',
  cellSize: 0,
  contactSlop: 0.02,
  sleeping: true,
  maxPushSpeed: 4,
};

/**
 * The headless engine: Verlet particles, constraints relaxed by Gauss–Seidel (XPBD) iterations inside substeps,
 * bodies as groups of particles and constraints. No DOM: runs in Node, a worker or the main thread.
 *
 * A step is detect collisions (broad phase → narrow phase), then a fixed list of phases per substep: accelerate →
 * integrate → place pins → relax constraints, contacts and bounds → derive velocities → contact velocities; then
 * break overstretched links → collision events → sleep.
 */
export class World {
  readonly particles = new ParticleStore();
  readonly distances = new DistanceConstraints();
  readonly angles = new AngleConstraints();
  readonly pins = new PinConstraints();
  readonly springs = new Springs();
  readonly areas = new AreaConstraints();
  readonly grabs = new GrabConstraints();
  /** Begin/end collision events of the last step. */
  readonly events = new CollisionEvents();
  /** Handles of the distance constraints that broke in the last step (see DistanceOptions.breakStrain). */
  readonly breaks = { count: 0, handles: new Float64Array(16) };
  private hasBreakableLinks = false;
  private readonly recordBreak = (row: number): void => {
    const b = this.breaks;
    if (b.count === b.handles.length) b.handles = grown(b.handles, b.count * 2);
    b.handles[b.count++] = this.constraintIds.handleOf(this.distances.slot[row]);
  };
  private readonly eventTracker = new EventTracker();
  private readonly sleep = new Sleep();
  /** Bodies or constraints changed: the sleep bookkeeping needs rebuilding. */
  private topologyDirty = true;

  private readonly particleIds = new HandleRegistry('particle', 'particles');
  private readonly constraintIds = new HandleRegistry('constraint', 'constraints');
  private readonly bodyIds = new HandleRegistry('body', 'bodies', 'bodies');
  /** Per constraint slot: which table and which row. */
  private constraintKind = new Uint8Array(64);
  private constraintRow = new Int32Array(64);
  /** Per body slot: kind, member particle slots and constraint handles. */
  private bodyKind: BodyKind[] = [];
  private bodyParticles: Int32Array[] = [];
  private bodyConstraints: Handle[][] = [];

  /** Collision state: per body slot colliders, this step's candidate pairs and contacts. */
  readonly colliders = new Colliders();
  readonly contacts = new Contacts();
  readonly pairs = new PairList();
  readonly narrowPhase = new NarrowPhase();
  private _broadPhase: BroadPhase;
  private collidersDirty = false;
  /** Per body slot: how far the body may move this step (speculative margin). */
  private motion = new Float64Array(16);
  private _contactSlop: number;
  private readonly acceptPair = (a: number, b: number) => this.shouldCollide(a, b);
  private readonly anchors = new AnchorCache();
  private readonly bodyHandleOf = (slot: number) => this.bodyIds.handleOf(slot);
  private readonly bodyAlive = (slot: number) => this.bodyIds.alive[slot] === 1;
  private readonly bodyParticlesOf = (slot: number) => this.bodyParticles[slot];

  gravity: Vec2;
  private _timestep: number;
  private _substeps: number;
  private _iterations: number;
  private _damping: number;
  private _integrator: Integrator;
  bounds: Bounds | null;
  private _boundsFriction: number;
  private _maxCatchUpSteps: number;
  variableStep: boolean;

  /** When true, each step records how long collision detection and the substeps took (ms) in `timings`. */
  measureTimings = false;
  readonly timings = { detect: 0, solve: 0 };

  /** Simulated seconds. */
  time = 0;
  /** Steps taken. */
  stepCount = 0;
  /** Fraction of a step left in the accumulator after advance(): blend the two newest states by it to render. */
  alpha = 0;
  private accumulator = 0;

  constructor(options: WorldOptions = {}) {
    const o = { ...DEFAULTS, ...options };
    this.gravity = { x: finite('gravity.x', o.gravity.x), y: finite('gravity.y', o.gravity.y) };
    this._timestep = positive('timestep', o.timestep);
    this._substeps = integer('substeps', o.substeps, 1, 1000);
    this._iterations = integer('iterations', o.iterations, 1, 1000);
    this._damping = nonNegative('damping', o.damping);
    this._integrator = oneOf('integrator', o.integrator, INTEGRATORS);
    this.bounds = o.bounds == null ? null : checkBounds(o.bounds);
    this._boundsFriction = nonNegative('boundsFriction', o.boundsFriction);
    this._maxCatchUpSteps = integer('maxCatchUpSteps', o.maxCatchUpSteps, 1, 1000);
    this.variableStep = Boolean(o.variableStep);
    this._broadPhase = makeBroadPhase(oneOf('broadphase', o.broadphase, ['grid', 'brute'] as const), nonNegative('cellSize', o.cellSize));
    this._contactSlop = nonNegative('contactSlop', o.contactSlop);
    this.narrowPhase.mode = oneOf('narrowphase', o.narrowphase, ['sat', 'gjk'] as const);
    this.sleep.enabled = Boolean(o.sleeping);
    this._maxPushSpeed = positive('maxPushSpeed', o.maxPushSpeed);
    const limits = { ...DEFAULT_LIMITS, ...options.limits };
    this.particleIds.limit = integer('limits.particles', limits.particles, 1, MAX_SLOTS);
    this.constraintIds.limit = integer('limits.constraints', limits.constraints, 1, MAX_SLOTS);
    this.bodyIds.limit = integer('limits.bodies', limits.bodies, 1, MAX_SLOTS);
  }

  /** The caps in force. */
  get limits(): Limits {
    return { particles: this.particleIds.limit, constraints: this.constraintIds.limit, bodies: this.bodyIds.limit };
  }

  private _maxPushSpeed: number;
  get maxPushSpeed(): number {
    return this._maxPushSpeed;
  }
  set maxPushSpeed(v: number) {
    this._maxPushSpeed = positive('maxPushSpeed', v);
  }

  /** Whether bodies at rest fall asleep. Turning it off wakes everything. */
  get sleeping(): boolean {
    return this.sleep.enabled;
  }
  set sleeping(v: boolean) {
    this.sleep.enabled = Boolean(v);
    if (!v) this.wakeAll();
  }

  /** Whether a body is being simulated (false once it has fallen asleep). */
  isAwake(body: Handle): boolean {
    return this.sleep.asleep[this.bodyIds.slotOf(body, 'body')] !== 1;
  }

  /** Wakes a sleeping body (its island wakes with it on contact). */
  wake(body: Handle): void {
    const slot = this.bodyIds.slotOf(body, 'body');
    this.sleep.wakeBody(slot, this.bodyParticles[slot], this.particles);
  }

  wakeAll(): void {
    for (let s = 0; s < this.bodyIds.high; s++) if (this.bodyIds.alive[s]) this.sleep.wakeBody(s, this.bodyParticles[s], this.particles);
  }

  /** True when every body is asleep and no free particle moves: a step then does no work. */
  get settled(): boolean {
    return !this.topologyDirty && this.sleep.enabled && this.sleep.awakeCount === 0 && this.freeMovableParticles === 0 && this.grabs.count === 0;
  }
  private freeMovableParticles = 0;

  /** Wakes the body a particle belongs to (anything the user does to a particle). */
  private wakeParticle(i: number): void {
    if (this.topologyDirty) return;
    const s = this.sleep.particleBody[i];
    if (s >= 0) this.sleep.wakeBody(s, this.bodyParticles[s], this.particles);
  }

  get broadphase(): 'grid' | 'brute' {
    return this._broadPhase.name;
  }
  set broadphase(v: 'grid' | 'brute') {
    const cell = this._broadPhase instanceof GridBroadPhase ? this._broadPhase.cellSize : 0;
    this._broadPhase = makeBroadPhase(oneOf('broadphase', v, ['grid', 'brute'] as const), cell);
  }
  get narrowphase(): 'sat' | 'gjk' {
    return this.narrowPhase.mode;
  }
  set narrowphase(v: 'sat' | 'gjk') {
    this.narrowPhase.mode = oneOf('narrowphase', v, ['sat', 'gjk'] as const);
  }
  get cellSize(): number {
    return this._broadPhase instanceof GridBroadPhase ? this._broadPhase.cellSize : 0;
  }
  set cellSize(v: number) {
    nonNegative('cellSize', v);
    if (this._broadPhase instanceof GridBroadPhase) this._broadPhase.cellSize = v;
  }
  /** The cell size the grid used in the last step (after the automatic choice). */
  get gridCellSize(): number {
    return this._broadPhase instanceof GridBroadPhase ? this._broadPhase.lastCellSize : 0;
  }
  get contactSlop(): number {
    return this._contactSlop;
  }
  set contactSlop(v: number) {
    this._contactSlop = nonNegative('contactSlop', v);
  }

  // ---- settings (validated) ----------------------------------------------------------------------------------

  get timestep(): number {
    return this._timestep;
  }
  set timestep(v: number) {
    this._timestep = positive('timestep', v);
  }
  get substeps(): number {
    return this._substeps;
  }
  set substeps(v: number) {
    this._substeps = integer('substeps', v, 1, 1000);
  }
  get iterations(): number {
    return this._iterations;
  }
  set iterations(v: number) {
    this._iterations = integer('iterations', v, 1, 1000);
  }
  get damping(): number {
    return this._damping;
  }
  set damping(v: number) {
    this._damping = nonNegative('damping', v);
  }
  get integrator(): Integrator {
    return this._integrator;
  }
  set integrator(v: Integrator) {
    this._integrator = oneOf('integrator', v, INTEGRATORS);
  }
  get boundsFriction(): number {
    return this._boundsFriction;
  }
  set boundsFriction(v: number) {
    this._boundsFriction = nonNegative('boundsFriction', v);
  }
  get maxCatchUpSteps(): number {
    return this._maxCatchUpSteps;
  }
  set maxCatchUpSteps(v: number) {
    this._maxCatchUpSteps = integer('maxCatchUpSteps', v, 1, 1000);
  }
  setGravity(x: number, y: number): void {
    this.gravity = { x: finite('gravity.x', x), y: finite('gravity.y', y) };
    this.wakeAll();
  }
  setBounds(bounds: Bounds | null): void {
    this.bounds = bounds == null ? null : checkBounds(bounds);
  }

  /** The substep length h = timestep / substeps. */
  get substepDt(): number {
    return this._timestep / this._substeps;
  }

  // ---- particles ---------------------------------------------------------------------------------------------

  addParticle(options: ParticleOptions): Handle {
    if (options == null || typeof options !== 'object') throw new TypeError(`particle options must be an object, got ${String(options)}`);
    const x = finite('x', options.x);
    const y = finite('y', options.y);
    const mass = options.mass === undefined ? 1 : options.mass;
    if (mass !== Infinity) positive('mass', mass);
    const radius = nonNegative('radius', options.radius ?? 0);
    const vx = finite('vx', options.vx ?? 0);
    const vy = finite('vy', options.vy ?? 0);

    const handle = this.particleIds.allocate();
    const slot = handleSlot(handle);
    const p = this.particles;
    if (slot >= p.count) p.pushRow();
    for (const name of p.columns) (p as unknown as Record<string, Column>)[name][slot] = 0;
    p.x[slot] = p.px[slot] = p.qx[slot] = x;
    p.y[slot] = p.py[slot] = p.qy[slot] = y;
    p.invMass[slot] = mass === Infinity ? 0 : 1 / mass;
    p.radius[slot] = radius;
    p.alive[slot] = 1;
    p.flags[slot] = mass === Infinity ? ParticleFlag.Static : 0;
    this.writeVelocity(slot, vx, vy);
    this.topologyChanged();
    return handle;
  }

  /** Removes a particle and every constraint that uses it. */
  removeParticle(handle: Handle): void {
    const slot = this.particleIds.slotOf(handle, 'particle');
    this.topologyChanged();
    this.removeConstraintsWhere((kind, row) => this.constraintUsesParticle(kind, row, slot));
    const p = this.particles;
    p.alive[slot] = 0;
    p.invMass[slot] = 0;
    p.flags[slot] = 0;
    this.particleIds.release(handle);
  }

  hasParticle(handle: unknown): boolean {
    return this.particleIds.isValid(handle);
  }

  /** The storage index of a live particle handle (index into world.particles' arrays). */
  particleIndex(handle: Handle): number {
    return this.particleIds.slotOf(handle, 'particle');
  }

  /** The handle of the particle stored at `index`. */
  particleHandle(index: number): Handle {
    return this.particleIds.handleOf(index);
  }

  /** Live particle count. */
  get particleCount(): number {
    let n = 0;
    for (let i = 0; i < this.particles.count; i++) n += this.particles.alive[i];
    return n;
  }

  getPosition(handle: Handle): Vec2 {
    const i = this.particleIndex(handle);
    return { x: this.particles.x[i], y: this.particles.y[i] };
  }

  /** Moves a particle (teleport: its velocity is kept). */
  setPosition(handle: Handle, x: number, y: number): void {
    const i = this.particleIndex(handle);
    this.wakeParticle(i);
    const nx = finite('x', x);
    const ny = finite('y', y);
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
    this.wakeParticle(i);
    this.writeVelocity(i, finite('vx', vx), finite('vy', vy));
  }

  /** Adds a force for the next step (cleared after it). */
  applyForce(handle: Handle, fx: number, fy: number): void {
    const i = this.particleIndex(handle);
    this.wakeParticle(i);
    this.particles.fx[i] += finite('fx', fx);
    this.particles.fy[i] += finite('fy', fy);
  }

  /** Changes the velocity by impulse / mass at once. */
  applyImpulse(handle: Handle, ix: number, iy: number): void {
    const i = this.particleIndex(handle);
    this.wakeParticle(i);
    const w = this.particles.invMass[i];
    const jx = finite('ix', ix);
    const jy = finite('iy', iy);
    this.particles.vx[i] += jx * w;
    this.particles.vy[i] += jy * w;
  }

  getMass(handle: Handle): number {
    const i = this.particleIndex(handle);
    const w = this.particles.flags[i] & ParticleFlag.Pinned ? this.savedInvMassOf(i) : this.sleep.awakeInvMass(i, this.particles);
    return w === 0 ? Infinity : 1 / w;
  }

  /**
   * Position Verlet's velocity is the mean over a substep, i.e. the velocity half a substep earlier than the
   * position. Storing v − ½·g·h makes a thrown particle follow x0 + v0·t + ½·g·t² exactly.
   */
  private writeVelocity(i: number, vx: number, vy: number): void {
    const p = this.particles;
    const half = this._integrator === 'verlet' && p.invMass[i] !== 0 ? 0.5 * this.substepDt : 0;
    p.vx[i] = vx - this.gravity.x * half;
    p.vy[i] = vy - this.gravity.y * half;
  }

  // ---- constraints -------------------------------------------------------------------------------------------

  /** A distance constraint (stick, slack rope link or minimum distance) between particles a and b. */
  addDistance(a: Handle, b: Handle, options: DistanceOptions = {}): Handle {
    const [ia, ib] = this.pair(a, b);
    const p = this.particles;
    const current = Math.sqrt((p.x[ib] - p.x[ia]) ** 2 + (p.y[ib] - p.y[ia]) ** 2);
    const length = options.length === undefined ? current : nonNegative('length', options.length);
    const minLength = options.minLength === undefined ? length : nonNegative('minLength', options.minLength);
    const maxLength = options.maxLength === undefined ? length : nonNegativeOrInfinity('maxLength', options.maxLength);
    if (minLength > maxLength) throw new RangeError(`minLength (${minLength}) must be <= maxLength (${maxLength})`);
    const compliance = nonNegative('compliance', options.compliance ?? 0);
    const breakStrain = options.breakStrain === undefined ? 0 : positive('breakStrain', options.breakStrain);
    if (breakStrain > 0 && !(maxLength > 0 && maxLength < Infinity)) throw new RangeError(`breakStrain needs a finite, positive maxLength, got ${maxLength}`);
    const row = this.distances.pushValues({ a: ia, b: ib, minLength, maxLength, compliance, breakStrain });
    if (breakStrain > 0) this.hasBreakableLinks = true;
    return this.registerConstraint(Kind.Distance, this.distances, row);
  }

  /** An angle limit at vertex b over the particles a, b, c. */
  addAngleLimit(a: Handle, b: Handle, c: Handle, options: AngleOptions): Handle {
    const [ia, ib] = this.pair(a, b, 'a', 'b');
    const [, ic] = this.pair(b, c, 'b', 'c');
    if (ia === ic) throw new RangeError(`a and c must be different particles, got ${a} twice`);
    if (options == null) throw new TypeError('angle options {min, max} are required');
    const min = finite('min', options.min);
    const max = finite('max', options.max);
    if (!(min <= max && max - min <= 2 * Math.PI)) throw new RangeError(`angle limits must satisfy min <= max <= min + 2π, got min ${min}, max ${max}`);
    const compliance = nonNegative('compliance', options.compliance ?? 0);
    const row = this.angles.pushValues({ a: ia, b: ib, c: ic, min, max, compliance });
    return this.registerConstraint(Kind.Angle, this.angles, row);
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
    const p = this.particles;
    const current = Math.sqrt((p.x[ib] - p.x[ia]) ** 2 + (p.y[ib] - p.y[ia]) ** 2);
    const restLength = options.length === undefined ? current : nonNegative('length', options.length);
    const stiffness = nonNegative('stiffness', options.stiffness);
    const damping = nonNegative('damping', options.damping ?? 0);
    const row = this.springs.pushValues({ a: ia, b: ib, restLength, stiffness, damping });
    return this.registerConstraint(Kind.Spring, this.springs, row);
  }

  /** Pins a particle to a world point (its current position by default). */
  addPin(particle: Handle, options: PinOptions = {}): Handle {
    const i = this.particleIndex(particle);
    const p = this.particles;
    if (p.flags[i] & ParticleFlag.Pinned) throw new RangeError(`particle ${particle} is already rigidly pinned`);
    const tx = options.x === undefined ? p.x[i] : finite('x', options.x);
    const ty = options.y === undefined ? p.y[i] : finite('y', options.y);
    const compliance = nonNegative('compliance', options.compliance ?? 0);
    const t = this.pins;
    const row = t.pushValues({ p: i, tx, ty, compliance });
    if (compliance === 0) {
      t.savedInvMass[row] = p.invMass[i];
      p.invMass[i] = 0;
      p.flags[i] |= ParticleFlag.Pinned;
      p.x[i] = p.px[i] = tx;
      p.y[i] = p.py[i] = ty;
      p.vx[i] = p.vy[i] = 0;
    }
    return this.registerConstraint(Kind.Pin, t, row);
  }

  /** Moves a pin's target (a dragged or animated anchor). */
  setPinTarget(pin: Handle, x: number, y: number): void {
    const row = this.constraintRowOf(pin, Kind.Pin, 'pin');
    this.wakeParticle(this.pins.p[row]);
    this.pins.tx[row] = finite('x', x);
    this.pins.ty[row] = finite('y', y);
  }

  /** Keeps the area of the closed loop of particles (in order) at pressure × its current area. */
  addAreaConstraint(loop: readonly Handle[], options: AreaOptions = {}): Handle {
    if (!Array.isArray(loop) || loop.length < 3) throw new RangeError(`an area constraint needs a loop of at least 3 particles, got ${Array.isArray(loop) ? loop.length : String(loop)}`);
    const slots = loop.map((h, k) => this.particleIds.slotOf(h, `loop[${k}]`));
    if (new Set(slots).size !== slots.length) throw new RangeError('an area constraint loop must not repeat a particle');
    const pressure = positive('pressure', options.pressure ?? 1);
    const t = this.areas;
    const compliance = nonNegative('compliance', options.compliance ?? 0);
    const start = t.appendLoop(slots);
    const restArea = loopArea(t.pool, start, slots.length, this.particles.x, this.particles.y) * pressure;
    const row = t.pushValues({ start, length: slots.length, restArea, compliance });
    return this.registerConstraint(Kind.Area, t, row);
  }

  removeConstraint(handle: Handle): void {
    const slot = this.constraintIds.slotOf(handle, 'constraint');
    this.topologyChanged();
    const kind = this.constraintKind[slot] as Kind;
    const row = this.constraintRow[slot];
    if (kind === Kind.Pin && this.pins.compliance[row] === 0) {
      const i = this.pins.p[row];
      this.particles.invMass[i] = this.pins.savedInvMass[row];
      this.particles.flags[i] &= ~ParticleFlag.Pinned;
    }
    const table = this.tableOf(kind) as Table & { slot: Int32Array };
    const from = table.swapRemove(row);
    if (from !== row) this.constraintRow[table.slot[row]] = row;
    if (kind === Kind.Area) this.areas.compactPool();
    this.constraintIds.release(handle);
  }

  /** Which kind of constraint a handle names. */
  constraintKindOf(handle: Handle): ConstraintKind {
    return CONSTRAINT_KINDS[this.constraintKind[this.constraintIds.slotOf(handle, 'constraint')]];
  }

  hasConstraint(handle: unknown): boolean {
    return this.constraintIds.isValid(handle);
  }

  get constraintCount(): number {
    return this.distances.count + this.angles.count + this.pins.count + this.springs.count + this.areas.count + this.grabs.count;
  }

  /** Length error of a distance constraint: how far the current length is outside [minLength, maxLength]. */
  distanceError(handle: Handle): number {
    const row = this.constraintRowOf(handle, Kind.Distance, 'distance constraint');
    const t = this.distances;
    const p = this.particles;
    const d = Math.sqrt((p.x[t.b[row]] - p.x[t.a[row]]) ** 2 + (p.y[t.b[row]] - p.y[t.a[row]]) ** 2);
    return d > t.maxLength[row] ? d - t.maxLength[row] : d < t.minLength[row] ? t.minLength[row] - d : 0;
  }

  /** The particle indices (slots in the state arrays) a distance constraint joins. */
  distanceParticleIndices(handle: Handle): [number, number] {
    const row = this.constraintRowOf(handle, Kind.Distance, 'distance constraint');
    return [this.distances.a[row], this.distances.b[row]];
  }

  /** How many distance constraints have broken (torn) so far. */
  get brokenLinkCount(): number {
    const { broken, count } = this.distances;
    let n = 0;
    for (let i = 0; i < count; i++) n += broken[i];
    return n;
  }

  /** Whether a distance constraint made with breakStrain has broken (it then no longer acts). */
  isBroken(handle: Handle): boolean {
    return this.distances.broken[this.constraintRowOf(handle, Kind.Distance, 'distance constraint')] === 1;
  }

  /** The largest relative stretch |d − L| / L over all distance constraints with L > 0 (0 when none). */
  maxStrain(): number {
    const t = this.distances;
    const { x, y } = this.particles;
    let worst = 0;
    for (let i = 0; i < t.count; i++) {
      const d = Math.sqrt((x[t.b[i]] - x[t.a[i]]) ** 2 + (y[t.b[i]] - y[t.a[i]]) ** 2);
      const over = d > t.maxLength[i] ? (d - t.maxLength[i]) / t.maxLength[i] : d < t.minLength[i] ? (t.minLength[i] - d) / t.minLength[i] : 0;
      if (over > worst && Number.isFinite(over)) worst = over;
    }
    return worst;
  }

  private pair(a: Handle, b: Handle, nameA = 'a', nameB = 'b'): [number, number] {
    const ia = this.particleIds.slotOf(a, nameA);
    const ib = this.particleIds.slotOf(b, nameB);
    if (ia === ib) throw new RangeError(`${nameA} and ${nameB} must be different particles, got ${a} twice`);
    return [ia, ib];
  }

  private registerConstraint(kind: Kind, table: { slot: Int32Array }, row: number): Handle {
    const handle = this.constraintIds.allocate();
    const slot = handleSlot(handle);
    if (slot >= this.constraintKind.length) {
      const k = new Uint8Array(this.constraintKind.length * 2);
      k.set(this.constraintKind);
      this.constraintKind = k;
      const r = new Int32Array(this.constraintRow.length * 2);
      r.set(this.constraintRow);
      this.constraintRow = r;
    }
    this.constraintKind[slot] = kind;
    this.constraintRow[slot] = row;
    table.slot[row] = slot;
    this.topologyChanged();
    return handle;
  }

  private constraintRowOf(handle: Handle, kind: Kind, what: string): number {
    const slot = this.constraintIds.slotOf(handle, what);
    if (this.constraintKind[slot] !== kind) throw new RangeError(`constraint ${handle} is not a ${what}`);
    return this.constraintRow[slot];
  }

  private tableOf(kind: Kind): Table {
    return [this.distances, this.angles, this.pins, this.springs, this.areas, this.grabs][kind];
  }

  /**
   * Bodies, particles or constraints changed. Everything wakes (a removed support must not leave sleepers
   * floating, and parked masses must not be restored over a changed pin) and the bookkeeping is rebuilt.
   */
  private topologyChanged(): void {
    if (!this.topologyDirty) this.wakeAll();
    this.topologyDirty = true;
  }

  private savedInvMassOf(particle: number): number {
    for (let r = 0; r < this.pins.count; r++) if (this.pins.p[r] === particle && this.pins.compliance[r] === 0) return this.pins.savedInvMass[r];
    return 0;
  }

  private constraintUsesParticle(kind: Kind, row: number, i: number): boolean {
    switch (kind) {
      case Kind.Distance:
        return this.distances.a[row] === i || this.distances.b[row] === i;
      case Kind.Angle:
        return this.angles.a[row] === i || this.angles.b[row] === i || this.angles.c[row] === i;
      case Kind.Pin:
        return this.pins.p[row] === i;
      case Kind.Spring:
        return this.springs.a[row] === i || this.springs.b[row] === i;
      case Kind.Area: {
        const t = this.areas;
        for (let k = 0; k < t.length[row]; k++) if (t.pool[t.start[row] + k] === i) return true;
        return false;
      }
      case Kind.Grab:
        return this.grabs.p0[row] === i || this.grabs.p1[row] === i || this.grabs.p2[row] === i;
    }
  }

  private removeConstraintsWhere(test: (kind: Kind, row: number) => boolean): void {
    const doomed: Handle[] = [];
    for (let slot = 0; slot < this.constraintIds.high; slot++) {
      if (!this.constraintIds.alive[slot]) continue;
      if (test(this.constraintKind[slot] as Kind, this.constraintRow[slot])) doomed.push(this.constraintIds.handleOf(slot));
    }
    for (const h of doomed) this.removeConstraint(h);
  }

  // ---- bodies ------------------------------------------------------------------------------------------------

  /** Groups particles and constraints into one body (the builders call this), colliding as `collider` says. */
  addBody(kind: BodyKind, particles: readonly Handle[], constraints: readonly Handle[] = [], collider: ColliderOptions = { shape: 'none' }): Handle {
    oneOf('kind', kind, BODY_KINDS);
    if (!Array.isArray(particles) || particles.length === 0) throw new RangeError(`a body needs at least one particle, got ${String(particles)}`);
    const slots = Int32Array.from(particles, (h, k) => this.particleIds.slotOf(h, `particles[${k}]`));
    constraints.forEach((h, k) => this.constraintIds.slotOf(h, `constraints[${k}]`));
    const resolved = this.checkCollider(collider, slots.length);
    const handle = this.bodyIds.allocate();
    const slot = handleSlot(handle);
    this.bodyKind[slot] = kind;
    this.bodyParticles[slot] = slots;
    this.bodyConstraints[slot] = constraints.slice();
    this.writeCollider(slot, resolved);
    this.topologyChanged();
    return handle;
  }

  /** Changes how a body collides (any subset of the options; the rest keep their values). */
  setCollider(body: Handle, options: ColliderOptions): void {
    const slot = this.bodyIds.slotOf(body, 'body');
    const c = this.colliders;
    const current: ColliderOptions = {
      shape: c.kind[slot] === ColliderKind.Polygon ? 'polygon' : c.kind[slot] === ColliderKind.Particles ? 'particles' : 'none',
      parts: this.bodyParts[slot],
      friction: c.friction[slot],
      restitution: c.restitution[slot],
      category: c.category[slot],
      mask: c.mask[slot],
      group: c.group[slot],
    };
    this.writeCollider(slot, this.checkCollider({ ...current, ...options }, this.bodyParticles[slot].length));
  }

  private bodyParts: (number[][] | undefined)[] = [];

  /** Whether a soft body has a centre particle held by springs (the 'springs' model): its last particle. */
  private isHubbed(slot: number): boolean {
    const idx = this.bodyParticles[slot];
    const hub = idx[idx.length - 1];
    for (let r = 0; r < this.springs.count; r++) if (this.springs.a[r] === hub || this.springs.b[r] === hub) return true;
    return false;
  }

  private checkCollider(o: ColliderOptions, particleCount: number): Required<Omit<ColliderOptions, 'parts'>> & { parts?: number[][] } {
    if (o == null || typeof o !== 'object') throw new TypeError(`collider options must be an object, got ${String(o)}`);
    const shape = oneOf('shape', o.shape ?? 'polygon', COLLIDER_SHAPES);
    let parts: number[][] | undefined;
    if (o.parts !== undefined) {
      if (!Array.isArray(o.parts) || o.parts.length === 0) throw new RangeError(`parts must be a non-empty list of index lists, got ${JSON.stringify(o.parts)}`);
      parts = o.parts.map((part, k) => {
        if (!Array.isArray(part) || part.length < 3) throw new RangeError(`parts[${k}] must list at least 3 particle indices, got ${JSON.stringify(part)}`);
        return part.map((i, j) => integer(`parts[${k}][${j}]`, i, 0, particleCount - 1));
      });
    }
    if (shape === 'polygon' && !parts && particleCount < 3) throw new RangeError(`a polygon collider needs at least 3 particles, got ${particleCount}`);
    const restitution = finite('restitution', o.restitution ?? 0);
    if (restitution < 0 || restitution > 1) throw new RangeError(`restitution must be between 0 and 1, got ${restitution}`);
    return {
      shape,
      parts,
      friction: nonNegative('friction', o.friction ?? 0.6),
      restitution,
      category: integer('category', o.category ?? 1, 0, 0xffffffff),
      mask: integer('mask', o.mask ?? 0xffffffff, 0, 0xffffffff),
      group: integer('group', o.group ?? 0, -0x80000000, 0x7fffffff),
    };
  }

  private writeCollider(slot: number, o: ReturnType<World['checkCollider']>): void {
    const c = this.colliders;
    c.ensureBodies(slot + 1);
    c.kind[slot] = o.shape === 'polygon' ? ColliderKind.Polygon : o.shape === 'particles' ? ColliderKind.Particles : ColliderKind.None;
    c.friction[slot] = o.friction;
    c.restitution[slot] = o.restitution;
    c.category[slot] = o.category;
    c.mask[slot] = o.mask;
    c.group[slot] = o.group;
    // A soft ring is picked and queried by its inside, not only by its particles' circles (the springs model's
    // last particle is the hub, not part of the ring).
    const ring = this.bodyKind[slot] === 'soft' ? this.bodyParticles[slot].length - (this.springs.count > 0 && this.isHubbed(slot) ? 1 : 0) : 0;
    c.ringLength[slot] = ring;
    this.bodyParts[slot] = o.parts;
    this.collidersDirty = true;
  }

  /** Removes a body with its particles and constraints. */
  removeBody(handle: Handle): void {
    const slot = this.bodyIds.slotOf(handle, 'body');
    this.topologyChanged();
    for (const c of this.bodyConstraints[slot]) if (this.constraintIds.isValid(c)) this.removeConstraint(c);
    for (const i of this.bodyParticles[slot]) {
      const h = this.particleIds.handleOf(i);
      if (this.particleIds.isValid(h)) this.removeParticle(h);
    }
    this.bodyParticles[slot] = new Int32Array(0);
    this.bodyConstraints[slot] = [];
    this.bodyParts[slot] = undefined;
    this.colliders.kind[slot] = ColliderKind.None;
    this.collidersDirty = true;
    this.bodyIds.release(handle);
  }

  hasBody(handle: unknown): boolean {
    return this.bodyIds.isValid(handle);
  }

  bodyKindOf(handle: Handle): BodyKind {
    return this.bodyKind[this.bodyIds.slotOf(handle, 'body')];
  }

  /** Storage indices of a body's particles (a view: do not modify). */
  bodyParticleIndices(handle: Handle): Int32Array {
    return this.bodyParticles[this.bodyIds.slotOf(handle, 'body')];
  }

  bodyParticleHandles(handle: Handle): Handle[] {
    return Array.from(this.bodyParticleIndices(handle), (i) => this.particleIds.handleOf(i));
  }

  bodyConstraintHandles(handle: Handle): Handle[] {
    return this.bodyConstraints[this.bodyIds.slotOf(handle, 'body')].slice();
  }

  /** Mean position of a body's particles. */
  bodyCentroid(handle: Handle): Vec2 {
    const idx = this.bodyParticleIndices(handle);
    let sx = 0;
    let sy = 0;
    for (const i of idx) {
      sx += this.particles.x[i];
      sy += this.particles.y[i];
    }
    return { x: sx / idx.length, y: sy / idx.length };
  }

  /** Adds an impulse spread over a body's particles by mass (a change of the body's velocity by impulse / mass). */
  applyBodyImpulse(handle: Handle, ix: number, iy: number): void {
    const idx = this.bodyParticleIndices(handle);
    const jx = finite('ix', ix);
    const jy = finite('iy', iy);
    this.wake(handle);
    let mass = 0;
    for (const i of idx) if (this.particles.invMass[i] > 0) mass += 1 / this.particles.invMass[i];
    if (mass === 0) return;
    for (const i of idx) {
      if (this.particles.invMass[i] === 0) continue;
      this.particles.vx[i] += jx / mass;
      this.particles.vy[i] += jy / mass;
    }
  }

  *bodies(): IterableIterator<Handle> {
    for (let slot = 0; slot < this.bodyIds.high; slot++) if (this.bodyIds.alive[slot]) yield this.bodyIds.handleOf(slot);
  }

  // ---- pointer drag and queries ------------------------------------------------------------------------------

  /**
   * Grabs whatever is at (x, y): a body whose shape contains the point (held at that very point of the body), else
   * the nearest movable particle within `pickRadius` (cloth, rope). Returns a grab handle for moveGrab/release, or
   * null when nothing movable is there.
   */
  grab(x: number, y: number, options: GrabOptions = {}): Handle | null {
    finite('x', x);
    finite('y', y);
    const stiffness = positive('stiffness', options.stiffness ?? 2000);
    const pickRadius = nonNegative('pickRadius', options.pickRadius ?? 0.5);
    if (this.topologyDirty) this.rebuildTopology();
    const p = this.particles;
    const c = this.colliders;
    for (const s of bodiesAtPoint(c, p, x, y)) {
      const idx = this.bodyParticles[s];
      const mass = this.bodyMass(s);
      if (mass === 0) continue;
      if (c.kind[s] === ColliderKind.Polygon) {
        // A triangle of the outline's fan holds the point: barycentric weights keep it fixed in the body.
        for (let k = 1; k + 1 < idx.length; k++) {
          const w = barycentric(p, idx[0], idx[k], idx[k + 1], x, y);
          if (w) return this.addGrab(idx[0], idx[k], idx[k + 1], w[0], w[1], w[2], x, y, 1 / (stiffness * mass));
        }
      }
      const nearest = this.nearestParticle(idx, x, y);
      if (nearest >= 0) return this.addGrab(nearest, nearest, nearest, 1, 0, 0, x, y, 1 / (stiffness * mass));
    }
    let best = -1;
    let bestD2 = pickRadius * pickRadius;
    for (let i = 0; i < p.count; i++) {
      if (!p.alive[i] || this.sleep.awakeInvMass(i, p) === 0) continue;
      const d2 = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
      if (d2 <= bestD2) [best, bestD2] = [i, d2];
    }
    if (best < 0) return null;
    this.wakeParticle(best);
    // Held at one particle, a cloth or rope is still pulled as a whole: the pull scales with the mass of the body
    // the particle belongs to, so dragging a cloth feels like dragging a box of the same mass.
    const owner = this.sleep.particleBody[best];
    const mass = owner >= 0 ? this.bodyMass(owner) : 1 / p.invMass[best];
    return this.addGrab(best, best, best, 1, 0, 0, x, y, 1 / (stiffness * mass));
  }

  /** Moves a grab's target (the pointer). */
  moveGrab(grab: Handle, x: number, y: number): void {
    const row = this.constraintRowOf(grab, Kind.Grab, 'grab');
    this.grabs.tx[row] = finite('x', x);
    this.grabs.ty[row] = finite('y', y);
    this.wakeParticle(this.grabs.p0[row]);
  }

  /** Lets go: the body keeps the velocity the drag gave it (a throw). */
  release(grab: Handle): void {
    this.constraintRowOf(grab, Kind.Grab, 'grab');
    this.removeConstraint(grab);
  }

  private addGrab(a: number, b: number, c: number, wa: number, wb: number, wc: number, x: number, y: number, compliance: number): Handle {
    this.wakeParticle(a);
    const row = this.grabs.pushValues({ p0: a, p1: b, p2: c, w0: wa, w1: wb, w2: wc, tx: x, ty: y, compliance });
    return this.registerConstraint(Kind.Grab, this.grabs, row);
  }

  private bodyMass(slot: number): number {
    let m = 0;
    for (const i of this.bodyParticles[slot]) {
      const w = this.sleep.awakeInvMass(i, this.particles);
      if (w > 0) m += 1 / w;
    }
    return m;
  }

  private nearestParticle(idx: Int32Array, x: number, y: number): number {
    const p = this.particles;
    let best = -1;
    let bestD2 = Infinity;
    for (const i of idx) {
      if (p.invMass[i] === 0 && this.sleep.awakeInvMass(i, p) === 0) continue;
      const d2 = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
      if (d2 < bestD2) [best, bestD2] = [i, d2];
    }
    return best;
  }

  /** Bodies whose collision shape contains (x, y), the last created first. */
  bodiesAtPoint(x: number, y: number): Handle[] {
    finite('x', x);
    finite('y', y);
    if (this.topologyDirty) this.rebuildTopology();
    return bodiesAtPoint(this.colliders, this.particles, x, y).map(this.bodyHandleOf);
  }

  /** Bodies whose collision shape overlaps the box. */
  bodiesInBox(minX: number, minY: number, maxX: number, maxY: number): Handle[] {
    [minX, minY, maxX, maxY].forEach((v, k) => finite(['minX', 'minY', 'maxX', 'maxY'][k], v));
    if (this.topologyDirty) this.rebuildTopology();
    return bodiesInBox(this.colliders, this.particles, minX, minY, maxX, maxY).map(this.bodyHandleOf);
  }

  /** The nearest body hit by the segment from (x0, y0) to (x1, y1), or null. */
  rayCast(x0: number, y0: number, x1: number, y1: number): RayCastHit | null {
    [x0, y0, x1, y1].forEach((v, k) => finite(['x0', 'y0', 'x1', 'y1'][k], v));
    if (this.topologyDirty) this.rebuildTopology();
    const hit = rayCast(this.colliders, this.particles, x0, y0, x1, y1);
    return hit && { body: this.bodyHandleOf(hit.slot), x: hit.x, y: hit.y, normalX: hit.normalX, normalY: hit.normalY, distance: hit.distance };
  }

  // ---- time --------------------------------------------------------------------------------------------------

  /** One step of `dt` seconds (the fixed timestep by default), in `substeps` substeps. */
  step(dt: number = this._timestep): void {
    if (dt !== this._timestep) positive('dt', dt);
    const n = this._substeps;
    const h = dt / n;
    if (this.topologyDirty) this.rebuildTopology();
    if (this.settled) {
      // Everything sleeps: nothing moves, nothing to compute.
      this.events.count = 0;
      this.breaks.count = 0;
      this.time += dt;
      this.stepCount++;
      return;
    }
    const t0 = this.measureTimings ? performance.now() : 0;
    const { x, y, sx, sy } = this.particles;
    for (let i = 0, count = this.particles.count; i < count; i++) {
      sx[i] = x[i];
      sy[i] = y[i];
    }
    this.detectCollisions(dt);
    const t1 = this.measureTimings ? performance.now() : 0;
    for (let s = 0; s < n; s++) this.substep(h);
    if (this.measureTimings) {
      this.timings.detect = t1 - t0;
      this.timings.solve = performance.now() - t1;
    }
    this.anchors.store(this.contacts);
    this.breaks.count = 0;
    if (this.hasBreakableLinks) breakOverstretched(this.distances, this.particles, this.recordBreak);
    const bodySlots = this.bodyIds.high;
    this.eventTracker.update(this.contacts, this.contacts.touched, this.bodyHandleOf, this.bodyAlive, this.events);
    this.sleep.update(bodySlots, this.bodyIds.alive, this.bodyParticlesOf, this.particles, this.contacts, this.contacts.touched, dt);
    this.particles.fx.fill(0, 0, this.particles.count);
    this.particles.fy.fill(0, 0, this.particles.count);
    this.time += dt;
    this.stepCount++;
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
    if (this.variableStep) {
      if (elapsed === 0) return 0;
      this.step(Math.min(elapsed, this._timestep * this._maxCatchUpSteps));
      this.alpha = 1;
      afterStep?.();
      return 1;
    }
    this.accumulator += elapsed;
    let taken = 0;
    while (this.accumulator >= this._timestep && taken < this._maxCatchUpSteps) {
      this.step();
      this.accumulator -= this._timestep;
      taken++;
      afterStep?.();
    }
    if (this.accumulator >= this._timestep) this.accumulator %= this._timestep;
    this.alpha = this.accumulator / this._timestep;
    return taken;
  }

  private substep(h: number): void {
    const h2 = h * h;
    this.accelerate(h);
    integrate(this.particles, h, 1 / (1 + h * this._damping), this._integrator);
    placeRigidPins(this.pins, this.particles);
    this.distances.lambda.fill(0, 0, this.distances.count);
    this.angles.lambda.fill(0, 0, this.angles.count);
    this.areas.lambda.fill(0, 0, this.areas.count);
    this.pins.lambdaX.fill(0, 0, this.pins.count);
    this.pins.lambdaY.fill(0, 0, this.pins.count);
    this.grabs.lambdaX.fill(0, 0, this.grabs.count);
    this.grabs.lambdaY.fill(0, 0, this.grabs.count);
    this.contacts.beginSubstep(this._maxPushSpeed * h);
    for (let k = 0; k < this._iterations; k++) this.relax(h2);
    updateVelocities(this.particles, h, this._integrator);
    if (this.contacts.count > 0) solveContactVelocities(this.contacts, this.particles);
  }

  /** Gravity, the user's forces and the springs' forces, as accelerations. */
  private accelerate(h: number): void {
    const { ax, ay, fx, fy, invMass } = this.particles;
    const gx = this.gravity.x;
    const gy = this.gravity.y;
    for (let i = 0, n = this.particles.count; i < n; i++) {
      ax[i] = gx + fx[i] * invMass[i];
      ay[i] = gy + fy[i] * invMass[i];
    }
    if (this.springs.count > 0) accumulateSprings(this.springs, this.particles, ax, ay, h);
  }

  /** One Gauss–Seidel sweep over every constraint (seed Algorithm 1), then the bounds. */
  private relax(h2: number): void {
    const p = this.particles;
    if (this.distances.count > 0) solveDistances(this.distances, p, h2);
    if (this.angles.count > 0) solveAngles(this.angles, p, h2);
    if (this.areas.count > 0) solveAreas(this.areas, p, h2);
    if (this.pins.count > 0) solveSoftPins(this.pins, p, h2);
    if (this.grabs.count > 0) solveGrabs(this.grabs, p, h2);
    if (this.contacts.count > 0) solveContacts(this.contacts, p);
    if (this.bounds) keepInBounds(p, this.bounds, this._boundsFriction);
  }

  // ---- collision pipeline ------------------------------------------------------------------------------------

  /** Particle → body map, cross-body constraint links and free particles, for sleeping (after any change). */
  private rebuildTopology(): void {
    if (this.collidersDirty) this.rebuildColliders();
    const high = this.bodyIds.high;
    const p = this.particles;
    this.sleep.rebuild(high, p.count, (slot) => (this.bodyIds.alive[slot] ? this.bodyParticles[slot] : null));
    const owner = this.sleep.particleBody;
    const links: [number, number][] = [];
    const link = (i: number, j: number) => {
      const a = owner[i];
      const b = owner[j];
      if (a >= 0 && b >= 0 && a !== b) links.push([a, b]);
    };
    const d = this.distances;
    for (let r = 0; r < d.count; r++) link(d.a[r], d.b[r]);
    const s = this.springs;
    for (let r = 0; r < s.count; r++) link(s.a[r], s.b[r]);
    const g = this.angles;
    for (let r = 0; r < g.count; r++) {
      link(g.a[r], g.b[r]);
      link(g.b[r], g.c[r]);
    }
    const ar = this.areas;
    for (let r = 0; r < ar.count; r++) for (let k = 1; k < ar.length[r]; k++) link(ar.pool[ar.start[r]], ar.pool[ar.start[r] + k]);
    this.sleep.setLinks(links);
    let free = 0;
    for (let i = 0; i < p.count; i++) if (p.alive[i] && owner[i] < 0 && p.invMass[i] > 0) free++;
    this.freeMovableParticles = free;
    let awake = 0;
    for (let b = 0; b < high; b++) if (this.bodyIds.alive[b] && !this.sleep.asleep[b]) awake++;
    this.sleep.awakeCount = awake;
    this.topologyDirty = false;
  }

  /** Broad phase then narrow phase, once per step: the contacts found act in every substep (speculatively). */
  private detectCollisions(dt: number): void {
    if (this.collidersDirty) this.rebuildColliders();
    const c = this.colliders;
    this.contacts.count = 0;
    this.pairs.count = 0;
    if (c.activeCount === 0) return;
    this.updateBoundingBoxes(dt);
    this._broadPhase.findPairs(c, this.acceptPair, this.pairs);
    this.narrowPhase.run(this.pairs, c, this.particles, this.motion, this._contactSlop, this.contacts);
    this.anchors.restore(this.contacts);
    recordApproachSpeeds(this.contacts, this.particles);
  }

  private rebuildColliders(): void {
    const high = this.bodyIds.high;
    this.motion = grown(this.motion, high);
    this.colliders.rebuild(high, (slot) => {
      if (!this.bodyIds.alive[slot]) return null;
      const particles = this.bodyParticles[slot];
      const parts = this.bodyParts[slot];
      return { particles, parts: parts ? parts.map((part) => Int32Array.from(part, (k) => particles[k])) : [particles] };
    });
    if (this._broadPhase instanceof GridBroadPhase) this._broadPhase.invalidateCellSize();
    this.collidersDirty = false;
  }

  /** Each collider's AABB, grown by how far it can move this step (velocity and gravity), and that distance. */
  private updateBoundingBoxes(dt: number): void {
    const c = this.colliders;
    const { x, y, vx, vy, radius, invMass } = this.particles;
    const g = Math.sqrt(this.gravity.x ** 2 + this.gravity.y ** 2) * dt * dt;
    for (let k = 0; k < c.activeCount; k++) {
      const s = c.active[k];
      const idx = c.particles[s];
      let minX = Infinity;
      let minY = Infinity;
      let maxX = -Infinity;
      let maxY = -Infinity;
      let speed2 = 0;
      let movable = 0;
      for (let q = 0; q < idx.length; q++) {
        const i = idx[q];
        const r = radius[i];
        if (x[i] - r < minX) minX = x[i] - r;
        if (y[i] - r < minY) minY = y[i] - r;
        if (x[i] + r > maxX) maxX = x[i] + r;
        if (y[i] + r > maxY) maxY = y[i] + r;
        const v2 = vx[i] * vx[i] + vy[i] * vy[i];
        if (v2 > speed2) speed2 = v2;
        if (invMass[i] !== 0) movable = 1;
      }
      const m = movable ? Math.sqrt(speed2) * dt + g : Math.sqrt(speed2) * dt;
      this.motion[s] = m;
      c.isStatic[s] = movable ? 0 : 1;
      c.minX[s] = minX - m;
      c.minY[s] = minY - m;
      c.maxX[s] = maxX + m;
      c.maxY[s] = maxY + m;
    }
  }

  private shouldCollide(a: number, b: number): boolean {
    const c = this.colliders;
    // Pairs where neither body can move (static or asleep) need no contacts.
    const asleep = this.sleep.asleep;
    if ((c.isStatic[a] || asleep[a]) && (c.isStatic[b] || asleep[b])) return false;
    const ga = c.group[a];
    if (ga !== 0 && ga === c.group[b]) return ga > 0;
    return (c.category[a] & c.mask[b]) !== 0 && (c.category[b] & c.mask[a]) !== 0;
  }

  // ---- determinism -------------------------------------------------------------------------------------------

  /** A hash of the full simulation state (positions, velocities, masses): equal states give equal hashes. */
  stateHash(): string {
    const p = this.particles;
    const n = p.count;
    return hashColumns([p.x, p.y, p.px, p.py, p.vx, p.vy, p.invMass, p.alive], n, [this.stepCount, this.constraintCount]);
  }

  /** The whole state as plain data (structured-cloneable: a worker can post it). */
  snapshot(): WorldSnapshot {
    // The sleep bookkeeping (awake count) is derived when the topology is rebuilt; a snapshot taken before that (before
    // the first step, right after an edit) would restore a stale count and freeze the world. Rebuild it now.
    if (this.topologyDirty) this.rebuildTopology();
    const tables = [this.particles, this.distances, this.angles, this.pins, this.springs, this.areas, this.grabs];
    return {
      sleep: this.sleep.snapshot(this.bodyIds.high, this.particles.count),
      settings: {
        gravity: { ...this.gravity },
        timestep: this._timestep,
        substeps: this._substeps,
        iterations: this._iterations,
        damping: this._damping,
        integrator: this._integrator,
        bounds: this.bounds ? { ...this.bounds } : null,
        boundsFriction: this._boundsFriction,
        maxCatchUpSteps: this._maxCatchUpSteps,
        variableStep: this.variableStep,
        broadphase: this.broadphase,
        narrowphase: this.narrowphase,
        cellSize: this.cellSize,
        contactSlop: this._contactSlop,
        sleeping: this.sleep.enabled,
        maxPushSpeed: this._maxPushSpeed,
        limits: this.limits,
      },
      time: this.time,
      stepCount: this.stepCount,
      accumulator: this.accumulator,
      tables: tables.map((t) => ({ count: t.count, columns: t.snapshot() })),
      areaPool: this.areas.pool.slice(0, this.areas.poolUsed),
      registries: [this.particleIds, this.constraintIds, this.bodyIds].map((r) => r.snapshot()),
      constraintKind: this.constraintKind.slice(),
      constraintRow: this.constraintRow.slice(),
      bodyKind: this.bodyKind.slice(),
      bodyParticles: this.bodyParticles.map((a) => a.slice()),
      bodyConstraints: this.bodyConstraints.map((a) => a.slice()),
      bodyParts: this.bodyParts.map((parts) => parts?.map((part) => part.slice())),
      anchors: this.anchors.snapshot(),
      colliders: (['kind', 'friction', 'restitution', 'category', 'mask', 'group'] as const).map((name) => this.colliders[name].slice(0, this.bodyIds.high)),
    };
  }

  restore(s: WorldSnapshot): void {
    Object.assign(this, {
      gravity: { ...s.settings.gravity },
      _timestep: s.settings.timestep,
      _substeps: s.settings.substeps,
      _iterations: s.settings.iterations,
      _damping: s.settings.damping,
      _integrator: s.settings.integrator,
      bounds: s.settings.bounds ? { ...s.settings.bounds } : null,
      _boundsFriction: s.settings.boundsFriction,
      _maxCatchUpSteps: s.settings.maxCatchUpSteps,
      variableStep: s.settings.variableStep,
      _contactSlop: s.settings.contactSlop,
      _maxPushSpeed: s.settings.maxPushSpeed,
    });
    this.particleIds.limit = s.settings.limits.particles;
    this.constraintIds.limit = s.settings.limits.constraints;
    this.bodyIds.limit = s.settings.limits.bodies;
    this.broadphase = s.settings.broadphase;
    this.narrowphase = s.settings.narrowphase;
    this.sleep.enabled = s.settings.sleeping;
    this.cellSize = s.settings.cellSize;
    this.time = s.time;
    this.stepCount = s.stepCount;
    this.accumulator = s.accumulator;
    const tables = [this.particles, this.distances, this.angles, this.pins, this.springs, this.areas, this.grabs];
    tables.forEach((t, k) => t.restore(s.tables[k].columns, s.tables[k].count));
    this.hasBreakableLinks = this.distances.breakStrain.some((v) => v > 0);
    this.breaks.count = 0;
    this.areas.pool = new Int32Array(Math.max(64, s.areaPool.length));
    this.areas.pool.set(s.areaPool);
    this.areas.poolUsed = s.areaPool.length;
    [this.particleIds, this.constraintIds, this.bodyIds].forEach((r, k) => r.restore(s.registries[k]));
    this.constraintKind = s.constraintKind.slice();
    this.constraintRow = s.constraintRow.slice();
    this.bodyKind = s.bodyKind.slice();
    this.bodyParticles = s.bodyParticles.map((a) => a.slice());
    this.bodyConstraints = s.bodyConstraints.map((a) => a.slice());
    this.bodyParts = s.bodyParts.map((parts) => parts?.map((part) => part.slice()));
    const c = this.colliders;
    c.ensureBodies(this.bodyIds.high);
    (['kind', 'friction', 'restitution', 'category', 'mask', 'group'] as const).forEach((name, k) => {
      c[name].fill(0);
      c[name].set(s.colliders[k]);
    });
    this.anchors.restoreSnapshot(s.anchors);
    this.collidersDirty = true;
    this.topologyDirty = true;
    this.rebuildTopology();
    this.sleep.restore(s.sleep);
    this.eventTracker.clear();
    this.events.count = 0;
  }
}

export interface WorldSnapshot {
  settings: Required<Omit<WorldOptions, 'bounds' | 'limits'>> & { bounds: Bounds | null; limits: Limits };
  time: number;
  stepCount: number;
  accumulator: number;
  tables: { count: number; columns: Column[] }[];
  areaPool: Int32Array;
  registries: RegistrySnapshot[];
  constraintKind: Uint8Array;
  constraintRow: Int32Array;
  bodyKind: BodyKind[];
  bodyParticles: Int32Array[];
  bodyConstraints: Handle[][];
  bodyParts: (number[][] | undefined)[];
  anchors: { keys: Float64Array; values: Float64Array };
  sleep: Float64Array[];
  colliders: (Float64Array | Uint8Array | Uint32Array | Int32Array)[];
}

/** Barycentric weights of (x, y) in triangle a, b, c, or null when outside (or degenerate). */
function barycentric(p: ParticleStore, a: number, b: number, c: number, x: number, y: number): [number, number, number] | null {
  const v0x = p.x[b] - p.x[a];
  const v0y = p.y[b] - p.y[a];
  const v1x = p.x[c] - p.x[a];
  const v1y = p.y[c] - p.y[a];
  const v2x = x - p.x[a];
  const v2y = y - p.y[a];
  const den = v0x * v1y - v1x * v0y;
  if (Math.abs(den) < 1e-18) return null;
  const u = (v2x * v1y - v1x * v2y) / den;
  const v = (v0x * v2y - v2x * v0y) / den;
  if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) return null;
  return [1 - u - v, u, v];
}

function makeBroadPhase(kind: 'grid' | 'brute', cellSize: number): BroadPhase {
  if (kind === 'brute') return new BruteForceBroadPhase();
  const grid = new GridBroadPhase();
  grid.cellSize = cellSize;
  return grid;
}

function checkBounds(b: Bounds): Bounds {
  if (b == null || typeof b !== 'object') throw new TypeError(`bounds must be {minX, minY, maxX, maxY} or null, got ${String(b)}`);
  const out = { minX: finite('bounds.minX', b.minX), minY: finite('bounds.minY', b.minY), maxX: finite('bounds.maxX', b.maxX), maxY: finite('bounds.maxY', b.maxY) };
  if (!(out.minX < out.maxX && out.minY < out.maxY)) throw new RangeError(`bounds must have minX < maxX and minY < maxY, got ${JSON.stringify(b)}`);
  return out;
}
