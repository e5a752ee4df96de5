// An experiment, not shipped (issue 16; bench/experiment-rigid.mjs compiles and drives it): the rigid contact solver's
// position sweep and velocity pass for single-point contacts between two rows (rigid discs, discs and static walls:
// all of S3 and of the 10,000-circle pile), in f64x2 lanes. The contacts are coloured each step (JS, in the bench)
// into batches that share no movable body, and a batch is laid out two lanes a packet. Within a colour the points are
// solved Jacobi-wise side by side, across colours Gauss–Seidel, with the same formulas and order of operations per
// point as solveRigidContacts / solveRigidContactVelocities in src/engine/rigid/contact-solver.ts (restitution 0,
// no manifold pairs, no particle-edge points, no shock sweep: the bench checks that the scene has none).
//
// The body columns (x, y, angle, qangle, rc, rs; vx, vy, omega) are the engine's own f64 columns, placed in this
// module's memory; a lane reads a row's value by its byte offset (row × 8). A padding lane points at a spare row
// with inverse mass and inertia 0 and never acts; a static body (inverse mass and inertia 0) may sit in both lanes
// of a packet: it is written back unchanged.
//
// Packet of two points (bytes):
//   0: i32 ia0, ia1, ib0, ib1 (row × 8)
//  16 nx  32 ny  48 rAx  64 rAy  80 rBx  96 rBy  112 radA  128 radB  144 friction
// 160 imA 176 iiA 192 imB 208 iiB                                   (per step, from the rows' inverse mass/inertia)
// 224 allowance 240 lambdaN 256 impulseN 272 impulseT 288 slip 304 gap 320 touched (all-ones lanes)   (state)
// 336 lAx 352 lAy 368 lBx 384 lBy 400 rnA 416 rnB 432 wn             (written by the sweep for the velocity pass)
const PACKET: usize = 448;

@inline function gather(column: usize, o0: usize, o1: usize): v128 {
  return v128.load64_lane(column + o1, v128.load64_splat(column + o0), 1);
}

@inline function scatter(column: usize, o0: usize, o1: usize, v: v128): void {
  v128.store64_lane(column + o0, v, 0);
  v128.store64_lane(column + o1, v, 1);
}

@inline function f(pk: usize, offset: usize): v128 {
  return v128.load(pk + offset);
}

/** The substep's start (RigidContacts.beginSubstep): λn 0, allowances shrink by maxPush. */
export function beginSubstep(packets: usize, count: i32, maxPush: f64): void {
  const zero = f64x2.splat(0);
  const push = f64x2.splat(maxPush);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET;
    v128.store(pk, zero, 240);
    const left = f64x2.sub(f(pk, 224), push);
    v128.store(pk, v128.bitselect(left, zero, f64x2.gt(left, zero)), 224);
  }
}

/** One position sweep over `count` packets: normal correction, then friction, per point. */
export function sweep(x: usize, y: usize, angle: usize, qangle: usize, rc: usize, rs: usize, packets: usize, count: i32): void {
  const zero = f64x2.splat(0);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = f(pk, 16);
    const ny = f(pk, 32);
    const rAx = f(pk, 48);
    const rAy = f(pk, 64);
    const rBx = f(pk, 80);
    const rBy = f(pk, 96);
    const radA = f(pk, 112);
    const radB = f(pk, 128);
    let ax = gather(x, oa0, oa1);
    let ay = gather(y, oa0, oa1);
    let bx = gather(x, ob0, ob1);
    let by = gather(y, ob0, ob1);
    let angA = gather(angle, oa0, oa1);
    let angB = gather(angle, ob0, ob1);
    let dA = f64x2.sub(angA, gather(qangle, oa0, oa1));
    let dB = f64x2.sub(angB, gather(qangle, ob0, ob1));
    const cA = gather(rc, oa0, oa1);
    const sA = gather(rs, oa0, oa1);
    const cB = gather(rc, ob0, ob1);
    const sB = gather(rs, ob0, ob1);
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
    const g = f64x2.sub(f64x2.add(f64x2.mul(gx, nx), f64x2.mul(gy, ny)), f(pk, 224));
    v128.store(pk, g, 304);
    const acts = f64x2.gt(g, zero);
    if (!v128.any_true(acts)) continue;
    const imA = f(pk, 160);
    const iiA = f(pk, 176);
    const imB = f(pk, 192);
    const iiB = f(pk, 208);
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
    v128.store(pk, v128.or(f(pk, 320), acts), 320);
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
    const lambda = f64x2.add(f(pk, 240), l);
    const impulseN = f64x2.add(f(pk, 256), l);
    v128.store(pk, lambda, 240);
    v128.store(pk, impulseN, 256);
    // Friction where μ > 0 and the point has acted this substep: the tangential drift of the material points, less
    // what has slid, undone within Coulomb's limit on the step's summed normal corrections.
    const mu = f(pk, 144);
    const rtA = f64x2.add(f64x2.mul(mAx, nx), f64x2.mul(mAy, ny));
    const rtB = f64x2.add(f64x2.mul(mBx, nx), f64x2.mul(mBy, ny));
    const w = f64x2.add(f64x2.add(imA, f64x2.mul(f64x2.mul(iiA, rtA), rtA)), f64x2.add(imB, f64x2.mul(f64x2.mul(iiB, rtB), rtB)));
    const holds = v128.and(v128.and(acts, v128.and(f64x2.ne(mu, zero), f64x2.gt(lambda, zero))), f64x2.gt(w, zero));
    if (v128.any_true(holds)) {
      const ux = f64x2.sub(f64x2.sub(f64x2.add(ax, mAx), f64x2.mul(dA, mAy)), f64x2.sub(f64x2.add(bx, mBx), f64x2.mul(dB, mBy)));
      const uy = f64x2.sub(f64x2.add(f64x2.add(ay, mAy), f64x2.mul(dA, mAx)), f64x2.add(f64x2.add(by, mBy), f64x2.mul(dB, mBx)));
      const slip = f(pk, 288);
      const drift = f64x2.sub(f64x2.add(f64x2.mul(f64x2.neg(ux), ny), f64x2.mul(uy, nx)), slip);
      const want = f64x2.div(drift, w);
      const limit = f64x2.mul(mu, impulseN);
      const before = f(pk, 272);
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
    scatter(x, oa0, oa1, ax);
    scatter(y, oa0, oa1, ay);
    scatter(angle, oa0, oa1, angA);
    scatter(x, ob0, ob1, bx);
    scatter(y, ob0, ob1, by);
    scatter(angle, ob0, ob1, angB);
  }
}

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

