// Probe (issue 16): does the rigid contact solve win in WebAssembly SIMD lanes? The contacts of a disc pile are
// coloured each step into batches that share no movable body, laid out two lanes a packet (f64x2), and swept by the
// kernel's rigidSweep / rigidVelocities (src/engine/kernel/solver.as, shipped since: wasm-kernel.ts colours and lays
// out as this bench does) against the JS solveRigidContacts / solveRigidContactVelocities on the same contacts and
// the same state; --f32 adds the f32x4 probe of experiment-rigid.as.
//
//   node bench/experiment-rigid.mjs                       S3 (2,000 circles) and the 10,000-circle pile, both parts
//   node bench/experiment-rigid.mjs --scenes s3 --steps 60 --settle 600
//   node bench/experiment-rigid.mjs --no-quality          only the per-sweep A/B (--no-ab: only the whole steps)
//   node bench/experiment-rigid.mjs --f32                 also an f32x4 sweep over float32 copies of the body columns
//   node bench/experiment-rigid.mjs --serial              one contact a packet in list order: the JS doubles, exactly
//   valgrind --tool=callgrind ... node --no-liftoff bench/experiment-rigid.mjs --count js|lanes|none   (see below)
//
// Part 1, per-sweep A/B: the engine steps with the JS solver (the reference trajectory); in every substep the position
// sweep runs three times on the same input (restored in between, untimed): JS over plain columns (today's engine), JS
// over the same columns placed in WebAssembly memory, and the lanes; then the velocity pass likewise. It reports
// medians of the per-substep times and of their paired ratios, the largest difference of the lanes' result from
// the JS one, the colouring and layout (once per step) and the unpack a step's end would need.
// Part 2, quality and whole steps: two worlds from the same start, one with the JS solver (plain columns), one with the
// lanes doing every sweep and velocity pass (columns in WebAssembly memory, coloured and laid out each step, unpacked
// at the step's end), stepped alternately: CPU ms per step and the deepest disc overlap (% of a diameter) every 100
// steps. What the lanes cover is what disc piles hold: single points between two rows, restitution 0, no shock sweep
// (checked each step; anything else throws).
import { build } from 'esbuild';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { join } from 'node:path';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { compileKernel } from '../scripts/build-wasm.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const arg = (name, fallback) => (process.argv.includes(name) ? process.argv[process.argv.indexOf(name) + 1] : fallback);

// ---- the engine, with hooks around the rigid solver's three entry points (a build-time wrapper: no source edited) --
const SOLVER = /src[\\/]engine[\\/]rigid[\\/]contact-solver\.ts$/;
const hookPlugin = {
  name: 'rigid-hooks',
  setup(b) {
    b.onLoad({ filter: SOLVER }, (args) => {
      let text = readFileSync(args.path, 'utf8');
      for (const name of ['prepareRigidContacts', 'solveRigidContacts', 'solveRigidContactVelocities']) {
        if (!text.includes(`export function ${name}(`)) throw new Error(`contact-solver.ts no longer exports ${name}(: update the hooks`);
        text = text.replace(`export function ${name}(`, `export function ${name}Js(`);
      }
      text += `
export const hooks = { prepare: null, sweep: null, velocity: null };
export function prepareRigidContacts(c, r, maxPush = -1) { if (hooks.prepare) hooks.prepare(c, r, maxPush); else prepareRigidContactsJs(c, r, maxPush); }
export function solveRigidContacts(c, r) { if (hooks.sweep) hooks.sweep(c, r); else solveRigidContactsJs(c, r); }
export function solveRigidContactVelocities(c, r, h) { if (hooks.velocity) hooks.velocity(c, r, h); else solveRigidContactVelocitiesJs(c, r, h); }
`;
      return { contents: text, loader: 'ts' };
    });
  },
};
const ENTRY = `
export { World, catalogue, buildScene } from './src/engine/index.ts';
export { hooks, prepareRigidContactsJs, solveRigidContactsJs, solveRigidContactVelocitiesJs } from './src/engine/rigid/contact-solver.ts';
`;
const out = `${root}node_modules/.cache/physics-elements/experiment-rigid-${process.pid}.mjs`;
await build({ stdin: { contents: ENTRY, resolveDir: root, loader: 'ts' }, bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile: out, logLevel: 'error', plugins: [hookPlugin] });
const E = await import(pathToFileURL(out).href);
rmSync(out);
const { hooks } = E;

// The shipped lanes (solver.as: rigidBegin, rigidSweep, rigidVelocities) and the f32x4 probe (experiment-rigid.as) in
// one module.
const asDir = mkdtempSync(join(tmpdir(), 'experiment-rigid-'));
const asFile = join(asDir, 'experiment.as');
writeFileSync(asFile, ['solver.as', 'experiment-rigid.as'].map((f) => readFileSync(new URL(`../src/engine/kernel/${f}`, import.meta.url), 'utf8')).join('\n'));
const { bytes } = await compileKernel(asFile);
rmSync(asDir, { recursive: true, force: true });
const wasmModule = new WebAssembly.Module(bytes);

