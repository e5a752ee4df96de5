// Picking what a pointer grabs: a point of a body (barycentric in a triangle of its outline, so a rigid body is held
// at that very point), else the nearest movable particle of the body, else the nearest free-standing movable particle.
import type { ParticleStore } from '../particles.js';
import { ColliderKind } from './colliders.js';
import type { StepContext } from './context.js';
import { bodiesAtPoint } from './queries.js';

/** Where a grab holds: up to three particles with weights, and the mass the pull scales with. */
export interface GrabPoint {
  p0: number;
  p1: number;
  p2: number;
  w0: number;
  w1: number;
  w2: number;
  mass: number;
  /** A rigid body's held point in its own frame (0, 0 otherwise). */
  rx: number;
  ry: number;
}

/** What a grab at (x, y) would hold, or null when nothing movable is there (the topology must be current). */
export function pickGrabPoint(ctx: StepContext, x: number, y: number, pickRadius: number): GrabPoint | null {
  const p = ctx.particles;
  const c = ctx.colliders;
  for (const s of bodiesAtPoint(c, p, ctx.rigidShapes, x, y)) {
    const idx = ctx.bodies.particles[s];
    const mass = bodyMass(ctx, idx);
    if (mass === 0) continue;
    if (c.kind[s] === ColliderKind.Rigid) {
      // Held at the very point pressed, in the body's frame (it turns with the body).
      const i = idx[0];
      const dx = x - p.x[i];
      const dy = y - p.y[i];
      return { p0: i, p1: i, p2: i, w0: 1, w1: 0, w2: 0, mass, rx: p.rc[i] * dx + p.rs[i] * dy, ry: -p.rs[i] * dx + p.rc[i] * dy };
    }
    if (c.kind[s] === ColliderKind.Polygon) {
      // A triangle of the outline's fan holds the point: barycentric weights keep it fixed in the body.
      for (let k = 1; k + 1 < idx.length; k++) {
        const w = barycentric(p, idx[0], idx[k], idx[k + 1], x, y);
        if (w) return { p0: idx[0], p1: idx[k], p2: idx[k + 1], w0: w[0], w1: w[1], w2: w[2], mass, rx: 0, ry: 0 };
      }
    }
    const nearest = nearestParticle(ctx, idx, x, y);
    if (nearest >= 0) return { p0: nearest, p1: nearest, p2: nearest, w0: 1, w1: 0, w2: 0, mass, rx: 0, ry: 0 };
  }
  let best = -1;
  let bestD2 = pickRadius * pickRadius;
  for (let i = 0; i < p.count; i++) {
    if (!p.alive[i] || ctx.sleep.awakeInvMass(i, p) === 0) continue;
    const d2 = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
    if (d2 <= bestD2) {
      best = i;
      bestD2 = d2;
    }
  }
  if (best < 0) return null;
  // Held at one particle, a cloth or rope is still pulled as a whole: the pull scales with the mass of the body the
  // particle belongs to, so dragging a cloth feels like dragging a box of the same mass.
  const owner = ctx.sleep.particleBody[best];
  const mass = owner >= 0 ? bodyMass(ctx, ctx.bodies.particles[owner]) : 1 / p.invMass[best];
  return { p0: best, p1: best, p2: best, w0: 1, w1: 0, w2: 0, mass, rx: 0, ry: 0 };
}

/** Total mass of the particles as when awake (a sleeping body's parked masses count). */
function bodyMass(ctx: StepContext, idx: Int32Array): number {
  let m = 0;
  for (const i of idx) {
    const w = ctx.sleep.awakeInvMass(i, ctx.particles);
    if (w > 0) m += 1 / w;
  }
  return m;
}

function nearestParticle(ctx: StepContext, idx: Int32Array, x: number, y: number): number {
  const p = ctx.particles;
  let best = -1;
  let bestD2 = Infinity;
  for (const i of idx) {
    if (p.invMass[i] === 0 && ctx.sleep.awakeInvMass(i, p) === 0) continue;
    const d2 = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
    if (d2 < bestD2) {
      best = i;
      bestD2 = d2;
    }
  }
  return best;
}

/** Barycentric weights of (x, y) in triangle a, b, c, or null when outside (or degenerate). */
function barycentric(p: ParticleStore, a: number, b: number, c: number, x: number, y: number): [number, number, number] | null {
  const v0x = p.x[b] - p.x[a];
  const v0y = p.y[b] - p.y[a];
  const v1x = p.x[c] - p.x[a];
  const v1y = p.y[c] - p.y[a];
  const v2x = x - p.x[a];
  const v2y = y - p.y[a];
  const den = v0x * v1y - v1x * v0y;
  if (Math.abs(den) < 1e-18) return null;
  const u = (v2x * v1y - v1x * v2y) / den;
  const v = (v0x * v2y - v2x * v0y) / den;
  if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) return null;
  return [1 - u - v, u, v];
}
