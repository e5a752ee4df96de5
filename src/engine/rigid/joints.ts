import { JointKind, type Joints } from './joint-table.js';
import { MAX_TURN, spin, turnBySpin, type BodyRows } from './rows.js';
import { inJointTree, solveJointTrees } from './joint-tree.js';

/**
 * The factor that keeps a sweep correction's turn of either body within MAX_TURN (half a radian, what a substep's
 * integration allows): a linearised correction that turns a body further is no longer near the answer, and among
 * masses and levers far apart (a tiny body welded on a long lever between heavy ones) such corrections overshoot,
 * each more than the last. Scaled down, both bodies' moves by the same factor, the correction keeps its direction and
 * momentum, and the next sweeps finish it. In random tangles of sliders (masses 10⁶ apart, anchors up to 3 sizes
 * off) speeds ran away in 36 of 60, now 20; of welds 17, then 2 (before welds joined the trees of joint-tree.ts).
 */
function withinTurn(turnA: number, turnB: number): number {
  const t = Math.max(Math.abs(turnA), Math.abs(turnB));
  return t > MAX_TURN ? MAX_TURN / t : 1;
}

/** World lever arms and points of the joint being solved: [lAx, lAy, pAx, pAy, lBx, lBy, pBx, pBy]. */
const at = new Float64Array(8);

function loadAnchors(j: Joints, r: BodyRows, i: number): void {
  const a = j.a[i];
  const ca = r.rc[a];
  const sa = r.rs[a];
  const lax = ca * j.rAx[i] - sa * j.rAy[i];
  const lay = sa * j.rAx[i] + ca * j.rAy[i];
  at[0] = lax;
  at[1] = lay;
  at[2] = r.x[a] + lax;
  at[3] = r.y[a] + lay;
  const b = j.b[i];
  if (b < 0) {
    at[4] = at[5] = 0;
    at[6] = j.rBx[i];
    at[7] = j.rBy[i];
    return;
  }
  const cb = r.rc[b];
  const sb = r.rs[b];
  const lbx = cb * j.rBx[i] - sb * j.rBy[i];
  const lby = sb * j.rBx[i] + cb * j.rBy[i];
  at[4] = lbx;
  at[5] = lby;
  at[6] = r.x[b] + lbx;
  at[7] = r.y[b] + lby;
}

/**
 * The reals of the correction being made (a typed array: V8 boxes a double passed to a call it does not inline, and
 * joints are solved every substep): [error c, nx, ny, α̃, γ, rate of change, h].
 */
const arg = new Float64Array(7);

/** What turnRow() turns a row by, times its inverse inertia (a typed array, like arg). */
const by = new Float64Array(1);

/** The relative angle correctWeld() holds, past the joint's refAngle: 0 for a weld, a limit's bound for a revolute. */
const weldAngle = new Float64Array(1);

/** Turns row i (−1: the world, which does not turn) by sign × by[0] × its inverse inertia. */
function turnRow(r: BodyRows, i: number, sign: number): void {
  if (i < 0) return;
  const iI = r.invInertia[i];
  if (iI === 0) return;
  spin[0] = sign * iI * by[0];
  turnBySpin(r, i);
}

/** Lever arms at the substep's start pose: [sAx, sAy, sBx, sBy]. */
const start = new Float64Array(4);

/** Loads start[] for joint i: each anchor turned by its body's angle at the start of the substep. */
function loadStartLevers(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  const ta = r.pangle[a];
  const ca = Math.cos(ta);
  const sa = Math.sin(ta);
  start[0] = ca * j.rAx[i] - sa * j.rAy[i];
  start[1] = sa * j.rAx[i] + ca * j.rAy[i];
  if (b < 0) {
    start[2] = start[3] = 0;
    return;
  }
  const tb = r.pangle[b];
  const cb = Math.cos(tb);
  const sb = Math.sin(tb);
  start[2] = cb * j.rBx[i] - sb * j.rBy[i];
  start[3] = sb * j.rBx[i] + cb * j.rBy[i];
}

