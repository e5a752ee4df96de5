// Concave outlines (seed 2.8): a simple polygon as a union of convex parts, by ear clipping then Hertel–Mehlhorn
// (drop every diagonal whose removal keeps both sides convex: at most 4× the optimal number of parts, and at most
// 2r + 1 parts for r reflex vertices). Setup-time code: it allocates, and it is O(n²).
import { polygon, readPoints, type PointLike, type Shape } from './shape.js';

type Points = readonly PointLike[] | readonly number[] | ArrayLike<number>;

interface Prepared {
  xs: Float64Array;
  ys: Float64Array;
  /** Vertices with a real corner (no 180° ones), counter-clockwise, as indices into the input. */
  corners: number[];
  /** For corner k, the straight (180°) input vertices between it and the next corner, in order. */
  between: number[][];
}

/** Validates a simple polygon and orders it counter-clockwise; throws a RangeError naming `points` otherwise. */
function prepare(points: Points): Prepared {
  const { xs, ys } = readPoints('points', points);
  const n = xs.length;
  if (n < 3) throw new RangeError(`points must have at least 3 points, got ${n}`);
  let area2 = 0;
  for (let k = 0; k < n; k++) {
    const j = (k + 1) % n;
    if (xs[k] === xs[j] && ys[k] === ys[j]) throw new RangeError(`points[${j}] repeats points[${k}] (${xs[k]}, ${ys[k]})`);
    area2 += xs[k] * ys[j] - xs[j] * ys[k];
  }
  if (!(area2 !== 0)) throw new RangeError(`points must enclose a non-zero area, got area 0`);
  checkSimple(xs, ys);
  const order: number[] = [];
  for (let k = 0; k < n; k++) order.push(area2 > 0 ? k : n - 1 - k);
  const turn = (p: number, q: number, r: number) => (xs[q] - xs[p]) * (ys[r] - ys[q]) - (ys[q] - ys[p]) * (xs[r] - xs[q]);
  const straight = order.map((v, k) => turn(order[(k + n - 1) % n], v, order[(k + 1) % n]) === 0);
  const corners: number[] = [];
  const between: number[][] = [];
  // Start at a corner so that the straight vertices after the last corner close the loop.
  const start = straight.indexOf(false);
  for (let s = 0; s < n; s++) {
    const k = (start + s) % n;
    if (!straight[k]) {
      corners.push(order[k]);
      between.push([]);
    } else {
      between[between.length - 1].push(order[k]);
    }
  }
  return { xs, ys, corners, between };
}

/**
 * Throws when two edges of the closed outline cross, touch, or overlap (other than neighbours at their shared end);
 * `name` is the argument the message names. A pentagram turns the same way at every corner, so only this finds it.
 */
export function checkSimple(xs: ArrayLike<number>, ys: ArrayLike<number>, name = 'points'): void {
  const n = xs.length;
  const orient = (a: number, b: number, c: number) => {
    const v = (xs[b] - xs[a]) * (ys[c] - ys[a]) - (ys[b] - ys[a]) * (xs[c] - xs[a]);
    return v > 0 ? 1 : v < 0 ? -1 : 0;
  };
  const onSegment = (a: number, b: number, p: number) =>
    Math.min(xs[a], xs[b]) <= xs[p] && xs[p] <= Math.max(xs[a], xs[b]) && Math.min(ys[a], ys[b]) <= ys[p] && ys[p] <= Math.max(ys[a], ys[b]);
  for (let i = 0; i < n; i++) {
    const i2 = (i + 1) % n;
    for (let j = i + 1; j < n; j++) {
      const j2 = (j + 1) % n;
      if (j === i2 || j2 === i) {
        // Neighbours share one end; they must not fold back onto each other.
        const shared = j === i2 ? i2 : i;
        const p = shared === i2 ? i : i2; // far end of edge i
        const q = shared === i2 ? j2 : j; // far end of edge j
        if (orient(p, shared, q) === 0 && (xs[p] - xs[shared]) * (xs[q] - xs[shared]) + (ys[p] - ys[shared]) * (ys[q] - ys[shared]) > 0) {
          throw new RangeError(`${name} must form a simple polygon, but edges ${i} and ${j} fold back onto each other at ${name}[${shared}]`);
        }
        continue;
      }
      const o1 = orient(i, i2, j);
      const o2 = orient(i, i2, j2);
      const o3 = orient(j, j2, i);
      const o4 = orient(j, j2, i2);
      const cross =
        (o1 * o2 < 0 && o3 * o4 < 0) ||
        (o1 === 0 && onSegment(i, i2, j)) ||
        (o2 === 0 && onSegment(i, i2, j2)) ||
        (o3 === 0 && onSegment(j, j2, i)) ||
        (o4 === 0 && onSegment(j, j2, i2));
      if (cross) throw new RangeError(`${name} must form a simple polygon, but edge ${i}–${i2} meets edge ${j}–${j2}`);
    }
  }
}

