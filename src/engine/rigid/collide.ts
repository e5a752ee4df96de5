// Contact manifolds for rigid bodies, in world coordinates: convex polygon vs polygon (reference face by the
// separating axis, incident edge clipped to its side planes, as Box2D's b2CollidePolygons), polygon vs circle and
// circle vs circle. Each point is a pair of points, one on each outline, with pA − pB = depth · n (n from A to B;
// depth < 0 for a speculative point within `margin`), and, for B, the edge it lies on and where along it (a
// particle-built outline turns that into the two particles it moves).
//
// Polygons here are strictly convex and counter-clockwise with unit outward normals given (a rigid shape merges
// collinear vertices once, when it is built); everything runs on caller-owned arrays and allocates nothing.

/** Up to two contact points of one pair of convex shapes. */
export class ContactManifold {
  /**
   * The query's reals, written by the caller (a typed array: V8 boxes a double passed to a call it does not inline,
   * and the narrow phase tests thousands of pairs a step): [0] margin; for circles [1, 2, 3] centre and radius of the
   * circle (A's in collideCircles), [4, 5, 6] B's circle in collideCircles; in collidePolygonCircle [7, 8] the
   * circle's velocity relative to the polygon and [9] how far ahead to sweep it (0: not at all).
   */
  readonly query = new Float64Array(10);
  count = 0;
  /** Unit normal from A to B. */
  nx = 0;
  ny = 0;
  pAx = new Float64Array(2);
  pAy = new Float64Array(2);
  pBx = new Float64Array(2);
  pBy = new Float64Array(2);
  depth = new Float64Array(2);
  /** B's edge (vertex k to k + 1) the point lies on and the fraction along it; edge −1 for a circle. */
  edgeB = new Int32Array(2);
  alphaB = new Float64Array(2);
  /**
   * Which features made each point (reference face, incident edge, which end of the clip, which side was the
   * reference), the same from step to step while the bodies keep touching the same way: friction anchors persist by it.
   */
  feature = new Int32Array(2);
}

/** A convex polygon as views into vertex and normal arrays: vertices [start, start + count). */
export interface PolygonRef {
  x: Float64Array;
  y: Float64Array;
  nx: Float64Array;
  ny: Float64Array;
  start: number;
  count: number;
  /**
   * Per vertex (rigid/seams.ts): INTERNAL_FACE when the face from it to the next is inside a static floor of flush
   * pieces. Null or absent when no face is.
   */
  internal?: Uint8Array | null;
}

/** PolygonRef.internal's bit for a seam face. */
export const INTERNAL_FACE = 1;

/** The reference face is B's only when its separation beats A's by this much (so it does not flicker on ties). */
const REFERENCE_TOLERANCE = 5e-4;

/** Result scratch of maxSeparation (a double returned from a call that is not inlined is boxed). */
const found = new Float64Array(2);

/**
 * The largest over P's edges of the smallest signed distance of Q's vertices to it, into found[0]; the edge into
 * found[1]. Stops early once an edge separates by more than the margin, query[0] (the pair is apart: the caller only
 * reads that found[0] > margin), and leaves an edge's vertex loop once it cannot beat the best edge so far (the result
 * is the same: only an edge whose smallest distance is larger replaces the best). The margin is read here, not passed:
 * a double passed to a call V8 does not inline is boxed, and when one of collidePolygons' two calls was not inlined
 * S2's 1000 boxes allocated 30 KB a step (one heap number a polygon pair) and spent ~4% of the step collecting it.
 */