/** The unit direction a distance correction acts along when it acts from the start pose (see correct()). */
const startDir = new Float64Array(2);

/**
 * How far the effective inverse mass through the start levers (SHAKE's) may stray from the one at the current pose,
 * as a fraction of the latter, before a distance correction acts along the current gradient instead. Where a body on
 * an off-centre anchor turns fast with its lever nearly across the rod, the two disagree and the start levers'
 * correction overshoots: of 200 random boxes hung by off-centre rods, 37 gained over 1% of their drop energy in 10 s
 * (one 63%); with this bound none gains over 0.08%, at a median loss of 6% (such a body whips through near-singular
 * poses that 6 substeps do not resolve). Where the levers agree (a bob at the rod's end, a plank hung by two rods)
 * nothing changes and SHAKE keeps the swing's energy.
 */
const SHAKE_AGREEMENT = 0.02;

/**
 * A positional correction of error arg[0] along unit (arg[1], arg[2]) (c > 0: A's anchor is ahead of B's along n),
 * with compliance α̃ = arg[3] and XPBD damping γ = arg[4] of the rate arg[5]: A moves back along n, B forward.
 * `fromStart`: the correction acts along startDir through the start levers start[] (SHAKE, as in correctPoint()),
 * the error still measured along n now: w = Σ 1/m·(n·s) + 1/I·(l × n)(s_l × s), unless that w strays from the
 * current pose's by more than SHAKE_AGREEMENT.
 */
function correct(j: Joints, r: BodyRows, i: number, fromStart: boolean): void {
  const a = j.a[i];
  const b = j.b[i];
  const nx = arg[1];
  const ny = arg[2];
  const alphaT = arg[3];
  const gamma = arg[4];
  const mA = r.invMass[a];
  const mB = b < 0 ? 0 : r.invMass[b];
  const iA = r.invInertia[a];
  const iB = b < 0 ? 0 : r.invInertia[b];
  const rnA = at[0] * ny - at[1] * nx;
  const rnB = at[4] * ny - at[5] * nx;
  let sx = nx;
  let sy = ny;
  let rsA = rnA;
  let rsB = rnB;
  let w = mA + iA * rnA * rnA + mB + iB * rnB * rnB;
  if (fromStart) {
    const along = nx * startDir[0] + ny * startDir[1];
    const startA = start[0] * startDir[1] - start[1] * startDir[0];
    const startB = start[2] * startDir[1] - start[3] * startDir[0];
    const wStart = (mA + mB) * along + iA * rnA * startA + iB * rnB * startB;
    if (Math.abs(wStart - w) <= SHAKE_AGREEMENT * w) {
      sx = startDir[0];
      sy = startDir[1];
      rsA = startA;
      rsB = startB;
      w = wStart;
    }
  }
  if (!(w > 0)) return;
  const rhs = -arg[0] - alphaT * j.lambda[i] - gamma * arg[5];
  let dl = rhs / ((1 + gamma) * w + alphaT);
  // Past MAX_TURN: scaled down to it, the rest of the error closed by moving the bodies alone (as in correctPoint).
  const f = withinTurn(iA * rsA * dl, iB * rsB * dl);
  dl *= f;
  const move = dl + (mA + mB > 0 ? ((1 - f) * rhs) / ((1 + gamma) * (mA + mB) + alphaT) : 0);
  j.lambda[i] += move;
  r.x[a] += mA * move * sx;
  r.y[a] += mA * move * sy;
  by[0] = rsA * dl;
  turnRow(r, a, 1);
  if (b < 0) return;
  r.x[b] -= mB * move * sx;
  r.y[b] -= mB * move * sy;
  by[0] = rsB * dl;
  turnRow(r, b, -1);
}

