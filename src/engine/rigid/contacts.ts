import { Table } from '../table.js';
import { KeyTable } from '../pipeline/key-table.js';
import { turn, type BodyRows } from './rows.js';

/**
 * Contact points where at least one side is a rigid body, solved in the XPBD substep loop (Müller et al. 2020, §3.5).
 *
 * Side A is always a rigid body row `a`. Side B is one of:
 * - a rigid body or a particle: row `b` (a particle is a row with inverse inertia 0), anchor (rBx, rBy) in its frame;
 * - a point on an edge of a particle-built outline: rows `b` and `b2` at fraction `alpha` (b2 ≥ 0);
 * - the world (b = −1): a fixed point (rBx, rBy) in world coordinates.
 * The anchors (rAx, rAy), (rBx, rBy) are material points in each body's frame, found by the narrow phase once a step
 * on the two outlines (A's point minus B's point is depth·n). A side with a radius (`radA`, `radB` > 0) is round: its
 * normal contact point is centre ± radius·n, wherever the body has turned to since, so a rolling disc stays on the
 * ground while its material anchor (used for friction) turns away.
 *
 * Per substep, for each point: the overlap d = (qA − qB)·n (n from A to B); if d > 0 both sides move apart along n by
 * d shared by generalised inverse mass (λn); then friction: the tangential drift of the two material points since
 * the step began, (pA − pB)·t − slip, is undone up to Coulomb's μ·λn (static friction holds exactly, a larger drift
 * slides and the excess becomes slip). After the substep's velocities are derived, the velocity pass sets each
 * acting point's normal velocity to −e times its approach speed for an impact, 0 otherwise (two points of one
 * manifold together, by a 2×2 solve, so a box dropped flat bounces flat).
 */
export class RigidContacts extends Table {
  readonly columns = [
    'a', 'b', 'b2', 'alpha', 'nx', 'ny', 'rAx', 'rAy', 'rBx', 'rBy', 'radA', 'radB', 'friction', 'restitution', 'lambdaN', 'lambdaT',
    'slip', 'allowance', 'approach', 'touched', 'pair', 'bodyA', 'bodyB', 'depth', 'gap', 'feature', 'impulseN', 'impulseT',
  ] as const;
  a = new Int32Array(16);
  b = new Int32Array(16);
  b2 = new Int32Array(16);
  alpha = new Float64Array(16);
  /** Unit normal from A to B, fixed for the step. */
  nx = new Float64Array(16);
  ny = new Float64Array(16);
  rAx = new Float64Array(16);
  rAy = new Float64Array(16);
  rBx = new Float64Array(16);
  rBy = new Float64Array(16);
  radA = new Float64Array(16);
  radB = new Float64Array(16);
  friction = new Float64Array(16);
  restitution = new Float64Array(16);
  /** Normal and tangential corrections of the current substep (XPBD multipliers, in position units × mass). */
  lambdaN = new Float64Array(16);
  lambdaT = new Float64Array(16);
  /** Tangential distance the point has slid since the step began (friction holds the rest). */
  slip = new Float64Array(16);
  /** Overlap tolerated this substep: an old deep overlap is pushed out at a bounded speed, not in one substep. */
  allowance = new Float64Array(16);
  /** Normal speed (B relative to A, negative approaching) when the point first acted in this step; NaN before. */
  approach = new Float64Array(16);
  touched = new Uint8Array(16);
  /** 1 on the first point of a two-point manifold (its partner is the next row). */
  pair = new Uint8Array(16);
  /** Body slots of the two sides (−1 for the world), for events and sleeping. */
  bodyA = new Int32Array(16);
  bodyB = new Int32Array(16);
  /** Depth at detection (negative: a speculative gap). */
  depth = new Float64Array(16);
  /** Overlap at the last position sweep, before its correction (negative: apart). */
  gap = new Float64Array(16);
  /** Normal and tangential corrections summed over the step so far (friction's Coulomb limit compares these). */
  impulseN = new Float64Array(16);
  impulseT = new Float64Array(16);
  /** Which bodies and features made the point (the same while they keep touching the same way); see anchorKey. */
  feature = new Float64Array(16);

  /**
   * The next point's reals, written by the caller before add(): nx, ny, rAx, rAy, rBx, rBy, radA, radB, alpha,
   * friction, restitution, depth, feature key. (An array rather than arguments: doubles passed to a call that is not inlined are
   * boxed, and the narrow phase adds thousands of points a step.)
   */
  readonly next = new Float64Array(13);

