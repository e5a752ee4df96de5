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
// 224 allowance 240 lambdaN 256 impulseN 272 impulseT 288 slip 304 gap 320 touched (all-ones lanes)   (state)
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

/** The substep's start (RigidContacts.beginSubstep): λn 0, allowances shrink by maxPush. */
export function rigidBegin(packets: usize, count: i32, maxPush: f64): void {
  const zero = f64x2.splat(0);
  const push = f64x2.splat(maxPush);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * RIGID_PACKET;
    v128.store(pk, zero, 240);
    const left = f64x2.sub(fld(pk, 224), push);
    v128.store(pk, v128.bitselect(left, zero, f64x2.gt(left, zero)), 224);
  }
}

/** One position sweep over `count` packets: normal correction, then friction, per point. */
export function rigidSweep(x: usize, y: usize, angle: usize, qangle: usize, rc: usize, rs: usize, packets: usize, count: i32): void {
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
    v128.store(pk, g, 304);
    const acts = f64x2.gt(g, zero);
    if (!v128.any_true(acts)) continue;
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
    if (v128.any_true(holds)) {
      const ux = f64x2.sub(f64x2.sub(f64x2.add(ax, mAx), f64x2.mul(dA, mAy)), f64x2.sub(f64x2.add(bx, mBx), f64x2.mul(dB, mBy)));
      const uy = f64x2.sub(f64x2.add(f64x2.add(ay, mAy), f64x2.mul(dA, mAx)), f64x2.add(f64x2.add(by, mBy), f64x2.mul(dB, mBx)));
      const slip = fld(pk, 288);
      const drift = f64x2.sub(f64x2.add(f64x2.mul(f64x2.neg(ux), ny), f64x2.mul(uy, nx)), slip);
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
export function rigidVelocities(vx: usize, vy: usize, omega: usize, packets: usize, count: i32): void {
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
    const mpA = f64x2.mul(fld(pk, 160), p);
    const mpB = f64x2.mul(fld(pk, 192), p);
    vax = f64x2.sub(vax, f64x2.mul(mpA, nx));
    vay = f64x2.sub(vay, f64x2.mul(mpA, ny));
    wa = f64x2.sub(wa, f64x2.mul(fld(pk, 176), f64x2.mul(p, fld(pk, 400))));
    vbx = f64x2.add(vbx, f64x2.mul(mpB, nx));
    vby = f64x2.add(vby, f64x2.mul(mpB, ny));
    wb = f64x2.add(wb, f64x2.mul(fld(pk, 208), f64x2.mul(p, fld(pk, 416))));
    scatter2(vx, oa0, oa1, vax);
    scatter2(vy, oa0, oa1, vay);
    scatter2(omega, oa0, oa1, wa);
    scatter2(vx, ob0, ob1, vbx);
    scatter2(vy, ob0, ob1, vby);
    scatter2(omega, ob0, ob1, wb);
  }
}

