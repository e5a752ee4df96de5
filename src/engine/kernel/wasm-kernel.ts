// The WebAssembly SIMD kernel's TypeScript side: it owns one WebAssembly.Memory that holds the engine's own particle
// columns (the ParticleStore's x, y, px, … become views into it: one copy of the state, which the JS phases and the
// kernel share) and the distance constraints, as runs (runs.ts: contiguous lanes, no indices) and, for the rest,
// coloured packets (colour.ts); see solver.as for their layout.
//
// Growth: a Table that outgrows its columns replaces them with plain arrays (table.ts); the next step sees that a
// column no longer lives in the memory and lays everything out again. The runs and packets are found again when the
// constraints' structure changes (the topology is rebuilt) and their limits refreshed when links break; the kernel
// reads inverse masses from the particle column itself. Only a new layout allocates.
//
// Rigid contacts in lanes: a step whose rigid contacts are all single points between rows or with the world (disc
// piles: no manifold pairs, no particle-built edge points, restitution 0, no shock sweep) has them coloured after its
// first substep's JS prepare (beginRigid) into batches that share no movable body, laid out two a packet after the
// distance data (by solver.as's rigidLayout, from the table's columns copied into the memory), and swept by
// rigidBegin / rigidSweep / rigidVelocities; the step's end copies back what
// the JS phases read (endRigid: anchors, events, sleep). Any other step leaves them to the JS solver. Only more
// contacts than ever before allocate (larger colouring arrays, a grown memory).
import type { ParticleStore } from '../particles.js';
import type { DistanceConstraints } from '../constraints/distance.js';
import type { StepContext } from '../pipeline/context.js';
import { arcsExact, type RigidContacts } from '../rigid/contacts.js';
import { colourRows } from './colour.js';
import { findRuns, kindOf, RunKind, type RunLayout } from './runs.js';

/** The columns the kernel reads or writes, in the order they are laid out. */
const COLUMNS = ['x', 'y', 'px', 'py', 'vx', 'vy', 'ax', 'ay', 'fx', 'fy', 'invMass', 'angle', 'qangle', 'rc', 'rs', 'omega', 'invInertia'] as const;
type KernelColumn = (typeof COLUMNS)[number];
/**
 * Rows past the columns' length: the padding lanes of runs and packets read (and write back unchanged) up to 3. The
 * first is also the rigid padding lanes' row; the second is the world's for rigid contacts (all 0 but rc = 1).
 */
const SPARE_ROWS = 4;
/** Bytes per packet of two rigid contact points, f64 and i32 words (see solver.as), and the f64 field indices. */
const RIGID_PACKET = 448;
const RIGID_F64 = RIGID_PACKET / 8;
const RF = { allowance: 14, slip: 18, touched: 20 };
const RIGID_FIELDS = 27;
/** Bytes a row of the contact table takes staged for the kernel's layout (eleven f64 columns, three i32: solver.as rigidLayout). */
const STAGED = 100;
/** The f64 columns staged, in solver.as rigidLayout's order. */
const STAGED_COLUMNS = ['nx', 'ny', 'rAx', 'rAy', 'rBx', 'rBy', 'radA', 'radB', 'friction', 'allowance', 'depth'] as const;
/**
 * Bytes per packet of two manifolds (one a lane, each with its two points; see solver.as), its f64 words, and the
 * field indices: shared fields, then point p's at MP + 18p + field.
 */
const MANIFOLD_PACKET = 800;
const MANIFOLD_F64 = MANIFOLD_PACKET / 8;
const MANIFOLD_FIELDS = 49;
/** Colours of the greedy colouring (two 32-bit masks a row), for contacts between movable bodies and for the rest. */
const COLOURS = 64;

/** Bytes per packet of two constraints, and where its fields are in f64 and i32 words (see solver.as). */
const PACKET_BYTES = 80;
const PACKET_F64 = PACKET_BYTES / 8;
const PACKET_I32 = PACKET_BYTES / 4;
const LO = 2;
const HI = 4;
const COMPLIANCE = 6;
/** Bytes per run record, and per pair of lanes of each kind of run (see solver.as). */
const RUN_BYTES = 32;
const PAIR_BYTES = [16, 32, 64];
const PAGE = 65536;

/**
 * solver.as's exports, under the one-letter names it gives them (each name ships in the module and again here): the
 * comment on each names its function there.
 */
