// Module-level scratch storage shared by the narrow-phase functions (single-threaded: each worker has its own
// module instance). Arrays grow by doubling when a larger polygon comes by, so the steady state never allocates.
import type { Shape } from './shape.js';

export let ax = new Float64Array(64);
export let ay = new Float64Array(64);
export let bx = new Float64Array(64);
export let by = new Float64Array(64);

function grow(n: number): void {
  let size = ax.length;
  while (size < n) size *= 2;
  ax = new Float64Array(size);
  ay = new Float64Array(size);
  bx = new Float64Array(size);
  by = new Float64Array(size);
}

/** Copies A's vertices into ax/ay and B's into bx/by (contiguous, no index indirection in the O(n·m) loops). */
export function load(a: Shape, b: Shape): void {
  const n = a.count > b.count ? a.count : b.count;
  if (n > ax.length) grow(n);
  const { xs, ys, index, offset, count } = a;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    ax[k] = xs[i];
    ay[k] = ys[i];
  }
  const bxs = b.xs;
  const bys = b.ys;
  const bi = b.index;
  const bo = b.offset;
  for (let k = 0, m = b.count; k < m; k++) {
    const i = bi[bo + k];
    bx[k] = bxs[i];
    by[k] = bys[i];
  }
}

/**
 * A vertex is on a face's line when it is this close to it, relative to its distance along the face: a run of
 * collinear edges (180° corners, straight up to rounding) then acts as one face. Far from the origin the rounding of
 * the coordinates themselves is allowed for as well (FACE_ROUNDING times their magnitude).
 */
export const FACE_TOLERANCE = 1e-10;
const FACE_ROUNDING = 16 * Number.EPSILON;

/**
 * (dx, dy) from a face's vertex runs along the face line of unit normal ±(nx, ny), within tolerance; `rounding` is
 * FACE_ROUNDING times that vertex's coordinate magnitude (the other's is the same to within |dx| + |dy|, which the
 * relative term already allows many times over).
 */
function onFaceLine(dx: number, dy: number, rounding: number, nx: number, ny: number): boolean {
  const d = nx * dx + ny * dy;
  const tol = FACE_TOLERANCE * (Math.abs(dx) + Math.abs(dy)) + rounding;
  return d <= tol && d >= -tol;
}

/** Result registers of faceEnds: the first and last vertex of a face, counter-clockwise. */
export const face = { first: 0, last: 0 };

/**
 * The face of polygon P (n vertices, counter-clockwise; a segment has 2) through vertices first..last (an edge, or a
 * single vertex with first === last) whose outward normal is ±(nx, ny), grown over the neighbouring vertices on its
 * line (measured from vertex `first`): the whole collinear run, into face.first/last. At most all n vertices.
 */
export function faceEnds(px: Float64Array, py: Float64Array, n: number, first: number, last: number, nx: number, ny: number): void {
  const x0 = px[first];
  const y0 = py[first];
  const rounding = FACE_ROUNDING * (Math.abs(x0) + Math.abs(y0));
  let size = last >= first ? last - first + 1 : last + n - first + 1;
  while (size < n) {
    const k = first === 0 ? n - 1 : first - 1;
    if (!onFaceLine(px[k] - x0, py[k] - y0, rounding, nx, ny)) break;
    first = k;
    size++;
  }
  while (size < n) {
    const k = last + 1 === n ? 0 : last + 1;
    if (!onFaceLine(px[k] - x0, py[k] - y0, rounding, nx, ny)) break;
    last = k;
    size++;
  }
  face.first = first;
  face.last = last;
}

/** Whether vertex v of polygon P (n vertices) has a neighbour on the line through it with normal ±(nx, ny): a face. */
export function onFace(px: Float64Array, py: Float64Array, n: number, v: number, nx: number, ny: number): boolean {
  if (n < 2) return false;
  const prev = v === 0 ? n - 1 : v - 1;
  const next = v + 1 === n ? 0 : v + 1;
  return neighbourOnLine(px[v], py[v], px[prev], py[prev], px[next], py[next], nx, ny);
}

