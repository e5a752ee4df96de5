// The columns the rigid-body kernels read and write. A rigid body is a row of the particle store with an angle and
// an inverse moment of inertia; a plain particle is the same row with inverse inertia 0 and angle 0, so every
// formula below reduces to the particle case without a branch (Müller et al. 2020, "Detailed Rigid Body Simulation
// with Extended Position Based Dynamics": generalised inverse mass w = 1/m + (r × n)²/I).
//
// Rotation: `angle` is the truth, summed exactly. (rc, rs) are cos and sin of a reference angle `qangle`, brought up to
// `angle` once a substep (syncRotation); between two syncs the contact solver only adds to `angle`, and a point of
// the body is found from its lever at the reference turned by the small angle since (first order), which is cheaper
// than keeping cos and sin exact through every one of thousands of corrections.

export interface BodyRows {
  /** Rows in use. */
  count: number;
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
  /** cos and sin of `qangle`, the reference angle (see above). */
  rc: Float64Array;
  rs: Float64Array;
  qangle: Float64Array;
  invMass: Float64Array;
  invInertia: Float64Array;
}

/** The angle turnBySpin() turns a row by (a typed array: a double passed to a call that is not inlined is boxed). */
export const spin = new Float64Array(1);

/** [turn, angle after it] for rotate() (typed: no boxed doubles per call). */
const turnTo = new Float64Array(2);

/**
 * Turns below which (rc, rs) is turned by the Taylor series of the rotation, to d⁸/8! for the cosine and d⁹/9! for
 * the sine: the first term left out is below 3·10⁻¹⁷ there, under half an ulp of 1, so the series is exact to rounding;
 * Math.cos and Math.sin above it. Most substeps' turns are far below it (a disc rolling at 36 units/s turns 0.1 rad in
 * a substep of 1/360 s), and a pair of Math.cos/Math.sin costs as much as about ten rows turned by the series.
 */
export const SERIES_TURN = 0.1;

/**
 * Turns (rc, rs) of row i by turnTo[0] to the angle turnTo[1]: the Taylor series of the rotation for a turn below
 * SERIES_TURN, Math.cos/Math.sin otherwise.
 */
function rotate(b: BodyRows, i: number): void {
  const d = turnTo[0];
  const to = turnTo[1];
  if (d < SERIES_TURN && d > -SERIES_TURN) {
    vectorTurn[0] = d;
    turnVector(b.rc, b.rs, i);
  }
  else {
    b.rc[i] = Math.cos(to);
    b.rs[i] = Math.sin(to);
  }
}

/** The turn turnVector() applies, in radians (a typed array: V8 boxes a double passed to a call it does not inline). */
export const vectorTurn = new Float64Array(1);

/**
 * Turns the vector (xs[i], ys[i]) by vectorTurn[0] radians: the series of rotate() below SERIES_TURN (exact to
 * rounding there), Math.cos and Math.sin above it.
 */
export function turnVector(xs: Float64Array, ys: Float64Array, i: number): void {
  const d = vectorTurn[0];
  const x = xs[i];
  const y = ys[i];
  let cd: number;
  let sd: number;
  if (d < SERIES_TURN && d > -SERIES_TURN) {
    const d2 = d * d;
    cd = 1 + d2 * (-1 / 2 + d2 * (1 / 24 + d2 * (-1 / 720 + d2 * (1 / 40320))));
    sd = d * (1 + d2 * (-1 / 6 + d2 * (1 / 120 + d2 * (-1 / 5040 + d2 * (1 / 362880)))));
  } else {
    cd = Math.cos(d);
    sd = Math.sin(d);
  }
  xs[i] = x * cd - y * sd;
  ys[i] = y * cd + x * sd;
}

/**
 * Turns row i by spin[0] radians, keeping its rotation exact (joints and grabs, which solve few constraints and need
 * their levers current).
 */
export function turnBySpin(b: BodyRows, i: number): void {
  const d = spin[0];
  b.angle[i] += d;
  b.qangle[i] += d;
  turnTo[0] = d;
  turnTo[1] = b.qangle[i];
  rotate(b, i);
}

