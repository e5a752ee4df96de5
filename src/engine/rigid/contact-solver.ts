// The rigid contact solver: per substep, the position sweep (normal correction, then friction) and, after the
// velocities are derived, the velocity pass (restitution, or a stop). See RigidContacts for the model.
//
// These run for every point in every substep, so nothing here passes or returns a double across a call: V8 boxes a
// double handed to a function it does not inline (a heap allocation each time). The helpers take integers and pass
// their reals through the small typed arrays below.
import { spin, turnBySpin, type BodyRows } from './rows.js';
import type { RigidContacts } from './contacts.js';

/** Approach speeds below this do not bounce (resting contacts would jitter otherwise). */
export const BOUNCE_THRESHOLD = 0.5;

/**
 * B's side of the point being solved (loadB): [0, 1] normal point qB (a round side's surface point towards A), [2, 3]
 * its lever from B's centre, [4, 5] the material point pB, [6, 7] its lever, [8] B's inverse mass along the
 * contact (an edge point's is split by α), [9] B's inverse inertia (0 for particles and the world).
 */
const side = new Float64Array(10);

/** An impulse or displacement per unit inverse mass: [x, y, lever × it] (applyTo, applyB). */
const imp = new Float64Array(3);

/** Per point at offset o (0: point i, 5: its partner): [d, w, rnA, rnB, λ] (position) or [drift, w, rtA, rtB, λ] (friction). */
const pt = new Float64Array(10);
const fr = new Float64Array(10);

/** Per point at offset o (0 or 7): [vn, w, rnA, rnB, lAx, lAy, target] (velocity pass). */
const vel = new Float64Array(14);

function loadB(c: RigidContacts, r: BodyRows, i: number): void {
  const ib = c.b[i];
  if (ib < 0) {
    side[0] = side[4] = c.rBx[i];
    side[1] = side[5] = c.rBy[i];
    side[2] = side[3] = side[6] = side[7] = side[8] = side[9] = 0;
    return;
  }
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const be = 1 - al;
    side[0] = side[4] = be * r.x[ib] + al * r.x[ib2];
    side[1] = side[5] = be * r.y[ib] + al * r.y[ib2];
    side[2] = side[3] = side[6] = side[7] = side[9] = 0;
    side[8] = be * be * r.invMass[ib] + al * al * r.invMass[ib2];
    return;
  }
  const cs = r.rc[ib];
  const sn = r.rs[ib];
  const mx = cs * c.rBx[i] - sn * c.rBy[i];
  const my = sn * c.rBx[i] + cs * c.rBy[i];
  side[6] = mx;
  side[7] = my;
  side[4] = r.x[ib] + mx;
  side[5] = r.y[ib] + my;
  const rad = c.radB[i];
  side[2] = rad > 0 ? -c.nx[i] * rad : mx;
  side[3] = rad > 0 ? -c.ny[i] * rad : my;
  side[0] = r.x[ib] + side[2];
  side[1] = r.y[ib] + side[3];
  side[8] = r.invMass[ib];
  side[9] = r.invInertia[ib];
}

/** Row i's position moves by sign/m·(imp[0], imp[1]) and its angle by sign/I·imp[2]. */
function applyTo(r: BodyRows, i: number, sign: number): void {
  const m = r.invMass[i] * sign;
  r.x[i] += m * imp[0];
  r.y[i] += m * imp[1];
  const iI = r.invInertia[i];
  if (iI !== 0) {
    spin[0] = sign * iI * imp[2];
    turnBySpin(r, i);
  }
}

/** B's side moves by +imp (the opposite of A): a row, or an edge point's two particles by β and α. */
function applyB(c: RigidContacts, r: BodyRows, i: number): void {
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 < 0) {
    applyTo(r, ib, 1);
    return;
  }
  const al = c.alpha[i];
  const w0 = r.invMass[ib] * (1 - al);
  const w1 = r.invMass[ib2] * al;
  r.x[ib] += w0 * imp[0];
  r.y[ib] += w0 * imp[1];
  r.x[ib2] += w1 * imp[0];
  r.y[ib2] += w1 * imp[1];
}