/**
 * Triangulates the corners of a prepared polygon by ear clipping. Returns triangles (counter-clockwise, as input
 * indices) and the diagonals it drew.
 */
function earClip(p: Prepared): { triangles: number[][]; diagonals: [number, number][] } {
  const { xs, ys, corners } = p;
  const m = corners.length;
  const prev = new Int32Array(m);
  const next = new Int32Array(m);
  for (let k = 0; k < m; k++) {
    prev[k] = (k + m - 1) % m;
    next[k] = (k + 1) % m;
  }
  const X = (k: number) => xs[corners[k]];
  const Y = (k: number) => ys[corners[k]];
  const turn = (a: number, b: number, c: number) => (X(b) - X(a)) * (Y(c) - Y(b)) - (Y(b) - Y(a)) * (X(c) - X(b));
  const alive = new Uint8Array(m).fill(1);
  // A vertex that is not strictly convex (reflex, or straight after clipping) may block an ear.
  const blocks = (k: number) => turn(prev[k], k, next[k]) <= 0;
  const inTriangle = (a: number, b: number, c: number, q: number) => {
    // Inside or on the boundary of the counter-clockwise triangle abc.
    const px = X(q), py = Y(q);
    const s1 = (X(b) - X(a)) * (py - Y(a)) - (Y(b) - Y(a)) * (px - X(a));
    const s2 = (X(c) - X(b)) * (py - Y(b)) - (Y(c) - Y(b)) * (px - X(b));
    const s3 = (X(a) - X(c)) * (py - Y(c)) - (Y(a) - Y(c)) * (px - X(c));
    return s1 >= 0 && s2 >= 0 && s3 >= 0;
  };
  const isEar = (k: number) => {
    const a = prev[k];
    const c = next[k];
    if (turn(a, k, c) <= 0) return false;
    for (let q = next[c]; q !== a; q = next[q]) {
      if (blocks(q) && inTriangle(a, k, c, q) && !(X(q) === X(a) && Y(q) === Y(a)) && !(X(q) === X(c) && Y(q) === Y(c))) return false;
    }
    return true;
  };
  const triangles: number[][] = [];
  const diagonals: [number, number][] = [];
  let left = m;
  let k = 0;
  let misses = 0;
  while (left > 3) {
    if (!isEar(k)) {
      k = next[k];
      if (++misses <= left) continue;
      // No ear found in a full turn: only rounding can do this. Clip the most convex corner and go on.
      let bestK = -1;
      let best = 0;
      let q = k;
      for (let s = 0; s < left; s++, q = next[q]) {
        const t = turn(prev[q], q, next[q]);
        if (t > best) {
          best = t;
          bestK = q;
        }
      }
      if (bestK < 0) throw new RangeError('points: ear clipping found no convex corner (is the polygon degenerate?)');
      k = bestK;
    }
    const a = prev[k];
    const c = next[k];
    triangles.push([corners[a], corners[k], corners[c]]);
    diagonals.push([corners[a], corners[c]]);
    next[a] = c;
    prev[c] = a;
    alive[k] = 0;
    left--;
    misses = 0;
    k = c;
  }
  const a = k;
  triangles.push([corners[prev[a]], corners[a], corners[next[a]]]);
  return { triangles, diagonals };
}

