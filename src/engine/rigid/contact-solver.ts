// The rigid contact solver: per substep the position sweep (normal correction, then friction) and, after the
// velocities are derived, the velocity pass (restitution, or a stop). See RigidContacts for the model.
//
// Speed: the sweep computes each point's levers from the bodies' rotation at the start of the substep (rc, rs) where
// it needs them, and within the sweep a body's point is that lever turned by the small angle the body has turned
// since (first order); corrections add to the angle without recomputing cos and sin (rows.ts). Points that stay
// apart cost only their overlap test; the weights and what the velocity pass reads are written only for points that
// act. Nothing passes or returns a double across a call: V8 boxes a double handed to a function it does not inline
// (a heap allocation each time); the helpers take integers and pass reals through typed arrays.
import type { BodyRows } from './rows.js';
import type { Joints } from './joint-table.js';
import { weldHeld } from './joints.js';
import { rim, rimArc, type RigidContacts } from './contacts.js';
import { grown } from '../table.js';
import { BOUNCE_THRESHOLD, hit, impactInSubstep } from '../impact.js';
import { setSide, type FrameBounces } from '../pipeline/frame-bounces.js';

/** B's current normal point [0, 1] and material point [2, 3] of the point being solved (pointsOf). */
const at = new Float64Array(4);

/** Per point at offset o (0: point i, 4: its partner): [overlap or drift, λ to apply, weight, unused]. */
const pt = new Float64Array(8);

/** The lever cross products push() and kick() apply a correction with: [A's, B's]. */
const lev = new Float64Array(2);

/** Per point at offset o (0 or 2) of the velocity pass: [normal speed, target]. */
const vel = new Float64Array(4);

/**
 * Per point at offset o of the velocity pass (vel's), 1 when its target is a bounce, 2 when it is the stop (e = 0) of
 * an impact on a particle frame (target(), settle()).
 */
const bounce = new Uint8Array(4);
/** Where the velocity pass notes its bounces (solveRigidContactVelocities' argument; null: nowhere). */
let bounces: FrameBounces | null = null;

/**
 * Lever arms, their cross products with the normal and the tangent, and the weights along both, from the bodies'
 * rotation at the start of the substep (after integration), for the points on the general path (B an edge point of
 * a particle-built outline) and their manifold partners. The common path (B a rigid body, a particle or the world)
 * computes its levers in the position sweep itself, where it needs them: a point that stays apart costs no more
 * than its overlap test, and the sweep writes what the velocity pass reads only for the points that act.
 */
export function prepareRigidContacts(c: RigidContacts, r: BodyRows, maxPush = -1, j?: Joints): void {
  if (!c.shockReady) orderForShock(c, r, j);
  const n = c.count;
  if (maxPush >= 0) {
    // The substep's start (RigidContacts.beginSubstep) in the same call: no correction yet, old overlaps may shrink.
    const { lambdaN, allowance } = c;
    for (let i = 0; i < n; i++) {
      lambdaN[i] = 0;
      const left = allowance[i] - maxPush;
      allowance[i] = left > 0 ? left : 0;
    }
  }
  if (c.edgePoints === 0) return;
  const { b2, pair } = c;
  for (let i = 0; i < n; i++) {
    if (pair[i] === 1) {
      if (b2[i] >= 0 || b2[i + 1] >= 0) {
        preparePoint(c, r, i);
        preparePoint(c, r, i + 1);
        prepareCoupling(c, r, i);
      }
      i++;
    } else if (b2[i] >= 0) preparePoint(c, r, i);
  }
}

/** Point i's levers, cross products and weights (the general path's prepare). */
function preparePoint(c: RigidContacts, r: BodyRows, i: number): void {
  const { rc, rs, invMass, invInertia } = r;
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
  c.lBx[i] = c.lBy[i] = c.mBx[i] = c.mBy[i] = c.rnB[i] = c.rtB[i] = 0;
  if (ib >= 0) {
    if (c.b2[i] >= 0) {
      const al = c.alpha[i];
      const be = 1 - al;
      const w = be * be * invMass[ib] + al * al * invMass[c.b2[i]];
      wn += w;
      wt += w;
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
  }
  c.wn[i] = wn;
  c.wt[i] = wt;
}

/**
 * The couplings K01 along n and t of a manifold's two points i, i + 1 (the 2×2 blocks) through the bodies they
 * share: A, and B when both points are on the same rigid body or particle (an edge point's B side is left out).
 */
function prepareCoupling(c: RigidContacts, r: BodyRows, i: number): void {
  const j = i + 1;
  const ia = c.a[i];
  const ib = c.b[i];
  const { invMass, invInertia } = r;
  let kn = invMass[ia] + invInertia[ia] * c.rnA[i] * c.rnA[j];
  let kt = invMass[ia] + invInertia[ia] * c.rtA[i] * c.rtA[j];
  if (ib >= 0 && c.b2[i] < 0 && c.b2[j] < 0 && c.b[j] === ib) {
    kn += invMass[ib] + invInertia[ib] * c.rnB[i] * c.rnB[j];
    kt += invMass[ib] + invInertia[ib] * c.rtB[i] * c.rtB[j];
  }
  c.kn01[i] = kn;
  c.kt01[i] = kt;
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
  move[0] = along === 1 ? -c.ny[i] * l : c.nx[i] * l;
  move[1] = along === 1 ? c.nx[i] * l : c.ny[i] * l;
  move[2] = l;
  applyAt(c, r, i, r.x, r.y, r.angle);
}

/** What applyAt() applies: [x, y of the move (or impulse) per unit inverse mass, its magnitude for the turn]. */
const move = new Float64Array(3);

/**
 * Applies move[] at point i, A back and B forward, to the columns given: positions and angles (push) or velocities
 * and angular velocities (kick). A turns by its inverse inertia × lev[0] × magnitude, B by lev[1]; an edge point's
 * two particles share B's move by their weights along the edge.
 */
function applyAt(c: RigidContacts, r: BodyRows, i: number, X: Float64Array, Y: Float64Array, turn: Float64Array): void {
  const dx = move[0];
  const dy = move[1];
  const l = move[2];
  const ia = c.a[i];
  const mA = r.invMass[ia];
  X[ia] -= mA * dx;
  Y[ia] -= mA * dy;
  turn[ia] -= r.invInertia[ia] * lev[0] * l;
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const w0 = r.invMass[ib] * (1 - al);
    const w1 = r.invMass[ib2] * al;
    X[ib] += w0 * dx;
    Y[ib] += w0 * dy;
    X[ib2] += w1 * dx;
    Y[ib2] += w1 * dy;
    return;
  }
  const mB = r.invMass[ib];
  X[ib] += mB * dx;
  Y[ib] += mB * dy;
  turn[ib] += r.invInertia[ib] * lev[1] * l;
}

