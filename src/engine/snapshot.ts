// Snapshot and restore of a world's StepContext, by explicit field lists: for the context and for each of its parts
// that holds both state and scratch, the fields a snapshot holds and the fields it leaves out, each with the reason.
// A test enumerates a fresh world's fields and fails on any field that is in neither list, so a new field cannot be
// forgotten silently; the lists drive the code below, so a renamed field fails that test instead of restoring nothing.
import type { Bounds } from './bounds.js';
import type { RegistrySnapshot } from './handles.js';
import type { Column } from './table.js';
import type { BodiesSnapshot } from './body-registry.js';
import type { ConstraintsSnapshot } from './constraint-registry.js';
import { CONSTRAINT_KINDS, type Limits, type WorldOptions } from './options.js';
import { BROAD_PHASES, checkedSettings, NARROW_PHASES } from './settings.js';
import { describeValue, integer, nonNegative, oneOf } from './validate.js';
import { MAX_SLOTS } from './handles.js';
import { GridBroadPhase, makeBroadPhase } from './pipeline/broadphase.js';
import type { StepContext } from './pipeline/context.js';
import { rebuildTopology } from './pipeline/topology.js';
import type { RigidShapesSnapshot } from './rigid/shapes.js';
import type { RigidAnchorCache } from './rigid/contacts.js';

/** What a snapshot holds of a part, and what it leaves out (field → why). */
export interface FieldList {
  readonly snapshotted: readonly string[];
  readonly notSnapshotted: Readonly<Record<string, string>>;
}

const CALLBACK = 'a callback made once per world (so that a step passes it without allocating)';
const PER_STEP = 'found again by every step';
const SCRATCH = 'scratch of a step';