/** Hertel–Mehlhorn: merges triangles across diagonals while both ends of the diagonal stay convex. */
function mergeParts(xs: Float64Array, ys: Float64Array, triangles: number[][], diagonals: [number, number][]): number[][] {
  const parts: (number[] | null)[] = triangles.map((t) => t.slice());
  const owner = new Map<string, number>(); // directed edge "u,w" → part
  const key = (u: number, w: number) => `${u},${w}`;
  parts.forEach((part, id) => part!.forEach((v, k) => owner.set(key(v, part![(k + 1) % part!.length]), id)));
  const turn = (p: number, q: number, r: number) => (xs[q] - xs[p]) * (ys[r] - ys[q]) - (ys[q] - ys[p]) * (xs[r] - xs[q]);
  for (const [u, w] of diagonals) {
    const pi = owner.get(key(u, w));
    const qi = owner.get(key(w, u));
    if (pi === undefined || qi === undefined || pi === qi) continue;
    const P = parts[pi]!;
    const Q = parts[qi]!;
    // P = [..., u, w, ...] → [w, ..., u]; Q = [..., w, u, ...] → [u, q1, ..., w].
    const pu = P.indexOf(u);
    const pw = (pu + 1) % P.length;
    const Pw = P.slice(pw).concat(P.slice(0, pw));
    const qw = Q.indexOf(w);
    const qu = (qw + 1) % Q.length;
    const Qu = Q.slice(qu).concat(Q.slice(0, qu));
    const atU = turn(Pw[Pw.length - 2], u, Qu[1]);
    const atW = turn(Qu[Qu.length - 2], w, Pw[1]);
    if (atU < 0 || atW < 0) continue;
    const merged = Pw.concat(Qu.slice(1, -1));
    parts[pi] = merged;
    parts[qi] = null;
    merged.forEach((v, k) => owner.set(key(v, merged[(k + 1) % merged.length]), pi));
    owner.delete(key(u, w));
    owner.delete(key(w, u));
  }
  return parts.filter((p): p is number[] => p !== null);
}

/**
 * Splits a simple polygon (any orientation, convex or not, at least 3 points, no repeated consecutive points, no
 * crossing or touching edges) into convex parts. Returns each part as a counter-clockwise list of indices into
 * `points`. Every input point is a vertex of some part: straight (180°) vertices stay on the part that holds their
 * edge. Throws a RangeError naming `points` for invalid input.
 */
export function decompose(points: Points): number[][] {
  const p = prepare(points);
  const { xs, ys, corners, between } = p;
  let parts: number[][];
  if (corners.length === 3) {
    parts = [corners.slice()];
  } else {
    const { triangles, diagonals } = earClip(p);
    parts = mergeParts(xs, ys, triangles, diagonals);
  }
  // Put the straight vertices back on the boundary edges they lie on (corner k → corner k + 1).
  const nextCorner = new Map<number, number>();
  const after = new Map<number, number[]>();
  corners.forEach((c, k) => {
    nextCorner.set(c, corners[(k + 1) % corners.length]);
    after.set(c, between[k]);
  });
  const out: number[][] = [];
  for (const part of parts) {
    const full: number[] = [];
    part.forEach((v, k) => {
      full.push(v);
      if (nextCorner.get(v) === part[(k + 1) % part.length]) full.push(...after.get(v)!);
    });
    // A part of zero area (rounding in a near-degenerate outline) adds nothing: leave it out.
    let a2 = 0;
    for (let k = 0; k < full.length; k++) {
      const i = full[k];
      const j = full[(k + 1) % full.length];
      a2 += xs[i] * ys[j] - xs[j] * ys[i];
    }
    if (a2 > 0) out.push(full);
  }
  return out;
}

/** Ear-clipping triangulation of a simple polygon: triangles as counter-clockwise index triples into `points`. */
export function triangulate(points: Points): number[][] {
  const p = prepare(points);
  if (p.corners.length === 3) return [p.corners.slice()];
  return earClip(p).triangles;
}

/** decompose(), with each part made into a standalone convex polygon shape. */
export function decomposeToShapes(points: Points): Shape[] {
  const { xs, ys } = readPoints('points', points);
  return decompose(points).map((part) => polygon(part.map((i) => ({ x: xs[i], y: ys[i] }))));
}
