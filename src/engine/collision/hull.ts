// Convex hull by quickhull (seed 5.1, Algorithm 8), robust to duplicate and collinear points: only points strictly
// outside a hull edge are kept, so duplicates and points on edges never become vertices.
import { readPoints, type PointLike } from './shape.js';

/**
 * Indices of the convex hull's vertices, counter-clockwise, starting at the lowest-x (then lowest-y) point.
 * Collinear and repeated points are left out; fewer than 3 indices when all points are collinear (2) or equal (1).
 */
export function quickhullIndices(xs: ArrayLike<number>, ys: ArrayLike<number>, count = xs.length): Int32Array {
  if (count === 0) return new Int32Array(0);
  let lo = 0;
  let hi = 0;
  for (let k = 1; k < count; k++) {
    if (xs[k] < xs[lo] || (xs[k] === xs[lo] && ys[k] < ys[lo])) lo = k;
    if (xs[k] > xs[hi] || (xs[k] === xs[hi] && ys[k] > ys[hi])) hi = k;
  }
  if (xs[lo] === xs[hi] && ys[lo] === ys[hi]) return Int32Array.of(lo);
  // Points strictly right of lo → hi (the lower chain) and of hi → lo (the upper chain).
  const below: number[] = [];
  const above: number[] = [];
  for (let k = 0; k < count; k++) {
    const c = cross(xs, ys, lo, hi, k);
    if (c < 0) below.push(k);
    else if (c > 0) above.push(k);
  }
  const out: number[] = [lo];
  expand(xs, ys, lo, hi, below, out);
  out.push(hi);
  expand(xs, ys, hi, lo, above, out);
  return Int32Array.from(out);
}

/** (b − a) × (p − a): positive when p is left of a → b. */
function cross(xs: ArrayLike<number>, ys: ArrayLike<number>, a: number, b: number, p: number): number {
  return (xs[b] - xs[a]) * (ys[p] - ys[a]) - (ys[b] - ys[a]) * (xs[p] - xs[a]);
}

/**
 * Appends, in order from a to b, the hull vertices strictly right of a → b among `set` (all strictly right of it).
 * Iterative (an explicit stack) so that adversarial inputs cannot overflow the call stack.
 */
function expand(xs: ArrayLike<number>, ys: ArrayLike<number>, a0: number, b0: number, set0: number[], out: number[]): void {
  // Work items: [a, b, set] to expand, or a vertex to emit (set = null).
  const stack: { a: number; b: number; set: number[] | null }[] = [{ a: a0, b: b0, set: set0 }];
  while (stack.length > 0) {
    const { a, b, set } = stack.pop()!;
    if (set === null) {
      out.push(a);
      continue;
    }
    if (set.length === 0) continue;
    // Farthest point from the line (most negative cross). Ties lie on a parallel of ab: take the one nearest a, an
    // end of that run, so the run's middle points fall on the hull edge between its ends and are dropped.
    const ux = xs[b] - xs[a];
    const uy = ys[b] - ys[a];
    let c = set[0];
    let best = cross(xs, ys, a, b, c);
    for (let k = 1; k < set.length; k++) {
      const p = set[k];
      const v = cross(xs, ys, a, b, p);
      if (v < best || (v === best && (xs[p] - xs[c]) * ux + (ys[p] - ys[c]) * uy < 0)) {
        best = v;
        c = p;
      }
    }
    const left: number[] = [];
    const right: number[] = [];
    for (const p of set) {
      if (p === c) continue;
      if (cross(xs, ys, a, c, p) < 0) left.push(p);
      else if (cross(xs, ys, c, b, p) < 0) right.push(p);
    }
    // Emit order: expand(a, c), c, expand(c, b): pushed in reverse.
    stack.push({ a: c, b, set: right });
    stack.push({ a: c, b: c, set: null });
    stack.push({ a, b: c, set: left });
  }
}

/** Convex hull of `points` ({x, y} objects or a flat number list) as new points, counter-clockwise. */
export function quickhull(points: readonly PointLike[] | readonly number[] | ArrayLike<number>): PointLike[] {
  const { xs, ys } = readPoints('points', points);
  const idx = quickhullIndices(xs, ys);
  const out: PointLike[] = [];
  for (let k = 0; k < idx.length; k++) out.push({ x: xs[idx[k]], y: ys[idx[k]] });
  return out;
}
