// Expanding Polytope Algorithm (seed 4.3, Algorithm 6), fixed per GUIDE.md: it starts from a full 2-simplex (the
// degenerate starts — a point, a segment, a collinear triangle, the origin on an edge — are grown into a polygon
// that encloses the origin first), inserts each new support point between the endpoints of the closest edge, and
// stops on a tolerance relative to the shapes' size, with an iteration cap.
// Shapes with a radius (circles) are handled on their cores, the radii added at the end: expanding a polygon towards
// a curved outline converges only linearly, and for nearly concentric circles it would need a polygon that follows
// the whole circle. On the cores the answer is exact: depth = r_A + r_B − core distance when the cores are apart,
// and core depth + r_A + r_B when they overlap.
import { core, coreDistance, intersect, supportAB, supportAX, supportAY, supportBX, supportBY } from './gjk.js';
import { Simplex, type Penetration } from './results.js';
import { shapeSize, supportIndex, vertexX, vertexY, type Shape } from './shape.js';
import { ax, ay, bx, by, face, faceEnds, faceMidpoint, load, mid, neighbourOnLine } from './scratch.js';

/** Convergence: the support along the closest edge's normal is within this fraction of the shapes' size of it. */
const EPA_TOLERANCE = 1e-10;
/** Convergence allowance for rounded coordinates: this many times their magnitude (about 16 ulps). */
const EPA_ROUNDING = 16 * Number.EPSILON;

// The polytope, counter-clockwise, in one interleaved array (inserting a vertex is one copyWithin): per vertex i,
// the CSO point (X, Y), its points on A (AX, AY) and B (BX, BY), and for edge i (vertex i to i + 1) its outward unit
// normal (NX, NY) and distance D from the origin.
const X = 0, Y = 1, AX = 2, AY = 3, BX = 4, BY = 5, NX = 6, NY = 7, D = 8, S = 9;
let poly = new Float64Array(32 * S);
let n = 0;

function reserve(size: number): void {
  if (size * S <= poly.length) return;
  let cap = poly.length;
  while (cap < size * S) cap *= 2;
  const next = new Float64Array(cap);
  next.set(poly);
  poly = next;
}

function setVertex(k: number, x: number, y: number, ax: number, ay: number, bx: number, by: number): void {
  const o = k * S;
  poly[o + X] = x;
  poly[o + Y] = y;
  poly[o + AX] = ax;
  poly[o + AY] = ay;
  poly[o + BX] = bx;
  poly[o + BY] = by;
}

function pushSupport(k: number): void {
  const ax = supportAX();
  const ay = supportAY();
  const bx = supportBX();
  const by = supportBY();
  setVertex(k, ax - bx, ay - by, ax, ay, bx, by);
}

/** Outward normal and origin distance of edge i; false for a zero-length edge. */
function computeEdge(i: number): boolean {
  const o = i * S;
  const q = (i + 1 === n ? 0 : i + 1) * S;
  const ex = poly[q + X] - poly[o + X];
  const ey = poly[q + Y] - poly[o + Y];
  const len = Math.sqrt(ex * ex + ey * ey);
  if (len === 0) {
    poly[o + NX] = 0;
    poly[o + NY] = 0;
    poly[o + D] = Infinity;
    return false;
  }
  const nx = ey / len;
  const ny = -ex / len;
  poly[o + NX] = nx;
  poly[o + NY] = ny;
  poly[o + D] = nx * poly[o + X] + ny * poly[o + Y];
  return true;
}

const restart = new Simplex();

/**
 * Penetration depth, normal (from A to B) and contact point of two overlapping shapes, expanding `simplex` (as
 * gjkIntersect leaves it: a triangle enclosing the origin; a point, a segment or a collinear triangle are grown
 * first; a start that does not enclose the origin is replaced by boolean GJK's). For shapes with a radius the
 * simplex is not needed: the answer comes from their cores. Returns out.hit: false when the shapes do not overlap
 * by a positive depth. Does not allocate (the polytope's storage grows once for very large polygons).
 */