// ---- scenes -----------------------------------------------------------------------------------------------------
const SCENES = {
  s3: {
    title: 'S3, 2,000 circles r 0.5 (catalogue)',
    settle: 600,
    steps: 60,
    quality: 600,
    make: () => {
      const d = E.catalogue.circles.make();
      return E.buildScene({ ...d, world: { ...d.world, sleeping: false } }).world;
    },
  },
  c10k: {
    title: '10,000 circles r 0.5 in a container 100 wide (bench/kernel.mjs)',
    settle: 600,
    steps: 20,
    quality: 600,
    make: () => {
      const base = E.catalogue.circles.make();
      const walls = base.bodies.filter((b) => b.static).map((b) => (b.id === 'floor' ? { ...b, width: 102 } : { ...b, x: Math.sign(b.x) * 50.5 }));
      const circles = Array.from({ length: 10000 }, (_, k) => {
        const row = Math.floor(k / 80);
        return { type: 'circle', x: ((k % 80) - 40) * 1.2 + (row % 2 ? 0.3 : -0.3), y: -2 - row * 1.2, radius: 0.5 };
      });
      return E.buildScene({ world: { ...base.world, sleeping: false }, bodies: [...walls, ...circles] }).world;
    },
  },
};

// ---- the lanes: body columns in WebAssembly memory, colouring and layout ----------------------------------------
const COLUMNS = ['x', 'y', 'angle', 'qangle', 'rc', 'rs', 'vx', 'vy', 'omega', 'invMass', 'invInertia', 'px', 'py', 'pangle'];
const PACKET = 448;
const PF = PACKET / 8; // f64 words a packet
const PI = PACKET / 4; // i32 words a packet
// Field index k: the lane pair at f64 word 2k of the packet (see experiment-rigid.as).
const F = { nx: 1, ny: 2, rAx: 3, rAy: 4, rBx: 5, rBy: 6, radA: 7, radB: 8, friction: 9, imA: 10, iiA: 11, imB: 12, iiB: 13, allowance: 14, lambdaN: 15, impulseN: 16, impulseT: 17, slip: 18, gap: 19, touched: 20, lAx: 21, lAy: 22, lBx: 23, lBy: 24, rnA: 25, rnB: 26, wn: 27 };
const PACKET4 = 464; // the f32x4 variant's packet of four points: i32x4 a, i32x4 b, then field k at 16 + 16k
const P4 = PACKET4 / 4;
const F32_COLUMNS = ['x', 'y', 'angle', 'qangle', 'rc', 'rs'];
const STATIC_FIELDS = ['nx', 'ny', 'rAx', 'rAy', 'rBx', 'rBy', 'radA', 'radB', 'friction'];
const STATE_FIELDS = ['allowance', 'lambdaN', 'impulseN', 'impulseT', 'slip', 'gap'];
const LEVER_FIELDS = ['lAx', 'lAy', 'lBx', 'lBy', 'rnA', 'rnB', 'wn'];

class Lanes {
  constructor(world) {
    this.world = world;
    const p = world.ctx.particles;
    this.p = p;
    this.rows = p.x.length; // the columns' capacity; row `rows` is the padding lanes' spare row (all zero)
    this.memory = new WebAssembly.Memory({ initial: 1 });
    this.exports = new WebAssembly.Instance(wasmModule, { env: { memory: this.memory } }).exports;
    this.columnBytes = (this.rows + 2) * 8;
    this.packetBase = COLUMNS.length * this.columnBytes;
    this.packetBase += (16 - (this.packetBase % 16)) % 16;
    this.address = {};
    this.packetCapacity = 0;
    this.grow(1024);
    // Masks of the colours each movable row takes part in (two u32 words: 64 colours), and the per-contact colour.
    this.low = new Uint32Array(this.rows + 1);
    this.high = new Uint32Array(this.rows + 1);
    this.lowS = new Uint32Array(this.rows + 1);
    this.highS = new Uint32Array(this.rows + 1);
    this.colourOf = new Int16Array(1024);
    this.slotOf = new Int32Array(1024);
    this.sizes = new Int32Array(128);
    this.start = new Int32Array(129);
    this.cursor = new Int32Array(1024);
    this.colours = [0, 0];
    this.packets = 0;
    this.tail = 0;
  }

  /** Room for `packets` packets; the body columns move into the memory (views replace the engine's arrays). */
  grow(packets) {
    if (packets <= this.packetCapacity) return;
    this.packetCapacity = Math.max(packets, 2 * this.packetCapacity);
    // The f32x4 variant's region after the packets: float32 copies of the sweep's body columns, then its packets.
    this.colBytes4 = Math.ceil(((this.rows + 4) * 4) / 16) * 16;
    this.f32Base = this.packetBase + this.packetCapacity * PACKET;
    this.packet4Base = this.f32Base + F32_COLUMNS.length * this.colBytes4;
    const need = this.packet4Base + this.packetCapacity * PACKET4;
    const have = this.memory.buffer.byteLength;
    // Keep the state: copy the columns out before the buffer grows (views of a grown memory are detached).
    const saved = COLUMNS.map((name) => this.p[name].slice());
    if (need > have) this.memory.grow(Math.ceil((need - have) / 65536));
    const buffer = this.memory.buffer;
    COLUMNS.forEach((name, k) => {
      const address = k * this.columnBytes;
      this.address[name] = address;
      const view = new Float64Array(buffer, address, this.rows);
      view.set(saved[k]);
      new Float64Array(buffer, address + this.rows * 8, 2).fill(0);
      this.p[name] = view;
    });
    this.f64 = new Float64Array(buffer);
    this.i32 = new Int32Array(buffer);
    this.f32 = new Float32Array(buffer);
    this.address4 = {};
    F32_COLUMNS.forEach((name, k) => (this.address4[name] = this.f32Base + k * this.colBytes4));
  }