export const FIELDS = {
  world: {
    snapshotted: ['ctx'],
    notSnapshotted: {},
  },
  /** In the order restore() puts them back (the snapshot's own keys, too). */
  context: {
    snapshotted: ['settings', 'time', 'stepCount', 'accumulator', 'particles', 'particleIds', 'constraints', 'bodies', 'colliders', 'anchors', 'sleep', 'broadPhase', 'rigidShapes', 'rigidAnchors'],
    notSnapshotted: {
      alpha: "the last advance()'s interpolation fraction: set again by the next advance()",
      pairs: PER_STEP,
      contacts: `${PER_STEP} (cleared by restore())`,
      narrowPhase: `its mode is settings.narrowphase; the rest is ${SCRATCH}`,
      motion: PER_STEP,
      events: "the last step's events (cleared by restore())",
      eventTracker: 'which pairs touched in the last step (cleared by a restore() that succeeds: touching pairs report begin again)',
      breaks: "the last step's broken links (cleared by restore())",
      hasBreakableLinks: "derived from the distance table's breakStrain",
      topologyDirty: 'rebuilt by restore()',
      collidersDirty: 'rebuilt by restore()',
      freeMovableParticles: 'rebuilt by restore()',
      pinMoved: 'a request for the next step, cleared by restore() (the pins are where the snapshot had them)',
      particleRows: 'rebuilt by restore()',
      freeSpin: "which bodies are closed is rebuilt by restore(); the rest is the step's own (its angular momenta)",
      measureTimings: "the caller's diagnostics switch, not simulation state",
      timings: "the last step's diagnostics",
      rowsRepaired: 'diagnostics: a count kept since the world was made (World.diagnostics())',
      acceptPair: CALLBACK,
      recordBreak: CALLBACK,
      bodyHandleOf: CALLBACK,
      bodyAlive: CALLBACK,
      bodyResting: CALLBACK,
      bodyParticlesOf: CALLBACK,
      rigidContacts: `${PER_STEP} (cleared by restore())`,
      wallHits: 'per substep: cleared by the velocity pass of the substep that noted them',
      frameBounces: 'per substep: cleared by the velocity pass of the substep that noted them',
      substepMotion: 'set at the start of each step from the settings',
      jointedPairs: 'rebuilt from the joints by restore()',
      jointedApart: 'rebuilt from the joints by restore()',
      substepReals: SCRATCH,
      rigidNarrowPhase: SCRATCH,
      rigidRows: 'rebuilt from the bodies by restore()',
      rigidCount: 'rebuilt from the bodies by restore()',
      kinematicRows: 'rebuilt from the bodies by restore()',
      kinematicCount: 'rebuilt from the bodies by restore()',
    },
  },
  rigidShapes: {
    snapshotted: ['sources', 'rows', 'type'],
    notSnapshotted: Object.fromEntries(
      ['kind', 'row', 'radius', 'partStart', 'partCount', 'partVertexStart', 'partVertexCount', 'partsUsed', 'lx', 'ly', 'lnx', 'lny', 'verticesUsed', 'polygons', 'polygonCount'].map((f) => [f, 'rebuilt from the sources by restore()']).concat(
        ['wx', 'wy', 'wnx', 'wny'].map((f) => [f, PER_STEP]),
        ['internal', 'partInternal', 'staticsMoved'].map((f) => [f, "the static parts' seams: found again at the first step after restore()'s rebuild"]),
      ),
    ),
  },
  colliders: {
    snapshotted: ['kind', 'friction', 'restitution', 'category', 'mask', 'group', 'ringLength'],
    notSnapshotted: Object.fromEntries(
      ['partStart', 'partCount', 'particles', 'partVertexStart', 'partVertexCount', 'partBody', 'partsUsed', 'vertices', 'verticesUsed', 'active', 'activeCount'].map((f) => [f, 'rebuilt from the bodies by restore()']).concat(
        ['isStatic', 'minX', 'minY', 'maxX', 'maxY'].map((f) => [f, PER_STEP]),
      ),
    ),
  },
  sleep: {
    snapshotted: ['sleepTime', 'lastMove', 'growing', 'asleep', 'dynamic', 'parkedInvMass', 'parkedInvInertia', 'awakeCount', 'asleepCount', 'speedThreshold', 'timeToSleep'],
    notSnapshotted: {
      enabled: 'settings.sleeping',
      particleBody: 'rebuilt from the bodies by restore()',
      linksA: 'rebuilt from the constraints by restore()',
      linksB: 'rebuilt from the constraints by restore()',
      linkCount: 'rebuilt from the constraints by restore()',
      parent: SCRATCH,
      islandMin: SCRATCH,
    },
  },
  grid: {
    snapshotted: ['autoCellSize'],
    notSnapshotted: {
      name: 'settings.broadphase',
      cellSize: 'settings.cellSize',
      maxCellsPerBody: 'a constant',
      lastCellSize: "the last step's, for debug drawing",
      lastOriginX: "the last step's, for debug drawing",
      lastOriginY: "the last step's, for debug drawing",
      keys: SCRATCH,
      values: SCRATCH,
      keysTmp: SCRATCH,
      valuesTmp: SCRATCH,
      large: SCRATCH,
      extents: SCRATCH,
      counts: SCRATCH,
    },
  },
  bodies: {
    snapshotted: ['ids', 'kind', 'particles', 'constraints', 'parts'],
    notSnapshotted: { owner: 'rebuilt from the particles by restore()' },
  },
  constraints: {
    snapshotted: ['ids', 'kind', 'row', 'distances', 'angles', 'pins', 'springs', 'areas', 'grabs', 'joints'],
    notSnapshotted: { tables: 'the same tables, indexed by kind' },
  },
  handles: {
    snapshotted: ['generation', 'alive', 'high', 'free'],
    notSnapshotted: { live: 'recounted from high and free', limit: 'settings.limits', what: 'a name for messages', limitName: 'a name for messages', plural: 'a name for messages' },
  },
} as const satisfies Record<string, FieldList>;

/** Fields of tables besides their columns (which are all snapshotted, with the row count). */
export const TABLE_FIELDS: FieldList = {
  snapshotted: ['count', 'pool', 'poolUsed'],
  notSnapshotted: { columns: 'the list of column names' },
};

/** The objects of a world that FIELDS describes, by list name (for the test that keeps the lists complete). */
export function describedParts(ctx: StepContext): [keyof typeof FIELDS, object][] {
  const parts: [keyof typeof FIELDS, object][] = [
    ['context', ctx],
    ['colliders', ctx.colliders],
    ['rigidShapes', ctx.rigidShapes],
    ['sleep', ctx.sleep],
    ['bodies', ctx.bodies],
    ['constraints', ctx.constraints],
    ['handles', ctx.particleIds],
    ['handles', ctx.bodies.ids],
    ['handles', ctx.constraints.ids],
  ];
  if (ctx.broadPhase instanceof GridBroadPhase) parts.push(['grid', ctx.broadPhase]);
  return parts;
}