/** Whether (px, py) or (qx, qy) lies on the line through (x, y) with normal ±(nx, ny), within the face tolerance. */
export function neighbourOnLine(x: number, y: number, px: number, py: number, qx: number, qy: number, nx: number, ny: number): boolean {
  const rounding = FACE_ROUNDING * (Math.abs(x) + Math.abs(y));
  return onFaceLine(px - x, py - y, rounding, nx, ny) || onFaceLine(qx - x, qy - y, rounding, nx, ny);
}

/** Result registers of faceMidpoint: a point of A's outline and the point of B's outline opposite it. */
export const mid = { ax: 0, ay: 0, bx: 0, by: 0 };

/**
 * Where A's face a0..a1 (loaded in ax/ay, outward normal n) and B's face b0..b1 (in bx/by, outward normal about −n)
 * overlap along the face direction t = (−ny, nx): at the middle of that interval, the point of A's face and the point
 * of B's face, into `mid`. Only the faces' ends are read, so the answer does not depend on where either list starts.
 * For faces that do not overlap (by rounding), the middle of the gap.
 */
export function faceMidpoint(a0: number, a1: number, b0: number, b1: number, nx: number, ny: number): void {
  const tx = -ny;
  const ty = nx;
  // A's face runs along +t, B's along −t (both counter-clockwise).
  const aLo = tx * ax[a0] + ty * ay[a0];
  const aHi = tx * ax[a1] + ty * ay[a1];
  const bHi = tx * bx[b0] + ty * by[b0];
  const bLo = tx * bx[b1] + ty * by[b1];
  const t = 0.5 * ((aLo > bLo ? aLo : bLo) + (aHi < bHi ? aHi : bHi));
  let u = aHi > aLo ? (t - aLo) / (aHi - aLo) : 0;
  u = u < 0 ? 0 : u > 1 ? 1 : u;
  mid.ax = ax[a0] + u * (ax[a1] - ax[a0]);
  mid.ay = ay[a0] + u * (ay[a1] - ay[a0]);
  u = bHi > bLo ? (bHi - t) / (bHi - bLo) : 0;
  u = u < 0 ? 0 : u > 1 ? 1 : u;
  mid.bx = bx[b0] + u * (bx[b1] - bx[b0]);
  mid.by = by[b0] + u * (by[b1] - by[b0]);
}

/** Result registers of maxSeparation. */
export const sep = { value: 0, edge: -1, vertex: -1, nx: 0, ny: 0 };

/**
 * Box2D's b2FindMaxSeparation on raw arrays: over the edges of polygon P (CCW, n vertices; n = 2 for a segment)
 * and their outward unit normals, the largest separation min_k n·(q_k − p_i) of polygon Q. These normals are the
 * facets of the Minkowski difference P − Q that belong to P, so −max over both polygons is the penetration depth.
 * Stops early at a separation >= stop (0 for a plain overlap test: separated or touching). Zero-length edges are skipped; with none left,
 * sep.value is −Infinity.
 */
export function maxSeparation(px: Float64Array, py: Float64Array, n: number, qx: Float64Array, qy: Float64Array, m: number, stop: number): void {
  let best = -Infinity;
  let bestEdge = -1;
  let bestVertex = -1;
  let bnx = 0;
  let bny = 0;
  for (let i = 0; i < n; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    const ex = px[j] - px[i];
    const ey = py[j] - py[i];
    const len2 = ex * ex + ey * ey;
    if (len2 === 0) continue;
    const inv = 1 / Math.sqrt(len2);
    const nx = ey * inv;
    const ny = -ex * inv;
    let min = Infinity;
    let arg = 0;
    for (let k = 0; k < m; k++) {
      const d = nx * qx[k] + ny * qy[k];
      if (d < min) {
        min = d;
        arg = k;
      }
    }
    const s = min - (nx * px[i] + ny * py[i]);
    // Exact ties (a square against itself) go to the larger normal (x, then y), not to the first edge in the list,
    // so the answer does not depend on which vertex a polygon's list starts from.
    if (s > best || (s === best && (nx > bnx || (nx === bnx && ny > bny)))) {
      best = s;
      bestEdge = i;
      bestVertex = arg;
      bnx = nx;
      bny = ny;
      if (s >= stop) break;
    }
  }
  sep.value = best;
  sep.edge = bestEdge;
  sep.vertex = bestVertex;
  sep.nx = bnx;
  sep.ny = bny;
}

