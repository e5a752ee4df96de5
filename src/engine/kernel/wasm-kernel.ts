// The WebAssembly SIMD kernel's TypeScript side: it owns one WebAssembly.Memory that holds the engine's own particle
// columns (the ParticleStore's x, y, px, … become views into it: one copy of the state, which the JS phases and the
// kernel share) and the distance constraints in coloured packets (see solver.as for their layout).
//
// Growth: a Table that outgrows its columns replaces them with plain arrays (table.ts); the next step sees that a
// column no longer lives in the memory and lays everything out again. The packets are coloured again when the
// constraints' structure changes (the topology is rebuilt) and their limits refreshed when links break; the kernel
// reads inverse masses from the particle column itself. Only a new layout allocates.
import type { ParticleStore } from '../particles.js';
import type { DistanceConstraints } from '../constraints/distance.js';
import type { StepContext } from '../pipeline/context.js';
import { colourRows } from './colour.js';

/** The columns the kernel reads or writes, in the order they are laid out. */
const COLUMNS = ['x', 'y', 'px', 'py', 'vx', 'vy', 'ax', 'ay', 'invMass'] as const;
type KernelColumn = (typeof COLUMNS)[number];

/** Bytes per packet of two constraints, and where its fields are in f64 and i32 words (see solver.as). */
const PACKET_BYTES = 80;
const PACKET_F64 = PACKET_BYTES / 8;
const PACKET_I32 = PACKET_BYTES / 4;
const LO = 2;
const HI = 4;
const COMPLIANCE = 6;
const PAGE = 65536;

interface KernelExports {
  solveDistances(x: number, y: number, invMass: number, packets: number, count: number, h2: number, fresh: boolean): void;
  integrateVerlet(x: number, y: number, px: number, py: number, vx: number, vy: number, ax: number, ay: number, invMass: number, n: number, h: number, damp: number): void;
  updateVelocities(x: number, y: number, px: number, py: number, vx: number, vy: number, n: number, inv: number): void;
}

export class WasmKernel {
  readonly name = 'wasm';
  private readonly memory = new WebAssembly.Memory({ initial: 1 });
  private readonly exports: KernelExports;
  /** Byte address of each column in the memory (valid while the columns are views into it). */
  private readonly address = Object.fromEntries(COLUMNS.map((c) => [c, 0])) as Record<KernelColumn, number>;
  /** Rows the columns have room for (their length; the memory holds two more: the padding lanes' dummy row). */
  private capacity = 0;
  private packetAddress = 0;
  private packetCapacity = 0;
  packetCount = 0;
  /** Per packet lane: the distance row it solves, -1 for padding. */
  private rows: Int32Array = new Int32Array(0);
  /** Padding lanes in the packets. */
  private padding = 0;
  /** The packets as f64 and i32 words (made with each layout: the memory only grows then). */
  private packetF64: Float64Array = new Float64Array(0);
  private packetI32: Int32Array = new Int32Array(0);
  /** The constraints changed (colour again), or some limits did (copy them again). */
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

  /** Before a step's substeps: the columns live in the memory, the packets match the constraints. */
  beginStep(ctx: StepContext): void {
    const { particles: p, constraints } = ctx;
    const c = constraints.distances;
    let layout = this.structureChanged || c.count !== this.rows.length - this.padding;
    for (const name of COLUMNS) if (p[name].buffer !== this.memory.buffer) layout = true;
    if (layout) this.layOut(ctx);
    else if (this.limitsChanged) this.copyLimits(c);
  }

  integrateVerlet(p: ParticleStore, h: number, damp: number): void {
    const m = this.address;
    this.exports.integrateVerlet(m.x, m.y, m.px, m.py, m.vx, m.vy, m.ax, m.ay, m.invMass, p.count, h, damp);
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
    const m = this.address;
    this.exports.solveDistances(m.x, m.y, m.invMass, this.packetAddress, this.packetCount, h2, this.freshLambdas);
    this.freshLambdas = false;
  }

  /** Bytes of memory the kernel holds (diagnostics). */
  get memoryBytes(): number {
    return this.memory.buffer.byteLength;
  }

  /** Places the particle columns and the coloured packets in the memory (growing it if needed). */
  private layOut(ctx: StepContext): void {
    const { particles: p, sleep } = ctx;
    const c = ctx.constraints.distances;
    const capacity = p.x.length;
    // Save every column first: the new places may overlap the old, and growing the memory detaches the old views.
    const saved = COLUMNS.map((name) => p[name].slice(0, capacity));
    // Immovable particles may share a batch: pinned and static ones, not those that only sleep (they wake).
    const awakeInvMass = p.invMass.map((w, i) => (i < p.count ? sleep.awakeInvMass(i, p) : w));
    const slack = Uint8Array.from(c.minLength.subarray(0, c.count), (lo, row) => (lo === c.maxLength[row] ? 0 : 1));
    this.rows = colourRows(c.count, c.a, c.b, slack, awakeInvMass);
    const packetCount = this.rows.length / 2;
    const columnBytes = align16((capacity + 2) * 8);
    const packetCapacity = Math.max(packetCount, this.packetCapacity);
    const bytes = COLUMNS.length * columnBytes + packetCapacity * PACKET_BYTES;
    if (bytes > this.memory.buffer.byteLength) this.memory.grow(Math.ceil((bytes * 1.5 - this.memory.buffer.byteLength) / PAGE));
    const buffer = this.memory.buffer;
    COLUMNS.forEach((name, k) => {
      const address = k * columnBytes;
      const full = new Float64Array(buffer, address, capacity + 2);
      full.fill(0);
      full.set(saved[k]);
      (p as unknown as Record<KernelColumn, Float64Array>)[name] = full.subarray(0, capacity);
      this.address[name] = address;
    });
    this.capacity = capacity;
    this.packetAddress = COLUMNS.length * columnBytes;
    this.packetCapacity = packetCapacity;
    this.packetCount = packetCount;
    this.padding = this.rows.length - c.count;
    this.packetF64 = new Float64Array(buffer, this.packetAddress, packetCount * PACKET_F64);
    this.packetI32 = new Int32Array(buffer, this.packetAddress, packetCount * PACKET_I32);
    this.writePackets(c);
    this.copyLimits(c);
    this.structureChanged = false;
    this.layouts++;
  }

  /** Particle offsets of each packet; padding lanes point at the dummy row (index `capacity`, inverse mass 0). */
  private writePackets(c: DistanceConstraints): void {
    const { rows, packetF64: f64, packetI32: i32 } = this;
    const dummy = this.capacity * 8;
    f64.fill(0);
    for (let lane = 0, n = rows.length; lane < n; lane++) {
      const row = rows[lane];
      const ints = (lane >> 1) * PACKET_I32 + (lane & 1);
      i32[ints] = row < 0 ? dummy : c.a[row] * 8;
      i32[ints + 2] = row < 0 ? dummy : c.b[row] * 8;
    }
  }

  /** Limits and compliance of every lane from the distance table. */
  private copyLimits(c: DistanceConstraints): void {
    const { rows, packetF64: f64 } = this;
    const { minLength, maxLength, compliance } = c;
    for (let lane = 0, n = rows.length; lane < n; lane++) {
      const row = rows[lane];
      if (row < 0) continue;
      const f = (lane >> 1) * PACKET_F64 + (lane & 1);
      f64[f + LO] = minLength[row];
      f64[f + HI] = maxLength[row];
      f64[f + COMPLIANCE] = compliance[row];
    }
    this.limitsChanged = false;
  }
}

function align16(bytes: number): number {
  return (bytes + 15) & ~15;
}