  /** The f32x4 layout of the same colours (batches padded to multiples of four). */
  layout4(c) {
    const n = c.count;
    if (!this.slot4Of || this.slot4Of.length < n) this.slot4Of = new Int32Array(2 * n);
    const { sizes, colourOf, f32, i32, slot4Of } = this;
    const start = new Int32Array(129);
    for (let k = 0; k < 128; k++) start[k + 1] = start[k] + ((sizes[k] + 3) & ~3);
    this.packets4 = start[128] >> 2;
    const cursor = start.slice(0, 128);
    const base = this.packet4Base / 4;
    const spare = this.rows * 4;
    for (let k = 0; k < 128; k++) {
      for (let s = start[k] + sizes[k]; s < start[k + 1]; s++) {
        const w = base + (s >> 2) * P4 + (s & 3);
        i32[w] = spare;
        i32[w + 4] = spare;
        for (let field = 1; field <= 27; field++) f32[w + 4 + 4 * field] = 0;
        f32[w + 4 + 4 * F.allowance] = 1;
      }
    }
    const { invMass, invInertia } = this.p;
    const { a: A, b: B, nx, ny, rAx, rAy, rBx, rBy, radA, radB, friction } = c;
    for (let i = 0; i < n; i++) {
      const s = cursor[colourOf[i]]++;
      slot4Of[i] = s;
      const w = base + (s >> 2) * P4 + (s & 3);
      i32[w] = A[i] * 4;
      i32[w + 4] = B[i] * 4;
      const v = w + 4;
      f32[v + 4] = nx[i];
      f32[v + 8] = ny[i];
      f32[v + 12] = rAx[i];
      f32[v + 16] = rAy[i];
      f32[v + 20] = rBx[i];
      f32[v + 24] = rBy[i];
      f32[v + 28] = radA[i];
      f32[v + 32] = radB[i];
      f32[v + 36] = friction[i];
      f32[v + 40] = invMass[A[i]];
      f32[v + 44] = invInertia[A[i]];
      f32[v + 48] = invMass[B[i]];
      f32[v + 52] = invInertia[B[i]];
    }
    this.packState4(c);
  }

  /** The per-substep state into the f32x4 lanes. */
  packState4(c) {
    const { f32, i32, slot4Of } = this;
    const base = this.packet4Base / 4;
    const cols = STATE_FIELDS.map((name) => [c[name], F[name]]);
    for (let i = 0, n = c.count; i < n; i++) {
      const s = slot4Of[i];
      const v = base + (s >> 2) * P4 + (s & 3) + 4;
      for (let k = 0; k < cols.length; k++) f32[v + 4 * cols[k][1]] = cols[k][0][i];
      i32[v + 4 * F.touched] = c.touched[i] ? -1 : 0;
    }
  }

  /** The f32x4 sweep: the body columns demoted to float32, swept, x, y and angle promoted back ({demote, sweep, promote} ms). */
  sweep32() {
    const e = this.exports;
    const n = this.rows + 2;
    let t = performance.now();
    for (const name of F32_COLUMNS) e.demote(this.address[name], this.address4[name], n);
    const t1 = performance.now();
    const a = this.address4;
    e.sweep32(a.x, a.y, a.angle, a.qangle, a.rc, a.rs, this.packet4Base, this.packets4);
    const t2 = performance.now();
    for (const name of ['x', 'y', 'angle']) e.promote(a[name], this.address[name], this.rows);
    return { demote: t1 - t, sweep: t2 - t1, promote: performance.now() - t2 };
  }