  add(a: number, b: number, b2: number, bodyA: number, bodyB: number, pair: number): void {
    if (this.count === this.a.length) this.reserve(1);
    const i = this.count++;
    const f = this.next;
    this.a[i] = a;
    this.b[i] = b;
    this.b2[i] = b2;
    this.nx[i] = f[0];
    this.ny[i] = f[1];
    this.rAx[i] = f[2];
    this.rAy[i] = f[3];
    this.rBx[i] = f[4];
    this.rBy[i] = f[5];
    this.radA[i] = f[6];
    this.radB[i] = f[7];
    this.alpha[i] = f[8];
    this.friction[i] = f[9];
    this.restitution[i] = f[10];
    this.depth[i] = f[11];
    this.allowance[i] = f[11] > 0 ? f[11] : 0;
    this.lambdaN[i] = 0;
    this.lambdaT[i] = 0;
    this.impulseN[i] = 0;
    this.impulseT[i] = 0;
    this.slip[i] = 0;
    this.approach[i] = NaN;
    this.touched[i] = 0;
    this.pair[i] = pair;
    this.bodyA[i] = bodyA;
    this.bodyB[i] = bodyB;
    this.gap[i] = f[11];
    this.feature[i] = f[12];
  }

  /** Start of a substep: no correction yet; old overlaps may shrink by up to `maxPush` more. */
  beginSubstep(maxPush: number): void {
    const { lambdaN, lambdaT, allowance } = this;
    for (let i = 0, n = this.count; i < n; i++) {
      lambdaN[i] = 0;
      lambdaT[i] = 0;
      const left = allowance[i] - maxPush;
      allowance[i] = left > 0 ? left : 0;
    }
  }
}

/** Approach speeds below this do not bounce (resting contacts would jitter otherwise). */
export const BOUNCE_THRESHOLD = 0.5;

/**
 * Scratch for the side currently being solved: world lever arms and weights. Kept in a typed array so the solver's
 * helpers return nothing (a double returned from a call that is not inlined is boxed).
 */
const side = new Float64Array(8);
// side[0..1]: B's normal point qB; side[2..3]: B's normal lever lB; side[4..5]: B's material point pB; side[6..7]: B's material lever.

/** B's normal point, material point and levers for point i (rigid or particle row, edge or world). */
function loadB(c: RigidContacts, r: BodyRows, i: number, nx: number, ny: number): void {
  const ib = c.b[i];
  if (ib < 0) {
    side[0] = side[4] = c.rBx[i];
    side[1] = side[5] = c.rBy[i];
    side[2] = side[3] = side[6] = side[7] = 0;
    return;
  }
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const be = 1 - al;
    side[0] = side[4] = be * r.x[ib] + al * r.x[ib2];
    side[1] = side[5] = be * r.y[ib] + al * r.y[ib2];
    side[2] = side[3] = side[6] = side[7] = 0;
    return;
  }
  const cs = r.rc[ib];
  const sn = r.rs[ib];
  const bx = c.rBx[i];
  const by = c.rBy[i];
  const mx = cs * bx - sn * by;
  const my = sn * bx + cs * by;
  side[6] = mx;
  side[7] = my;
  side[4] = r.x[ib] + mx;
  side[5] = r.y[ib] + my;
  const rad = c.radB[i];
  if (rad > 0) {
    side[2] = -nx * rad;
    side[3] = -ny * rad;
  } else {
    side[2] = mx;
    side[3] = my;
  }
  side[0] = r.x[ib] + side[2];
  side[1] = r.y[ib] + side[3];
}

/** B's generalised inverse mass along a direction with lever cross product `rn` (edge: split by α). */
function weightB(c: RigidContacts, r: BodyRows, i: number, rn: number): number {
  const ib = c.b[i];
  if (ib < 0) return 0;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const be = 1 - al;
    return be * be * r.invMass[ib] + al * al * r.invMass[ib2];
  }
  return r.invMass[ib] + r.invInertia[ib] * rn * rn;
}

