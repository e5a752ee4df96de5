import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';
import { spin, turnBySpin } from '../rigid/rows.js';

/**
 * Pointer drag: a soft XPBD pin that pulls a point of a body toward a moving target. The point is a weighted sum
 * of up to three particles (barycentric in a triangle of the body), so a particle frame can be held anywhere, not
 * only at a corner; a cloth or rope is held at one particle (weight 1); a rigid body at a point (rx, ry) of its own
 * frame, as a soft point joint to the pointer.
 */
export class GrabConstraints extends Table {
  readonly columns = ['p0', 'p1', 'p2', 'w0', 'w1', 'w2', 'tx', 'ty', 'compliance', 'lambdaX', 'lambdaY', 'slot', 'rx', 'ry'] as const;
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
}

/**
 * The fastest a grab drags its point (units/s). A pointer that jumps (a touch elsewhere, a lost frame) would otherwise
 * fling a light body at jump / h.
 */
export const GRAB_SPEED_LIMIT = 200;

export function solveGrabs(g: GrabConstraints, p: ParticleStore, h2: number): void {
  const { x, y, invMass } = p;
  const reach = GRAB_SPEED_LIMIT * Math.sqrt(h2);
  for (let i = 0, n = g.count; i < n; i++) {
    if (p.invInertia[g.p0[i]] !== 0) {
      solveRigidGrab(g, p, i, h2, reach);
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
    let cx = wa * x[a] + wb * x[b] + wc * x[c] - g.tx[i];
    let cy = wa * y[a] + wb * y[b] + wc * y[c] - g.ty[i];
    const error = Math.sqrt(cx * cx + cy * cy);
    if (error > reach) {
      cx *= reach / error;
      cy *= reach / error;
    }
    const alpha = g.compliance[i] / h2;
    const dlx = (-cx - alpha * g.lambdaX[i]) / (w + alpha);
    const dly = (-cy - alpha * g.lambdaY[i]) / (w + alpha);
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

/** A rigid body held at (rx, ry) of its frame: both directions at once (2×2), soft by the grab's compliance. */
function solveRigidGrab(g: GrabConstraints, p: ParticleStore, i: number, h2: number, reach: number): void {
  const a = g.p0[i];
  const c = p.rc[a];
  const s = p.rs[a];
  const lx = c * g.rx[i] - s * g.ry[i];
  const ly = s * g.rx[i] + c * g.ry[i];
  let ex = p.x[a] + lx - g.tx[i];
  let ey = p.y[a] + ly - g.ty[i];
  const error = Math.sqrt(ex * ex + ey * ey);
  if (error > reach) {
    ex *= reach / error;
    ey *= reach / error;
  }
  const m = p.invMass[a];
  const iI = p.invInertia[a];
  const alpha = g.compliance[i] / h2;
  const k11 = m + iI * ly * ly + alpha;
  const k12 = -iI * lx * ly;
  const k22 = m + iI * lx * lx + alpha;
  const det = k11 * k22 - k12 * k12;
  if (!(det > 0)) return;
  const rx = -ex - alpha * g.lambdaX[i];
  const ry = -ey - alpha * g.lambdaY[i];
  const dx = (k22 * rx - k12 * ry) / det;
  const dy = (k11 * ry - k12 * rx) / det;
  g.lambdaX[i] += dx;
  g.lambdaY[i] += dy;
  p.x[a] += m * dx;
  p.y[a] += m * dy;
  spin[0] = iI * (lx * dy - ly * dx);
  turnBySpin(p, a);
}
