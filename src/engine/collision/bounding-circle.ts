// Bounding circle (seed 5.1): the minimum enclosing circle, by Welzl's algorithm in its iterative move-to-front form.
import { readPoints, ShapeType, unitScale, type PointLike, type Shape } from './shape.js';

export class BoundingCircle {
  x = 0;
  y = 0;
  r = 0;
}

/** Relative slack of the containment test, so that points on the circle stay inside after rounding. */
const SLACK = 1e-12;

/** The smallest circle around the shape (a circle's own for a circle shape), written into `out`. */
export function boundingCircleOf(shape: Shape, out: BoundingCircle = new BoundingCircle()): BoundingCircle {
  const { xs, ys, index, offset, count } = shape;
  if (shape.type === ShapeType.Circle) {
    const i = index[offset];
    out.x = xs[i];
    out.y = ys[i];
    out.r = shape.radius;
    return out;
  }
  const px = new Float64Array(count);
  const py = new Float64Array(count);
  for (let k = 0; k < count; k++) {
    px[k] = xs[index[offset + k]];
    py[k] = ys[index[offset + k]];
  }
  return minimumCircle(px, py, count, out);
}

/** The smallest circle around `points` ({x, y} objects or a flat number list; at least one). */
export function boundingCircle(points: readonly PointLike[] | readonly number[] | ArrayLike<number>, out: BoundingCircle = new BoundingCircle()): BoundingCircle {
  const { xs, ys } = readPoints('points', points);
  if (xs.length === 0) throw new RangeError('points must hold at least one point, got 0');
  return minimumCircle(xs, ys, xs.length, out);
}

/** Welzl: expected linear time once the points are in random order (a fixed-seed shuffle keeps it reproducible). */
function minimumCircle(xs: Float64Array, ys: Float64Array, n: number, out: BoundingCircle): BoundingCircle {
  // Shuffle a copy (xorshift, fixed seed): polygons arrive in angular order, the worst case for the plain loop.
  let seed = 0x9e3779b9;
  for (let k = n - 1; k > 0; k--) {
    seed ^= seed << 13;
    seed ^= seed >>> 17;
    seed ^= seed << 5;
    const j = (seed >>> 0) % (k + 1);
    const tx = xs[k];
    const ty = ys[k];
    xs[k] = xs[j];
    ys[k] = ys[j];
    xs[j] = tx;
    ys[j] = ty;
  }
  let cx = xs[0];
  let cy = ys[0];
  let r2 = 0;
  const inside = (k: number) => {
    const dx = xs[k] - cx;
    const dy = ys[k] - cy;
    // Relative slack only: an absolute one (it was 1e-300) is the whole r² of points 1e-150 apart, and such a
    // circle came out of radius 0 or around some of the points only.
    return dx * dx + dy * dy <= r2 * (1 + SLACK);
  };
  for (let i = 1; i < n; i++) {
    if (inside(i)) continue;
    cx = xs[i];
    cy = ys[i];
    r2 = 0;
    for (let j = 0; j < i; j++) {
      if (inside(j)) continue;
      cx = (xs[i] + xs[j]) / 2;
      cy = (ys[i] + ys[j]) / 2;
      r2 = ((xs[i] - xs[j]) ** 2 + (ys[i] - ys[j]) ** 2) / 4;
      for (let k = 0; k < j; k++) {
        if (inside(k)) continue;
        // Circle through i, j, k (k lies outside the circle on diameter ij, so they are not collinear in exact
        // arithmetic; if rounding makes them so, the diameter of the farthest pair is the answer).
        // In units of the offsets (by a power of two, exactly): the circumcentre multiplies three lengths, and points
        // 1e-120 apart gave a circle of radius 0 (underflow), points 1e120 apart one at Infinity.
        const ax = xs[i], ay = ys[i];
        const s = unitScale(
          Math.max(Math.abs(xs[j] - ax), Math.abs(ys[j] - ay), Math.abs(xs[k] - ax), Math.abs(ys[k] - ay)),
        );
        const bx = (xs[j] - ax) * s, by = (ys[j] - ay) * s;
        const qx = (xs[k] - ax) * s, qy = (ys[k] - ay) * s;
        const d = 2 * (bx * qy - by * qx);
        const b2 = bx * bx + by * by;
        const q2 = qx * qx + qy * qy;
        if (d !== 0) {
          const ux = (qy * b2 - by * q2) / d / s;
          const uy = (bx * q2 - qx * b2) / d / s;
          cx = ax + ux;
          cy = ay + uy;
          r2 = ux * ux + uy * uy;
        } else {
          const pairs: [number, number][] = [[i, j], [i, k], [j, k]];
          let best = -1;
          for (const [p, q] of pairs) {
            const dd = (xs[p] - xs[q]) ** 2 + (ys[p] - ys[q]) ** 2;
            if (dd > best) {
              best = dd;
              cx = (xs[p] + xs[q]) / 2;
              cy = (ys[p] + ys[q]) / 2;
              r2 = dd / 4;
            }
          }
        }
      }
    }
  }
  out.x = cx;
  out.y = cy;
  out.r = Math.sqrt(r2);
  return out;
}

/** The circles overlap or touch. */
export function boundingCircleOverlap(a: BoundingCircle, b: BoundingCircle): boolean {
  const dx = b.x - a.x;
  const dy = b.y - a.y;
  const r = a.r + b.r;
  return dx * dx + dy * dy <= r * r;
}