/** Moves B by +λ along (dx, dy) with lever cross product `rn` (the opposite of what A gets). */
function pushB(c: RigidContacts, r: BodyRows, i: number, l: number, dx: number, dy: number, rn: number): void {
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const be = 1 - al;
    const w0 = r.invMass[ib] * be * l;
    const w1 = r.invMass[ib2] * al * l;
    r.x[ib] += w0 * dx;
    r.y[ib] += w0 * dy;
    r.x[ib2] += w1 * dx;
    r.y[ib2] += w1 * dy;
    return;
  }
  const m = r.invMass[ib] * l;
  r.x[ib] += m * dx;
  r.y[ib] += m * dy;
  const iI = r.invInertia[ib];
  if (iI !== 0) turn(r, ib, iI * rn * l);
}

/** The point being solved: [d, w, rnA, rnB] per point, at offset 0 (point i) and 4 (its partner). */
const pt = new Float64Array(8);

/**
 * Point i's overlap d (past its allowance), generalised inverse mass w along n and the levers' cross products, into
 * pt[o..o+3]; also records the overlap as `gap` (the velocity pass looks at it).
 */
function measure(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const ra = c.radA[i];
  let lAx: number;
  let lAy: number;
  if (ra > 0) {
    lAx = nx * ra;
    lAy = ny * ra;
  } else {
    const cs = r.rc[ia];
    const sn = r.rs[ia];
    lAx = cs * c.rAx[i] - sn * c.rAy[i];
    lAy = sn * c.rAx[i] + cs * c.rAy[i];
  }
  loadB(c, r, i, nx, ny);
  const d = (r.x[ia] + lAx - side[0]) * nx + (r.y[ia] + lAy - side[1]) * ny - c.allowance[i];
  c.gap[i] = d;
  const rnA = lAx * ny - lAy * nx;
  const rnB = side[2] * ny - side[3] * nx;
  pt[o] = d;
  pt[o + 1] = r.invMass[ia] + r.invInertia[ia] * rnA * rnA + weightB(c, r, i, rnB);
  pt[o + 2] = rnA;
  pt[o + 3] = rnB;
}

/** Pushes point i's sides apart by dl along n (levers from pt[o..]). */
function pushApart(c: RigidContacts, r: BodyRows, i: number, dl: number, o: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  c.lambdaN[i] += dl;
  c.impulseN[i] += dl;
  const imA = r.invMass[ia];
  r.x[ia] -= imA * dl * nx;
  r.y[ia] -= imA * dl * ny;
  const iIA = r.invInertia[ia];
  if (iIA !== 0) turn(r, ia, -iIA * pt[o + 2] * dl);
  pushB(c, r, i, dl, nx, ny, pt[o + 3]);
}

/** The first time point i acts in a step: remember its approach speed (and its partner's) for restitution. */
function firstTouch(c: RigidContacts, r: BodyRows, i: number): void {
  c.touched[i] = 1;
  if (c.restitution[i] > 0 && c.approach[i] !== c.approach[i]) {
    c.approach[i] = pointNormalSpeed(c, r, i);
    // A manifold's two points bounce together (a box landing flat may touch with one corner a substep earlier).
    const j = c.pair[i] === 1 ? i + 1 : i > 0 && c.pair[i - 1] === 1 ? i - 1 : -1;
    if (j >= 0 && c.approach[j] !== c.approach[j]) c.approach[j] = pointNormalSpeed(c, r, j);
  }
}

/**
 * One Gauss–Seidel sweep over the points: the normal correction, then friction. The two points of a manifold
 * between rigid bodies (or a rigid body and the world) take their normal corrections together by a 2×2 solve
 * (Box2D's block solver, on positions): one after the other, a deep first point would turn the body about the
 * second and throw it sideways.
 */
export function solveRigidContacts(c: RigidContacts, r: BodyRows): void {
  const n = c.count;
  for (let i = 0; i < n; i++) {
    if (c.pair[i] === 1 && c.b2[i] < 0 && c.b2[i + 1] < 0) {
      solvePair(c, r, i);
      frictionPair(c, r, i);
      i++;
    } else solvePoint(c, r, i);
  }
}

function solvePoint(c: RigidContacts, r: BodyRows, i: number): void {
  measure(c, r, i, 0);
  const d = pt[0];
  if (d <= 0 || pt[1] === 0) return;
  if (c.touched[i] === 0) firstTouch(c, r, i);
  pushApart(c, r, i, d / pt[1], 0);
  friction(c, r, i);
}

