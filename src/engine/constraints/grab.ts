import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';
import { spin, turnBySpin } from '../rigid/rows.js';

/**
 * Pointer drag: a damped soft XPBD pin that pulls a point of a body toward a moving target, a spring of stiffness
 * k = stiffness × mass (compliance 1/k) with a damper c = 2ζ√(k·mass) on the held point's velocity (ζ =
 * GRAB_DAMPING_RATIO), so the point settles on a still pointer without swinging about it and a throw leaves at the
 * pointer's speed, not at the phase of a swing. The point is a weighted sum of up to three particles (barycentric in a
 * triangle of the body), so a particle frame can be held anywhere, not only at a corner; a cloth or rope is held at one
 * particle (weight 1); a rigid body at a point (rx, ry) of its own frame, as a soft point joint to the pointer.
 */
export class GrabConstraints extends Table {
  readonly columns = ['p0', 'p1', 'p2', 'w0', 'w1', 'w2', 'tx', 'ty', 'compliance', 'lambdaX', 'lambdaY', 'slot', 'rx', 'ry', 'lag', 'aimX', 'aimY', 'aimVX', 'aimVY'] as const;
  p0 = new Int32Array(16);
  p1 = new Int32Array(16);
  p2 = new Int32Array(16);
  w0 = new Float64Array(16);
  w1 = new Float64Array(16);
  w2 = new Float64Array(16);
  tx = new Float64Array(16);
  ty = new Float64Array(16);
  compliance = new Float64Array(16);
  lambdaX = new Float64Array(16);
  lambdaY = new Float64Array(16);
  slot = new Int32Array(16);
  /** The held point in a rigid body's frame (p0 is the body's row; 0, 0 for particles). */
  rx = new Float64Array(16);
  ry = new Float64Array(16);
  /**
   * Damping over stiffness, c/k = 2ζ/ω (seconds, ω = √stiffness): how far the held point trails a steadily moving
   * pointer per unit of its speed. Set by grabLag().
   */
  lag = new Float64Array(16);
  /**
   * Where the pull aims this substep: it glides from where the last step left it to the pointer (tx, ty) in equal
   * parts over the step's substeps, at the pointer's speed over the step (aimVX, aimVY), so the held point is pulled
   * as by a pointer moving steadily, not one that jumps at each step's start.
   */
  aimX = new Float64Array(16);
  aimY = new Float64Array(16);
  aimVX = new Float64Array(16);
  aimVY = new Float64Array(16);
}

/** A step of dt begins: each grab's aim is to reach the pointer by the step's end. */
export function beginGrabStep(g: GrabConstraints, dt: number): void {
  for (let i = 0, n = g.count; i < n; i++) {
    g.aimVX[i] = (g.tx[i] - g.aimX[i]) / dt;
    g.aimVY[i] = (g.ty[i] - g.aimY[i]) / dt;
  }
}

/** A substep of h begins: each grab's aim moves on by h of its step's glide. */
export function aimGrabs(g: GrabConstraints, h: number): void {
  for (let i = 0, n = g.count; i < n; i++) {
    g.aimX[i] += g.aimVX[i] * h;
    g.aimY[i] += g.aimVY[i] * h;
  }
}

/**
 * The fastest a grab drags its point (units/s). A pointer that jumps (a touch elsewhere, a lost frame) would otherwise
 * fling a light body at jump / h. The spring's stretch counts up to GRAB_SPEED_LIMIT × lag: there its pull equals the
 * damper's at GRAB_SPEED_LIMIT, so however far the pointer is, the held point speeds up toward it no faster than that.
 * A very stiff grab (lag shorter than a substep) is nearly a hard pin, which moves its point by the stretch each
 * substep: its stretch counts up to one substep's travel at GRAB_SPEED_LIMIT.
 */
export const GRAB_SPEED_LIMIT = 200;

/**
 * The grab's damping ratio ζ: 1 is critical damping (no overshoot); below 1 the point overshoots a still pointer by
 * e^(−πζ/√(1−ζ²)) of the jump in the continuous spring (1.5% at 0.8; 1.1% measured in the substepped solve, which
 * damps a little more), and picks up a quick flick's speed sooner (in a one-dimensional model of this solve, a flick of
 * 80 ms leaves at 0.94 of the pointer's speed at 0.8, 0.86 at 1, with the default stiffness).
 */
export const GRAB_DAMPING_RATIO = 0.8;

/** The `lag` column for a grab of the given stiffness (pull per unit of distance and of mass, 1/s²). */
export function grabLag(stiffness: number): number {
  return (2 * GRAB_DAMPING_RATIO) / Math.sqrt(stiffness);
}

