import { Table } from '../table.js';
import { turn, type BodyRows } from './rows.js';

/** What a joint holds. */
export const enum JointKind {
  /** The two anchor points coincide; the bodies turn freely about them (angle limits and a motor optional). */
  Revolute = 0,
  /** The anchor points coincide and the relative angle is fixed. */
  Weld = 1,
  /** B slides along an axis fixed in A (translation limits optional); no relative rotation. */
  Prismatic = 2,
  /** The anchors' distance stays within [lower, upper] (rigid when equal), softly with compliance and damping. */
  Distance = 3,
}

export const JOINT_KINDS = ['revolute', 'weld', 'prismatic', 'distance'] as const;
export type JointType = (typeof JOINT_KINDS)[number];

/**
 * Joints between two rows (rigid bodies or particles; b = −1 is the world, its anchor a world point), solved as XPBD
 * positional and angular constraints at the anchors (Müller et al. 2020, §3.3–3.4):
 *   point:    Δλ = (−c − α̃λ) / (w_A + w_B + α̃),   w = 1/m + (r × n)²/I,   α̃ = compliance / h²
 *   angle:    Δλ = (−e − α̃λ) / (1/I_A + 1/I_B + α̃)
 * A motor advances its target angle by h·speed each substep and caps |λ| at the torque limit times h².
 */
export class Joints extends Table {
  readonly columns = [
    'kind', 'a', 'b', 'rAx', 'rAy', 'rBx', 'rBy', 'compliance', 'damping', 'refAngle', 'lower', 'upper', 'limit', 'motor', 'motorSpeed',
    'maxMotorTorque', 'axisX', 'axisY', 'lambda', 'lambdaY', 'lambdaAngle', 'lambdaMotor', 'slot', 'bodyA', 'bodyB', 'collide',
  ] as const;
  kind = new Uint8Array(16);
  a = new Int32Array(16);
  b = new Int32Array(16);
  /** Anchors in each body's frame (B's in world coordinates when b = −1). */
  rAx = new Float64Array(16);
  rAy = new Float64Array(16);
  rBx = new Float64Array(16);
  rBy = new Float64Array(16);
  /** Positional compliance (inverse stiffness); 0 = rigid. */
  compliance = new Float64Array(16);
  /** Damping coefficient of a soft distance joint (force per unit of relative speed along it). */
  damping = new Float64Array(16);
  /** Rest angle of A relative to B (θA − θB; B's angle is 0 for the world) for weld, prismatic and revolute limits. */
  refAngle = new Float64Array(16);
  /** Limits: relative angle (revolute), translation along the axis (prismatic), length (distance). */
  lower = new Float64Array(16);
  upper = new Float64Array(16);
  limit = new Uint8Array(16);
  motor = new Uint8Array(16);
  motorSpeed = new Float64Array(16);
  maxMotorTorque = new Float64Array(16);
  /** Prismatic axis in A's frame (unit). */
  axisX = new Float64Array(16);
  axisY = new Float64Array(16);
  /** Multipliers of this substep: distance (or the point's x) and the point's y, angle and motor. */
  lambda = new Float64Array(16);
  lambdaY = new Float64Array(16);
  lambdaAngle = new Float64Array(16);
  lambdaMotor = new Float64Array(16);
  /** Constraint registry slot (the handle's), and the body slots of the two sides (−1: world). */
  slot = new Int32Array(16);
  bodyA = new Int32Array(16);
  bodyB = new Int32Array(16);
  /** 1: the two bodies still collide with each other (by default jointed bodies do not). */
  collide = new Uint8Array(16);

