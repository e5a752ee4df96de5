// Collision detection, once per step: bounding boxes grown by each body's motion → broad phase (filtered pairs) →
// narrow phase (contact features) → last step's friction anchors and the approach speeds for restitution.
import type { StepContext } from './context.js';
import { recordApproachSpeeds } from './contacts.js';
import { rebuildColliders } from './topology.js';

/** Broad phase then narrow phase: the contacts found act in every substep of the step (speculatively). */
export function detectCollisions(ctx: StepContext, dt: number): void {
  if (ctx.collidersDirty) rebuildColliders(ctx);
  const c = ctx.colliders;
  ctx.contacts.count = 0;
  ctx.pairs.count = 0;
  if (c.activeCount === 0) return;
  updateBoundingBoxes(ctx, dt);
  ctx.broadPhase.findPairs(c, ctx.acceptPair, ctx.pairs);
  ctx.narrowPhase.run(ctx.pairs, c, ctx.particles, ctx.motion, ctx.settings.contactSlop, ctx.contacts);
  ctx.anchors.restore(ctx.contacts);
  recordApproachSpeeds(ctx.contacts, ctx.particles);
}

/** Each collider's AABB, grown by how far it can move this step (velocity and gravity), and that distance. */
export function updateBoundingBoxes(ctx: StepContext, dt: number): void {
  const c = ctx.colliders;
  const motion = ctx.motion;
  const { x, y, vx, vy, radius, invMass } = ctx.particles;
  const gravity = ctx.settings.gravity;
  const g = Math.sqrt(gravity.x ** 2 + gravity.y ** 2) * dt * dt;
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    const idx = c.particles[s];
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    let speed2 = 0;
    let movable = 0;
    for (let q = 0; q < idx.length; q++) {
      const i = idx[q];
      const r = radius[i];
      if (x[i] - r < minX) minX = x[i] - r;
      if (y[i] - r < minY) minY = y[i] - r;
      if (x[i] + r > maxX) maxX = x[i] + r;
      if (y[i] + r > maxY) maxY = y[i] + r;
      const v2 = vx[i] * vx[i] + vy[i] * vy[i];
      if (v2 > speed2) speed2 = v2;
      if (invMass[i] !== 0) movable = 1;
    }
    const m = movable ? Math.sqrt(speed2) * dt + g : Math.sqrt(speed2) * dt;
    motion[s] = m;
    c.isStatic[s] = movable ? 0 : 1;
    c.minX[s] = minX - m;
    c.minY[s] = minY - m;
    c.maxX[s] = maxX + m;
    c.maxY[s] = maxY + m;
  }
}

/**
 * Collision filtering of two body slots: pairs where neither body can move (static or asleep) need no contacts;
 * a shared positive group always collides, a shared negative group never does; otherwise each body's category
 * must be in the other's mask.
 */
export function shouldCollide(ctx: StepContext, a: number, b: number): boolean {
  const c = ctx.colliders;
  const asleep = ctx.sleep.asleep;
  if ((c.isStatic[a] || asleep[a]) && (c.isStatic[b] || asleep[b])) return false;
  const ga = c.group[a];
  if (ga !== 0 && ga === c.group[b]) return ga > 0;
  return (c.category[a] & c.mask[b]) !== 0 && (c.category[b] & c.mask[a]) !== 0;
}
