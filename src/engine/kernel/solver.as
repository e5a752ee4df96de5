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
export function solveDistances(x: usize, y: usize, invMass: usize, runs: usize, runCount: i32, packets: usize, count: i32, h2: f64, fresh: bool): void {
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
    else if (shape == 4) sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, false, COMPLIANT);
    else sweepRun(x, y, invMass, a, b, pairs, data, h2, fresh, true, COMPLIANT);
  }
  solvePackets(x, y, invMass, packets, count, h2, fresh);
}

@inline function laneBytes(kind: i32): usize {
  return kind == STICK ? 16 : kind == LIMITS ? 32 : 64;
}

/** Pairs of lanes of one run: parallel lanes (a + k, b + k), or interleaved lanes (a + 2k, a + 2k + 1). */
@inline function sweepRun(x: usize, y: usize, invMass: usize, a: usize, b: usize, pairs: i32, data: usize, h2: f64, fresh: bool, interleaved: bool, kind: i32): void {
  const vh2 = f64x2.splat(h2);
  const zero = f64x2.splat(0);
  const one = f64x2.splat(1);
  const tinyLength = f64x2.splat(1e-12);
  const step: usize = interleaved ? 32 : 16;
  for (let k = 0; k < pairs; k++) {
    const oa = a + <usize>k * step;
    const ob = b + <usize>k * step;
    const pk = data + <usize>k * laneBytes(kind);
    let xa: v128, ya: v128, xb: v128, yb: v128, wa: v128, wb: v128;
    if (interleaved) {
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
    const err = kind == STICK ? f64x2.sub(d, lo) : v128.bitselect(f64x2.sub(d, hi), f64x2.sub(d, lo), f64x2.gt(d, hi));
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
    if (interleaved) {
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
    const err = v128.bitselect(f64x2.sub(d, hi), f64x2.sub(d, lo), f64x2.gt(d, hi));
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
export function integrateVerlet(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, ax: usize, ay: usize, invMass: usize, n: i32, h: f64, damp: f64, forces: bool, gx: f64, gy: f64): void {
  if (forces) integrate(x, y, px, py, vx, vy, ax, ay, invMass, n, h, damp, true, gx, gy);
  else integrate(x, y, px, py, vx, vy, ax, ay, invMass, n, h, damp, false, gx, gy);
}

@inline function integrate(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, ax: usize, ay: usize, invMass: usize, n: i32, h: f64, damp: f64, forces: bool, gx: f64, gy: f64): void {
  const vh = f64x2.splat(h);
  const vh2 = f64x2.splat(h * h);
  const vdamp = f64x2.splat(damp);
  const vgx = f64x2.splat(gx);
  const vgy = f64x2.splat(gy);
  const zero = f64x2.splat(0);
  for (let i = 0; i < n; i += 2) {
    const o = <usize>i << 3;
    const w = v128.load(invMass + o);
    const movable = f64x2.ne(w, zero);
    const cx = v128.load(x + o);
    const cy = v128.load(y + o);
    v128.store(px + o, cx);
    v128.store(py + o, cy);
    // With forces, ax and ay are the columns fx and fy: a = g + f·invMass, as accelerate() computes it.
    const accx = forces ? f64x2.add(vgx, f64x2.mul(v128.load(ax + o), w)) : v128.load(ax + o);
    const accy = forces ? f64x2.add(vgy, f64x2.mul(v128.load(ay + o), w)) : v128.load(ay + o);
    const nx = f64x2.add(cx, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vx + o), vdamp), vh), f64x2.mul(accx, vh2)));
    const ny = f64x2.add(cy, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vy + o), vdamp), vh), f64x2.mul(accy, vh2)));
    v128.store(x + o, v128.bitselect(nx, cx, movable));
    v128.store(y + o, v128.bitselect(ny, cy, movable));
  }
}

/** Velocities from the substep's motion: v = (x − px)·(1/h), rows [0, n) rounded up to even. */
export function updateVelocities(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, n: i32, inv: f64): void {
  const vinv = f64x2.splat(inv);
  for (let i = 0; i < n; i += 2) {
    const o = <usize>i << 3;
    v128.store(vx + o, f64x2.mul(f64x2.sub(v128.load(x + o), v128.load(px + o)), vinv));
    v128.store(vy + o, f64x2.mul(f64x2.sub(v128.load(y + o), v128.load(py + o)), vinv));
  }
}