type Snapshotted = (typeof FIELDS.context.snapshotted)[number];
type Fields = Record<string, Column | number>;

/** The whole state of a world as plain data (structured-cloneable: a worker can post it). Opaque to callers. */
export interface WorldSnapshot extends Record<Snapshotted, unknown> {
  settings: Required<Omit<WorldOptions, 'bounds' | 'limits'>> & { bounds: Bounds | null; limits: Limits };
  time: number;
  stepCount: number;
  accumulator: number;
  particles: { count: number; columns: Column[] };
  particleIds: RegistrySnapshot;
  constraints: ConstraintsSnapshot;
  bodies: BodiesSnapshot;
  colliders: Fields;
  anchors: { keys: Float64Array; values: Float64Array };
  sleep: Fields;
  broadPhase: Fields;
  rigidShapes: RigidShapesSnapshot;
  rigidAnchors: ReturnType<RigidAnchorCache['snapshot']>;
}

/**
 * Refuses a table holding NaN or ±Infinity in any row (a snapshot edited or damaged on its way); `open` names the
 * columns that may be ±Infinity (a joint's or link's limit left open). A NaN in a constraint's target or compliance
 * froze its particle for good, an ∞ rest length or compliance made NaN accelerations.
 */
function finiteColumns(what: string, table: { columns: readonly string[]; count: number }, open: readonly string[] = []): void {
  for (const name of table.columns) {
    const column = (table as unknown as Record<string, ArrayLike<number>>)[name];
    const limit = open.includes(name);
    for (let i = 0; i < table.count; i++) {
      const v = column[i];
      if (limit ? v !== v : !Number.isFinite(v)) throw new RangeError(`${what}.${name}[${i}] must be a ${limit ? '' : 'finite '}number, got ${describeValue(v)}`);
    }
  }
}

export function snapshotContext(ctx: StepContext): WorldSnapshot {
  // The sleep bookkeeping (awake count) is derived when the topology is rebuilt; a snapshot taken before that (before
  // the first step, right after an edit) would restore a stale count and freeze the world. Rebuild it now.
  if (ctx.topologyDirty) rebuildTopology(ctx);
  const s = ctx.settings;
  const grid = ctx.broadPhase instanceof GridBroadPhase ? ctx.broadPhase : null;
  return {
    settings: {
      ...s,
      gravity: { ...s.gravity },
      bounds: s.bounds ? { ...s.bounds } : null,
      broadphase: ctx.broadPhase.name,
      narrowphase: ctx.narrowPhase.mode,
      cellSize: grid ? grid.cellSize : 0,
      sleeping: ctx.sleep.enabled,
      limits: { particles: ctx.particleIds.limit, constraints: ctx.constraints.ids.limit, bodies: ctx.bodies.ids.limit },
    },
    time: ctx.time,
    stepCount: ctx.stepCount,
    accumulator: ctx.accumulator,
    particles: { count: ctx.particles.count, columns: ctx.particles.snapshot() },
    particleIds: ctx.particleIds.snapshot(),
    constraints: ctx.constraints.snapshot(),
    bodies: ctx.bodies.snapshot(),
    colliders: saveFields(ctx.colliders, FIELDS.colliders.snapshotted),
    anchors: ctx.anchors.snapshot(),
    sleep: saveFields(ctx.sleep, FIELDS.sleep.snapshotted),
    broadPhase: grid ? saveFields(grid, FIELDS.grid.snapshotted) : {},
    rigidShapes: ctx.rigidShapes.snapshot(ctx.bodies.ids.high),
    rigidAnchors: ctx.rigidAnchors.snapshot(),
  };
}

