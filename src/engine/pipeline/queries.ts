import { circleView, polygonView } from '../collision/shape.js';
import { pointInShape, raycast } from '../collision/query.js';
import { RayHit } from '../collision/results.js';
import type { ParticleStore } from '../particles.js';
import { ColliderKind, type Colliders } from './colliders.js';
import { RigidShapeKind, type RigidShapes } from '../rigid/shapes.js';

/** Where a ray first hits a body. */
export interface BodyRayHit {
  /** Body slot (the world turns it into a handle). */
  slot: number;
  x: number;
  y: number;
  normalX: number;
  normalY: number;
  distance: number;
}

/** Particle AABB of a collider (without the motion margin the broad phase adds). */
function particleBounds(c: Colliders, p: ParticleStore, s: number, out: Float64Array): void {
  const idx = c.particles[s];
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let k = 0; k < idx.length; k++) {
    const i = idx[k];
    const r = p.radius[i];
    minX = Math.min(minX, p.x[i] - r);
    minY = Math.min(minY, p.y[i] - r);
    maxX = Math.max(maxX, p.x[i] + r);
    maxY = Math.max(maxY, p.y[i] + r);
  }
  out[0] = minX;
  out[1] = minY;
  out[2] = maxX;
  out[3] = maxY;
}

const box = new Float64Array(4);

/**
 * The convex parts of a body, wherever their vertices live: a particle-built body's parts index the particles; a
 * rigid polygon's are runs of its shape's world vertices (indexed through an identity list). Filled by partsOf().
 */
interface Parts {
  xs: Float64Array;
  ys: Float64Array;
  index: Int32Array;
  start: Int32Array;
  count: Int32Array;
  first: number;
  end: number;
}
const parts: Parts = { xs: new Float64Array(0), ys: new Float64Array(0), index: new Int32Array(0), start: new Int32Array(0), count: new Int32Array(0), first: 0, end: 0 };
let identity = new Int32Array(0);

/** Points `parts` at body s's convex parts; false for a body without polygon parts (particles, a rigid disc). */
function partsOf(c: Colliders, p: ParticleStore, shapes: RigidShapes, s: number): boolean {
  if (c.kind[s] === ColliderKind.Polygon) {
    Object.assign(parts, { xs: p.x, ys: p.y, index: c.vertices, start: c.partVertexStart, count: c.partVertexCount, first: c.partStart[s], end: c.partStart[s] + c.partCount[s] });
    return true;
  }
  if (c.kind[s] !== ColliderKind.Rigid || shapes.kind[s] !== RigidShapeKind.Polygon) return false;
  if (identity.length < shapes.verticesUsed) identity = Int32Array.from({ length: shapes.verticesUsed * 2 }, (_, k) => k);
  Object.assign(parts, { xs: shapes.wx, ys: shapes.wy, index: identity, start: shapes.partVertexStart, count: shapes.partVertexCount, first: shapes.partStart[s], end: shapes.partStart[s] + shapes.partCount[s] });
  return true;
}

/** Body slots whose collision shape contains the point, last created first (the one drawn on top). */
export function bodiesAtPoint(c: Colliders, p: ParticleStore, shapes: RigidShapes, x: number, y: number): number[] {
  const found: number[] = [];
  for (let k = c.activeCount - 1; k >= 0; k--) {
    const s = c.active[k];
    particleBounds(c, p, s, box);
    if (x < box[0] || x > box[2] || y < box[1] || y > box[3]) continue;
    if (contains(c, p, shapes, s, x, y)) found.push(s);
  }
  return found;
}

function contains(c: Colliders, p: ParticleStore, shapes: RigidShapes, s: number, x: number, y: number): boolean {
  if (partsOf(c, p, shapes, s)) {
    for (let part = parts.first; part < parts.end; part++) {
      if (pointInShape(polygonView(parts.xs, parts.ys, parts.index, parts.start[part], parts.count[part]), x, y)) return true;
    }
    return false;
  }
  // Particles and a rigid disc (its row's radius is the disc's).
  const idx = c.particles[s];
  for (let k = 0; k < idx.length; k++) {
    const i = idx[k];
    const r = p.radius[i];
    if ((p.x[i] - x) ** 2 + (p.y[i] - y) ** 2 <= r * r) return true;
  }
  return c.ringLength[s] >= 3 && insideRing(idx, c.ringLength[s], p, x, y);
}

