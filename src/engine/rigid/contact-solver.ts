// The rigid contact solver: per substep a prepare pass (lever arms and weights from the bodies' rotation), the
// position sweep (normal correction, then friction) and, after the velocities are derived, the velocity pass
// (restitution, or a stop). See RigidContacts for the model.
//
// Speed: the levers are computed once a substep (prepare); within the sweep a body's point is its lever turned by
// the small angle the body has turned since (first order), and corrections add to the angle without recomputing
// cos and sin (rows.ts). Nothing passes or returns a double across a call: V8 boxes a double handed to a function it
// does not inline (a heap allocation each time); the helpers take integers and pass reals through typed arrays.
import type { BodyRows } from './rows.js';
import type { RigidContacts } from './contacts.js';

/** Approach speeds below this do not bounce (resting contacts would jitter otherwise). */
export const BOUNCE_THRESHOLD = 0.5;

/** B's current normal point [0, 1] and material point [2, 3] of the point being solved (pointsOf). */
const at = new Float64Array(4);

/** Per point at offset o (0: point i, 4: its partner): [overlap or drift, λ to apply, weight, unused]. */
const pt = new Float64Array(8);

/** The lever cross products push() and kick() apply a correction with: [A's, B's]. */
const lev = new Float64Array(2);

/** Per point at offset o (0 or 2) of the velocity pass: [normal speed, target]. */
const vel = new Float64Array(4);

/**
 * Lever arms, their cross products with the normal and the tangent, and the weights along both, from the bodies'
 * rotation at the start of the substep (after integration): once per point per substep. A round side pushes
 * through its centre (normal lever along n); friction acts at the material point.
 */
export function prepareRigidContacts(c: RigidContacts, r: BodyRows): void {
  const { rc, rs, invMass, invInertia } = r;
  for (let i = 0, n = c.count; i < n; i++) {
    const ia = c.a[i];
    const ib = c.b[i];
    const nx = c.nx[i];
    const ny = c.ny[i];
    let cs = rc[ia];
    let sn = rs[ia];
    const mAx = cs * c.rAx[i] - sn * c.rAy[i];
    const mAy = sn * c.rAx[i] + cs * c.rAy[i];
    const ra = c.radA[i];
    const lAx = ra > 0 ? nx * ra : mAx;
    const lAy = ra > 0 ? ny * ra : mAy;
    c.lAx[i] = lAx;
    c.lAy[i] = lAy;
    c.mAx[i] = mAx;
    c.mAy[i] = mAy;
    const rnA = lAx * ny - lAy * nx;
    const rtA = mAx * nx + mAy * ny; // m × t with t = (−ny, nx)
    c.rnA[i] = rnA;
    c.rtA[i] = rtA;
    let wn = invMass[ia] + invInertia[ia] * rnA * rnA;
    let wt = invMass[ia] + invInertia[ia] * rtA * rtA;
    if (ib >= 0) {
      if (c.b2[i] >= 0) {
        const al = c.alpha[i];
        const be = 1 - al;
        const w = be * be * invMass[ib] + al * al * invMass[c.b2[i]];
        wn += w;
        wt += w;
        c.lBx[i] = c.lBy[i] = c.mBx[i] = c.mBy[i] = c.rnB[i] = c.rtB[i] = 0;
      } else {
        cs = rc[ib];
        sn = rs[ib];
        const mBx = cs * c.rBx[i] - sn * c.rBy[i];
        const mBy = sn * c.rBx[i] + cs * c.rBy[i];
        const rb = c.radB[i];
        const lBx = rb > 0 ? -nx * rb : mBx;
        const lBy = rb > 0 ? -ny * rb : mBy;
        c.lBx[i] = lBx;
        c.lBy[i] = lBy;
        c.mBx[i] = mBx;
        c.mBy[i] = mBy;
        const rnB = lBx * ny - lBy * nx;
        const rtB = mBx * nx + mBy * ny;
        c.rnB[i] = rnB;
        c.rtB[i] = rtB;
        wn += invMass[ib] + invInertia[ib] * rnB * rnB;
        wt += invMass[ib] + invInertia[ib] * rtB * rtB;
      }
    } else c.lBx[i] = c.lBy[i] = c.mBx[i] = c.mBy[i] = c.rnB[i] = c.rtB[i] = 0;
    c.wn[i] = wn;
    c.wt[i] = wt;
    // A manifold's two points couple through the bodies they share (the 2×2 blocks): K01 along n and along t.
    if (i > 0 && c.pair[i - 1] === 1 && c.b2[i - 1] < 0 && c.b2[i] < 0) {
      const j = i - 1;
      let kn = invMass[ia] + invInertia[ia] * c.rnA[j] * rnA;
      let kt = invMass[ia] + invInertia[ia] * c.rtA[j] * rtA;
      if (ib >= 0) {
        kn += invMass[ib] + invInertia[ib] * c.rnB[j] * c.rnB[i];
        kt += invMass[ib] + invInertia[ib] * c.rtB[j] * c.rtB[i];
      }
      c.kn01[j] = kn;
      c.kt01[j] = kt;
    }
  }
}