function maxSeparation(P: PolygonRef, Q: PolygonRef, query: Float64Array): void {
  const margin = query[0];
  let best = -Infinity;
  let bestEdge = 0;
  const { x: px, y: py, nx: pnx, ny: pny } = P;
  const { x: qx, y: qy } = Q;
  const qs = Q.start;
  const qe = qs + Q.count;
  if (Q.count === 4) {
    // A quadrilateral (boxes, most of a pile): its vertices in locals, the same distances in the same order.
    const q0x = qx[qs];
    const q0y = qy[qs];
    const q1x = qx[qs + 1];
    const q1y = qy[qs + 1];
    const q2x = qx[qs + 2];
    const q2y = qy[qs + 2];
    const q3x = qx[qs + 3];
    const q3y = qy[qs + 3];
    for (let i = 0; i < P.count; i++) {
      const k = P.start + i;
      const nx = pnx[k];
      const ny = pny[k];
      const vx = px[k];
      const vy = py[k];
      let min = Infinity;
      edge: {
        let d = (q0x - vx) * nx + (q0y - vy) * ny;
        if (d < min) {
          min = d;
          if (min <= best) break edge;
        }
        d = (q1x - vx) * nx + (q1y - vy) * ny;
        if (d < min) {
          min = d;
          if (min <= best) break edge;
        }
        d = (q2x - vx) * nx + (q2y - vy) * ny;
        if (d < min) {
          min = d;
          if (min <= best) break edge;
        }
        d = (q3x - vx) * nx + (q3y - vy) * ny;
        if (d < min) min = d;
      }
      if (min > best) {
        best = min;
        bestEdge = i;
        if (best > margin) break;
      }
    }
    found[0] = best;
    found[1] = bestEdge;
    return;
  }
  for (let i = 0; i < P.count; i++) {
    const k = P.start + i;
    const nx = pnx[k];
    const ny = pny[k];
    const vx = px[k];
    const vy = py[k];
    let min = Infinity;
    for (let j = qs; j < qe; j++) {
      const d = (qx[j] - vx) * nx + (qy[j] - vy) * ny;
      if (d < min) {
        min = d;
        if (min <= best) break;
      }
    }
    if (min > best) {
      best = min;
      bestEdge = i;
      if (best > margin) break;
    }
  }
  found[0] = best;
  found[1] = bestEdge;
}

export function collidePolygons(A: PolygonRef, B: PolygonRef, out: ContactManifold): boolean {
  out.count = 0;
  const margin = out.query[0];
  maxSeparation(A, B, out.query);
  const sepA = found[0];
  if (sepA > margin) return false;
  const edgeA = found[1];
  maxSeparation(B, A, out.query);
  const sepB = found[0];
  if (sepB > margin) return false;
  const edgeB = found[1];
  const bRefers = sepB > sepA + REFERENCE_TOLERANCE;
  if ((A.internal || B.internal) && (bRefers ? seamAxis(B, edgeB, A) : seamAxis(A, edgeA, B))) return clipAcrossSeam(A, B, out);
  if (bRefers) return clip(B, edgeB, A, true, out);
  return clip(A, edgeA, B, false, out);
}

/**
 * Whether P's face e is an internal face (a seam: rigid/seams.ts), or faces one of Q's within 60°: the axis a box
 * sliding over a join of flush static pieces meets the second piece by. Only a body that sank into the first piece
 * can be there, and the floor's top is the contact it has.
 */
function seamAxis(P: PolygonRef, e: number, Q: PolygonRef): boolean {
  if (P.internal && (P.internal[P.start + e] & INTERNAL_FACE) !== 0) return true;
  const seams = Q.internal;
  if (!seams) return false;
  const nx = P.nx[P.start + e];
  const ny = P.ny[P.start + e];
  for (let k = Q.start, end = Q.start + Q.count; k < end; k++) if ((seams[k] & INTERNAL_FACE) !== 0 && nx * Q.nx[k] + ny * Q.ny[k] < -0.5) return true;
  return false;
}

/**
 * collidePolygons for a pair within the margin whose axis of largest separation is a seam's: the same, from the other
 * axes. (The pair is apart only when some axis says so, and collidePolygons returned before: no contact is made
 * where the bodies are apart.)
 */