/** Applies pt[o+1] as point i's normal correction (λn of the substep and of the step). */
function pushApart(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  c.lambdaN[i] += pt[o + 1];
  c.impulseN[i] += pt[o + 1];
  lev[0] = c.rnA[i];
  lev[1] = c.rnB[i];
  push(c, r, i, o, 0);
}

/**
 * Point i acts: the first time in a step it is marked touched; a bouncy point (restitution > 0) also keeps its
 * approach speed for restitution, the fastest seen at the start of any substep in which it acted, until it bounces
 * (then +∞). Taking only the first substep's would lose impacts that arrive through a chain of touching bodies within
 * the step: in a Newton's cradle the second ball is pushed into the third in the substep the first ball hits it,
 * while its velocity is still 0, and the third ball's point then never bounced (the far ball rose to 13% of the
 * release height and the middle balls swung along). A manifold's two points bounce together (a box landing flat may
 * touch with one corner a substep earlier).
 */
function touch(c: RigidContacts, r: BodyRows, i: number): void {
  c.touched[i] = 1;
  if (c.restitution[i] > 0) {
    keepApproach(c, r, i, 1);
    const j = c.pair[i] === 1 ? i + 1 : i > 0 && c.pair[i - 1] === 1 ? i - 1 : -1;
    if (j >= 0) keepApproach(c, r, j, 0);
  } else if (c.b[i] >= 0 && c.frameRow[c.b[i]] === 1) keepApproach(c, r, i, 1);
}

/**
 * Point i's approach speed, its impact speed now: kept if none was, or if this one approaches faster (not once
 * bounced). A partner's touch lends it (own 0) for the velocity pass of its substep, always the latest: a lent speed
 * kept from an earlier substep had turned with the partner's corrections since (a corner bounced at 6.2 from a lent
 * approach it no longer had, 4.1), and the point's own touch replaces it.
 */
function keepApproach(c: RigidContacts, r: BodyRows, i: number, own: 0 | 1): void {
  const kept = c.approach[i];
  if (kept === Infinity) return;
  // (ownApproach and lift mean something only while approach is a number: the narrow phase resets approach alone.)
  const owned = kept === kept ? c.ownApproach[i] : 0;
  if (own === 0 && owned === 1) return;
  normalSpeed(c, r, i, 0);
  impactSpeed(c, r, i);
  if (owned === 0 || vel[0] < kept) {
    c.approach[i] = vel[0];
    c.lift[i] = vel[1];
    c.ownApproach[i] = own;
  }
}

/**
 * Point i's normal speed at the moment it hit into vel[0], from its stored one there, and into vel[1] the lift a
 * bounce adds to −e × it (impact(): a is the sides' relative normal acceleration by gravity, the overlap c.gap's,
 * for a point that overlaps). Other forces are left out: only gravity is the same through the step.
 */
function impactSpeed(c: RigidContacts, r: BodyRows, i: number): void {
  const m = c.motion;
  const ia = c.a[i];
  const ib = c.b[i];
  // Gravity moves the movable sides alike: a counts for a movable side against a fixed one (or the world).
  let share = r.invMass[ia] > 0 ? -1 : 0;
  if (ib >= 0) {
    const ib2 = c.b2[i];
    const al = ib2 >= 0 ? c.alpha[i] : 0;
    share += (1 - al) * (r.invMass[ib] > 0 ? 1 : 0) + (ib2 >= 0 && r.invMass[ib2] > 0 ? al : 0);
  }
  hit[0] = vel[0];
  hit[1] = share * (m[0] * c.nx[i] + m[1] * c.ny[i]);
  impactInSubstep(c.gap, i, m);
  vel[0] = hit[0];
  vel[1] = hit[1];
}

/**
 * One Gauss–Seidel sweep over the points: the normal correction, then friction. The two points of a manifold
 * between rigid bodies (or a rigid body and the world) take their normal corrections together by a 2×2 solve
 * (Box2D's block solver, on positions): one after the other, a deep first point would turn the body about the
 * second and throw it sideways.
 */
