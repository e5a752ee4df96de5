// Bookkeeping rebuilt when bodies, particles or constraints change (never inside a step): the colliders' parts and
// active list, the particle → body map, the body pairs constraints join (sleeping islands) and the free particles.
import { GridBroadPhase } from './broadphase.js';
import type { StepContext } from './context.js';
import { grown } from '../table.js';
import { ParticleFlag } from '../particles.js';
import { ColliderKind } from './colliders.js';
import { BodyType } from '../rigid/shapes.js';
import { rebuildFreeSpin } from './spin.js';
import { eachLinkedPair } from './linked.js';

/**
 * Bodies, particles or constraints changed. Everything wakes (a removed support must not leave sleepers floating,
 * and parked masses must not be restored over a changed pin) and the bookkeeping is rebuilt before its next use.
 */
export function topologyChanged(ctx: StepContext): void {
  if (!ctx.topologyDirty) wakeAll(ctx);
  ctx.topologyDirty = true;
}

export function wakeAll(ctx: StepContext): void {
  const { ids, particles } = ctx.bodies;
  for (let s = 0; s < ids.high; s++) if (ids.alive[s]) ctx.sleep.wakeBody(s, particles[s], ctx.particles);
}

/** Wakes the body a particle belongs to (anything the user does to a particle). */
export function wakeParticle(ctx: StepContext, i: number): void {
  if (ctx.topologyDirty) return;
  const s = ctx.sleep.particleBody[i];
  if (s >= 0) ctx.sleep.wakeBody(s, ctx.bodies.particles[s], ctx.particles);
}

/** Rebuilds what is stale: after this the colliders and the sleep bookkeeping match the bodies. */
export function ensureTopology(ctx: StepContext): void {
  if (ctx.topologyDirty) rebuildTopology(ctx);
}

/** Particle → body map, cross-body constraint links and free particles, for sleeping (after any change). */
export function rebuildTopology(ctx: StepContext): void {
  ctx.kernel?.topologyChanged();
  if (ctx.collidersDirty) rebuildColliders(ctx);
  const { ids, particles: members } = ctx.bodies;
  const high = ids.high;
  const p = ctx.particles;
  const sleep = ctx.sleep;
  sleep.rebuild(high, p.count, (slot) => (ids.alive[slot] ? members[slot] : null));
  const owner = sleep.particleBody;
  const links: [number, number][] = [];
  const link = (i: number, j: number) => {
    const a = owner[i];
    const b = owner[j];
    if (a >= 0 && b >= 0 && a !== b) links.push([a, b]);
  };
  eachLinkedPair(ctx, link);
  // Joints: their bodies (from their rows), sleeping links, and the jointed pairs that do not collide.
  const j = ctx.constraints.joints;
  const jointed = ctx.jointedPairs;
  jointed.reset(j.count);
  const before = ctx.jointedApart.slice(0, high);
  ctx.jointedApart = grown(ctx.jointedApart, high);
  const apart = ctx.jointedApart;
  apart.fill(0);
  for (let r = 0; r < j.count; r++) {
    const a = owner[j.a[r]];
    const b = j.b[r] >= 0 ? owner[j.b[r]] : -1;
    j.bodyA[r] = a;
    j.bodyB[r] = b;
    if (a < 0 || b < 0 || a === b) continue;
    links.push([a, b]);
    if (j.collide[r] !== 0) continue;
    jointed.insert(pairKey(a, b), 1);
    apart[a] = apart[b] = 1;
  }
  // A static piece jointed apart from a body hides no seams (collide.ts collideAlike): the seams again when that changed.
  for (let slot = 0; slot < high; slot++) if (apart[slot] !== (before[slot] ?? 0)) ctx.rigidShapes.staticsMoved = true;
  sleep.setLinks(links);
  listRigidRows(ctx);
  markFrameRows(ctx);
  rebuildFreeSpin(ctx);
  let free = 0;
  let movable = 0;
  for (let i = 0; i < p.count; i++) {
    if (!p.alive[i] || p.invMass[i] === 0) continue;
    movable++;
    if (owner[i] < 0) free++;
  }
  ctx.freeMovableParticles = free;
  // Less the dynamic rigid bodies' rows (listRigidRows above lists them with the kinematic ones).
  for (let k = 0; k < ctx.rigidCount; k++) if (p.invMass[ctx.rigidRows[k]] > 0) movable--;
  ctx.particleRows = movable;
  let awake = 0;
  for (let b = 0; b < high; b++) if (ids.alive[b] && !sleep.asleep[b]) awake++;
  sleep.awakeCount = awake;
  ctx.topologyDirty = false;
}

