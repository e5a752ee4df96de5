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
import { shapeSize, type Shape } from './shape.js';

/** Convergence: the support along the closest edge's normal is within this fraction of the shapes' size of it. */
const EPA_TOLERANCE = 1e-10;

// The polytope, counter-clockwise: CSO vertices with their points on A and B, and for edge i (vertex i to i + 1)
// its outward unit normal and distance from the origin.
let px = new Float64Array(32);
let py = new Float64Array(32);
let pax = new Float64Array(32);
let pay = new Float64Array(32);
let pbx = new Float64Array(32);
let pby = new Float64Array(32);
let enx = new Float64Array(32);
let eny = new Float64Array(32);
let ed = new Float64Array(32);
let n = 0;

function reserve(size: number): void {
  if (size <= px.length) return;
  let cap = px.length;
  while (cap < size) cap *= 2;
  const grow = (a: Float64Array) => {
    const b = new Float64Array(cap);
    b.set(a);
    return b;
  };
  px = grow(px);
  py = grow(py);
  pax = grow(pax);
  pay = grow(pay);
  pbx = grow(pbx);
  pby = grow(pby);
  enx = grow(enx);
  eny = grow(eny);
  ed = grow(ed);
}

function setVertex(k: number, x: number, y: number, ax: number, ay: number, bx: number, by: number): void {
  px[k] = x;
  py[k] = y;
  pax[k] = ax;
  pay[k] = ay;
  pbx[k] = bx;
  pby[k] = by;
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
  const j = i + 1 === n ? 0 : i + 1;
  const ex = px[j] - px[i];
  const ey = py[j] - py[i];
  const len = Math.sqrt(ex * ex + ey * ey);
  if (len === 0) {
    enx[i] = 0;
    eny[i] = 0;
    ed[i] = Infinity;
    return false;
  }
  const nx = ey / len;
  const ny = -ex / len;
  enx[i] = nx;
  eny[i] = ny;
  ed[i] = nx * px[i] + ny * py[i];
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
  const scale = shapeSize(a) + shapeSize(b);
  const tol = EPA_TOLERANCE * scale;
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
  let best = 0;
  for (let iter = 0; iter < cap; iter++) {
    // Closest edge to the origin.
    best = 0;
    let dmin = ed[0];
    for (let i = 1; i < n; i++) {
      if (ed[i] < dmin) {
        dmin = ed[i];
        best = i;
      }
    }
    const nx = enx[best];
    const ny = eny[best];
    supportAB(a, b, nx, ny, 0, 0);
    const sx = supportAX() - supportBX();
    const sy = supportAY() - supportBY();
    if (sx * nx + sy * ny - dmin <= tol) break;
    // Insert the support point between the closest edge's endpoints.
    for (let k = n; k > best + 1; k--) {
      px[k] = px[k - 1];
      py[k] = py[k - 1];
      pax[k] = pax[k - 1];
      pay[k] = pay[k - 1];
      pbx[k] = pbx[k - 1];
      pby[k] = pby[k - 1];
      enx[k] = enx[k - 1];
      eny[k] = eny[k - 1];
      ed[k] = ed[k - 1];
    }
    n++;
    pushSupport(best + 1);
    computeEdge(best);
    computeEdge(best + 1);
  }
  // Result from the closest edge: depth, normal, and the witness points by the origin's projection onto the edge.
  let i = 0;
  let depth = ed[0];
  for (let k = 1; k < n; k++) {
    if (ed[k] < depth) {
      depth = ed[k];
      i = k;
    }
  }
  const j = i + 1 === n ? 0 : i + 1;
  const ex = px[j] - px[i];
  const ey = py[j] - py[i];
  let t = -(px[i] * ex + py[i] * ey) / (ex * ex + ey * ey);
  if (!(t > 0)) t = 0;
  else if (t > 1) t = 1;
  const qax = pax[i] + t * (pax[j] - pax[i]);
  const qay = pay[i] + t * (pay[j] - pay[i]);
  const qbx = pbx[i] + t * (pbx[j] - pbx[i]);
  const qby = pby[i] + t * (pby[j] - pby[i]);
  out.normalX = enx[i];
  out.normalY = eny[i];
  out.depth = depth > 0 ? depth : 0;
  out.pointX = 0.5 * (qax + qbx);
  out.pointY = 0.5 * (qay + qby);
  out.hit = depth > 0;
  return out.hit;
}