export function solveRigidContacts(c: RigidContacts, r: BodyRows): void {
  const { x, y, angle, qangle, rc, rs, invMass, invInertia } = r;
  const { a: A, b: B, b2: B2, pair, nx: NX, ny: NY, rAx, rAy, rBx, rBy, radA, radB, lAx, lAy, lBx, lBy } = c;
  const { rnA, rnB, wn, kn01, allowance, gap, lambdaN, impulseN, impulseT, slip, friction, touched, restitution } = c;
  for (let i = 0, n = c.count; i < n; i++) {
    const two = pair[i] === 1;
    // Edge points of particle-built outlines take the general path.
    if (B2[i] >= 0 || (two && B2[i + 1] >= 0)) {
      if (two) {
        solvePair(c, r, i);
        frictionPair(c, r, i);
        i++;
      } else solvePoint(c, r, i);
      continue;
    }
    // The common case inline (no calls: they cost more than the arithmetic). B is a row (rigid body, particle) or
    // the world (ib −1: its point is (rBx, rBy)). Each side's point is its lever at the substep's rotation (rc, rs)
    // turned by the angle since (first order); a round side's normal lever runs from its centre along n.
    const ia = A[i];
    const ib = B[i];
    const onRow = ib >= 0;
    const j = i + 1;
    const nx = NX[i];
    const ny = NY[i];
    const cA = rc[ia];
    const sA = rs[ia];
    const cB = onRow ? rc[ib] : 1;
    const sB = onRow ? rs[ib] : 0;
    let dA = angle[ia] - qangle[ia];
    let dB = onRow ? angle[ib] - qangle[ib] : 0;
    let ax = x[ia];
    let ay = y[ia];
    let bx = onRow ? x[ib] : 0;
    let by = onRow ? y[ib] : 0;
    // Material levers (m) and normal levers (l) of point i, and of its partner j.
    const mA0x = cA * rAx[i] - sA * rAy[i];
    const mA0y = sA * rAx[i] + cA * rAy[i];
    const mB0x = onRow ? cB * rBx[i] - sB * rBy[i] : 0;
    const mB0y = onRow ? sB * rBx[i] + cB * rBy[i] : 0;
    const ra0 = radA[i];
    const rb0 = radB[i];
    const lA0x = ra0 > 0 ? nx * ra0 : mA0x;
    const lA0y = ra0 > 0 ? ny * ra0 : mA0y;
    const lB0x = onRow && rb0 > 0 ? -nx * rb0 : mB0x;
    const lB0y = onRow && rb0 > 0 ? -ny * rb0 : mB0y;
    // Overlaps (past their allowance).
    const g0 = (ax + lA0x - dA * lA0y - (onRow ? bx + lB0x - dB * lB0y : rBx[i])) * nx + (ay + lA0y + dA * lA0x - (onRow ? by + lB0y + dB * lB0x : rBy[i])) * ny - allowance[i];
    gap[i] = g0;
    let mA1x = 0;
    let mA1y = 0;
    let mB1x = 0;
    let mB1y = 0;
    let lA1x = 0;
    let lA1y = 0;
    let lB1x = 0;
    let lB1y = 0;
    let g1 = -1;
    if (two) {
      mA1x = cA * rAx[j] - sA * rAy[j];
      mA1y = sA * rAx[j] + cA * rAy[j];
      mB1x = onRow ? cB * rBx[j] - sB * rBy[j] : 0;
      mB1y = onRow ? sB * rBx[j] + cB * rBy[j] : 0;
      const ra1 = radA[j];
      const rb1 = radB[j];
      lA1x = ra1 > 0 ? nx * ra1 : mA1x;
      lA1y = ra1 > 0 ? ny * ra1 : mA1y;
      lB1x = onRow && rb1 > 0 ? -nx * rb1 : mB1x;
      lB1y = onRow && rb1 > 0 ? -ny * rb1 : mB1y;
      g1 = (ax + lA1x - dA * lA1y - (onRow ? bx + lB1x - dB * lB1y : rBx[j])) * nx + (ay + lA1y + dA * lA1x - (onRow ? by + lB1y + dB * lB1x : rBy[j])) * ny - allowance[j];
      gap[j] = g1;
    }
    if (g0 <= 0 && g1 <= 0) {
      // Apart, and not touched yet this step: friction's reference follows the bodies (see followApart).
      if (friction[i] !== 0 && touched[i] === 0 && (!two || touched[j] === 0)) {
        let apart = -(ax + mA0x - dA * mA0y - (onRow ? bx + mB0x - dB * mB0y : rBx[i])) * ny + (ay + mA0y + dA * mA0x - (onRow ? by + mB0y + dB * mB0x : rBy[i])) * nx;
        if (ra0 > 0 || rb0 > 0) {
          rim[0] = -(mA0x - dA * mA0y) * ny + (mA0y + dA * mA0x) * nx;
          rim[1] = ra0;
          rimArc();
          apart = apart + rim[2];
          rim[0] = -(mB0x - dB * mB0y) * ny + (mB0y + dB * mB0x) * nx;
          rim[1] = rb0;
          rimArc();
          apart = apart - rim[2];
        }
        if (two) {
          let apart1 = -(ax + mA1x - dA * mA1y - (onRow ? bx + mB1x - dB * mB1y : rBx[j])) * ny + (ay + mA1y + dA * mA1x - (onRow ? by + mB1y + dB * mB1x : rBy[j])) * nx;
          if (radA[j] > 0 || radB[j] > 0) {
            rim[0] = -(mA1x - dA * mA1y) * ny + (mA1y + dA * mA1x) * nx;
            rim[1] = radA[j];
            rimArc();
            apart1 = apart1 + rim[2];
            rim[0] = -(mB1x - dB * mB1y) * ny + (mB1y + dB * mB1x) * nx;
            rim[1] = radB[j];
            rimArc();
            apart1 = apart1 - rim[2];
          }
          apart = 0.5 * (apart + apart1);
          slip[j] = apart;
        }
        slip[i] = apart;
      }
      if (two) i++;
      continue;
    }
    // The manifold acts: its weights, and what the velocity pass (and touch) read, for both points.
    const imA = invMass[ia];
    const iiA = invInertia[ia];
    const imB = onRow ? invMass[ib] : 0;
    const iiB = onRow ? invInertia[ib] : 0;
    const rnA0 = lA0x * ny - lA0y * nx;
    const rnB0 = lB0x * ny - lB0y * nx;
    const k00 = imA + iiA * rnA0 * rnA0 + (onRow ? imB + iiB * rnB0 * rnB0 : 0);
    lAx[i] = lA0x;
    lAy[i] = lA0y;
    lBx[i] = lB0x;
    lBy[i] = lB0y;
    rnA[i] = rnA0;
    rnB[i] = rnB0;
    wn[i] = k00;
    let rnA1 = 0;
    let rnB1 = 0;
    let k11 = 0;
    let k01 = 0;
    if (two) {
      rnA1 = lA1x * ny - lA1y * nx;
      rnB1 = lB1x * ny - lB1y * nx;
      k11 = imA + iiA * rnA1 * rnA1 + (onRow ? imB + iiB * rnB1 * rnB1 : 0);
      k01 = imA + iiA * rnA0 * rnA1 + (onRow ? imB + iiB * rnB0 * rnB1 : 0);
      lAx[j] = lA1x;
      lAy[j] = lA1y;
      lBx[j] = lB1x;
      lBy[j] = lB1y;
      rnA[j] = rnA1;
      rnB[j] = rnB1;
      wn[j] = k11;
      kn01[i] = k01;
    }
    if (g0 > 0 && (touched[i] === 0 || restitution[i] > 0)) touch(c, r, i);
    if (g1 > 0 && (touched[j] === 0 || restitution[j] > 0)) touch(c, r, j);
    // Normal corrections: one point, or a manifold's two by the 2×2 block (one after the other when it would pull).
    let l0 = 0;
    let l1 = 0;
    if (!two) l0 = k00 > 0 ? g0 / k00 : 0;
    else {
      const det = k00 * k11 - k01 * k01;
      if (g0 > 0 && g1 > 0 && det > 1e-9 * k00 * k11) {
        l0 = (k11 * g0 - k01 * g1) / det;
        l1 = (k00 * g1 - k01 * g0) / det;
      }
      if (!(l0 > 0 && l1 > 0)) {
        // One point, or a block that would pull: the deeper one first, then the other as far as it still overlaps
        // once the first's correction has moved both sides (K01 couples them).
        if (g0 >= g1) {
          l0 = k00 > 0 ? g0 / k00 : 0;
          l1 = k11 > 0 ? Math.max(0, (g1 - k01 * l0) / k11) : 0;
        } else {
          l1 = k11 > 0 ? g1 / k11 : 0;
          l0 = k00 > 0 ? Math.max(0, (g0 - k01 * l1) / k00) : 0;
        }
      }
      if (l1 > 0 && (touched[j] === 0 || restitution[j] > 0)) touch(c, r, j);
      if (l0 > 0 && (touched[i] === 0 || restitution[i] > 0)) touch(c, r, i);
    }
    // Apply: A back along n, B forward, each turned by its levers' cross products.
    const ln = l0 + l1;
    if (ln !== 0) {
      ax -= imA * ln * nx;
      ay -= imA * ln * ny;
      x[ia] = ax;
      y[ia] = ay;
      const tA = iiA * (l0 * rnA0 + (two ? l1 * rnA1 : 0));
      angle[ia] -= tA;
      dA -= tA;
      if (onRow) {
        bx += imB * ln * nx;
        by += imB * ln * ny;
        x[ib] = bx;
        y[ib] = by;
        const tB = iiB * (l0 * rnB0 + (two ? l1 * rnB1 : 0));
        angle[ib] += tB;
        dB += tB;
      }
      lambdaN[i] += l0;
      impulseN[i] += l0;
      if (two) {
        lambdaN[j] += l1;
        impulseN[j] += l1;
      }
    }
    // Friction: the tangential drift of the material points (a manifold's: their mean, at their midpoint) since the
    // step began, less what has slid, undone within Coulomb's limit on the step's summed normal corrections.
    const mu = friction[i];
    if (mu === 0 || (lambdaN[i] <= 0 && (!two || lambdaN[j] <= 0))) {
      if (two) i++;
      continue;
    }
    let drift = -(ax + mA0x - dA * mA0y - (onRow ? bx + mB0x - dB * mB0y : rBx[i])) * ny + (ay + mA0y + dA * mA0x - (onRow ? by + mB0y + dB * mB0x : rBy[i])) * nx;
    // A round side's material point measured along its rim (arcBeyond).
    if (ra0 > 0 || rb0 > 0) {
      rim[0] = -(mA0x - dA * mA0y) * ny + (mA0y + dA * mA0x) * nx;
      rim[1] = ra0;
      rimArc();
      drift = drift + rim[2];
      rim[0] = -(mB0x - dB * mB0y) * ny + (mB0y + dB * mB0x) * nx;
      rim[1] = rb0;
      rimArc();
      drift = drift - rim[2];
    }
    // Cross products of the material levers with t = (−ny, nx), and the weight along t.
    const rtA0 = mA0x * nx + mA0y * ny;
    const rtB0 = mB0x * nx + mB0y * ny;
    let la = rtA0;
    let lb = rtB0;
    let w = imA + iiA * rtA0 * rtA0 + (onRow ? imB + iiB * rtB0 * rtB0 : 0);
    let load = impulseN[i];
    if (two) {
      let drift1 = -(ax + mA1x - dA * mA1y - (onRow ? bx + mB1x - dB * mB1y : rBx[j])) * ny + (ay + mA1y + dA * mA1x - (onRow ? by + mB1y + dB * mB1x : rBy[j])) * nx;
      if (radA[j] > 0 || radB[j] > 0) {
        rim[0] = -(mA1x - dA * mA1y) * ny + (mA1y + dA * mA1x) * nx;
        rim[1] = radA[j];
        rimArc();
        drift1 = drift1 + rim[2];
        rim[0] = -(mB1x - dB * mB1y) * ny + (mB1y + dB * mB1x) * nx;
        rim[1] = radB[j];
        rimArc();
        drift1 = drift1 - rim[2];
      }
      const rtA1 = mA1x * nx + mA1y * ny;
      const rtB1 = mB1x * nx + mB1y * ny;
      const w1 = imA + iiA * rtA1 * rtA1 + (onRow ? imB + iiB * rtB1 * rtB1 : 0);
      const kt01 = imA + iiA * rtA0 * rtA1 + (onRow ? imB + iiB * rtB0 * rtB1 : 0);
      drift = 0.5 * (drift + drift1);
      la = 0.5 * (la + rtA1);
      lb = 0.5 * (lb + rtB1);
      w = 0.25 * (w + w1) + 0.5 * kt01;
      load += impulseN[j];
    }
    drift -= slip[i];
    if (w > 0) {
      const want = drift / w;
      const limit = mu * load;
      const before = impulseT[i];
      let total = before + want;
      if (total > limit) total = limit;
      else if (total < -limit) total = -limit;
      const dt = total - before;
      impulseT[i] = total;
      slip[i] += (want - dt) * w;
      if (two) slip[j] = slip[i];
      // Along t = (−ny, nx): A back, B forward.
      x[ia] = ax + imA * dt * ny;
      y[ia] = ay - imA * dt * nx;
      angle[ia] -= iiA * la * dt;
      if (onRow) {
        x[ib] = bx - imB * dt * ny;
        y[ib] = by + imB * dt * nx;
        angle[ib] += iiB * lb * dt;
      }
    }
    if (two) i++;
  }
}