/**
 * Makes the two anchors meet: the 2×2 system of both directions at once (Box2D's revolute point constraint),
 * (K + α̃)·Δλ = −Δ − α̃·λ. Projected along the error direction alone, a light body on a long lever (a pendulum's bob)
 * would turn instead of swing and the anchors would part.
 *
 * The correction acts through the levers of the substep's start pose (s), while the error it cancels is measured at
 * the current pose (l): K = Σ 1/m·I + 1/I·l⊥ s⊥ᵀ. That is SHAKE's choice (the constraint force along the gradient at
 * the start of the step) instead of projecting along the gradient at the predicted pose: projecting at the predicted
 * pose takes O(h²) energy from a swinging body every substep, so a pendulum lost 11% of its amplitude in 10 s at 6
 * substeps (3.5% at 20); along the start gradient it keeps it (the test measures both).
 */
function correctPoint(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  const alphaT = arg[3];
  const ex = at[2] - at[6];
  const ey = at[3] - at[7];
  if (ex === 0 && ey === 0 && alphaT === 0) return;
  loadStartLevers(j, r, i, a, b);
  const mA = r.invMass[a];
  const iA = r.invInertia[a];
  const lax = at[0];
  const lay = at[1];
  const sax = start[0];
  const say = start[1];
  let k11 = mA + iA * lay * say + alphaT;
  let k12 = -iA * lay * sax;
  let k21 = -iA * lax * say;
  let k22 = mA + iA * lax * sax + alphaT;
  let mB = 0;
  let iB = 0;
  const sbx = start[2];
  const sby = start[3];
  if (b >= 0) {
    const lbx = at[4];
    const lby = at[5];
    mB = r.invMass[b];
    iB = r.invInertia[b];
    k11 += mB + iB * lby * sby;
    k12 -= iB * lby * sbx;
    k21 -= iB * lbx * sby;
    k22 += mB + iB * lbx * sbx;
  }
  const det = k11 * k22 - k12 * k21;
  if (!(det > 0)) return;
  const rx = -ex - alphaT * j.lambda[i];
  const ry = -ey - alphaT * j.lambdaY[i];
  let px = (k22 * rx - k12 * ry) / det;
  let py = (k11 * ry - k21 * rx) / det;
  // A correction that would turn a body past MAX_TURN (anchors far apart after a hard hit) is scaled down to it, and
  // what that leaves of the gap is closed by moving the bodies alone. Scaled down alone, it left most of the gap
  // each substep, and the velocity that made swung the body through its pivot and back, further each time: of 300
  // random hits by boxes 1-200 times heavier on a box hinged to the world, one threw it at 1,200 units/s and four
  // with a motor (not solved with the trees) at up to 34,000, one 4,900 units from its pivot; now none passes 520,
  // and the pivot opens 0.88 instead of 1.22 at the 90th percentile (0.90 instead of 1.26 with the motor).
  const f = withinTurn(iA * (sax * py - say * px), iB * (sbx * py - sby * px));
  const t = mA + mB > 0 ? (1 - f) / (mA + mB + alphaT) : 0;
  const turnA = f * (sax * py - say * px);
  const turnB = f * (sbx * py - sby * px);
  px = f * px + t * rx;
  py = f * py + t * ry;
  j.lambda[i] += px;
  j.lambdaY[i] += py;
  r.x[a] += mA * px;
  r.y[a] += mA * py;
  by[0] = turnA;
  turnRow(r, a, 1);
  if (b >= 0) {
    r.x[b] -= mB * px;
    r.y[b] -= mB * py;
    by[0] = turnB;
    turnRow(r, b, -1);
  }
}

/**
 * A weld as one 3×3 system (Box2D's weld joint): the anchors meet and the relative angle is the rest angle, both at
 * once. Solved one after the other, on a long lever the angle's turn would throw the anchor far off and the point's
 * correction turn it back: the pair oscillates and can blow up.
 *   K = J(l)·M⁻¹·J(s)ᵀ with J(l) = [[1, 0, −ly], [0, 1, lx], [0, 0, 1]] per body,  K·Δλ = −(pA − pB, θA − θB − θrest)
 *   (point compliance α̃ on the first two diagonals). As in correctPoint, the correction acts through the levers s of
 *   the substep's start pose (SHAKE), the error measured at the current levers l: along the current levers a
 *   welded pair spinning free lost 31–46% of its energy in 10 s at 6 substeps.
 */