interface KernelExports {
  /** solveDistances */
  a(x: number, y: number, invMass: number, runs: number, runCount: number, packets: number, count: number, h2: number, fresh: boolean): void;
  /** integrateVerlet */
  b(x: number, y: number, px: number, py: number, vx: number, vy: number, ax: number, ay: number, invMass: number, n: number, h: number, damp: number, forces: boolean, gx: number, gy: number): void;
  /** updateVelocities */
  c(x: number, y: number, px: number, py: number, vx: number, vy: number, n: number, inv: number): void;
  /** rigidBegin */
  e(packets: number, count: number, maxPush: number): void;
  /** rigidSweep */
  f(x: number, y: number, angle: number, qangle: number, rc: number, rs: number, packets: number, count: number): void;
  /** rigidVelocities */
  g(vx: number, vy: number, omega: number, packets: number, count: number): void;
  /** rigidLayout */
  d(stage: number, cap: number, n: number, invMass: number, invInertia: number, packets: number, world: number): void;
  /** manifoldBegin */
  h(packets: number, count: number, maxPush: number): void;
  /** manifoldSweep */
  i(x: number, y: number, angle: number, qangle: number, rc: number, rs: number, packets: number, count: number): void;
  /** manifoldVelocities */
  j(vx: number, vy: number, omega: number, packets: number, count: number, h: number): void;
}

export class WasmKernel {
  #memory = new WebAssembly.Memory({ initial: 1 });
  #exports: KernelExports;
  /** Byte address of each column in the memory (valid while the columns are views into it). */
  readonly #address = Object.fromEntries(COLUMNS.map((c) => [c, 0])) as Record<KernelColumn, number>;
  /** Rows the columns have room for (their length; the memory holds SPARE_ROWS more, zero). */
  #capacity = 0;
  #runAddress = 0;
  #runCount = 0;
  #runs: RunLayout | null = null;
  /** Byte address of each run's lane data. */
  #runData: Int32Array = new Int32Array(0);
  #packetAddress = 0;
  #packetCount = 0;
  /** Per packet lane: the distance row it solves, -1 for padding. */
  #packetRows: Int32Array = new Int32Array(0);
  /** Distance rows laid out (runs and packets): a different count means the table changed. */
  #laidOutRows = -1;
  /** The memory as f64 and i32 words (made with each layout: the memory only grows then). */
  #f64: Float64Array = new Float64Array(0);
  #i32: Int32Array = new Int32Array(0);
  /** The constraints changed (find the runs again), or some limits did (copy them again). */
  #structureChanged = true;
  #limitsChanged = false;
  /** No sweep has run since the multipliers were reset. */
  #freshLambdas = true;
  /** Layouts made (diagnostics and tests: steady stepping makes none). */
  layouts = 0;
  /** This step's rigid contacts run in the lanes (set by beginRigid, cleared by endRigid). */
  rigidLanes = false;
  /** Tests: one rigid contact a packet, in list order (the JS solver's order, so its doubles exactly). */
  rigidSerial = false;
  /** Steps whose rigid contacts ran in the lanes, and steps that had rigid contacts the lanes do not take. */
  rigidLaneSteps = 0;
  rigidJsSteps = 0;
  /** Byte address of the rigid packets (after the distance data), room for how many bytes, and how many this step. */
  #rigidAddress = 0;
  #rigidCapacity = 0;
  #rigidPackets = 0;
  /** This step's contacts are laid out by manifold (some are pairs): manifold packets, else single-point packets. */
  #manifolds = false;
  /** The step's substep reals ([0]: the substep's length, which the manifolds' velocity pass reads). */
  #substepReals: Float64Array = new Float64Array(1);
  /** Steps laid out by manifold (diagnostics and tests). */
  manifoldSteps = 0;
  /** Colouring: per row, masks of the colours it takes part in (with movable bodies: 0-31, 32-63; with a static body
   *  or the world: 0-31, 32-63). */
  #masks = new Uint32Array(0);
  /** Per contact: its colour (64 + k for the static colours), then its lane (packet s >> 1, lane s & 1). */
  #colourOf = new Int16Array(0);
  #slotOf = new Int32Array(0);
  readonly #batchSize = new Int32Array(2 * COLOURS);
  readonly #batchCursor = new Int32Array(2 * COLOURS + 1);

  readonly #module: WebAssembly.Module;

  constructor(module: WebAssembly.Module) {
    this.#module = module;
    this.#exports = this.#instantiate();
  }

  #instantiate(): KernelExports {
    return new WebAssembly.Instance(this.#module, { env: { memory: this.#memory } }).exports as unknown as KernelExports;
  }

