import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Angle limits over three particles a–b–c with b the vertex (seed 2.6: joint limits of a ragdoll). The angle is the
 * signed angle from (a − b) to (c − b), in (−π, π], counter-clockwise positive in a y-up frame; it is kept in
 * [min, max] by an XPBD correction along the angle's gradient.
 */
export class AngleConstraints extends Table {
  readonly columns = ['a', 'b', 'c', 'min', 'max', 'compliance', 'lambda', 'slot'] as const;
  a = new Int32Array(16);
  b = new Int32Array(16);
  c = new Int32Array(16);
  min = new Float64Array(16);
  max = new Float64Array(16);
  compliance = new Float64Array(16);
  lambda = new Float64Array(16);
  slot = new Int32Array(16);
}

export function signedAngle(ux: number, uy: number, vx: number, vy: number): number {
  return Math.atan2(ux * vy - uy * vx, ux * vx + uy * vy);
}

/** The same angle in (−π, π]. */
export function wrapAngle(a: number): number {
  const twoPi = 2 * Math.PI;
  a = a - twoPi * Math.floor((a + Math.PI) / twoPi);
  return a === -Math.PI ? Math.PI : a;
}

/** The largest angle error (rad) one solve corrects; the rest waits for the next substep. */
const MAX_ANGLE_STEP = 0.5;

export function solveAngles(c: AngleConstraints, p: ParticleStore, h2: number): void {
  const { a, b, c: cc, min, max, compliance, lambda } = c;
  const { x, y, invMass } = p;
  for (let i = 0, n = c.count; i < n; i++) {
    const ia = a[i];
    const ib = b[i];
    const ic = cc[i];
    const ux = x[ia] - x[ib];
    const uy = y[ia] - y[ib];
    const vx = x[ic] - x[ib];
    const vy = y[ic] - y[ib];
    const uu = ux * ux + uy * uy;
    const vv = vx * vx + vy * vy;
    if (uu < 1e-18 || vv < 1e-18) continue;
    // Measured from the centre of the range, so a range across ±π works.
    const centre = 0.5 * (min[i] + max[i]);
    const half = 0.5 * (max[i] - min[i]);
    const rel = wrapAngle(signedAngle(ux, uy, vx, vy) - centre);
    let err: number;
    if (rel > half) err = rel - half;
    else if (rel < -half) err = rel + half;
    else continue;
    // At most MAX_ANGLE_STEP a solve: the correction moves the particles along the angle's tangents, which for a large
    // error flings them outward (a turn of π moved by π·|u| lengthens u 3.3 times), and limits that cannot all hold
    // at once (a ragdoll's own and one added across them) fed that from solve to solve until the doll was at 1e9.
    // (Math.min/max, not branches assigning the module's constant: in a phi with the local doubles V8 boxed every err.)
    err = Math.min(MAX_ANGLE_STEP, Math.max(-MAX_ANGLE_STEP, err));
    // ∂θ/∂c = perp(v)/|v|², ∂θ/∂a = −perp(u)/|u|², ∂θ/∂b = −(∂θ/∂a + ∂θ/∂c), with perp(x, y) = (−y, x).
    const gax = uy / uu;
    const gay = -ux / uu;
    const gcx = -vy / vv;
    const gcy = vx / vv;
    const gbx = -(gax + gcx);
    const gby = -(gay + gcy);
    const wa = invMass[ia];
    const wb = invMass[ib];
    const wc = invMass[ic];
    const w = wa * (gax * gax + gay * gay) + wb * (gbx * gbx + gby * gby) + wc * (gcx * gcx + gcy * gcy);
    if (w === 0) continue;
    const alpha = compliance[i] / h2;
    const dl = (-err - alpha * lambda[i]) / (w + alpha);
    lambda[i] += dl;
    x[ia] += wa * dl * gax;
    y[ia] += wa * dl * gay;
    x[ib] += wb * dl * gbx;
    y[ib] += wb * dl * gby;
    x[ic] += wc * dl * gcx;
    y[ic] += wc * dl * gcy;
  }
}