  /**
   * Colours the contacts (greedy, list order, lowest free colour of 64; contacts with a static body in colours of
   * their own after the others: the wall has the last word, as in the JS sweep) and lays them out in packets.
   */
  layout(c, serial = false) {
    const n = c.count;
    if (this.colourOf.length < n) {
      this.colourOf = new Int16Array(2 * n);
      this.slotOf = new Int32Array(2 * n);
      this.cursor = new Int32Array(2 * n);
    }
    const { a: A, b: B } = c;
    const { low, high, lowS, highS, colourOf, sizes, start } = this;
    let t = performance.now();
    sizes.fill(0);
    if (serial) {
      // The check layout: every contact alone in a packet, in list order (the JS sweep's order, so its doubles).
      this.colours[0] = n;
      this.colours[1] = 0;
    } else {
      const invMass = this.p.invMass;
      for (let i = 0; i < n; i++) {
        low[A[i]] = high[A[i]] = lowS[A[i]] = highS[A[i]] = 0;
        low[B[i]] = high[B[i]] = lowS[B[i]] = highS[B[i]] = 0;
      }
      let used0 = 0;
      let used1 = 0;
      for (let i = 0; i < n; i++) {
        const ia = A[i];
        const ib = B[i];
        const movA = invMass[ia] !== 0;
        const movB = invMass[ib] !== 0;
        // Contacts with a static body take colours of their own, swept after the others (masks lowS, highS).
        const lo = movA && movB ? low : lowS;
        const hi = movA && movB ? high : highS;
        const l = lo[ia] | lo[ib];
        const h = hi[ia] | hi[ib];
        const k = ~l !== 0 ? 31 - Math.clz32(~l & (l + 1)) : ~h !== 0 ? 63 - Math.clz32(~h & (h + 1)) : -1;
        if (k < 0) throw new Error(`contact ${i} found no free colour of 64`);
        const bit = 1 << (k & 31);
        if (k < 32) {
          if (movA) lo[ia] |= bit;
          if (movB) lo[ib] |= bit;
        } else {
          if (movA) hi[ia] |= bit;
          if (movB) hi[ib] |= bit;
        }
        if (lo === low) {
          if (k >= used0) used0 = k + 1;
          colourOf[i] = k;
          sizes[k]++;
        } else {
          if (k >= used1) used1 = k + 1;
          colourOf[i] = 64 + k;
          sizes[64 + k]++;
        }
      }
      this.colours[0] = used0;
      this.colours[1] = used1;
    }
    // Batches padded to whole packets; then each contact's slot (lane s & 1 of packet s >> 1).
    const cursor = this.cursor;
    if (serial) {
      for (let i = 0; i < n; i++) cursor[i] = 2 * i;
      this.packets = n;
    } else {
      start[0] = 0;
      for (let k = 0; k < 128; k++) start[k + 1] = start[k] + ((sizes[k] + 1) & ~1);
      for (let k = 0; k < 128; k++) cursor[k] = start[k];
      this.packets = start[128] >> 1;
    }
    this.colourMs = performance.now() - t;
    this.grow(this.packets);
    const { f64, i32, slotOf } = this;
    const base = this.packetBase / 8;
    const spare = this.rows * 8;
    // Padding lanes: the spare row on both sides, apart (allowance 1), no friction.
    const pad = (s) => {
      const w = base + (s >> 1) * PF + (s & 1);
      const q = 2 * (base + (s >> 1) * PF) + (s & 1);
      i32[q] = spare;
      i32[q + 2] = spare;
      for (let field = 1; field <= 27; field++) f64[w + 2 * field] = 0;
      f64[w + 2 * F.allowance] = 1;
    };
    if (serial) for (let i = 0; i < n; i++) pad(2 * i + 1);
    else for (let k = 0; k < 128; k++) if (sizes[k] & 1) pad(start[k + 1] - 1);
    // (After grow: a grown memory detaches the old views.)
    const { invMass, invInertia } = this.p;
    const { nx, ny, rAx, rAy, rBx, rBy, radA, radB, friction, allowance, lambdaN, impulseN, impulseT, slip, gap, touched } = c;
    for (let i = 0; i < n; i++) {
      const s = serial ? cursor[i] : cursor[colourOf[i]]++;
      slotOf[i] = s;
      const q = 2 * (base + (s >> 1) * PF) + (s & 1);
      const w = base + (s >> 1) * PF + (s & 1);
      const ia = A[i];
      const ib = B[i];
      i32[q] = ia * 8;
      i32[q + 2] = ib * 8;
      f64[w + 2] = nx[i];
      f64[w + 4] = ny[i];
      f64[w + 6] = rAx[i];
      f64[w + 8] = rAy[i];
      f64[w + 10] = rBx[i];
      f64[w + 12] = rBy[i];
      f64[w + 14] = radA[i];
      f64[w + 16] = radB[i];
      f64[w + 18] = friction[i];
      f64[w + 20] = invMass[ia];
      f64[w + 22] = invInertia[ia];
      f64[w + 24] = invMass[ib];
      f64[w + 26] = invInertia[ib];
      f64[w + 28] = allowance[i];
      f64[w + 30] = lambdaN[i];
      f64[w + 32] = impulseN[i];
      f64[w + 34] = impulseT[i];
      f64[w + 36] = slip[i];
      f64[w + 38] = gap[i];
      const t = touched[i] ? -1 : 0;
      i32[2 * w + 80] = t;
      i32[2 * w + 81] = t;
    }
  }

  /** The per-substep state of contact i into its lane (the A/B harness feeds both solvers the same input). */
  packState(c, withLevers) {
    const { f64, i32, slotOf } = this;
    const base = this.packetBase / 8;
    const fields = withLevers ? [...STATE_FIELDS, ...LEVER_FIELDS] : STATE_FIELDS;
    const cols = fields.map((name) => [c[name], F[name]]);
    for (let i = 0, n = c.count; i < n; i++) {
      const s = slotOf[i];
      const w = base + (s >> 1) * PF + (s & 1);
      for (let k = 0; k < cols.length; k++) f64[w + 2 * cols[k][1]] = cols[k][0][i];
      const t = c.touched[i] ? -1 : 0;
      i32[2 * (w + 2 * F.touched)] = t;
      i32[2 * (w + 2 * F.touched) + 1] = t;
    }
  }