/** Velocity counterpart of applyTo: v += sign/m·(imp[0], imp[1]), ω += sign/I·imp[2]. */
function kickTo(r: BodyRows, i: number, sign: number): void {
  const m = r.invMass[i] * sign;
  r.vx[i] += m * imp[0];
  r.vy[i] += m * imp[1];
  r.omega[i] += sign * r.invInertia[i] * imp[2];
}

function kickB(c: RigidContacts, r: BodyRows, i: number): void {
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 < 0) {
    kickTo(r, ib, 1);
    return;
  }
  const al = c.alpha[i];
  const w0 = r.invMass[ib] * (1 - al);
  const w1 = r.invMass[ib2] * al;
  r.vx[ib] += w0 * imp[0];
  r.vy[ib] += w0 * imp[1];
  r.vx[ib2] += w1 * imp[0];
  r.vy[ib2] += w1 * imp[1];
}

// ---- position sweep -----------------------------------------------------------------------------------------

/**
 * Point i's overlap d (past its allowance), generalised inverse mass w along n and the levers' cross products, into
 * pt[o..o+3]; the overlap is also kept as `gap` (the velocity pass looks at it). A round side pushes through its
 * centre.
 */
function measure(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const ra = c.radA[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const lAx = ra > 0 ? nx * ra : cs * c.rAx[i] - sn * c.rAy[i];
  const lAy = ra > 0 ? ny * ra : sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i);
  const d = (r.x[ia] + lAx - side[0]) * nx + (r.y[ia] + lAy - side[1]) * ny - c.allowance[i];
  c.gap[i] = d;
  const rnA = lAx * ny - lAy * nx;
  const rnB = side[2] * ny - side[3] * nx;
  pt[o] = d;
  pt[o + 1] = r.invMass[ia] + r.invInertia[ia] * rnA * rnA + side[8] + side[9] * rnB * rnB;
  pt[o + 2] = rnA;
  pt[o + 3] = rnB;
}

/** Pushes point i's sides apart by pt[o+4] along n (levers from pt[o+2], pt[o+3]). */
function pushApart(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const dl = pt[o + 4];
  c.lambdaN[i] += dl;
  c.impulseN[i] += dl;
  imp[0] = dl * c.nx[i];
  imp[1] = dl * c.ny[i];
  imp[2] = dl * pt[o + 2];
  applyTo(r, c.a[i], -1);
  imp[2] = dl * pt[o + 3];
  applyB(c, r, i);
}

/** The first time point i acts in a step: its approach speed (and its partner's) for restitution. */
function firstTouch(c: RigidContacts, r: BodyRows, i: number): void {
  c.touched[i] = 1;
  if (c.restitution[i] > 0 && c.approach[i] !== c.approach[i]) {
    loadVelocity(c, r, i, 0);
    c.approach[i] = vel[0];
    // A manifold's two points bounce together (a box landing flat may touch with one corner a substep earlier).
    const j = c.pair[i] === 1 ? i + 1 : i > 0 && c.pair[i - 1] === 1 ? i - 1 : -1;
    if (j >= 0 && c.approach[j] !== c.approach[j]) {
      loadVelocity(c, r, j, 0);
      c.approach[j] = vel[0];
    }
  }
}

/**
 * One Gauss–Seidel sweep over the points: the normal correction, then friction. The two points of a manifold
 * between rigid bodies (or a rigid body and the world) take their normal corrections together by a 2×2 solve
 * (Box2D's block solver, on positions): one after the other, a deep first point would turn the body about the
 * second and throw it sideways.
 */
