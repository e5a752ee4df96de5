// 8-DOP: a discrete oriented polytope with slabs along x, y and the two diagonals (seed 5.1, k-DOP with k = 8).
import type { Shape } from './shape.js';

/**
 * Slab k spans [min[k], max[k]] of the projection p·axis_k, axes (1, 0), (0, 1), (1, 1), (1, −1) (the diagonals
 * unnormalized: the slab bounds are x + y and x − y).
 */
export class KDOP8 {
  min = new Float64Array(4);
  max = new Float64Array(4);
}

/** The tightest 8-DOP around the shape (radius included), written into `out`. */
export function kdopOf(shape: Shape, out: KDOP8 = new KDOP8()): KDOP8 {
  const { xs, ys, index, offset, count, radius } = shape;
  let a0 = Infinity, b0 = -Infinity, a1 = Infinity, b1 = -Infinity, a2 = Infinity, b2 = -Infinity, a3 = Infinity, b3 = -Infinity;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const x = xs[i];
    const y = ys[i];
    const s = x + y;
    const d = x - y;
    if (x < a0) a0 = x;
    if (x > b0) b0 = x;
    if (y < a1) a1 = y;
    if (y > b1) b1 = y;
    if (s < a2) a2 = s;
    if (s > b2) b2 = s;
    if (d < a3) a3 = d;
    if (d > b3) b3 = d;
  }
  const rd = radius * Math.SQRT2; // |axis| = √2 for the diagonals
  out.min[0] = a0 - radius;
  out.max[0] = b0 + radius;
  out.min[1] = a1 - radius;
  out.max[1] = b1 + radius;
  out.min[2] = a2 - rd;
  out.max[2] = b2 + rd;
  out.min[3] = a3 - rd;
  out.max[3] = b3 + rd;
  return out;
}

/** The 8-DOPs overlap or touch: every slab pair overlaps (they are convex, and these are all their facet normals). */
export function kdopOverlap(a: KDOP8, b: KDOP8): boolean {
  const amin = a.min, amax = a.max, bmin = b.min, bmax = b.max;
  for (let k = 0; k < 4; k++) if (amax[k] < bmin[k] || amin[k] > bmax[k]) return false;
  return true;
}

/** (x, y) is inside or on the 8-DOP. */
export function kdopContains(dop: KDOP8, x: number, y: number): boolean {
  const s = x + y;
  const d = x - y;
  return (
    x >= dop.min[0] && x <= dop.max[0] && y >= dop.min[1] && y <= dop.max[1] &&
    s >= dop.min[2] && s <= dop.max[2] && d >= dop.min[3] && d <= dop.max[3]
  );
}
