// An experiment, not shipped (issue 16; bench/experiment-rigid.mjs compiles it together with solver.as, whose
// rigidBegin / rigidSweep / rigidVelocities are the shipped f64x2 lanes): the rigid contact position sweep in f32x4
// lanes over float32 copies of the body columns, packets of four points, the same colours as the f64x2 layout, and
// the copies' cost (demote, promote). Same formulas and order of operations as rigidSweep in solver.as.

// The f32x4 variant: packets of four points, the same fields at 16 + 16k for the f64 layout's field k at 16k (i32x4
// offsets of a at 0 and of b at 16, row × 4 into float32 columns).
const PACKET4: usize = 464;

@inline function gather4(column: usize, o: v128): v128 {
  let v = v128.load32_splat(column + <usize>i32x4.extract_lane(o, 0));
  v = v128.load32_lane(column + <usize>i32x4.extract_lane(o, 1), v, 1);
  v = v128.load32_lane(column + <usize>i32x4.extract_lane(o, 2), v, 2);
  return v128.load32_lane(column + <usize>i32x4.extract_lane(o, 3), v, 3);
}

@inline function scatter4(column: usize, o: v128, v: v128): void {
  v128.store32_lane(column + <usize>i32x4.extract_lane(o, 0), v, 0);
  v128.store32_lane(column + <usize>i32x4.extract_lane(o, 1), v, 1);
  v128.store32_lane(column + <usize>i32x4.extract_lane(o, 2), v, 2);
  v128.store32_lane(column + <usize>i32x4.extract_lane(o, 3), v, 3);
}

@inline function f4(pk: usize, offset: usize): v128 {
  return v128.load(pk + offset);
}