/** Puts a snapshot back; a value that is not a snapshot is refused before anything changes. */
export function restoreContext(ctx: StepContext, s: WorldSnapshot): void {
  if (s == null || typeof s !== 'object') throw new TypeError(`snapshot must be an object made by World.snapshot(), got ${describeValue(s)}`);
  for (const name of FIELDS.context.snapshotted) {
    if (s[name] == null) throw new TypeError(`snapshot has no ${name}: it was not made by World.snapshot() of this version`);
  }
  const columns = (s.particles as { columns?: unknown }).columns;
  if (!Array.isArray(columns) || !columns.every((c) => ArrayBuffer.isView(c))) {
    throw new TypeError('snapshot holds no typed arrays where World.snapshot() puts them (JSON.stringify turns them into plain objects): keep the snapshot object, or copy it with structuredClone()');
  }
  restoreSettings(ctx, s.settings);
  ctx.time = nonNegative('snapshot time', s.time);
  ctx.stepCount = integer('snapshot stepCount', s.stepCount, 0);
  ctx.accumulator = nonNegative('snapshot accumulator', s.accumulator);
  ctx.particles.restore(s.particles.columns, s.particles.count);
  finiteColumns('snapshot particles', ctx.particles);
  ctx.particleIds.restore(s.particleIds);
  ctx.constraints.restore(s.constraints);
  ctx.constraints.tables.forEach((t, k) => finiteColumns(`snapshot ${CONSTRAINT_KINDS[k]} constraints`, t, ['lower', 'upper', 'minLength', 'maxLength', 'min', 'max', 'breakStrain']));
  ctx.bodies.restore(s.bodies);
  ctx.colliders.ensureBodies(ctx.bodies.ids.high);
  loadFields(ctx.colliders, FIELDS.colliders.snapshotted, s.colliders);
  const { friction, restitution } = ctx.colliders;
  finiteColumns('snapshot colliders', { columns: ['friction', 'restitution'], count: ctx.bodies.ids.high, friction, restitution } as never);
  ctx.anchors.restoreSnapshot(s.anchors);
  ctx.rigidShapes.restore(s.rigidShapes);
  ctx.rigidAnchors.restoreSnapshot(s.rigidAnchors);

  const distances = ctx.constraints.distances;
  ctx.hasBreakableLinks = distances.breakStrain.some((v) => v > 0);
  ctx.pairs.count = 0;
  ctx.contacts.count = 0;
  ctx.rigidContacts.count = 0;
  ctx.events.count = 0;
  ctx.breaks.count = 0;
  ctx.pinMoved = false;
  ctx.collidersDirty = true;
  ctx.topologyDirty = true;
  rebuildTopology(ctx);
  // The rebuild starts the sleep bookkeeping and the grid's cell size afresh; the run had carried them on.
  loadFields(ctx.sleep, FIELDS.sleep.snapshotted, s.sleep);
  if (ctx.broadPhase instanceof GridBroadPhase) loadFields(ctx.broadPhase, FIELDS.grid.snapshotted, s.broadPhase);
}

function restoreSettings(ctx: StepContext, s: WorldSnapshot['settings']): void {
  Object.assign(ctx.settings, checkedSettings(s));
  ctx.particleIds.limit = integer('limits.particles', s.limits.particles, 1, MAX_SLOTS);
  ctx.constraints.ids.limit = integer('limits.constraints', s.limits.constraints, 1, MAX_SLOTS);
  ctx.bodies.ids.limit = integer('limits.bodies', s.limits.bodies, 1, MAX_SLOTS);
  ctx.broadPhase = makeBroadPhase(oneOf('broadphase', s.broadphase, BROAD_PHASES), nonNegative('cellSize', s.cellSize));
  ctx.narrowPhase.mode = oneOf('narrowphase', s.narrowphase, NARROW_PHASES);
  ctx.sleep.enabled = Boolean(s.sleeping);
}

/** Copies of the named fields (typed arrays copied whole, numbers as they are). */
function saveFields(owner: object, names: readonly string[]): Fields {
  const o = owner as Record<string, Column | number>;
  const out: Fields = {};
  for (const name of names) out[name] = copy(o[name]);
  return out;
}

function loadFields(owner: object, names: readonly string[], saved: Fields): void {
  const o = owner as Record<string, Column | number>;
  for (const name of names) {
    if (typeof saved[name] !== typeof o[name]) throw new TypeError(`snapshot field ${name} is missing or of the wrong type`);
    o[name] = copy(saved[name]);
  }
}

function copy(value: Column | number): Column | number {
  return typeof value === 'number' ? value : value.slice();
}
