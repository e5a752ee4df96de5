// The scene's own attributes, checked once per update (before it renders): the values the engine and the canvas get
// (defaults in place of bad values), and the problems to report. The keeper and the engine calls between updates read
// the checked values; nothing re-validates on a timer.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Bounds, KernelChoice } from '../../engine/index.js';
import type { HostParams } from '../../worker/protocol.js';
import { Checker, GRAVITY_LIMIT, misspeltAttributes, numberAttribute, type Problem } from '../checks.js';
import { MAX_STEP_SECONDS, MIN_STEP_SECONDS } from '../../engine/validate.js';
import { SCHEME_COLOURS, type ColourScheme } from './scheme.js';

/** The scene properties the configuration is read from (as set: unchecked). */
export interface SceneAttributes {
  width: number;
  height: number;
  gravity: string;
  iterations: number;
  /** A count, 'auto', or null (no attribute: 'auto'); NaN for a value that is neither. */
  substeps: number | 'auto' | null;
  timestep: number;
  broadphase: string;
  narrowphase: string;
  bounds: string;
  background?: string;
  worker: string;
  kernel: string;
  maxRestarts: number;
  drawMode: string;
  debug: boolean;
  /**
   * The view a bad `width` or `height` falls back to: the element's own defaults (a preset's view is 16 × 10, laid out
   * for it). Absent: the scene's, 16 × 9.
   */
  readonly viewDefaults?: ViewSize;
}

/** A view's size in world units. */
export interface ViewSize {
  width: number;
  height: number;
}

/** `<physics-scene>`'s default view. */
const SCENE_VIEW: ViewSize = { width: 16, height: 9 };

/**
 * Lit converter for the substeps attribute: "auto" stays "auto", anything else reads as a number (blank: NaN, which
 * the checks report), no attribute as null (auto). @internal
 */
export const substepsAttribute = {
  fromAttribute: (value: string | null): number | 'auto' | null => (value !== null && value.trim() === 'auto' ? 'auto' : numberAttribute.fromAttribute(value)),
  toAttribute: (value: unknown): unknown => value,
};

/** The checked configuration. */
export interface SceneConfig {
  width: number;
  height: number;
  gravity: { x: number; y: number };
  iterations: number;
  /** A count, or 'auto': the engine's choice by what moves (6 for rigid bodies alone, 10 when particles move). */
  substeps: number | 'auto';
  timestep: number;
  broadphase: 'grid' | 'brute';
  narrowphase: 'sat' | 'gjk';
  bounds: 'view' | 'none';
  worker: 'auto' | 'none';
  kernel: KernelChoice;
  maxRestarts: number;
  drawMode: 'over' | 'replace';
  /** CSS colour of the canvas ('transparent' for "none"). */
  background: string;
}

/** The engine's kernel choices (engine/kernel/choice.ts), listed here so the element layer imports no engine code. */
const KERNELS: readonly KernelChoice[] = ['auto', 'wasm', 'js'];

/**
 * Reads and checks the scene's attributes, in the order their problems are reported; without a `background`, the
 * canvas takes the default of the page's colour scheme. @internal
 */
export function readConfig(scene: Element & SceneAttributes, scheme: ColourScheme = 'light'): { config: SceneConfig; problems: Problem[] } {
  const check = new Checker(scene);
  const config: SceneConfig = {
    ...viewOf(check, scene),
    gravity: gravityOf(check, scene.gravity),
    iterations: check.number('iterations', scene.iterations, { integer: true, min: 1, max: 1000, fallback: 1 })!,
    substeps: substepsOf(check, scene.substeps),
    timestep: check.number('timestep', scene.timestep, { min: MIN_STEP_SECONDS, max: MAX_STEP_SECONDS, fallback: 1 / 60 })!,
    broadphase: check.oneOf('broadphase', scene.broadphase, ['grid', 'brute'] as const, 'grid'),
    narrowphase: check.oneOf('narrowphase', scene.narrowphase, ['sat', 'gjk'] as const, 'sat'),
    bounds: check.oneOf('bounds', scene.bounds, ['view', 'none'] as const, 'view'),
    worker: check.oneOf('worker', scene.worker, ['auto', 'none'] as const, 'auto'),
    kernel: check.oneOf('kernel', scene.kernel, KERNELS, 'auto'),
    maxRestarts: check.number('max-restarts', scene.maxRestarts, { integer: true, min: 0, max: 100, fallback: 3 })!,
    drawMode: check.oneOf('draw-mode', scene.drawMode, ['over', 'replace'] as const, 'over'),
    background: check.color('background', scene.background, SCHEME_COLOURS[scheme].background) ?? 'transparent',
  };
  return { config, problems: check.problems };
}

/**
 * The view's width and height as the scene uses them: each the element's default (`viewDefaults`) when bad. A preset
 * lays its bodies out for this, so they fit the view drawn. @internal
 */
export function checkedView(scene: Element & Pick<SceneAttributes, 'width' | 'height' | 'viewDefaults'>): ViewSize {
  return viewOf(new Checker(scene), scene);
}