function clipAcrossSeam(A: PolygonRef, B: PolygonRef, out: ContactManifold): boolean {
  let sepA = -Infinity;
  let edgeA = -1;
  let sepB = -Infinity;
  let edgeB = -1;
  for (let e = 0; e < A.count; e++) {
    if (seamAxis(A, e, B)) continue;
    const s = separation(A, e, B);
    if (s > sepA) (sepA = s), (edgeA = e);
  }
  for (let e = 0; e < B.count; e++) {
    if (seamAxis(B, e, A)) continue;
    const s = separation(B, e, A);
    if (s > sepB) (sepB = s), (edgeB = e);
  }
  if (edgeA < 0 && edgeB < 0) return false;
  if (edgeA < 0 || sepB > sepA + REFERENCE_TOLERANCE) return clip(B, edgeB, A, true, out);
  return clip(A, edgeA, B, false, out);
}

/** Whether normal n at P's vertex v points out through a seam face (rigid/seams.ts) that starts or ends there. */
function acrossSeam(P: PolygonRef, v: number, nx: number, ny: number): boolean {
  const seams = P.internal;
  if (!seams) return false;
  const after = P.start + v;
  const before = P.start + (v === 0 ? P.count - 1 : v - 1);
  return ((seams[after] & INTERNAL_FACE) !== 0 && nx * P.nx[after] + ny * P.ny[after] > 0) || ((seams[before] & INTERNAL_FACE) !== 0 && nx * P.nx[before] + ny * P.ny[before] > 0);
}

/** sweepCircle()'s hit (2·edge: a face, 2·vertex + 1: a corner; centre then at hx, hy) is a seam face, or across one. */
function sweptAcrossSeam(P: PolygonRef, hit: number, hx: number, hy: number): boolean {
  const seams = P.internal;
  if (!seams) return false;
  const k = P.start + (hit >> 1);
  if ((hit & 1) === 0) return (seams[k] & INTERNAL_FACE) !== 0;
  return acrossSeam(P, hit >> 1, hx - P.x[k], hy - P.y[k]);
}

/** The smallest signed distance of Q's vertices to P's face e. */
function separation(P: PolygonRef, e: number, Q: PolygonRef): number {
  const k = P.start + e;
  let min = Infinity;
  for (let j = Q.start, end = Q.start + Q.count; j < end; j++) min = Math.min(min, (Q.x[j] - P.x[k]) * P.nx[k] + (Q.y[j] - P.y[k]) * P.ny[k]);
  return min;
}

/**
 * Clips the incident edge of I against reference edge e of R (R = B when `flip`), keeping points within `margin`
 * of the reference face.
 */
