// The WebAssembly SIMD kernel's TypeScript side: it owns one WebAssembly.Memory that holds the engine's own particle
// columns (the ParticleStore's x, y, px, … become views into it: one copy of the state, which the JS phases and the
// kernel share) and the distance constraints, as runs (runs.ts: contiguous lanes, no indices) and, for the rest,
// coloured packets (colour.ts); see solver.as for their layout.
//
// Growth: a Table that outgrows its columns replaces them with plain arrays (table.ts); the next step sees that a
// column no longer lives in the memory and lays everything out again. The runs and packets are found again when the
// constraints' structure changes (the topology is rebuilt) and their limits refreshed when links break; the kernel
// reads inverse masses from the particle column itself. Only a new layout allocates.
import type { ParticleStore } from '../particles.js';
import type { DistanceConstraints } from '../constraints/distance.js';
import type { StepContext } from '../pipeline/context.js';
import { colourRows } from './colour.js';
import { findRuns, kindOf, RunKind, type RunLayout } from './runs.js';

/** The columns the kernel reads or writes, in the order they are laid out. */
const COLUMNS = ['x', 'y', 'px', 'py', 'vx', 'vy', 'ax', 'ay', 'fx', 'fy', 'invMass'] as const;
type KernelColumn = (typeof COLUMNS)[number];
/** Rows past the columns' length: the padding lanes of runs and packets read (and write back unchanged) up to 3. */
const SPARE_ROWS = 4;

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

interface KernelExports {
  solveDistances(x: number, y: number, invMass: number, runs: number, runCount: number, packets: number, count: number, h2: number, fresh: boolean): void;
  integrateVerlet(x: number, y: number, px: number, py: number, vx: number, vy: number, ax: number, ay: number, invMass: number, n: number, h: number, damp: number, forces: boolean, gx: number, gy: number): void;
  updateVelocities(x: number, y: number, px: number, py: number, vx: number, vy: number, n: number, inv: number): void;
}

export class WasmKernel {
  readonly name = 'wasm';
  private readonly memory = new WebAssembly.Memory({ initial: 1 });
  private readonly exports: KernelExports;
  /** Byte address of each column in the memory (valid while the columns are views into it). */
  private readonly address = Object.fromEntries(COLUMNS.map((c) => [c, 0])) as Record<KernelColumn, number>;
  /** Rows the columns have room for (their length; the memory holds SPARE_ROWS more, zero). */
  private capacity = 0;
  private runAddress = 0;
  runCount = 0;
  private runs: RunLayout | null = null;
  /** Byte address of each run's lane data. */
  private runData: Int32Array = new Int32Array(0);
  private packetAddress = 0;
  packetCount = 0;
  /** Per packet lane: the distance row it solves, -1 for padding. */
  private packetRows: Int32Array = new Int32Array(0);
  /** Distance rows laid out (runs and packets): a different count means the table changed. */
  private laidOutRows = -1;
  /** The memory as f64 and i32 words (made with each layout: the memory only grows then). */
  private f64: Float64Array = new Float64Array(0);
  private i32: Int32Array = new Int32Array(0);
  /** The constraints changed (find the runs again), or some limits did (copy them again). */
  private structureChanged = true;
  private limitsChanged = false;
  /** No sweep has run since the multipliers were reset. */
  private freshLambdas = true;
  /** Layouts made (diagnostics and tests: steady stepping makes none). */
  layouts = 0;

  constructor(module: WebAssembly.Module) {
    const instance = new WebAssembly.Instance(module, { env: { memory: this.memory } });
    this.exports = instance.exports as unknown as KernelExports;
  }

  /** Bodies, particles or constraints were added, removed or restored. */
  topologyChanged(): void {
    this.structureChanged = true;
  }

  /** Some links' limits changed (they broke). */
  distanceLimitsChanged(): void {
    this.limitsChanged = true;
  }

  /** Before a step's substeps: the columns live in the memory, the runs and packets match the constraints. */
  beginStep(ctx: StepContext): void {
    const { particles: p, constraints } = ctx;
    const c = constraints.distances;
    let layout = this.structureChanged || c.count !== this.laidOutRows;
    for (const name of COLUMNS) if (p[name].buffer !== this.memory.buffer) layout = true;
    // A link whose limits no longer fit its run's kind (only a break changes them, and a broken link fits any kind).
    if (!layout && this.limitsChanged && !this.copyLimits(c)) layout = true;
    if (layout) this.layOut(ctx);
  }

  /**
   * Position Verlet. `gravity` given: the accelerations are g + f·invMass, computed here (the step's accelerate phase,
   * fused; the ax/ay columns are then not written); null: read from ax/ay (springs added to them).
   */
  integrateVerlet(p: ParticleStore, h: number, damp: number, gravity: { x: number; y: number } | null): void {
    const m = this.address;
    if (gravity) this.exports.integrateVerlet(m.x, m.y, m.px, m.py, m.vx, m.vy, m.fx, m.fy, m.invMass, p.count, h, damp, true, gravity.x, gravity.y);
    else this.exports.integrateVerlet(m.x, m.y, m.px, m.py, m.vx, m.vy, m.ax, m.ay, m.invMass, p.count, h, damp, false, 0, 0);
  }

