import type { ColliderOptions, Handle, Vec2, World } from '../world.js';
import { compliance, coordinate, describeValue, flag, knownNames, mass, objectOf, positive } from '../validate.js';
import { resolveCollider } from '../options.js';

/** What every builder returns: the body and the handles of what it made. */
export interface Built {
  body: Handle;
  particles: Handle[];
  constraints: Handle[];
}

export function point(name: string, p: unknown): Vec2 {
  if (p == null || typeof p !== 'object') throw new TypeError(`${name} must be a point {x, y}, got ${String(p)}`);
  const v = p as Vec2;
  return { x: coordinate(`${name}.x`, v.x), y: coordinate(`${name}.y`, v.y) };
}

/** How a box, polygon or circle is made: a true rigid body, or a frame of particles and sticks (the thesis' model). */
export type BodyModel = 'rigid' | 'particles';
export const BODY_MODELS: readonly BodyModel[] = ['rigid', 'particles'];

/** Collision and material options every builder takes. */
export interface BodyOptions {
  /** Immovable: every particle gets infinite mass (walls, floors, obstacles). Default false. */
  static?: boolean;
  /** Whether the body collides (defaults differ per builder). */
  collide?: boolean;
  friction?: number;
  restitution?: number;
  category?: number;
  mask?: number;
  group?: number;
}

/**
 * The option names every builder takes. Each builder's record of names (`satisfies Record<keyof T, true>`) holds it
 * to its options type, as OPTION_NAMES does for the World's methods.
 */
export const BODY_OPTIONS = { static: true, collide: true, friction: true, restitution: true, category: true, mask: true, group: true } satisfies Record<keyof BodyOptions, true>;

/**
 * A builder's options: an object whose every name the builder takes. A misspelt or foreign name (`density` for a box,
 * which takes `mass`) is a TypeError naming it, as `new World()` does, instead of an option silently ignored.
 */
export function builderOptions<T>(world: World, what: string, o: T, names: Readonly<Record<string, true>>): T & object {
  if (world == null || typeof (world as Partial<World>).addParticle !== 'function') throw new TypeError(`a builder needs the World to build in first, got ${describeValue(world)}`);
  knownNames(`${what} option`, objectOf(`${what} options`, o), names);
  // The options the body is made with last (its collider, true/false switches) are checked before anything is made,
  // so a bad one leaves the world as it was, not a row or a handle spent.
  const b = o as BodyOptions & Record<string, unknown>;
  resolveCollider({ shape: 'none', friction: b.friction, restitution: b.restitution, category: b.category, mask: b.mask, group: b.group }, 0);
  for (const name of SWITCHES) if (b[name] !== undefined) flag(name, b[name]);
  return o as T & object;
}

/** The builders' true/false options. */
const SWITCHES = ['static', 'collide', 'kinematic', 'pinStart', 'pinEnd', 'ropeLike', 'tethers'] as const;

/** The collision options of a body's options, passed on as they are (a box's frame, a rigid body). */
export function collisionOptions(o: BodyOptions): Pick<BodyOptions, 'collide' | 'friction' | 'restitution' | 'category' | 'mask' | 'group'> {
  return { collide: o.collide, friction: o.friction, restitution: o.restitution, category: o.category, mask: o.mask, group: o.group };
}

/** The collider a builder asks for, from the body options and its default shape. */
export function colliderOf(o: BodyOptions, shape: 'polygon' | 'particles', collideByDefault: boolean, parts?: number[][]): ColliderOptions {
  const collide = o.collide ?? collideByDefault;
  return {
    shape: collide ? shape : 'none',
    parts,
    friction: o.friction,
    restitution: o.restitution,
    category: o.category,
    mask: o.mask,
    group: o.group,
  };
}

/** Per-particle mass from a total mass spread over n particles (`fallback`, found as `from` says, when not given). */
export function massEach(name: string, total: number | undefined, n: number, fallback: number, from: string): number {
  // Each particle must be heavy enough that its inverse mass stays finite.
  return mass(`${name} / ${n} particles`, (total === undefined ? fallback : positive(name, total)) / n, total === undefined ? `its default (${from})` : '');
}

/** A builder's compliance option (default 0: rigid), checked as the World's are. */
export function complianceOf(name: string, value: number | undefined): number {
  return compliance(name, value ?? 0);
}

/** Runs `make` and removes what it made if it throws, so a failed build leaves the world untouched. */
export function transactional(world: World, make: (particles: Handle[], constraints: Handle[]) => Handle): Built {
  const particles: Handle[] = [];
  const constraints: Handle[] = [];
  // The body is registered last: a full registry is found before its particles are made.
  world.ensureBodyRoom();
  try {
    const body = make(particles, constraints);
    return { body, particles, constraints };
  } catch (error) {
    for (const c of constraints) if (world.hasConstraint(c)) world.removeConstraint(c);
    for (const p of particles) if (world.hasParticle(p)) world.removeParticle(p);
    throw error;
  }
}

/**
 * Long-range attachments (Kim, Chentanez and Müller 2012): each free particle gets a unilateral link to its nearest
 * pinned particle, no longer than their rest distance along the body. An inextensible rope or cloth can never be
 * farther from its anchor than that, so the link is exact physics; it stops the stretch that Gauss–Seidel leaves
 * in long hanging chains, at the cost of one cheap, mostly inactive constraint per particle.
 */
export function addTethers(
  world: World,
  particles: Handle[],
  pinned: number[],
  restDistance: (from: number, to: number) => number,
  constraints: Handle[],
): void {
  if (pinned.length === 0) return;
  const isPinned = new Set(pinned);
  for (let k = 0; k < particles.length; k++) {
    if (isPinned.has(k)) continue;
    let anchor = pinned[0];
    let best = Infinity;
    for (const p of pinned) {
      const d = restDistance(p, k);
      if (d < best) {
        best = d;
        anchor = p;
      }
    }
    constraints.push(world.addDistance(particles[anchor], particles[k], { minLength: 0, maxLength: best }));
  }
}
