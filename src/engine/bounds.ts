import { ParticleFlag, type ParticleStore } from './particles.js';

/** An axis-aligned box the particles cannot leave (Jakobsen's first collision). */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/**
 * Projects particles (inflated by their radius) back inside the box. Friction is Coulomb's on the step's
 * tangential motion: the tangential displacement since the substep began is cancelled up to `friction` times the
 * normal correction (static when it all fits, kinetic otherwise).
 */
export function keepInBounds(p: ParticleStore, b: Bounds, friction: number): void {
  const { x, y, px, py, radius, invMass, flags } = p;
  for (let i = 0, n = p.count; i < n; i++) {
    // A rigid body meets the walls by its shape (rigid contacts with the world), not as a circle.
    if (invMass[i] === 0 || flags[i] & ParticleFlag.Rigid) continue;
    const r = radius[i];
    let dx = 0;
    let dy = 0;
    if (x[i] < b.minX + r) dx = b.minX + r - x[i];
    else if (x[i] > b.maxX - r) dx = b.maxX - r - x[i];
    if (y[i] < b.minY + r) dy = b.minY + r - y[i];
    else if (y[i] > b.maxY - r) dy = b.maxY - r - y[i];
    if (dx === 0 && dy === 0) continue;
    x[i] += dx;
    y[i] += dy;
    if (friction > 0) {
      if (dy !== 0) x[i] -= frictionShift(x[i] - px[i], Math.abs(dy) * friction);
      if (dx !== 0) y[i] -= frictionShift(y[i] - py[i], Math.abs(dx) * friction);
    }
  }
}

/** How much of a tangential displacement `t` friction removes, given the most it may remove. */
export function frictionShift(t: number, limit: number): number {
  if (t > limit) return limit;
  if (t < -limit) return -limit;
  return t;
}
