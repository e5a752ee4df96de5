// The particle solver kernel in AssemblyScript, compiled to WebAssembly with 128-bit SIMD (f64x2 lanes) by
// scripts/build-wasm.mjs. Not part of the TypeScript build (hence the .as name): its output is the byte string in
// wasm-bytes.ts. It owns no memory of its own layout: the TypeScript side (wasm-kernel.ts) places the engine's
// particle columns, the distance constraints' runs and the coloured packets in the imported memory and passes their
// byte addresses.
//
// Every formula is the JS solver's, written in the same order of operations, so a constraint solved here gives the
// same doubles as in distance.ts, except for the rigid links of runs (one division instead of two: see sweepRun); and
// the order in which constraints are visited differs (runs, then coloured packets).
//
// Two layouts of the distance constraints:
//  - Runs: constraints whose particles step by one row from lane to lane (a cloth's or a grid's links, tethers to a
//    pinned row). A run is read with contiguous 128-bit loads, no index per lane: "parallel" runs are lanes
//    (a + k, b + k) with b − a ≥ 2; "interleaved" runs are lanes (a + 2k, a + 2k + 1) (a chain's or a row's links,
//    every other one). Two consecutive lanes never share a particle, so each pair is solved lane-parallel and the sweep
//    is Gauss–Seidel from pair to pair. A run of odd length ends with a padding lane whose limits make it inactive: it
//    reads and writes back its two particles unchanged.
//  - Packets: every other constraint, graph-coloured (colour.ts) into pairs that share no movable particle, each pair
//    with its four particle offsets.

// Run record (RUN bytes): i32 a, i32 b (byte offsets of lane 0's particles into the f64 columns), i32 pairs,
// i32 shape (0 parallel, 1 interleaved) | kind << 1, i32 data (byte address of its lane data).
const RUN: usize = 32;
// Lane data per pair of lanes, by kind:
//   STICK (rigid, minLength = maxLength): f64×2 length (NaN: the link acts no more: broken, or padding)
//   LIMITS (rigid, minLength < maxLength: slack links, tethers): f64×2 lo, f64×2 hi
//   COMPLIANT: f64×2 lo, hi, compliance, lambda (the XPBD multiplier, this substep)
const STICK: i32 = 0;
const LIMITS: i32 = 1;
const COMPLIANT: i32 = 2;

// A packet is two distance constraints of the same colour (they share no movable particle, so their lanes are
// independent):
//   0: i32×4  byte offsets of a0, a1, b0, b1 into the x, y and invMass columns
//  16: f64×2  lo   minLength        32: f64×2  hi   maxLength
//  48: f64×2  compliance            64: f64×2  lambda (the XPBD multiplier, this substep)
const PACKET: usize = 80;

/**
 * One Gauss–Seidel sweep over every distance constraint: the runs, then the packets (XPBD; h2 = substep²). `fresh`: the
 * first sweep of a substep, whose multipliers start at zero (saves a pass to clear them).
 */
function solveDistances(x: usize, y: usize, invMass: usize, runs: usize, runCount: i32, packets: usize, count: i32, h2: f64, fresh: bool): void {
  for (let r = 0; r < runCount; r++) {
    const rec = runs + <usize>r * RUN;
    const a = <usize>load<i32>(rec);
    const b = <usize>load<i32>(rec, 4);
    const pairs = load<i32>(rec, 8);
    const shape = load<i32>(rec, 12);
    const data = <usize>load<i32>(rec, 16);
    // One loop per shape and kind, each with its branches folded away.
    if (shape == 0) sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, false, STICK);
    else if (shape == 1) sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, true, STICK);
    else if (shape == 2) sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, false, LIMITS);
    else if (shape == 3) sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, true, LIMITS);
    // Compliant runs (soft links: rarer, and bound by their divisions) share one loop, which picks its lanes by a mask.
    else sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, shape == 5, COMPLIANT, true);
  }
  solvePackets(x, y, invMass, packets, count, h2, fresh);
}

@inline function laneBytes(kind: i32): usize {
  return kind == STICK ? 16 : kind == LIMITS ? 32 : 64;
}

/** Pairs of lanes of one run: parallel lanes (a + k, b + k), or interleaved lanes (a + 2k, a + 2k + 1). */
@inline function sweepRun(x: usize, y: usize, invMass: usize, a: usize, b: usize, pairs: i32, data: usize, h2: f64, fresh: bool, interleaved: bool, kind: i32, mixed: bool = false): void {
  const vh2 = f64x2.splat(h2);
  const zero = f64x2.splat(0);
  const one = f64x2.splat(1);
  const tinyLength = f64x2.splat(1e-12);
  const step: usize = interleaved ? 32 : 16;
  // mixed: `interleaved` is known only when the loop runs; the lanes are picked by this mask from both halves.
  const im = i64x2.splat(interleaved ? -1 : 0);
  for (let k = 0; k < pairs; k++) {
    const oa = a + <usize>k * step;
    const ob = mixed ? (interleaved ? oa + 16 : b + <usize>k * step) : b + <usize>k * step;
    const pk = data + <usize>k * laneBytes(kind);
    let xa: v128, ya: v128, xb: v128, yb: v128, wa: v128, wb: v128;
    if (mixed) {
      // Interleaved: the halves at oa and oa + 16, the a's and the b's shuffled out; parallel: the halves themselves.
      const x0 = v128.load(x + oa);
      const x1 = v128.load(x + ob);
      const y0 = v128.load(y + oa);
      const y1 = v128.load(y + ob);
      const w0 = v128.load(invMass + oa);
      const w1 = v128.load(invMass + ob);
      xa = v128.bitselect(f64x2.shuffle(x0, x1, 0, 2), x0, im);
      xb = v128.bitselect(f64x2.shuffle(x0, x1, 1, 3), x1, im);
      ya = v128.bitselect(f64x2.shuffle(y0, y1, 0, 2), y0, im);
      yb = v128.bitselect(f64x2.shuffle(y0, y1, 1, 3), y1, im);
      wa = v128.bitselect(f64x2.shuffle(w0, w1, 0, 2), w0, im);
      wb = v128.bitselect(f64x2.shuffle(w0, w1, 1, 3), w1, im);
    } else if (interleaved) {
      // Particles a, a + 1 (lane 0) and a + 2, a + 3 (lane 1): two loads, then the a's and the b's.
      const x0 = v128.load(x + oa);
      const x1 = v128.load(x + oa, 16);
      const y0 = v128.load(y + oa);
      const y1 = v128.load(y + oa, 16);
      const w0 = v128.load(invMass + oa);
      const w1 = v128.load(invMass + oa, 16);
      xa = f64x2.shuffle(x0, x1, 0, 2);
      xb = f64x2.shuffle(x0, x1, 1, 3);
      ya = f64x2.shuffle(y0, y1, 0, 2);
      yb = f64x2.shuffle(y0, y1, 1, 3);
      wa = f64x2.shuffle(w0, w1, 0, 2);
      wb = f64x2.shuffle(w0, w1, 1, 3);
    } else {
      xa = v128.load(x + oa);
      ya = v128.load(y + oa);
      xb = v128.load(x + ob);
      yb = v128.load(y + ob);
      wa = v128.load(invMass + oa);
      wb = v128.load(invMass + ob);
    }
    const w = f64x2.add(wa, wb);
    let dx = f64x2.sub(xb, xa);
    let dy = f64x2.sub(yb, ya);
    const d2 = f64x2.add(f64x2.mul(dx, dx), f64x2.mul(dy, dy));
    let active: v128;
    let lo: v128;
    let hi: v128 = zero;
    if (kind == STICK) {
      lo = v128.load(pk);
      // A link between immovables does nothing; neither does a broken one or a padding lane (NaN length).
      active = v128.and(f64x2.ne(w, zero), f64x2.eq(lo, lo));
    } else {
      lo = v128.load(pk);
      hi = v128.load(pk, 16);
      // A slack link (lo < hi) whose length is within its limits does nothing; neither does a link between immovables.
      const slack = v128.and(f64x2.ne(lo, hi), v128.and(f64x2.ge(d2, f64x2.mul(lo, lo)), f64x2.le(d2, f64x2.mul(hi, hi))));
      active = v128.andnot(f64x2.ne(w, zero), slack);
      // Slack links within their limits (a cloth's tethers, mostly): skip the pair.
      if (!v128.any_true(active)) continue;
    }
    let d = f64x2.sqrt(d2);
    // Past the upper limit the error is d − hi; otherwise d − lo (the same when lo = hi).
    // Past the upper limit by d² as `slack` tests it (d may round to hi; d − lo then pulled a tether onto its pin).
    const err = kind == STICK ? f64x2.sub(d, lo) : v128.bitselect(f64x2.sub(d, hi), f64x2.sub(d, lo), f64x2.gt(d2, f64x2.mul(hi, hi)));
    // Coincident particles have no direction: a fixed one keeps the result finite and deterministic. Rare: a branch
    // around the three selects (and the all-active branch below) gives the same doubles with fewer instructions per pair,
    // which is what bounds this loop (see docs/engine.md: f32x4 square roots and divisions did not pay).
    const coincident = f64x2.lt(d, tinyLength);
    if (v128.any_true(coincident)) {
      dx = v128.bitselect(one, dx, coincident);
      dy = v128.bitselect(zero, dy, coincident);
      d = v128.bitselect(one, d, coincident);
    }
    let s: v128;
    if (kind == COMPLIANT) {
      const lambda = fresh ? zero : v128.load(pk, 48);
      const alpha = f64x2.div(v128.load(pk, 32), vh2);
      const denominator = v128.bitselect(f64x2.add(w, alpha), one, active);
      const dl = v128.and(f64x2.div(f64x2.sub(f64x2.neg(err), f64x2.mul(alpha, lambda)), denominator), active);
      v128.store(pk, f64x2.add(lambda, dl), 48);
      s = f64x2.neg(f64x2.div(dl, d));
    } else {
      // Rigid: s = −err / (w·d), one division where the JS loop takes two (dl = −err / w, then dl / d), equal to it
      // within an ulp or two. Here s holds its negation, err / (w·d), and the corrections below change sign instead.
      if (i64x2.all_true(active)) s = f64x2.div(err, f64x2.mul(w, d));
      else s = v128.and(f64x2.div(err, f64x2.mul(v128.bitselect(w, one, active), d)), active);
    }
    const nxa = f64x2.add(xa, f64x2.mul(f64x2.mul(wa, s), dx));
    const nya = f64x2.add(ya, f64x2.mul(f64x2.mul(wa, s), dy));
    const nxb = f64x2.sub(xb, f64x2.mul(f64x2.mul(wb, s), dx));
    const nyb = f64x2.sub(yb, f64x2.mul(f64x2.mul(wb, s), dy));
    if (mixed) {
      v128.store(x + oa, v128.bitselect(f64x2.shuffle(nxa, nxb, 0, 2), nxa, im));
      v128.store(x + ob, v128.bitselect(f64x2.shuffle(nxa, nxb, 1, 3), nxb, im));
      v128.store(y + oa, v128.bitselect(f64x2.shuffle(nya, nyb, 0, 2), nya, im));
      v128.store(y + ob, v128.bitselect(f64x2.shuffle(nya, nyb, 1, 3), nyb, im));
    } else if (interleaved) {
      v128.store(x + oa, f64x2.shuffle(nxa, nxb, 0, 2));
      v128.store(x + oa, f64x2.shuffle(nxa, nxb, 1, 3), 16);
      v128.store(y + oa, f64x2.shuffle(nya, nyb, 0, 2));
      v128.store(y + oa, f64x2.shuffle(nya, nyb, 1, 3), 16);
    } else {
      v128.store(x + oa, nxa);
      v128.store(y + oa, nya);
      v128.store(x + ob, nxb);
      v128.store(y + ob, nyb);
    }
  }
}

