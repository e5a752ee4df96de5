// Contact manifold: up to two contact points for a polygon pair by clipping the incident face against the side
// planes of the reference face (Box2D's b2CollidePolygons), and for every point the vertex–edge feature the
// position-based response of seed 4.2 needs (which vertex of which shape penetrates which edge, and where along it).
// A face is a run of collinear edges (180° corners are allowed, and shapes that are views over particles cannot
// have them merged away): the faces are clipped whole, and each point names the sub-edge it lies on.
import type { Manifold } from './results.js';
import { ShapeType, type Shape } from './shape.js';
import { ax, ay, bx, by, face, faceEnds, load, maxSeparation, near, nearestFeature, sep } from './scratch.js';

/**
 * Contact manifold of two shapes (polygons, segments as two-sided polygons, circles), written into `out`.
 * Returns true when they overlap by a positive depth, or, with `margin` > 0, when they are closer than `margin`
 * (speculative contacts: then depth may be negative, down to −margin). See Manifold for the meaning of each field.
 */
export function polygonManifold(a: Shape, b: Shape, out: Manifold, margin = 0): boolean {
  const ta = a.type;
  const tb = b.type;
  if (ta === ShapeType.Circle) {
    if (tb === ShapeType.Circle) return circleCircle(a, b, out, margin);
    return polygonCircle(b, a, true, out, margin);
  }
  if (tb === ShapeType.Circle) return polygonCircle(a, b, false, out, margin);
  return polygonPolygon(a, b, out, margin);
}

function polygonPolygon(a: Shape, b: Shape, out: Manifold, margin: number): boolean {
  load(a, b);
  const na = a.count;
  const nb = b.count;
  maxSeparation(ax, ay, na, bx, by, nb, margin);
  const sepA = sep.value;
  if (sepA >= margin) return miss(out);
  const edgeA = sep.edge;
  const nax = sep.nx;
  const nay = sep.ny;
  maxSeparation(bx, by, nb, ax, ay, na, margin);
  const sepB = sep.value;
  if (sepB >= margin) return miss(out);
  if (sepA === -Infinity && sepB === -Infinity) return miss(out);
  const edgeB = sep.edge;
  const nbx = sep.nx;
  const nby = sep.ny;
  // Reference face: the one of least penetration (A's on a tie), so the deepest point is the penetration depth. Near
  // a tie between two nearly parallel faces either choice gives the same points (the ends of where the faces overlap)
  // and the same vertex–edge features, so the contacts do not jump when the choice changes from one step to the next.
  const flip = sepA === -Infinity || sepB > sepA;
  if (flip ? clip(out, margin, bx, by, nb, edgeB, nbx, nby, ax, ay, na, true) : clip(out, margin, ax, ay, na, edgeA, nax, nay, bx, by, nb, false)) {
    return true;
  }
  // Speculative contacts of shapes apart (or a rounding miss): the incident face may miss the side planes; try the
  // other polygon's face.
  if (sepA !== -Infinity && sepB !== -Infinity) {
    if (flip ? clip(out, margin, ax, ay, na, edgeA, nax, nay, bx, by, nb, false) : clip(out, margin, bx, by, nb, edgeB, nbx, nby, ax, ay, na, true)) {
      return true;
    }
  }
  // Neither face's side planes hold a point of the other's incident face within the margin. Without a margin that
  // happens only when the overlap is rounding (the least face's side planes always hold its deepest point): touching.
  // With one, shapes apart corner to corner get one speculative point, the deepest vertex of the incident polygon
  // under the shallower face, α clamped to the edge.
  if (!(margin > 0)) return miss(out);
  const useB = sepB > sepA;
  deepest(out, useB ? bx : ax, useB ? by : ay, useB ? nb : na, useB ? edgeB : edgeA, useB ? nbx : nax, useB ? nby : nay, useB ? ax : bx, useB ? ay : by, useB ? na : nb, useB);
  return true;
}

/**
 * Clips the incident face of polygon I against the reference face through edge e of polygon R (outward unit normal
 * n, towards I). `flip` when R is B. Writes the points with separation <= margin; returns whether there is one.
 */