/** The same sweep in f32x4 lanes over float32 copies of the body columns (speed and precision probe). */
export function sweep32(x: usize, y: usize, angle: usize, qangle: usize, rc: usize, rs: usize, packets: usize, count: i32): void {
  const zero = f32x4.splat(0);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET4;
    const oa = v128.load(pk);
    const ob = v128.load(pk, 16);
    const nx = f4(pk, 32);
    const ny = f4(pk, 48);
    const rAx = f4(pk, 64);
    const rAy = f4(pk, 80);
    const rBx = f4(pk, 96);
    const rBy = f4(pk, 112);
    const radA = f4(pk, 128);
    const radB = f4(pk, 144);
    let ax = gather4(x, oa);
    let ay = gather4(y, oa);
    let bx = gather4(x, ob);
    let by = gather4(y, ob);
    let angA = gather4(angle, oa);
    let angB = gather4(angle, ob);
    let dA = f32x4.sub(angA, gather4(qangle, oa));
    let dB = f32x4.sub(angB, gather4(qangle, ob));
    const cA = gather4(rc, oa);
    const sA = gather4(rs, oa);
    const cB = gather4(rc, ob);
    const sB = gather4(rs, ob);
    const mAx = f32x4.sub(f32x4.mul(cA, rAx), f32x4.mul(sA, rAy));
    const mAy = f32x4.add(f32x4.mul(sA, rAx), f32x4.mul(cA, rAy));
    const mBx = f32x4.sub(f32x4.mul(cB, rBx), f32x4.mul(sB, rBy));
    const mBy = f32x4.add(f32x4.mul(sB, rBx), f32x4.mul(cB, rBy));
    const roundA = f32x4.gt(radA, zero);
    const roundB = f32x4.gt(radB, zero);
    const lAx = v128.bitselect(f32x4.mul(nx, radA), mAx, roundA);
    const lAy = v128.bitselect(f32x4.mul(ny, radA), mAy, roundA);
    const lBx = v128.bitselect(f32x4.mul(f32x4.neg(nx), radB), mBx, roundB);
    const lBy = v128.bitselect(f32x4.mul(f32x4.neg(ny), radB), mBy, roundB);
    // g = (ax + lAx − dA·lAy − (bx + lBx − dB·lBy))·nx + (ay + lAy + dA·lAx − (by + lBy + dB·lBx))·ny − allowance
    const gx = f32x4.sub(f32x4.sub(f32x4.add(ax, lAx), f32x4.mul(dA, lAy)), f32x4.sub(f32x4.add(bx, lBx), f32x4.mul(dB, lBy)));
    const gy = f32x4.sub(f32x4.add(f32x4.add(ay, lAy), f32x4.mul(dA, lAx)), f32x4.add(f32x4.add(by, lBy), f32x4.mul(dB, lBx)));
    const g = f32x4.sub(f32x4.add(f32x4.mul(gx, nx), f32x4.mul(gy, ny)), f4(pk, 240));
    v128.store(pk, g, 320);
    const acts = f32x4.gt(g, zero);
    if (!v128.any_true(acts)) continue;
    const imA = f4(pk, 176);
    const iiA = f4(pk, 192);
    const imB = f4(pk, 208);
    const iiB = f4(pk, 224);
    // Weights, and what the velocity pass reads.
    const rnA = f32x4.sub(f32x4.mul(lAx, ny), f32x4.mul(lAy, nx));
    const rnB = f32x4.sub(f32x4.mul(lBx, ny), f32x4.mul(lBy, nx));
    const k00 = f32x4.add(f32x4.add(imA, f32x4.mul(f32x4.mul(iiA, rnA), rnA)), f32x4.add(imB, f32x4.mul(f32x4.mul(iiB, rnB), rnB)));
    v128.store(pk, lAx, 352);
    v128.store(pk, lAy, 368);
    v128.store(pk, lBx, 384);
    v128.store(pk, lBy, 400);
    v128.store(pk, rnA, 416);
    v128.store(pk, rnB, 432);
    v128.store(pk, k00, 448);
    v128.store(pk, v128.or(f4(pk, 336), acts), 336);
    // Normal correction: l = g / k00 where the point overlaps (and k00 > 0), 0 elsewhere.
    const l = v128.and(f32x4.div(g, k00), v128.and(acts, f32x4.gt(k00, zero)));
    const mlA = f32x4.mul(imA, l);
    ax = f32x4.sub(ax, f32x4.mul(mlA, nx));
    ay = f32x4.sub(ay, f32x4.mul(mlA, ny));
    const tA = f32x4.mul(iiA, f32x4.mul(l, rnA));
    angA = f32x4.sub(angA, tA);
    dA = f32x4.sub(dA, tA);
    const mlB = f32x4.mul(imB, l);
    bx = f32x4.add(bx, f32x4.mul(mlB, nx));
    by = f32x4.add(by, f32x4.mul(mlB, ny));
    const tB = f32x4.mul(iiB, f32x4.mul(l, rnB));
    angB = f32x4.add(angB, tB);
    dB = f32x4.add(dB, tB);
    const lambda = f32x4.add(f4(pk, 256), l);
    const impulseN = f32x4.add(f4(pk, 272), l);
    v128.store(pk, lambda, 256);
    v128.store(pk, impulseN, 272);
    // Friction where μ > 0 and the point has acted this substep: the tangential drift of the material points, less
    // what has slid, undone within Coulomb's limit on the step's summed normal corrections.
    const mu = f4(pk, 160);
    const rtA = f32x4.add(f32x4.mul(mAx, nx), f32x4.mul(mAy, ny));
    const rtB = f32x4.add(f32x4.mul(mBx, nx), f32x4.mul(mBy, ny));
    const w = f32x4.add(f32x4.add(imA, f32x4.mul(f32x4.mul(iiA, rtA), rtA)), f32x4.add(imB, f32x4.mul(f32x4.mul(iiB, rtB), rtB)));
    const holds = v128.and(v128.and(acts, v128.and(f32x4.ne(mu, zero), f32x4.gt(lambda, zero))), f32x4.gt(w, zero));
    if (v128.any_true(holds)) {
      const ux = f32x4.sub(f32x4.sub(f32x4.add(ax, mAx), f32x4.mul(dA, mAy)), f32x4.sub(f32x4.add(bx, mBx), f32x4.mul(dB, mBy)));
      const uy = f32x4.sub(f32x4.add(f32x4.add(ay, mAy), f32x4.mul(dA, mAx)), f32x4.add(f32x4.add(by, mBy), f32x4.mul(dB, mBx)));
      const slip = f4(pk, 304);
      const drift = f32x4.sub(f32x4.add(f32x4.mul(f32x4.neg(ux), ny), f32x4.mul(uy, nx)), slip);
      const want = f32x4.div(drift, w);
      const limit = f32x4.mul(mu, impulseN);
      const before = f4(pk, 288);
      const total = f32x4.pmax(f32x4.pmin(f32x4.add(before, want), limit), f32x4.neg(limit));
      const dt = v128.and(f32x4.sub(total, before), holds);
      v128.store(pk, v128.bitselect(total, before, holds), 288);
      v128.store(pk, v128.bitselect(f32x4.add(slip, f32x4.mul(f32x4.sub(want, dt), w)), slip, holds), 304);
      const tlA = f32x4.mul(imA, dt);
      ax = f32x4.add(ax, f32x4.mul(tlA, ny));
      ay = f32x4.sub(ay, f32x4.mul(tlA, nx));
      angA = f32x4.sub(angA, f32x4.mul(f32x4.mul(iiA, rtA), dt));
      const tlB = f32x4.mul(imB, dt);
      bx = f32x4.sub(bx, f32x4.mul(tlB, ny));
      by = f32x4.add(by, f32x4.mul(tlB, nx));
      angB = f32x4.add(angB, f32x4.mul(f32x4.mul(iiB, rtB), dt));
    }
    scatter4(x, oa, ax);
    scatter4(y, oa, ay);
    scatter4(angle, oa, angA);
    scatter4(x, ob, bx);
    scatter4(y, ob, by);
    scatter4(angle, ob, angB);
  }
}

/** f64 column → float32 copy (n rows), and back: what an f32 sweep on the engine's f64 state pays per substep. */
export function demote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) store<u64>(dst + (<usize>i << 2), i64x2.extract_lane(f32x4.demote_f64x2_zero(v128.load(src + (<usize>i << 3))), 0));
}

export function promote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) v128.store(dst + (<usize>i << 3), f64x2.promote_low_f32x4(v128.load64_zero(src + (<usize>i << 2))));
}