  updateVelocities(p: ParticleStore, h: number): void {
    const m = this.address;
    this.exports.updateVelocities(m.x, m.y, m.px, m.py, m.vx, m.vy, p.count, 1 / h);
  }

  /** The multipliers start each substep at zero: the next sweep does not read them. */
  resetLambdas(): void {
    this.freshLambdas = true;
  }

  solveDistances(h2: number): void {
    if (this.runCount === 0 && this.packetCount === 0) return;
    const m = this.address;
    this.exports.solveDistances(m.x, m.y, m.invMass, this.runAddress, this.runCount, this.packetAddress, this.packetCount, h2, this.freshLambdas);
    this.freshLambdas = false;
  }

  /** Bytes of memory the kernel holds (diagnostics). */
  get memoryBytes(): number {
    return this.memory.buffer.byteLength;
  }

  /** Distance rows solved in runs and in packets (diagnostics and tests). */
  get layoutCounts(): { runs: number; runLinks: number; packetLinks: number } {
    const runLinks = this.runs ? this.runs.rows.reduce((n, r) => n + (r >= 0 ? 1 : 0), 0) : 0;
    return { runs: this.runCount, runLinks, packetLinks: this.packetRows.reduce((n, r) => n + (r >= 0 ? 1 : 0), 0) };
  }

  /** Places the particle columns, the runs and the coloured packets in the memory (growing it if needed). */
  private layOut(ctx: StepContext): void {
    const { particles: p, sleep } = ctx;
    const c = ctx.constraints.distances;
    const capacity = p.x.length;
    // Save every column first: the new places may overlap the old, and growing the memory detaches the old views.
    const saved = COLUMNS.map((name) => p[name].slice(0, capacity));
    const runs = findRuns(c.count, c.a, c.b, c.minLength, c.maxLength, c.compliance);
    // Immovable particles may share a packet: pinned and static ones, not those that only sleep (they wake).
    const awakeInvMass = p.invMass.map((w, i) => (i < p.count ? sleep.awakeInvMass(i, p) : w));
    const slack = Uint8Array.from(c.minLength.subarray(0, c.count), (lo, row) => (lo === c.maxLength[row] ? 0 : 1));
    this.packetRows = runs.leftover.length > 0 ? colourRows(c.count, c.a, c.b, slack, awakeInvMass, 2, runs.leftover) : new Int32Array(0);
    const packetCount = this.packetRows.length / 2;
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
    const bytes = packetAddress + packetCount * PACKET_BYTES;
    if (bytes > this.memory.buffer.byteLength) this.memory.grow(Math.ceil((bytes * 1.5 - this.memory.buffer.byteLength) / PAGE));
    const buffer = this.memory.buffer;
    this.f64 = new Float64Array(buffer);
    this.i32 = new Int32Array(buffer);
    COLUMNS.forEach((name, k) => {
      const address = k * columnBytes;
      const full = new Float64Array(buffer, address, capacity + SPARE_ROWS);
      full.fill(0);
      full.set(saved[k]);
      (p as unknown as Record<KernelColumn, Float64Array>)[name] = full.subarray(0, capacity);
      this.address[name] = address;
    });
    this.capacity = capacity;
    // Run records.
    for (let k = 0; k < runCount; k++) {
      const r = (runAddress + k * RUN_BYTES) >> 2;
      runData[k] += dataAddress;
      this.i32[r] = runs.first[k] * 8;
      this.i32[r + 1] = runs.second[k] * 8;
      this.i32[r + 2] = (runs.laneStart[k + 1] - runs.laneStart[k]) / 2;
      this.i32[r + 3] = runs.interleaved[k] | (runs.kind[k] << 1);
      this.i32[r + 4] = runData[k];
    }
    this.runs = runs;
    this.runData = runData;
    this.runAddress = runAddress;
    this.runCount = runCount;
    this.packetAddress = packetAddress;
    this.packetCount = packetCount;
    this.laidOutRows = c.count;
    this.f64.fill(0, dataAddress / 8, bytes / 8);
    this.writePackets(c);
    this.copyLimits(c);
    this.structureChanged = false;
    this.layouts++;
  }

  /** Particle offsets of each packet; padding lanes point at a spare row (index `capacity`, inverse mass 0). */
  private writePackets(c: DistanceConstraints): void {
    const { packetRows: rows, i32 } = this;
    const dummy = this.capacity * 8;
    const base = this.packetAddress >> 2;
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
  private copyLimits(c: DistanceConstraints): boolean {
    const { f64 } = this;
    const { minLength, maxLength, compliance } = c;
    this.limitsChanged = false;
    const runs = this.runs;
    if (runs) {
      for (let k = 0; k < this.runCount; k++) {
        const kind = runs.kind[k] as RunKind;
        const data = this.runData[k] / 8;
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
    const base = this.packetAddress / 8;
    const rows = this.packetRows;
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

function align16(bytes: number): number {
  return (bytes + 15) & ~15;
}