/** The coloured packets (see PACKET). */
function solvePackets(x: usize, y: usize, invMass: usize, packets: usize, count: i32, h2: f64, fresh: bool): void {
  const vh2 = f64x2.splat(h2);
  const zero = f64x2.splat(0);
  const one = f64x2.splat(1);
  const tinyLength = f64x2.splat(1e-12);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET;
    const a0 = <usize>load<i32>(pk);
    const a1 = <usize>load<i32>(pk, 4);
    const b0 = <usize>load<i32>(pk, 8);
    const b1 = <usize>load<i32>(pk, 12);
    const lo = v128.load(pk, 16);
    const hi = v128.load(pk, 32);
    const compliance = v128.load(pk, 48);
    const lambda = fresh ? zero : v128.load(pk, 64);
    // Inverse masses are read where they live: pins, sleep and the API change them between steps.
    const wa = f64x2.replace_lane(f64x2.splat(load<f64>(invMass + a0)), 1, load<f64>(invMass + a1));
    const wb = f64x2.replace_lane(f64x2.splat(load<f64>(invMass + b0)), 1, load<f64>(invMass + b1));
    const xa = f64x2.replace_lane(f64x2.splat(load<f64>(x + a0)), 1, load<f64>(x + a1));
    const ya = f64x2.replace_lane(f64x2.splat(load<f64>(y + a0)), 1, load<f64>(y + a1));
    const xb = f64x2.replace_lane(f64x2.splat(load<f64>(x + b0)), 1, load<f64>(x + b1));
    const yb = f64x2.replace_lane(f64x2.splat(load<f64>(y + b0)), 1, load<f64>(y + b1));
    const w = f64x2.add(wa, wb);
    let dx = f64x2.sub(xb, xa);
    let dy = f64x2.sub(yb, ya);
    const d2 = f64x2.add(f64x2.mul(dx, dx), f64x2.mul(dy, dy));
    const slack = v128.and(f64x2.ne(lo, hi), v128.and(f64x2.ge(d2, f64x2.mul(lo, lo)), f64x2.le(d2, f64x2.mul(hi, hi))));
    const active = v128.andnot(f64x2.ne(w, zero), slack);
    if (!v128.any_true(active)) continue;
    let d = f64x2.sqrt(d2);
    const err = v128.bitselect(f64x2.sub(d, hi), f64x2.sub(d, lo), f64x2.gt(d2, f64x2.mul(hi, hi)));
    const coincident = f64x2.lt(d, tinyLength);
    if (v128.any_true(coincident)) {
      dx = v128.bitselect(one, dx, coincident);
      dy = v128.bitselect(zero, dy, coincident);
      d = v128.bitselect(one, d, coincident);
    }
    const alpha = f64x2.div(compliance, vh2);
    const denominator = v128.bitselect(f64x2.add(w, alpha), one, active);
    const dl = v128.and(f64x2.div(f64x2.sub(f64x2.neg(err), f64x2.mul(alpha, lambda)), denominator), active);
    v128.store(pk, f64x2.add(lambda, dl), 64);
    const s = f64x2.div(dl, d);
    const nxa = f64x2.sub(xa, f64x2.mul(f64x2.mul(wa, s), dx));
    const nya = f64x2.sub(ya, f64x2.mul(f64x2.mul(wa, s), dy));
    const nxb = f64x2.add(xb, f64x2.mul(f64x2.mul(wb, s), dx));
    const nyb = f64x2.add(yb, f64x2.mul(f64x2.mul(wb, s), dy));
    store<f64>(x + a0, f64x2.extract_lane(nxa, 0));
    store<f64>(x + a1, f64x2.extract_lane(nxa, 1));
    store<f64>(y + a0, f64x2.extract_lane(nya, 0));
    store<f64>(y + a1, f64x2.extract_lane(nya, 1));
    store<f64>(x + b0, f64x2.extract_lane(nxb, 0));
    store<f64>(x + b1, f64x2.extract_lane(nxb, 1));
    store<f64>(y + b0, f64x2.extract_lane(nyb, 0));
    store<f64>(y + b1, f64x2.extract_lane(nyb, 1));
  }
}

/**
 * Position Verlet over rows [0, n) rounded up to even (the columns have room for it): px = x, then for movable rows
 * x += v·damp·h + a·h². With `forces`, the acceleration is gx + fx·invMass (the JS accelerate phase, fused: no
 * springs); without, it is read from the ax/ay columns. Columns are f64 arrays at the given byte addresses.
 */
