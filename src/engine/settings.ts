// The world's settings as the step reads them, their defaults and their checks (shared by the World's constructor,
// its setters and restore(), so a setting is validated the same way wherever it comes from).
import type { Bounds } from './bounds.js';
import { INTEGRATORS, verletHalfSubstep, type Integrator } from './integrate.js';
import { checkBounds, type SubstepChoice, type Vec2, type WorldOptions } from './options.js';
import { acceleration, describeValue, flag, integer, MAX_STEP_SECONDS, MIN_STEP_SECONDS, nonNegative, oneOf, positive } from './validate.js';

/** See WorldOptions for what each setting does. */
export interface StepSettings {
  gravity: Vec2;
  timestep: number;
  substeps: SubstepChoice;
  iterations: number;
  damping: number;
  integrator: Integrator;
  bounds: Bounds | null;
  boundsFriction: number;
  maxCatchUpSteps: number;
  variableStep: boolean;
  contactSlop: number;
  maxPushSpeed: number;
}

/** Every option's default (limits: DEFAULT_LIMITS). */
export const DEFAULTS: Required<Omit<WorldOptions, 'limits'>> = {
  gravity: { x: 0, y: 9.81 },
  timestep: 1 / 60,
  substeps: 'auto',
  iterations: 1,
  damping: 0,
  integrator: 'verlet',
  bounds: null,
  boundsFriction: 0.5,
  maxCatchUpSteps: 5,
  variableStep: false,
  broadphase: 'grid',
  narrowphase: 'sat',
  cellSize: 0,
  contactSlop: 0.02,
  sleeping: true,
  maxPushSpeed: 4,
};

export const BROAD_PHASES = ['grid', 'brute'] as const;
export const NARROW_PHASES = ['sat', 'gjk'] as const;

export { MAX_STEP_SECONDS, MIN_STEP_SECONDS } from './validate.js';

/** A step's length in seconds, from MIN_STEP_SECONDS to MAX_STEP_SECONDS (`name`: what the caller calls it). */
export function stepLength(name: string, v: unknown, hint = ''): number {
  const seconds = positive(name, v);
  if (seconds < MIN_STEP_SECONDS || seconds > MAX_STEP_SECONDS) {
    throw new RangeError(`${name} must be from 1e-6 to ${MAX_STEP_SECONDS} (seconds), got ${describeValue(v)}${hint}`);
  }
  return seconds;
}

/** Each setting's check: returns the value to store or throws a TypeError/RangeError naming the setting. */
export const CHECK: { readonly [K in keyof StepSettings]: (value: StepSettings[K]) => StepSettings[K] } = {
  gravity: (g) => {
    if (g == null || typeof g !== 'object') throw new TypeError(`gravity must be a vector {x, y}, got ${describeValue(g)}`);
    return { x: acceleration('gravity.x', g.x), y: acceleration('gravity.y', g.y) };
  },
  timestep: (v) => stepLength('timestep', v),
  substeps: (v) => (v === 'auto' ? 'auto' : substepCountOption(v)),
  iterations: (v) => integer('iterations', v, 1, 1000),
  damping: (v) => nonNegative('damping', v),
  integrator: (v) => oneOf('integrator', v, INTEGRATORS),
  bounds: (b) => (b == null ? null : checkBounds(b)),
  boundsFriction: (v) => nonNegative('boundsFriction', v),
  maxCatchUpSteps: (v) => integer('maxCatchUpSteps', v, 1, 1000),
  variableStep: (v) => flag('variableStep', v),
  contactSlop: (v) => nonNegative('contactSlop', v),
  maxPushSpeed: (v) => positive('maxPushSpeed', v),
};

/** `substeps` when not 'auto': a whole number from 1 to 1000 (the error says 'auto' is allowed too). */
function substepCountOption(v: unknown): number {
  const ok = typeof v === 'number' && Number.isInteger(v) && v >= 1 && v <= 1000;
  if (!ok) {
    const error = typeof v === 'number' ? RangeError : TypeError;
    throw new error(`substeps must be 'auto' or a whole number from 1 to 1000, got ${describeValue(v)}`);
  }
  return v;
}

const NAMES = Object.keys(CHECK) as (keyof StepSettings)[];

/**
 * Substeps per step under `substeps: 'auto'`: `rigid` when every movable body is a rigid body (static and kinematic
 * bodies and joints may be there too), `particles` when a particle, rope, cloth, soft body, ragdoll or particle-built
 * frame moves. Rigid contacts keep one normal per manifold, their anchors from step to step and a shock pass for
 * heavy loads, so they need fewer substeps than chains of particles and sticks (cloth and ropes stretch visibly at 4).
 * 6 is the smallest count at which every rigid acceptance test passes with margin: at 5 the 2000-circle container
 * pile overlaps by 4.8% of a diameter (the test allows 5%; 2.8% at 6, 1.1% at 10) and a box 100× heavier placed on a
 * pyramid slides 0.008 of the 0.01 allowed (0.003 at 6); see docs/engine.md, "Substeps".
 */
export const AUTO_SUBSTEPS = { rigid: 6, particles: 10 } as const;

/** The substeps a step takes: the explicit count, or under 'auto' by what moves (`particleRows`: movable rows that are not rigid bodies). */
export function substepCount(settings: StepSettings, particleRows: number): number {
  const s = settings.substeps;
  if (s !== 'auto') return s;
  return particleRows > 0 ? AUTO_SUBSTEPS.particles : AUTO_SUBSTEPS.rigid;
}

/**
 * ½·h of a row's reference substep (0 under the Euler integrators): between steps every movable row stores position
 * Verlet's v − ½·g·h for it, so that a thrown particle or body follows x0 + v0·t + ½·g·t² exactly. A particle's is the
 * substep of a world whose particles move, a rigid row's that of a world of rigid bodies alone (substepCount with
 * no moving particles, or one: they differ only under 'auto'), both known from the settings alone; a step of another
 * substep shifts to its own and back (step.ts).
 */
export function verletReferenceHalf(settings: StepSettings, rigid: boolean): number {
  return verletHalfSubstep(settings.integrator, settings.timestep / substepCount(settings, rigid ? 0 : 1));
}

/** Checked settings from options completed with the defaults (gravity and bounds copied, never shared). */
export function checkedSettings(options: Required<Omit<WorldOptions, 'limits'>>): StepSettings {
  const out = {} as Record<keyof StepSettings, unknown>;
  for (const name of NAMES) out[name] = (CHECK[name] as (v: unknown) => unknown)(options[name]);
  return out as StepSettings;
}
