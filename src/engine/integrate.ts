import { ParticleFlag, type ParticleStore } from './particles.js';

/** The integrators the seed compares (2.5). Position Verlet is the default. */
export type Integrator = 'verlet' | 'semi-implicit-euler' | 'explicit-euler';
export const INTEGRATORS: readonly Integrator[] = ['verlet', 'semi-implicit-euler', 'explicit-euler'];

/**
 * Advances every movable particle by one substep h from the accelerations in p.ax/p.ay and remembers where it
 * started (px/py). `damp` = 1 / (1 + h·linearDamping). Immovable particles only get px = x, so their velocity
 * (a moving pin's, say) is still derived correctly afterwards.
 *
 * - verlet:              x' = x + (x − x_prev)·damp + a·h²   (written with v = (x − x_prev)/h)
 * - semi-implicit-euler: v' = (v + a·h)·damp, x' = x + v'·h
 * - explicit-euler:      x' = x + v·h, v' = (v + a·h)·damp  (gains energy on oscillators: kept for comparison)
 */
export function integrate(p: ParticleStore, h: number, damp: number, integrator: Integrator): void {
  const { x, y, px, py, vx, vy, qx, qy, ax, ay, invMass, alive } = p;
  const n = p.count;
  const h2 = h * h;
  // One loop per integrator, so the per-particle body has no branch on the method.
  if (integrator === 'verlet') {
    for (let i = 0; i < n; i++) {
      px[i] = x[i];
      py[i] = y[i];
      if (invMass[i] === 0) continue;
      x[i] += vx[i] * damp * h + ax[i] * h2;
      y[i] += vy[i] * damp * h + ay[i] * h2;
    }
  } else if (integrator === 'semi-implicit-euler') {
    for (let i = 0; i < n; i++) {
      px[i] = x[i];
      py[i] = y[i];
      if (invMass[i] === 0) continue;
      vx[i] = (vx[i] + ax[i] * h) * damp;
      vy[i] = (vy[i] + ay[i] * h) * damp;
      x[i] += vx[i] * h;
      y[i] += vy[i] * h;
    }
  } else {
    for (let i = 0; i < n; i++) {
      px[i] = x[i];
      py[i] = y[i];
      if (alive[i] === 0 || invMass[i] === 0) continue;
      x[i] += vx[i] * h;
      y[i] += vy[i] * h;
      vx[i] = (vx[i] + ax[i] * h) * damp;
      vy[i] = (vy[i] + ay[i] * h) * damp;
      qx[i] = x[i];
      qy[i] = y[i];
    }
  }
}

/**
 * After the constraints moved particles, velocities follow the positions. For the position-based integrators
 * v = (x − x_prev)/h. Explicit Euler keeps its own velocity and only adds what the constraints moved.
 */
export function updateVelocities(p: ParticleStore, h: number, integrator: Integrator): void {
  const { x, y, px, py, vx, vy, qx, qy, invMass, alive } = p;
  const inv = 1 / h;
  const n = p.count;
  if (integrator === 'explicit-euler') {
    for (let i = 0; i < n; i++) {
      if (alive[i] === 0) continue;
      if (invMass[i] === 0) {
        vx[i] = (x[i] - px[i]) * inv;
        vy[i] = (y[i] - py[i]) * inv;
      } else {
        vx[i] += (x[i] - qx[i]) * inv;
        vy[i] += (y[i] - qy[i]) * inv;
      }
    }
    return;
  }
  // Dead slots hold px = x, so they get v = 0 without a branch.
  for (let i = 0; i < n; i++) {
    vx[i] = (x[i] - px[i]) * inv;
    vy[i] = (y[i] - py[i]) * inv;
  }
}

/**
 * ½·h of a substep of length h under position Verlet, 0 under the Euler integrators: a particle's stored velocity is
 * v − ½·g·h (the mean over the substep to come), so that a thrown particle follows x0 + v0·t + ½·g·t² exactly.
 */
export function verletHalfSubstep(integrator: Integrator, h: number): number {
  return integrator === 'verlet' ? 0.5 * h : 0;
}

/**
 * Adds (dx, dy) to the stored velocity of every movable particle that is not a rigid body's row, and (rx, ry) to every
 * movable rigid row: how the v − ½·g·h of position Verlet follows a change of g or h (each kind of row keeps it for its
 * own reference substep: verletReferenceHalf). A sleeping body's rows are at rest (invMass 0 while parked: they wake at
 * rest).
 */
export function shiftVerletVelocities(p: ParticleStore, dx: number, dy: number, rx: number, ry: number): void {
  if (dx === 0 && dy === 0 && rx === 0 && ry === 0) return;
  const { vx, vy, invMass, alive, flags } = p;
  for (let i = 0, n = p.count; i < n; i++) {
    if (alive[i] === 0 || invMass[i] === 0) continue;
    const rigid = (flags[i] & ParticleFlag.Rigid) !== 0;
    vx[i] += rigid ? rx : dx;
    vy[i] += rigid ? ry : dy;
  }
}
