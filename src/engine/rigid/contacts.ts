import { Table } from '../table.js';
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
    'slip', 'allowance', 'approach', 'touched', 'pair', 'bodyA', 'bodyB', 'depth',
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

  /**
   * The next point's reals, written by the caller before add(): nx, ny, rAx, rAy, rBx, rBy, radA, radB, alpha,
   * friction, restitution, depth. (An array rather than arguments: doubles passed to a call that is not inlined are
   * boxed, and the narrow phase adds thousands of points a step.)
   */
  readonly next = new Float64Array(12);

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
    this.slip[i] = 0;
    this.approach[i] = NaN;
    this.touched[i] = 0;
    this.pair[i] = pair;
    this.bodyA[i] = bodyA;
    this.bodyB[i] = bodyB;
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

/** One Gauss–Seidel sweep over the points: normal, then friction (positions). */
export function solveRigidContacts(c: RigidContacts, r: BodyRows): void {
  const { x, y, rc, rs, invMass, invInertia } = r;
  const { nx: NX, ny: NY, rAx, rAy, radA, allowance, lambdaN, lambdaT, slip, friction, touched, approach, restitution } = c;
  for (let i = 0, n = c.count; i < n; i++) {
    const ia = c.a[i];
    const nx = NX[i];
    const ny = NY[i];
    // A's material lever and normal lever (a round side pushes through its centre).
    let cs = rc[ia];
    let sn = rs[ia];
    let mAx = cs * rAx[i] - sn * rAy[i];
    let mAy = sn * rAx[i] + cs * rAy[i];
    const ra = radA[i];
    const lAx = ra > 0 ? nx * ra : mAx;
    const lAy = ra > 0 ? ny * ra : mAy;
    loadB(c, r, i, nx, ny);
    const d = (x[ia] + lAx - side[0]) * nx + (y[ia] + lAy - side[1]) * ny - allowance[i];
    if (d <= 0) continue;
    if (touched[i] === 0) {
      touched[i] = 1;
      // Approach speed for restitution, from the velocities before this substep's corrections.
      if (restitution[i] > 0 && approach[i] !== approach[i]) approach[i] = relativeNormalSpeed(c, r, i, ia, lAx, lAy, nx, ny);
    }
    const imA = invMass[ia];
    const iIA = invInertia[ia];
    const rnA = lAx * ny - lAy * nx;
    const rnB = side[2] * ny - side[3] * nx;
    const w = imA + iIA * rnA * rnA + weightB(c, r, i, rnB);
    if (w === 0) continue;
    const dl = d / w;
    lambdaN[i] += dl;
    x[ia] -= imA * dl * nx;
    y[ia] -= imA * dl * ny;
    if (iIA !== 0) turn(r, ia, -iIA * rnA * dl);
    pushB(c, r, i, dl, nx, ny, rnB);

    // Friction: the material points' tangential drift since the step began.
    const mu = friction[i];
    if (mu === 0) continue;
    cs = rc[ia];
    sn = rs[ia];
    mAx = cs * rAx[i] - sn * rAy[i];
    mAy = sn * rAx[i] + cs * rAy[i];
    loadB(c, r, i, nx, ny);
    const tx = -ny;
    const ty = nx;
    const drift = (x[ia] + mAx - side[4]) * tx + (y[ia] + mAy - side[5]) * ty - slip[i];
    const rtA = mAx * ty - mAy * tx;
    const rtB = side[6] * ty - side[7] * tx;
    const wt = imA + iIA * rtA * rtA + weightB(c, r, i, rtB);
    if (wt === 0) continue;
    const want = drift / wt;
    const limit = mu * lambdaN[i];
    const before = lambdaT[i];
    let total = before + want;
    if (total > limit) total = limit;
    else if (total < -limit) total = -limit;
    const dt = total - before;
    lambdaT[i] = total;
    // What friction could not hold has slid: the anchors follow it.
    slip[i] += (want - dt) * wt;
    x[ia] -= imA * dt * tx;
    y[ia] -= imA * dt * ty;
    if (iIA !== 0) turn(r, ia, -iIA * rtA * dt);
    pushB(c, r, i, dt, tx, ty, rtB);
  }
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
 * (which uses up a pending bounce); false when the point did not act this substep.
 */
function loadVelocity(c: RigidContacts, r: BodyRows, i: number, o: number, withTarget: boolean): boolean {
  if (c.lambdaN[i] <= 0) return false;
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
  if (!withTarget) return true;
  // Target normal speed: bounce once per impact (approach recorded when the point first acted), else stop.
  let target = 0;
  const e = c.restitution[i];
  const approach = c.approach[i];
  if (e > 0 && approach < -BOUNCE_THRESHOLD) {
    target = -e * approach;
    c.approach[i] = 0;
  }
  vel[o + 6] = target;
  return true;
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
 * rotation they share, and a box dropped flat would bounce crooked.
 */
export function solveRigidContactVelocities(c: RigidContacts, r: BodyRows): void {
  const n = c.count;
  for (let i = 0; i < n; i++) {
    const first = loadVelocity(c, r, i, 0, true);
    if (c.pair[i] === 1 && c.b2[i] < 0 && c.b2[i + 1] < 0) {
      const second = loadVelocity(c, r, i + 1, 7, true);
      if (first && second) {
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
          const P0 = (k11 * b0 - k01 * b1) / det;
          const P1 = (k00 * b1 - k01 * b0) / det;
          applyNormalImpulse(c, r, i, P0, vel[2], vel[3]);
          applyNormalImpulse(c, r, i + 1, P1, vel[9], vel[10]);
          i++;
          continue;
        }
      }
      // One point acting (or the two are dependent): one after the other, the second's speed measured again after
      // the first's impulse (its target stays).
      if (first && vel[1] > 0) applyNormalImpulse(c, r, i, (vel[6] - vel[0]) / vel[1], vel[2], vel[3]);
      if (second && loadVelocity(c, r, i + 1, 7, false) && vel[8] > 0) applyNormalImpulse(c, r, i + 1, (vel[13] - vel[7]) / vel[8], vel[9], vel[10]);
      i++;
      continue;
    }
    if (first && vel[1] > 0) applyNormalImpulse(c, r, i, (vel[6] - vel[0]) / vel[1], vel[2], vel[3]);
  }
}
