// Argument checks for the public JS API. Every error names the argument and the value it got, so a bad call is
// caught where it is made and never reaches the state as NaN.

function show(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number' || typeof value === 'boolean' || value == null) return String(value);
  if (typeof value === 'bigint') return `${value}n`;
  try {
    return JSON.stringify(value) ?? String(value);
  } catch {
    return Object.prototype.toString.call(value);
  }
}

/** A finite number (not NaN, not ±Infinity). */
export function finite(name: string, value: unknown): number {
  if (typeof value !== 'number') throw new TypeError(`${name} must be a number, got ${show(value)}`);
  if (!Number.isFinite(value)) throw new RangeError(`${name} must be a finite number, got ${show(value)}`);
  return value;
}

/** An angle in radians, within ±1e9: beyond, rounding eats a substep's turn (at 1e16 a spinning body stood still). */
export function angleOf(name: string, value: unknown): number {
  const v = finite(name, value);
  if (v > MAX_WORLD_COORDINATE || v < -MAX_WORLD_COORDINATE) throw new RangeError(`${name} must be within ±1e9 radians (beyond, rounding eats a body's turn), got ${show(value)}`);
  return v;
}

/**
 * The largest magnitude of a coordinate in world units: a position, anchor, length or size. Beyond it a double no
 * longer holds the detail a step needs (its spacing at 1e9 is 1.2e-7 units, at 1e12 1.2e-4): the same jointed
 * pendulum moved to (1e9, 1e9) ends 2 s later within 3e-4 units of where it ends at the origin, at 1e10 2e-2 off, at
 * 1e12 0.9 off (and 23% faster), at 1e13 it never moves. The collision functions (collision/shape.ts) allow more:
 * they only need products of coordinates to stay finite.
 */
export const MAX_WORLD_COORDINATE = 1e9;

/** A finite number within ±MAX_WORLD_COORDINATE (a position, anchor, length or size in world units). */
export function coordinate(name: string, value: unknown): number {
  const v = finite(name, value);
  if (v > MAX_WORLD_COORDINATE || v < -MAX_WORLD_COORDINATE) {
    throw new RangeError(`${name} must be within ±1e9 (world units; beyond, positions lose the precision a step needs), got ${show(value)}`);
  }
  return v;
}

/**
 * The largest speed a body may be given, in world units (or radians) a second: at it a body crosses the whole
 * coordinate range (±MAX_WORLD_COORDINATE) in two seconds. Far beyond, one step puts it where a double has no detail
 * left, and a speed near the largest double overflows to Infinity on the way (then NaN).
 */
export const MAX_SPEED = 1e9;

/** A finite speed (a velocity component, or one an impulse adds) within ±MAX_SPEED. */
export function speed(name: string, value: unknown): number {
  return withinMaxSpeed(name, value, 'give a speed within ±1e9 (world units or radians per second)');
}

/**
 * A gravity component, within ±MAX_SPEED a second per second: a body falls at most MAX_SPEED faster each second (a
 * larger one overflows a step's bounding boxes and positions to Infinity).
 */
export function acceleration(name: string, value: unknown): number {
  return withinMaxSpeed(name, value, 'be within ±1e9 (world units per second²)');
}

function withinMaxSpeed(name: string, value: unknown, rule: string): number {
  const v = finite(name, value);
  if (v > MAX_SPEED || v < -MAX_SPEED) throw new RangeError(`${name} must ${rule}, got ${show(value)}`);
  return v;
}

/** What the speed checks of an impulse (the velocity it leaves), and of the forces over a step, call their components. */
export const IMPULSE_SPEED = ['vx + ix / mass', 'vy + iy / mass'] as const;
export const FORCE_SPEED = ['fx · timestep / mass (with the forces given since the last step)', 'fy · timestep / mass (with the forces given since the last step)'] as const;

/**
 * The velocity a push (jx, jy) leaves a body of inverse mass `invMass`, each component within ±MAX_SPEED: (vx, vy) +
 * (jx, jy) · invMass · seconds, where (vx, vy) is its velocity now (an impulse, `seconds` 1) or the speed the step's
 * earlier forces add (a force, over `seconds`): pushes add up, so the limit counts what they add together.
 * names[k] names component k ('vx + ix / mass').
 */
export function pushSpeed(names: readonly [string, string], jx: number, jy: number, invMass: number, seconds = 1, vx = 0, vy = 0): void {
  pushedSpeed(names[0], vx, vx + jx * invMass * seconds);
  pushedSpeed(names[1], vy, vy + jy * invMass * seconds);
}

/**
 * A speed component a push takes from `before` to `after`: refused past ±MAX_SPEED only when the push makes it
 * larger (a body already past the limit may still be slowed, or pushed along another axis).
 */
export function pushedSpeed(name: string, before: number, after: number): void {
  if (!(Math.abs(after) <= MAX_SPEED || Math.abs(after) <= Math.abs(before))) speed(name, after);
}

/** A finite number > 0. */
export function positive(name: string, value: unknown): number {
  const v = finite(name, value);
  if (!(v > 0)) throw new RangeError(`${name} must be > 0, got ${show(value)}`);
  return v;
}

/**
 * The softest compliance a constraint may have (world units per unit of force): softer than anything a step can show,
 * and beyond it compliance / h² (h down to 1e-9 s) overflows to Infinity in the solver, and the state to NaN.
 */
export const MAX_COMPLIANCE = 1e9;

/** The largest `pressure` of an area constraint (a multiple of the rest area): beyond, areas overflow. */
export const MAX_PRESSURE = 1e6;

/** A compliance: a number from 0 (rigid) to MAX_COMPLIANCE. */
export function compliance(name: string, value: unknown): number {
  const v = nonNegative(name, value);
  if (v > MAX_COMPLIANCE) throw new RangeError(`${name} must be from 0 (rigid) to 1e9 (softer than anything a step shows), got ${show(value)}`);
  return v;
}

