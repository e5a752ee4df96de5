// Contact manifold: up to two contact points for a polygon pair by clipping the incident edge against the side
// planes of the reference edge (Box2D's b2CollidePolygons), and for every point the vertex–edge feature the
// position-based response of seed 4.2 needs (which vertex of which shape penetrates which edge, and where along it).
import type { Manifold } from './results.js';
import { ShapeType, type Shape } from './shape.js';
import { ax, ay, bx, by, load, maxSeparation, near, nearestFeature, sep } from './scratch.js';

/**
 * The reference face is the polygon whose best separating facet is shallower by this fraction of the depth; A wins
 * ties. The bias keeps the reference face from flickering between two nearly parallel faces from step to step.
 */
const REFERENCE_BIAS = 0.98;

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
  // Reference polygon: A unless B's face is shallower by the bias.
  const flip = sepA === -Infinity || sepB > sepA + (1 - REFERENCE_BIAS) * Math.abs(sepA);
  if (flip ? clip(out, margin, bx, by, nb, edgeB, nbx, nby, ax, ay, na, true) : clip(out, margin, ax, ay, na, edgeA, nax, nay, bx, by, nb, false)) {
    return true;
  }
  // Deep overlaps: the incident edge may miss the biased face's side planes; try the other face.
  if (sepA !== -Infinity && sepB !== -Infinity) {
    if (flip ? clip(out, margin, ax, ay, na, edgeA, nax, nay, bx, by, nb, false) : clip(out, margin, bx, by, nb, edgeB, nbx, nby, ax, ay, na, true)) {
      return true;
    }
  }
  // Neither face's side planes hold a point of the other's incident edge: one point, the deepest vertex of the
  // incident polygon under the shallower face, α clamped to the edge.
  const useB = sepB > sepA;
  deepest(out, useB ? bx : ax, useB ? by : ay, useB ? nb : na, useB ? edgeB : edgeA, useB ? nbx : nax, useB ? nby : nay, useB ? ax : bx, useB ? ay : by, useB ? na : nb, useB);
  return true;
}

/**
 * Clips the incident edge of polygon I against reference edge e of polygon R (outward unit normal n, towards I).
 * `flip` when R is B. Writes the points with separation <= margin; returns whether there is one.
 */
function clip(
  out: Manifold, margin: number,
  rx: Float64Array, ry: Float64Array, rn: number, e: number, nx: number, ny: number,
  ix: Float64Array, iy: Float64Array, inn: number, flip: boolean,
): boolean {
  // Incident edge: the edge of I whose normal is most anti-parallel to n.
  let i1 = 0;
  let minDot = Infinity;
  for (let k = 0; k < inn; k++) {
    const k2 = k + 1 === inn ? 0 : k + 1;
    const ex = ix[k2] - ix[k];
    const ey = iy[k2] - iy[k];
    const len2 = ex * ex + ey * ey;
    if (len2 === 0) continue;
    const d = (ey * nx - ex * ny) / Math.sqrt(len2);
    if (d < minDot) {
      minDot = d;
      i1 = k;
    }
  }
  const i2 = i1 + 1 === inn ? 0 : i1 + 1;
  const e2 = e + 1 === rn ? 0 : e + 1;
  const r1x = rx[e];
  const r1y = ry[e];
  const r2x = rx[e2];
  const r2y = ry[e2];
  // Unit tangent of the reference edge (CCW: normal (ty, −tx)).
  const tx = -ny;
  const ty = nx;
  const lo = tx * r1x + ty * r1y;
  const hi = tx * r2x + ty * r2y;

  // The incident edge as two points, each remembering its feature: −1 = still vertex i1 / i2 of I, otherwise the
  // reference vertex (e or e2) whose side plane clipped it.
  const v1x = ix[i1];
  const v1y = iy[i1];
  const v2x = ix[i2];
  const v2y = iy[i2];
  let p0x = v1x;
  let p0y = v1y;
  let p1x = v2x;
  let p1y = v2y;
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
    f0 = e;
  } else if (d1 < 0) {
    const s = d0 / (d0 - d1);
    p1x = p0x + s * (p1x - p0x);
    p1y = p0y + s * (p1y - p0y);
    f1 = e;
  }
  // Side plane t·p <= hi.
  d0 = hi - (tx * p0x + ty * p0y);
  d1 = hi - (tx * p1x + ty * p1y);
  if (d0 < 0 && d1 < 0) return false;
  if (d0 < 0) {
    const s = d0 / (d0 - d1);
    p0x += s * (p1x - p0x);
    p0y += s * (p1y - p0y);
    f0 = e2;
  } else if (d1 < 0) {
    const s = d0 / (d0 - d1);
    p1x = p0x + s * (p1x - p0x);
    p1y = p0y + s * (p1y - p0y);
    f1 = e2;
  }

  const refOwner = flip ? 1 : 0;
  const incOwner = flip ? 0 : 1;
  const c = nx * r1x + ny * r1y;
  const elx = r2x - r1x;
  const ely = r2y - r1y;
  const invRef = 1 / (elx * elx + ely * ely);
  const ilx = v2x - v1x;
  const ily = v2y - v1y;
  const invInc = 1 / (ilx * ilx + ily * ily);
  let count = 0;
  for (let k = 0; k < 2; k++) {
    const qx = k === 0 ? p0x : p1x;
    const qy = k === 0 ? p0y : p1y;
    const f = k === 0 ? f0 : f1;
    const s = nx * qx + ny * qy - c; // separation of the point from the reference face
    if (s > margin) continue;
    const depth = -s;
    let alpha: number;
    if (f < 0) {
      // A vertex of I below the reference edge; α is its projection onto that edge.
      out.incident[count] = incOwner;
      out.vertex[count] = k === 0 ? i1 : i2;
      out.edge[count] = e;
      alpha = ((qx - r1x) * elx + (qy - r1y) * ely) * invRef;
    } else {
      // A reference vertex inside I: it meets the incident edge at the clipped point, along the normal.
      out.incident[count] = refOwner;
      out.vertex[count] = f;
      out.edge[count] = i1;
      alpha = ((qx - v1x) * ilx + (qy - v1y) * ily) * invInc;
    }
    out.alpha[count] = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
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
  const e2 = e + 1 === rn ? 0 : e + 1;
  const elx = rx[e2] - rx[e];
  const ely = ry[e2] - ry[e];
  const alpha = ((ix[v] - rx[e]) * elx + (iy[v] - ry[e]) * ely) / (elx * elx + ely * ely);
  const depth = nx * rx[e] + ny * ry[e] - min;
  out.count = 1;
  out.normalX = flip ? -nx : nx;
  out.normalY = flip ? -ny : ny;
  out.incident[0] = flip ? 0 : 1;
  out.vertex[0] = v;
  out.edge[0] = e;
  out.alpha[0] = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
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
