import { HandleRegistry } from '../handles.js';
import { ParticleStore } from '../particles.js';
import { grown } from '../table.js';
import { ConstraintRegistry } from '../constraint-registry.js';
import { BodyRegistry } from '../body-registry.js';
import type { StepSettings } from '../settings.js';
import { Colliders } from './colliders.js';
import { PairList, type BroadPhase } from './broadphase.js';
import { NarrowPhase } from './narrowphase.js';
import { AnchorCache, Contacts } from './contacts.js';
import { Sleep } from './sleep.js';
import { FreeSpin } from './spin.js';
import { KeyTable } from './key-table.js';
import { CollisionEvents, EventTracker } from './events.js';
import { shouldCollide } from './collide.js';
import { RigidNarrowPhase } from './rigid-narrowphase.js';
import { RigidAnchorCache, RigidContacts } from '../rigid/contacts.js';
import { RigidShapes } from '../rigid/shapes.js';
import { WallHits } from '../bounds.js';
import { FrameBounces } from './frame-bounces.js';
import { chooseKernel, type KernelDiagnostics } from '../kernel/choice.js';
import type { WasmKernel } from '../kernel/wasm-kernel.js';

/**
 * Everything a step works on: the particles, the constraint tables and the bodies (with their handle registries),
 * the collision state (colliders, candidate pairs, contacts, broad and narrow phase), sleep, events, the settings and
 * the clock. The World is a facade over one context; the step's phases are plain functions of it. What of it a
 * snapshot holds and what is rebuilt is listed in snapshot.ts (a test keeps that list complete).
 */
export class StepContext {
  /** Simulated seconds and steps taken. */
  time = 0;
  stepCount = 0;
  /** Real time not yet stepped (advance()), and its fraction of a step (for interpolated rendering). */
  accumulator = 0;
  alpha = 0;
  /** Rows the step's guard put back since the world was made (pipeline/guard.ts; World.diagnostics()). */
  rowsRepaired = 0;

  readonly particles = new ParticleStore();
  readonly particleIds = new HandleRegistry('particle', 'particles');
  readonly constraints = new ConstraintRegistry();
  readonly bodies = new BodyRegistry();

  /** Collision state: per body slot colliders, this step's candidate pairs and contacts. */
  readonly colliders = new Colliders();
  readonly pairs = new PairList();
  readonly contacts = new Contacts();
  readonly narrowPhase = new NarrowPhase();
  /** Friction anchors of last step's contacts, by feature. */
  readonly anchors = new AnchorCache();
  /** Per body slot: how far the body may move this step (speculative margin). */
  motion = new Float64Array(16);

  /** Rigid bodies: their shapes (per body slot), this step's contact points, and the narrow phase that finds them. */
  readonly rigidShapes = new RigidShapes();
  readonly rigidContacts = new RigidContacts();
  /** The particles the world's bounds pushed back in the current substep, for their bounces. */
  readonly wallHits = new WallHits();
  /** The current substep's bounces, solved again for the particle frames in them (frame-bounces.ts). */
  readonly frameBounces = new FrameBounces();
  /** This step's gravity and substep: [gx, gy, h, h/2 under position Verlet or 0] (impact.ts); the rigid contacts' own. */
  readonly substepMotion = this.rigidContacts.motion;
  readonly rigidNarrowPhase = new RigidNarrowPhase();
  /** Friction anchors of last step's rigid contact points, by feature. */
  readonly rigidAnchors = new RigidAnchorCache();
  /** Reals handed to per-body calls (a typed array: no boxed doubles per call): the substep's length and damping
   *  factor for the rigid phases; the step's length and gravity's reach while bounding boxes are grown. */
  readonly substepReals = new Float64Array(2);
  /** Body pairs joined by a joint that does not let them collide (rebuilt with the topology). */
  readonly jointedPairs = new KeyTable();
  /** Per body slot: 1 when a joint keeps it from colliding with another body (a static one then hides no seams). */
  jointedApart = new Uint8Array(16);
  /** Rows of the rigid bodies that turn (dynamic and kinematic), and of the kinematic ones (rebuilt with the topology). */
  rigidRows = new Int32Array(16);
  rigidCount = 0;
  kinematicRows = new Int32Array(16);
  kinematicCount = 0;

  readonly sleep = new Sleep();
  /** Bodies of particles that keep their angular momentum through a step nothing outside acts on them (spin.ts). */
  readonly freeSpin = new FreeSpin();
  /** Begin/end collision events of the last step. */
  readonly events = new CollisionEvents();
  readonly eventTracker = new EventTracker();
  /** Handles of the distance constraints that broke in the last step. */
  readonly breaks = { count: 0, handles: new Float64Array(16) };
  /** Some distance constraint can break (a step checks for tearing only then). */
  hasBreakableLinks = false;

  /** Bodies or constraints changed: the sleep bookkeeping needs rebuilding. */
  topologyDirty = true;
  /** Colliders changed: their parts and the active list need rebuilding. */
  collidersDirty = false;
  /** Movable particles that belong to no body (they never sleep). */
  freeMovableParticles = 0;
  /** A pin of a particle that belongs to no body was moved: the next step runs, settled or not. */
  pinMoved = false;
  /** Movable rows that are not rigid bodies (particles of any body or none): 'auto' substeps depend on it. */
  particleRows = 0;

  /** When true, each step records how long collision detection and the substeps took (ms) in `timings`. */
  measureTimings = false;
  readonly timings = { detect: 0, solve: 0 };

  // Callbacks made once, so that the step passes them without allocating.
  readonly acceptPair = (a: number, b: number): boolean => shouldCollide(this, a, b);
  readonly recordBreak = (row: number): void => {
    const b = this.breaks;
    if (b.count === b.handles.length) b.handles = grown(b.handles, b.count * 2);
    b.handles[b.count++] = this.constraints.ids.handleOf(this.constraints.distances.slot[row]);
  };
  readonly bodyHandleOf = (slot: number): number => this.bodies.ids.handleOf(slot);
  readonly bodyAlive = (slot: number): boolean => this.bodies.ids.alive[slot] === 1;
  /** Asleep, or static: a body that makes no contacts while it rests (collision events keep its pairs). */
  readonly bodyResting = (slot: number): boolean => this.sleep.asleep[slot] === 1 || this.colliders.isStatic[slot] === 1;
  readonly bodyParticlesOf = (slot: number): Int32Array => this.bodies.particles[slot];

  /** The WebAssembly SIMD kernel when it runs (null: the JS loops), and what World.diagnostics() says about it. */
  declare readonly kernel: WasmKernel | null;
  declare readonly kernelDiagnostics: KernelDiagnostics;

  constructor(
    readonly settings: StepSettings,
    public broadPhase: BroadPhase,
    kernel?: unknown,
  ) {
    const chosen = chooseKernel(kernel);
    // Not enumerable: how the step computes, chosen once, not simulation state (snapshot.ts lists the state fields).
    Object.defineProperties(this, { kernel: { value: chosen.kernel }, kernelDiagnostics: { value: chosen.diagnostics } });
  }
}
