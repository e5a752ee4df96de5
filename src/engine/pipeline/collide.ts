// Collision detection, once per step: bounding boxes grown by each body's motion → broad phase (filtered pairs) →
// narrow phase (contact features) → last step's friction anchors and the approach speeds for restitution.
import type { StepContext } from './context.js';
import { recordApproachSpeeds } from './contacts.js';
import { pairKey, rebuildColliders } from './topology.js';
import { ColliderKind, type Colliders } from './colliders.js';
import { RigidShapeKind } from '../rigid/shapes.js';
import { findInternalFaces } from '../rigid/seams.js';
import { boundsContacts, discRecords } from './rigid-narrowphase.js';
import { ParticleFlag } from '../particles.js';
import { grown } from '../table.js';
import { overlaps, partnerMotions } from './broadphase.js';

/** Broad phase then narrow phase: the contacts found act in every substep of the step (speculatively). */
export function detectCollisions(ctx: StepContext, dt: number): void {
  if (ctx.collidersDirty) rebuildColliders(ctx);
  const c = ctx.colliders;
  ctx.contacts.count = 0;
  ctx.rigidContacts.count = 0;
  ctx.pairs.count = 0;
  if (c.activeCount === 0) return;
  const shapes = ctx.rigidShapes;
  if (shapes.polygonCount > 0) {
    shapes.updateWorld(ctx.particles);
    if (shapes.staticsMoved) {
      findInternalFaces(shapes, (a, b) => collideAlike(c, a, b) && ctx.jointedApart[a] === 0 && ctx.jointedApart[b] === 0);
      shapes.staticsMoved = false;
    }
  }
  updateBoundingBoxes(ctx, dt);
  ctx.broadPhase.findPairs(c, ctx.acceptPair, ctx.pairs);
  growPushedBodies(ctx);
  const slop = ctx.settings.contactSlop;
  ctx.narrowPhase.run(ctx.pairs, c, ctx.particles, ctx.motion, slop, ctx.contacts);
  ctx.rigidNarrowPhase.run(ctx.pairs, c, shapes, ctx.particles, ctx.motion, slop, ctx.rigidContacts);
  const bounds = ctx.settings.bounds;
  if (bounds && ctx.rigidCount > 0) boundsContacts(bounds, shapes, c, ctx.particles, ctx.motion, ctx.pairs, slop, ctx.settings.boundsFriction, ctx.rigidContacts);
  // A sleeping body about to be hit wakes before the solve, not after it (it would meet the impact as static).
  ctx.sleep.wakeTouched(ctx.contacts, ctx.rigidContacts, ctx.bodyParticlesOf, ctx.particles);
  ctx.rigidAnchors.restore(ctx.rigidContacts, slop, ctx.particles, dt);
  ctx.anchors.restore(ctx.contacts);
  recordApproachSpeeds(ctx.contacts, ctx.particles, ctx.substepMotion);
}

/**
 * Whether two bodies collide (or not) with the same bodies: both collide, with the same filter (the caller also asks
 * that no joint keeps either apart from a body: that body would meet the seam from inside the jointed piece).
 */
function collideAlike(c: Colliders, a: number, b: number): boolean {
  return c.kind[a] !== ColliderKind.None && c.kind[b] !== ColliderKind.None && c.category[a] === c.category[b] && c.mask[a] === c.mask[b] && c.group[a] === c.group[b];
}

/** The static colliders, gathered when some body grows (growPushedBodies). */
let statics = new Int32Array(16);

/**
 * Found by updateBoundingBoxes for growPushedBodies: [0] the largest motion of any collider this step, [1] the smallest
 * size (AABB's shorter side less twice its motion) of a collider that is not static.
 */
const reach = new Float64Array(2);

/**
 * A slow body that a fast one will hit this step is driven as far as the hitter moves, but its AABB was grown by its
 * own motion only: it had no pair with the wall behind it, and the hitter pushed it into the wall, or through it,
 * before the next step's detection (a disc between a wall and a box 3× its mass at 500 units/s went through a wall
 * 1 thick). Such a body's AABB and motion grow by its fastest partner's motion, when that exceeds its own by more
 * than a quarter of the body's size, and it gets the pairs with static bodies that its larger box now reaches (walls
 * are what it must not be pushed through; the broad phase is not run again: 10,000 circles, where bodies land fast on
 * the pile, were 10% slower with a second run).
 */
