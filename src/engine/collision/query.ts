// Queries: point in shape, and ray casts against each shape (hit, distance, normal).
import { finite, nonNegativeOrInfinity } from '../validate.js';
import type { RayHit } from './results.js';
import { ShapeType, type Shape } from './shape.js';

/**
 * (x, y) is inside the shape or on its outline. A segment counts points within 1e-12 of its length of it (it has no
 * inside); a polygon view need not be convex for its outline's points, but its inside test assumes convexity.
 * Throws a TypeError or RangeError naming x or y when it is not a finite number (NaN would compare as inside).
 */
export function pointInShape(shape: Shape, x: number, y: number): boolean {
  if (!(Number.isFinite(x) && Number.isFinite(y))) {
    finite('x', x);
    finite('y', y);
  }
  const { xs, ys, index, offset, count } = shape;
  if (shape.type === ShapeType.Circle) {
    const i = index[offset];
    const dx = x - xs[i];
    const dy = y - ys[i];
    return dx * dx + dy * dy <= shape.radius * shape.radius;
  }
  if (shape.type === ShapeType.Segment) {
    const i = index[offset];
    const j = index[offset + 1];
    const ex = xs[j] - xs[i];
    const ey = ys[j] - ys[i];
    const px = x - xs[i];
    const py = y - ys[i];
    const len2 = ex * ex + ey * ey;
    const t = px * ex + py * ey;
    if (t < 0 || t > len2) return false;
    const c = ex * py - ey * px;
    return c * c <= 1e-24 * len2 * len2;
  }
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + (k + 1 === count ? 0 : k + 1)];
    // Inside is left of every counter-clockwise edge.
    if ((xs[j] - xs[i]) * (y - ys[i]) - (ys[j] - ys[i]) * (x - xs[i]) < 0) return false;
  }
  return true;
}

/**
 * Casts the ray from (ox, oy) along (dx, dy) (any non-zero finite length, 5e-324 to 1.8e308; normalized here) up to
 * `maxDistance` (>= 0, may be Infinity), written into `out`. A ray that starts inside (or on) a polygon or circle
 * hits it at distance 0 with normal −direction; a circle of radius 0 hit from outside also has normal −direction. A
 * ray parallel to a segment misses it. A zero direction misses everything. Throws a TypeError or RangeError naming a
 * coordinate that is not a finite number, or a maxDistance that is negative or NaN.
 */
export function raycast(shape: Shape, ox: number, oy: number, dx: number, dy: number, maxDistance: number, out: RayHit): boolean {
  if (!(Number.isFinite(ox) && Number.isFinite(oy) && Number.isFinite(dx) && Number.isFinite(dy) && maxDistance >= 0)) badRay(ox, oy, dx, dy, maxDistance);
  out.hit = false;
  // Normalised through the larger component: dx² + dy² underflows to 0 for a direction of length 1e-200 and
  // overflows to Infinity for 1e200, while (dx, dy)/m has a length in [1, √2] whatever m is.
  const m = Math.max(Math.abs(dx), Math.abs(dy));
  if (m === 0) return false;
  dx /= m;
  dy /= m;
  const len = Math.sqrt(dx * dx + dy * dy);
  dx /= len;
  dy /= len;
  const { xs, ys, index, offset, count } = shape;
  if (shape.type === ShapeType.Circle) {
    const i = index[offset];
    const cx = xs[i];
    const cy = ys[i];
    const r = shape.radius;
    const mx = ox - cx;
    const my = oy - cy;
    const b = mx * dx + my * dy;
    const c = mx * mx + my * my - r * r;
    if (c <= 0) return inside(out, ox, oy, dx, dy);
    const disc = b * b - c;
    if (disc < 0 || b > 0) return false;
    const t = -b - Math.sqrt(disc);
    if (t > maxDistance) return false;
    out.hit = true;
    out.distance = t;
    out.x = ox + t * dx;
    out.y = oy + t * dy;
    // From the centre to the hit point, measured from the origin (fewer digits lost than x − cx far from (0, 0)).
    // A circle of radius 0 is a point: it faces the ray.
    const hx = mx + t * dx;
    const hy = my + t * dy;
    const hl = Math.sqrt(hx * hx + hy * hy);
    out.normalX = hl > 0 ? hx / hl : -dx;
    out.normalY = hl > 0 ? hy / hl : -dy;
    return true;
  }
  if (shape.type === ShapeType.Segment) {
    const i = index[offset];
    const j = index[offset + 1];
    const ex = xs[j] - xs[i];
    const ey = ys[j] - ys[i];
    const denom = dx * ey - dy * ex; // d × e
    if (denom === 0) return false;
    const wx = xs[i] - ox;
    const wy = ys[i] - oy;
    const t = (wx * ey - wy * ex) / denom; // along the ray
    const s = (wx * dy - wy * dx) / denom; // along the segment
    if (t < 0 || t > maxDistance || s < 0 || s > 1) return false;
    const el = Math.sqrt(ex * ex + ey * ey);
    let nx = ey / el;
    let ny = -ex / el;
    if (nx * dx + ny * dy > 0) {
      nx = -nx;
      ny = -ny;
    }
    out.hit = true;
    out.distance = t;
    out.x = ox + t * dx;
    out.y = oy + t * dy;
    out.normalX = nx;
    out.normalY = ny;
    return true;
  }
  // Polygon: Cyrus–Beck clipping of the ray against the edges' half-planes.
  let lower = 0;
  let upper = maxDistance;
  let edge = -1;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + (k + 1 === count ? 0 : k + 1)];
    const nx = ys[j] - ys[i]; // outward normal (unnormalized)
    const ny = xs[i] - xs[j];
    const num = nx * (xs[i] - ox) + ny * (ys[i] - oy); // >= 0 when the origin is inside this half-plane
    const den = nx * dx + ny * dy;
    if (den === 0) {
      if (num < 0) return false;
    } else if (den < 0) {
      if (num < lower * den) {
        lower = num / den; // entering
        edge = k;
      }
    } else if (num < upper * den) {
      upper = num / den; // leaving
    }
    if (upper < lower) return false;
  }
  if (edge < 0) return inside(out, ox, oy, dx, dy);
  const i = index[offset + edge];
  const j = index[offset + (edge + 1 === count ? 0 : edge + 1)];
  const nx = ys[j] - ys[i];
  const ny = xs[i] - xs[j];
  const nl = Math.sqrt(nx * nx + ny * ny);
  out.hit = true;
  out.distance = lower;
  out.x = ox + lower * dx;
  out.y = oy + lower * dy;
  out.normalX = nx / nl;
  out.normalY = ny / nl;
  return true;
}

/** Names the first bad argument of raycast (kept out of it so the check there stays a few comparisons). */
function badRay(ox: number, oy: number, dx: number, dy: number, maxDistance: number): never {
  finite('ox', ox);
  finite('oy', oy);
  finite('dx', dx);
  finite('dy', dy);
  nonNegativeOrInfinity('maxDistance', maxDistance);
  throw new RangeError(`raycast arguments must be finite numbers, got (${ox}, ${oy}, ${dx}, ${dy}, ${maxDistance})`);
}

function inside(out: RayHit, ox: number, oy: number, dx: number, dy: number): boolean {
  out.hit = true;
  out.distance = 0;
  out.x = ox;
  out.y = oy;
  out.normalX = -dx;
  out.normalY = -dy;
  return true;
}