/**
 * The edge of polygon P (or segment) the point (cx, cy) is furthest outside of: into sep.value/edge/nx/ny, as
 * maxSeparation with Q a single point. Stops at the first separation >= stop; with no edge of positive length
 * sep.value is −Infinity and sep.edge −1.
 */
export function pointSeparation(p: Shape, cx: number, cy: number, stop: number): void {
  const { xs, ys, index, offset, count } = p;
  let best = -Infinity;
  let bestEdge = -1;
  let bnx = 0;
  let bny = 0;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + (k + 1 === count ? 0 : k + 1)];
    const ex = xs[j] - xs[i];
    const ey = ys[j] - ys[i];
    const len2 = ex * ex + ey * ey;
    if (len2 === 0) continue;
    const inv = 1 / Math.sqrt(len2);
    const nx = ey * inv;
    const ny = -ex * inv;
    const s = nx * (cx - xs[i]) + ny * (cy - ys[i]);
    if (s > best) {
      best = s;
      bestEdge = k;
      bnx = nx;
      bny = ny;
      if (s >= stop) break;
    }
  }
  sep.value = best;
  sep.edge = bestEdge;
  sep.nx = bnx;
  sep.ny = bny;
}

/** Result registers of nearestFeature. */
export const near = { nx: 0, ny: 0, distance: 0, edge: -1, alpha: 0 };

/**
 * Where a circle's centre (cx, cy) meets polygon P (or segment): into `near`, the unit normal from P towards the centre,
 * the centre's signed distance from P along it (negative inside: then the nearest edge's normal), the edge and where
 * along it (alpha in [0, 1]; 0 or 1 in a vertex region, where the normal runs from that vertex). False when the centre
 * is `reach` or more away, or P has no edge of positive length (near.edge is then −1).
 */
export function nearestFeature(p: Shape, cx: number, cy: number, reach: number): boolean {
  pointSeparation(p, cx, cy, reach);
  near.edge = sep.edge;
  if (sep.edge < 0 || sep.value >= reach) return false;
  const { xs, ys, index, offset, count } = p;
  const i1 = index[offset + sep.edge];
  const i2 = index[offset + (sep.edge + 1 === count ? 0 : sep.edge + 1)];
  const x1 = xs[i1];
  const y1 = ys[i1];
  const ex = xs[i2] - x1;
  const ey = ys[i2] - y1;
  const alpha = ((cx - x1) * ex + (cy - y1) * ey) / (ex * ex + ey * ey);
  near.nx = sep.nx;
  near.ny = sep.ny;
  near.distance = sep.value;
  near.alpha = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
  if (sep.value > 0 && (alpha <= 0 || alpha >= 1)) {
    const dx = cx - (x1 + near.alpha * ex);
    const dy = cy - (y1 + near.alpha * ey);
    const d = Math.sqrt(dx * dx + dy * dy);
    if (d >= reach) return false;
    // d = 0: the centre is on the vertex (its separation from the edge was rounding, or d² underflowed), and the
    // edge's normal serves: any normal of the corner gives the same overlap, the radius (0/0 gave a NaN normal).
    if (d > 0) {
      near.nx = dx / d;
      near.ny = dy / d;
    }
    near.distance = d;
  }
  return true;
}