  beginSubstep(): void {
    this.lambda.fill(0, 0, this.count);
    this.lambdaY.fill(0, 0, this.count);
    this.lambdaAngle.fill(0, 0, this.count);
    this.lambdaMotor.fill(0, 0, this.count);
  }
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

/** Generalised inverse mass of row i (−1: world) along a unit direction with lever cross product rn. */
function weight(r: BodyRows, i: number, rn: number): number {
  return i < 0 ? 0 : r.invMass[i] + r.invInertia[i] * rn * rn;
}

/** Moves row i (−1: world) by λ·(dx, dy) at a lever with cross product rn. */
function push(r: BodyRows, i: number, l: number, dx: number, dy: number, rn: number): void {
  if (i < 0) return;
  const m = r.invMass[i] * l;
  r.x[i] += m * dx;
  r.y[i] += m * dy;
  const iI = r.invInertia[i];
  if (iI !== 0) turn(r, i, iI * rn * l);
}

/**
 * A positional correction of error c along unit (nx, ny) (c > 0: A's anchor is ahead of B's along n), with the
 * joint's compliance and multiplier in `lambda`: A moves back along n, B forward. Returns nothing; the multiplier is
 * updated in place.
 */
function correct(j: Joints, r: BodyRows, i: number, c: number, nx: number, ny: number, alphaT: number, gamma: number, rate: number): void {
  const a = j.a[i];
  const b = j.b[i];
  const rnA = at[0] * ny - at[1] * nx;
  const rnB = at[4] * ny - at[5] * nx;
  const w = weight(r, a, rnA) + weight(r, b, rnB);
  if (w === 0) return;
  const dl = (-c - alphaT * j.lambda[i] - gamma * rate) / ((1 + gamma) * w + alphaT);
  j.lambda[i] += dl;
  push(r, a, dl, nx, ny, rnA);
  push(r, b, -dl, nx, ny, rnB);
}

/**
 * Makes the two anchors meet: the 2×2 effective-mass system of both directions at once (Box2D's revolute point
 * constraint), (K + α̃)·Δλ = −Δ − α̃·λ with K = Σ 1/m·I + 1/I·[r⊥ r⊥ᵀ]. Projected along the error direction alone, a
 * light body on a long lever (a pendulum's bob) would turn instead of swing and the anchors would part.
 */
function correctPoint(j: Joints, r: BodyRows, i: number, a: number, b: number, alphaT: number): void {
  const ex = at[2] - at[6];
  const ey = at[3] - at[7];
  if (ex === 0 && ey === 0 && alphaT === 0) return;
  const mA = r.invMass[a];
  const iA = r.invInertia[a];
  const lax = at[0];
  const lay = at[1];
  let k11 = mA + iA * lay * lay + alphaT;
  let k12 = -iA * lax * lay;
  let k22 = mA + iA * lax * lax + alphaT;
  let mB = 0;
  let iB = 0;
  const lbx = at[4];
  const lby = at[5];
  if (b >= 0) {
    mB = r.invMass[b];
    iB = r.invInertia[b];
    k11 += mB + iB * lby * lby;
    k12 -= iB * lbx * lby;
    k22 += mB + iB * lbx * lbx;
  }
  const det = k11 * k22 - k12 * k12;
  if (!(det > 0)) return;
  const rx = -ex - alphaT * j.lambda[i];
  const ry = -ey - alphaT * j.lambdaY[i];
  const px = (k22 * rx - k12 * ry) / det;
  const py = (k11 * ry - k12 * rx) / det;
  j.lambda[i] += px;
  j.lambdaY[i] += py;
  r.x[a] += mA * px;
  r.y[a] += mA * py;
  if (iA !== 0) turn(r, a, iA * (lax * py - lay * px));
  if (b >= 0) {
    r.x[b] -= mB * px;
    r.y[b] -= mB * py;
    if (iB !== 0) turn(r, b, -iB * (lbx * py - lby * px));
  }
}

/** Turns A and B so the relative angle θA − θB changes by −e (one-sided limits pass the violated bound). */
function correctAngle(r: BodyRows, a: number, b: number, e: number): void {
  const iA = r.invInertia[a];
  const iB = b < 0 ? 0 : r.invInertia[b];
  const w = iA + iB;
  if (w === 0) return;
  const dl = -e / w;
  if (iA !== 0) turn(r, a, iA * dl);
  if (iB !== 0) turn(r, b, -iB * dl);
}

/** Relative angle θA − θB (the world's angle is 0). */
function relativeAngle(r: BodyRows, a: number, b: number): number {
  return r.angle[a] - (b < 0 ? 0 : r.angle[b]);
}

/** One Gauss–Seidel sweep over the joints (before the contacts, each substep). */
export function solveJoints(j: Joints, r: BodyRows, h: number): void {
  const h2 = h * h;
  for (let i = 0, n = j.count; i < n; i++) {
    const kind = j.kind[i] as JointKind;
    const a = j.a[i];
    const b = j.b[i];
    const alphaT = j.compliance[i] / h2;
    if (kind === JointKind.Prismatic) {
      solvePrismatic(j, r, i, a, b);
      continue;
    }
    if (kind === JointKind.Revolute || kind === JointKind.Weld) {
      // Angle first (weld lock, revolute limits and motor), then the point, which the angle's turn moved.
      if (kind === JointKind.Weld) {
        correctAngle(r, a, b, relativeAngle(r, a, b) - j.refAngle[i]);
      } else {
        if (j.motor[i] === 1) solveMotor(j, r, i, a, b, h);
        if (j.limit[i] === 1) {
          const rel = relativeAngle(r, a, b) - j.refAngle[i];
          if (rel < j.lower[i]) correctAngle(r, a, b, rel - j.lower[i]);
          else if (rel > j.upper[i]) correctAngle(r, a, b, rel - j.upper[i]);
        }
      }
      loadAnchors(j, r, i);
      correctPoint(j, r, i, a, b, alphaT);
      continue;
    }
    // Distance: only outside [lower, upper]; a soft one is a damped spring.
    loadAnchors(j, r, i);
    const dx = at[2] - at[6];
    const dy = at[3] - at[7];
    const len = Math.sqrt(dx * dx + dy * dy);
    if (len < 1e-12) continue;
    const c = len < j.lower[i] ? len - j.lower[i] : len > j.upper[i] ? len - j.upper[i] : 0;
    if (c === 0 && alphaT === 0) continue;
    const nx = dx / len;
    const ny = dy / len;
    // XPBD damping (Macklin et al. 2016): γ = α̃·β̃/h with β̃ = h²·β, and the constraint's rate of change this substep.
    let gamma = 0;
    let rate = 0;
    if (j.damping[i] > 0 && alphaT > 0) {
      gamma = (j.compliance[i] * j.damping[i]) / h;
      rate = anchorMotion(r, a, 0, nx, ny) - anchorMotion(r, b, 4, nx, ny);
    }
    correct(j, r, i, c, nx, ny, alphaT, gamma, rate);
  }
}

/** How far row i's anchor (lever at[o], at[o+1]) moved along (nx, ny) in this substep so far. */
function anchorMotion(r: BodyRows, i: number, o: number, nx: number, ny: number): number {
  if (i < 0) return 0;
  const dθ = r.angle[i] - r.pangle[i];
  const mx = r.x[i] - r.px[i] - dθ * at[o + 1];
  const my = r.y[i] - r.py[i] + dθ * at[o];
  return mx * nx + my * ny;
}

/**
 * A motor turns A relative to B at `motorSpeed`: this substep's relative turn should be h·speed. The correction is
 * capped at the torque limit (|λ| ≤ τmax·h² over the substep).
 */
function solveMotor(j: Joints, r: BodyRows, i: number, a: number, b: number, h: number): void {
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
  if (iA !== 0) turn(r, a, iA * dl);
  if (iB !== 0) turn(r, b, -iB * dl);
}

/** Prismatic: no relative turn, B's anchor on A's axis line, and within [lower, upper] along it when limited. */
function solvePrismatic(j: Joints, r: BodyRows, i: number, a: number, b: number): void {
  correctAngle(r, a, b, relativeAngle(r, a, b) - j.refAngle[i]);
  loadAnchors(j, r, i);
  const ca = r.rc[a];
  const sa = r.rs[a];
  const ux = ca * j.axisX[i] - sa * j.axisY[i];
  const uy = sa * j.axisX[i] + ca * j.axisY[i];
  // Perpendicular error: A's anchor minus B's, across the axis.
  const dx = at[2] - at[6];
  const dy = at[3] - at[7];
  const across = -dx * uy + dy * ux;
  if (across !== 0) correct(j, r, i, across, -uy, ux, 0, 0, 0);
  if (j.limit[i] !== 1) return;
  loadAnchors(j, r, i);
  // Translation of B's anchor along the axis from A's.
  const along = (at[6] - at[2]) * ux + (at[7] - at[3]) * uy;
  if (along < j.lower[i]) correct(j, r, i, along - j.lower[i], -ux, -uy, 0, 0, 0);
  else if (along > j.upper[i]) correct(j, r, i, along - j.upper[i], -ux, -uy, 0, 0, 0);
}
