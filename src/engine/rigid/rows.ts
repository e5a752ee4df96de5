// The columns the rigid-body kernels read and write. A rigid body is a row of the particle store with an angle and
// an inverse moment of inertia; a plain particle is the same row with inverse inertia 0 and angle 0, so every
// formula below reduces to the particle case without a branch (Müller et al. 2020, "Detailed Rigid Body Simulation
// with Extended Position Based Dynamics": generalised inverse mass w = 1/m + (r × n)²/I).

export interface BodyRows {
  x: Float64Array;
  y: Float64Array;
  /** Pose at the start of the substep. */
  px: Float64Array;
  py: Float64Array;
  vx: Float64Array;
  vy: Float64Array;
  angle: Float64Array;
  pangle: Float64Array;
  omega: Float64Array;
  /** cos and sin of `angle`, kept in step with it (every kernel that turns a body updates them). */
  rc: Float64Array;
  rs: Float64Array;
  invMass: Float64Array;
  invInertia: Float64Array;
}

/** The angle turnBySpin() turns a row by (a typed array: a double passed to a call that is not inlined is boxed). */
export const spin = new Float64Array(1);

/**
 * Turns row i by spin[0] radians. Solver corrections turn a body by tiny angles many times a substep, so cos/sin are
 * advanced by the Taylor series of the rotation (exact to rounding for |d| < 1e-3) instead of Math.cos/Math.sin; the
 * angle itself is summed exactly, and syncRotation() re-derives cos/sin from it once a step.
 */
export function turnBySpin(b: BodyRows, i: number): void {
  const d = spin[0];
  b.angle[i] += d;
  const c = b.rc[i];
  const s = b.rs[i];
  if (d < 1e-3 && d > -1e-3) {
    const d2 = d * d;
    const cd = 1 - d2 * 0.5 + d2 * d2 * (1 / 24);
    const sd = d * (1 - d2 * (1 / 6) + d2 * d2 * (1 / 120));
    b.rc[i] = c * cd - s * sd;
    b.rs[i] = s * cd + c * sd;
  } else {
    b.rc[i] = Math.cos(b.angle[i]);
    b.rs[i] = Math.sin(b.angle[i]);
  }
}

/** cos/sin from the angle for the listed rows (once a step: the incremental updates of turn() drift by rounding). */
export function syncRotation(b: BodyRows, rows: Int32Array, count: number): void {
  const { angle, rc, rs } = b;
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    rc[i] = Math.cos(angle[i]);
    rs[i] = Math.sin(angle[i]);
  }
}

/**
 * The angular half of a substep's integration for the listed rigid rows: remember the angle, add the torque's
 * angular acceleration, turn by h·ω (step = [h, damping factor], in a typed array so the call boxes no doubles). (The linear half is the particles' integrator: x += h·(v + h·a).) Rows with
 * inverse inertia 0 (static and kinematic bodies) keep their ω undamped.
 */
export function integrateRotation(b: BodyRows, torque: Float64Array, rows: Int32Array, count: number, step: Float64Array): void {
  const h = step[0];
  const damp = step[1];
  const { angle, pangle, omega, invInertia } = b;
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    pangle[i] = angle[i];
    const iI = invInertia[i];
    const w = iI > 0 ? (omega[i] + h * torque[i] * iI) * damp : omega[i];
    omega[i] = w;
    if (w !== 0) {
      spin[0] = h * w;
      turnBySpin(b, i);
    }
  }
}

/**
 * Kinematic rows move at their prescribed velocity (the particle integrator leaves rows of inverse mass 0 where they
 * are), so contacts see them move within each substep and a turning drum carries what lies in it.
 */
export function integrateKinematic(b: BodyRows, rows: Int32Array, count: number, step: Float64Array): void {
  const h = step[0];
  const { x, y, vx, vy } = b;
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    x[i] += h * vx[i];
    y[i] += h * vy[i];
  }
}

/** ω = (θ − θ̄)/h after the position solve, as v = (x − x̄)/h is for positions. */
export function updateAngularVelocity(b: BodyRows, rows: Int32Array, count: number, step: Float64Array): void {
  const { angle, pangle, omega } = b;
  const inv = 1 / step[0];
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    omega[i] = (angle[i] - pangle[i]) * inv;
  }
}
