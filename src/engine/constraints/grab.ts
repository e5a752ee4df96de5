import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Pointer drag: a soft XPBD pin that pulls a point of a body toward a moving target. The point is a weighted sum
 * of up to three particles (barycentric in a triangle of the body), so a rigid body can be held anywhere, not only
 * at a corner; a cloth or rope is held at one particle (weight 1).
 */
export class GrabConstraints extends Table {
  readonly columns = ['p0', 'p1', 'p2', 'w0', 'w1', 'w2', 'tx', 'ty', 'compliance', 'lambdaX', 'lambdaY', 'slot'] as const;
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