function clip(R: PolygonRef, e: number, I: PolygonRef, flip: boolean, out: ContactManifold): boolean {
  const margin = out.query[0];
  const r0 = R.start + e;
  const r1 = R.start + (e + 1 === R.count ? 0 : e + 1);
  const nx = R.nx[r0];
  const ny = R.ny[r0];
  const v1x = R.x[r0];
  const v1y = R.y[r0];
  const v2x = R.x[r1];
  const v2y = R.y[r1];
  // Incident edge: the one whose normal is most anti-parallel to the reference normal.
  let inc = 0;
  let most = Infinity;
  for (let k = 0; k < I.count; k++) {
    const dot = I.nx[I.start + k] * nx + I.ny[I.start + k] * ny;
    if (dot < most) {
      most = dot;
      inc = k;
    }
  }
  const i0 = I.start + inc;
  const i1 = I.start + (inc + 1 === I.count ? 0 : inc + 1);
  let w1x = I.x[i0];
  let w1y = I.y[i0];
  let w2x = I.x[i1];
  let w2y = I.y[i1];
  // Side planes of the reference edge, along its tangent t (from v1 to v2): keep t·(w − v1) ≥ 0 and t·(w − v2) ≤ 0.
  const tx = -ny;
  const ty = nx;
  // With counter-clockwise order and outward normal n = (ty, −tx) of tangent t: t = (−ny, nx).
  const lo = v1x * tx + v1y * ty;
  const hi = v2x * tx + v2y * ty;
  let s1 = w1x * tx + w1y * ty;
  let s2 = w2x * tx + w2y * ty;
  // The incident edge runs against the reference tangent; clip each end into [lo, hi].
  if (s1 > hi) {
    if (s2 > hi) return false;
    const f = (s1 - hi) / (s1 - s2);
    w1x += f * (w2x - w1x);
    w1y += f * (w2y - w1y);
    s1 = hi;
  } else if (s1 < lo) {
    if (s2 < lo) return false;
    const f = (lo - s1) / (s2 - s1);
    w1x += f * (w2x - w1x);
    w1y += f * (w2y - w1y);
    s1 = lo;
  }
  if (s2 > hi) {
    const f = (s2 - hi) / (s2 - s1);
    w2x += f * (w1x - w2x);
    w2y += f * (w1y - w2y);
  } else if (s2 < lo) {
    const f = (lo - s2) / (s1 - s2);
    w2x += f * (w1x - w2x);
    w2y += f * (w1y - w2y);
  }
  out.nx = flip ? -nx : nx;
  out.ny = flip ? -ny : ny;
  // The incident edge's direction for the fraction along it (B's edge when B is incident).
  const ex = I.x[i1] - I.x[i0];
  const ey = I.y[i1] - I.y[i0];
  const elen2 = ex * ex + ey * ey;
  const rex = v2x - v1x;
  const rey = v2y - v1y;
  const rlen2 = rex * rex + rey * rey;
  // (The fractions are clamped inline: clamp01 was not always inlined here, and a double passed to and returned from
  // a call that is not inlined is boxed: S2 allocated 14 KB a step in clip.)
  for (let k = 0; k < 2; k++) {
    const wx = k === 0 ? w1x : w2x;
    const wy = k === 0 ? w1y : w2y;
    const sep = (wx - v1x) * nx + (wy - v1y) * ny;
    if (sep > margin) continue;
    const j = out.count++;
    out.feature[j] = (flip ? 32768 : 0) + (e & 127) * 256 + (inc & 127) * 2 + k;
    // Q: the incident point projected onto the reference face.
    const qx = wx - sep * nx;
    const qy = wy - sep * ny;
    out.depth[j] = -sep;
    if (flip) {
      // B is the reference: A's point is the incident one.
      out.pAx[j] = wx;
      out.pAy[j] = wy;
      out.pBx[j] = qx;
      out.pBy[j] = qy;
      out.edgeB[j] = e;
      const along = ((qx - v1x) * rex + (qy - v1y) * rey) / rlen2;
      out.alphaB[j] = along < 0 ? 0 : along > 1 ? 1 : along;
    } else {
      out.pAx[j] = qx;
      out.pAy[j] = qy;
      out.pBx[j] = wx;
      out.pBy[j] = wy;
      out.edgeB[j] = inc;
      const along = ((wx - I.x[i0]) * ex + (wy - I.y[i0]) * ey) / elen2;
      out.alphaB[j] = along < 0 ? 0 : along > 1 ? 1 : along;
    }
  }
  return out.count > 0;
}

function clamp01(a: number): number {
  return a < 0 ? 0 : a > 1 ? 1 : a;
}

/**
 * Polygon P against the circle of out.query[1..3] (centre x, y, radius). With `circleIsA` the circle is side A (the
 * normal and the points are swapped accordingly); otherwise P is A. For the polygon side as B, edgeB/alphaB say where
 * on it.
 */