export function epa(a: Shape, b: Shape, simplex: Simplex, out: Penetration): boolean {
  if (a.radius > 0 || b.radius > 0) return rounded(a, b, out);
  return polytope(a, b, simplex, out);
}

/** EPA on A − B with radii 0 (polygons, segments, and the cores of rounded shapes). */
function polytope(a: Shape, b: Shape, simplex: Simplex, out: Penetration): boolean {
  // Size of A − B for the relative tolerance: its simplex's extent (support points), else the shapes' sizes.
  let scale = 0;
  for (let k = 0; k < simplex.count; k++) {
    const m = Math.abs(simplex.x[k]) + Math.abs(simplex.y[k]);
    if (m > scale) scale = m;
  }
  if (!(scale > 0)) scale = shapeSize(a) + shapeSize(b);
  // Far from the origin the support points themselves are rounded (1e6 away, by about 1e-10): a gain below that is
  // noise, and chasing it folds the polytope over a face found twice.
  let magnitude = 0;
  for (let k = 0; k < simplex.count; k++) {
    const m = Math.abs(simplex.ax[k]) + Math.abs(simplex.ay[k]) + Math.abs(simplex.bx[k]) + Math.abs(simplex.by[k]);
    if (m > magnitude) magnitude = m;
  }
  const tol = EPA_TOLERANCE * scale + EPA_ROUNDING * magnitude;
  reserve(8);
  if (!initPolytope(a, b, simplex, tol)) {
    // The start does not enclose the origin: ask boolean GJK for one that does, once.
    if (simplex === restart || !intersect(a, b, restart, 0, 0) || !initPolytope(a, b, restart, tol)) {
      out.hit = false;
      out.depth = 0;
      return false;
    }
  }
  const cap = 64 + a.count + b.count;
  reserve(n + cap + 1);
  const P = poly;
  for (let iter = 0; iter < cap; iter++) {
    // Closest edge to the origin.
    let best = 0;
    let dmin = P[D];
    for (let i = 1, o = S + D; i < n; i++, o += S) {
      if (P[o] < dmin) {
        dmin = P[o];
        best = i;
      }
    }
    const nx = P[best * S + NX];
    const ny = P[best * S + NY];
    supportAB(a, b, nx, ny, 0, 0);
    const sx = supportAX() - supportBX();
    const sy = supportAY() - supportBY();
    if (sx * nx + sy * ny - dmin <= tol) break;
    // Insert the support point between the closest edge's endpoints.
    P.copyWithin((best + 2) * S, (best + 1) * S, n * S);
    n++;
    pushSupport(best + 1);
    computeEdge(best);
    computeEdge(best + 1);
    // A point that does not lie beyond the edge (on the same face, past its end, by rounding) would fold the
    // polytope: take it out again and stop, the edge is as close as the face.
    if (P[best * S + D] < dmin || P[(best + 1) * S + D] < dmin) {
      P.copyWithin((best + 1) * S, (best + 2) * S, n * S);
      n--;
      computeEdge(best);
      break;
    }
  }
  // Result from the closest edge: depth, normal, and the witness points by the origin's projection onto the edge.
  let i = 0;
  let depth = P[D];
  for (let k = 1; k < n; k++) {
    if (P[k * S + D] < depth) {
      depth = P[k * S + D];
      i = k;
    }
  }
  const o = i * S;
  const q = (i + 1 === n ? 0 : i + 1) * S;
  const ex = P[q + X] - P[o + X];
  const ey = P[q + Y] - P[o + Y];
  let t = -(P[o + X] * ex + P[o + Y] * ey) / (ex * ex + ey * ey);
  if (!(t > 0)) t = 0;
  else if (t > 1) t = 1;
  const qax = P[o + AX] + t * (P[q + AX] - P[o + AX]);
  const qay = P[o + AY] + t * (P[q + AY] - P[o + AY]);
  const qbx = P[o + BX] + t * (P[q + BX] - P[o + BX]);
  const qby = P[o + BY] + t * (P[q + BY] - P[o + BY]);
  out.normalX = P[o + NX];
  out.normalY = P[o + NY];
  out.depth = depth > 0 ? depth : 0;
  out.pointX = 0.5 * (qax + qbx);
  out.pointY = 0.5 * (qay + qby);
  // Within its tolerance of zero the depth is touching, and the edge it came from need not be a face of A − B
  // (an edge through the origin of a polytope that only touches it): no overlap, no direction to trust.
  out.hit = depth > tol;
  if (out.hit) parallelFaces(a, b, out);
  return out.hit;
}