function integrateVerlet(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, ax: usize, ay: usize, invMass: usize, n: i32, h: f64, damp: f64, forces: bool, gx: f64, gy: f64): void {
  const vh = f64x2.splat(h);
  const vh2 = f64x2.splat(h * h);
  const vdamp = f64x2.splat(damp);
  const vgx = f64x2.splat(gx);
  const vgy = f64x2.splat(gy);
  const zero = f64x2.splat(0);
  // One loop for both (a select where it was two loops: the same doubles, 200 bytes less of the kernel's budget).
  const fused = i64x2.splat(forces ? -1 : 0);
  for (let i = 0; i < n; i += 2) {
    const o = <usize>i << 3;
    const w = v128.load(invMass + o);
    const movable = f64x2.ne(w, zero);
    const cx = v128.load(x + o);
    const cy = v128.load(y + o);
    v128.store(px + o, cx);
    v128.store(py + o, cy);
    // With forces, ax and ay are the columns fx and fy: a = g + f·invMass, as accelerate() computes it.
    const lx = v128.load(ax + o);
    const ly = v128.load(ay + o);
    const accx = v128.bitselect(f64x2.add(vgx, f64x2.mul(lx, w)), lx, fused);
    const accy = v128.bitselect(f64x2.add(vgy, f64x2.mul(ly, w)), ly, fused);
    const nx = f64x2.add(cx, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vx + o), vdamp), vh), f64x2.mul(accx, vh2)));
    const ny = f64x2.add(cy, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vy + o), vdamp), vh), f64x2.mul(accy, vh2)));
    v128.store(x + o, v128.bitselect(nx, cx, movable));
    v128.store(y + o, v128.bitselect(ny, cy, movable));
  }
}

/** Velocities from the substep's motion: v = (x − px)·(1/h), rows [0, n) rounded up to even. */
function updateVelocities(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, n: i32, inv: f64): void {
  const vinv = f64x2.splat(inv);
  for (let i = 0; i < n; i += 2) {
    const o = <usize>i << 3;
    v128.store(vx + o, f64x2.mul(f64x2.sub(v128.load(x + o), v128.load(px + o)), vinv));
    v128.store(vy + o, f64x2.mul(f64x2.sub(v128.load(y + o), v128.load(py + o)), vinv));
  }
}

// ---- Rigid contacts in lanes (issue 16) ------------------------------------------------------------------------
// The rigid contact solver's position sweep and velocity pass for single-point contacts (rigid discs with discs and
// static walls: disc piles), in f64x2 lanes, with the same formulas and order of operations per point as
// solveRigidContacts / solveRigidContactVelocities in src/engine/rigid/contact-solver.ts (restitution 0, no manifold
// pairs, no particle-edge points, no shock sweep: wasm-kernel.ts checks each step and otherwise leaves the step's
// rigid contacts to the JS solver). wasm-kernel.ts colours the contacts each step into batches that share no movable
// body (contacts with a static body or the world in colours of their own, swept last), two lanes a packet: within a
// packet the two points touch different movable bodies, so solving them side by side is the same as one after the
// other; the sweep is Gauss–Seidel in the colours' order.
//
// The body columns (x, y, angle, qangle, rc, rs; vx, vy, omega) are the engine's own f64 columns in this memory; a
// lane reads a row's value by its byte offset (row × 8). A padding lane points at a spare row (inverse mass and inertia
// 0, apart) and never acts; the world is another spare row at the origin with rotation (1, 0) and inverse mass 0, so
// its point is (rBx, rBy) as in the JS solver; a static body may sit in both lanes of a packet: it is written back
// unchanged.
//
// Packet of two points (bytes):
//   0: i32 ia0, ia1, ib0, ib1 (row × 8)
//  16 nx  32 ny  48 rAx  64 rAy  80 rBx  96 rBy  112 radA  128 radB  144 friction
// 160 imA 176 iiA 192 imB 208 iiB                                   (per step, from the rows' inverse mass/inertia)
// 224 allowance 240 lambdaN 256 impulseN 272 impulseT 288 slip 304 (unused: the JS solver's gap, which nothing reads
// after it) 320 touched (all-ones lanes)                                                            (state)
// 336 lAx 352 lAy 368 lBx 384 lBy 400 rnA 416 rnB 432 wn             (written by the sweep for the velocity pass)
const RIGID_PACKET: usize = 448;

@inline function gather2(column: usize, o0: usize, o1: usize): v128 {
  return v128.load64_lane(column + o1, v128.load64_splat(column + o0), 1);
}

@inline function scatter2(column: usize, o0: usize, o1: usize, v: v128): void {
  v128.store64_lane(column + o0, v, 0);
  v128.store64_lane(column + o1, v, 1);
}

@inline function fld(pk: usize, offset: usize): v128 {
  return v128.load(pk + offset);
}

/**
 * The step's layout of `n` single points (wasm-kernel.ts writeRigid): their columns staged at `stage`, `cap` rows each
 * (f64 nx, ny, rAx, rAy, rBx, rBy, radA, radB, friction, allowance; then i32 a, b, lane), each point into its lane
 * (packet s >> 1, lane s & 1) with its rows' byte offsets (the world's row for b −1) and inverse mass and inertia
 * (read from their columns: the world's row has 0), λn, the impulses, slip and touched 0 (gap is written by every
 * sweep before it is read). A copy a field, no arithmetic: the same doubles as the table's.
 */
function rigidLayout(stage: usize, cap: usize, n: i32, invMass: usize, invInertia: usize, packets: usize, world: usize): void {
  const column = cap << 3;
  const ints = stage + column * 11;
  for (let i = 0; i < n; i++) {
    const j = <usize>i << 3;
    const q = ints + (<usize>i << 2);
    const s = load<i32>(q + (cap << 3));
    const lane = <usize>(s & 1);
    const pk = packets + <usize>(s >> 1) * RIGID_PACKET;
    const f = pk + (lane << 3);
    const oa = <usize>load<i32>(q) << 3;
    const b = load<i32>(q + (cap << 2));
    const ob = b >= 0 ? <usize>b << 3 : world;
    store<i32>(pk + (lane << 2), <i32>oa);
    store<i32>(pk + (lane << 2), <i32>ob, 8);
    // nx … friction (fields 1-9), written out: as a loop the function took 1.3-1.5x as long (10,000 circles).
    store<f64>(f, load<f64>(stage + j), 16);
    store<f64>(f, load<f64>(stage + 1 * column + j), 32);
    store<f64>(f, load<f64>(stage + 2 * column + j), 48);
    store<f64>(f, load<f64>(stage + 3 * column + j), 64);
    store<f64>(f, load<f64>(stage + 4 * column + j), 80);
    store<f64>(f, load<f64>(stage + 5 * column + j), 96);
    store<f64>(f, load<f64>(stage + 6 * column + j), 112);
    store<f64>(f, load<f64>(stage + 7 * column + j), 128);
    store<f64>(f, load<f64>(stage + 8 * column + j), 144);
    // The world's point is (rBx, rBy) itself (its row turns it by (1, 0)).
    if (b < 0) store<f64>(f, 0, 128);
    store<f64>(f, load<f64>(invMass + oa), 160);
    store<f64>(f, load<f64>(invInertia + oa), 176);
    store<f64>(f, load<f64>(invMass + ob), 192);
    store<f64>(f, load<f64>(invInertia + ob), 208);
    store<f64>(f, load<f64>(stage + 9 * column + j), 224);
    store<f64>(f, 0, 240);
    store<f64>(f, 0, 256);
    store<f64>(f, 0, 272);
    store<f64>(f, 0, 288);
    store<f64>(f, load<f64>(stage + 10 * column + j), 304);
    store<i64>(f, 0, 320);
  }
}

/** The substep's start (RigidContacts.beginSubstep): λn 0, allowances shrink by maxPush. */
function rigidBegin(packets: usize, count: i32, maxPush: f64): void {
  const zero = f64x2.splat(0);
  const push = f64x2.splat(maxPush);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * RIGID_PACKET;
    v128.store(pk, zero, 240);
    const left = f64x2.sub(fld(pk, 224), push);
    v128.store(pk, v128.bitselect(left, zero, f64x2.gt(left, zero)), 224);
  }
}

/**
 * The material points' offset along the tangent t = (−ny, nx): (pA − pB)·t, each point its body's centre plus its
 * lever turned by the angle since the reference (first order). Inlined: a call passing fourteen v128 values spilled
 * them and every live value of the sweep around it (a disc pile's sweep took a sixth more instructions for it).
 */
@inline function offsetAlong(ax: v128, ay: v128, bx: v128, by: v128, dA: v128, dB: v128, mAx: v128, mAy: v128, mBx: v128, mBy: v128, nx: v128, ny: v128): v128 {
  const ux = f64x2.sub(f64x2.sub(f64x2.add(ax, mAx), f64x2.mul(dA, mAy)), f64x2.sub(f64x2.add(bx, mBx), f64x2.mul(dB, mBy)));
  const uy = f64x2.sub(f64x2.add(f64x2.add(ay, mAy), f64x2.mul(dA, mAx)), f64x2.add(f64x2.add(by, mBy), f64x2.mul(dB, mBx)));
  return f64x2.add(f64x2.mul(f64x2.neg(ux), ny), f64x2.mul(uy, nx));
}

