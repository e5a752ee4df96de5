// The options and results of the World's public API, and the checks of the options that several modules share.
import type { Bounds } from './bounds.js';
import type { Handle } from './handles.js';
import type { Integrator } from './integrate.js';
import { coordinate, finite, integer, nonNegative, oneOf } from './validate.js';

export interface Vec2 {
  x: number;
  y: number;
}

/** A substep count, or 'auto': chosen per step by what the world holds (see WorldOptions.substeps). */
export type SubstepChoice = number | 'auto';

/**
 * The World's settings, each also a property to change later. `new World()` and `buildScene({ world })` take
 * `WorldOptions & KernelOptions`: the kernel is chosen at construction only, so a variable that holds it too is typed
 * `const options: WorldOptions & KernelOptions = { kernel: 'wasm', substeps: 8 }`.
 */
export interface WorldOptions {
  /** Acceleration of gravity. Default {x: 0, y: 9.81}: y grows downward, as on a canvas or in SVG. */
  gravity?: Vec2;
  /** The fixed step in seconds. Default 1/60. */
  timestep?: number;
  /**
   * Substeps per step: a count, or 'auto' (default): 6 when every body that moves is a rigid body, 10 when particles,
   * ropes, cloth, soft bodies, ragdolls or particle-built frames move (substeps buy more stiffness per cost than
   * iterations; rigid contacts need fewer). World.substepCount reads the count the next step takes.
   */
  substeps?: SubstepChoice;
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
  /** Rate (per second) at which the loop's deformation dies out: its motion apart from moving and turning as one. Default 0. */
  damping?: number;
}

/** Material and filtering of a rigid body (as ColliderOptions, without the particle-based shapes). */
export type RigidMaterial = Omit<ColliderOptions, 'shape' | 'parts'>;

/** A rigid body: a shape (an outline or a disc) with a pose, velocities, a type and a material. */
export interface RigidBodyOptions extends RigidMaterial {
  /** Outline in body coordinates, any simple polygon (a concave one collides as convex parts). Give points, radius or outlines. */
  points?: Vec2[];
  /** A disc of this radius about the body's origin. */
  radius?: number;
  /** Several outlines making one body (a drum's wall, a table), instead of points or radius. */
  outlines?: Vec2[][];
  /** Where the body's origin goes, and its rotation (radians). */
  x: number;
  y: number;
  angle?: number;
  /** Velocity of the centre of mass, and angular velocity (rad/s, positive turns x toward y). */
  vx?: number;
  vy?: number;
  angularVelocity?: number;
  /** 'dynamic' (default), 'static' or 'kinematic' (moved by its velocities only). */
  type?: 'dynamic' | 'static' | 'kinematic';
  /** Mass per unit area (default 1), or the total `mass` instead. */
  density?: number;
  mass?: number;
  /** False: the body collides with nothing. Default true. */
  collide?: boolean;
}

/** A body's origin and angle. */
export interface Pose {
  x: number;
  y: number;
  angle: number;
}

/** What a rigid body moves with: mass, moment of inertia about the centre of mass, and where that centre is. */
export interface MassInfo {
  mass: number;
  inertia: number;
  centerX: number;
  centerY: number;
}

export type JointType = 'revolute' | 'weld' | 'prismatic' | 'distance' | 'spring';
export const JOINT_TYPES: readonly JointType[] = ['revolute', 'weld', 'prismatic', 'distance', 'spring'];

/**
 * A joint between two bodies (or a body and the world) at anchor points given in world coordinates where the bodies
 * are now. Either side may be a particle instead (`particleA`, `particleB`): a rope's end, a cloth's corner.
 */