function correctWeld(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  const alphaT = arg[3];
  loadStartLevers(j, r, i, a, b);
  const mA = r.invMass[a];
  const iA = r.invInertia[a];
  const mB = b < 0 ? 0 : r.invMass[b];
  const iB = b < 0 ? 0 : r.invInertia[b];
  const lax = at[0];
  const lay = at[1];
  const lbx = at[4];
  const lby = at[5];
  const sax = start[0];
  const say = start[1];
  const sbx = start[2];
  const sby = start[3];
  // K = J(now)·M⁻¹·J(start)ᵀ: not symmetric once the levers have turned within the substep.
  const k11 = mA + mB + iA * lay * say + iB * lby * sby + alphaT;
  const k12 = -iA * lay * sax - iB * lby * sbx;
  const k13 = -iA * lay - iB * lby;
  const k21 = -iA * lax * say - iB * lbx * sby;
  const k22 = mA + mB + iA * lax * sax + iB * lbx * sbx + alphaT;
  const k23 = iA * lax + iB * lbx;
  const k31 = -iA * say - iB * sby;
  const k32 = iA * sax + iB * sbx;
  const k33 = iA + iB;
  const e1 = -(at[2] - at[6]) - alphaT * j.lambda[i];
  const e2 = -(at[3] - at[7]) - alphaT * j.lambdaY[i];
  const e3 = -(r.angle[a] - (b < 0 ? 0 : r.angle[b]) - j.refAngle[i] - weldAngle[0]);
  // Cramer's rule (no rotation freedom at all: fall back to the point alone).
  const c11 = k22 * k33 - k23 * k32;
  const c12 = k23 * k31 - k21 * k33;
  const c13 = k21 * k32 - k22 * k31;
  const det = k11 * c11 + k12 * c12 + k13 * c13;
  if (!(det > 1e-14 * k11 * k22 * Math.max(k33, 1e-300))) {
    correctPoint(j, r, i, a, b);
    return;
  }
  let px = (e1 * c11 + k12 * (k23 * e3 - e2 * k33) + k13 * (e2 * k32 - k22 * e3)) / det;
  let py = (k11 * (e2 * k33 - k23 * e3) + e1 * (k23 * k31 - k21 * k33) + k13 * (k21 * e3 - e2 * k31)) / det;
  let pt = (k11 * (k22 * e3 - e2 * k32) + k12 * (e2 * k31 - k21 * e3) + e1 * c13) / det;
  const f = withinTurn(iA * (sax * py - say * px + pt), iB * (sbx * py - sby * px + pt));
  px *= f;
  py *= f;
  pt *= f;
  j.lambda[i] += px;
  j.lambdaY[i] += py;
  r.x[a] += mA * px;
  r.y[a] += mA * py;
  by[0] = sax * py - say * px + pt;
  turnRow(r, a, 1);
  if (b < 0) return;
  r.x[b] -= mB * px;
  r.y[b] -= mB * py;
  by[0] = sbx * py - sby * px + pt;
  turnRow(r, b, -1);
}

/**
 * A limited revolute joint past a bound (anchors loaded): the point and the bound at once, as a weld at the bound.
 * False (nothing done) within its limits or without them.
 */
function holdLimit(j: Joints, r: BodyRows, i: number, a: number, b: number): boolean {
  if (j.limit[i] !== 1) return false;
  const rel = r.angle[a] - (b < 0 ? 0 : r.angle[b]) - j.refAngle[i];
  if (rel >= j.lower[i] && rel <= j.upper[i]) return false;
  weldAngle[0] = rel < j.lower[i] ? j.lower[i] : j.upper[i];
  correctWeld(j, r, i, a, b);
  return true;
}