/**
 * Steps between two exact rotations of a row (resyncRotation). Turned by the series substep after substep, (rc, rs)
 * drifts from cos and sin of the angle by rounding, faster than linearly (a row spun at 0.5–30 rad/s, h = 1/360: 1e-14
 * to 2e-13 after 384 substeps, 5e-13 to 3e-12 after 3,840); 16 steps keep it near 1e-14.
 */
export const RESYNC_STEPS = 16;

/**
 * (rc, rs) from Math.cos/Math.sin of the angle for one listed row in RESYNC_STEPS, in turn by `step` (the step's
 * count), so that no row's incremental turns drift for long, at a sixteenth of the trigonometry of resyncing all.
 */
export function resyncRotation(b: BodyRows, rows: Int32Array, count: number, step: number): void {
  const { angle, qangle, rc, rs } = b;
  for (let k = step % RESYNC_STEPS; k < count; k += RESYNC_STEPS) {
    const i = rows[k];
    const a = angle[i];
    rc[i] = Math.cos(a);
    rs[i] = Math.sin(a);
    qangle[i] = a;
  }
}

/** Brings the rotation of the listed rows up to their angles, by the turn since the last sync (rotate()'s arithmetic). */
export function syncRotation(b: BodyRows, rows: Int32Array, count: number): void {
  const { angle, qangle, rc, rs } = b;
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    const a = angle[i];
    const d = a - qangle[i];
    if (d === 0) continue;
    qangle[i] = a;
    if (d < SERIES_TURN && d > -SERIES_TURN) {
      const c = rc[i];
      const s = rs[i];
      const d2 = d * d;
      const cd = 1 + d2 * (-1 / 2 + d2 * (1 / 24 + d2 * (-1 / 720 + d2 * (1 / 40320))));
      const sd = d * (1 + d2 * (-1 / 6 + d2 * (1 / 120 + d2 * (-1 / 5040 + d2 * (1 / 362880)))));
      rc[i] = c * cd - s * sd;
      rs[i] = s * cd + c * sd;
    } else {
      rc[i] = Math.cos(a);
      rs[i] = Math.sin(a);
    }
  }
}

/** The most a rigid body turns in one substep (radians). */
export const MAX_TURN = 0.5;

/**
 * The angular half of a substep's integration for the listed rigid rows: remember the angle, add the torque's
 * angular acceleration, turn by h·ω (step = [h, damping factor], in a typed array so the call boxes no doubles),
 * and bring the rotation (rc, rs) up to the new angle as syncRotation() does. Rows with inverse inertia 0 (static and kinematic bodies) keep
 * their ω undamped.
 */
export function integrateRotation(b: BodyRows, torque: Float64Array, rows: Int32Array, count: number, step: Float64Array): void {
  const h = step[0];
  const damp = step[1];
  const { angle, pangle, omega, invInertia, qangle, rc, rs } = b;
  for (let k = 0; k < count; k++) {
    const i = rows[k];
    const a0 = angle[i];
    pangle[i] = a0;
    const iI = invInertia[i];
    let w = iI > 0 ? (omega[i] + h * torque[i] * iI) * damp : omega[i];
    // At most half a radian a substep (Box2D caps a step's turn likewise): a body spun faster than the substeps can
    // resolve would tunnel through its contacts and feed its own blow-up.
    if (w * h > MAX_TURN) w = MAX_TURN / h;
    else if (w * h < -MAX_TURN) w = -MAX_TURN / h;
    omega[i] = w;
    const a = a0 + h * w;
    angle[i] = a;
    // The rotation follows here, as syncRotation(b, rows, count) would (one pass over the rows, not two), with
    // rotate()'s arithmetic written out (a call per row costs more than the turn).
    const d = a - qangle[i];
    if (d === 0) continue;
    qangle[i] = a;
    if (d < SERIES_TURN && d > -SERIES_TURN) {
      const c = rc[i];
      const s = rs[i];
      const d2 = d * d;
      const cd = 1 + d2 * (-1 / 2 + d2 * (1 / 24 + d2 * (-1 / 720 + d2 * (1 / 40320))));
      const sd = d * (1 + d2 * (-1 / 6 + d2 * (1 / 120 + d2 * (-1 / 5040 + d2 * (1 / 362880)))));
      rc[i] = c * cd - s * sd;
      rs[i] = s * cd + c * sd;
    } else {
      rc[i] = Math.cos(a);
      rs[i] = Math.sin(a);
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