  /** What the step's end reads (anchors, events, sleep) back into the contact columns (or `into`, same shape). */
  unpack(c, into = c) {
    const { f64, i32, slotOf } = this;
    const base = this.packetBase / 8;
    const { allowance, lambdaN, impulseN, impulseT, slip, gap, touched } = into;
    for (let i = 0, n = c.count; i < n; i++) {
      const s = slotOf[i];
      const w = base + (s >> 1) * PF + (s & 1);
      allowance[i] = f64[w + 2 * F.allowance];
      lambdaN[i] = f64[w + 2 * F.lambdaN];
      impulseN[i] = f64[w + 2 * F.impulseN];
      impulseT[i] = f64[w + 2 * F.impulseT];
      slip[i] = f64[w + 2 * F.slip];
      gap[i] = f64[w + 2 * F.gap];
      touched[i] = i32[2 * (w + 2 * F.touched)] !== 0 ? 1 : 0;
    }
  }

  beginSubstep(maxPush) {
    this.exports.rigidBegin(this.packetBase, this.packets, maxPush);
  }

  sweep() {
    const a = this.address;
    this.exports.rigidSweep(a.x, a.y, a.angle, a.qangle, a.rc, a.rs, this.packetBase, this.packets);
  }

  velocities() {
    const a = this.address;
    this.exports.rigidVelocities(a.vx, a.vy, a.omega, this.packetBase, this.packets);
  }

  /** Batch sizes (points a colour), in sweep order. */
  batchSizes() {
    const out = [];
    for (let k = 0; k < 128; k++) if (this.sizes[k] > 0) out.push(this.sizes[k]);
    return out;
  }
}

/** The scene must be what the lanes solve: single points between two rows, restitution 0, no shock sweep. */
function checkContacts(c) {
  for (let i = 0; i < c.count; i++) {
    if (c.pair[i] !== 0 || c.b2[i] >= 0 || c.b[i] < 0 || c.restitution[i] !== 0) throw new Error(`contact ${i} is not a single point between two rows with restitution 0`);
  }
  if (c.shockCount > 0) throw new Error('the shock sweep is on');
}

// ---- helpers ----------------------------------------------------------------------------------------------------
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const quart = (xs, q) => [...xs].sort((a, b) => a - b)[Math.floor((xs.length - 1) * q)];
const us = (ms) => `${(ms * 1000).toFixed(1)} µs`;

/** Deepest overlap between two discs of radius 0.5, as a fraction of the diameter (containers.test.ts's measure). */
function deepestOverlap(world) {
  const { x, y } = world.ctx.particles;
  const ids = [];
  for (let i = 0; i < world.ctx.particles.count; i++) if (world.ctx.particles.invMass[i] > 0) ids.push(i);
  // A grid of cell 1: a pair can overlap only in neighbouring cells.
  const cells = new Map();
  for (const i of ids) {
    const key = `${Math.floor(x[i])},${Math.floor(y[i])}`;
    if (!cells.has(key)) cells.set(key, []);
    cells.get(key).push(i);
  }
  let deepest = 0;
  for (const i of ids) {
    const cx = Math.floor(x[i]);
    const cy = Math.floor(y[i]);
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (const j of cells.get(`${cx + dx},${cy + dy}`) ?? []) {
          if (j <= i) continue;
          const d = Math.sqrt((x[i] - x[j]) ** 2 + (y[i] - y[j]) ** 2);
          deepest = Math.max(deepest, 1 - d);
        }
      }
    }
  }
  return deepest;
}

const BODY_SWEEP = ['x', 'y', 'angle'];
const BODY_VEL = ['vx', 'vy', 'omega'];
const C_SWEEP = ['lambdaN', 'impulseN', 'impulseT', 'slip', 'gap', 'touched', 'approach', 'allowance', 'lAx', 'lAy', 'lBx', 'lBy', 'rnA', 'rnB', 'wn', 'kn01'];
const C_VEL = ['approach'];

function save(obj, names, n, into) {
  for (const name of names) {
    if (!into[name] || into[name].length < n) into[name] = new obj[name].constructor(Math.max(n, 16) * 2);
    into[name].set(obj[name].subarray(0, n));
  }
  return into;
}
function load(obj, names, n, from) {
  for (const name of names) obj[name].set(from[name].subarray(0, n));
}
function maxDiff(a, b, names, n) {
  let m = 0;
  for (const name of names) for (let i = 0; i < n; i++) m = Math.max(m, Math.abs(a[name][i] - b[name][i]));
  return m;
}