/**
 * Faces of A and B that meet parallel (a box resting on a box): the polytope's edge may end anywhere on them, and
 * where depends on which vertex each list starts from. Then the contact point is taken, as sat takes it, from the
 * middle of where the two faces overlap.
 */
function parallelFaces(a: Shape, b: Shape, out: Penetration): void {
  const nx = out.normalX;
  const ny = out.normalY;
  const va = supportIndex(a, nx, ny);
  const vb = supportIndex(b, -nx, -ny);
  if (!hasFace(a, va, nx, ny) || !hasFace(b, vb, nx, ny)) return;
  load(a, b);
  faceEnds(ax, ay, a.count, va, va, nx, ny);
  const a0 = face.first;
  const a1 = face.last;
  faceEnds(bx, by, b.count, vb, vb, nx, ny);
  faceMidpoint(a0, a1, face.first, face.last, nx, ny);
  out.pointX = 0.5 * (mid.ax + mid.bx);
  out.pointY = 0.5 * (mid.ay + mid.by);
}

/** Whether vertex v of a shape has a neighbour on the line through it with normal ±(nx, ny) (read through the view). */
function hasFace(s: Shape, v: number, nx: number, ny: number): boolean {
  const n = s.count;
  if (n < 2) return false;
  const prev = v === 0 ? n - 1 : v - 1;
  const next = v + 1 === n ? 0 : v + 1;
  return neighbourOnLine(vertexX(s, v), vertexY(s, v), vertexX(s, prev), vertexY(s, prev), vertexX(s, next), vertexY(s, next), nx, ny);
}

/**
 * Fills the polytope from the simplex, growing degenerate starts into a polygon. False when the result does not
 * enclose the origin (then A − B may still contain it: the caller restarts from boolean GJK) or has no area.
 */
