import { grown, Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Keeps the area of a closed loop of particles at `restArea` (the pressure model of a soft body). The loop's
 * particle indices live in one shared pool, each row owning [start, start + length). The gradient of the
 * shoelace area with respect to vertex i is ½·perp(p[i+1] − p[i−1]). `damping` (per second) is the loop's material
 * damping: the rate at which its particles' motion apart from the loop's rigid motion dies out (pipeline/spin.ts).
 */
export class AreaConstraints extends Table {
  readonly columns = ['start', 'length', 'restArea', 'compliance', 'lambda', 'slot', 'damping'] as const;
  start = new Int32Array(16);
  length = new Int32Array(16);
  restArea = new Float64Array(16);
  compliance = new Float64Array(16);
  lambda = new Float64Array(16);
  damping = new Float64Array(16);
  slot = new Int32Array(16);
  pool = new Int32Array(64);
  poolUsed = 0;

  appendLoop(indices: ArrayLike<number>): number {
    const start = this.poolUsed;
    this.pool = grown(this.pool, start + indices.length);
    for (let k = 0; k < indices.length; k++) this.pool[start + k] = indices[k];
    this.poolUsed += indices.length;
    return start;
  }

  /** Drops the pool entries no row uses any more (called after removals, outside step()). */
  compactPool(): void {
    const next = new Int32Array(Math.max(64, this.pool.length));
    let used = 0;
    for (let i = 0; i < this.count; i++) {
      next.set(this.pool.subarray(this.start[i], this.start[i] + this.length[i]), used);
      this.start[i] = used;
      used += this.length[i];
    }
    this.pool = next;
    this.poolUsed = used;
  }
}

export function loopArea(pool: Int32Array, start: number, length: number, x: Float64Array, y: Float64Array): number {
  let sum = 0;
  for (let k = 0; k < length; k++) {
    const i = pool[start + k];
    const j = pool[start + ((k + 1) % length)];
    sum += x[i] * y[j] - x[j] * y[i];
  }
  return 0.5 * sum;
}

export function solveAreas(c: AreaConstraints, p: ParticleStore, h2: number): void {
  const { x, y, invMass } = p;
  const pool = c.pool;
  for (let r = 0, n = c.count; r < n; r++) {
    const start = c.start[r];
    const len = c.length[r];
    const err = loopArea(pool, start, len, x, y) - c.restArea[r];
    let w = 0;
    for (let k = 0; k < len; k++) {
      const prev = pool[start + ((k + len - 1) % len)];
      const next = pool[start + ((k + 1) % len)];
      const gx = 0.5 * (y[next] - y[prev]);
      const gy = 0.5 * (x[prev] - x[next]);
      w += invMass[pool[start + k]] * (gx * gx + gy * gy);
    }
    if (w === 0) continue;
    const alpha = c.compliance[r] / h2;
    const dl = (-err - alpha * c.lambda[r]) / (w + alpha);
    c.lambda[r] += dl;
    // Gradients are taken from the positions before this loop moves anything (Jacobi within the loop), so the
    // first vertex's move does not bias the others'.
    const last = pool[start + len - 1];
    let prevX = x[last];
    let prevY = y[last];
    const startX = x[pool[start]];
    const startY = y[pool[start]];
    for (let k = 0; k < len; k++) {
      const i = pool[start + k];
      const next = pool[start + ((k + 1) % len)];
      const nx = k === len - 1 ? startX : x[next];
      const ny = k === len - 1 ? startY : y[next];
      const gx = 0.5 * (ny - prevY);
      const gy = 0.5 * (prevX - nx);
      prevX = x[i];
      prevY = y[i];
      const wi = invMass[i] * dl;
      x[i] += wi * gx;
      y[i] += wi * gy;
    }
  }
}