/**
 * XPBD with damping (Macklin, Müller, Chentanez, "XPBD", 2016, eq. 26): with α̃ = compliance/h² and γ = α̃·β̃/h =
 * (c/k)/h = lag/h, a step toward the target is Δλ = (−C − γ·d − α̃λ) / ((1 + γ)·w + α̃), where C is the held point's
 * offset from the target (its length capped at GRAB_SPEED_LIMIT × max(lag, h)) and d how far the point moved this substep.
 */
export function solveGrabs(g: GrabConstraints, p: ParticleStore, h2: number): void {
  const { x, y, px, py, invMass } = p;
  const h = Math.sqrt(h2);
  for (let i = 0, n = g.count; i < n; i++) {
    const gamma = g.lag[i] / h;
    const reach = GRAB_SPEED_LIMIT * Math.max(g.lag[i], h);
    if (p.invInertia[g.p0[i]] !== 0) {
      solveRigidGrab(g, p, i, h2, gamma, reach);
      continue;
    }
    const a = g.p0[i];
    const b = g.p1[i];
    const c = g.p2[i];
    const wa = g.w0[i];
    const wb = g.w1[i];
    const wc = g.w2[i];
    const ma = invMass[a];
    const mb = invMass[b];
    const mc = invMass[c];
    const w = wa * wa * ma + wb * wb * mb + wc * wc * mc;
    if (w === 0) continue;
    let cx = wa * x[a] + wb * x[b] + wc * x[c] - g.aimX[i];
    let cy = wa * y[a] + wb * y[b] + wc * y[c] - g.aimY[i];
    const error = Math.sqrt(cx * cx + cy * cy);
    if (error > reach) {
      cx *= reach / error;
      cy *= reach / error;
    }
    // The held point's move this substep.
    const dx = wa * (x[a] - px[a]) + wb * (x[b] - px[b]) + wc * (x[c] - px[c]);
    const dy = wa * (y[a] - py[a]) + wb * (y[b] - py[b]) + wc * (y[c] - py[c]);
    const alpha = g.compliance[i] / h2;
    const k = (1 + gamma) * w + alpha;
    const dlx = (-cx - gamma * dx - alpha * g.lambdaX[i]) / k;
    const dly = (-cy - gamma * dy - alpha * g.lambdaY[i]) / k;
    g.lambdaX[i] += dlx;
    g.lambdaY[i] += dly;
    x[a] += ma * wa * dlx;
    y[a] += ma * wa * dly;
    x[b] += mb * wb * dlx;
    y[b] += mb * wb * dly;
    x[c] += mc * wc * dlx;
    y[c] += mc * wc * dly;
  }
}

/**
 * A rigid body held at (rx, ry) of its frame: both directions at once (2×2), soft by the grab's compliance, damped on
 * the held point's move since the substep began (the centre's move plus the turn of the arm from the start angle).
 */
function solveRigidGrab(g: GrabConstraints, p: ParticleStore, i: number, h2: number, gamma: number, reach: number): void {
  const a = g.p0[i];
  const c = p.rc[a];
  const s = p.rs[a];
  const lx = c * g.rx[i] - s * g.ry[i];
  const ly = s * g.rx[i] + c * g.ry[i];
  let ex = p.x[a] + lx - g.aimX[i];
  let ey = p.y[a] + ly - g.aimY[i];
  const error = Math.sqrt(ex * ex + ey * ey);
  if (error > reach) {
    ex *= reach / error;
    ey *= reach / error;
  }
  // The arm at the substep's start angle is the arm now turned back by the turn since.
  const turn = p.angle[a] - p.pangle[a];
  const tc = Math.cos(turn);
  const ts = Math.sin(turn);
  const mx = p.x[a] - p.px[a] + lx - (tc * lx + ts * ly);
  const my = p.y[a] - p.py[a] + ly - (-ts * lx + tc * ly);
  const m = p.invMass[a];
  const iI = p.invInertia[a];
  const alpha = g.compliance[i] / h2;
  const scale = 1 + gamma;
  const k11 = scale * (m + iI * ly * ly) + alpha;
  const k12 = -scale * iI * lx * ly;
  const k22 = scale * (m + iI * lx * lx) + alpha;
  const det = k11 * k22 - k12 * k12;
  if (!(det > 0)) return;
  const rx = -ex - gamma * mx - alpha * g.lambdaX[i];
  const ry = -ey - gamma * my - alpha * g.lambdaY[i];
  const dx = (k22 * rx - k12 * ry) / det;
  const dy = (k11 * ry - k12 * rx) / det;
  g.lambdaX[i] += dx;
  g.lambdaY[i] += dy;
  p.x[a] += m * dx;
  p.y[a] += m * dy;
  spin[0] = iI * (lx * dy - ly * dx);
  turnBySpin(p, a);
}