/**
 * Per joint, this substep: 1 when it is a spring soft enough to act as a force (applySpringForces), which
 * solveJoints then leaves alone. Scratch, set at each substep's start.
 */
let springForce = new Uint8Array(16);

/** The largest k·h²·w and c·h·w of a spring acting as a force (w: its effective inverse mass along its line). */
const EXPLICIT_STIFFNESS = 0.1;
const EXPLICIT_DAMPING = 0.2;

/** Whether any joint is a spring (a compliant distance joint): the substeps then compute accelerations each time. */
export function hasSprings(j: Joints): boolean {
  for (let i = 0, n = j.count; i < n; i++) if (j.compliance[i] > 0) return true;
  return false;
}

/**
 * Springs soft enough for an explicit step (k·h²·w ≤ 0.1, c·h·w ≤ 0.2, w the effective inverse mass of its two
 * anchors along its line) act as forces: Hooke's k·(stretch) plus c·(stretch speed), into the rows' accelerations and,
 * as a turn of the spin, their torques, before the substep moves them (symplectic Euler: an undamped spring keeps its
 * energy). As XPBD compliant constraints, an implicit step, they lost amplitude at about k·h/(2m) a second: a spring
 * of k = 1000 on a mass of 1 kept 5% of its swing after 2 s. Stiffer springs stay constraints (stable at any k).
 */
export function applySpringForces(j: Joints, r: BodyRows, ax: Float64Array, ay: Float64Array, h: number): void {
  if (springForce.length < j.count) springForce = new Uint8Array(j.a.length);
  const { invMass, invInertia, vx, vy, omega } = r;
  for (let i = 0, n = j.count; i < n; i++) {
    springForce[i] = 0;
    if (!(j.compliance[i] > 0)) continue;
    loadAnchors(j, r, i);
    const dx = at[2] - at[6];
    const dy = at[3] - at[7];
    const len = Math.sqrt(dx * dx + dy * dy);
    if (len < 1e-12) continue;
    const nx = dx / len;
    const ny = dy / len;
    const a = j.a[i];
    const b = j.b[i];
    // The effective inverse mass along n: each side's 1/m + (lever × n)²/I.
    const crossA = at[0] * ny - at[1] * nx;
    let w = invMass[a] + invInertia[a] * crossA * crossA;
    const crossB = at[4] * ny - at[5] * nx;
    if (b >= 0) w += invMass[b] + invInertia[b] * crossB * crossB;
    const k = 1 / j.compliance[i];
    const c = j.damping[i];
    if (k * h * h * w > EXPLICIT_STIFFNESS || c * h * w > EXPLICIT_DAMPING) continue;
    springForce[i] = 1;
    const stretch = len < j.lower[i] ? len - j.lower[i] : len > j.upper[i] ? len - j.upper[i] : 0;
    // The rate the length changes at: A's anchor's velocity minus B's, along n (an anchor's velocity v + ω × lever).
    let rate = (vx[a] - omega[a] * at[1]) * nx + (vy[a] + omega[a] * at[0]) * ny;
    if (b >= 0) rate -= (vx[b] - omega[b] * at[5]) * nx + (vy[b] + omega[b] * at[4]) * ny;
    // On A, towards B when stretched (and against the stretching); on B the opposite.
    const f = -(k * stretch + c * rate);
    ax[a] += f * nx * invMass[a];
    ay[a] += f * ny * invMass[a];
    omega[a] += h * f * crossA * invInertia[a];
    if (b >= 0) {
      ax[b] -= f * nx * invMass[b];
      ay[b] -= f * ny * invMass[b];
      omega[b] -= h * f * crossB * invInertia[b];
    }
  }
}