function initPolytope(a: Shape, b: Shape, s: Simplex, tol: number): boolean {
  n = s.count;
  for (let k = 0; k < n; k++) setVertex(k, s.x[k], s.y[k], s.ax[k], s.ay[k], s.bx[k], s.by[k]);
  if (n === 3) {
    const cross = (poly[1 * S + X] - poly[0 * S + X]) * (poly[2 * S + Y] - poly[0 * S + Y]) - (poly[1 * S + Y] - poly[0 * S + Y]) * (poly[2 * S + X] - poly[0 * S + X]);
    const e1 = Math.abs(poly[1 * S + X] - poly[0 * S + X]) + Math.abs(poly[1 * S + Y] - poly[0 * S + Y]);
    const e2 = Math.abs(poly[2 * S + X] - poly[0 * S + X]) + Math.abs(poly[2 * S + Y] - poly[0 * S + Y]);
    if (Math.abs(cross) <= tol * (e1 + e2)) {
      // Collinear: keep the two points farthest apart.
      const d01 = (poly[1 * S + X] - poly[0 * S + X]) ** 2 + (poly[1 * S + Y] - poly[0 * S + Y]) ** 2;
      const d02 = (poly[2 * S + X] - poly[0 * S + X]) ** 2 + (poly[2 * S + Y] - poly[0 * S + Y]) ** 2;
      const d12 = (poly[2 * S + X] - poly[1 * S + X]) ** 2 + (poly[2 * S + Y] - poly[1 * S + Y]) ** 2;
      if (d02 >= d01 && d02 >= d12) copyVertex(1, 2);
      else if (d12 >= d01 && d12 >= d02) copyVertex(0, 2);
      n = 2;
    } else if (cross < 0) {
      swapVertices(1, 2);
    }
  }
  // A lone point at the origin tells nothing (and is no support point): start from a support point instead.
  if (n === 1 && Math.abs(poly[0 * S + X]) + Math.abs(poly[0 * S + Y]) <= tol) n = 0;
  if (n === 0) {
    supportAB(a, b, 1, 0, 0, 0);
    pushSupport(0);
    n = 1;
  }
  if (n === 2 && Math.abs(poly[1 * S + X] - poly[0 * S + X]) + Math.abs(poly[1 * S + Y] - poly[0 * S + Y]) <= tol) n = 1;
  if (n === 1) {
    // A point: add the support point opposite to it (or along ±x, ±y when it is the origin).
    const x0 = poly[0 * S + X];
    const y0 = poly[0 * S + Y];
    const len = Math.sqrt(x0 * x0 + y0 * y0);
    let found = false;
    for (let attempt = 0; attempt < 5 && !found; attempt++) {
      let dx: number;
      let dy: number;
      if (attempt === 0) {
        if (len <= tol) continue;
        dx = -x0;
        dy = -y0;
      } else {
        dx = attempt === 1 ? 1 : attempt === 2 ? -1 : 0;
        dy = attempt === 3 ? 1 : attempt === 4 ? -1 : 0;
      }
      supportAB(a, b, dx, dy, 0, 0);
      const sx = supportAX() - supportBX();
      const sy = supportAY() - supportBY();
      if (Math.abs(sx - x0) + Math.abs(sy - y0) > tol) {
        pushSupport(1);
        found = true;
      }
    }
    if (!found) return false; // A − B is a single point: no area, no penetration
    n = 2;
  }
  if (n === 2) {
    // A segment: add the support points on both sides of it; keep those off the line.
    const ex = poly[1 * S + X] - poly[0 * S + X];
    const ey = poly[1 * S + Y] - poly[0 * S + Y];
    const len = Math.sqrt(ex * ex + ey * ey);
    const nx = -ey / len; // left of p0 → p1
    const ny = ex / len;
    supportAB(a, b, nx, ny, 0, 0);
    const lx = supportAX() - supportBX();
    const ly = supportAY() - supportBY();
    const hl = (lx - poly[0 * S + X]) * nx + (ly - poly[0 * S + Y]) * ny;
    const lax = supportAX(), lay = supportAY(), lbx = supportBX(), lby = supportBY();
    supportAB(a, b, -nx, -ny, 0, 0);
    const rx = supportAX() - supportBX();
    const ry = supportAY() - supportBY();
    const hr = -((rx - poly[0 * S + X]) * nx + (ry - poly[0 * S + Y]) * ny);
    if (hl <= tol && hr <= tol) return false; // A − B is flat
    // Counter-clockwise: p0, [right point], p1, [left point].
    if (hr > tol) {
      copyVertex(2, 1);
      pushSupport(1);
      n = 3;
    }
    if (hl > tol) {
      setVertex(n, lx, ly, lax, lay, lbx, lby);
      n++;
    }
  }
  for (let i = 0; i < n; i++) {
    computeEdge(i);
    if (poly[i * S + D] < -tol) return false; // the origin is outside
  }
  // Convex (a start built from points inside A − B, rather than support points, may not be).
  for (let i = 0; i < n; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    const k = j + 1 === n ? 0 : j + 1;
    if (poly[i * S + NX] * (poly[k * S + X] - poly[j * S + X]) + poly[i * S + NY] * (poly[k * S + Y] - poly[j * S + Y]) > tol) return false;
  }
  return true;
}

function copyVertex(to: number, from: number): void {
  setVertex(to, poly[from * S + X], poly[from * S + Y], poly[from * S + AX], poly[from * S + AY], poly[from * S + BX], poly[from * S + BY]);
}

function swapVertices(i: number, j: number): void {
  const x = poly[i * S + X], y = poly[i * S + Y], ax = poly[i * S + AX], ay = poly[i * S + AY], bx = poly[i * S + BX], by = poly[i * S + BY];
  copyVertex(i, j);
  setVertex(j, x, y, ax, ay, bx, by);
}

const gjkSimplex = new Simplex();