function clip(
  out: Manifold, margin: number,
  rx: Float64Array, ry: Float64Array, rn: number, e: number, nx: number, ny: number,
  ix: Float64Array, iy: Float64Array, inn: number, flip: boolean,
): boolean {
  // Reference face: edge e and the collinear edges next to it, r0..r1.
  faceEnds(rx, ry, rn, e, e + 1 === rn ? 0 : e + 1, nx, ny);
  const r0 = face.first;
  const r1 = face.last;
  // Incident face: the edge of I whose normal is most anti-parallel to n (exact ties to the larger normal, as in
  // maxSeparation, not to the first in the list), and the collinear edges next to it, v0..v1.
  let i1 = 0;
  let minDot = Infinity;
  let inx = 0;
  let iny = 0;
  for (let k = 0; k < inn; k++) {
    const k2 = k + 1 === inn ? 0 : k + 1;
    const ex = ix[k2] - ix[k];
    const ey = iy[k2] - iy[k];
    const len2 = ex * ex + ey * ey;
    if (len2 === 0) continue;
    const inv = 1 / Math.sqrt(len2);
    const cx = ey * inv;
    const cy = -ex * inv;
    const d = cx * nx + cy * ny;
    if (d <= minDot && (d < minDot || cx > inx || (cx === inx && cy > iny))) {
      minDot = d;
      i1 = k;
      inx = cx;
      iny = cy;
    }
  }
  faceEnds(ix, iy, inn, i1, i1 + 1 === inn ? 0 : i1 + 1, inx, iny);
  const v0 = face.first;
  const v1 = face.last;
  // Unit tangent of the reference face (CCW: normal (ty, −tx)); the face spans lo..hi along it.
  const tx = -ny;
  const ty = nx;
  const lo = tx * rx[r0] + ty * ry[r0];
  const hi = tx * rx[r1] + ty * ry[r1];

  // The incident face as two points, each remembering its feature: −1 = still vertex v0 / v1 of I, otherwise the
  // reference vertex (r0 or r1) whose side plane clipped it.
  let p0x = ix[v0];
  let p0y = iy[v0];
  let p1x = ix[v1];
  let p1y = iy[v1];
  let f0 = -1;
  let f1 = -1;
  // Side plane t·p >= lo.
  let d0 = tx * p0x + ty * p0y - lo;
  let d1 = tx * p1x + ty * p1y - lo;
  if (d0 < 0 && d1 < 0) return false;
  if (d0 < 0) {
    const s = d0 / (d0 - d1);
    p0x += s * (p1x - p0x);
    p0y += s * (p1y - p0y);
    f0 = r0;
  } else if (d1 < 0) {
    const s = d0 / (d0 - d1);
    p1x = p0x + s * (p1x - p0x);
    p1y = p0y + s * (p1y - p0y);
    f1 = r0;
  }
  // Side plane t·p <= hi.
  d0 = hi - (tx * p0x + ty * p0y);
  d1 = hi - (tx * p1x + ty * p1y);
  if (d0 < 0 && d1 < 0) return false;
  if (d0 < 0) {
    const s = d0 / (d0 - d1);
    p0x += s * (p1x - p0x);
    p0y += s * (p1y - p0y);
    f0 = r1;
  } else if (d1 < 0) {
    const s = d0 / (d0 - d1);
    p1x = p0x + s * (p1x - p0x);
    p1y = p0y + s * (p1y - p0y);
    f1 = r1;
  }

  const refOwner = flip ? 1 : 0;
  const incOwner = flip ? 0 : 1;
  // Separations are measured from the face's first vertex, not from edge e's: collinear edges with equal normals
  // tie, and which of them is e depends on where the list starts.
  const cx = rx[r0];
  const cy = ry[r0];
  let count = 0;
  for (let k = 0; k < 2; k++) {
    const qx = k === 0 ? p0x : p1x;
    const qy = k === 0 ? p0y : p1y;
    const f = k === 0 ? f0 : f1;
    const s = nx * (qx - cx) + ny * (qy - cy); // separation of the point from the reference face
    if (s > margin) continue;
    const depth = -s;
    const tq = tx * qx + ty * qy;
    let edge: number;
    let alpha: number;
    if (f < 0) {
      // A vertex of I below the reference face: α is its projection onto the sub-edge of the face it lies over.
      edge = subEdge(rx, ry, rn, r0, r1, tx, ty, tq, 1);
      out.incident[count] = incOwner;
      out.vertex[count] = k === 0 ? v0 : v1;
      alpha = project(rx, ry, rn, edge, qx, qy);
    } else {
      // A reference vertex inside I: it meets the incident face at the clipped point, along the normal; α places
      // that point on the sub-edge of the incident face it lies on (which runs along −t).
      edge = subEdge(ix, iy, inn, v0, v1, tx, ty, tq, -1);
      out.incident[count] = refOwner;
      out.vertex[count] = f;
      alpha = project(ix, iy, inn, edge, qx, qy);
    }
    out.edge[count] = edge;
    out.alpha[count] = alpha;
    out.depth[count] = depth;
    out.pointX[count] = qx + 0.5 * depth * nx;
    out.pointY[count] = qy + 0.5 * depth * ny;
    count++;
  }
  out.count = count;
  out.normalX = flip ? -nx : nx;
  out.normalY = flip ? -ny : ny;
  return count > 0;
}