/** A stiffness the solver turns into the compliance 1/stiffness: at least 1/MAX_COMPLIANCE. */
export function stiffness(name: string, value: unknown): number {
  const v = positive(name, value);
  if (v < 1 / MAX_COMPLIANCE) throw new RangeError(`${name} must be at least 1e-9 (its compliance 1/${name} at most 1e9), got ${show(value)}`);
  return v;
}

/**
 * The lightest a movable particle or body may be: its inverse mass (and a rigid body's inverse inertia, at most
 * 1/MIN_INERTIA) must stay far from overflowing, or one step makes its state NaN.
 */
export const MIN_MASS = 1e-12;
export const MIN_INERTIA = 1e-30;

/** A mass of a movable particle or body: a finite number of at least MIN_MASS (`from`: how it was found, if not given). */
export function mass(name: string, value: unknown, from = ''): number {
  const v = finite(name, value);
  if (!(v >= MIN_MASS)) throw new RangeError(`${name} must be at least 1e-12${from ? `; ${from} gives` : ', got'} ${show(value)}`);
  return v;
}

/** true or false (a string such as "false" is a TypeError, not a truthy value). */
export function flag(name: string, value: unknown): boolean {
  if (typeof value !== 'boolean') throw new TypeError(`${name} must be true or false, got ${show(value)}`);
  return value;
}

/**
 * The longest step World.step() takes, and the longest `timestep`, in seconds: its substeps would be too long for any
 * contact or link to hold.
 */
export const MAX_STEP_SECONDS = 1;

/**
 * The shortest step World.step() takes, and the shortest `timestep`, in seconds (a microsecond): a shorter one's
 * substeps make 1/h and compliance/h² overflow to Infinity, and the state NaN. variableStep's advance() gathers
 * shorter elapsed times until they make one.
 */
export const MIN_STEP_SECONDS = 1e-6;

/** A finite number >= 0. */
export function nonNegative(name: string, value: unknown): number {
  const v = finite(name, value);
  if (!(v >= 0)) throw new RangeError(`${name} must be >= 0, got ${show(value)}`);
  return v;
}

/** A number >= 0 that may be +Infinity (an open upper limit). */
export function nonNegativeOrInfinity(name: string, value: unknown): number {
  if (value === Infinity) return Infinity;
  return nonNegative(name, value);
}

/** A whole number in [min, max]. */
export function integer(name: string, value: unknown, min: number, max = Number.MAX_SAFE_INTEGER): number {
  const v = finite(name, value);
  if (!Number.isInteger(v) || v < min || v > max) {
    throw new RangeError(`${name} must be a whole number from ${min} to ${max}, got ${show(value)}`);
  }
  return v;
}

/** A number in [0, 1]. */
export function unit(name: string, value: unknown): number {
  const v = finite(name, value);
  if (v < 0 || v > 1) throw new RangeError(`${name} must be between 0 and 1, got ${show(value)}`);
  return v;
}

/** One of a fixed set of strings. */
export function oneOf<T extends string>(name: string, value: unknown, allowed: readonly T[]): T {
  if (typeof value !== 'string' || !(allowed as readonly string[]).includes(value)) {
    throw new RangeError(`${name} must be one of ${allowed.map((a) => `"${a}"`).join(', ')}, got ${show(value)}`);
  }
  return value as T;
}

export { show as describeValue };

/** Levenshtein distance: single-character insertions, deletions and substitutions. */
export function editDistance(a: string, b: string): number {
  let row = Array.from({ length: b.length + 1 }, (_, j) => j);
  for (let i = 1; i <= a.length; i++) {
    const next = [i];
    for (let j = 1; j <= b.length; j++) next.push(Math.min(row[j] + 1, next[j - 1] + 1, row[j - 1] + (a[i - 1] === b[j - 1] ? 0 : 1)));
    row = next;
  }
  return row[b.length];
}

/** The name among `names` nearest to `name` by edit distance, and that distance ('' and Infinity for no names). */
export function nearestName(name: string, names: Iterable<string>): { nearest: string; distance: number } {
  let nearest = '';
  let distance = Infinity;
  for (const candidate of names) {
    const d = editDistance(name, candidate);
    if (d < distance) [nearest, distance] = [candidate, d];
  }
  return { nearest, distance };
}

/**
 * Throws a TypeError for the first key of `options` that is not in `known` (`what` names the object: "World option"),
 * with the known name it most likely meant when one is within two edits. Plain JS has no type check to catch
 * `{ substepz: 3 }`, which would otherwise be ignored in silence.
 */
export function knownOptions(what: string, options: object, known: readonly string[]): void {
  for (const name of Object.keys(options)) {
    if (known.includes(name)) continue;
    const { nearest, distance } = nearestName(name, known);
    const hint = distance <= 2 ? ` (did you mean ${nearest}?)` : '';
    throw new TypeError(`unknown ${what} ${JSON.stringify(name)}${hint}: the ${what}s are ${known.join(', ')}`);
  }
}

/**
 * knownOptions() for the calls a builder makes thousands of times (addParticle, addDistance): the names as an object's
 * keys, looked up without making a list of the options' names; the message is knownOptions()'s.
 */
export function knownNames(what: string, options: object, known: Readonly<Record<string, true>>): void {
  for (const name in options) if (known[name] !== true) knownOptions(what, { [name]: true }, Object.keys(known));
}

/** An options argument: an object, or a TypeError naming it and what it was. */
export function objectOf<T>(what: string, value: T): T & object {
  if (value == null || typeof value !== 'object') throw new TypeError(`${what} must be an object, got ${show(value)}`);
  return value as T & object;
}