/**
 * The row joint i holds as the ground holds it, or −1: a rigid weld (compliance 0) between a row that moves and one
 * that does not (the world, a static or kinematic row) leaves the first no freedom at all.
 */
export function weldHeld(j: Joints, r: BodyRows, i: number): number {
  if ((j.kind[i] as JointKind) !== JointKind.Weld || j.compliance[i] !== 0) return -1;
  const a = j.a[i];
  const b = j.b[i];
  const fixedA = r.invMass[a] === 0 && r.invInertia[a] === 0;
  const fixedB = b < 0 || (r.invMass[b] === 0 && r.invInertia[b] === 0);
  return fixedA === fixedB ? -1 : fixedA ? b : a;
}

/**
 * Each row a weld holds (weldHeld) set to the very pose the weld gives it. Before the shock sweep, which then moves
 * only what hits it (pipeline/step.ts): solved as a joint, the pose a contact had just pushed it from came back only
 * part of the way (the linearised solve, MAX_TURN), and a box welded to the world, hit by one 20 times heavier, gave
 * way 0.08 and swung back over ten steps.
 */
export function holdWelded(j: Joints, r: BodyRows): void {
  for (let i = 0; i < j.count; i++) {
    const held = weldHeld(j, r, i);
    if (held < 0) continue;
    loadAnchors(j, r, i);
    // θA − θB = refAngle; the held side's anchor goes onto the other's.
    const isA = held === j.a[i];
    const other = isA ? j.b[i] : j.a[i];
    spin[0] = (other < 0 ? 0 : r.angle[other]) + (isA ? j.refAngle[i] : -j.refAngle[i]) - r.angle[held];
    turnBySpin(r, held);
    loadAnchors(j, r, i);
    r.x[held] += isA ? at[6] - at[2] : at[2] - at[6];
    r.y[held] += isA ? at[7] - at[3] : at[3] - at[7];
  }
}