/**
 * B's normal and material points of point i now, into at[0..3]: a row's centre plus its lever turned by the angle
 * since the levers were prepared (first order), an edge point between its two particles, or the world's point.
 */
function pointsOfB(c: RigidContacts, r: BodyRows, i: number): void {
  const ib = c.b[i];
  if (ib < 0) {
    at[0] = at[2] = c.rBx[i];
    at[1] = at[3] = c.rBy[i];
    return;
  }
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    at[0] = at[2] = (1 - al) * r.x[ib] + al * r.x[ib2];
    at[1] = at[3] = (1 - al) * r.y[ib] + al * r.y[ib2];
    return;
  }
  const d = r.angle[ib] - r.qangle[ib];
  const x = r.x[ib];
  const y = r.y[ib];
  at[0] = x + c.lBx[i] - d * c.lBy[i];
  at[1] = y + c.lBy[i] + d * c.lBx[i];
  at[2] = x + c.mBx[i] - d * c.mBy[i];
  at[3] = y + c.mBy[i] + d * c.mBx[i];
}

/** Point i's overlap past its allowance into pt[o] (and `gap`). */
function overlap(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const d = r.angle[ia] - r.qangle[ia];
  const lx = c.lAx[i];
  const ly = c.lAy[i];
  pointsOfB(c, r, i);
  const g = (r.x[ia] + lx - d * ly - at[0]) * c.nx[i] + (r.y[ia] + ly + d * lx - at[1]) * c.ny[i] - c.allowance[i];
  c.gap[i] = g;
  pt[o] = g;
}

/**
 * Moves point i's two sides by pt[o+1] along the normal (the tangent: `along` 1), A back and B forward, turning them
 * by the lever cross products in lev: positions and angles only (the rotation follows at the next sync).
 */
function push(c: RigidContacts, r: BodyRows, i: number, o: number, along: number): void {
  const l = pt[o + 1];
  const dx = along === 1 ? -c.ny[i] * l : c.nx[i] * l;
  const dy = along === 1 ? c.nx[i] * l : c.ny[i] * l;
  const ia = c.a[i];
  const mA = r.invMass[ia];
  r.x[ia] -= mA * dx;
  r.y[ia] -= mA * dy;
  r.angle[ia] -= r.invInertia[ia] * lev[0] * l;
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const w0 = r.invMass[ib] * (1 - al);
    const w1 = r.invMass[ib2] * al;
    r.x[ib] += w0 * dx;
    r.y[ib] += w0 * dy;
    r.x[ib2] += w1 * dx;
    r.y[ib2] += w1 * dy;
    return;
  }
  const mB = r.invMass[ib];
  r.x[ib] += mB * dx;
  r.y[ib] += mB * dy;
  r.angle[ib] += r.invInertia[ib] * lev[1] * l;
}

/** Applies pt[o+1] as point i's normal correction (λn of the substep and of the step). */
function pushApart(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  c.lambdaN[i] += pt[o + 1];
  c.impulseN[i] += pt[o + 1];
  lev[0] = c.rnA[i];
  lev[1] = c.rnB[i];
  push(c, r, i, o, 0);
}