  /**
   * Room for `bytes`: a new, larger memory (with the old one's bytes when `keep`) and the module instantiated on it.
   * Never Memory.grow(): growing detaches the old buffer, and in V8 the first ArrayBuffer detached in a realm slows
   * every typed-array access of the JS code after it (measured: S3 under the JS solver 2.65 → 3.35 ms a step, the
   * narrow phase and the rigid solver alike, once any memory in the process had grown).
   */
  #replaceMemory(bytes: number, keep: boolean): void {
    const old = this.#memory;
    this.#memory = new WebAssembly.Memory({ initial: Math.ceil(bytes / PAGE) });
    if (keep) new Uint8Array(this.#memory.buffer).set(new Uint8Array(old.buffer));
    this.#exports = this.#instantiate();
  }

  /** Bodies, particles or constraints were added, removed or restored. */
  topologyChanged(): void {
    this.#structureChanged = true;
  }

  /** Some links' limits changed (they broke). */
  distanceLimitsChanged(): void {
    this.#limitsChanged = true;
  }

  /** Whether some column no longer lives in the memory (a table outgrew it: the layout is made again). */
  #columnsMoved(p: ParticleStore): boolean {
    // A loop, not some(): a closure would be allocated every step.
    for (const name of COLUMNS) if (p[name].buffer !== this.#memory.buffer) return true;
    return false;
  }