/** One Gauss–Seidel sweep over the joints (before the contacts, each substep). */
export function solveJoints(j: Joints, r: BodyRows, h: number): void {
  const h2 = h * h;
  arg[6] = h;
  // The revolute joints' points over the trees they form, at once; the sweep does the rest.
  const trees = solveJointTrees(j, r, h);
  for (let i = 0, n = j.count; i < n; i++) {
    const kind = j.kind[i] as JointKind;
    const a = j.a[i];
    const b = j.b[i];
    const alphaT = j.compliance[i] / h2;
    arg[3] = alphaT;
    arg[4] = 0;
    arg[5] = 0;
    if (kind === JointKind.Prismatic) {
      solvePrismatic(j, r, i, a, b);
      continue;
    }
    if (kind === JointKind.Weld) {
      if (trees && inJointTree(i)) continue;
      loadAnchors(j, r, i);
      weldAngle[0] = 0;
      correctWeld(j, r, i, a, b);
      continue;
    }
    if (kind === JointKind.Revolute) {
      if (trees && j.limit[i] === 0 && j.motor[i] === 0 && inJointTree(i)) continue;
      // Past a limit: the point and the bound at once, as a weld at the bound. One after the other, the angle's turn
      // about the centre of mass left the centre moving, and the point turned that back into spin: a rod pivoted at
      // its end rebounded from its limit at 0.42 of its speed. Then the motor: before the point, the point's turn
      // undid part of it every substep, and a motor held no load (a rod pivoted at its end sagged at 0.075 rad/s under
      // gravity whatever its torque, and a 1 rad/s motor ran at 0.89-1.08).
      loadAnchors(j, r, i);
      if (!holdLimit(j, r, i, a, b)) correctPoint(j, r, i, a, b);
      if (j.motor[i] === 1) {
        solveMotor(j, r, i, a, b);
        // A motor driving into its limit (a flipper) turned it past the bound and off its pivot: the limit has the
        // last word.
        if (j.limit[i] === 1) {
          loadAnchors(j, r, i);
          holdLimit(j, r, i, a, b);
        }
      }
      continue;
    }
    // Distance: only outside [lower, upper]; a soft one is a damped spring (a force this substep, if soft enough).
    // The flag is read only for a spring: applySpringForces sets every joint's each substep while any spring exists,
    // and a rigid joint taking a removed spring's row must not see the flag left from then.
    if (j.compliance[i] > 0 && springForce[i] === 1) continue;
    loadAnchors(j, r, i);
    const dx = at[2] - at[6];
    const dy = at[3] - at[7];
    const len = Math.sqrt(dx * dx + dy * dy);
    if (len < 1e-12) continue;
    const c = len < j.lower[i] ? len - j.lower[i] : len > j.upper[i] ? len - j.upper[i] : 0;
    if (c === 0 && alphaT === 0) continue;
    const nx = dx / len;
    const ny = dy / len;
    arg[0] = c;
    arg[1] = nx;
    arg[2] = ny;
    // XPBD damping (Macklin et al. 2016): γ = α̃·β̃/h with β̃ = h²·β, and the constraint's rate of change this substep:
    // how far the two anchors moved apart along n (A's motion minus B's, each its centre's plus its turn × lever).
    if (j.damping[i] > 0 && alphaT > 0) {
      arg[4] = (j.compliance[i] * j.damping[i]) / h;
      const tA = r.angle[a] - r.pangle[a];
      let rate = (r.x[a] - r.px[a] - tA * at[1]) * nx + (r.y[a] - r.py[a] + tA * at[0]) * ny;
      if (b >= 0) {
        const tB = r.angle[b] - r.pangle[b];
        rate -= (r.x[b] - r.px[b] - tB * at[5]) * nx + (r.y[b] - r.py[b] + tB * at[4]) * ny;
      }
      arg[5] = rate;
    }
    // Along the anchors' direction at the substep's start pose, where it is defined and within 60° of today's.
    loadStartLevers(j, r, i, a, b);
    const sdx = r.px[a] + start[0] - (b < 0 ? j.rBx[i] : r.px[b] + start[2]);
    const sdy = r.py[a] + start[1] - (b < 0 ? j.rBy[i] : r.py[b] + start[3]);
    const slen = Math.sqrt(sdx * sdx + sdy * sdy);
    const fromStart = slen > 1e-12 && sdx * nx + sdy * ny > 0.5 * slen;
    if (fromStart) {
      startDir[0] = sdx / slen;
      startDir[1] = sdy / slen;
    }
    correct(j, r, i, fromStart);
  }
}

/**
 * A motor turns A relative to B at `motorSpeed`: this substep's relative turn should be h·speed. The correction is
 * capped at the torque limit (|λ| ≤ τmax·h² over the substep).
 */
function solveMotor(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  const h = arg[6];
  const turned = r.angle[a] - r.pangle[a] - (b < 0 ? 0 : r.angle[b] - r.pangle[b]);
  const e = turned - h * j.motorSpeed[i];
  const iA = r.invInertia[a];
  const iB = b < 0 ? 0 : r.invInertia[b];
  const w = iA + iB;
  if (w === 0) return;
  const cap = j.maxMotorTorque[i] * h * h;
  const before = j.lambdaMotor[i];
  let total = before - e / w;
  if (total > cap) total = cap;
  else if (total < -cap) total = -cap;
  const dl = total - before;
  j.lambdaMotor[i] = total;
  by[0] = dl;
  turnRow(r, a, 1);
  turnRow(r, b, -1);
}

