// An experiment, not shipped (bench/kernel.mjs --f32 compiles it): the distance sweep in f32x4 lanes over float32
// copies of x, y and the inverse masses, to measure against the shipped f64x2 kernel on the engine's own f64 columns.
// Packets of four constraints of one colour:
//   0: i32×4 byte offsets of a0..a3 into the f32 columns    16: i32×4 of b0..b3
//  32: f32×4 lo   48: f32×4 hi   64: f32×4 compliance   80: f32×4 lambda
const PACKET: usize = 96;

@inline function gather(base: usize, i: v128): v128 {
  let v = f32x4.splat(load<f32>(base + <usize>i32x4.extract_lane(i, 0)));
  v = f32x4.replace_lane(v, 1, load<f32>(base + <usize>i32x4.extract_lane(i, 1)));
  v = f32x4.replace_lane(v, 2, load<f32>(base + <usize>i32x4.extract_lane(i, 2)));
  return f32x4.replace_lane(v, 3, load<f32>(base + <usize>i32x4.extract_lane(i, 3)));
}

@inline function scatter(base: usize, i: v128, v: v128): void {
  store<f32>(base + <usize>i32x4.extract_lane(i, 0), f32x4.extract_lane(v, 0));
  store<f32>(base + <usize>i32x4.extract_lane(i, 1), f32x4.extract_lane(v, 1));
  store<f32>(base + <usize>i32x4.extract_lane(i, 2), f32x4.extract_lane(v, 2));
  store<f32>(base + <usize>i32x4.extract_lane(i, 3), f32x4.extract_lane(v, 3));
}

export function solveDistances32(x: usize, y: usize, invMass: usize, packets: usize, count: i32, h2: f32): void {
  const vh2 = f32x4.splat(h2);
  const zero = f32x4.splat(0);
  const one = f32x4.splat(1);
  const tiny = f32x4.splat(1e-12);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET;
    const ia = v128.load(pk);
    const ib = v128.load(pk, 16);
    const lo = v128.load(pk, 32);
    const hi = v128.load(pk, 48);
    const compliance = v128.load(pk, 64);
    const lambda = v128.load(pk, 80);
    const xa = gather(x, ia);
    const ya = gather(y, ia);
    const xb = gather(x, ib);
    const yb = gather(y, ib);
    const wa = gather(invMass, ia);
    const wb = gather(invMass, ib);
    const w = f32x4.add(wa, wb);
    let dx = f32x4.sub(xb, xa);
    let dy = f32x4.sub(yb, ya);
    const d2 = f32x4.add(f32x4.mul(dx, dx), f32x4.mul(dy, dy));
    const slack = v128.and(f32x4.ne(lo, hi), v128.and(f32x4.ge(d2, f32x4.mul(lo, lo)), f32x4.le(d2, f32x4.mul(hi, hi))));
    const active = v128.andnot(f32x4.ne(w, zero), slack);
    let d = f32x4.sqrt(d2);
    const err = v128.bitselect(f32x4.sub(d, hi), f32x4.sub(d, lo), f32x4.gt(d2, f32x4.mul(hi, hi)));
    const coincident = f32x4.lt(d, tiny);
    dx = v128.bitselect(one, dx, coincident);
    dy = v128.bitselect(zero, dy, coincident);
    d = v128.bitselect(one, d, coincident);
    const alpha = f32x4.div(compliance, vh2);
    const denominator = v128.bitselect(f32x4.add(w, alpha), one, active);
    const dl = v128.and(f32x4.div(f32x4.sub(f32x4.neg(err), f32x4.mul(alpha, lambda)), denominator), active);
    v128.store(pk, f32x4.add(lambda, dl), 80);
    const s = f32x4.div(dl, d);
    scatter(x, ia, f32x4.sub(xa, f32x4.mul(f32x4.mul(wa, s), dx)));
    scatter(y, ia, f32x4.sub(ya, f32x4.mul(f32x4.mul(wa, s), dy)));
    scatter(x, ib, f32x4.add(xb, f32x4.mul(f32x4.mul(wb, s), dx)));
    scatter(y, ib, f32x4.add(yb, f32x4.mul(f32x4.mul(wb, s), dy)));
  }
}

/** f64 column → f32 copy (n even), and back: what an f32 kernel on the engine's f64 state pays per substep. */
export function demote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) store<u64>(dst + (<usize>i << 2), i64x2.extract_lane(f32x4.demote_f64x2_zero(v128.load(src + (<usize>i << 3))), 0));
}

export function promote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) v128.store(dst + (<usize>i << 3), f64x2.promote_low_f32x4(v128.load64_zero(src + (<usize>i << 2))));
}