export function collidePolygonCircle(P: PolygonRef, circleIsA: boolean, out: ContactManifold): boolean {
  out.count = 0;
  const margin = out.query[0];
  const cx = out.query[1];
  const cy = out.query[2];
  const r = out.query[3];
  // The edge the centre is farthest outside of (or least inside), but a seam's (rigid/seams.ts): beyond one, or least
  // deep under one, the circle is in the neighbouring piece, and this one's contact is a face that is no seam (before,
  // a disc sunk into the floor at a join met no face of either piece and fell through).
  const seams = P.internal;
  let best = -Infinity;
  let edge = 0;
  let apart = -Infinity;
  let apartEdge = 0;
  for (let i = 0; i < P.count; i++) {
    const k = P.start + i;
    const s = (cx - P.x[k]) * P.nx[k] + (cy - P.y[k]) * P.ny[k];
    if (s > apart) {
      apart = s;
      apartEdge = i;
    }
    if (s > best && !(seams && (seams[k] & INTERNAL_FACE) !== 0)) {
      best = s;
      edge = i;
    }
  }
  if (apart - r > margin) return false;
  if (best === -Infinity) {
    // Every face a seam (a tile inside a block of tiles): its faces as they are.
    best = apart;
    edge = apartEdge;
  } else if (apart > 0 && best <= 0) return false; // Outside only through seams: in the neighbouring piece, its contact.
  const k0 = P.start + edge;
  const k1 = P.start + (edge + 1 === P.count ? 0 : edge + 1);
  const v1x = P.x[k0];
  const v1y = P.y[k0];
  const ex = P.x[k1] - v1x;
  const ey = P.y[k1] - v1y;
  const len2 = ex * ex + ey * ey;
  const along = ((cx - v1x) * ex + (cy - v1y) * ey) / len2;
  let nx: number;
  let ny: number;
  let px: number;
  let py: number;
  let depth: number;
  let alpha: number;
  const faceRegion = best <= 0 || (along >= 0 && along <= 1);
  if (faceRegion) {
    // Face region (or the centre is inside): push along the face normal.
    nx = P.nx[k0];
    ny = P.ny[k0];
    px = cx - best * nx;
    py = cy - best * ny;
    depth = r - best;
    alpha = clamp01(along);
  } else {
    // Vertex region: the nearer end of the edge.
    const atEnd = along > 1;
    px = atEnd ? P.x[k1] : v1x;
    py = atEnd ? P.y[k1] : v1y;
    const dx = cx - px;
    const dy = cy - py;
    const d = Math.sqrt(dx * dx + dy * dy);
    if (d - r > margin) return false;
    nx = dx / d;
    ny = dy / d;
    // A corner on a seam, the circle past the seam's side: that is the neighbouring piece's to answer (its face where
    // the floor goes on flat, the corner of both at a peak). Two answers at one place, one of them along a face inside
    // the floor, tripped a disc crossing a join, and one at a peak held a ball on it.
    if (acrossSeam(P, (atEnd ? k1 : k0) - P.start, nx, ny)) return false;
    depth = r - d;
    alpha = atEnd ? 1 : 0;
  }
  if (depth < 0 && out.query[9] > 0) {
    // Apart: the feature it meets first on its straight path, if that is another (a corner the centre is not facing
    // yet, a face instead of a corner): found where it is now, a fast disc meeting a corner was turned 3-74° wrong.
    const hit = sweepCircle(P, out.query);
    // The vertex the centre faces now (−1: it faces a face).
    const facing = faceRegion ? -1 : along > 1 ? k1 - P.start : edge;
    // Where the centre is when it touches.
    const hx = cx + out.query[7] * sweptTime[0];
    const hy = cy + out.query[8] * sweptTime[0];
    if (hit >= 0 && !(faceRegion && hit === 2 * edge) && !sweptAcrossSeam(P, hit, hx, hy)) {
      const k = P.start + (hit >> 1);
      if ((hit & 1) === 0) {
        // A face: its normal; the point where the centre's path meets it, less the radius.
        nx = P.nx[k];
        ny = P.ny[k];
        px = hx - r * nx;
        py = hy - r * ny;
        edge = hit >> 1;
        alpha = sweptTime[1];
      } else {
        // A corner (vertex k, the start of edge k): from it to the centre where they touch.
        px = P.x[k];
        py = P.y[k];
        const d = Math.sqrt((hx - px) * (hx - px) + (hy - py) * (hy - py));
        nx = (hx - px) / d;
        ny = (hy - py) / d;
        // The corner it faces now keeps its name (edge, end): the feature its friction anchors are kept by.
        if (hit >> 1 !== facing) {
          edge = hit >> 1;
          alpha = 0;
        }
      }
      // The gap along the new normal, as the solver measures it.
      depth = r - ((cx - px) * nx + (cy - py) * ny);
    }
  }
  const sx = cx - r * nx;
  const sy = cy - r * ny;
  out.count = 1;
  out.depth[0] = depth;
  out.feature[0] = edge * 2 + (alpha === 0 || alpha === 1 ? 1 : 0);
  if (circleIsA) {
    out.nx = -nx;
    out.ny = -ny;
    out.pAx[0] = sx;
    out.pAy[0] = sy;
    out.pBx[0] = px;
    out.pBy[0] = py;
    out.edgeB[0] = edge;
    out.alphaB[0] = alpha;
  } else {
    out.nx = nx;
    out.ny = ny;
    out.pAx[0] = px;
    out.pAy[0] = py;
    out.pBx[0] = sx;
    out.pBy[0] = sy;
    out.edgeB[0] = -1;
    out.alphaB[0] = 0;
  }
  return true;
}