function growPushedBodies(ctx: StepContext): void {
  const c = ctx.colliders;
  const pairs = ctx.pairs;
  const motion = ctx.motion;
  // Nothing to grow unless the fastest body moves more than a quarter of the smallest one's size (both found by
  // updateBoundingBoxes). A body grows when a partner moves more than its own motion plus a quarter of its size, so
  // more than this threshold: only such fast partners are looked at (a pile's landing rows are a few of its bodies).
  const threshold = 0.25 * reach[1];
  if (reach[0] <= threshold) return;
  const pushed = partnerMotions(c, pairs, motion, threshold);
  let staticCount = -1;
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    const extra = pushed[s];
    if (extra <= threshold || c.isStatic[s]) continue;
    const m = motion[s];
    const size = Math.min(c.maxX[s] - c.minX[s], c.maxY[s] - c.minY[s]) - 2 * m;
    if (extra <= m + 0.25 * size) continue;
    if (staticCount < 0) staticCount = gatherStatics(c);
    const minX = c.minX[s] - extra;
    const minY = c.minY[s] - extra;
    const maxX = c.maxX[s] + extra;
    const maxY = c.maxY[s] + extra;
    for (let q = 0; q < staticCount; q++) {
      const w = statics[q];
      const reaches = minX <= c.maxX[w] && c.minX[w] <= maxX && minY <= c.maxY[w] && c.minY[w] <= maxY;
      // A pair the broad phase found already (the boxes overlapped before growing) is not listed twice.
      if (reaches && !overlaps(c, s, w) && ctx.acceptPair(s, w)) pairs.push(s, w);
    }
    motion[s] = m + extra;
    discRecords.data[8 * s + 3] = m + extra;
    c.minX[s] = minX;
    c.minY[s] = minY;
    c.maxX[s] = maxX;
    c.maxY[s] = maxY;
  }
}

/** Lists the active static colliders in statics[]; returns how many. */
function gatherStatics(c: StepContext['colliders']): number {
  let n = 0;
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    if (!c.isStatic[s]) continue;
    if (n === statics.length) statics = grown(statics, n + 1);
    statics[n++] = s;
  }
  return n;
}

/** Each collider's AABB, grown by how far it can move this step (velocity and gravity), and that distance. */
export function updateBoundingBoxes(ctx: StepContext, dt: number): void {
  const c = ctx.colliders;
  const motion = ctx.motion;
  const { x, y, vx, vy, radius, invMass, omega, flags } = ctx.particles;
  const gravity = ctx.settings.gravity;
  const g = Math.sqrt(gravity.x ** 2 + gravity.y ** 2) * dt * dt;
  // The step's reals for rigidBoundingBox (a typed array: no boxed doubles per call).
  ctx.substepReals[0] = dt;
  ctx.substepReals[1] = g;
  const shapes = ctx.rigidShapes;
  // Room for every slot's record (bodies were added: not within a step's usual work).
  if (discRecords.data.length < 8 * c.minX.length) discRecords.data = new Float64Array(8 * c.minX.length);
  const discs = discRecords.data;
  discRecords.vx = vx;
  discRecords.vy = vy;
  discRecords.dt[0] = dt;
  let fastest = 0;
  let smallest = Infinity;
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    if (c.kind[s] === ColliderKind.Rigid) {
      // The body's row from the shapes' column (its particle list is one row: no pointer to chase per body).
      const i = shapes.row[s];
      if (shapes.kind[s] === RigidShapeKind.Circle) {
        // A dynamic disc (most bodies of a pile), inline: what rigidBoundingBox does for it.
        const r = shapes.radius[s];
        const w = omega[i] < 0 ? -omega[i] : omega[i];
        const dynamic = invMass[i] !== 0;
        const speed = Math.sqrt(vx[i] * vx[i] + vy[i] * vy[i]) + w * radius[i];
        if (dynamic) {
          const m = speed * dt + g;
          motion[s] = m;
          writeDisc(discs, s, shapes.row[s], r, m, ctx.particles, c.friction[s]);
          c.isStatic[s] = 0;
          const minX = x[i] - r - m;
          const minY = y[i] - r - m;
          const maxX = x[i] + r + m;
          const maxY = y[i] + r + m;
          c.minX[s] = minX;
          c.minY[s] = minY;
          c.maxX[s] = maxX;
          c.maxY[s] = maxY;
          if (m > fastest) fastest = m;
          const size = Math.min(maxX - minX, maxY - minY) - 2 * m;
          if (size < smallest) smallest = size;
          continue;
        }
      }
      rigidBoundingBox(ctx, s, i, x, y, vx, vy, omega, radius, invMass, flags);
      const m = motion[s];
      if (shapes.kind[s] === RigidShapeKind.Circle) writeDisc(discs, s, shapes.row[s], shapes.radius[s], m, ctx.particles, c.friction[s]);
      else discs[8 * s + 2] = -1;
      if (m > fastest) fastest = m;
      if (c.isStatic[s]) continue;
      const size = Math.min(c.maxX[s] - c.minX[s], c.maxY[s] - c.minY[s]) - 2 * m;
      if (size < smallest) smallest = size;
      continue;
    }
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
    discs[8 * s + 2] = -1;
    c.isStatic[s] = movable ? 0 : 1;
    c.minX[s] = minX - m;
    c.minY[s] = minY - m;
    c.maxX[s] = maxX + m;
    c.maxY[s] = maxY + m;
    if (m > fastest) fastest = m;
    if (!movable) continue;
    const size = Math.min(c.maxX[s] - c.minX[s], c.maxY[s] - c.minY[s]) - 2 * m;
    if (size < smallest) smallest = size;
  }
  reach[0] = fastest;
  reach[1] = smallest;
}