/**
 * Shapes with radii: the penetration of their cores inflated by the radii. Cores apart: from their closest points.
 * Cores overlapping (a circle's centre inside a polygon, crossing segments): EPA on the cores plus the radii.
 */
function rounded(a: Shape, b: Shape, out: Penetration): boolean {
  const ra = a.radius;
  const rb = b.radius;
  const d = coreDistance(a, b);
  let nx: number;
  let ny: number;
  let depth: number;
  let pax: number, pay: number, pbx: number, pby: number;
  if (d > 0) {
    depth = ra + rb - d;
    if (!(depth > 0)) {
      out.hit = false;
      out.depth = 0;
      return false;
    }
    nx = (core.bx - core.ax) / d;
    ny = (core.by - core.ay) / d;
    pax = core.ax;
    pay = core.ay;
    pbx = core.bx;
    pby = core.by;
  } else {
    // The cores overlap or touch: their own penetration (0 when touching), along its normal.
    intersect(a, b, gjkSimplex, 0, 0);
    if (!polytope(a, b, gjkSimplex, out)) return flatCores(a, b, out);
    nx = out.normalX;
    ny = out.normalY;
    const cd = out.depth;
    depth = cd + ra + rb;
    // The polytope's contact point is midway between the cores' surfaces.
    pax = out.pointX + 0.5 * cd * nx;
    pay = out.pointY + 0.5 * cd * ny;
    pbx = out.pointX - 0.5 * cd * nx;
    pby = out.pointY - 0.5 * cd * ny;
  }
  // Outline points: A's core point pushed out by ra along n, B's by rb along −n; the contact point is between.
  out.hit = true;
  out.normalX = nx;
  out.normalY = ny;
  out.depth = depth;
  out.pointX = 0.5 * (pax + ra * nx + pbx - rb * nx);
  out.pointY = 0.5 * (pay + ra * ny + pby - rb * ny);
  return true;
}

/**
 * Rounded shapes whose cores touch or whose core difference has no area (a circle centred on a segment, or two
 * concentric circles): the least overlap over the cores' edge normals, each tried in the direction it faces.
 */
function flatCores(a: Shape, b: Shape, out: Penetration): boolean {
  let bestX = 1;
  let bestY = 0;
  let best = Infinity;
  for (let side = 0; side < 2; side++) {
    const s = side === 0 ? a : b;
    const sign = side === 0 ? 1 : -1; // B's outward normals point from B to A
    const { xs, ys, index, offset, count } = s;
    for (let k = 0; k < count && count > 1; k++) {
      const i = index[offset + k];
      const j = index[offset + (k + 1 === count ? 0 : k + 1)];
      const ex = xs[j] - xs[i];
      const ey = ys[j] - ys[i];
      const len = Math.sqrt(ex * ex + ey * ey);
      if (len === 0) continue;
      const nx = (sign * ey) / len;
      const ny = (-sign * ex) / len;
      supportAB(a, b, nx, ny, a.radius, b.radius);
      const h = (supportAX() - supportBX()) * nx + (supportAY() - supportBY()) * ny;
      if (h < best) {
        best = h;
        bestX = nx;
        bestY = ny;
      }
    }
  }
  supportAB(a, b, bestX, bestY, a.radius, b.radius);
  const depth = (supportAX() - supportBX()) * bestX + (supportAY() - supportBY()) * bestY;
  out.normalX = bestX;
  out.normalY = bestY;
  out.depth = depth > 0 ? depth : 0;
  out.pointX = 0.5 * (supportAX() + supportBX());
  out.pointY = 0.5 * (supportAY() + supportBY());
  out.hit = depth > 0;
  return out.hit;
}

/** Boolean GJK, then EPA from its simplex: the penetration of two shapes, or out.hit = false. */
export function gjkEpa(a: Shape, b: Shape, out: Penetration): boolean {
  if (a.radius > 0 || b.radius > 0) return rounded(a, b, out);
  if (!intersect(a, b, gjkSimplex, 0, 0)) {
    out.hit = false;
    out.depth = 0;
    return false;
  }
  return polytope(a, b, gjkSimplex, out);
}