/** Crossing-number test against a closed ring of particles (any simple outline, convex or not). */
function insideRing(idx: Int32Array, n: number, p: ParticleStore, x: number, y: number): boolean {
  let inside = false;
  for (let k = 0, j = n - 1; k < n; j = k++) {
    const xi = p.x[idx[k]];
    const yi = p.y[idx[k]];
    const xj = p.x[idx[j]];
    const yj = p.y[idx[j]];
    if (yi > y !== yj > y && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** Body slots whose shape overlaps the box [minX, maxX] × [minY, maxY]. */
export function bodiesInBox(c: Colliders, p: ParticleStore, shapes: RigidShapes, minX: number, minY: number, maxX: number, maxY: number): number[] {
  const found: number[] = [];
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    particleBounds(c, p, s, box);
    if (box[0] > maxX || box[2] < minX || box[1] > maxY || box[3] < minY) continue;
    if (overlapsBox(c, p, shapes, s, minX, minY, maxX, maxY)) found.push(s);
  }
  return found;
}

function overlapsBox(c: Colliders, p: ParticleStore, shapes: RigidShapes, s: number, minX: number, minY: number, maxX: number, maxY: number): boolean {
  const { radius } = p;
  if (!partsOf(c, p, shapes, s)) {
    const { x, y } = p;
    const idx = c.particles[s];
    for (let k = 0; k < idx.length; k++) {
      const i = idx[k];
      const cx = Math.max(minX, Math.min(x[i], maxX));
      const cy = Math.max(minY, Math.min(y[i], maxY));
      if ((x[i] - cx) ** 2 + (y[i] - cy) ** 2 <= radius[i] * radius[i]) return true;
    }
    return false;
  }
  // Separating axes: the box's two axes (already passed: the part's bounds overlap) and each part's edge normals.
  const { xs: x, ys: y, index } = parts;
  for (let part = parts.first; part < parts.end; part++) {
    const start = parts.start[part];
    const n = parts.count[part];
    let pMinX = Infinity;
    let pMinY = Infinity;
    let pMaxX = -Infinity;
    let pMaxY = -Infinity;
    for (let k = 0; k < n; k++) {
      const i = index[start + k];
      pMinX = Math.min(pMinX, x[i]);
      pMaxX = Math.max(pMaxX, x[i]);
      pMinY = Math.min(pMinY, y[i]);
      pMaxY = Math.max(pMaxY, y[i]);
    }
    if (pMinX > maxX || pMaxX < minX || pMinY > maxY || pMaxY < minY) continue;
    let separated = false;
    for (let k = 0; k < n && !separated; k++) {
      const i0 = index[start + k];
      const i1 = index[start + ((k + 1) % n)];
      const nx = y[i1] - y[i0];
      const ny = x[i0] - x[i1];
      const edge = x[i0] * nx + y[i0] * ny;
      // The box corner deepest against this edge's outward normal.
      const cx = nx > 0 ? minX : maxX;
      const cy = ny > 0 ? minY : maxY;
      if (cx * nx + cy * ny > edge) separated = true;
    }
    if (!separated) return true;
  }
  return false;
}

const hit = new RayHit();

/** The nearest body a ray from (x0, y0) toward (x1, y1) hits within that segment, or null. */
export function rayCast(c: Colliders, p: ParticleStore, shapes: RigidShapes, x0: number, y0: number, x1: number, y1: number): BodyRayHit | null {
  const dx = x1 - x0;
  const dy = y1 - y0;
  const length = Math.sqrt(dx * dx + dy * dy);
  let best: BodyRayHit | null = null;
  const consider = (s: number) => {
    if (hit.hit && (!best || hit.distance < best.distance)) best = { slot: s, x: hit.x, y: hit.y, normalX: hit.normalX, normalY: hit.normalY, distance: hit.distance };
  };
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    particleBounds(c, p, s, box);
    // Slab test against the body's bounds first.
    if (!segmentMeetsBox(x0, y0, dx, dy, box)) continue;
    if (partsOf(c, p, shapes, s)) {
      for (let part = parts.first; part < parts.end; part++) {
        raycast(polygonView(parts.xs, parts.ys, parts.index, parts.start[part], parts.count[part]), x0, y0, dx, dy, length, hit);
        consider(s);
      }
    } else {
      const idx = c.particles[s];
      for (let q = 0; q < idx.length; q++) {
        if (p.radius[idx[q]] <= 0) continue;
        raycast(circleView(p.x, p.y, idx, q, p.radius[idx[q]]), x0, y0, dx, dy, length, hit);
        consider(s);
      }
    }
  }
  return best;
}

function segmentMeetsBox(x0: number, y0: number, dx: number, dy: number, b: Float64Array): boolean {
  let t0 = 0;
  let t1 = 1;
  for (let axis = 0; axis < 2; axis++) {
    const o = axis === 0 ? x0 : y0;
    const d = axis === 0 ? dx : dy;
    const lo = b[axis];
    const hi = b[axis + 2];
    if (Math.abs(d) < 1e-300) {
      if (o < lo || o > hi) return false;
      continue;
    }
    let ta = (lo - o) / d;
    let tb = (hi - o) / d;
    if (ta > tb) [ta, tb] = [tb, ta];
    t0 = Math.max(t0, ta);
    t1 = Math.min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}