/** Body slot s's record in discRecords: a rigid disc of radius r on row `row`, moving up to m this step. */
function writeDisc(discs: Float64Array, s: number, row: number, r: number, m: number, p: StepContext['particles'], friction: number): void {
  const o = 8 * s;
  discs[o] = p.x[row];
  discs[o + 1] = p.y[row];
  discs[o + 2] = r;
  discs[o + 3] = m;
  discs[o + 4] = p.rc[row];
  discs[o + 5] = p.rs[row];
  discs[o + 6] = friction;
  discs[o + 7] = row;
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
  if (ctx.jointedPairs.size > 0 && ctx.jointedPairs.find(pairKey(a, b)) >= 0) return false;
  const ga = c.group[a];
  if (ga !== 0 && ga === c.group[b]) return ga > 0;
  return (c.category[a] & c.mask[b]) !== 0 && (c.category[b] & c.mask[a]) !== 0;
}

/**
 * A rigid body's AABB: its world vertices (a disc: centre ± radius), grown by how far any point of it can move this
 * step: |v|·dt + |ω|·extent·dt, plus gravity's share for a dynamic body. A moving kinematic body is not static for
 * pair filtering (it must wake and push what it meets).
 */
function rigidBoundingBox(
  ctx: StepContext, s: number, i: number,
  x: Float64Array, y: Float64Array, vx: Float64Array, vy: Float64Array, omega: Float64Array, radius: Float64Array, invMass: Float64Array, flags: Uint8Array,
): void {
  const dt = ctx.substepReals[0];
  const g = ctx.substepReals[1];
  const c = ctx.colliders;
  const shapes = ctx.rigidShapes;
  let minX: number;
  let minY: number;
  let maxX: number;
  let maxY: number;
  if (shapes.kind[s] === RigidShapeKind.Circle) {
    const r = shapes.radius[s];
    minX = x[i] - r;
    maxX = x[i] + r;
    minY = y[i] - r;
    maxY = y[i] + r;
  } else {
    minX = minY = Infinity;
    maxX = maxY = -Infinity;
    const { wx, wy } = shapes;
    const p0 = shapes.partStart[s];
    const v0 = shapes.partVertexStart[p0];
    const last = p0 + shapes.partCount[s] - 1;
    const v1 = shapes.partVertexStart[last] + shapes.partVertexCount[last];
    for (let v = v0; v < v1; v++) {
      if (wx[v] < minX) minX = wx[v];
      if (wx[v] > maxX) maxX = wx[v];
      if (wy[v] < minY) minY = wy[v];
      if (wy[v] > maxY) maxY = wy[v];
    }
  }
  const w = omega[i] < 0 ? -omega[i] : omega[i];
  const speed = Math.sqrt(vx[i] * vx[i] + vy[i] * vy[i]) + w * radius[i];
  const dynamic = invMass[i] !== 0;
  const moving = dynamic || ((flags[i] & ParticleFlag.Kinematic) !== 0 && speed > 0);
  const m = speed * dt + (dynamic ? g : 0);
  ctx.motion[s] = m;
  c.isStatic[s] = moving ? 0 : 1;
  c.minX[s] = minX - m;
  c.minY[s] = minY - m;
  c.maxX[s] = maxX + m;
  c.maxY[s] = maxY + m;
}

