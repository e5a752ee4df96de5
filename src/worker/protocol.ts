// What crosses the worker boundary: plain-data scene descriptions, the command interface (the same on the main thread
// and in the worker), and the layout of one published state frame (a Float64Array).
import type { BodyDescription, BodyKind, BodyType, Bounds, KernelChoice, WorldOptions } from '../engine/index.js';
import type { JointOptions, JointType, SubstepChoice } from '../engine/options.js';

/** A body as the host knows it: the element layer's numeric key plus the engine's plain-data description. */
export interface KeyedBody {
  key: number;
  desc: BodyDescription;
}

/**
 * A link between bodies, named by body keys. Each end attaches to a rigid body at the anchor point itself, to a body
 * built of particles at its particle nearest to the anchor, or (a joint without `b`) to the world.
 */
export type LinkDescription =
  | JointLink
  /** A damped Hooke spring (<physics-spring>): between particles an explicit force, with a rigid end an engine spring joint. */
  | { type: 'spring'; a: number; b: number; x?: number; y?: number; stiffness: number; damping?: number; length?: number }
  /**
   * Pins body `a` to the world point (x, y): its particle nearest to it (or `particle`, an index into the body); a
   * rigid body (without `particle`) by a revolute joint to the world at the point.
   */
  | { type: 'pin'; a: number; x: number; y: number; particle?: number; compliance?: number };

/**
 * <physics-joint>: an engine joint (World.addJoint) between body `a` and body `b`, or the world when `b` is absent.
 * Angles in radians, angular speeds in rad/s (the element converts its degrees).
 */
export interface JointLink extends Pick<JointOptions, JointSettings> {
  type: 'joint';
  /** Default 'distance' (a stick between the ends: the joint's meaning before it had types). */
  joint?: JointType;
  a: number;
  b?: number;
  /** The anchor (revolute, weld, prismatic; distance and spring: both ends, unless x1/y1, x2/y2 name them). */
  x?: number;
  y?: number;
  /** Distance and spring: the end on a, and the end on b. */
  x1?: number;
  y1?: number;
  x2?: number;
  y2?: number;
}

/** The joint settings a <physics-joint> passes on as World.addJoint takes them (documented there). */
type JointSettings = 'axis' | 'lowerAngle' | 'upperAngle' | 'motorSpeed' | 'maxMotorTorque' | 'lower' | 'upper' | 'length' | 'stiffness' | 'damping' | 'compliance' | 'collideConnected';

export interface KeyedLink {
  key: number;
  desc: LinkDescription;
}

/** Run-time parameters; every field optional in updates. */
export interface HostParams {
  gravity: { x: number; y: number };
  timestep: number;
  /** Substeps per step: a count, or 'auto' (the engine's choice by what moves: see WorldOptions.substeps). */
  substeps: SubstepChoice;
  iterations: number;
  broadphase: 'grid' | 'brute';
  narrowphase: 'sat' | 'gjk';
  /** Write AABBs, contacts and the grid cell size into frames. */
  debug: boolean;
  /** Send collision events (only while someone listens). */
  events: boolean;
  /** Walls and floor (the view's, or none): they follow the scene's width and height. */
  bounds: Bounds | null;
  /** The solver kernel the world is made with (World option `kernel`); a change remakes the world, keeping its state. */
  kernel: KernelChoice;
}

export interface HostScene {
  world: WorldOptions;
  params?: Partial<HostParams>;
  bodies: KeyedBody[];
  links: KeyedLink[];
  /** Start running at once (default false). */
  running?: boolean;
}

