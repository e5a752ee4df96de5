import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';

/**
 * Mass–spring links (seed 2.4): Hooke's force k·(d − L) plus a damping force c·(relative speed along the link),
 * added to the particles' forces before integration. Unlike the XPBD constraints these are explicit forces, which
 * is what the seed's integrator comparison is about: a stiff spring with a large step shows each integrator's
 * stability.
 */
export class Springs extends Table {
  readonly columns = ['a', 'b', 'restLength', 'stiffness', 'damping', 'slot'] as const;
  a = new Int32Array(16);
  b = new Int32Array(16);
  restLength = new Float64Array(16);
  stiffness = new Float64Array(16);
  damping = new Float64Array(16);
  slot = new Int32Array(16);
}

/**
 * An explicit spring is stable only while ω·h < 2 (ω² = k / m). So that a stiff spring on a light particle softens
 * instead of exploding, each spring's stiffness is capped at SPRING_LIMIT·m/h² and its damping at SPRING_LIMIT·m/h,
 * with m the pair's reduced mass: a particle held by up to 40 such springs stays under the limit (Σk·h²/m ≤ 4). A
 * particle held by more than 30 shares SPRING_TOTAL among them, below that limit (a soft body's hub of 100 spokes
 * blew up, and hit what was near).
 */
const SPRING_LIMIT = 0.1;
const SPRING_TOTAL = 3;

/** Springs per particle row (scratch of accumulateSprings). */
let springsAt = new Int32Array(64);

/** Adds spring forces into ax/ay (accelerations scratch, already holding gravity + user force per unit mass). */
export function accumulateSprings(s: Springs, p: ParticleStore, ax: Float64Array, ay: Float64Array, h: number): void {
  const { x, y, vx, vy, invMass } = p;
  if (springsAt.length < p.count) springsAt = new Int32Array(2 * p.count);
  const at = springsAt;
  at.fill(0, 0, p.count);
  for (let i = 0, n = s.count; i < n; i++) {
    at[s.a[i]]++;
    at[s.b[i]]++;
  }
  for (let i = 0, n = s.count; i < n; i++) {
    const ia = s.a[i];
    const ib = s.b[i];
    const w = invMass[ia] + invMass[ib];
    if (w === 0) continue;
    const most = at[ia] > at[ib] ? at[ia] : at[ib];
    const limit = most * SPRING_LIMIT > SPRING_TOTAL ? SPRING_TOTAL / most : SPRING_LIMIT;
    const reduced = 1 / w;
    const kMax = (limit * reduced) / (h * h);
    const cMax = (limit * reduced) / h;
    const k = s.stiffness[i] < kMax ? s.stiffness[i] : kMax;
    const c = s.damping[i] < cMax ? s.damping[i] : cMax;
    let dx = x[ib] - x[ia];
    let dy = y[ib] - y[ia];
    const d = Math.sqrt(dx * dx + dy * dy);
    if (d < 1e-12) continue;
    dx /= d;
    dy /= d;
    const relSpeed = (vx[ib] - vx[ia]) * dx + (vy[ib] - vy[ia]) * dy;
    const f = k * (d - s.restLength[i]) + c * relSpeed;
    ax[ia] += f * dx * invMass[ia];
    ay[ia] += f * dy * invMass[ia];
    ax[ib] -= f * dx * invMass[ib];
    ay[ib] -= f * dy * invMass[ib];
  }
}