function solvePair(c: RigidContacts, r: BodyRows, i: number): void {
  measure(c, r, i, 0);
  measure(c, r, i + 1, 4);
  const d0 = pt[0];
  const d1 = pt[4];
  if (d0 <= 0 && d1 <= 0) return;
  if (d0 > 0 && c.touched[i] === 0) firstTouch(c, r, i);
  if (d1 > 0 && c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
  if (d0 > 0 && d1 > 0) {
    const ia = c.a[i];
    const ib = c.b[i];
    const k00 = pt[1];
    const k11 = pt[5];
    let k01 = r.invMass[ia] + r.invInertia[ia] * pt[2] * pt[6];
    if (ib >= 0) k01 += r.invMass[ib] + r.invInertia[ib] * pt[3] * pt[7];
    const det = k00 * k11 - k01 * k01;
    if (det > 1e-9 * k00 * k11) {
      const l0 = (k11 * d0 - k01 * d1) / det;
      const l1 = (k00 * d1 - k01 * d0) / det;
      if (l0 >= 0 && l1 >= 0) {
        pushApart(c, r, i, l0, 0);
        pushApart(c, r, i + 1, l1, 4);
        return;
      }
    }
  }
  // One point overlapping, or the block would pull: one after the other.
  if (d0 > 0 && pt[1] > 0) pushApart(c, r, i, d0 / pt[1], 0);
  measure(c, r, i + 1, 4);
  if (pt[4] > 0 && pt[5] > 0) {
    if (c.touched[i + 1] === 0) firstTouch(c, r, i + 1);
    pushApart(c, r, i + 1, pt[4] / pt[5], 4);
  }
}

/** Friction of the point being solved: [drift, wt, rtA, rtB] per point, at offset 0 (point i) and 4 (its partner). */
const fr = new Float64Array(8);

/** Point i's tangential drift since the step began (less what has slid), weight and levers, into fr[o..o+3]. */
function measureFriction(c: RigidContacts, r: BodyRows, i: number, o: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const mAx = cs * c.rAx[i] - sn * c.rAy[i];
  const mAy = sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i, nx, ny);
  const tx = -ny;
  const ty = nx;
  const rtA = mAx * ty - mAy * tx;
  const rtB = side[6] * ty - side[7] * tx;
  fr[o] = (r.x[ia] + mAx - side[4]) * tx + (r.y[ia] + mAy - side[5]) * ty - c.slip[i];
  fr[o + 1] = r.invMass[ia] + r.invInertia[ia] * rtA * rtA + weightB(c, r, i, rtB);
  fr[o + 2] = rtA;
  fr[o + 3] = rtB;
}

/** Moves point i's sides by dt along the tangent (A back, B forward; levers from fr[o..]). */
function pushAlong(c: RigidContacts, r: BodyRows, i: number, dt: number, o: number): void {
  const ia = c.a[i];
  const tx = -c.ny[i];
  const ty = c.nx[i];
  c.lambdaT[i] += dt;
  const imA = r.invMass[ia];
  r.x[ia] -= imA * dt * tx;
  r.y[ia] -= imA * dt * ty;
  const iIA = r.invInertia[ia];
  if (iIA !== 0) turn(r, ia, -iIA * fr[o + 2] * dt);
  pushB(c, r, i, dt, tx, ty, fr[o + 3]);
}

/**
 * Friction of point i (after its normal correction this sweep): the material points' tangential drift since the
 * step began is undone within Coulomb's limit, μ times the normal correction of the step so far; what cannot be
 * held slides, and the anchors follow (slip).
 */
function friction(c: RigidContacts, r: BodyRows, i: number): void {
  const mu = c.friction[i];
  if (mu === 0 || c.lambdaN[i] <= 0) return;
  measureFriction(c, r, i, 0);
  if (fr[1] === 0) return;
  holdWithin(c, r, i, fr[0] / fr[1], fr[1], 0);
}

/** Applies the tangential correction `want` to point i as far as Coulomb allows; the rest becomes slip. */
function holdWithin(c: RigidContacts, r: BodyRows, i: number, want: number, wt: number, o: number): void {
  const limit = c.friction[i] * c.impulseN[i];
  const before = c.impulseT[i];
  let total = before + want;
  if (total > limit) total = limit;
  else if (total < -limit) total = -limit;
  const dt = total - before;
  c.impulseT[i] = total;
  c.slip[i] += (want - dt) * wt;
  pushAlong(c, r, i, dt, o);
}