/** What the renderer needs to draw a body: its particles (storage indices) and its shape. */
export interface TopologyBody {
  key: number;
  type: BodyType;
  kind: BodyKind;
  indices: Int32Array;
  /** Cloth grid size. */
  columns?: number;
  rows?: number;
  /** Circles, rope thickness, ragdoll head: a drawing radius in world units. */
  radius?: number;
  /** Soft bodies of the springs model carry a hub particle after the ring. */
  ring?: number;
  /** Torn cloth: per grid node, bit 1 = the link to the right neighbour broke, bit 2 = the link down broke. */
  torn?: Uint8Array;
  /**
   * A rigid body (the engine's rigid model: one particle, its centre of mass): drawn from its pose, which a frame
   * gives as its centre of mass and its angle, with `outline` (a box or polygon) or `radius` (a disc) about it.
   */
  rigid?: boolean;
  /** A rigid body's outline x0, y0, x1, y1, … about its centre of mass, unturned (the polygon as described, not its convex parts). */
  outline?: Float64Array;
  /** A rigid body's centre of mass in its own coordinates: its origin (the x, y it was described at) is pose − R(angle)·center. */
  center?: [number, number];
}

/**
 * One end of a drawn link: a point fixed on a rigid body (`body` ≥ 0, its place in Topology.bodies; x, y about its
 * centre of mass, turning with it), a particle (`particle` ≥ 0, a storage index), or the world point (x, y).
 */
export interface LinkEnd {
  body: number;
  particle: number;
  x: number;
  y: number;
}

/** A link as drawn: a line between its ends; `pivot` (pins, revolute and weld joints): the ends are held together. */
export interface TopologyLink {
  a: LinkEnd;
  b: LinkEnd;
  pivot: boolean;
}

export interface Topology {
  version: number;
  bodies: TopologyBody[];
  /** Links in force (joints, springs, pins), for drawing. */
  links: TopologyLink[];
}

export type Transport = 'shared' | 'transfer' | 'direct';

export interface Diagnostics {
  /** True when the engine code runs inside a DedicatedWorkerGlobalScope. */
  inWorker: boolean;
  transport: Transport;
  crossOriginIsolated: boolean;
  running: boolean;
  stepCount: number;
  /**
   * Milliseconds a step takes in the running loop (the engine's step and reading what it left, not sending the
   * frame), averaged over about its last ten ticks; NaN before the loop has stepped. step(n) calls are not counted.
   */
  stepMs: number;
  /** The substeps the next step takes: the count asked for, or the engine's choice under 'auto' (World.substepCount). */
  substepCount: number;
  particleCount: number;
  bodyCount: number;
  linkCount: number;
  /** Distance links broken by tearing (a torn cloth's). */
  brokenLinks: number;
  /** Frames published, and frames skipped because every pooled transfer buffer was in flight. */
  published: number;
  skipped: number;
  /** Transfer buffers ever allocated (stays at the pool size in the steady state). */
  buffersAllocated: number;
  /** Whether collision events are collected and sent (only while someone listens). */
  events: boolean;
  /** Collision events sent so far. */
  eventsSent: number;
  /** The solver kernel that runs ('wasm': WebAssembly SIMD), the one asked for, and why WebAssembly does not run ('' when it does). */
  kernel: 'js' | 'wasm';
  kernelRequested: KernelChoice;
  kernelReason: string;
  /**
   * Bodies and particles the engine's step put back where they started a step, at rest, because the solver left them
   * not finite or running away (World.diagnostics().rowsRepaired): 0 unless joints tangle beyond what it resolves.
   */
  rowsRepaired: number;
}

export interface HostError {
  key: number;
  /** Best guess at the description field the engine complained about (e.g. "radius"), or "". */
  field: string;
  message: string;
  /** A call refused (applyImpulse, setVelocity), not a description: nothing of the element's markup to correct. */
  call?: string;
}

export interface HostSnapshot {
  world: unknown;
  bodies: { key: number; desc: BodyDescription; handle: number; pose: number[] }[];
  links: { key: number; desc: LinkDescription; handles: number[]; drawn: TopologyLink | null }[];
  params: HostParams;
  /** The host's topology version when taken (-1: a change not yet published), to match frames against it. */
  topology?: number;
}

/**
 * The newest published frame, laid over a restored snapshot after a worker restart: particle positions (x at 2·i,
 * y at 2·i+1), the bodies' poses (x, y, angle per body in topology order: rigid bodies take their angle from it) and,
 * when the two newest frames allow it, velocities and angular velocities (per body); applied only when the frame's
 * topology is the snapshot's (same particles in the same slots, same bodies in the same order).
 */