/** The velocity pass (restitution 0): each point that acted this substep gets normal speed 0. */
export function velocities(vx: usize, vy: usize, omega: usize, packets: usize, count: i32): void {
  const zero = f64x2.splat(0);
  for (let k = 0; k < count; k++) {
    const pk = packets + <usize>k * PACKET;
    const acted = f64x2.gt(f(pk, 240), zero);
    if (!v128.any_true(acted)) continue;
    const oa0 = <usize>load<i32>(pk);
    const oa1 = <usize>load<i32>(pk, 4);
    const ob0 = <usize>load<i32>(pk, 8);
    const ob1 = <usize>load<i32>(pk, 12);
    const nx = f(pk, 16);
    const ny = f(pk, 32);
    let vax = gather(vx, oa0, oa1);
    let vay = gather(vy, oa0, oa1);
    let wa = gather(omega, oa0, oa1);
    let vbx = gather(vx, ob0, ob1);
    let vby = gather(vy, ob0, ob1);
    let wb = gather(omega, ob0, ob1);
    const rvx = f64x2.sub(vbx, vax);
    const rvy = f64x2.sub(vby, vay);
    // v = (rvx − wb·lBy + wa·lAy)·nx + (rvy + wb·lBx − wa·lAx)·ny
    const ux = f64x2.add(f64x2.sub(rvx, f64x2.mul(wb, f(pk, 384))), f64x2.mul(wa, f(pk, 352)));
    const uy = f64x2.sub(f64x2.add(rvy, f64x2.mul(wb, f(pk, 368))), f64x2.mul(wa, f(pk, 336)));
    const v = f64x2.add(f64x2.mul(ux, nx), f64x2.mul(uy, ny));
    const k00 = f(pk, 432);
    const p = v128.and(f64x2.div(f64x2.sub(zero, v), k00), v128.and(acted, f64x2.gt(k00, zero)));
    const mpA = f64x2.mul(f(pk, 160), p);
    const mpB = f64x2.mul(f(pk, 192), p);
    vax = f64x2.sub(vax, f64x2.mul(mpA, nx));
    vay = f64x2.sub(vay, f64x2.mul(mpA, ny));
    wa = f64x2.sub(wa, f64x2.mul(f(pk, 176), f64x2.mul(p, f(pk, 400))));
    vbx = f64x2.add(vbx, f64x2.mul(mpB, nx));
    vby = f64x2.add(vby, f64x2.mul(mpB, ny));
    wb = f64x2.add(wb, f64x2.mul(f(pk, 208), f64x2.mul(p, f(pk, 416))));
    scatter(vx, oa0, oa1, vax);
    scatter(vy, oa0, oa1, vay);
    scatter(omega, oa0, oa1, wa);
    scatter(vx, ob0, ob1, vbx);
    scatter(vy, ob0, ob1, vby);
    scatter(omega, ob0, ob1, wb);
  }
}

/** f64 column → float32 copy (n rows), and back: what an f32 sweep on the engine's f64 state pays per substep. */
export function demote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) store<u64>(dst + (<usize>i << 2), i64x2.extract_lane(f32x4.demote_f64x2_zero(v128.load(src + (<usize>i << 3))), 0));
}

export function promote(src: usize, dst: usize, n: i32): void {
  for (let i = 0; i < n; i += 2) v128.store(dst + (<usize>i << 3), f64x2.promote_low_f32x4(v128.load64_zero(src + (<usize>i << 2))));
}