/**
 * Friction of a manifold's two points as one constraint at their midpoint, with Coulomb's limit on their summed
 * normal corrections. In 2D the two points of a face contact slide together (a turn moves them along the normal, not
 * along the face), so two tangential constraints would be one twice over: solved one after the other, the first
 * would saturate while the second still held, record a slide that did not happen, and a pile would creep sideways
 * step after step.
 */
function frictionPair(c: RigidContacts, r: BodyRows, i: number): void {
  const mu = c.friction[i];
  if (mu === 0 || (c.lambdaN[i] <= 0 && c.lambdaN[i + 1] <= 0)) return;
  measureFriction(c, r, i, 0);
  measureFriction(c, r, i + 1, 4);
  // The midpoint's drift and levers are the points' means (cross products are linear in the lever).
  // (Both points carry the manifold's slip, so the mean of their drifts is the midpoint's.)
  const drift = 0.5 * (fr[0] + fr[4]);
  const rtA = 0.5 * (fr[2] + fr[6]);
  const rtB = 0.5 * (fr[3] + fr[7]);
  const ia = c.a[i];
  const wt = r.invMass[ia] + r.invInertia[ia] * rtA * rtA + weightB(c, r, i, rtB);
  if (wt === 0) return;
  const want = drift / wt;
  const limit = mu * (c.impulseN[i] + c.impulseN[i + 1]);
  const before = c.impulseT[i];
  let total = before + want;
  if (total > limit) total = limit;
  else if (total < -limit) total = -limit;
  const dt = total - before;
  c.impulseT[i] = total;
  c.slip[i] += (want - dt) * wt;
  c.slip[i + 1] = c.slip[i];
  fr[2] = rtA;
  fr[3] = rtB;
  pushAlong(c, r, i, dt, 0);
}

/** Normal speed of point i's B side relative to its A side now (negative when approaching). */
function pointNormalSpeed(c: RigidContacts, r: BodyRows, i: number): number {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const ra = c.radA[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const lAx = ra > 0 ? nx * ra : cs * c.rAx[i] - sn * c.rAy[i];
  const lAy = ra > 0 ? ny * ra : sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i, nx, ny);
  return relativeNormalSpeed(c, r, i, ia, lAx, lAy, nx, ny);
}

/** Normal speed of B's contact point relative to A's (negative when approaching). */
function relativeNormalSpeed(c: RigidContacts, r: BodyRows, i: number, ia: number, lAx: number, lAy: number, nx: number, ny: number): number {
  const { vx, vy, omega } = r;
  const wa = omega[ia];
  const vax = vx[ia] - wa * lAy;
  const vay = vy[ia] + wa * lAx;
  const ib = c.b[i];
  let vbx = 0;
  let vby = 0;
  if (ib >= 0) {
    const ib2 = c.b2[i];
    if (ib2 >= 0) {
      const al = c.alpha[i];
      vbx = (1 - al) * vx[ib] + al * vx[ib2];
      vby = (1 - al) * vy[ib] + al * vy[ib2];
    } else {
      const wb = omega[ib];
      vbx = vx[ib] - wb * side[3];
      vby = vy[ib] + wb * side[2];
    }
  }
  return (vbx - vax) * nx + (vby - vay) * ny;
}

/** Per point of the velocity pass: [vn, w, rnA, rnB, lAx, lAy, target]. */
const vel = new Float64Array(14);

/**
 * Normal speed, weight and levers of point i into vel[o..o+5], and with `withTarget` its target speed into vel[o+6]
 * (which uses up a pending bounce).
 */