/** A lone point on the general path (B an edge point of a particle-built outline). */
function solvePoint(c: RigidContacts, r: BodyRows, i: number): void {
  overlap(c, r, i, 0);
  if (pt[0] <= 0) {
    followApart(c, r, i, false);
    return;
  }
  if (c.wn[i] === 0) return;
  if (c.touched[i] === 0 || c.restitution[i] > 0) touch(c, r, i);
  pt[1] = pt[0] / c.wn[i];
  pushApart(c, r, i, 0);
  friction(c, r, i);
}

function solvePair(c: RigidContacts, r: BodyRows, i: number): void {
  overlap(c, r, i, 0);
  overlap(c, r, i + 1, 4);
  const d0 = pt[0];
  const d1 = pt[4];
  if (d0 <= 0 && d1 <= 0) {
    followApart(c, r, i, true);
    return;
  }
  if (d0 > 0 && (c.touched[i] === 0 || c.restitution[i] > 0)) touch(c, r, i);
  if (d1 > 0 && (c.touched[i + 1] === 0 || c.restitution[i + 1] > 0)) touch(c, r, i + 1);
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
    if (c.touched[i + 1] === 0 || c.restitution[i + 1] > 0) touch(c, r, i + 1);
    pt[5] = pt[4] / k11;
    pushApart(c, r, i + 1, 4);
  }
}

/**
 * A point (a manifold's two: their mean) that has not touched yet this step and does not overlap now: its slip
 * becomes its whole drift, so that when it lands later in the step friction holds it from about that substep's start,
 * not from the step's. Friction would otherwise undo what it slid through the air before landing: a disc thrown at
 * a floor left it spinning backwards, or faster than it rolled, depending on when in the step it landed. Overwrites
 * pt[0..1], pt[4..5].
 */
function followApart(c: RigidContacts, r: BodyRows, i: number, two: boolean): void {
  if (c.friction[i] === 0 || c.touched[i] !== 0 || (two && c.touched[i + 1] !== 0)) return;
  c.slip[i] = 0;
  drift(c, r, i, 0);
  if (two) {
    c.slip[i + 1] = 0;
    drift(c, r, i + 1, 4);
    pt[0] = 0.5 * (pt[0] + pt[4]);
    c.slip[i + 1] = pt[0];
  }
  c.slip[i] = pt[0];
}