export interface FramePatch {
  topology: number;
  stepCount: number;
  time: number;
  positions: Float64Array;
  velocities: Float64Array | null;
  poses?: Float64Array;
  spins?: Float64Array | null;
}

/**
 * Internal test faults (not tagged internal: host/faults.ts's declarations name it): 'throw' makes the next tick of the
 * step loop throw, 'hang' blocks the worker (busy wait).
 */
export type DebugFault = 'throw' | 'hang';

/** The command interface of the engine host. Every call returns a promise on the client side. */
export interface EngineApi {
  load(scene: HostScene): HostError[];
  addBody(body: KeyedBody): HostError | null;
  updateBody(body: KeyedBody): HostError | null;
  removeBody(key: number): void;
  addLink(link: KeyedLink): HostError | null;
  updateLink(link: KeyedLink): HostError | null;
  removeLink(key: number): void;
  setParams(params: Partial<HostParams>): HostError | null;
  play(): void;
  pause(): void;
  /** Takes n fixed steps now (paused or not); returns the step count. */
  step(n?: number): number;
  /** Rebuilds the scene from the current descriptions (time 0). */
  reset(): void;
  grab(x: number, y: number, stiffness?: number): number | null;
  moveGrab(grab: number, x: number, y: number): void;
  release(grab: number): void;
  applyImpulse(key: number, ix: number, iy: number): HostError | null;
  setVelocity(key: number, vx: number, vy: number): HostError | null;
  snapshot(): HostSnapshot;
  /** Puts a snapshot back; with `frame` (a restart), the newest published positions and velocities on top. Returns the step count. */
  restore(snapshot: HostSnapshot, frame?: FramePatch | null): number;
  stateHash(): string;
  diagnostics(): Diagnostics;
  /** Bodies (keys) whose shape contains the point. */
  bodiesAt(x: number, y: number): number[];
  /** @internal Test hook (fault recovery tests): makes the engine fail on purpose. */
  debugFault(fault: DebugFault): void;
}

// ---- frame layout --------------------------------------------------------------------------------------------

/** Header slots of a frame (Float64Array). */
export const F = {
  seq: 0,
  topology: 1,
  stepCount: 2,
  time: 3,
  particles: 4,
  bodies: 5,
  contacts: 6,
  debug: 7,
  cellSize: 8,
  running: 9,
  /** performance.now() of the publisher when the frame was written (worker clock). */
  stamp: 10,
  links: 11,
  /**
   * Collision events sent before this frame. In shared mode a frame can be read before the events message sent ahead
   * of it arrives: a reader that needs a step's events waits until it has received this many.
   */
  eventsSent: 12,
} as const;
export const HEADER = 16;
/** Pose per body: x, y, angle (radians). */
export const POSE = 3;
/** Debug: AABB per body (minX, minY, maxX, maxY), contact point and normal (x, y, nx, ny). */
export const AABB = 4;
export const CONTACT = 4;
export const MAX_CONTACTS = 1024;

/** Floats needed for a frame. */
export function frameLength(particles: number, bodies: number, contacts: number, debug: boolean): number {
  return HEADER + 2 * particles + POSE * bodies + (debug ? AABB * bodies + CONTACT * contacts : 0);
}

export function poseOffset(particles: number): number {
  return HEADER + 2 * particles;
}
export function aabbOffset(particles: number, bodies: number): number {
  return HEADER + 2 * particles + POSE * bodies;
}
export function contactOffset(particles: number, bodies: number): number {
  return HEADER + 2 * particles + POSE * bodies + AABB * bodies;
}

/** Collision events: [type (0 begin, 1 end), keyA, keyB, normalX, normalY, depth, speed] per event. */
export const EVENT = 7;

/** Messages on the frame port (worker → page). */
export type PortMessage =
  | { type: 'frame'; buffer: ArrayBuffer }
  | { type: 'shared'; buffer: SharedArrayBuffer }
  | { type: 'topology'; topology: Topology }
  | { type: 'events'; data: Float64Array; count: number };
/** Page → worker: a transfer buffer handed back to the pool. */
export type ReturnMessage = { type: 'recycle'; buffer: ArrayBuffer };