function loadVelocity(c: RigidContacts, r: BodyRows, i: number, o: number, withTarget: boolean): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const ra = c.radA[i];
  const cs = r.rc[ia];
  const sn = r.rs[ia];
  const lAx = ra > 0 ? nx * ra : cs * c.rAx[i] - sn * c.rAy[i];
  const lAy = ra > 0 ? ny * ra : sn * c.rAx[i] + cs * c.rAy[i];
  loadB(c, r, i, nx, ny);
  const rnA = lAx * ny - lAy * nx;
  const rnB = side[2] * ny - side[3] * nx;
  vel[o] = relativeNormalSpeed(c, r, i, ia, lAx, lAy, nx, ny);
  vel[o + 1] = r.invMass[ia] + r.invInertia[ia] * rnA * rnA + weightB(c, r, i, rnB);
  vel[o + 2] = rnA;
  vel[o + 3] = rnB;
  vel[o + 4] = lAx;
  vel[o + 5] = lAy;
  if (!withTarget) return;
  // Target normal speed: bounce once per impact (approach recorded when the point first acted), else stop.
  let target = 0;
  const e = c.restitution[i];
  const approach = c.approach[i];
  if (e > 0 && approach < -BOUNCE_THRESHOLD) {
    target = -e * approach;
    c.approach[i] = 0;
  }
  vel[o + 6] = target;
}

/** Applies a normal impulse P (per unit mass weights) to point i's two sides. */
function applyNormalImpulse(c: RigidContacts, r: BodyRows, i: number, P: number, rnA: number, rnB: number): void {
  const ia = c.a[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const imA = r.invMass[ia];
  r.vx[ia] -= imA * P * nx;
  r.vy[ia] -= imA * P * ny;
  r.omega[ia] -= r.invInertia[ia] * rnA * P;
  const ib = c.b[i];
  if (ib < 0) return;
  const ib2 = c.b2[i];
  if (ib2 >= 0) {
    const al = c.alpha[i];
    const m0 = r.invMass[ib] * (1 - al) * P;
    const m1 = r.invMass[ib2] * al * P;
    r.vx[ib] += m0 * nx;
    r.vy[ib] += m0 * ny;
    r.vx[ib2] += m1 * nx;
    r.vy[ib2] += m1 * ny;
    return;
  }
  const imB = r.invMass[ib];
  r.vx[ib] += imB * P * nx;
  r.vy[ib] += imB * P * ny;
  r.omega[ib] += r.invInertia[ib] * rnB * P;
}

/**
 * The velocity pass after a substep's velocities are derived: each point that acted gets its target normal speed
 * (−e × approach for an impact, 0 otherwise), so pushing an overlap out does not leave bodies flying apart at
 * depth / h. The two points of a manifold between two rigid bodies (or a rigid body and the world) are solved
 * together by a 2×2 system: solved one after the other, the second would undo part of the first through the
 * rotation they share, and a box dropped flat would bounce crooked. A point whose partner acted while it was itself
 * still within a substep's approach of touching (a box landing flat by a hair's tilt) joins it.
 */
export function solveRigidContactVelocities(c: RigidContacts, r: BodyRows, h: number): void {
  for (let i = 0, n = c.count; i < n; i++) {
    if (c.pair[i] === 1 && c.b2[i] < 0 && c.b2[i + 1] < 0) {
      solvePairVelocity(c, r, i, h);
      i++;
    } else pointVelocity(c, r, i);
  }
}

function pointVelocity(c: RigidContacts, r: BodyRows, i: number): void {
  if (c.lambdaN[i] <= 0) return;
  loadVelocity(c, r, i, 0, true);
  if (vel[1] > 0) applyNormalImpulse(c, r, i, (vel[6] - vel[0]) / vel[1], vel[2], vel[3]);
}

function solvePairVelocity(c: RigidContacts, r: BodyRows, i: number, h: number): void {
  const acted0 = c.lambdaN[i] > 0;
  const acted1 = c.lambdaN[i + 1] > 0;
  if (!acted0 && !acted1) return;
  loadVelocity(c, r, i, 0, false);
  loadVelocity(c, r, i + 1, 7, false);
  const use0 = acted0 || (vel[0] < 0 && c.gap[i] > 2 * vel[0] * h);
  const use1 = acted1 || (vel[7] < 0 && c.gap[i + 1] > 2 * vel[7] * h);
  if (use0) loadVelocity(c, r, i, 0, true);
  if (use1) loadVelocity(c, r, i + 1, 7, true);
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
      applyNormalImpulse(c, r, i, (k11 * b0 - k01 * b1) / det, vel[2], vel[3]);
      applyNormalImpulse(c, r, i + 1, (k00 * b1 - k01 * b0) / det, vel[9], vel[10]);
      return;
    }
  }
  // One point (or two dependent ones): one after the other, the second's speed measured again after the first.
  if (use0 && vel[1] > 0) applyNormalImpulse(c, r, i, (vel[6] - vel[0]) / vel[1], vel[2], vel[3]);
  if (use1) {
    const target = vel[13];
    loadVelocity(c, r, i + 1, 7, false);
    if (vel[8] > 0) applyNormalImpulse(c, r, i + 1, (target - vel[7]) / vel[8], vel[9], vel[10]);
  }
}

