// Separating-axis test with minimum translation vector (seed 3.1, Algorithm 2), fixed per GUIDE.md: the normal is
// signed to point from A to B, and each candidate axis is tested in the one direction that is a facet of the
// Minkowski difference (Box2D's max-separation form), so the depth is exactly the MTV length even when one shape
// contains the other. Shapes that only touch are not a hit. The contact point is the deepest vertex's, or, where
// the shapes meet face to face, taken from the middle of the faces' overlap, so that it lies on both outlines and
// does not depend on which vertex either list starts from.
import type { Penetration } from './results.js';
import { ShapeType, type Shape } from './shape.js';
import { ax, ay, bx, by, face, faceEnds, faceMidpoint, load, maxSeparation, mid, near, nearestFeature, onFace, sep } from './scratch.js';

/**
 * Overlap test with MTV. Polygon–polygon, polygon–circle, circle–circle, and segments (as two-sided polygons) with
 * either. Returns out.hit: true when the shapes overlap by a positive depth. On a hit, `out` holds the unit normal
 * from A to B, the depth and a contact point (see Penetration); otherwise only hit = false is written.
 */
export function sat(a: Shape, b: Shape, out: Penetration): boolean {
  const ta = a.type;
  const tb = b.type;
  if (ta === ShapeType.Circle) {
    if (tb === ShapeType.Circle) return circleCircle(a, b, out);
    return polygonCircle(b, a, true, out);
  }
  if (tb === ShapeType.Circle) return polygonCircle(a, b, false, out);
  return polygonPolygon(a, b, out);
}

function polygonPolygon(a: Shape, b: Shape, out: Penetration): boolean {
  load(a, b);
  const n = a.count;
  const m = b.count;
  maxSeparation(ax, ay, n, bx, by, m, 0);
  const sepA = sep.value;
  if (sepA >= 0) return miss(out);
  const edgeA = sep.edge;
  const nax = sep.nx;
  const nay = sep.ny;
  const vb = sep.vertex;
  maxSeparation(bx, by, m, ax, ay, n, 0);
  const sepB = sep.value;
  if (sepB >= 0) return miss(out);
  if (sepA === -Infinity && sepB === -Infinity) return miss(out); // two points: no area to overlap
  // The facet of least penetration (A's on a tie; B's normal points from B to A), and the other shape's deepest
  // vertex, depth below it: the point is midway, B's vertex moved along the normal, A's against it.
  const facetOfB = sepB > sepA;
  const depth = facetOfB ? -sepB : -sepA;
  const nx = facetOfB ? -sep.nx : nax;
  const ny = facetOfB ? -sep.ny : nay;
  const v = facetOfB ? sep.vertex : vb;
  const vx = facetOfB ? ax : bx;
  const vy = facetOfB ? ay : by;
  const half = facetOfB ? -0.5 * depth : 0.5 * depth;
  out.hit = true;
  out.normalX = nx;
  out.normalY = ny;
  out.depth = depth;
  out.pointX = vx[v] + half * nx;
  out.pointY = vy[v] + half * ny;
  faceToFace(out, n, m, facetOfB ? v : edgeA, facetOfB ? sep.edge : v, facetOfB);
  return true;
}

/**
 * Whether the shapes meet face to face: the deepest vertex has a neighbour on the facet's line too. Then the contact
 * point is taken from the middle of where the two faces overlap: A's (n vertices) through vertex or edge `a`, B's (m
 * vertices) through vertex or edge `b`; `facetOfB` says which of them is the facet's edge. (A call of its own keeps
 * polygonPolygon small enough to be inlined.)
 */
function faceToFace(out: Penetration, n: number, m: number, a: number, b: number, facetOfB: boolean): void {
  const nx = out.normalX;
  const ny = out.normalY;
  if (!(facetOfB ? onFace(ax, ay, n, a, nx, ny) : onFace(bx, by, m, b, nx, ny))) return;
  // The facet's edge runs on to the next vertex; the other face starts as its single deepest vertex.
  const aEnd = facetOfB ? a : a + 1 === n ? 0 : a + 1;
  const bEnd = facetOfB ? (b + 1 === m ? 0 : b + 1) : b;
  faceEnds(ax, ay, n, a, aEnd, nx, ny);
  const a0 = face.first;
  const a1 = face.last;
  faceEnds(bx, by, m, b, bEnd, nx, ny);
  faceMidpoint(a0, a1, face.first, face.last, nx, ny);
  out.pointX = 0.5 * (mid.ax + mid.bx);
  out.pointY = 0.5 * (mid.ay + mid.by);
}

/** Polygon (or segment) P against circle C; `flip` when C is shape A. */
function polygonCircle(p: Shape, c: Shape, flip: boolean, out: Penetration): boolean {
  const ci = c.index[c.offset];
  const cx = c.xs[ci];
  const cy = c.ys[ci];
  const r = c.radius;
  let nx: number;
  let ny: number;
  let depth: number;
  if (nearestFeature(p, cx, cy, r)) {
    nx = near.nx;
    ny = near.ny;
    depth = r - near.distance;
  } else if (near.edge < 0) {
    // Every edge has zero length: P is a point.
    const v = p.index[p.offset];
    const dx = cx - p.xs[v];
    const dy = cy - p.ys[v];
    const d = Math.sqrt(dx * dx + dy * dy);
    if (d >= r) return miss(out);
    nx = d > 0 ? dx / d : 1;
    ny = d > 0 ? dy / d : 0;
    depth = r - d;
  } else return miss(out);
  // (nx, ny) points from P to C; C's deepest point is centre − r·n.
  out.hit = true;
  out.depth = depth;
  out.pointX = cx - (r - 0.5 * depth) * nx;
  out.pointY = cy - (r - 0.5 * depth) * ny;
  out.normalX = flip ? -nx : nx;
  out.normalY = flip ? -ny : ny;
  return true;
}

function circleCircle(a: Shape, b: Shape, out: Penetration): boolean {
  const ia = a.index[a.offset];
  const ib = b.index[b.offset];
  const dx = b.xs[ib] - a.xs[ia];
  const dy = b.ys[ib] - a.ys[ia];
  const rs = a.radius + b.radius;
  const d2 = dx * dx + dy * dy;
  if (d2 >= rs * rs) return miss(out);
  const d = Math.sqrt(d2);
  const nx = d > 0 ? dx / d : 1;
  const ny = d > 0 ? dy / d : 0;
  const depth = rs - d;
  out.hit = true;
  out.normalX = nx;
  out.normalY = ny;
  out.depth = depth;
  const rb = b.radius - 0.5 * depth;
  out.pointX = b.xs[ib] - rb * nx;
  out.pointY = b.ys[ib] - rb * ny;
  return true;
}

function miss(out: Penetration): boolean {
  out.hit = false;
  return false;
}