/** contacts.ts alongTangent: a lever turned by d (first order), along t = (−ny, nx). */
@inline function alongTangent(mx: v128, my: v128, d: v128, nx: v128, ny: v128): v128 {
  return f64x2.add(f64x2.mul(f64x2.neg(f64x2.sub(mx, f64x2.mul(d, my))), ny), f64x2.mul(f64x2.add(my, f64x2.mul(d, mx)), nx));
}

/** contacts.ts arcBeyond: r·asin(s) − m·t for s = m·t / r, its series to s⁷ (Horner's rule); 0 where the side is not round. */
@inline function arcBeyond(mt: v128, rad: v128): v128 {
  const s = f64x2.div(mt, rad);
  const s2 = f64x2.mul(s, s);
  const p = f64x2.mul(s2, f64x2.add(f64x2.splat(1.0 / 6.0), f64x2.mul(s2, f64x2.add(f64x2.splat(3.0 / 40.0), f64x2.mul(s2, f64x2.splat(5.0 / 112.0))))));
  return v128.and(f64x2.mul(mt, p), f64x2.gt(rad, f64x2.splat(0)));
}

/** One position sweep over `count` packets: normal correction, then friction, per point. */
function rigidSweep(x: usize, y: usize, angle: usize, qangle: usize, rc: usize, rs: usize, packets: usize, count: i32): void {
  const zero = f64x2.splat(0);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * RIGID_PACKET;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = fld(pk, 16);
    const ny = fld(pk, 32);
    const rAx = fld(pk, 48);
    const rAy = fld(pk, 64);
    const rBx = fld(pk, 80);
    const rBy = fld(pk, 96);
    const radA = fld(pk, 112);
    const radB = fld(pk, 128);
    let ax = gather2(x, oa0, oa1);
    let ay = gather2(y, oa0, oa1);
    let bx = gather2(x, ob0, ob1);
    let by = gather2(y, ob0, ob1);
    let angA = gather2(angle, oa0, oa1);
    let angB = gather2(angle, ob0, ob1);
    let dA = f64x2.sub(angA, gather2(qangle, oa0, oa1));
    let dB = f64x2.sub(angB, gather2(qangle, ob0, ob1));
    const cA = gather2(rc, oa0, oa1);
    const sA = gather2(rs, oa0, oa1);
    const cB = gather2(rc, ob0, ob1);
    const sB = gather2(rs, ob0, ob1);
    const mAx = f64x2.sub(f64x2.mul(cA, rAx), f64x2.mul(sA, rAy));
    const mAy = f64x2.add(f64x2.mul(sA, rAx), f64x2.mul(cA, rAy));
    const mBx = f64x2.sub(f64x2.mul(cB, rBx), f64x2.mul(sB, rBy));
    const mBy = f64x2.add(f64x2.mul(sB, rBx), f64x2.mul(cB, rBy));
    const roundA = f64x2.gt(radA, zero);
    const roundB = f64x2.gt(radB, zero);
    const lAx = v128.bitselect(f64x2.mul(nx, radA), mAx, roundA);
    const lAy = v128.bitselect(f64x2.mul(ny, radA), mAy, roundA);
    const lBx = v128.bitselect(f64x2.mul(f64x2.neg(nx), radB), mBx, roundB);
    const lBy = v128.bitselect(f64x2.mul(f64x2.neg(ny), radB), mBy, roundB);
    // g = (ax + lAx − dA·lAy − (bx + lBx − dB·lBy))·nx + (ay + lAy + dA·lAx − (by + lBy + dB·lBx))·ny − allowance
    const gx = f64x2.sub(f64x2.sub(f64x2.add(ax, lAx), f64x2.mul(dA, lAy)), f64x2.sub(f64x2.add(bx, lBx), f64x2.mul(dB, lBy)));
    const gy = f64x2.sub(f64x2.add(f64x2.add(ay, lAy), f64x2.mul(dA, lAx)), f64x2.add(f64x2.add(by, lBy), f64x2.mul(dB, lBx)));
    const g = f64x2.sub(f64x2.add(f64x2.mul(gx, nx), f64x2.mul(gy, ny)), fld(pk, 224));
    const acts = f64x2.gt(g, zero);
    // Apart and not touched yet this step: slip becomes the whole drift (contact-solver.ts followApart).
    const apart = v128.andnot(f64x2.ne(fld(pk, 144), zero), v128.or(fld(pk, 320), acts));
    if (!v128.any_true(v128.or(acts, apart))) continue;
    const imA = fld(pk, 160);
    const iiA = fld(pk, 176);
    const imB = fld(pk, 192);
    const iiB = fld(pk, 208);
    // Weights, and what the velocity pass reads.
    const rnA = f64x2.sub(f64x2.mul(lAx, ny), f64x2.mul(lAy, nx));
    const rnB = f64x2.sub(f64x2.mul(lBx, ny), f64x2.mul(lBy, nx));
    const k00 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rnA), rnA)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rnB), rnB)));
    v128.store(pk, lAx, 336);
    v128.store(pk, lAy, 352);
    v128.store(pk, lBx, 368);
    v128.store(pk, lBy, 384);
    v128.store(pk, rnA, 400);
    v128.store(pk, rnB, 416);
    v128.store(pk, k00, 432);
    v128.store(pk, v128.or(fld(pk, 320), acts), 320);
    // Normal correction: l = g / k00 where the point overlaps (and k00 > 0), 0 elsewhere.
    const l = v128.and(f64x2.div(g, k00), v128.and(acts, f64x2.gt(k00, zero)));
    const mlA = f64x2.mul(imA, l);
    ax = f64x2.sub(ax, f64x2.mul(mlA, nx));
    ay = f64x2.sub(ay, f64x2.mul(mlA, ny));
    const tA = f64x2.mul(iiA, f64x2.mul(l, rnA));
    angA = f64x2.sub(angA, tA);
    dA = f64x2.sub(dA, tA);
    const mlB = f64x2.mul(imB, l);
    bx = f64x2.add(bx, f64x2.mul(mlB, nx));
    by = f64x2.add(by, f64x2.mul(mlB, ny));
    const tB = f64x2.mul(iiB, f64x2.mul(l, rnB));
    angB = f64x2.add(angB, tB);
    dB = f64x2.add(dB, tB);
    const lambda = f64x2.add(fld(pk, 240), l);
    const impulseN = f64x2.add(fld(pk, 256), l);
    v128.store(pk, lambda, 240);
    v128.store(pk, impulseN, 256);
    // Friction where μ > 0 and the point has acted this substep: the tangential drift of the material points, less
    // what has slid, undone within Coulomb's limit on the step's summed normal corrections.
    const mu = fld(pk, 144);
    const rtA = f64x2.add(f64x2.mul(mAx, nx), f64x2.mul(mAy, ny));
    const rtB = f64x2.add(f64x2.mul(mBx, nx), f64x2.mul(mBy, ny));
    const w = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA), rtA)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB), rtB)));
    const holds = v128.and(v128.and(acts, v128.and(f64x2.ne(mu, zero), f64x2.gt(lambda, zero))), f64x2.gt(w, zero));
    if (v128.any_true(v128.or(holds, apart))) {
      let offset = offsetAlong(ax, ay, bx, by, dA, dB, mAx, mAy, mBx, mBy, nx, ny);
      // A round side's material point measured along its rim (contacts.ts arcBeyond, the same series).
      if (v128.any_true(v128.or(roundA, roundB))) offset = f64x2.sub(f64x2.add(offset, arcBeyond(alongTangent(mAx, mAy, dA, nx, ny), radA)), arcBeyond(alongTangent(mBx, mBy, dB, nx, ny), radB));
      const slip = v128.bitselect(offset, fld(pk, 288), apart);
      const drift = f64x2.sub(offset, slip);
      const want = f64x2.div(drift, w);
      const limit = f64x2.mul(mu, impulseN);
      const before = fld(pk, 272);
      const total = f64x2.pmax(f64x2.pmin(f64x2.add(before, want), limit), f64x2.neg(limit));
      const dt = v128.and(f64x2.sub(total, before), holds);
      v128.store(pk, v128.bitselect(total, before, holds), 272);
      v128.store(pk, v128.bitselect(f64x2.add(slip, f64x2.mul(f64x2.sub(want, dt), w)), slip, holds), 288);
      const tlA = f64x2.mul(imA, dt);
      ax = f64x2.add(ax, f64x2.mul(tlA, ny));
      ay = f64x2.sub(ay, f64x2.mul(tlA, nx));
      angA = f64x2.sub(angA, f64x2.mul(f64x2.mul(iiA, rtA), dt));
      const tlB = f64x2.mul(imB, dt);
      bx = f64x2.sub(bx, f64x2.mul(tlB, ny));
      by = f64x2.add(by, f64x2.mul(tlB, nx));
      angB = f64x2.add(angB, f64x2.mul(f64x2.mul(iiB, rtB), dt));
    }
    scatter2(x, oa0, oa1, ax);
    scatter2(y, oa0, oa1, ay);
    scatter2(angle, oa0, oa1, angA);
    scatter2(x, ob0, ob1, bx);
    scatter2(y, ob0, ob1, by);
    scatter2(angle, ob0, ob1, angB);
  }
}