/** The first time point i acts in a step: its approach speed (and its partner's) for restitution. */
function firstTouch(c: RigidContacts, r: BodyRows, i: number): void {
  c.touched[i] = 1;
  if (c.restitution[i] > 0 && c.approach[i] !== c.approach[i]) {
    normalSpeed(c, r, i, 0);
    c.approach[i] = vel[0];
    // A manifold's two points bounce together (a box landing flat may touch with one corner a substep earlier).
    const j = c.pair[i] === 1 ? i + 1 : i > 0 && c.pair[i - 1] === 1 ? i - 1 : -1;
    if (j >= 0 && c.approach[j] !== c.approach[j]) {
      normalSpeed(c, r, j, 0);
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
    overlap(c, r, i, 0);
    if (pt[0] <= 0 || c.wn[i] === 0) continue;
    if (c.touched[i] === 0) firstTouch(c, r, i);
    pt[1] = pt[0] / c.wn[i];
    pushApart(c, r, i, 0);
    friction(c, r, i);
  }
}

function solvePair(c: RigidContacts, r: BodyRows, i: number): void {
  overlap(c, r, i, 0);
  overlap(c, r, i + 1, 4);
  const d0 = pt[0];
  const d1 = pt[4];
  if (d0 <= 0 && d1 <= 0) return;
  if (d0 > 0 && c.touched[i] === 0) firstTouch(c, r, i);
  if (d1 > 0 && c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
  const k00 = c.wn[i];
  const k11 = c.wn[i + 1];
  if (d0 > 0 && d1 > 0) {
    const k01 = c.kn01[i];
    const det = k00 * k11 - k01 * k01;
    if (det > 1e-9 * k00 * k11) {
      pt[1] = (k11 * d0 - k01 * d1) / det;
      pt[5] = (k00 * d1 - k01 * d0) / det;
      if (pt[1] >= 0 && pt[5] >= 0) {
        pushApart(c, r, i, 0);
        pushApart(c, r, i + 1, 4);
        return;
      }
    }
  }
  // One point overlapping, or the block would pull: one after the other.
  if (d0 > 0 && k00 > 0) {
    pt[1] = d0 / k00;
    pushApart(c, r, i, 0);
  }
  overlap(c, r, i + 1, 4);
  if (pt[4] > 0 && k11 > 0) {
    if (c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
    pt[5] = pt[4] / k11;
    pushApart(c, r, i + 1, 4);
  }
}

/** Point i's tangential drift since the step began, less what has slid, into pt[o]. */
function drift(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const d = r.angle[ia] - r.qangle[ia];
  const mx = c.mAx[i];
  const my = c.mAy[i];
  pointsOfB(c, r, i);
  pt[o] = -(r.x[ia] + mx - d * my - at[2]) * c.ny[i] + (r.y[ia] + my + d * mx - at[3]) * c.nx[i] - c.slip[i];
}

/**
 * Undoes pt[0]/pt[2] (drift over weight) of point i as far as Coulomb's limit allows: μ times the normal correction
 * of the step so far (both summed over the step, as the drift is), over `points` points of the manifold, turning
 * the bodies by the levers in lev. What cannot be held has slid, and the anchors follow it (slip, shared by a
 * manifold's points).
 */
function hold(c: RigidContacts, r: BodyRows, i: number, points: number): void {
  const wt = pt[2];
  const want = pt[0] / wt;
  const load = points === 2 ? c.impulseN[i] + c.impulseN[i + 1] : c.impulseN[i];
  const limit = c.friction[i] * load;
  const before = c.impulseT[i];
  let total = before + want;
  if (total > limit) total = limit;
  else if (total < -limit) total = -limit;
  const dt = total - before;
  c.impulseT[i] = total;
  c.slip[i] += (want - dt) * wt;
  if (points === 2) c.slip[i + 1] = c.slip[i];
  c.lambdaT[i] += dt;
  pt[1] = dt;
  push(c, r, i, 0, 1);
}

/** Friction of a lone point (after its normal correction this sweep). */
function friction(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.friction[i] === 0 || c.lambdaN[i] <= 0 || c.wt[i] === 0) return;
  drift(c, r, i, 0);
  pt[2] = c.wt[i];
  lev[0] = c.rtA[i];
  lev[1] = c.rtB[i];
  hold(c, r, i, 1);
}

/**
 * Friction of a manifold's two points as one constraint at their midpoint, with Coulomb's limit on their summed
 * normal corrections. In 2D the two points of a face contact slide together (a turn moves them along the normal,
 * not along the face), so two tangential constraints would be one twice over: solved one after the other, the first
 * would saturate while the second still held, record a slide that did not happen, and a pile would creep sideways
 * step after step. (The midpoint's levers are the points' means: cross products are linear in the lever; its weight
 * is the mean of the points' weights and their coupling.)
 */
function frictionPair(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.friction[i] === 0 || (c.lambdaN[i] <= 0 && c.lambdaN[i + 1] <= 0)) return;
  const wt = 0.25 * (c.wt[i] + c.wt[i + 1]) + 0.5 * c.kt01[i];
  if (wt === 0) return;
  drift(c, r, i, 0);
  drift(c, r, i + 1, 4);
  pt[0] = 0.5 * (pt[0] + pt[4]);
  pt[2] = wt;
  lev[0] = 0.5 * (c.rtA[i] + c.rtA[i + 1]);
  lev[1] = 0.5 * (c.rtB[i] + c.rtB[i + 1]);
  hold(c, r, i, 2);
}

// ---- velocity pass ------------------------------------------------------------------------------------------

/** Normal speed of point i (B relative to A, negative approaching) into vel[o]. */
function normalSpeed(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const wa = r.omega[ia];
  let vx = -(r.vx[ia] - wa * c.lAy[i]);
  let vy = -(r.vy[ia] + wa * c.lAx[i]);
  const ib = c.b[i];
  if (ib >= 0) {
    const ib2 = c.b2[i];
    if (ib2 >= 0) {
      const al = c.alpha[i];
      vx += (1 - al) * r.vx[ib] + al * r.vx[ib2];
      vy += (1 - al) * r.vy[ib] + al * r.vy[ib2];
    } else {
      const wb = r.omega[ib];
      vx += r.vx[ib] - wb * c.lBy[i];
      vy += r.vy[ib] + wb * c.lBx[i];
    }
  }
  vel[o] = vx * c.nx[i] + vy * c.ny[i];
}

/** Target normal speed of point i into vel[o+1]: −e × its approach for an impact (once), else 0. */
function target(c: RigidContacts, i: number, o: number): void {
  let t = 0;
  const e = c.restitution[i];
  const approach = c.approach[i];
  if (e > 0 && approach < -BOUNCE_THRESHOLD) {
    t = -e * approach;
    c.approach[i] = 0;
  }
  vel[o + 1] = t;
}

/** Point i's sides get the normal velocity impulse pt[o+1] (per unit inverse mass; prepared levers). */
function kick(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const P = pt[o + 1];
  const px = P * c.nx[i];
  const py = P * c.ny[i];
  const ia = c.a[i];
  const mA = r.invMass[ia];
  r.vx[ia] -= mA * px;
  r.vy[ia] -= mA * py;
  r.omega[ia] -= r.invInertia[ia] * c.rnA[i] * P;
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const w0 = r.invMass[ib] * (1 - al);
    const w1 = r.invMass[ib2] * al;
    r.vx[ib] += w0 * px;
    r.vy[ib] += w0 * py;
    r.vx[ib2] += w1 * px;
    r.vy[ib2] += w1 * py;
    return;
  }
  const mB = r.invMass[ib];
  r.vx[ib] += mB * px;
  r.vy[ib] += mB * py;
  r.omega[ib] += r.invInertia[ib] * c.rnB[i] * P;
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
    if (c.lambdaN[i] <= 0 || c.wn[i] <= 0) continue;
    normalSpeed(c, r, i, 0);
    target(c, i, 0);
    pt[1] = (vel[1] - vel[0]) / c.wn[i];
    kick(c, r, i, 0);
  }
}