/** The colliders' convex parts and active list, from the bodies (after bodies or colliders changed). */
export function rebuildColliders(ctx: StepContext): void {
  const bodies = ctx.bodies;
  const high = bodies.ids.high;
  ctx.motion = grown(ctx.motion, high);
  const shapes = ctx.rigidShapes;
  shapes.rebuild(high);
  // A rigid body collides by its own shape (rigid/shapes.ts), not by parts of particles.
  ctx.colliders.rebuild(high, (slot) => {
    if (!bodies.ids.alive[slot]) return null;
    if (shapes.source(slot)) return { particles: bodies.particles[slot], parts: [] };
    return { particles: bodies.particles[slot], parts: bodies.partIndices(slot) };
  });
  for (let slot = 0; slot < high; slot++) if (shapes.source(slot) && ctx.colliders.kind[slot] !== ColliderKind.None) ctx.colliders.kind[slot] = ColliderKind.Rigid;
  if (ctx.broadPhase instanceof GridBroadPhase) ctx.broadPhase.invalidateCellSize();
  ctx.collidersDirty = false;
}

/** The rows of the rigid bodies that turn (dynamic, kinematic) and of the kinematic ones. */
function listRigidRows(ctx: StepContext): void {
  const shapes = ctx.rigidShapes;
  const { ids, particles } = ctx.bodies;
  const p = ctx.particles;
  ctx.rigidRows = grown(ctx.rigidRows, ids.high);
  ctx.kinematicRows = grown(ctx.kinematicRows, ids.high);
  ctx.rigidCount = 0;
  ctx.kinematicCount = 0;
  for (let s = 0; s < ids.high; s++) {
    if (!ids.alive[s] || !shapes.source(s)) continue;
    const type = shapes.type[s];
    if (type === BodyType.Static) continue;
    const i = particles[s][0];
    ctx.rigidRows[ctx.rigidCount++] = i;
    if (type === BodyType.Kinematic && p.flags[i] & ParticleFlag.Kinematic) ctx.kinematicRows[ctx.kinematicCount++] = i;
  }
}

/**
 * The rows of bodies that may be particle frames (kind 'rigid', two rows or more, none a rigid row), for the velocity
 * passes: they note the stops (e = 0) of these for the frames' bounces (frame-bounces.ts).
 */
function markFrameRows(ctx: StepContext): void {
  const { ids, particles, kind } = ctx.bodies;
  const p = ctx.particles;
  const fb = ctx.frameBounces;
  fb.frameRow = grown(fb.frameRow, p.count);
  fb.frameRow.fill(0);
  fb.anyFrame = false;
  for (let s = 0; s < ids.high; s++) {
    if (!ids.alive[s] || kind[s] !== 'rigid') continue;
    const rows = particles[s];
    if (rows.length < 2) continue;
    let frame = true;
    for (const r of rows) if (p.flags[r] & ParticleFlag.Rigid) frame = false;
    if (frame) for (const r of rows) fb.frameRow[r] = 1;
    fb.anyFrame ||= frame;
  }
  ctx.rigidContacts.frameRow = fb.frameRow;
}

/** A key for an unordered pair of body slots. */
export function pairKey(a: number, b: number): number {
  return a < b ? a * 4194304 + b : b * 4194304 + a;
}