// ---- part 1: per-sweep A/B on the JS trajectory -----------------------------------------------------------------
function perSweep(scene) {
  const world = scene.make();
  for (let k = 0, n = Number(arg('--settle', scene.settle)); k < n; k++) world.step();
  const p = world.ctx.particles;
  const rows = p.count;
  const lanes = new Lanes(world);
  // Today's engine: the same columns as plain arrays (refreshed from the views before each run, untimed).
  const plain = {};
  for (const name of COLUMNS) plain[name] = new Float64Array(p[name].length);
  const T = { jsPlain: [], jsViews: [], lanes: [], vJsPlain: [], vJsViews: [], vLanes: [], layout: [], unpack: [], begin: [], beginJs: [], colour: [], f32: [], demote: [], promote: [] };
  const R = { sweep: [], vel: [], f32: [] };
  const diff = { sweep: 0, sweepAngle: 0, vel: 0, velOmega: 0, f32: 0, f32Angle: 0 };
  const rF64 = {};
  const stats = { contacts: [], colours: [], batches: [], acting: [] };
  const sBody = {};
  const sC = {};
  const rJs = {};
  const rC = {};
  const rPlain = {};
  let substep = 0;
  hooks.prepare = (c, r, maxPush) => {
    const fresh = !c.shockReady;
    let t = performance.now();
    E.prepareRigidContactsJs(c, r, maxPush);
    T.beginJs.push(performance.now() - t);
    if (fresh) {
      checkContacts(c);
      t = performance.now();
      lanes.layout(c, SERIAL);
      T.layout.push(performance.now() - t);
      T.colour.push(lanes.colourMs);
      if (F32) lanes.layout4(c);
      stats.contacts.push(c.count);
      stats.colours.push(lanes.colours[0] + lanes.colours[1]);
      stats.batches.push(lanes.batchSizes());
      t = performance.now();
      lanes.unpack(c, rC.unpack ?? (rC.unpack = { allowance: new Float64Array(4 * c.count), lambdaN: new Float64Array(4 * c.count), impulseN: new Float64Array(4 * c.count), impulseT: new Float64Array(4 * c.count), slip: new Float64Array(4 * c.count), gap: new Float64Array(4 * c.count), touched: new Uint8Array(4 * c.count) }));
      T.unpack.push(performance.now() - t);
    } else {
      lanes.packState(c, false);
      t = performance.now();
      lanes.beginSubstep(maxPush);
      T.begin.push(performance.now() - t);
    }
  };
  hooks.sweep = (c, r) => {
    const n = c.count;
    save(p, BODY_SWEEP, rows, sBody);
    save(c, C_SWEEP, n, sC);
    const order = substep++ % 3;
    const runs = [
      () => {
        load(p, BODY_SWEEP, rows, sBody);
        for (const name of COLUMNS) plain[name].set(p[name]);
        load(c, C_SWEEP, n, sC);
        const t = performance.now();
        E.solveRigidContactsJs(c, plain);
        T.jsPlain.push(performance.now() - t);
        save(plain, BODY_SWEEP, rows, rPlain);
      },
      () => {
        load(p, BODY_SWEEP, rows, sBody);
        load(c, C_SWEEP, n, sC);
        const t = performance.now();
        E.solveRigidContactsJs(c, p);
        T.jsViews.push(performance.now() - t);
        save(p, BODY_SWEEP, rows, rJs);
        save(c, C_SWEEP, n, rC);
      },
      () => {
        load(p, BODY_SWEEP, rows, sBody);
        load(c, C_SWEEP, n, sC);
        lanes.packState(c, false);
        const t = performance.now();
        lanes.sweep();
        T.lanes.push(performance.now() - t);
      },
    ];
    for (let k = 0; k < 3; k++) runs[(k + order) % 3]();
    // The lanes' result is in the views only if they ran last: run them again on the same input to compare.
    load(p, BODY_SWEEP, rows, sBody);
    load(c, C_SWEEP, n, sC);
    lanes.packState(c, false);
    lanes.sweep();
    diff.sweep = Math.max(diff.sweep, maxDiff(p, rJs, ['x', 'y'], rows));
    diff.sweepAngle = Math.max(diff.sweepAngle, maxDiff(p, rJs, ['angle'], rows));
    if (F32) {
      // The f32x4 variant on the same input: its time, and how far it lands from the f64x2 lanes (same colours).
      const r64 = save(p, BODY_SWEEP, rows, rF64);
      load(p, BODY_SWEEP, rows, sBody);
      lanes.packState4(c);
      const t32 = lanes.sweep32();
      T.f32.push(t32.sweep);
      T.demote.push(t32.demote);
      T.promote.push(t32.promote);
      R.f32.push(t32.sweep / T.lanes.at(-1));
      diff.f32 = Math.max(diff.f32, maxDiff(p, r64, ['x', 'y'], rows));
      diff.f32Angle = Math.max(diff.f32Angle, maxDiff(p, r64, ['angle'], rows));
    }
    if (maxDiff(rPlain, rJs, BODY_SWEEP, rows) !== 0) throw new Error('JS over plain columns and over views differ');
    let acting = 0;
    for (let i = 0; i < n; i++) if (rC.lambdaN[i] > 0) acting++;
    stats.acting.push(acting / n);
    R.sweep.push(T.lanes.at(-1) / T.jsPlain.at(-1));
    // Continue on the JS result.
    load(p, BODY_SWEEP, rows, rJs);
    load(c, C_SWEEP, n, rC);
  };
  hooks.velocity = (c, r, h) => {
    const n = c.count;
    const sVel = save(p, BODY_VEL, rows, {});
    const sCv = save(c, C_VEL, n, {});
    let jsResult = null;
    const order = substep % 3;
    const runs = [
      () => {
        load(p, BODY_VEL, rows, sVel);
        for (const name of COLUMNS) plain[name].set(p[name]);
        load(c, C_VEL, n, sCv);
        const t = performance.now();
        E.solveRigidContactVelocitiesJs(c, plain, h);
        T.vJsPlain.push(performance.now() - t);
      },
      () => {
        load(p, BODY_VEL, rows, sVel);
        load(c, C_VEL, n, sCv);
        const t = performance.now();
        E.solveRigidContactVelocitiesJs(c, p, h);
        T.vJsViews.push(performance.now() - t);
        jsResult = save(p, BODY_VEL, rows, {});
      },
      () => {
        load(p, BODY_VEL, rows, sVel);
        lanes.packState(c, true);
        const t = performance.now();
        lanes.velocities();
        T.vLanes.push(performance.now() - t);
      },
    ];
    for (let k = 0; k < 3; k++) runs[(k + order) % 3]();
    load(p, BODY_VEL, rows, sVel);
    lanes.packState(c, true);
    lanes.velocities();
    diff.vel = Math.max(diff.vel, maxDiff(p, jsResult, ['vx', 'vy'], rows));
    diff.velOmega = Math.max(diff.velOmega, maxDiff(p, jsResult, ['omega'], rows));
    R.vel.push(T.vLanes.at(-1) / T.vJsPlain.at(-1));
    load(p, BODY_VEL, rows, jsResult);
    load(c, C_VEL, n, sCv);
  };
  const steps = Number(arg('--steps', scene.steps));
  for (let k = 0; k < steps; k++) world.step();
  hooks.prepare = hooks.sweep = hooks.velocity = null;

  const sub = T.lanes.length / steps;
  const contacts = median(stats.contacts);
  console.log(`\n## ${scene.title}: per-sweep A/B, ${steps} steps × ${sub} substeps after ${arg('--settle', scene.settle)} steps (load ${loadavg()[0].toFixed(1)})`);
  console.log(`contacts ${Math.min(...stats.contacts)}–${Math.max(...stats.contacts)} (all single points between two rows), acting per sweep ${(100 * median(stats.acting)).toFixed(0)}%`);
  const allColours = stats.colours;
  console.log(`colours per step ${Math.min(...allColours)}–${Math.max(...allColours)} (dynamic–dynamic + with a static body: ${lanes.colours[0]} + ${lanes.colours[1]} in the last step)`);
  const last = stats.batches.at(-1);
  const padding = last.filter((s) => s & 1).length;
  if (SERIAL) console.log('--serial: one contact a packet (the other lane padding), in list order');
  else console.log(`batch sizes, last step, in sweep order: ${last.join(' ')} (${padding} padding lanes of ${last.reduce((a, b) => a + b + (b & 1), 0)})`);
  console.log('| pass | JS, plain columns | JS, columns in wasm memory | lanes f64x2 | lanes ÷ JS plain (median of paired ratios, quartiles) |');
  console.log('|---|---|---|---|---|');
  const q = (xs) => `${median(xs).toFixed(2)} (${quart(xs, 0.25).toFixed(2)}–${quart(xs, 0.75).toFixed(2)})`;
  console.log(`| position sweep | ${us(median(T.jsPlain))} | ${us(median(T.jsViews))} | ${us(median(T.lanes))} | ${q(R.sweep)} |`);
  console.log(`| velocity pass | ${us(median(T.vJsPlain))} | ${us(median(T.vJsViews))} | ${us(median(T.vLanes))} | ${q(R.vel)} |`);
  console.log(`per step: colouring + layout ${us(median(T.layout))} (${(median(T.layout) * 1e6 / contacts).toFixed(0)} ns a contact; the colouring ${us(median(T.colour))}), unpack at the step's end ${us(median(T.unpack))}; substep start: JS prepare ${us(median(T.beginJs))}, lanes ${us(median(T.begin))}`);
  const perStepJs = sub * (median(T.jsPlain) + median(T.vJsPlain));
  const perStepLanes = sub * (median(T.lanes) + median(T.vLanes)) + median(T.layout) + median(T.unpack);
  console.log(`a step's contact solve: JS ${(perStepJs).toFixed(3)} ms, lanes with layout and unpack ${(perStepLanes).toFixed(3)} ms (${(perStepLanes / perStepJs).toFixed(2)}×)`);
  console.log(`largest difference lanes − JS after one sweep: position ${diff.sweep.toExponential(2)}, angle ${diff.sweepAngle.toExponential(2)}; after one velocity pass: velocity ${diff.vel.toExponential(2)}, ω ${diff.velOmega.toExponential(2)}${SERIAL ? ' (--serial: one contact a packet in list order, the JS order: must be 0)' : ''}`);
  if (F32) {
    console.log(`f32x4 lanes (same colours, batches padded to fours, ${lanes.packets4} packets): sweep ${us(median(T.f32))}, ${median(R.f32).toFixed(2)}× the f64x2 sweep (${quart(R.f32, 0.25).toFixed(2)}–${quart(R.f32, 0.75).toFixed(2)}); demoting the six body columns ${us(median(T.demote))}, promoting x, y, angle ${us(median(T.promote))} a substep`);
    console.log(`f32x4 − f64x2 lanes after one sweep: position ${diff.f32.toExponential(2)}, angle ${diff.f32Angle.toExponential(2)}`);
  }
  return { perStepJs, perStepLanes };
}

