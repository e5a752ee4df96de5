// The particle solver kernel in AssemblyScript, compiled to WebAssembly with 128-bit SIMD (f64x2 lanes) by
// scripts/build-wasm.mjs. Not part of the TypeScript build (hence the .as name): its output is the byte string in
// wasm-bytes.ts. It owns no memory of its own layout: the TypeScript side (wasm-kernel.ts) places the engine's
// particle columns and the coloured constraint packets in the imported memory and passes their byte addresses.
//
// Every formula is the JS solver's, written in the same order of operations, so a constraint solved here gives the
// same doubles as in distance.ts; only the order in which constraints are visited differs (coloured batches).

// A packet is two distance constraints of the same colour (they share no movable particle, so their lanes are
// independent):
//   0: i32×4  byte offsets of a0, a1, b0, b1 into the x, y and invMass columns
//  16: f64×2  lo   minLength        32: f64×2  hi   maxLength
//  48: f64×2  compliance            64: f64×2  lambda (the XPBD multiplier, this substep)
const PACKET: usize = 80;

/**
 * One Gauss–Seidel sweep over `packets` distance-constraint packets (XPBD; h2 = substep²). `fresh`: the first sweep of
 * a substep, whose multipliers start at zero (saves a pass over the packets to clear them).
 */
export function solveDistances(x: usize, y: usize, invMass: usize, packets: usize, count: i32, h2: f64, fresh: bool): void {
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
    // A slack link (lo < hi) whose length is within its limits does nothing; neither does a link between immovables.
    const slack = v128.and(f64x2.ne(lo, hi), v128.and(f64x2.ge(d2, f64x2.mul(lo, lo)), f64x2.le(d2, f64x2.mul(hi, hi))));
    const active = v128.andnot(f64x2.ne(w, zero), slack);
    // Slack links within their limits (a cloth's tethers, mostly) are batched apart from sticks: skip such packets.
    if (!v128.any_true(active)) continue;
    let d = f64x2.sqrt(d2);
    // Past the upper limit the error is d − hi; otherwise d − lo (the same when lo = hi).
    const err = v128.bitselect(f64x2.sub(d, hi), f64x2.sub(d, lo), f64x2.gt(d, hi));
    // Coincident particles have no direction: a fixed one keeps the result finite and deterministic.
    const coincident = f64x2.lt(d, tinyLength);
    dx = v128.bitselect(one, dx, coincident);
    dy = v128.bitselect(zero, dy, coincident);
    d = v128.bitselect(one, d, coincident);
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
 * x += v·damp·h + a·h². Columns are f64 arrays at the given byte addresses.
 */
export function integrateVerlet(x: usize, y: usize, px: usize, py: usize, vx: usize, vy: usize, ax: usize, ay: usize, invMass: usize, n: i32, h: f64, damp: f64): void {
  const vh = f64x2.splat(h);
  const vh2 = f64x2.splat(h * h);
  const vdamp = f64x2.splat(damp);
  const zero = f64x2.splat(0);
  for (let i = 0; i < n; i += 2) {
    const o = <usize>i << 3;
    const movable = f64x2.ne(v128.load(invMass + o), zero);
    const cx = v128.load(x + o);
    const cy = v128.load(y + o);
    v128.store(px + o, cx);
    v128.store(py + o, cy);
    const nx = f64x2.add(cx, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vx + o), vdamp), vh), f64x2.mul(v128.load(ax + o), vh2)));
    const ny = f64x2.add(cy, f64x2.add(f64x2.mul(f64x2.mul(v128.load(vy + o), vdamp), vh), f64x2.mul(v128.load(ay + o), vh2)));
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