/** Scratch of sweepCircle: the time of the hit it returns, and for a face the fraction along it. */
const sweptTime = new Float64Array(2);

/**
 * The first feature of P that the query's circle (centre query[1, 2], radius query[3]) moving at query[7, 8] meets
 * within query[9]: edge k's face as 2k, its start vertex as 2k + 1, or −1 for none (time and fraction in sweptTime).
 * The centre's ray against P grown by r: each face moved out by r, each vertex a circle of radius r. (The reals come
 * in the typed array: V8 boxes a double passed to a call it does not inline.)
 */
function sweepCircle(P: PolygonRef, query: Float64Array): number {
  const cx = query[1];
  const cy = query[2];
  const r = query[3];
  const vx = query[7];
  const vy = query[8];
  const v2 = vx * vx + vy * vy;
  let first = query[9];
  let hit = -1;
  for (let i = 0; i < P.count; i++) {
    const k = P.start + i;
    const k1 = P.start + (i + 1 === P.count ? 0 : i + 1);
    const x0 = P.x[k];
    const y0 = P.y[k];
    const closing = vx * P.nx[k] + vy * P.ny[k];
    const gap = (cx - x0) * P.nx[k] + (cy - y0) * P.ny[k] - r;
    if (closing < 0 && gap >= 0 && gap < -closing * first) {
      const t = gap / -closing;
      const ex = P.x[k1] - x0;
      const ey = P.y[k1] - y0;
      const along = ((cx + vx * t - x0) * ex + (cy + vy * t - y0) * ey) / (ex * ex + ey * ey);
      if (along >= 0 && along <= 1) {
        first = t;
        hit = 2 * i;
        sweptTime[1] = along;
      }
    }
    const dx = cx - x0;
    const dy = cy - y0;
    const b = dx * vx + dy * vy;
    const c = dx * dx + dy * dy - r * r;
    const discriminant = b * b - v2 * c;
    if (b < 0 && c > 0 && discriminant >= 0) {
      const t = c / (Math.sqrt(discriminant) - b);
      if (t < first) {
        first = t;
        hit = 2 * i + 1;
      }
    }
  }
  sweptTime[0] = first;
  return hit;
}

/** Circle A (out.query[1..3]) against circle B (out.query[4..6]). Coincident centres push along −y (up on a y-down canvas). */
export function collideCircles(out: ContactManifold): boolean {
  out.count = 0;
  const q = out.query;
  const margin = q[0];
  const ax = q[1];
  const ay = q[2];
  const ra = q[3];
  const bx = q[4];
  const by = q[5];
  const rb = q[6];
  const dx = bx - ax;
  const dy = by - ay;
  const reach = ra + rb + margin;
  const d2 = dx * dx + dy * dy;
  if (d2 > reach * reach) return false;
  const d = Math.sqrt(d2);
  const nx = d > 1e-12 ? dx / d : 0;
  const ny = d > 1e-12 ? dy / d : -1;
  out.count = 1;
  out.nx = nx;
  out.ny = ny;
  out.depth[0] = ra + rb - d;
  out.pAx[0] = ax + ra * nx;
  out.pAy[0] = ay + ra * ny;
  out.pBx[0] = bx - rb * nx;
  out.pBy[0] = by - rb * ny;
  out.edgeB[0] = -1;
  out.alphaB[0] = 0;
  out.feature[0] = 0;
  return true;
}