/**
 * The smallest view width or height. Smaller, the page loses the box's aspect ratio (CSS reads 1e-10 as 0: the element
 * was 0 px tall) and a preset lays out bodies too small for the engine's smallest mass.
 */
const MIN_VIEW = 1e-3;

function viewOf(check: Checker, scene: Element & Pick<SceneAttributes, 'width' | 'height' | 'viewDefaults'>): ViewSize {
  const defaults = scene.viewDefaults ?? SCENE_VIEW;
  const size = (side: 'width' | 'height') => check.number(side, scene[side], { positive: true, min: MIN_VIEW, fallback: defaults[side] })!;
  return { width: size('width'), height: size('height') };
}

/** Substeps: "auto" (default, also when absent) or a whole number from 1 to 1000 (the engine's limits). */
function substepsOf(check: Checker, value: unknown): number | 'auto' {
  if (value === 'auto') return 'auto';
  // No attribute and no property value: auto. An attribute written blank is NaN here (substepsAttribute): reported.
  if (value === undefined || value === null) return 'auto';
  const n = typeof value === 'number' ? value : String(value).trim() === '' ? NaN : Number(value);
  if (Number.isInteger(n) && n >= 1 && n <= 1000) return n;
  check.fail('substeps', value, 'must be "auto" or a whole number from 1 to 1000');
  return 'auto';
}

/** Gravity "x y": two numbers (default 0 9.81). */
function gravityOf(check: Checker, value: string): { x: number; y: number } {
  const g = check.numbers('gravity', value);
  if (g && g.length === 2 && g.every((a) => Math.abs(a) <= GRAVITY_LIMIT)) return { x: g[0], y: g[1] };
  if (g && g.length === 2) check.fail('gravity', value, 'must be within ±1e9 (units/s²) each');
  else if (g) check.fail('gravity', value, 'must be two numbers "x y"');
  return { x: 0, y: 9.81 };
}

/** Walls at the sides and a floor at the bottom; open at the top, so bodies may start above the view. @internal */
export function viewBounds(config: Pick<SceneConfig, 'bounds' | 'width' | 'height'>): Bounds | null {
  return config.bounds === 'view' ? { minX: 0, minY: -1e6, maxX: config.width, maxY: config.height } : null;
}


/** Which engine parameters each scene property sets. */
const PARAMS_OF: Record<string, (keyof HostParams)[]> = {
  gravity: ['gravity'],
  iterations: ['iterations'],
  substeps: ['substeps'],
  timestep: ['timestep'],
  broadphase: ['broadphase'],
  narrowphase: ['narrowphase'],
  debug: ['debug'],
  width: ['bounds'],
  height: ['bounds'],
  bounds: ['bounds'],
  kernel: ['kernel'],
};

/** The parameters to send when the properties `changed` changed (empty when none is an engine parameter). @internal */
export function changedParams(changed: Iterable<PropertyKey>, params: HostParams): Partial<HostParams> {
  const out: Record<string, unknown> = {};
  for (const name of changed) for (const p of PARAMS_OF[String(name)] ?? []) out[p] = params[p];
  return out as Partial<HostParams>;
}

export interface ConfigOptions {
  /** Where the scene's problems go. */
  problems: { set(source: unknown, el: Element, problems: Problem[]): void };
  /** The page's colour scheme, which decides the default background. */
  scheme(): ColourScheme;
}

/** @internal */
export class ConfigController implements ReactiveController {
  private current: SceneConfig | null = null;
  /** Added to `gravity` when sent to the engine (a preset's wind). */
  private gravityOffset = { x: 0, y: 0 };

  constructor(
    private readonly host: ReactiveControllerHost & Element & SceneAttributes,
    private readonly options: ConfigOptions,
  ) {
    host.addController(this);
  }

  /** Before each render: the attributes checked, their problems reported. */
  hostUpdate(): void {
    this.read();
  }

  /** The configuration as of the last update. */
  get config(): SceneConfig {
    return this.current ?? this.read();
  }

  /** Reads and checks the attributes now (problems reported once each; their lines put back in the error box). */
  read(): SceneConfig {
    const { config, problems } = readConfig(this.host, this.options.scheme());
    this.current = config;
    this.options.problems.set('config', this.host, [...problems, ...misspeltAttributes(this.host)]);
    return config;
  }

  /** A preset's uniform extra acceleration, added to `gravity`. True when it changed. */
  setGravityOffset(x: number, y: number): boolean {
    if (x === this.gravityOffset.x && y === this.gravityOffset.y) return false;
    this.gravityOffset = { x, y };
    return true;
  }

  /** The engine parameters (`events`: whether collision events are wanted). */
  params(events: boolean): HostParams {
    const c = this.config;
    return {
      gravity: { x: c.gravity.x + this.gravityOffset.x, y: c.gravity.y + this.gravityOffset.y },
      iterations: c.iterations,
      substeps: c.substeps,
      timestep: c.timestep,
      broadphase: c.broadphase,
      narrowphase: c.narrowphase,
      debug: this.host.debug,
      events,
      bounds: viewBounds(c),
      kernel: c.kernel,
    };
  }
}