export function solveRigidContacts(c: RigidContacts, r: BodyRows): void {
  for (let i = 0, n = c.count; i < n; i++) {
    if (c.pair[i] === 1 && c.b2[i] < 0 && c.b2[i + 1] < 0) {
      solvePair(c, r, i);
      frictionPair(c, r, i);
      i++;
      continue;
    }
    measure(c, r, i, 0);
    if (pt[0] <= 0 || pt[1] === 0) continue;
    if (c.touched[i] === 0) firstTouch(c, r, i);
    pt[4] = pt[0] / pt[1];
    pushApart(c, r, i, 0);
    friction(c, r, i);
  }
}

function solvePair(c: RigidContacts, r: BodyRows, i: number): void {
  measure(c, r, i, 0);
  measure(c, r, i + 1, 5);
  const d0 = pt[0];
  const d1 = pt[5];
  if (d0 <= 0 && d1 <= 0) return;
  if (d0 > 0 && c.touched[i] === 0) firstTouch(c, r, i);
  if (d1 > 0 && c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
  if (d0 > 0 && d1 > 0) {
    const ia = c.a[i];
    const ib = c.b[i];
    const k00 = pt[1];
    const k11 = pt[6];
    let k01 = r.invMass[ia] + r.invInertia[ia] * pt[2] * pt[7];
    if (ib >= 0) k01 += r.invMass[ib] + r.invInertia[ib] * pt[3] * pt[8];
    const det = k00 * k11 - k01 * k01;
    if (det > 1e-9 * k00 * k11) {
      pt[4] = (k11 * d0 - k01 * d1) / det;
      pt[9] = (k00 * d1 - k01 * d0) / det;
      if (pt[4] >= 0 && pt[9] >= 0) {
        pushApart(c, r, i, 0);
        pushApart(c, r, i + 1, 5);
        return;
      }
    }
  }
  // One point overlapping, or the block would pull: one after the other.
  if (d0 > 0 && pt[1] > 0) {
    pt[4] = d0 / pt[1];
    pushApart(c, r, i, 0);
  }
  measure(c, r, i + 1, 5);
  if (pt[5] > 0 && pt[6] > 0) {
    if (c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
    pt[9] = pt[5] / pt[6];
    pushApart(c, r, i + 1, 5);
  }
}

/** Point i's tangential drift since the step began (less what has slid), weight and levers, into fr[o..o+3]. */
function measureFriction(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const mAx = cs * c.rAx[i] - sn * c.rAy[i];
  const mAy = sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i);
  const tx = -c.ny[i];
  const ty = c.nx[i];
  const rtA = mAx * ty - mAy * tx;
  const rtB = side[6] * ty - side[7] * tx;
  fr[o] = (r.x[ia] + mAx - side[4]) * tx + (r.y[ia] + mAy - side[5]) * ty - c.slip[i];
  fr[o + 1] = r.invMass[ia] + r.invInertia[ia] * rtA * rtA + side[8] + side[9] * rtB * rtB;
  fr[o + 2] = rtA;
  fr[o + 3] = rtB;
}

/**
 * Undoes fr[o+4] of point i's drift (per unit weight) as far as Coulomb's limit allows, μ times the normal
 * correction of the step so far (both summed over the step, as the drift is); the rest has slid, and the anchors
 * follow it (slip). `partner` ≥ 0 shares the manifold's slip and normal load.
 */
function hold(c: RigidContacts, r: BodyRows, i: number, o: number, partner: number): void {
  const want = fr[o + 4];
  const wt = fr[o + 1];
  const load = partner >= 0 ? c.impulseN[i] + c.impulseN[partner] : c.impulseN[i];
  const limit = c.friction[i] * load;
  const before = c.impulseT[i];
  let total = before + want;
  if (total > limit) total = limit;
  else if (total < -limit) total = -limit;
  const dt = total - before;
  c.impulseT[i] = total;
  c.slip[i] += (want - dt) * wt;
  if (partner >= 0) c.slip[partner] = c.slip[i];
  c.lambdaT[i] += dt;
  imp[0] = -dt * c.ny[i];
  imp[1] = dt * c.nx[i];
  imp[2] = dt * fr[o + 2];
  applyTo(r, c.a[i], -1);
  imp[2] = dt * fr[o + 3];
  applyB(c, r, i);
}

/** Friction of a lone point (after its normal correction this sweep). */
function friction(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.friction[i] === 0 || c.lambdaN[i] <= 0) return;
  measureFriction(c, r, i, 0);
  if (fr[1] === 0) return;
  fr[4] = fr[0] / fr[1];
  hold(c, r, i, 0, -1);
}