/** The velocity pass (restitution 0): each point that acted this substep gets normal speed 0. */
function rigidVelocities(vx: usize, vy: usize, omega: usize, packets: usize, count: i32): void {
  const zero = f64x2.splat(0);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * RIGID_PACKET;
    const acted = f64x2.gt(fld(pk, 240), zero);
    if (!v128.any_true(acted)) continue;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = fld(pk, 16);
    const ny = fld(pk, 32);
    let vax = gather2(vx, oa0, oa1);
    let vay = gather2(vy, oa0, oa1);
    let wa = gather2(omega, oa0, oa1);
    let vbx = gather2(vx, ob0, ob1);
    let vby = gather2(vy, ob0, ob1);
    let wb = gather2(omega, ob0, ob1);
    const rvx = f64x2.sub(vbx, vax);
    const rvy = f64x2.sub(vby, vay);
    // v = (rvx − wb·lBy + wa·lAy)·nx + (rvy + wb·lBx − wa·lAx)·ny
    const ux = f64x2.add(f64x2.sub(rvx, f64x2.mul(wb, fld(pk, 384))), f64x2.mul(wa, fld(pk, 352)));
    const uy = f64x2.sub(f64x2.add(rvy, f64x2.mul(wb, fld(pk, 368))), f64x2.mul(wa, fld(pk, 336)));
    const v = f64x2.add(f64x2.mul(ux, nx), f64x2.mul(uy, ny));
    const k00 = fld(pk, 432);
    const p = v128.and(f64x2.div(f64x2.sub(zero, v), k00), v128.and(acted, f64x2.gt(k00, zero)));
    const imA = fld(pk, 160);
    const iiA = fld(pk, 176);
    const imB = fld(pk, 192);
    const iiB = fld(pk, 208);
    const mpA = f64x2.mul(imA, p);
    const mpB = f64x2.mul(imB, p);
    vax = f64x2.sub(vax, f64x2.mul(mpA, nx));
    vay = f64x2.sub(vay, f64x2.mul(mpA, ny));
    wa = f64x2.sub(wa, f64x2.mul(iiA, f64x2.mul(p, fld(pk, 400))));
    vbx = f64x2.add(vbx, f64x2.mul(mpB, nx));
    vby = f64x2.add(vby, f64x2.mul(mpB, ny));
    wb = f64x2.add(wb, f64x2.mul(iiB, f64x2.mul(p, fld(pk, 416))));
    // Friction for the impulse (contact-solver.ts, the velocity pass): the sliding at a landing cut by up to μ·p.
    const mu = fld(pk, 144);
    const rtA = f64x2.add(f64x2.mul(fld(pk, 336), nx), f64x2.mul(fld(pk, 352), ny));
    const rtB = f64x2.add(f64x2.mul(fld(pk, 368), nx), f64x2.mul(fld(pk, 384), ny));
    const w = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA), rtA)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB), rtB)));
    // Only in the substep the point first acts in (its step's corrections are this substep's), as in the JS.
    const slides = v128.and(v128.and(v128.and(f64x2.gt(p, zero), f64x2.gt(mu, zero)), v128.and(f64x2.gt(w, zero), f64x2.lt(fld(pk, 304), zero))), f64x2.eq(fld(pk, 256), fld(pk, 240)));
    if (v128.any_true(slides)) {
      // vt = −rvx·ny + rvy·nx + wb·rtB − wa·rtA; a lane that does not slide adds 0.
      const vt = f64x2.sub(f64x2.add(f64x2.add(f64x2.mul(f64x2.neg(f64x2.sub(vbx, vax)), ny), f64x2.mul(f64x2.sub(vby, vay), nx)), f64x2.mul(wb, rtB)), f64x2.mul(wa, rtA));
      const limit = f64x2.mul(mu, p);
      const pt = v128.and(f64x2.pmax(f64x2.pmin(f64x2.div(f64x2.neg(vt), w), limit), f64x2.neg(limit)), slides);
      vax = f64x2.add(vax, f64x2.mul(f64x2.mul(imA, pt), ny));
      vay = f64x2.sub(vay, f64x2.mul(f64x2.mul(imA, pt), nx));
      wa = f64x2.sub(wa, f64x2.mul(f64x2.mul(iiA, rtA), pt));
      vbx = f64x2.sub(vbx, f64x2.mul(f64x2.mul(imB, pt), ny));
      vby = f64x2.add(vby, f64x2.mul(f64x2.mul(imB, pt), nx));
      wb = f64x2.add(wb, f64x2.mul(f64x2.mul(iiB, rtB), pt));
    }
    scatter2(vx, oa0, oa1, vax);
    scatter2(vy, oa0, oa1, vay);
    scatter2(omega, oa0, oa1, wa);
    scatter2(vx, ob0, ob1, vbx);
    scatter2(vy, ob0, ob1, vby);
    scatter2(omega, ob0, ob1, wb);
  }
}


// ---- Manifolds in lanes (issue 14): a step with two-point manifolds ---------------------------------------------
// A step whose rigid contacts include manifold pairs (boxes, polygons lying on a face) lays every contact out by
// manifold: one manifold a lane, two lanes a packet (coloured by bodies as above, the world and static bodies last),
// each lane holding its two points, the second inactive for a lone point (allowance +∞, so never overlapping; `two`
// 0). The formulas and their order of operations are solveRigidContacts' inline path (the 2×2 block normal solve, or
// one point after the other when it would pull; the manifold's friction at its points' midpoint) and
// solveRigidContactVelocities' (the 2×2 block on speeds, with the partner joining within two substeps' approach).
// A lane the JS solver skips (nothing overlaps, nothing to apply) writes its bodies back unchanged.
//
// Packet of two manifolds (bytes): 0: i32 ia0, ia1, ib0, ib1 (row × 8); then f64×2 fields at 16 + 16k:
//   k 0 nx  1 ny  2 friction  3 imA  4 iiA  5 imB  6 iiB  7 two (all-ones lanes)  8 impulseT  9 slip (point 0)
//    10 slip (point 1)  11 kn01 (written by the sweep)
//   point p at k = 12 + 18p: +0 rAx +1 rAy +2 rBx +3 rBy +4 radA +5 radB +6 allowance +7 lambdaN +8 impulseN +9 gap
//    +10 touched (all-ones lanes)  +11 lAx +12 lAy +13 lBx +14 lBy +15 rnA +16 rnB +17 wn (written by the sweep)
const MANIFOLD_PACKET: usize = 800;
const P0: usize = 16 + 16 * 12;
const P1: usize = 16 + 16 * 30;

@inline function mf(pk: usize, k: usize): v128 {
  return v128.load(pk + 16 + 16 * k);
}

@inline function mput(pk: usize, k: usize, v: v128): void {
  v128.store(pk + 16 + 16 * k, v);
}

/** The substep's start for manifold packets: λn 0, allowances shrink by maxPush (+∞ stays +∞). */
function manifoldBegin(packets: usize, count: i32, maxPush: f64): void {
  const zero = f64x2.splat(0);
  const push = f64x2.splat(maxPush);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * MANIFOLD_PACKET;
    v128.store(pk + P0, zero, 16 * 7);
    v128.store(pk + P1, zero, 16 * 7);
    const left0 = f64x2.sub(v128.load(pk + P0, 16 * 6), push);
    v128.store(pk + P0, v128.bitselect(left0, zero, f64x2.gt(left0, zero)), 16 * 6);
    const left1 = f64x2.sub(v128.load(pk + P1, 16 * 6), push);
    v128.store(pk + P1, v128.bitselect(left1, zero, f64x2.gt(left1, zero)), 16 * 6);
  }
}