/** Prismatic: no relative turn, B's anchor on A's axis line, and within [lower, upper] along it when limited. */
function solvePrismatic(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  loadAnchors(j, r, i);
  const mA = r.invMass[a];
  const iA = r.invInertia[a];
  const mB = b < 0 ? 0 : r.invMass[b];
  const iB = b < 0 ? 0 : r.invInertia[b];
  // Held by what does not move with it (the world, a static or kinematic B), the axis is B's: where A's turns to when
  // the angle lock holds. Turning with A, the axis swept B's anchor across it from `along` away, every turn a hit
  // gave A: a box on a slider to the world, hit by one 170 times heavier, was thrown 10⁸ units.
  const heldByB = mB === 0 && iB === 0;
  const ca = heldByB ? Math.cos((b < 0 ? 0 : r.angle[b]) + j.refAngle[i]) : r.rc[a];
  const sa = heldByB ? Math.sin((b < 0 ? 0 : r.angle[b]) + j.refAngle[i]) : r.rs[a];
  const ux = ca * j.axisX[i] - sa * j.axisY[i];
  const uy = sa * j.axisX[i] + ca * j.axisY[i];
  // Across the axis (p = (−uy, ux)) and the relative angle together, as a 2×2 system like the weld's: A's anchor
  // minus B's, across the axis, goes to 0, and so does θA − θB − θrest. (The axis turning with A is left out of the
  // gradient, as usual for prismatic joints; the angle lock keeps that turn small.)
  const px = -uy;
  const py = ux;
  const e1 = -((at[2] - at[6]) * px + (at[3] - at[7]) * py);
  const e2 = -(r.angle[a] - (b < 0 ? 0 : r.angle[b]) - j.refAngle[i]);
  // The push across the axis acts where B's anchor is, for A too (Box2D's d + rA): A's anchor sits `along` the axis
  // from there, and a lever to A's own anchor gave each correction a torque of about along · l1, which fed energy
  // into two free bodies until they blew up. An axis held by B does not turn with A: A's own lever.
  const rA = heldByB ? at[0] * py - at[1] * px : (at[0] + at[6] - at[2]) * py - (at[1] + at[7] - at[3]) * px;
  const rB = at[4] * py - at[5] * px;
  const k11 = mA + mB + iA * rA * rA + iB * rB * rB;
  const k12 = iA * rA + iB * rB;
  const k22 = iA + iB;
  const det = k11 * k22 - k12 * k12;
  let l1 = 0;
  let l2 = 0;
  if (det > 1e-12 * k11 * Math.max(k22, 1e-300)) {
    l1 = (k22 * e1 - k12 * e2) / det;
    l2 = (k11 * e2 - k12 * e1) / det;
  } else if (k11 > 0) l1 = e1 / k11;
  const f = withinTurn(iA * (rA * l1 + l2), iB * (rB * l1 + l2));
  l1 *= f;
  l2 *= f;
  // What the scaled-down correction leaves across the axis: closed by moving the bodies alone (as in correctPoint).
  const move = l1 + (mA + mB > 0 ? ((1 - f) * e1) / (mA + mB) : 0);
  r.x[a] += mA * move * px;
  r.y[a] += mA * move * py;
  by[0] = rA * l1 + l2;
  turnRow(r, a, 1);
  if (b >= 0) {
    r.x[b] -= mB * move * px;
    r.y[b] -= mB * move * py;
    by[0] = rB * l1 + l2;
    turnRow(r, b, -1);
  }
  if (j.limit[i] !== 1) return;
  loadAnchors(j, r, i);
  // Translation of B's anchor along the axis from A's, pushed back within [lower, upper].
  const along = (at[6] - at[2]) * ux + (at[7] - at[3]) * uy;
  arg[0] = along < j.lower[i] ? along - j.lower[i] : along > j.upper[i] ? along - j.upper[i] : 0;
  arg[1] = -ux;
  arg[2] = -uy;
  // Held by a side that does not move, the other is pushed back through its centre: the angle lock has just set its
  // turn, and a push at its anchor turned it off again (300 random hits by bodies up to 200 times heavier passed the
  // limit by 0.072 at the median and 1.05 at the 90th percentile; now 0.033 and 0.46).
  if (heldByB || (mA === 0 && iA === 0)) at[0] = at[1] = at[4] = at[5] = 0;
  if (arg[0] !== 0) correct(j, r, i, false);
}