/**
 * Friction of a manifold's two points as one constraint at their midpoint, with Coulomb's limit on their summed
 * normal corrections. In 2D the two points of a face contact slide together (a turn moves them along the normal,
 * not along the face), so two tangential constraints would be one twice over: solved one after the other, the first
 * would saturate while the second still held, record a slide that did not happen, and a pile would creep sideways
 * step after step.
 */
function frictionPair(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.friction[i] === 0 || (c.lambdaN[i] <= 0 && c.lambdaN[i + 1] <= 0)) return;
  measureFriction(c, r, i, 0);
  measureFriction(c, r, i + 1, 5);
  // Both points carry the manifold's slip, so the mean of their drifts is the midpoint's; cross products are linear
  // in the lever, so the midpoint's are the means too.
  const rtA = 0.5 * (fr[2] + fr[7]);
  const rtB = 0.5 * (fr[3] + fr[8]);
  const ia = c.a[i];
  const wt = r.invMass[ia] + r.invInertia[ia] * rtA * rtA + side[8] + side[9] * rtB * rtB;
  if (wt === 0) return;
  fr[1] = wt;
  fr[2] = rtA;
  fr[3] = rtB;
  fr[4] = (0.5 * (fr[0] + fr[5])) / wt;
  hold(c, r, i, 0, i + 1);
}

// ---- velocity pass ------------------------------------------------------------------------------------------

/** Normal speed (B relative to A, negative approaching), weight and levers of point i into vel[o..o+5]. */
function loadVelocity(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const ra = c.radA[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const lAx = ra > 0 ? nx * ra : cs * c.rAx[i] - sn * c.rAy[i];
  const lAy = ra > 0 ? ny * ra : sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i);
  const rnA = lAx * ny - lAy * nx;
  const rnB = side[2] * ny - side[3] * nx;
  const wa = r.omega[ia];
  let vbx = 0;
  let vby = 0;
  const ib = c.b[i];
  if (ib >= 0) {
    const ib2 = c.b2[i];
    if (ib2 >= 0) {
      const al = c.alpha[i];
      vbx = (1 - al) * r.vx[ib] + al * r.vx[ib2];
      vby = (1 - al) * r.vy[ib] + al * r.vy[ib2];
    } else {
      const wb = r.omega[ib];
      vbx = r.vx[ib] - wb * side[3];
      vby = r.vy[ib] + wb * side[2];
    }
  }
  vel[o] = (vbx - r.vx[ia] + wa * lAy) * nx + (vby - r.vy[ia] - wa * lAx) * ny;
  vel[o + 1] = r.invMass[ia] + r.invInertia[ia] * rnA * rnA + side[8] + side[9] * rnB * rnB;
  vel[o + 2] = rnA;
  vel[o + 3] = rnB;
  vel[o + 4] = lAx;
  vel[o + 5] = lAy;
}

/** Target normal speed of point i into vel[o+6]: −e × its approach for an impact (once), else 0. */
function loadTarget(c: RigidContacts, i: number, o: number): void {
  let target = 0;
  const e = c.restitution[i];
  const approach = c.approach[i];
  if (e > 0 && approach < -BOUNCE_THRESHOLD) {
    target = -e * approach;
    c.approach[i] = 0;
  }
  vel[o + 6] = target;
}