/** Point i's tangential drift since the step began, less its slip (slid, or flown before landing), into pt[o]. */
function drift(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const d = r.angle[ia] - r.qangle[ia];
  const mx = c.mAx[i];
  const my = c.mAy[i];
  pointsOfB(c, r, i);
  let offset = -(r.x[ia] + mx - d * my - at[2]) * c.ny[i] + (r.y[ia] + my + d * mx - at[3]) * c.nx[i];
  // A round side's material point measured along its rim (arcBeyond); B's is a rigid row's unless it is an edge point.
  const ib = c.b[i];
  if (c.radA[i] > 0 || (ib >= 0 && c.b2[i] < 0 && c.radB[i] > 0)) {
    rim[0] = -(mx - d * my) * c.ny[i] + (my + d * mx) * c.nx[i];
    rim[1] = c.radA[i];
    rimArc();
    offset = offset + rim[2];
    if (ib >= 0 && c.b2[i] < 0) {
      const dB = r.angle[ib] - r.qangle[ib];
      rim[0] = -(c.mBx[i] - dB * c.mBy[i]) * c.ny[i] + (c.mBy[i] + dB * c.mBx[i]) * c.nx[i];
      rim[1] = c.radB[i];
      rimArc();
      offset = offset - rim[2];
    }
  }
  pt[o] = offset - c.slip[i];
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

// ---- shock propagation ------------------------------------------------------------------------------------------

/**
 * The shock sweep runs in a step where the movable rows' masses spread this many times (massesSpread) and some
 * contact joins two rigid bodies STACK_MASS_RATIO apart. Across 10× alone, a tower of boxes each 5× the one below
 * sank 69% of a box into itself, and each 8× collapsed; boxes alike (or all within 10×) keep the plain sweeps.
 */
export const SHOCK_MASS_RATIO = 10;
export const STACK_MASS_RATIO = 1.5;

/**
 * How far apart (the default contact slop) a point found at detection may be and still rest one body on the other
 * for the levels. A box falling at 200 units/s onto a light one on the ground was levelled by its speculative point
 * with the ground beside it: on the light box's level, the sweep left it 0.86 deep, and it came back out at 56 units/s.
 */
const SHOCK_TOUCH = 0.02;

/** Levels beyond this are not told apart (a deeper pile's top is solved as one level). */
const MAX_LEVEL = 64;

/**
 * Once a step (the first prepare after detection): when some contact joins two dynamic rigid bodies whose masses
 * differ SHOCK_MASS_RATIO× or more, each body's level (contacts away from a static body or the world, by relaxation
 * over the contact graph) and the manifolds between bodies on different levels, lowest first, for the shock sweep.
 * A heavy body landing on light ones pushes them into each other far faster than one sweep a substep can carry the
 * load down to the ground (the light boxes give way sideways and a pyramid bursts); the shock sweep (Guendelman et
 * al. 2003) then clears what overlap is left from the bottom up, moving only the upper body of each contact.
 */
export function orderForShock(c: RigidContacts, r: BodyRows, j?: Joints): void {
  c.shockReady = true;
  c.shockCount = 0;
  const { a: A, b: B, b2: B2, pair } = c;
  const { invMass, invInertia } = r;
  const n = c.count;
  // Whether some contact needs the sweep; when no two movable rows' masses differ that much (S1, S2, S3: all bodies
  // alike), no contact can, and the pass over the contacts only counts the edge points.
  const spread = massesSpread(invMass, r.count);
  if (c.level.length < invMass.length) c.level = grown(c.level, invMass.length);
  const level = c.level;
  const welded = j ? markWelded(j, r, level, -1) : 0;
  let needed = false;
  let edges = 0;
  for (let i = 0; i < n; i++) {
    if (B2[i] >= 0) {
      edges++;
      continue;
    }
    if (needed || !(spread || welded)) continue;
    const ib = B[i];
    if (ib < 0 || invInertia[ib] === 0) continue;
    const ma = invMass[A[i]];
    const mb = invMass[ib];
    needed = ma > 0 && mb > 0 && (ma > STACK_MASS_RATIO * mb || mb > STACK_MASS_RATIO * ma || level[A[i]] < 0 || level[ib] < 0);
  }
  c.edgePoints = edges;
  if (!needed) {
    if (welded) markWelded(j!, r, level, 0);
    return;
  }
  if (c.shockOrder.length < n) c.shockOrder = grown(c.shockOrder, n);
  for (let i = 0; i < n; i++) {
    level[A[i]] = invMass[A[i]] > 0 ? MAX_LEVEL : 0;
    if (B[i] >= 0) level[B[i]] = invMass[B[i]] > 0 ? MAX_LEVEL : 0;
  }
  if (welded) markWelded(j!, r, level, 0);
  for (let pass = 0, changed = true; changed && pass < MAX_LEVEL; pass++) {
    changed = false;
    for (let i = 0; i < n; i++) {
      // Only what touched at detection carries a level: a body still falling toward a pile stays above all of it.
      if (c.depth[i] < -SHOCK_TOUCH || !onShockPath(c, r, i)) continue;
      const ia = A[i];
      const ib = B[i];
      const la = level[ia];
      const lb = ib >= 0 ? level[ib] : 0;
      if (la > lb + 1) {
        level[ia] = lb + 1;
        changed = true;
      } else if (ib >= 0 && lb > la + 1) {
        level[ib] = la + 1;
        changed = true;
      }
    }
  }
  // Counting sort of the manifolds between different levels by their lower side's level.
  const start = c.levelStart;
  start.fill(0);
  for (let pass = 0; pass < 2; pass++) {
    for (let i = 0; i < n; i++) {
      const two = pair[i] === 1;
      const ib = B[i];
      const la = level[A[i]];
      const lb = ib >= 0 ? level[ib] : 0;
      if (la !== lb && onShockPath(c, r, i) && !(two && B2[i + 1] >= 0)) {
        const key = la < lb ? la : lb;
        if (pass === 0) start[key + 1]++;
        else c.shockOrder[start[key]++] = i;
      }
      if (two) i++;
    }
    if (pass === 0) {
      for (let k = 1; k <= MAX_LEVEL + 1; k++) start[k] += start[k - 1];
      c.shockCount = start[MAX_LEVEL + 1];
    }
  }
}

/** Sets `level` to `value` for each row a rigid weld holds (weldHeld) and returns how many. */
function markWelded(j: Joints, r: BodyRows, level: Int32Array, value: number): number {
  let count = 0;
  for (let k = 0; k < j.count; k++) {
    const held = weldHeld(j, r, k);
    if (held >= 0) {
      level[held] = value;
      count++;
    }
  }
  return count;
}

/**
 * Whether two movable rows' inverse masses differ SHOCK_MASS_RATIO× or more: the largest above that many times the
 * smallest. (If some pair has ma > R·mb, then largest ≥ ma > R·mb ≥ R·smallest: false rules every contact out.)
 */
function massesSpread(invMass: Float64Array, count: number): boolean {
  let lo = Infinity;
  let hi = 0;
  for (let i = 0; i < count; i++) {
    const m = invMass[i];
    if (m > 0) {
      if (m < lo) lo = m;
      if (m > hi) hi = m;
    }
  }
  return hi > SHOCK_MASS_RATIO * lo;
}

/**
 * Point i is between rigid bodies, or a rigid body and a static one or the world: particles (ropes, cloth, soft
 * bodies) stay out of the levels and the shock sweep, and give way as they do without it.
 */
function onShockPath(c: RigidContacts, r: BodyRows, i: number): boolean {
  const ib = c.b[i];
  return c.b2[i] < 0 && (ib < 0 || r.invMass[ib] === 0 || r.invInertia[ib] > 0);
}

/**
 * The shock sweep, after the substep's regular sweeps: manifold by manifold from the ground up, what overlap is left
 * is cleared by moving the upper body only (the lower one, already resting on what is under it, counts as fixed).
 * Normal corrections only; they do not count as the points' λn (friction and the velocity pass keep the regular
 * sweep's).
 */
export function shockSweep(c: RigidContacts, r: BodyRows): void {
  const { x, y, angle, px, py, pangle, invMass, invInertia } = r;
  const level = c.level;
  for (let k = 0; k < c.shockCount; k++) {
    const i = c.shockOrder[k];
    const two = c.pair[i] === 1;
    const ia = c.a[i];
    const ib = c.b[i];
    // The side that moves: B when it is the upper one, else A.
    const moveB = ib >= 0 && level[ib] > level[ia];
    const row = moveB ? ib : ia;
    preparePoint(c, r, i);
    overlap(c, r, i, 0);
    let g1 = -1;
    if (two) {
      preparePoint(c, r, i + 1);
      overlap(c, r, i + 1, 4);
      g1 = pt[4];
    }
    const g0 = pt[0];
    if (g0 <= 0 && g1 <= 0) continue;
    const im = invMass[row];
    const ii = invInertia[row];
    const r0 = moveB ? c.rnB[i] : c.rnA[i];
    const r1 = two ? (moveB ? c.rnB[i + 1] : c.rnA[i + 1]) : 0;
    shockBlock(im, ii, r0, r1, g0, g1, two);
    const l0 = blk[0];
    const l1 = blk[1];
    // A back along n, or B forward; the pose at the substep's start moves with it, so the correction adds no
    // velocity (shockVelocity stops the approach instead: pushed up at depth / h, a loaded pile would jump).
    const s = moveB ? 1 : -1;
    const ln = s * (l0 + l1);
    const dx = im * ln * c.nx[i];
    const dy = im * ln * c.ny[i];
    const da = s * ii * (l0 * r0 + l1 * r1);
    x[row] += dx;
    y[row] += dy;
    angle[row] += da;
    px[row] += dx;
    py[row] += dy;
    pangle[row] += da;
  }
}

/** How close to touching a point the shock sweep's velocity pass stops (see shockVelocity). */
const SHOCK_REST = 1e-3;

/** The approach speed a point `gap` apart (negative: apart) may keep for one substep of length h. */
function approachLeft(gap: number, h: number): number {
  return gap < -SHOCK_REST ? (-gap - SHOCK_REST) / h : 0;
}

/** shockBlock()'s answer: the two points' corrections (or impulses), both ≥ 0. */
const blk = new Float64Array(2);

/**
 * The shock sweeps' 2×2 block for the one body that moves (inverse mass im and inertia ii, the points' lever cross
 * products r0, r1) against what each point needs, b0 and b1 (an overlap, or an approach speed): both by the block
 * when both need and it pushes, else the larger first, then the other as far as it still needs once the first has
 * moved the body. Into blk (a typed array: doubles returned from a call are boxed).
 */
function shockBlock(im: number, ii: number, r0: number, r1: number, b0: number, b1: number, two: boolean): void {
  const k00 = im + ii * r0 * r0;
  const k11 = im + ii * r1 * r1;
  const k01 = im + ii * r0 * r1;
  let l0 = 0;
  let l1 = 0;
  const det = k00 * k11 - k01 * k01;
  if (b0 > 0 && b1 > 0 && det > 1e-9 * k00 * k11) {
    l0 = (k11 * b0 - k01 * b1) / det;
    l1 = (k00 * b1 - k01 * b0) / det;
  }
  if (!(l0 > 0 && l1 > 0)) {
    if (b0 >= b1) {
      l0 = b0 / k00;
      l1 = two ? Math.max(0, (b1 - k01 * l0) / k11) : 0;
    } else {
      l1 = b1 / k11;
      l0 = Math.max(0, (b0 - k01 * l1) / k00);
    }
  }
  blk[0] = l0;
  blk[1] = l1;
}

/**
 * The shock sweep on velocities, after the velocity pass: manifold by manifold from the ground up, the upper body
 * stops approaching the lower one (which counts as fixed); separating points (a bounce) are left alone. With the
 * position sweep above, which moves without adding velocity, a heavy body landing on light ones is stopped within the
 * substep instead of being lifted out of the overlap it made, and the pile under it neither jumps nor tips. At rest
 * too: the light body gives way under the heavy one in the regular sweep, the position sweep lifts the heavy one back
 * without a velocity, so without this the approach would grow by g·h every substep until it bounced.
 */
function shockVelocity(c: RigidContacts, r: BodyRows, h: number): void {
  const { vx, vy, omega, invMass, invInertia } = r;
  const level = c.level;
  for (let k = 0; k < c.shockCount; k++) {
    const i = c.shockOrder[k];
    const two = c.pair[i] === 1;
    const ia = c.a[i];
    const ib = c.b[i];
    const moveB = ib >= 0 && level[ib] > level[ia];
    const row = moveB ? ib : ia;
    // A point that has not acted this substep keeps the approach that brings it within SHOCK_REST of touching in one
    // substep (stopped outright, a heavy box falling at 60 units/s onto a light one hung 0.83 above it); one that
    // close is stopped (let it close the last of its gap, a box resting on a light one crept down at 0.014 units/s).
    normalSpeed(c, r, i, 0);
    const v0 = c.lambdaN[i] > 0 ? vel[0] : vel[0] + approachLeft(c.gap[i], h);
    let v1 = 0;
    if (two) {
      normalSpeed(c, r, i + 1, 2);
      v1 = c.lambdaN[i + 1] > 0 ? vel[2] : vel[2] + approachLeft(c.gap[i + 1], h);
    }
    if (v0 >= 0 && v1 >= 0) continue;
    const im = invMass[row];
    const ii = invInertia[row];
    const r0 = moveB ? c.rnB[i] : c.rnA[i];
    const r1 = two ? (moveB ? c.rnB[i + 1] : c.rnA[i + 1]) : 0;
    // Impulses (per unit inverse mass) that bring the approaching points to rest.
    shockBlock(im, ii, r0, r1, -v0, -v1, two);
    const p0 = blk[0];
    const p1 = blk[1];
    const s = moveB ? 1 : -1;
    const P = s * (p0 + p1);
    vx[row] += im * P * c.nx[i];
    vy[row] += im * P * c.ny[i];
    omega[row] += s * ii * (p0 * r0 + p1 * r1);
  }
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

/**
 * Target normal speed of point i into vel[o+1]: −e × its approach for an impact (bounce[o] = 1; settle() marks it
 * done once its impulse is applied), else 0. The approach of a point that `acted` is the faster of the one kept and
 * its normal speed now, vel[o] (see solveRigidContactVelocities); a point that only joins its partner (it did not
 * touch) bounces from the approach kept with its partner's, both of one moment: its speed now has turned with the
 * partner's correction, and a corner swung in by it bounced from that speed (16 of 200 elastic box–box hits changed
 * the energy by 1–10%). A point that was separating when it touched goes on at that speed, and one that bounced
 * earlier in the step at up to its bounce's: a target of 0 pulled both back (a hit lost up to 7%).
 */
function target(c: RigidContacts, i: number, o: number, acted: boolean): void {
  let t = 0;
  bounce[o] = 0;
  const e = c.restitution[i];
  if (e > 0) {
    const kept = c.approach[i];
    const approach = kept !== kept || (acted && vel[o] < kept) ? vel[o] : kept;
    if (kept === Infinity) {
      const now = vel[o];
      t = now < 0 ? 0 : now < c.lift[i] ? now : c.lift[i];
    } else if (approach < -BOUNCE_THRESHOLD) {
      t = -e * approach + (kept === kept ? c.lift[i] : 0);
      bounce[o] = 1;
    } else if (acted && approach > 0 && kept > 0) t = approach;
  } else if (c.approach[i] < -BOUNCE_THRESHOLD) {
    // A particle frame's point (only they keep an approach with e = 0: touch()) stops, and the frame with it.
    bounce[o] = 2;
  }
  vel[o + 1] = t;
}

/** Point i's bounce (target at vel[o+1]) was applied: no other in this step; lift keeps its speed (target()). */
function settle(c: RigidContacts, i: number, o: number): void {
  if (bounce[o] === 0) return;
  c.approach[i] = Infinity;
  if (bounce[o] === 1) c.lift[i] = vel[o + 1];
  // For a particle frame on side B (frame-bounces.ts).
  const b = bounces;
  if (b === null) return;
  const k = b.add();
  const j = 2 * k;
  setSide(b, k, 0, c.a[i], -1);
  b.armX[j] = c.lAx[i];
  b.armY[j] = c.lAy[i];
  setSide(b, k, 1, c.b[i], c.b2[i]);
  if (c.b2[i] >= 0) b.alpha[j + 1] = c.alpha[i];
  else {
    b.armX[j + 1] = c.lBx[i];
    b.armY[j + 1] = c.lBy[i];
  }
  b.nx[k] = c.nx[i];
  b.ny[k] = c.ny[i];
  b.target[k] = vel[o + 1];
  // Friction with its stop (e = 0) only (frame-bounces.ts).
  b.friction[k] = bounce[o] === 2 ? c.friction[i] : 0;
}

/** Point i's sides get the normal velocity impulse pt[o+1] (per unit inverse mass; prepared levers). */
function kick(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const P = pt[o + 1];
  move[0] = P * c.nx[i];
  move[1] = P * c.ny[i];
  move[2] = P;
  lev[0] = c.rnA[i];
  lev[1] = c.rnB[i];
  applyAt(c, r, i, r.vx, r.vy, r.omega);
}

/**
 * The velocity pass after a substep's velocities are derived: each point that acted gets its target normal speed
 * (−e × approach for an impact, 0 otherwise), so pushing an overlap out does not leave bodies flying apart at
 * depth / h. The two points of a manifold between two rigid bodies (or a rigid body and the world) are solved
 * together by a 2×2 system: solved one after the other, the second would undo part of the first through the
 * rotation they share, and a box dropped flat would bounce crooked. A point whose partner acted while it was itself
 * within two substeps' approach of touching (a box landing flat by a hair's tilt) joins it.
 */
export function solveRigidContactVelocities(c: RigidContacts, r: BodyRows, h: number, frameBounces: FrameBounces | null = null): void {
  bounces = frameBounces;
  const { vx, vy, omega, invMass, invInertia } = r;
  const { a: A, b: B, b2: B2, pair, nx: NX, ny: NY, lAx, lAy, lBx, lBy, rnA, rnB, wn, kn01, lambdaN, gap, restitution, impulseN, friction, depth } = c;
  for (let i = 0, n = c.count; i < n; i++) {
    const two = pair[i] === 1;
    if (B2[i] >= 0 || (two && B2[i + 1] >= 0)) {
      if (two) {
        pairVelocity(c, r, i, h);
        i++;
      } else pointVelocity(c, r, i);
      continue;
    }
    const j = i + 1;
    const acted0 = lambdaN[i] > 0;
    const acted1 = two && lambdaN[j] > 0;
    if (!acted0 && !acted1) {
      if (two) i++;
      continue;
    }
    // The common case inline: normal speeds of B's points relative to A's (negative approaching).
    const ia = A[i];
    const ib = B[i];
    const nx = NX[i];
    const ny = NY[i];
    const wa = omega[ia];
    const wb = ib >= 0 ? omega[ib] : 0;
    const vbx = ib >= 0 ? vx[ib] : 0;
    const vby = ib >= 0 ? vy[ib] : 0;
    const rvx = vbx - vx[ia];
    const rvy = vby - vy[ia];
    const v0 = (rvx - wb * lBy[i] + wa * lAy[i]) * nx + (rvy + wb * lBx[i] - wa * lAx[i]) * ny;
    const v1 = two ? (rvx - wb * lBy[j] + wa * lAy[j]) * nx + (rvy + wb * lBx[j] - wa * lAx[j]) * ny : 0;
    // A point joins when it acted, or when its partner acted while it was within two substeps' approach.
    const use0 = acted0 || (v0 < 0 && gap[i] > 2 * v0 * h);
    const use1 = two && (acted1 || (v1 < 0 && gap[j] > 2 * v1 * h));
    // Targets: −e × the approach for an impact (once), else 0. The approach is the faster of the one kept (touch())
    // and the one now: an impulse that reached A or B earlier in this sweep (a cradle's ball just hit) bounces on.
    let t0 = 0;
    let t1 = 0;
    const e = restitution[i];
    bounce[0] = 0;
    bounce[2] = 0;
    // (A particle frame's points keep an approach with e = 0 too: its stop, target() and settle().)
    if (e > 0 || (ib >= 0 && c.frameRow[ib] === 1)) {
      if (use0) {
        vel[0] = v0;
        target(c, i, 0, acted0);
        t0 = vel[1];
      }
      if (use1) {
        vel[2] = v1;
        target(c, j, 2, acted1);
        t1 = vel[3];
      }
    }
    let p0 = 0;
    let p1 = 0;
    const k00 = wn[i];
    if (use0 && use1) {
      const k11 = wn[j];
      const k01 = kn01[i];
      const det = k00 * k11 - k01 * k01;
      if (det > 1e-9 * k00 * k11) {
        p0 = (k11 * (t0 - v0) - k01 * (t1 - v1)) / det;
        p1 = (k00 * (t1 - v1) - k01 * (t0 - v0)) / det;
        // A block that pushes one point and pulls the other (a rolling polygon's pivot as its next corner lands):
        // the pushing point alone. The pull held the pivot down and stopped the roll (polygons rolled 3-5× short).
        // A bouncing manifold (e > 0) instead keeps the block when both points touched, and otherwise takes the one
        // that touched alone: spun boxes' corners hitting elastically gained up to 47% when a point kept the speed
        // of its overlap's push, or a corner that only joined bounced alone. (A stop alone, e = 0, takes energy
        // out.) (Plain assignments: a destructured pair allocates an array in the hot loop.)
        const push0 = p0 >= 0 && p1 < 0;
        if (push0 || (p1 >= 0 && p0 < 0)) {
          if (e === 0 ? push0 : !acted1) {
            p0 = (t0 - v0) / k00;
            p1 = 0;
          } else if (e === 0 || !acted0) {
            p0 = 0;
            p1 = (t1 - v1) / k11;
          }
        }
      } else {
        p0 = (t0 - v0) / k00;
        p1 = (t1 - v1 - k01 * p0) / k11;
      }
    } else if (use0) p0 = k00 > 0 ? (t0 - v0) / k00 : 0;
    else if (use1) p1 = wn[j] > 0 ? (t1 - v1) / wn[j] : 0;
    if (p0 === 0 && p1 === 0) {
      if (two) i++;
      continue;
    }
    if (p0 !== 0) settle(c, i, 0);
    if (p1 !== 0) settle(c, j, 2);
    const P = p0 + p1;
    const imA = invMass[ia];
    vx[ia] -= imA * P * nx;
    vy[ia] -= imA * P * ny;
    omega[ia] -= invInertia[ia] * (p0 * rnA[i] + (two ? p1 * rnA[j] : 0));
    if (ib >= 0) {
      const imB = invMass[ib];
      vx[ib] += imB * P * nx;
      vy[ib] += imB * P * ny;
      omega[ib] += invInertia[ib] * (p0 * rnB[i] + (two ? p1 * rnB[j] : 0));
    }
    // Coulomb's friction for this impulse, for a landing (every point of it apart when the step began, none acting
    // before this substep: its step's corrections are this substep's). Contacts that go on touching are left to the
    // sweep, whose friction they load from the start. The sliding at point i (a manifold's first point: a face's two
    // points have the same lever along n, so the same turn and speed along t) is cut by up to μ·P, never past rolling.
    // The sweep's friction is bounded by the sweep's normal corrections, and a landing late in a substep has little
    // overlap there: this pass stops most of its approach (and restitution adds its bounce). Without it a box thrown
    // onto the floor came to rest anywhere within 2.7 units of where Coulomb's law puts it, depending on when in the
    // step it landed, and a bouncing disc kept much of its slide. Inline: a rarely run function is left unoptimised,
    // and its arithmetic allocates. (The kernel's velocity passes do the same, lane by lane.)
    const mu = friction[i];
    if (P > 0 && mu > 0 && depth[i] < 0 && impulseN[i] === lambdaN[i] && (!two || (depth[j] < 0 && impulseN[j] === lambdaN[j]))) {
      // The levers' components along n (their cross products with t = (−ny, nx)), and the weight along t.
      const rtA = lAx[i] * nx + lAy[i] * ny;
      const rtB = lBx[i] * nx + lBy[i] * ny;
      const iiA = invInertia[ia];
      const imB = ib >= 0 ? invMass[ib] : 0;
      const iiB = ib >= 0 ? invInertia[ib] : 0;
      const w = imA + iiA * rtA * rtA + (imB + iiB * rtB * rtB);
      if (w > 0) {
        // B's speed relative to A's along t at the contact.
        const tvx = (ib >= 0 ? vx[ib] : 0) - vx[ia];
        const tvy = (ib >= 0 ? vy[ib] : 0) - vy[ia];
        const vt = -tvx * ny + tvy * nx + (ib >= 0 ? omega[ib] : 0) * rtB - omega[ia] * rtA;
        const limit = mu * P;
        let pt = -vt / w;
        if (pt > limit) pt = limit;
        else if (pt < -limit) pt = -limit;
        // Along t: A back, B forward.
        vx[ia] += imA * pt * ny;
        vy[ia] -= imA * pt * nx;
        omega[ia] -= iiA * rtA * pt;
        if (ib >= 0) {
          vx[ib] -= imB * pt * ny;
          vy[ib] += imB * pt * nx;
          omega[ib] += iiB * rtB * pt;
        }
      }
    }
    if (two) i++;
  }
  if (c.shockCount > 0) shockVelocity(c, r, h);
}

/** A lone point's velocity on the general path (B an edge point of a particle-built outline). */
function pointVelocity(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.lambdaN[i] <= 0 || c.wn[i] <= 0) return;
  normalSpeed(c, r, i, 0);
  target(c, i, 0, true);
  pt[1] = (vel[1] - vel[0]) / c.wn[i];
  kick(c, r, i, 0);
  settle(c, i, 0);
}

function pairVelocity(c: RigidContacts, r: BodyRows, i: number, h: number): void {
  const acted0 = c.lambdaN[i] > 0;
  const acted1 = c.lambdaN[i + 1] > 0;
  if (!acted0 && !acted1) return;
  normalSpeed(c, r, i, 0);
  normalSpeed(c, r, i + 1, 2);
  const use0 = acted0 || (vel[0] < 0 && c.gap[i] > 2 * vel[0] * h);
  const use1 = acted1 || (vel[2] < 0 && c.gap[i + 1] > 2 * vel[2] * h);
  bounce[0] = 0;
  bounce[2] = 0;
  if (use0) target(c, i, 0, acted0);
  if (use1) target(c, i + 1, 2, acted1);
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
      // A block that pushes one point and pulls the other: the pushing point alone, or for a bouncing manifold
      // the whole block when both touched, else the one that touched (as in the common case).
      const push0 = pt[1] >= 0 && pt[5] < 0;
      const mixed = push0 || (pt[5] >= 0 && pt[1] < 0);
      const stop = c.restitution[i] === 0;
      if (mixed && (stop ? push0 : !acted1)) {
        pt[1] = b0 / k00;
        kick(c, r, i, 0);
        settle(c, i, 0);
      } else if (mixed && (stop || !acted0)) {
        pt[5] = b1 / k11;
        kick(c, r, i + 1, 4);
        settle(c, i + 1, 2);
      } else {
        kick(c, r, i, 0);
        kick(c, r, i + 1, 4);
        settle(c, i, 0);
        settle(c, i + 1, 2);
      }
      return;
    }
  }
  // One point (or two dependent ones): one after the other, the second's speed measured again after the first.
  if (use0 && k00 > 0) {
    pt[1] = (vel[1] - vel[0]) / k00;
    kick(c, r, i, 0);
    settle(c, i, 0);
  }
  if (use1 && k11 > 0) {
    normalSpeed(c, r, i + 1, 2);
    pt[5] = (vel[3] - vel[2]) / k11;
    kick(c, r, i + 1, 4);
    settle(c, i + 1, 2);
  }
}