// ---- part 2: quality and whole steps ----------------------------------------------------------------------------
function wholeSteps(scene) {
  const js = scene.make();
  const w = scene.make();
  const lanes = new Lanes(w);
  const pw = w.ctx.particles;
  let sweeps = 0;
  let perStep = 6;
  const useLanes = (on) => {
    if (!on) {
      hooks.prepare = hooks.sweep = hooks.velocity = null;
      return;
    }
    hooks.prepare = (c, r, maxPush) => {
      if (!c.shockReady) {
        E.prepareRigidContactsJs(c, r, maxPush);
        checkContacts(c);
        lanes.layout(c);
        sweeps = 0;
      } else lanes.beginSubstep(maxPush);
    };
    hooks.sweep = () => lanes.sweep();
    hooks.velocity = (c, r, h) => {
      lanes.velocities();
      perStep = Math.round(1 / 60 / h);
      if (++sweeps === perStep) lanes.unpack(c);
    };
  };
  const n = Number(arg('--quality', scene.quality));
  const cpu = { js: [], lanes: [] };
  const checkpoints = [];
  for (let k = 0; k < n; k++) {
    for (const which of k % 2 ? ['lanes', 'js'] : ['js', 'lanes']) {
      useLanes(which === 'lanes');
      const c0 = process.cpuUsage();
      (which === 'js' ? js : w).step();
      const c1 = process.cpuUsage(c0);
      cpu[which].push((c1.user + c1.system) / 1000);
    }
    if (w.ctx.particles !== pw) throw new Error('the particle store was replaced');
    if ((k + 1) % 100 === 0) checkpoints.push(`${k + 1}: ${(100 * deepestOverlap(js)).toFixed(2)} / ${(100 * deepestOverlap(w)).toFixed(2)}`);
  }
  useLanes(false);
  const window = Math.min(100, n);
  const [mJs, mLanes] = [cpu.js, cpu.lanes].map((xs) => median(xs.slice(-window)));
  const pairs = cpu.js.slice(-window).map((t, k) => cpu.lanes.at(-window + k) / t);
  const [dJs, dLanes] = [deepestOverlap(js), deepestOverlap(w)];
  console.log(`\n## ${scene.title}: whole steps, JS solver vs lanes, ${n} steps from the start, alternating (load ${loadavg()[0].toFixed(1)})`);
  console.log(`CPU ms per step, median of the last ${window}: JS ${mJs.toFixed(2)}, lanes ${mLanes.toFixed(2)}, paired ratio ${median(pairs).toFixed(2)}`);
  console.log(`deepest disc overlap after ${n} steps: JS ${(100 * dJs).toFixed(2)}%, lanes ${(100 * dLanes).toFixed(2)}% of a diameter`);
  console.log(`deepest overlap every 100 steps, JS / lanes (%): ${checkpoints.join(', ')}`);
  let escaped = 0;
  const { x, y } = w.ctx.particles;
  for (let i = 0; i < w.ctx.particles.count; i++) if (w.ctx.particles.invMass[i] > 0 && (!Number.isFinite(x[i]) || y[i] > 0.01)) escaped++;
  console.log(`lanes: discs below the floor's top or not finite: ${escaped}`);
}