/**
 * Fills the polytope from the simplex, growing degenerate starts into a polygon. False when the result does not
 * enclose the origin (then A − B may still contain it: the caller restarts from boolean GJK) or has no area.
 */
function initPolytope(a: Shape, b: Shape, s: Simplex, tol: number): boolean {
  n = s.count;
  for (let k = 0; k < n; k++) setVertex(k, s.x[k], s.y[k], s.ax[k], s.ay[k], s.bx[k], s.by[k]);
  if (n === 3) {
    const cross = (px[1] - px[0]) * (py[2] - py[0]) - (py[1] - py[0]) * (px[2] - px[0]);
    const e1 = Math.abs(px[1] - px[0]) + Math.abs(py[1] - py[0]);
    const e2 = Math.abs(px[2] - px[0]) + Math.abs(py[2] - py[0]);
    if (Math.abs(cross) <= tol * (e1 + e2)) {
      // Collinear: keep the two points farthest apart.
      const d01 = (px[1] - px[0]) ** 2 + (py[1] - py[0]) ** 2;
      const d02 = (px[2] - px[0]) ** 2 + (py[2] - py[0]) ** 2;
      const d12 = (px[2] - px[1]) ** 2 + (py[2] - py[1]) ** 2;
      if (d02 >= d01 && d02 >= d12) copyVertex(1, 2);
      else if (d12 >= d01 && d12 >= d02) copyVertex(0, 2);
      n = 2;
    } else if (cross < 0) {
      swapVertices(1, 2);
    }
  }
  // A lone point at the origin tells nothing (and is no support point): start from a support point instead.
  if (n === 1 && Math.abs(px[0]) + Math.abs(py[0]) <= tol) n = 0;
  if (n === 0) {
    supportAB(a, b, 1, 0, 0, 0);
    pushSupport(0);
    n = 1;
  }
  if (n === 2 && Math.abs(px[1] - px[0]) + Math.abs(py[1] - py[0]) <= tol) n = 1;
  if (n === 1) {
    // A point: add the support point opposite to it (or along ±x, ±y when it is the origin).
    const x0 = px[0];
    const y0 = py[0];
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
    const ex = px[1] - px[0];
    const ey = py[1] - py[0];
    const len = Math.sqrt(ex * ex + ey * ey);
    const nx = -ey / len; // left of p0 → p1
    const ny = ex / len;
    supportAB(a, b, nx, ny, 0, 0);
    const lx = supportAX() - supportBX();
    const ly = supportAY() - supportBY();
    const hl = (lx - px[0]) * nx + (ly - py[0]) * ny;
    const lax = supportAX(), lay = supportAY(), lbx = supportBX(), lby = supportBY();
    supportAB(a, b, -nx, -ny, 0, 0);
    const rx = supportAX() - supportBX();
    const ry = supportAY() - supportBY();
    const hr = -((rx - px[0]) * nx + (ry - py[0]) * ny);
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
    if (ed[i] < -tol) return false; // the origin is outside
  }
  // Convex (a start built from points inside A − B, rather than support points, may not be).
  for (let i = 0; i < n; i++) {
    const j = i + 1 === n ? 0 : i + 1;
    const k = j + 1 === n ? 0 : j + 1;
    if (enx[i] * (px[k] - px[j]) + eny[i] * (py[k] - py[j]) > tol) return false;
  }
  return true;
}

function copyVertex(to: number, from: number): void {
  setVertex(to, px[from], py[from], pax[from], pay[from], pbx[from], pby[from]);
}

function swapVertices(i: number, j: number): void {
  const x = px[i], y = py[i], ax = pax[i], ay = pay[i], bx = pbx[i], by = pby[i];
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