/** Math.max(0, v) per lane (v finite or ±∞). */
@inline function max0(v: v128): v128 {
  return v128.and(v, f64x2.gt(v, f64x2.splat(0)));
}

/** One position sweep over `count` manifold packets (solveRigidContacts' inline path, lane by lane). */
function manifoldSweep(x: usize, y: usize, angle: usize, qangle: usize, rc: usize, rs: usize, packets: usize, count: i32): void {
  const zero = f64x2.splat(0);
  const half = f64x2.splat(0.5);
  const quarter = f64x2.splat(0.25);
  const tiny = f64x2.splat(1e-9);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * MANIFOLD_PACKET;
    const q0 = pk + P0;
    const q1 = pk + P1;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = mf(pk, 0);
    const ny = mf(pk, 1);
    const ax0 = gather2(x, oa0, oa1);
    const ay0 = gather2(y, oa0, oa1);
    const bx0 = gather2(x, ob0, ob1);
    const by0 = gather2(y, ob0, ob1);
    const angA0 = gather2(angle, oa0, oa1);
    const angB0 = gather2(angle, ob0, ob1);
    let dA = f64x2.sub(angA0, gather2(qangle, oa0, oa1));
    let dB = f64x2.sub(angB0, gather2(qangle, ob0, ob1));
    const cA = gather2(rc, oa0, oa1);
    const sA = gather2(rs, oa0, oa1);
    const cB = gather2(rc, ob0, ob1);
    const sB = gather2(rs, ob0, ob1);
    // Material levers (m) of both points, which are also their normal levers: no side is round here (lanesFit in
    // wasm-kernel.ts leaves a step with manifolds and round points to the JS solver).
    let rx = v128.load(q0);
    let ry = v128.load(q0, 16);
    const mA0x = f64x2.sub(f64x2.mul(cA, rx), f64x2.mul(sA, ry));
    const mA0y = f64x2.add(f64x2.mul(sA, rx), f64x2.mul(cA, ry));
    rx = v128.load(q0, 32);
    ry = v128.load(q0, 48);
    const mB0x = f64x2.sub(f64x2.mul(cB, rx), f64x2.mul(sB, ry));
    const mB0y = f64x2.add(f64x2.mul(sB, rx), f64x2.mul(cB, ry));
    rx = v128.load(q1);
    ry = v128.load(q1, 16);
    const mA1x = f64x2.sub(f64x2.mul(cA, rx), f64x2.mul(sA, ry));
    const mA1y = f64x2.add(f64x2.mul(sA, rx), f64x2.mul(cA, ry));
    rx = v128.load(q1, 32);
    ry = v128.load(q1, 48);
    const mB1x = f64x2.sub(f64x2.mul(cB, rx), f64x2.mul(sB, ry));
    const mB1y = f64x2.add(f64x2.mul(sB, rx), f64x2.mul(cB, ry));
    const lA0x = mA0x, lA0y = mA0y, lB0x = mB0x, lB0y = mB0y, lA1x = mA1x, lA1y = mA1y, lB1x = mB1x, lB1y = mB1y;
    // Overlaps past their allowances.
    const g0 = f64x2.sub(f64x2.add(
      f64x2.mul(f64x2.sub(f64x2.sub(f64x2.add(ax0, lA0x), f64x2.mul(dA, lA0y)), f64x2.sub(f64x2.add(bx0, lB0x), f64x2.mul(dB, lB0y))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(f64x2.add(ay0, lA0y), f64x2.mul(dA, lA0x)), f64x2.add(f64x2.add(by0, lB0y), f64x2.mul(dB, lB0x))), ny)),
      v128.load(q0, 96));
    const g1 = f64x2.sub(f64x2.add(
      f64x2.mul(f64x2.sub(f64x2.sub(f64x2.add(ax0, lA1x), f64x2.mul(dA, lA1y)), f64x2.sub(f64x2.add(bx0, lB1x), f64x2.mul(dB, lB1y))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(f64x2.add(ay0, lA1y), f64x2.mul(dA, lA1x)), f64x2.add(f64x2.add(by0, lB1y), f64x2.mul(dB, lB1x))), ny)),
      v128.load(q1, 96));
    v128.store(q0, g0, 144);
    v128.store(q1, g1, 144);
    const over0 = f64x2.gt(g0, zero);
    const over1 = f64x2.gt(g1, zero);
    const acts = v128.or(over0, over1);
    const two = mf(pk, 7);
    // Apart and neither point touched yet this step: both slips become the drift (contact-solver.ts followApart), by
    // the friction code below, which leaves such a lane's bodies as they are.
    const apart = v128.andnot(f64x2.ne(mf(pk, 2), zero), v128.or(acts, v128.or(v128.load(q0, 160), v128.load(q1, 160))));
    if (!v128.any_true(v128.or(acts, apart))) continue;
    // The manifold acts: weights, and what the velocity pass reads, for both points.
    const imA = mf(pk, 3);
    const iiA = mf(pk, 4);
    const imB = mf(pk, 5);
    const iiB = mf(pk, 6);
    const rnA0 = f64x2.sub(f64x2.mul(lA0x, ny), f64x2.mul(lA0y, nx));
    const rnB0 = f64x2.sub(f64x2.mul(lB0x, ny), f64x2.mul(lB0y, nx));
    const rnA1 = f64x2.sub(f64x2.mul(lA1x, ny), f64x2.mul(lA1y, nx));
    const rnB1 = f64x2.sub(f64x2.mul(lB1x, ny), f64x2.mul(lB1y, nx));
    const k00 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rnA0), rnA0)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rnB0), rnB0)));
    const k11 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rnA1), rnA1)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rnB1), rnB1)));
    const k01 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rnA0), rnA1)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rnB0), rnB1)));
    v128.store(q0, lA0x, 16 * 11);
    v128.store(q0, lA0y, 16 * 12);
    v128.store(q0, lB0x, 16 * 13);
    v128.store(q0, lB0y, 16 * 14);
    v128.store(q0, rnA0, 16 * 15);
    v128.store(q0, rnB0, 16 * 16);
    v128.store(q0, k00, 16 * 17);
    v128.store(q1, lA1x, 16 * 11);
    v128.store(q1, lA1y, 16 * 12);
    v128.store(q1, lB1x, 16 * 13);
    v128.store(q1, lB1y, 16 * 14);
    v128.store(q1, rnA1, 16 * 15);
    v128.store(q1, rnB1, 16 * 16);
    v128.store(q1, k11, 16 * 17);
    mput(pk, 11, k01);
    // Normal corrections: the 2×2 block when both overlap and it pushes, else the deeper point first, then the other
    // as far as it still overlaps (a lone point: its own correction, the second stays 0).
    const det = f64x2.sub(f64x2.mul(k00, k11), f64x2.mul(k01, k01));
    const block = v128.and(v128.and(over0, over1), f64x2.gt(det, f64x2.mul(f64x2.mul(tiny, k00), k11)));
    let l0 = v128.and(f64x2.div(f64x2.sub(f64x2.mul(k11, g0), f64x2.mul(k01, g1)), det), block);
    let l1 = v128.and(f64x2.div(f64x2.sub(f64x2.mul(k00, g1), f64x2.mul(k01, g0)), det), block);
    const pushes = v128.and(f64x2.gt(l0, zero), f64x2.gt(l1, zero));
    if (!i64x2.all_true(pushes)) {
      const k00p = f64x2.gt(k00, zero);
      const k11p = f64x2.gt(k11, zero);
      const fa0 = v128.and(f64x2.div(g0, k00), k00p);
      const fa1 = v128.and(max0(f64x2.div(f64x2.sub(g1, f64x2.mul(k01, fa0)), k11)), k11p);
      const fb1 = v128.and(f64x2.div(g1, k11), k11p);
      const fb0 = v128.and(max0(f64x2.div(f64x2.sub(g0, f64x2.mul(k01, fb1)), k00)), k00p);
      const first = f64x2.ge(g0, g1);
      l0 = v128.bitselect(l0, v128.bitselect(fa0, fb0, first), pushes);
      l1 = v128.bitselect(l1, v128.bitselect(fa1, fb1, first), pushes);
    }
    l0 = v128.and(l0, acts);
    l1 = v128.and(l1, v128.and(acts, two));
    const t0 = v128.or(over0, f64x2.gt(l0, zero));
    const t1 = v128.or(over1, f64x2.gt(l1, zero));
    v128.store(q0, v128.or(v128.load(q0, 160), t0), 160);
    v128.store(q1, v128.or(v128.load(q1, 160), t1), 160);
    // Apply: A back along n, B forward, each turned by its levers' cross products (nothing when ln is 0).
    const ln = f64x2.add(l0, l1);
    const moves = f64x2.ne(ln, zero);
    const mlA = f64x2.mul(imA, ln);
    let ax1 = f64x2.sub(ax0, f64x2.mul(mlA, nx));
    let ay1 = f64x2.sub(ay0, f64x2.mul(mlA, ny));
    const tA = f64x2.mul(iiA, f64x2.add(f64x2.mul(l0, rnA0), v128.and(f64x2.mul(l1, rnA1), two)));
    let angA1 = f64x2.sub(angA0, tA);
    const mlB = f64x2.mul(imB, ln);
    let bx1 = f64x2.add(bx0, f64x2.mul(mlB, nx));
    let by1 = f64x2.add(by0, f64x2.mul(mlB, ny));
    const tB = f64x2.mul(iiB, f64x2.add(f64x2.mul(l0, rnB0), v128.and(f64x2.mul(l1, rnB1), two)));
    let angB1 = f64x2.add(angB0, tB);
    let lambda0 = f64x2.add(v128.load(q0, 112), l0);
    let lambda1 = f64x2.add(v128.load(q1, 112), l1);
    let impulse0 = f64x2.add(v128.load(q0, 128), l0);
    let impulse1 = f64x2.add(v128.load(q1, 128), l1);
    const dA1 = f64x2.sub(dA, tA);
    const dB1 = f64x2.add(dB, tB);
    if (i64x2.all_true(moves)) {
      dA = dA1;
      dB = dB1;
    } else {
      // A lane with nothing to apply keeps its bodies and multipliers exactly (the JS skips it).
      ax1 = v128.bitselect(ax1, ax0, moves);
      ay1 = v128.bitselect(ay1, ay0, moves);
      angA1 = v128.bitselect(angA1, angA0, moves);
      dA = v128.bitselect(dA1, dA, moves);
      bx1 = v128.bitselect(bx1, bx0, moves);
      by1 = v128.bitselect(by1, by0, moves);
      angB1 = v128.bitselect(angB1, angB0, moves);
      dB = v128.bitselect(dB1, dB, moves);
      lambda0 = v128.bitselect(lambda0, v128.load(q0, 112), moves);
      lambda1 = v128.bitselect(lambda1, v128.load(q1, 112), moves);
      impulse0 = v128.bitselect(impulse0, v128.load(q0, 128), moves);
      impulse1 = v128.bitselect(impulse1, v128.load(q1, 128), moves);
    }
    v128.store(q0, lambda0, 112);
    v128.store(q1, lambda1, 112);
    v128.store(q0, impulse0, 128);
    v128.store(q1, impulse1, 128);
    let axN = ax1;
    let ayN = ay1;
    let angAN = angA1;
    let bxN = bx1;
    let byN = by1;
    let angBN = angB1;
    // Friction at the manifold's midpoint (a lone point: at the point), within Coulomb's limit on the step's summed
    // normal corrections.
    const mu = mf(pk, 2);
    const loaded = v128.and(acts, v128.and(f64x2.ne(mu, zero), v128.or(f64x2.gt(lambda0, zero), f64x2.gt(lambda1, zero))));
    if (v128.any_true(v128.or(loaded, apart))) {
      const drift0 = offsetAlong(ax1, ay1, bx1, by1, dA, dB, mA0x, mA0y, mB0x, mB0y, nx, ny);
      const drift1 = offsetAlong(ax1, ay1, bx1, by1, dA, dB, mA1x, mA1y, mB1x, mB1y, nx, ny);
      const rtA0 = f64x2.add(f64x2.mul(mA0x, nx), f64x2.mul(mA0y, ny));
      const rtB0 = f64x2.add(f64x2.mul(mB0x, nx), f64x2.mul(mB0y, ny));
      const rtA1 = f64x2.add(f64x2.mul(mA1x, nx), f64x2.mul(mA1y, ny));
      const rtB1 = f64x2.add(f64x2.mul(mB1x, nx), f64x2.mul(mB1y, ny));
      const w0 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA0), rtA0)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB0), rtB0)));
      const w1 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA1), rtA1)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB1), rtB1)));
      const kt01 = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA0), rtA1)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB0), rtB1)));
      const offset = v128.bitselect(f64x2.mul(half, f64x2.add(drift0, drift1)), drift0, two);
      const slip = v128.bitselect(offset, mf(pk, 9), apart);
      const drift = f64x2.sub(offset, slip);
      const la = v128.bitselect(f64x2.mul(half, f64x2.add(rtA0, rtA1)), rtA0, two);
      const lb = v128.bitselect(f64x2.mul(half, f64x2.add(rtB0, rtB1)), rtB0, two);
      const w = v128.bitselect(f64x2.add(f64x2.mul(quarter, f64x2.add(w0, w1)), f64x2.mul(half, kt01)), w0, two);
      const load = v128.bitselect(f64x2.add(impulse0, impulse1), impulse0, two);
      const holds = v128.and(loaded, f64x2.gt(w, zero));
      const want = f64x2.div(drift, w);
      const limit = f64x2.mul(mu, load);
      const before = mf(pk, 8);
      const total = f64x2.pmax(f64x2.pmin(f64x2.add(before, want), limit), f64x2.neg(limit));
      const dt = f64x2.sub(total, before);
      const slipped = f64x2.add(slip, f64x2.mul(f64x2.sub(want, dt), w));
      const tlA = f64x2.mul(imA, dt);
      axN = f64x2.add(ax1, f64x2.mul(tlA, ny));
      ayN = f64x2.sub(ay1, f64x2.mul(tlA, nx));
      angAN = f64x2.sub(angA1, f64x2.mul(f64x2.mul(iiA, la), dt));
      const tlB = f64x2.mul(imB, dt);
      bxN = f64x2.sub(bx1, f64x2.mul(tlB, ny));
      byN = f64x2.add(by1, f64x2.mul(tlB, nx));
      angBN = f64x2.add(angB1, f64x2.mul(f64x2.mul(iiB, lb), dt));
      // A lane where friction does not act keeps its bodies and state exactly.
      mput(pk, 8, v128.bitselect(total, before, holds));
      mput(pk, 9, v128.bitselect(slipped, slip, holds));
      mput(pk, 10, v128.bitselect(slipped, v128.bitselect(offset, mf(pk, 10), apart), v128.and(holds, two)));
      axN = v128.bitselect(axN, ax1, holds);
      ayN = v128.bitselect(ayN, ay1, holds);
      angAN = v128.bitselect(angAN, angA1, holds);
      bxN = v128.bitselect(bxN, bx1, holds);
      byN = v128.bitselect(byN, by1, holds);
      angBN = v128.bitselect(angBN, angB1, holds);
    }
    scatter2(x, oa0, oa1, axN);
    scatter2(y, oa0, oa1, ayN);
    scatter2(angle, oa0, oa1, angAN);
    scatter2(x, ob0, ob1, bxN);
    scatter2(y, ob0, ob1, byN);
    scatter2(angle, ob0, ob1, angBN);
  }
}