// ---- instruction counts: the same restores, then one kind of sweep (valgrind --tool=callgrind, three runs) -------
//   valgrind --tool=callgrind --callgrind-out-file=/tmp/x.out node bench/experiment-rigid.mjs --count js|lanes|none
function countSweeps(scene, kind) {
  const world = scene.make();
  for (let k = 0, n = Number(arg('--settle', 200)); k < n; k++) world.step();
  const p = world.ctx.particles;
  const rows = p.count;
  const lanes = new Lanes(world);
  let c = null;
  hooks.prepare = (cc, r, maxPush) => {
    E.prepareRigidContactsJs(cc, r, maxPush);
    if (c === null) {
      c = cc;
      lanes.layout(cc);
    }
  };
  hooks.sweep = (cc, r) => {
    if (c === cc && !hooks.done) {
      hooks.done = true;
      const sBody = save(p, BODY_SWEEP, rows, {});
      const sC = save(c, C_SWEEP, c.count, {});
      const t = performance.now();
      for (let k = 0, n = Number(arg('--sweeps', 200)); k < n; k++) {
        load(p, BODY_SWEEP, rows, sBody);
        load(c, C_SWEEP, c.count, sC);
        lanes.packState(c, false);
        const t1 = performance.now();
        if (kind === 'js') E.solveRigidContactsJs(c, p);
        else if (kind === 'lanes') lanes.sweep();
        (hooks.each ??= []).push(performance.now() - t1);
      }
      hooks.ms = performance.now() - t;
    }
    E.solveRigidContactsJs(cc, r);
  };
  world.step();
  hooks.prepare = hooks.sweep = null;
  console.log(`${kind}: ${arg('--sweeps', 200)} sweeps of ${c.count} contacts (${lanes.packets} packets), restores included: ${hooks.ms.toFixed(1)} ms; median sweep alone ${us(median(hooks.each))}`);
}

const SERIAL = process.argv.includes('--serial');
const F32 = process.argv.includes('--f32');
if (process.argv.includes('--count')) {
  countSweeps(SCENES[arg('--scenes', 's3')], arg('--count', 'none'));
  process.exit(0);
}
const names = arg('--scenes', 'c10k,s3').split(',');
console.log(`experiment-rigid: ${bytes.length} bytes of WebAssembly, Node ${process.version}`);
for (const name of names) {
  const scene = SCENES[name];
  if (!scene) throw new Error(`unknown scene ${name}: ${Object.keys(SCENES).join(', ')}`);
  if (!process.argv.includes('--no-ab')) perSweep(scene);
  if (!process.argv.includes('--no-quality')) wholeSteps(scene);
}