export interface JointOptions {
  type: JointType;
  /** A rigid body (or a body of one particle). */
  a?: Handle;
  /** The other body; omitted or null: the world. */
  b?: Handle | null;
  particleA?: Handle;
  particleB?: Handle;
  /** Where the bodies are joined (revolute, weld, prismatic). Default: A's centre of mass. */
  anchor?: Vec2;
  /** Each side's anchor (distance, spring). Default: `anchor`, else each body's centre. */
  anchorA?: Vec2;
  anchorB?: Vec2;
  /** Prismatic: the direction B slides along, in world coordinates now (it turns with A, or with B where B is the world, a static or a kinematic body). Default (1, 0). */
  axis?: Vec2;
  /** Revolute: limits of A's angle relative to B (the world's angle is 0), from where they are now (radians). */
  lowerAngle?: number;
  upperAngle?: number;
  /** Revolute: a motor turning A relative to B at this speed (rad/s, positive turns x toward y), with at most `maxMotorTorque`. */
  motorSpeed?: number;
  maxMotorTorque?: number;
  /** Prismatic: translation limits along the axis; distance: length limits (a rope: lower 0). */
  lower?: number;
  upper?: number;
  /** Distance and spring: rest length (default the anchors' distance now). */
  length?: number;
  /** Spring: stiffness k (force per unit of stretch) and damping c (force per unit of stretch speed). */
  stiffness?: number;
  damping?: number;
  /** Softness of the point or distance constraint (inverse stiffness); 0 = rigid (default). */
  compliance?: number;
  /** Whether the two joined bodies still collide with each other. Default false. */
  collideConnected?: boolean;
}

export type BodyKind = 'particle' | 'rope' | 'cloth' | 'rigid' | 'soft' | 'ragdoll' | 'custom';
export const BODY_KINDS: readonly BodyKind[] = ['particle', 'rope', 'cloth', 'rigid', 'soft', 'ragdoll', 'custom'];

export type ConstraintKind = 'distance' | 'angle' | 'pin' | 'spring' | 'area' | 'grab' | 'joint';
/** In the order of the constraint registry's tables (see Kind in constraint-registry.ts). */
export const CONSTRAINT_KINDS: readonly ConstraintKind[] = ['distance', 'angle', 'pin', 'spring', 'area', 'grab', 'joint'];

/** A collider's options checked and completed with their defaults (parts as given: indices into the body's particles). */
export type ResolvedCollider = Required<Omit<ColliderOptions, 'parts'>> & { parts?: number[][] };

/** Checks collider options for a body of `particleCount` particles and fills in the defaults. */
export function resolveCollider(o: ColliderOptions, particleCount: number): ResolvedCollider {
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

export function checkBounds(b: Bounds): Bounds {
  if (b == null || typeof b !== 'object') throw new TypeError(`bounds must be {minX, minY, maxX, maxY} or null, got ${String(b)}`);
  const out = { minX: coordinate('bounds.minX', b.minX), minY: coordinate('bounds.minY', b.minY), maxX: coordinate('bounds.maxX', b.maxX), maxY: coordinate('bounds.maxY', b.maxY) };
  if (!(out.minX < out.maxX && out.minY < out.maxY)) throw new RangeError(`bounds must have minX < maxX and minY < maxY, got ${JSON.stringify(b)}`);
  return out;
}

/**
 * The names each options object of the World's methods takes (the compiler holds each list to its type), so that a
 * misspelt name is a TypeError naming it (validate.ts knownNames) instead of an option silently ignored.
 */
export const OPTION_NAMES = {
  particle: { x: true, y: true, mass: true, radius: true, vx: true, vy: true } satisfies Record<keyof ParticleOptions, true>,
  distance: { length: true, minLength: true, maxLength: true, compliance: true, breakStrain: true } satisfies Record<keyof DistanceOptions, true>,
  angle: { min: true, max: true, compliance: true } satisfies Record<keyof AngleOptions, true>,
  spring: { length: true, stiffness: true, damping: true } satisfies Record<keyof SpringOptions, true>,
  pin: { x: true, y: true, compliance: true } satisfies Record<keyof PinOptions, true>,
  area: { pressure: true, compliance: true, damping: true } satisfies Record<keyof AreaOptions, true>,
  grab: { stiffness: true, pickRadius: true } satisfies Record<keyof GrabOptions, true>,
  collider: { shape: true, parts: true, friction: true, restitution: true, category: true, mask: true, group: true } satisfies Record<keyof ColliderOptions, true>,
  rigidBody: {
    points: true, radius: true, outlines: true, x: true, y: true, angle: true, vx: true, vy: true, angularVelocity: true, type: true,
    density: true, mass: true, collide: true, friction: true, restitution: true, category: true, mask: true, group: true,
  } satisfies Record<keyof RigidBodyOptions, true>,
  joint: {
    type: true, a: true, b: true, particleA: true, particleB: true, anchor: true, anchorA: true, anchorB: true, axis: true, lowerAngle: true,
    upperAngle: true, motorSpeed: true, maxMotorTorque: true, lower: true, upper: true, length: true, stiffness: true, damping: true,
    compliance: true, collideConnected: true,
  } satisfies Record<keyof JointOptions, true>,
};