  /** Before a step's substeps: the columns live in the memory, the runs and packets match the constraints. */
  beginStep(ctx: StepContext): void {
    const { particles: p, constraints } = ctx;
    const c = constraints.distances;
    let layout = this.#structureChanged || c.count !== this.#laidOutRows || this.#columnsMoved(p);
    // A link whose limits no longer fit its run's kind (only a break changes them, and a broken link fits any kind).
    if (!layout && this.#limitsChanged && !this.#copyLimits(c)) layout = true;
    if (layout) this.#layOut(ctx);
  }

  /**
   * Position Verlet. `gravity` given: the accelerations are g + f·invMass, computed here (the step's accelerate phase,
   * fused; the ax/ay columns are then not written); null: read from ax/ay (springs added to them).
   */
  integrateVerlet(p: ParticleStore, h: number, damp: number, gravity: { x: number; y: number } | null): void {
    const m = this.#address;
    if (gravity) this.#exports.b(m.x, m.y, m.px, m.py, m.vx, m.vy, m.fx, m.fy, m.invMass, p.count, h, damp, true, gravity.x, gravity.y);
    else this.#exports.b(m.x, m.y, m.px, m.py, m.vx, m.vy, m.ax, m.ay, m.invMass, p.count, h, damp, false, 0, 0);
  }

  updateVelocities(p: ParticleStore, h: number): void {
    const m = this.#address;
    this.#exports.c(m.x, m.y, m.px, m.py, m.vx, m.vy, p.count, 1 / h);
  }

  /** The multipliers start each substep at zero: the next sweep does not read them. */
  resetLambdas(): void {
    this.#freshLambdas = true;
  }

  solveDistances(h2: number): void {
    if (this.#runCount === 0 && this.#packetCount === 0) return;
    const m = this.#address;
    this.#exports.a(m.x, m.y, m.invMass, this.#runAddress, this.#runCount, this.#packetAddress, this.#packetCount, h2, this.#freshLambdas);
    this.#freshLambdas = false;
  }

  /**
   * After the first substep's JS prepare (orderForShock has run): takes the step's rigid contacts into the lanes when
   * every one is a single point between two rows or with the world, restitution 0, and no shock sweep; colours them
   * (greedy, list order, the lowest colour of 64 free at both movable bodies; contacts with a static body or the world
   * in colours of their own, swept after the others: the wall has the last word, as in the JS sweep, whose list has
   * them last) and lays them out. False (the JS solver keeps them): any other contact, or more than 64 colours.
   */
  beginRigid(ctx: StepContext): boolean {
    const c = ctx.rigidContacts;
    const p = ctx.particles;
    this.rigidLanes = false;
    const fit = lanesFit(c);
    if (fit === 0) {
      this.rigidJsSteps++;
      return false;
    }
    const manifolds = fit === 2;
    if (this.#structureChanged || this.#columnsMoved(p)) this.#layOut(ctx);
    const n = c.count;
    const rows = this.#capacity + 2;
    if (this.#masks.length < 4 * rows) this.#masks = new Uint32Array(4 * rows);
    if (this.#colourOf.length < n) {
      this.#colourOf = new Int16Array(2 * n);
      this.#slotOf = new Int32Array(2 * n);
    }
    const { a: A, b: B, pair } = c;
    const { invMass, invInertia } = p;
    const masks = this.#masks, colourOf = this.#colourOf, size = this.#batchSize, cursor = this.#batchCursor;
    let packets: number;
    if (this.rigidSerial) {
      // One contact (one manifold) a packet, in list order.
      packets = 0;
      for (let i = 0; i < n; i++, packets++) if (manifolds && pair[i] === 1) i++;
    } else {
      size.fill(0);
      // The masks of the rows in contact cleared: all at once when the contacts are many, else row by row.
      if (2 * n > rows) masks.fill(0, 0, 4 * rows);
      else {
        for (let i = 0; i < n; i++) {
          const ra = 4 * A[i];
          masks[ra] = masks[ra + 1] = masks[ra + 2] = masks[ra + 3] = 0;
          const ib = B[i];
          if (ib >= 0) masks[4 * ib] = masks[4 * ib + 1] = masks[4 * ib + 2] = masks[4 * ib + 3] = 0;
        }
      }
      // Greedy in list order, a manifold (its first point) at a time when laid out by manifold. Per row four masks:
      // colours taken with movable bodies (0-31, 32-63), then with static bodies or the world.
      for (let i = 0; i < n; i++) {
        const ia = A[i];
        const ib = B[i];
        const movA = invMass[ia] !== 0 || invInertia[ia] !== 0;
        const movB = ib >= 0 && (invMass[ib] !== 0 || invInertia[ib] !== 0);
        const both = movA && movB;
        const ma = 4 * ia + (both ? 0 : 2);
        const mb = 4 * ib + (both ? 0 : 2);
        const l = (movA ? masks[ma] : 0) | (movB ? masks[mb] : 0);
        const h = (movA ? masks[ma + 1] : 0) | (movB ? masks[mb + 1] : 0);
        // The lowest clear bit of l, else of h.
        const k = ~l !== 0 ? 31 - Math.clz32(~l & (l + 1)) : ~h !== 0 ? 63 - Math.clz32(~h & (h + 1)) : -1;
        if (k < 0) {
          this.rigidJsSteps++;
          return false;
        }
        const bit = 1 << (k & 31);
        const word = k < 32 ? 0 : 1;
        if (movA) masks[ma + word] |= bit;
        if (movB) masks[mb + word] |= bit;
        const colour = both ? k : COLOURS + k;
        colourOf[i] = colour;
        size[colour]++;
        if (manifolds && pair[i] === 1) i++;
      }
      // Each colour's batch padded to whole packets.
      cursor[0] = 0;
      for (let k = 0; k < 2 * COLOURS; k++) cursor[k + 1] = cursor[k] + ((size[k] + 1) & ~1);
      packets = cursor[2 * COLOURS] >> 1;
    }
    this.#manifolds = manifolds;
    this.#substepReals = ctx.substepReals;
    // Single points: their columns staged after the packets (whole columns: STAGED bytes a row of the table).
    const bytes = manifolds ? packets * MANIFOLD_PACKET : align16(packets * RIGID_PACKET) + c.a.length * STAGED;
    if (bytes > this.#rigidCapacity) this.#growRigid(p, bytes);
    if (manifolds) {
      this.#writeManifolds(c, p.invMass, p.invInertia);
      this.manifoldSteps++;
    }
    this.#rigidPackets = packets;
    if (!manifolds) this.#writeRigid(c);
    this.rigidLanes = true;
    this.rigidLaneSteps++;
    return true;
  }

  /** A substep's start for the lanes (as prepareRigidContacts': no correction yet, allowances shrink by maxPush). */
  rigidBeginSubstep(maxPush: number): void {
    if (this.#manifolds) this.#exports.h(this.#rigidAddress, this.#rigidPackets, maxPush);
    else this.#exports.e(this.#rigidAddress, this.#rigidPackets, maxPush);
  }

  rigidSweep(): void {
    const m = this.#address;
    if (this.#manifolds) this.#exports.i(m.x, m.y, m.angle, m.qangle, m.rc, m.rs, this.#rigidAddress, this.#rigidPackets);
    else this.#exports.f(m.x, m.y, m.angle, m.qangle, m.rc, m.rs, this.#rigidAddress, this.#rigidPackets);
  }

  rigidVelocities(): void {
    const m = this.#address;
    if (this.#manifolds) this.#exports.j(m.vx, m.vy, m.omega, this.#rigidAddress, this.#rigidPackets, this.#substepReals[0]);
    else this.#exports.g(m.vx, m.vy, m.omega, this.#rigidAddress, this.#rigidPackets);
  }

  /**
   * The step's end: what the JS phases read back from the lanes into the contact table: touched (events, sleep,
   * anchors), and a touched point's slip and allowance (the anchors) and normal levers (a begin event's speed counts
   * the bodies' spin through them: without them a rod spinning into a block began its pair at speed 0). Nothing reads λn, the impulses or gap after
   * the solver, and the next step's narrow phase writes every field again; an untouched point keeps the narrow
   * phase's touched 0.
   */
  endRigid(c: RigidContacts): void {
    this.rigidLanes = false;
    const f64 = this.#f64, i32 = this.#i32, slotOf = this.#slotOf;
    const { allowance, slip, touched, pair } = c;
    const manifolds = this.#manifolds;
    const base = this.#rigidAddress >> 3;
    for (let i = 0, n = c.count; i < n; i++) {
      const s = slotOf[i];
      if (!manifolds) {
        const w = base + (s >> 1) * RIGID_F64 + (s & 1);
        if (i32[2 * (w + 2 * RF.touched)] === 0) continue;
        touched[i] = 1;
        allowance[i] = f64[w + 2 * RF.allowance];
        slip[i] = f64[w + 2 * RF.slip];
        leversBack(c, f64, i, w + 42);
        continue;
      }
      // Point 0 of a lane to its first contact, point 1 to its partner (literal offsets as in writeManifolds); the
      // partner's slip follows the manifold's once friction has acted.
      const w = base + (s >> 1) * MANIFOLD_F64 + 2 + (s & 1);
      if (i32[2 * w + 88] !== 0) {
        touched[i] = 1;
        slip[i] = f64[w + 18];
        allowance[i] = f64[w + 36];
        leversBack(c, f64, i, w + 46);
      }
      if (pair[i] !== 1) continue;
      if (i32[2 * w + 160] !== 0) {
        touched[i + 1] = 1;
        slip[i + 1] = f64[w + 20];
        allowance[i + 1] = f64[w + 72];
        leversBack(c, f64, i + 1, w + 82);
      }
      i++;
    }
  }

  /** Room for `needed` bytes of rigid packets (half as much again): the memory grows, the column views are made again. */
  #growRigid(p: ParticleStore, needed: number): void {
    this.#rigidCapacity = Math.ceil(needed * 1.5);
    const bytes = this.#rigidAddress + this.#rigidCapacity;
    if (bytes > this.#memory.buffer.byteLength) {
      // A new memory with the old bytes: the column views are made again on it.
      this.#replaceMemory(Math.max(bytes, this.#memory.buffer.byteLength * 1.5), true);
      const buffer = this.#memory.buffer;
      this.#f64 = new Float64Array(buffer);
      this.#i32 = new Int32Array(buffer);
      const columns = p as unknown as Record<KernelColumn, Float64Array>;
      for (const name of COLUMNS) columns[name] = new Float64Array(buffer, this.#address[name], this.#capacity);
    }
  }

  /**
   * Each contact's lane, laid out by the kernel (solver.as rigidLayout) from the table's columns copied whole into the
   * memory after the packets (a memcpy each) with each contact's lane: the same copies as twenty stores a contact from
   * JS, which cost more (10,000 circles: layout and colouring 0.92 → 0.65 ms a step, S3 0.15 → 0.10 ms).
   */
  #writeRigid(c: RigidContacts): void {
    const f64 = this.#f64, i32 = this.#i32, slotOf = this.#slotOf, colourOf = this.#colourOf, size = this.#batchSize, cursor = this.#batchCursor;
    const n = c.count;
    const serial = this.rigidSerial;
    if (serial) for (let i = 0; i < n; i++) this.#pad(2 * i + 1, RIGID_F64, RIGID_FIELDS, 2 * RF.allowance);
    else for (let k = 0; k < 2 * COLOURS; k++) if (size[k] & 1) this.#pad(cursor[k + 1] - 1, RIGID_F64, RIGID_FIELDS, 2 * RF.allowance);
    const cap = c.a.length;
    const stage = this.#rigidAddress + align16(this.#rigidPackets * RIGID_PACKET);
    for (let k = 0; k < STAGED_COLUMNS.length; k++) f64.set(c[STAGED_COLUMNS[k]], stage / 8 + k * cap);
    const ints = stage / 4 + 22 * cap;
    i32.set(c.a, ints);
    i32.set(c.b, ints + cap);
    for (let i = 0; i < n; i++) i32[ints + 2 * cap + i] = slotOf[i] = serial ? 2 * i : cursor[colourOf[i]]++;
    this.#exports.d(stage, cap, n, this.#address.invMass, this.#address.invInertia, this.#rigidAddress, (this.#capacity + 1) * 8);
  }

  /**
   * Each manifold's lane (a lone point: its second point inactive, allowance +∞): the rows' byte offsets, the shared
   * fields, each point's geometry and state.
   */
  #writeManifolds(c: RigidContacts, invMass: Float64Array, invInertia: Float64Array): void {
    const f64 = this.#f64, i32 = this.#i32, slotOf = this.#slotOf, colourOf = this.#colourOf, size = this.#batchSize, cursor = this.#batchCursor;
    const base = this.#rigidAddress >> 3;
    const world = (this.#capacity + 1) * 8;
    const n = c.count;
    const serial = this.rigidSerial;
    const { a: A, b: B, pair, nx, ny, rAx, rAy, rBx, rBy, radA, radB, friction, allowance, depth } = c;
    if (serial) {
      for (let i = 0, s = 1; i < n; i++, s += 2) {
        this.#f64[this.#pad(s, MANIFOLD_F64, MANIFOLD_FIELDS, 38) + 74] = Infinity;
        if (pair[i] === 1) i++;
      }
    } else for (let k = 0; k < 2 * COLOURS; k++) if (size[k] & 1) this.#f64[this.#pad(cursor[k + 1] - 1, MANIFOLD_F64, MANIFOLD_FIELDS, 38) + 74] = Infinity;
    // Field k of a lane at f64 word w + 2k (w: its packet's first field, plus the lane); point p's fields from
    // k = 12 + 18p (see solver.as). Literal offsets: this loop runs once a step over every manifold.
    for (let i = 0, m = 0; i < n; i++, m++) {
      const s = serial ? 2 * m : cursor[colourOf[i]]++;
      const two = pair[i] === 1;
      const j = two ? i + 1 : i;
      slotOf[i] = s;
      slotOf[j] = s;
      const lane = s & 1;
      const packet = base + (s >> 1) * MANIFOLD_F64;
      const w = packet + 2 + lane;
      const q = 2 * packet + lane;
      const ia = A[i];
      const ib = B[i];
      const onRow = ib >= 0;
      i32[q] = ia * 8;
      i32[q + 2] = onRow ? ib * 8 : world;
      f64[w] = nx[i];
      f64[w + 2] = ny[i];
      f64[w + 4] = friction[i];
      f64[w + 6] = invMass[ia];
      f64[w + 8] = invInertia[ia];
      f64[w + 10] = onRow ? invMass[ib] : 0;
      f64[w + 12] = onRow ? invInertia[ib] : 0;
      const t = two ? -1 : 0;
      i32[2 * w + 28] = t;
      i32[2 * w + 29] = t;
      // Field 48: the larger depth at detection (negative: every point was apart, a landing whose impulse gets friction).
      f64[w + 96] = depth[j] > depth[i] ? depth[j] : depth[i];
      // impulseT and both points' slip start at 0, as λn, impulseN and touched below: stored, not copied (the narrow
      // phase starts every point there, and the prepare only zeroes λn again). Gap: every sweep writes it first.
      f64[w + 16] = 0;
      f64[w + 18] = 0;
      f64[w + 20] = 0;
      // Point 0 (k 12..): rAx, rAy, rBx, rBy (the world's point is (rBx, rBy) itself: its row turns it by (1, 0)),
      // radA, radB, allowance, λn, impulseN, (gap: not laid out), touched.
      f64[w + 24] = rAx[i];
      f64[w + 26] = rAy[i];
      f64[w + 28] = rBx[i];
      f64[w + 30] = rBy[i];
      f64[w + 32] = radA[i];
      f64[w + 34] = onRow ? radB[i] : 0;
      f64[w + 36] = allowance[i];
      f64[w + 38] = 0;
      f64[w + 40] = 0;
      f64[w + 44] = 0;
      // Point 1 (k 30..40, its gap too, which every sweep writes first): zero, then the partner's geometry, or for a
      // lone point nowhere and never overlapping (allowance +∞).
      for (let k = 60; k <= 80; k += 2) f64[w + k] = 0;
      if (two) {
        f64[w + 60] = rAx[j];
        f64[w + 62] = rAy[j];
        f64[w + 64] = rBx[j];
        f64[w + 66] = rBy[j];
        f64[w + 68] = radA[j];
        if (onRow) f64[w + 70] = radB[j];
        f64[w + 72] = allowance[j];
        i++;
      } else f64[w + 72] = Infinity;
    }
  }

  /**
   * A padding lane `s` of packets `words` f64 words long: the spare row on both sides, its f64 fields 1..`fields`
   * (words 2, 4, … of the lane) zero, and 1 at its word `allowance` (apart: it never acts, no friction). Returns the
   * lane's first f64 word.
   */
  #pad(s: number, words: number, fields: number, allowance: number): number {
    const f64 = this.#f64;
    const packet = this.#rigidAddress / 8 + (s >> 1) * words;
    const w = packet + (s & 1);
    this.#i32[2 * packet + (s & 1)] = this.#i32[2 * packet + (s & 1) + 2] = this.#capacity * 8;
    for (let field = 1; field <= fields; field++) f64[w + 2 * field] = 0;
    f64[w + allowance] = 1;
    return w;
  }

  /** Places the particle columns, the runs and the coloured packets in the memory (growing it if needed). */
  #layOut(ctx: StepContext): void {
    const { particles: p, sleep } = ctx;
    const c = ctx.constraints.distances;
    const capacity = p.x.length;
    // Save every column first: the new places may overlap the old (or a new memory replace the old).
    const saved = COLUMNS.map((name) => p[name].slice(0, capacity));
    const runs = findRuns(c.count, c.a, c.b, c.minLength, c.maxLength, c.compliance);
    // Immovable particles may share a packet: pinned and static ones, not those that only sleep (they wake).
    const awakeInvMass = p.invMass.map((w, i) => (i < p.count ? sleep.awakeInvMass(i, p) : w));
    const slack = Uint8Array.from(c.minLength.subarray(0, c.count), (lo, row) => (lo === c.maxLength[row] ? 0 : 1));
    this.#packetRows = runs.leftover.length > 0 ? colourRows(c.count, c.a, c.b, slack, awakeInvMass, 2, runs.leftover) : new Int32Array(0);
    const packetCount = this.#packetRows.length / 2;
    const runCount = runs.lanes.length;
    const runData = new Int32Array(runCount);
    let dataBytes = 0;
    for (let k = 0; k < runCount; k++) {
      runData[k] = dataBytes;
      dataBytes += ((runs.laneStart[k + 1] - runs.laneStart[k]) / 2) * PAIR_BYTES[runs.kind[k]];
    }
    const columnBytes = align16((capacity + SPARE_ROWS) * 8);
    const runAddress = COLUMNS.length * columnBytes;
    const dataAddress = runAddress + align16(runCount * RUN_BYTES);
    const packetAddress = dataAddress + dataBytes;
    const rigidAddress = align16(packetAddress + packetCount * PACKET_BYTES);
    const bytes = rigidAddress + this.#rigidCapacity;
    // (Everything is written again below: the new memory need not keep the old bytes.)
    if (bytes > this.#memory.buffer.byteLength) this.#replaceMemory(bytes * 1.5, false);
    const buffer = this.#memory.buffer;
    this.#f64 = new Float64Array(buffer);
    this.#i32 = new Int32Array(buffer);
    COLUMNS.forEach((name, k) => {
      const address = k * columnBytes;
      const full = new Float64Array(buffer, address, capacity + SPARE_ROWS);
      full.fill(0);
      full.set(saved[k]);
      (p as unknown as Record<KernelColumn, Float64Array>)[name] = full.subarray(0, capacity);
      this.#address[name] = address;
    });
    this.#capacity = capacity;
    // The rigid lanes' world row: at the origin, rotation (1, 0), inverse mass and inertia 0.
    this.#f64[(this.#address.rc >> 3) + capacity + 1] = 1;
    this.#rigidAddress = rigidAddress;
    // Run records.
    for (let k = 0; k < runCount; k++) {
      const r = (runAddress + k * RUN_BYTES) >> 2;
      runData[k] += dataAddress;
      this.#i32[r] = runs.first[k] * 8;
      this.#i32[r + 1] = runs.second[k] * 8;
      this.#i32[r + 2] = (runs.laneStart[k + 1] - runs.laneStart[k]) / 2;
      this.#i32[r + 3] = runs.interleaved[k] | (runs.kind[k] << 1);
      this.#i32[r + 4] = runData[k];
    }
    this.#runs = runs;
    this.#runData = runData;
    this.#runAddress = runAddress;
    this.#runCount = runCount;
    this.#packetAddress = packetAddress;
    this.#packetCount = packetCount;
    this.#laidOutRows = c.count;
    this.#f64.fill(0, dataAddress / 8, rigidAddress / 8);
    this.#writePackets(c);
    this.#copyLimits(c);
    this.#structureChanged = false;
    this.layouts++;
  }

  /** Particle offsets of each packet; padding lanes point at a spare row (index `capacity`, inverse mass 0). */
  #writePackets(c: DistanceConstraints): void {
    const rows = this.#packetRows, i32 = this.#i32;
    const dummy = this.#capacity * 8;
    const base = this.#packetAddress >> 2;
    for (let lane = 0, n = rows.length; lane < n; lane++) {
      const row = rows[lane];
      const ints = base + (lane >> 1) * PACKET_I32 + (lane & 1);
      i32[ints] = row < 0 ? dummy : c.a[row] * 8;
      i32[ints + 2] = row < 0 ? dummy : c.b[row] * 8;
    }
  }

  /**
   * Limits and compliance of every lane from the distance table. False when a row no longer fits its run's kind (the
   * runs must be found again).
   */
  #copyLimits(c: DistanceConstraints): boolean {
    const f64 = this.#f64;
    const { minLength, maxLength, compliance } = c;
    this.#limitsChanged = false;
    const runs = this.#runs;
    if (runs) {
      for (let k = 0; k < this.#runCount; k++) {
        const kind = runs.kind[k] as RunKind;
        const data = this.#runData[k] / 8;
        const start: number = runs.laneStart[k];
        const end: number = runs.laneStart[k + 1];
        for (let lane: number = start; lane < end; lane++) {
          const row = runs.rows[lane];
          // f64 word of this lane's first field: pairs of lanes, each field an f64×2.
          const f = data + ((lane - start) >> 1) * (PAIR_BYTES[kind] / 8) + ((lane - start) & 1);
          const broken = row >= 0 && minLength[row] === 0 && maxLength[row] === Infinity;
          if (row >= 0 && !broken && kindOf(minLength, maxLength, compliance, row) !== kind) return false;
          if (kind === RunKind.Stick) {
            // NaN: the lane does nothing (a padding lane, or a broken link, whose limits are open).
            f64[f] = row < 0 || broken ? NaN : minLength[row];
            continue;
          }
          f64[f] = row < 0 ? 0 : minLength[row];
          f64[f + 2] = row < 0 ? Infinity : maxLength[row];
          if (kind === RunKind.Compliant) f64[f + 4] = row < 0 ? 0 : compliance[row];
        }
      }
    }
    const base = this.#packetAddress / 8;
    const rows = this.#packetRows;
    for (let lane = 0, n = rows.length; lane < n; lane++) {
      const row = rows[lane];
      if (row < 0) continue;
      const f = base + (lane >> 1) * PACKET_F64 + (lane & 1);
      f64[f + LO] = minLength[row];
      f64[f + HI] = maxLength[row];
      f64[f + COMPLIANCE] = compliance[row];
    }
    return true;
  }
}

/**
 * Whether the lanes take the step's rigid contacts: 0 no, 1 as single points (all lone), 2 by manifold (some pairs).
 * Each point between two rows or with the world (no particle-built edge point, no particle frame's corner: its stops
 * are solved again in pipeline/frame-bounces.ts), restitution 0, no shock sweep; a
 * pair's partner follows it (the same bodies); by manifold only when no side is round;
 * not while the step measures its rims' arcs exactly
 * (contacts.ts FAST_TURN: the lanes' series falls short there).
 */
function lanesFit(c: RigidContacts): 0 | 1 | 2 {
  if (c.shockCount > 0 || c.edgePoints > 0 || arcsExact()) return 0;
  const { pair, b2, restitution, a, b, radA, radB, frameRow } = c;
  let fit: 0 | 1 | 2 = 1;
  let round = false;
  for (let i = 0, n = c.count; i < n; i++) {
    // A particle frame's corner: its stops are solved again with the frame as one body (pipeline/frame-bounces.ts).
    if (b2[i] >= 0 || restitution[i] !== 0 || a[i] < 0 || (b[i] >= 0 && frameRow[b[i]] === 1)) return 0;
    if (radA[i] > 0 || radB[i] > 0) round = true;
    if (pair[i] === 1) {
      const j = i + 1;
      if (j >= n || b2[j] >= 0 || restitution[j] !== 0 || a[j] !== a[i] || b[j] !== b[i] || pair[j] !== 0) return 0;
      fit = 2;
      i++;
    } else if (pair[i] !== 0) return 0;
  }
  // The manifold lanes hold no round side (their sweep has no rim arcs: solver.as): such a step is the JS solver's.
  return fit === 2 && round ? 0 : fit;
}

/** Contact i's normal levers lAx, lAy, lBx, lBy from a lane's f64 words w, w + 2, w + 4, w + 6 (rigid packet: field 21 on; manifold: a point's 11 on). */
function leversBack(c: RigidContacts, f64: Float64Array, i: number, w: number): void {
  c.lAx[i] = f64[w];
  c.lAy[i] = f64[w + 2];
  c.lBx[i] = f64[w + 4];
  c.lBy[i] = f64[w + 6];
}

function align16(bytes: number): number {
  return (bytes + 15) & ~15;
}