function pairVelocity(c: RigidContacts, r: BodyRows, i: number, h: number): void {
  const acted0 = c.lambdaN[i] > 0;
  const acted1 = c.lambdaN[i + 1] > 0;
  if (!acted0 && !acted1) return;
  normalSpeed(c, r, i, 0);
  normalSpeed(c, r, i + 1, 2);
  const use0 = acted0 || (vel[0] < 0 && c.gap[i] > 2 * vel[0] * h);
  const use1 = acted1 || (vel[2] < 0 && c.gap[i + 1] > 2 * vel[2] * h);
  if (use0) target(c, i, 0);
  if (use1) target(c, i + 1, 2);
  const k00 = c.wn[i];
  const k11 = c.wn[i + 1];
  if (use0 && use1) {
    // K P = target − vn, K_jk = 1/mA + 1/mB + (rAj × n)(rAk × n)/IA + (rBj × n)(rBk × n)/IB.
    const k01 = c.kn01[i];
    const b0 = vel[1] - vel[0];
    const b1 = vel[3] - vel[2];
    const det = k00 * k11 - k01 * k01;
    if (det > 1e-9 * k00 * k11) {
      pt[1] = (k11 * b0 - k01 * b1) / det;
      pt[5] = (k00 * b1 - k01 * b0) / det;
      kick(c, r, i, 0);
      kick(c, r, i + 1, 4);
      return;
    }
  }
  // One point (or two dependent ones): one after the other, the second's speed measured again after the first.
  if (use0 && k00 > 0) {
    pt[1] = (vel[1] - vel[0]) / k00;
    kick(c, r, i, 0);
  }
  if (use1 && k11 > 0) {
    normalSpeed(c, r, i + 1, 2);
    pt[5] = (vel[3] - vel[2]) / k11;
    kick(c, r, i + 1, 4);
  }
}