/** The velocity pass over manifold packets (restitution 0: target speed 0); h the substep's length. */
function manifoldVelocities(vx: usize, vy: usize, omega: usize, packets: usize, count: i32, h: f64): void {
  const zero = f64x2.splat(0);
  const tiny = f64x2.splat(1e-9);
  const twice = f64x2.splat(2);
  const vh = f64x2.splat(h);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * MANIFOLD_PACKET;
    const q0 = pk + P0;
    const q1 = pk + P1;
    const acted0 = f64x2.gt(v128.load(q0, 112), zero);
    const acted1 = f64x2.gt(v128.load(q1, 112), zero);
    const acted = v128.or(acted0, acted1);
    if (!v128.any_true(acted)) continue;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = mf(pk, 0);
    const ny = mf(pk, 1);
    const two = mf(pk, 7);
    const vax = gather2(vx, oa0, oa1);
    const vay = gather2(vy, oa0, oa1);
    const wa = gather2(omega, oa0, oa1);
    const vbx = gather2(vx, ob0, ob1);
    const vby = gather2(vy, ob0, ob1);
    const wb = gather2(omega, ob0, ob1);
    const rvx = f64x2.sub(vbx, vax);
    const rvy = f64x2.sub(vby, vay);
    // v = (rvx − wb·lBy + wa·lAy)·nx + (rvy + wb·lBx − wa·lAx)·ny, per point.
    const v0 = f64x2.add(
      f64x2.mul(f64x2.add(f64x2.sub(rvx, f64x2.mul(wb, v128.load(q0, 16 * 14))), f64x2.mul(wa, v128.load(q0, 16 * 12))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(rvy, f64x2.mul(wb, v128.load(q0, 16 * 13))), f64x2.mul(wa, v128.load(q0, 16 * 11))), ny));
    const v1 = f64x2.add(
      f64x2.mul(f64x2.add(f64x2.sub(rvx, f64x2.mul(wb, v128.load(q1, 16 * 14))), f64x2.mul(wa, v128.load(q1, 16 * 12))), nx),
      f64x2.mul(f64x2.sub(f64x2.add(rvy, f64x2.mul(wb, v128.load(q1, 16 * 13))), f64x2.mul(wa, v128.load(q1, 16 * 11))), ny));
    // A point joins when it acted, or when its partner acted while it was within two substeps' approach.
    const use0 = v128.and(acted, v128.or(acted0, v128.and(f64x2.lt(v0, zero), f64x2.gt(v128.load(q0, 144), f64x2.mul(f64x2.mul(twice, v0), vh)))));
    const use1 = v128.and(v128.and(acted, two), v128.or(acted1, v128.and(f64x2.lt(v1, zero), f64x2.gt(v128.load(q1, 144), f64x2.mul(f64x2.mul(twice, v1), vh)))));
    const b0 = f64x2.sub(zero, v0);
    const b1 = f64x2.sub(zero, v1);
    const k00 = v128.load(q0, 16 * 17);
    const k11 = v128.load(q1, 16 * 17);
    const k01 = mf(pk, 11);
    const both = v128.and(use0, use1);
    // Both: the 2×2 block, or (dependent) one after the other without measuring again.
    const det = f64x2.sub(f64x2.mul(k00, k11), f64x2.mul(k01, k01));
    const block = f64x2.gt(det, f64x2.mul(f64x2.mul(tiny, k00), k11));
    // The block's answer; the other cases only when some lane does not take it.
    let p0 = f64x2.div(f64x2.sub(f64x2.mul(k11, b0), f64x2.mul(k01, b1)), det);
    let p1 = f64x2.div(f64x2.sub(f64x2.mul(k00, b1), f64x2.mul(k01, b0)), det);
    const blocked = v128.and(both, block);
    // A block that pushes one point and pulls the other (a rolling polygon's pivot): the pushing point alone.
    const on0 = v128.and(blocked, v128.and(f64x2.ge(p0, zero), f64x2.lt(p1, zero)));
    const on1 = v128.and(blocked, v128.and(f64x2.ge(p1, zero), f64x2.lt(p0, zero)));
    if (v128.any_true(v128.or(on0, on1))) {
      p0 = v128.bitselect(f64x2.div(b0, k00), v128.andnot(p0, on1), on0);
      p1 = v128.bitselect(f64x2.div(b1, k11), v128.andnot(p1, on0), on1);
    }
    if (!i64x2.all_true(blocked)) {
      const pf0 = f64x2.div(b0, k00);
      const pf1 = f64x2.div(f64x2.sub(b1, f64x2.mul(k01, pf0)), k11);
      // One point: its own, where its weight is positive.
      const po0 = v128.and(pf0, f64x2.gt(k00, zero));
      const po1 = v128.and(f64x2.div(b1, k11), f64x2.gt(k11, zero));
      p0 = v128.bitselect(v128.bitselect(p0, pf0, block), v128.and(po0, use0), both);
      p1 = v128.bitselect(v128.bitselect(p1, pf1, block), v128.and(po1, use1), both);
    }
    const kicks = v128.and(acted, v128.not(v128.and(f64x2.eq(p0, zero), f64x2.eq(p1, zero))));
    if (!v128.any_true(kicks)) continue;
    const P = f64x2.add(p0, p1);
    const imA = mf(pk, 3);
    const iiA = mf(pk, 4);
    const imB = mf(pk, 5);
    const iiB = mf(pk, 6);
    const mpA = f64x2.mul(imA, P);
    const mpB = f64x2.mul(imB, P);
    const tA = f64x2.mul(iiA, f64x2.add(f64x2.mul(p0, v128.load(q0, 16 * 15)), v128.and(f64x2.mul(p1, v128.load(q1, 16 * 15)), two)));
    const tB = f64x2.mul(iiB, f64x2.add(f64x2.mul(p0, v128.load(q0, 16 * 16)), v128.and(f64x2.mul(p1, v128.load(q1, 16 * 16)), two)));
    let nvax = f64x2.sub(vax, f64x2.mul(mpA, nx));
    let nvay = f64x2.sub(vay, f64x2.mul(mpA, ny));
    let nwa = f64x2.sub(wa, tA);
    let nvbx = f64x2.add(vbx, f64x2.mul(mpB, nx));
    let nvby = f64x2.add(vby, f64x2.mul(mpB, ny));
    let nwb = f64x2.add(wb, tB);
    if (!i64x2.all_true(kicks)) {
      // A lane with no impulse keeps its bodies' velocities exactly (the JS skips it).
      nvax = v128.bitselect(nvax, vax, kicks);
      nvay = v128.bitselect(nvay, vay, kicks);
      nwa = v128.bitselect(nwa, wa, kicks);
      nvbx = v128.bitselect(nvbx, vbx, kicks);
      nvby = v128.bitselect(nvby, vby, kicks);
      nwb = v128.bitselect(nwb, wb, kicks);
    }
    // Friction for the impulse, as for single points, at the first point's levers (a face's two points have the same
    // lever along n, so the same turn and speed along t).
    const mu = mf(pk, 2);
    const rtA = f64x2.add(f64x2.mul(v128.load(q0, 16 * 11), nx), f64x2.mul(v128.load(q0, 16 * 12), ny));
    const rtB = f64x2.add(f64x2.mul(v128.load(q0, 16 * 13), nx), f64x2.mul(v128.load(q0, 16 * 14), ny));
    const w = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA), rtA)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB), rtB)));
    // A landing: every point apart when the step began (field 48: the larger depth), none acting before this substep.
    const slides = v128.and(v128.and(v128.and(kicks, f64x2.lt(mf(pk, 48), zero)), v128.and(f64x2.eq(v128.load(q0, 128), v128.load(q0, 112)), f64x2.eq(v128.load(q1, 128), v128.load(q1, 112)))), v128.and(v128.and(f64x2.gt(P, zero), f64x2.gt(mu, zero)), f64x2.gt(w, zero)));
    if (v128.any_true(slides)) {
      const vt = f64x2.sub(f64x2.add(f64x2.add(f64x2.mul(f64x2.neg(f64x2.sub(nvbx, nvax)), ny), f64x2.mul(f64x2.sub(nvby, nvay), nx)), f64x2.mul(nwb, rtB)), f64x2.mul(nwa, rtA));
      const limit = f64x2.mul(mu, P);
      const pt = v128.and(f64x2.pmax(f64x2.pmin(f64x2.div(f64x2.neg(vt), w), limit), f64x2.neg(limit)), slides);
      nvax = f64x2.add(nvax, f64x2.mul(f64x2.mul(imA, pt), ny));
      nvay = f64x2.sub(nvay, f64x2.mul(f64x2.mul(imA, pt), nx));
      nwa = f64x2.sub(nwa, f64x2.mul(f64x2.mul(iiA, rtA), pt));
      nvbx = f64x2.sub(nvbx, f64x2.mul(f64x2.mul(imB, pt), ny));
      nvby = f64x2.add(nvby, f64x2.mul(f64x2.mul(imB, pt), nx));
      nwb = f64x2.add(nwb, f64x2.mul(f64x2.mul(iiB, rtB), pt));
    }
    scatter2(vx, oa0, oa1, nvax);
    scatter2(vy, oa0, oa1, nvay);
    scatter2(omega, oa0, oa1, nwa);
    scatter2(vx, ob0, ob1, nvbx);
    scatter2(vy, ob0, ob1, nvby);
    scatter2(omega, ob0, ob1, nwb);
  }
}

// The exports under one-letter names (wasm-kernel.ts KernelExports maps them back): a name is written in the module and
// again in the JS that calls it, in every build that ships the kernel.
export {
  solveDistances as a,
  integrateVerlet as b,
  updateVelocities as c,
  rigidLayout as d,
  rigidBegin as e,
  rigidSweep as f,
  rigidVelocities as g,
  manifoldBegin as h,
  manifoldSweep as i,
  manifoldVelocities as j,
};