/** A point's feature key: its two body slots (B −1, the world, as 2²² − 1) and the manifold's feature bits. */
export function anchorKey(bodyA: number, bodyB: number, feature: number): number {
  return ((bodyA * 4194304 + (bodyB < 0 ? 4194303 : bodyB)) * 65536 + feature) % 9007199254740991;
}

/**
 * Last step's friction anchors by feature key (Box2D keeps impulses by feature id for warm starting; a position-based
 * solver keeps the material points instead). A point found again next step starts from the anchors it held, moved
 * by what it slid, so static friction holds a resting body where it first touched and creep cannot accumulate from
 * step to step; anchors more than `reach` from the fresh contact (the bodies moved) are dropped.
 */
export class RigidAnchorCache {
  private readonly table = new KeyTable();
  private rA = new Float64Array(64);
  private rB = new Float64Array(64);

  /** Remembers the anchors of every point that acted and of rigid, particle or world B (not particle edges). */
  store(c: RigidContacts, r: BodyRows): void {
    this.table.reset(c.count);
    if (this.rA.length < 2 * c.count) {
      this.rA = new Float64Array(4 * c.count);
      this.rB = new Float64Array(4 * c.count);
    }
    let n = 0;
    for (let i = 0; i < c.count; i++) {
      if (!c.touched[i] || c.b2[i] >= 0) continue;
      const slot = this.table.insert(c.feature[i], n);
      if (this.table.values[slot] !== n) continue;
      // B's anchor moves along the tangent by what slid this step: that much is no longer held back.
      const tx = -c.ny[i];
      const ty = c.nx[i];
      const ib = c.b[i];
      let bx = c.rBx[i];
      let by = c.rBy[i];
      if (ib >= 0) {
        const cb = r.rc[ib];
        const sb = r.rs[ib];
        bx = r.x[ib] + cb * c.rBx[i] - sb * c.rBy[i];
        by = r.y[ib] + sb * c.rBx[i] + cb * c.rBy[i];
      }
      bx += c.slip[i] * tx;
      by += c.slip[i] * ty;
      if (ib >= 0) {
        const cb = r.rc[ib];
        const sb = r.rs[ib];
        const dx = bx - r.x[ib];
        const dy = by - r.y[ib];
        bx = cb * dx + sb * dy;
        by = -sb * dx + cb * dy;
      }
      this.rA[2 * n] = c.rAx[i];
      this.rA[2 * n + 1] = c.rAy[i];
      this.rB[2 * n] = bx;
      this.rB[2 * n + 1] = by;
      n++;
    }
  }

  /** Gives each new point the anchors its feature held last step, when they are within `reach` of the fresh ones. */
  restore(c: RigidContacts, reach: number): void {
    const reach2 = reach * reach;
    for (let i = 0; i < c.count; i++) {
      if (c.b2[i] >= 0) continue;
      const slot = this.table.find(c.feature[i]);
      if (slot < 0) continue;
      const k = this.table.values[slot];
      const dax = this.rA[2 * k] - c.rAx[i];
      const day = this.rA[2 * k + 1] - c.rAy[i];
      if (dax * dax + day * day > reach2) continue;
      const dbx = this.rB[2 * k] - c.rBx[i];
      const dby = this.rB[2 * k + 1] - c.rBy[i];
      if (dbx * dbx + dby * dby > reach2) continue;
      c.rAx[i] = this.rA[2 * k];
      c.rAy[i] = this.rA[2 * k + 1];
      c.rBx[i] = this.rB[2 * k];
      c.rBy[i] = this.rB[2 * k + 1];
    }
  }

  snapshot(): { keys: Float64Array; values: Float64Array; rA: Float64Array; rB: Float64Array } {
    return { ...this.table.snapshot(), rA: this.rA.slice(), rB: this.rB.slice() };
  }

  restoreSnapshot(s: { keys: Float64Array; values: Float64Array; rA: Float64Array; rB: Float64Array }): void {
    this.table.restore(s);
    this.rA = s.rA.slice();
    this.rB = s.rB.slice();
  }
}