/** Point i's sides get the normal velocity impulse pt[slot] (per unit inverse mass; levers from vel[o+2], vel[o+3]). */
function kickApart(c: RigidContacts, r: BodyRows, i: number, o: number, slot: number): void {
  const P = pt[slot];
  imp[0] = P * c.nx[i];
  imp[1] = P * c.ny[i];
  imp[2] = P * vel[o + 2];
  kickTo(r, c.a[i], -1);
  imp[2] = P * vel[o + 3];
  kickB(c, r, i);
}

/**
 * The velocity pass after a substep's velocities are derived: each point that acted gets its target normal speed
 * (−e × approach for an impact, 0 otherwise), so pushing an overlap out does not leave bodies flying apart at
 * depth / h. The two points of a manifold between two rigid bodies (or a rigid body and the world) are solved
 * together by a 2×2 system: solved one after the other, the second would undo part of the first through the
 * rotation they share, and a box dropped flat would bounce crooked. A point whose partner acted while it was itself
 * within two substeps' approach of touching (a box landing flat by a hair's tilt) joins it.
 */
export function solveRigidContactVelocities(c: RigidContacts, r: BodyRows, h: number): void {
  for (let i = 0, n = c.count; i < n; i++) {
    if (c.pair[i] === 1 && c.b2[i] < 0 && c.b2[i + 1] < 0) {
      pairVelocity(c, r, i, h);
      i++;
      continue;
    }
    if (c.lambdaN[i] <= 0) continue;
    loadVelocity(c, r, i, 0);
    loadTarget(c, i, 0);
    if (vel[1] <= 0) continue;
    pt[4] = (vel[6] - vel[0]) / vel[1];
    kickApart(c, r, i, 0, 4);
  }
}

function pairVelocity(c: RigidContacts, r: BodyRows, i: number, h: number): void {
  const acted0 = c.lambdaN[i] > 0;
  const acted1 = c.lambdaN[i + 1] > 0;
  if (!acted0 && !acted1) return;
  loadVelocity(c, r, i, 0);
  loadVelocity(c, r, i + 1, 7);
  const use0 = acted0 || (vel[0] < 0 && c.gap[i] > 2 * vel[0] * h);
  const use1 = acted1 || (vel[7] < 0 && c.gap[i + 1] > 2 * vel[7] * h);
  if (use0) loadTarget(c, i, 0);
  if (use1) loadTarget(c, i + 1, 7);
  if (use0 && use1) {
    // K P = target − vn, K_jk = 1/mA + 1/mB + (rAj × n)(rAk × n)/IA + (rBj × n)(rBk × n)/IB.
    const ia = c.a[i];
    const ib = c.b[i];
    const k00 = vel[1];
    const k11 = vel[8];
    let k01 = r.invMass[ia] + r.invInertia[ia] * vel[2] * vel[9];
    if (ib >= 0) k01 += r.invMass[ib] + r.invInertia[ib] * vel[3] * vel[10];
    const b0 = vel[6] - vel[0];
    const b1 = vel[13] - vel[7];
    const det = k00 * k11 - k01 * k01;
    if (det > 1e-9 * k00 * k11) {
      pt[4] = (k11 * b0 - k01 * b1) / det;
      pt[9] = (k00 * b1 - k01 * b0) / det;
      kickApart(c, r, i, 0, 4);
      kickApart(c, r, i + 1, 7, 9);
      return;
    }
  }
  // One point (or two dependent ones): one after the other, the second's speed measured again after the first.
  if (use0 && vel[1] > 0) {
    pt[4] = (vel[6] - vel[0]) / vel[1];
    kickApart(c, r, i, 0, 4);
  }
  if (use1) {
    const target = vel[13];
    loadVelocity(c, r, i + 1, 7);
    if (vel[8] > 0) {
      pt[9] = (target - vel[7]) / vel[8];
      kickApart(c, r, i + 1, 7, 9);
    }
  }
}