/**
 * The edge of the face first..last of polygon P (n vertices) over which the point at tq along (tx, ty) lies; the
 * face runs along `sign`·t. A point exactly over a corner between two sub-edges goes to the earlier one.
 */
function subEdge(px: Float64Array, py: Float64Array, n: number, first: number, last: number, tx: number, ty: number, tq: number, sign: number): number {
  let j = first;
  for (;;) {
    const next = j + 1 === n ? 0 : j + 1;
    if (next === last || sign * (tx * px[next] + ty * py[next]) >= sign * tq) return j;
    j = next;
  }
}

/** Where (x, y) projects onto edge e of polygon P (n vertices), as a fraction of the edge clamped to [0, 1]. */
function project(px: Float64Array, py: Float64Array, n: number, e: number, x: number, y: number): number {
  const e2 = e + 1 === n ? 0 : e + 1;
  const ex = px[e2] - px[e];
  const ey = py[e2] - py[e];
  const len2 = ex * ex + ey * ey;
  if (len2 === 0) return 0;
  const alpha = ((x - px[e]) * ex + (y - py[e]) * ey) / len2;
  return alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
}

/** One contact: the vertex of I deepest below reference edge e of R. */
function deepest(
  out: Manifold,
  rx: Float64Array, ry: Float64Array, rn: number, e: number, nx: number, ny: number,
  ix: Float64Array, iy: Float64Array, inn: number, flip: boolean,
): void {
  let v = 0;
  let min = Infinity;
  for (let k = 0; k < inn; k++) {
    const d = nx * ix[k] + ny * iy[k];
    if (d < min) {
      min = d;
      v = k;
    }
  }
  const depth = nx * rx[e] + ny * ry[e] - min;
  out.count = 1;
  out.normalX = flip ? -nx : nx;
  out.normalY = flip ? -ny : ny;
  out.incident[0] = flip ? 0 : 1;
  out.vertex[0] = v;
  out.edge[0] = e;
  out.alpha[0] = project(rx, ry, rn, e, ix[v], iy[v]);
  out.depth[0] = depth;
  out.pointX[0] = ix[v] + 0.5 * depth * nx;
  out.pointY[0] = iy[v] + 0.5 * depth * ny;
}

/** Polygon (or segment) P against circle C; `flip` when C is shape A. One point: C's centre against P's edge. */
function polygonCircle(p: Shape, c: Shape, flip: boolean, out: Manifold, margin: number): boolean {
  const ci = c.index[c.offset];
  const cx = c.xs[ci];
  const cy = c.ys[ci];
  const r = c.radius;
  if (!nearestFeature(p, cx, cy, r + margin)) return miss(out);
  const { nx, ny, alpha } = near;
  const depth = r - near.distance;
  out.count = 1;
  out.normalX = flip ? -nx : nx;
  out.normalY = flip ? -ny : ny;
  out.depth[0] = depth;
  out.pointX[0] = cx - (r - 0.5 * depth) * nx;
  out.pointY[0] = cy - (r - 0.5 * depth) * ny;
  out.incident[0] = flip ? 0 : 1;
  out.vertex[0] = 0;
  out.edge[0] = near.edge;
  out.alpha[0] = alpha;
  return true;
}

function circleCircle(a: Shape, b: Shape, out: Manifold, margin: number): boolean {
  const ia = a.index[a.offset];
  const ib = b.index[b.offset];
  const dx = b.xs[ib] - a.xs[ia];
  const dy = b.ys[ib] - a.ys[ia];
  const reach = a.radius + b.radius + margin;
  const d2 = dx * dx + dy * dy;
  if (d2 >= reach * reach) return miss(out);
  const d = Math.sqrt(d2);
  const nx = d > 0 ? dx / d : 1;
  const ny = d > 0 ? dy / d : 0;
  const depth = a.radius + b.radius - d;
  out.count = 1;
  out.normalX = nx;
  out.normalY = ny;
  out.depth[0] = depth;
  const rb = b.radius - 0.5 * depth;
  out.pointX[0] = b.xs[ib] - rb * nx;
  out.pointY[0] = b.ys[ib] - rb * ny;
  out.incident[0] = 1;
  out.vertex[0] = 0;
  out.edge[0] = -1;
  out.alpha[0] = 0;
  return true;
}

function miss(out: Manifold): boolean {
  out.count = 0;
  return false;
}
