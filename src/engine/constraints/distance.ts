import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Distance constraints between two particles, solved as XPBD: the length is kept within [minLength, maxLength]
 * (equal for a stick, 0..L for a slack rope link, L..∞ for a minimum distance). `compliance` is the inverse
 * stiffness in length per unit force (0 = rigid); because XPBD scales it by 1/h² and carries the multiplier
 * `lambda` across iterations, a given compliance means the same physical stiffness whatever the substep and
 * iteration counts.
 */
export class DistanceConstraints extends Table {
  readonly columns = ['a', 'b', 'minLength', 'maxLength', 'compliance', 'lambda', 'breakStrain', 'broken', 'slot'] as const;
  a = new Int32Array(16);
  b = new Int32Array(16);
  minLength = new Float64Array(16);
  maxLength = new Float64Array(16);
  compliance = new Float64Array(16);
  lambda = new Float64Array(16);
  /** Stretch (d − maxLength) / maxLength beyond which the link breaks; 0 = unbreakable. */
  breakStrain = new Float64Array(16);
  /** 1 once broken: the limits are then open, [0, ∞), and the link no longer acts. */
  broken = new Uint8Array(16);
  /** Handle slot owning this row (for swap-remove bookkeeping). */
  slot = new Int32Array(16);
}

export function solveDistances(c: DistanceConstraints, p: ParticleStore, h2: number): void {
  const { a, b, minLength, maxLength, compliance, lambda } = c;
  const { x, y, invMass } = p;
  const n = c.count;
  for (let i = 0; i < n; i++) {
    const ia = a[i];
    const ib = b[i];
    const wa = invMass[ia];
    const wb = invMass[ib];
    const w = wa + wb;
    if (w === 0) continue;
    let dx = x[ib] - x[ia];
    let dy = y[ib] - y[ia];
    const d2 = dx * dx + dy * dy;
    const lo = minLength[i];
    const hi = maxLength[i];
    let d: number;
    let err: number;
    if (lo === hi) {
      d = Math.sqrt(d2);
      err = d - lo;
    } else {
      // Slack rope links and tethers are mostly inactive: skip them before paying for the square root.
      if (d2 >= lo * lo && d2 <= hi * hi) continue;
      d = Math.sqrt(d2);
      // Past the upper limit by the same test as above: d itself may round to hi when d² is just past hi², and
      // d − lo then pulled a taut tether's particle onto its pin.
      err = d2 > hi * hi ? d - hi : d - lo;
    }
    if (d < 1e-12) {
      // Coincident particles have no direction; pick a fixed one so the result stays finite and deterministic.
      dx = 1;
      dy = 0;
      d = 1;
    }
    const k = compliance[i];
    let dl: number;
    if (k === 0) dl = -err / w;
    else {
      const alpha = k / h2;
      dl = (-err - alpha * lambda[i]) / (w + alpha);
      lambda[i] += dl;
    }
    const s = dl / d;
    x[ia] -= wa * s * dx;
    y[ia] -= wa * s * dy;
    x[ib] += wb * s * dx;
    y[ib] += wb * s * dy;
  }
}

/**
 * Tearing (seed 2.7's cloth, torn by a strain threshold): every breakable link stretched past its breakStrain breaks
 * for good (until the scene is rebuilt or restored). Calls onBreak(row) for each; run once per step, after the solve.
 */
export function breakOverstretched(c: DistanceConstraints, p: ParticleStore, onBreak: (row: number) => void): void {
  const { a, b, maxLength, breakStrain } = c;
  const { x, y } = p;
  for (let i = 0, n = c.count; i < n; i++) {
    const limit = breakStrain[i];
    if (limit === 0) continue;
    const dx = x[b[i]] - x[a[i]];
    const dy = y[b[i]] - y[a[i]];
    const reach = maxLength[i] * (1 + limit);
    if (dx * dx + dy * dy <= reach * reach) continue;
    c.minLength[i] = 0;
    c.maxLength[i] = Infinity;
    c.breakStrain[i] = 0;
    c.broken[i] = 1;
    onBreak(i);
  }
}

/**
 * How far constraint `row`'s length is outside [minLength, maxLength] (`relative`: as a fraction of the limit it
 * passes; a non-finite fraction, from a zero limit, counts as 0).
 */
export function stretchOf(t: DistanceConstraints, row: number, p: ParticleStore, relative: boolean): number {
  const { x, y } = p;
  const d = Math.sqrt((x[t.b[row]] - x[t.a[row]]) ** 2 + (y[t.b[row]] - y[t.a[row]]) ** 2);
  const over = d > t.maxLength[row] ? d - t.maxLength[row] : d < t.minLength[row] ? t.minLength[row] - d : 0;
  if (!relative || over === 0) return over;
  const fraction = over / (d > t.maxLength[row] ? t.maxLength[row] : t.minLength[row]);
  return Number.isFinite(fraction) ? fraction : 0;
}
