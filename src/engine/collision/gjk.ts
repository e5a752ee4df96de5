// Gilbert–Johnson–Keerthi on the Minkowski difference A − B (seed 3.2).
// - gjkIntersect: boolean GJK after Muratori (Algorithm 5), on the full support functions (a circle's support is
//   centre + r·d/|d|), with an iteration cap so curved supports terminate. Touching is not an intersection.
// - gjkDistance: distance and closest points (Algorithm 3, with the closest point P and the support point V kept
//   apart as GUIDE.md asks), Ericson's Voronoi-region sub-algorithm for the 1- and 2-simplex (Algorithm 4), run on
//   the shapes' cores (polygon, segment, circle centre) with the radii subtracted at the end, which is exact.
import type { ClosestPoints, Simplex } from './results.js';
import { Simplex as SimplexClass } from './results.js';
import type { Shape } from './shape.js';

// ---------------------------------------------------------------------------------------------------------------
// Support of A − B

/** Registers written by supportAB: the support points of A along d and of B along −d. */
let sax = 0;
let say = 0;
let sbx = 0;
let sby = 0;

/** Support of A − B along (dx, dy) with radii ra, rb: sA(d) − sB(−d), into sax/say/sbx/sby. */
export function supportAB(a: Shape, b: Shape, dx: number, dy: number, ra: number, rb: number): void {
  let xs = a.xs;
  let ys = a.ys;
  let index = a.index;
  let offset = a.offset;
  let count = a.count;
  let i = index[offset];
  let best = xs[i] * dx + ys[i] * dy;
  let arg = i;
  for (let k = 1; k < count; k++) {
    i = index[offset + k];
    const d = xs[i] * dx + ys[i] * dy;
    if (d > best) {
      best = d;
      arg = i;
    }
  }
  sax = xs[arg];
  say = ys[arg];
  xs = b.xs;
  ys = b.ys;
  index = b.index;
  offset = b.offset;
  count = b.count;
  i = index[offset];
  best = -(xs[i] * dx + ys[i] * dy);
  arg = i;
  for (let k = 1; k < count; k++) {
    i = index[offset + k];
    const d = -(xs[i] * dx + ys[i] * dy);
    if (d > best) {
      best = d;
      arg = i;
    }
  }
  sbx = xs[arg];
  sby = ys[arg];
  if (ra > 0 || rb > 0) {
    const len = Math.sqrt(dx * dx + dy * dy);
    const ux = len > 0 ? dx / len : 1;
    const uy = len > 0 ? dy / len : 0;
    sax += ra * ux;
    say += ra * uy;
    sbx -= rb * ux;
    sby -= rb * uy;
  }
}

/** The last support pair computed (for EPA, which lives in another module). */
export function lastSupport(out: Simplex, k: number): void {
  out.ax[k] = sax;
  out.ay[k] = say;
  out.bx[k] = sbx;
  out.by[k] = sby;
  out.x[k] = sax - sbx;
  out.y[k] = say - sby;
}

export function supportX(): number {
  return sax - sbx;
}
export function supportY(): number {
  return say - sby;
}
export function supportAX(): number {
  return sax;
}
export function supportAY(): number {
  return say;
}
export function supportBX(): number {
  return sbx;
}
export function supportBY(): number {
  return sby;
}

// ---------------------------------------------------------------------------------------------------------------
// Boolean GJK (Muratori)

const scratchSimplex = new SimplexClass();

/**
 * True when A and B overlap (the origin is strictly inside A − B). With `simplexOut`, leaves there the last
 * simplex: on true a triangle enclosing the origin, ready for epa(). Allocation-free.
 */
export function gjkIntersect(a: Shape, b: Shape, simplexOut?: Simplex): boolean {
  return intersect(a, b, simplexOut ?? scratchSimplex, a.radius, b.radius);
}

/** Search directions shorter than this (|dx| + |dy|) are scaled up to length ~1 before their dot products underflow. */
const TINY = 1e-100;

/** Boolean GJK on A and B inflated by ra and rb (the shapes' radii, or 0 for their cores). */
export function intersect(a: Shape, b: Shape, s: Simplex, ra: number, rb: number): boolean {
  // Simplex points, newest first: A (a*), B (b*), C (c*). x, y is the CSO point; ax.. the shapes' points.
  let Ax = 0, Ay = 0, Aax = 0, Aay = 0, Abx = 0, Aby = 0;
  let Bx = 0, By = 0, Bax = 0, Bay = 0, Bbx = 0, Bby = 0;
  let Cx = 0, Cy = 0, Cax = 0, Cay = 0, Cbx = 0, Cby = 0;
  let count = 1;
  let result = false;
  // First direction: between the shapes' first vertices.
  const ia = a.index[a.offset];
  const ib = b.index[b.offset];
  let dx = a.xs[ia] - b.xs[ib];
  let dy = a.ys[ia] - b.ys[ib];
  if (dx === 0 && dy === 0) dx = 1;
  // Only the direction matters; a tiny one (shapes that differ by denormals) would underflow in the dot products.
  let m = Math.abs(dx) + Math.abs(dy);
  if (m < TINY) {
    dx /= m;
    dy /= m;
  }
  supportAB(a, b, dx, dy, ra, rb);
  Bax = sax; Bay = say; Bbx = sbx; Bby = sby;
  Bx = sax - sbx;
  By = say - sby;
  dx = -Bx;
  dy = -By;
  if (dx !== 0 || dy !== 0) {
    const cap = 64 + a.count + b.count;
    for (let iter = 0; iter < cap; iter++) {
      m = Math.abs(dx) + Math.abs(dy);
      if (m < TINY) {
        dx /= m;
        dy /= m;
      }
      supportAB(a, b, dx, dy, ra, rb);
      const px = sax - sbx;
      const py = say - sby;
      // The new point does not pass the origin along d: d separates the origin from A − B (or touches it).
      if (px * dx + py * dy <= 0) break;
      if (count === 1) {
        Ax = px; Ay = py; Aax = sax; Aay = say; Abx = sbx; Aby = sby;
        count = 2;
        // Line [B, A]: A passed the origin along −B, so the origin projects inside AB; head perpendicular to it.
        const abx = Bx - Ax;
        const aby = By - Ay;
        const side = aby * Ax - abx * Ay; // cross(AB, AO)
        if (side > 0) {
          dx = -aby;
          dy = abx;
        } else if (side < 0) {
          dx = aby;
          dy = -abx;
        } else {
          // The origin lies on segment AB: inside iff A − B extends past the line on both sides.
          supportAB(a, b, -aby, abx, ra, rb);
          if ((sax - sbx) * -aby + (say - sby) * abx <= 0) break;
          Cx = Bx; Cy = By; Cax = Bax; Cay = Bay; Cbx = Bbx; Cby = Bby;
          Bx = Ax; By = Ay; Bax = Aax; Bay = Aay; Bbx = Abx; Bby = Aby;
          Ax = sax - sbx; Ay = say - sby; Aax = sax; Aay = say; Abx = sbx; Aby = sby;
          count = 3;
          supportAB(a, b, aby, -abx, ra, rb);
          if ((sax - sbx) * aby + (say - sby) * -abx <= 0) break;
          result = true;
          break;
        }
        continue;
      }
      // Triangle [C, B, A] with A newest.
      Cx = Bx; Cy = By; Cax = Bax; Cay = Bay; Cbx = Bbx; Cby = Bby;
      Bx = Ax; By = Ay; Bax = Aax; Bay = Aay; Bbx = Abx; Bby = Aby;
      Ax = px; Ay = py; Aax = sax; Aay = say; Abx = sbx; Aby = sby;
      count = 3;
      const abx = Bx - Ax;
      const aby = By - Ay;
      const acx = Cx - Ax;
      const acy = Cy - Ay;
      // Normal of AB away from C.
      let nx = -aby;
      let ny = abx;
      if (nx * acx + ny * acy > 0) {
        nx = -nx;
        ny = -ny;
      }
      if (-(nx * Ax + ny * Ay) >= 0) {
        // Origin beyond AB (or on it): drop C.
        count = 2;
        dx = nx;
        dy = ny;
        continue;
      }
      nx = -acy;
      ny = acx;
      if (nx * abx + ny * aby > 0) {
        nx = -nx;
        ny = -ny;
      }
      if (-(nx * Ax + ny * Ay) >= 0) {
        // Origin beyond AC: drop B.
        Bx = Cx; By = Cy; Bax = Cax; Bay = Cay; Bbx = Cbx; Bby = Cby;
        count = 2;
        dx = nx;
        dy = ny;
        continue;
      }
      result = true;
      break;
    }
  }
  // Write the simplex out, oldest first.
  if (count === 1) {
    s.count = 1;
    s.x[0] = Bx; s.y[0] = By; s.ax[0] = Bax; s.ay[0] = Bay; s.bx[0] = Bbx; s.by[0] = Bby;
  } else {
    let k = 0;
    if (count === 3) {
      s.x[0] = Cx; s.y[0] = Cy; s.ax[0] = Cax; s.ay[0] = Cay; s.bx[0] = Cbx; s.by[0] = Cby;
      k = 1;
    }
    s.x[k] = Bx; s.y[k] = By; s.ax[k] = Bax; s.ay[k] = Bay; s.bx[k] = Bbx; s.by[k] = Bby;
    s.x[k + 1] = Ax; s.y[k + 1] = Ay; s.ax[k + 1] = Aax; s.ay[k + 1] = Aay; s.bx[k + 1] = Abx; s.by[k + 1] = Aby;
    s.count = count;
  }
  return result;
}

// ---------------------------------------------------------------------------------------------------------------
// GJK distance (cores) with Ericson's Voronoi-region sub-algorithm

// Simplex of the distance loop: CSO points w, the vertex indices that made them, barycentric weights.
const wx = new Float64Array(3);
const wy = new Float64Array(3);
const wi = new Int32Array(3); // vertex index in A
const wj = new Int32Array(3); // vertex index in B
const lam = new Float64Array(3);
let wcount = 0;

function copyVertex(to: number, from: number): void {
  wx[to] = wx[from];
  wy[to] = wy[from];
  wi[to] = wi[from];
  wj[to] = wj[from];
}

/** Closest point of segment w0 w1 to the origin by Voronoi regions; keeps only the vertices it needs. */
function solve2(): void {
  const ex = wx[1] - wx[0];
  const ey = wy[1] - wy[0];
  // Region of w0: the origin projects before it.
  const d2 = -(wx[0] * ex + wy[0] * ey);
  if (d2 <= 0) {
    lam[0] = 1;
    wcount = 1;
    return;
  }
  // Region of w1.
  const d1 = wx[1] * ex + wy[1] * ey;
  if (d1 <= 0) {
    copyVertex(0, 1);
    lam[0] = 1;
    wcount = 1;
    return;
  }
  const inv = 1 / (d1 + d2);
  lam[0] = d1 * inv;
  lam[1] = d2 * inv;
  wcount = 2;
}

/** Closest point of triangle w0 w1 w2 to the origin: vertex, edge or face region (Ericson; Box2D's b2Simplex::Solve3). */
function solve3(): void {
  const x1 = wx[0], y1 = wy[0], x2 = wx[1], y2 = wy[1], x3 = wx[2], y3 = wy[2];
  // Edge 12
  const e12x = x2 - x1, e12y = y2 - y1;
  const d12_1 = x2 * e12x + y2 * e12y;
  const d12_2 = -(x1 * e12x + y1 * e12y);
  // Edge 13
  const e13x = x3 - x1, e13y = y3 - y1;
  const d13_1 = x3 * e13x + y3 * e13y;
  const d13_2 = -(x1 * e13x + y1 * e13y);
  // Edge 23
  const e23x = x3 - x2, e23y = y3 - y2;
  const d23_1 = x3 * e23x + y3 * e23y;
  const d23_2 = -(x2 * e23x + y2 * e23y);
  // Triangle: signed areas of the sub-triangles with the origin, times the sign of the triangle's orientation
  // (Box2D multiplies by the orientation itself: a product of four lengths, which underflows to 0 for shapes 1e-80
  // across, giving weights 0/0, and overflows for 1e80; only its sign matters to the regions and the weights).
  const n123 = e12x * e13y - e12y * e13x;
  const o123 = n123 > 0 ? 1 : n123 < 0 ? -1 : 0;
  const d123_1 = o123 * (x2 * y3 - y2 * x3);
  const d123_2 = o123 * (x3 * y1 - y3 * x1);
  const d123_3 = o123 * (x1 * y2 - y1 * x2);

  if (d12_2 <= 0 && d13_2 <= 0) {
    lam[0] = 1;
    wcount = 1;
    return;
  }
  if (d12_1 > 0 && d12_2 > 0 && d123_3 <= 0) {
    const inv = 1 / (d12_1 + d12_2);
    lam[0] = d12_1 * inv;
    lam[1] = d12_2 * inv;
    wcount = 2;
    return;
  }
  if (d13_1 > 0 && d13_2 > 0 && d123_2 <= 0) {
    const inv = 1 / (d13_1 + d13_2);
    lam[0] = d13_1 * inv;
    lam[1] = d13_2 * inv;
    copyVertex(1, 2);
    wcount = 2;
    return;
  }
  if (d12_1 <= 0 && d23_2 <= 0) {
    copyVertex(0, 1);
    lam[0] = 1;
    wcount = 1;
    return;
  }
  if (d13_1 <= 0 && d23_1 <= 0) {
    copyVertex(0, 2);
    lam[0] = 1;
    wcount = 1;
    return;
  }
  if (d23_1 > 0 && d23_2 > 0 && d123_1 <= 0) {
    const inv = 1 / (d23_1 + d23_2);
    copyVertex(0, 2); // slot 0: w3, slot 1: w2
    lam[0] = d23_2 * inv;
    lam[1] = d23_1 * inv;
    wcount = 2;
    return;
  }
  // Face region: the origin is inside the triangle.
  const inv = 1 / (d123_1 + d123_2 + d123_3);
  lam[0] = d123_1 * inv;
  lam[1] = d123_2 * inv;
  lam[2] = d123_3 * inv;
  wcount = 3;
}

/**
 * Closest points of the cores, written by coreDistance, and the magnitude of the coordinates they were made of (the
 * largest |ax| + |ay| + |bx| + |by| over the vertices of the final simplex), for rounding allowances.
 */
export const core = { ax: 0, ay: 0, bx: 0, by: 0, iterations: 0, magnitude: 0 };

/**
 * A distance at most this fraction of the coordinates' magnitude may be rounding (about 4,500 ulps; the loop's own
 * errors are a few): the distance functions then ask boolean GJK whether the shapes overlap.
 */
const NEAR_ZERO = 1e-12;

/**
 * Distance between the cores of A and B (their vertices' convex hulls: a circle's centre, a segment, a polygon),
 * with the closest points in `core`; 0 when the cores overlap or touch (then core.a = core.b is a common point), and
 * always when boolean GJK says the cores overlap. Exact for polygons up to rounding: it stops when a support vertex
 * repeats or stops bringing the simplex closer.
 */
export function coreDistance(a: Shape, b: Shape): number {
  const axs = a.xs, ays = a.ys, aidx = a.index, aoff = a.offset, an = a.count;
  const bxs = b.xs, bys = b.ys, bidx = b.index, boff = b.offset, bn = b.count;
  wi[0] = 0;
  wj[0] = 0;
  wx[0] = axs[aidx[aoff]] - bxs[bidx[boff]];
  wy[0] = ays[aidx[aoff]] - bys[bidx[boff]];
  lam[0] = 1;
  wcount = 1;
  const cap = 20 + 2 * (an + bn);
  let iter = 0;
  let overlap = false;
  while (iter < cap) {
    const saved = wcount;
    const si0 = wi[0], sj0 = wj[0], si1 = wi[1], sj1 = wj[1], si2 = wi[2], sj2 = wj[2];
    if (wcount === 2) solve2();
    else if (wcount === 3) solve3();
    if (wcount === 3) {
      overlap = true;
      break;
    }
    // Closest point P of the simplex, and the search direction.
    let px: number;
    let py: number;
    let dx: number;
    let dy: number;
    if (wcount === 1) {
      px = wx[0];
      py = wy[0];
      dx = -px;
      dy = -py;
    } else {
      px = lam[0] * wx[0] + lam[1] * wx[1];
      py = lam[0] * wy[0] + lam[1] * wy[1];
      // Perpendicular to the edge towards the origin: more accurate than −P when P is small.
      const ex = wx[1] - wx[0];
      const ey = wy[1] - wy[0];
      const side = ex * -wy[0] - ey * -wx[0];
      if (side > 0) {
        dx = -ey;
        dy = ex;
      } else {
        dx = ey;
        dy = -ex;
      }
    }
    const pp = px * px + py * py;
    if (pp === 0 || dx * dx + dy * dy === 0) {
      overlap = true; // the origin is on the simplex
      break;
    }
    // Support of the cores along d.
    let i = 0;
    let best = -Infinity;
    for (let k = 0; k < an; k++) {
      const v = aidx[aoff + k];
      const d = axs[v] * dx + ays[v] * dy;
      if (d > best) {
        best = d;
        i = k;
      }
    }
    let j = 0;
    best = -Infinity;
    for (let k = 0; k < bn; k++) {
      const v = bidx[boff + k];
      const d = -(bxs[v] * dx + bys[v] * dy);
      if (d > best) {
        best = d;
        j = k;
      }
    }
    iter++;
    // A repeated vertex: the simplex already holds the closest feature.
    if (
      (i === si0 && j === sj0) ||
      (saved > 1 && i === si1 && j === sj1) ||
      (saved > 2 && i === si2 && j === sj2)
    ) {
      break;
    }
    const vx = axs[aidx[aoff + i]] - bxs[bidx[boff + j]];
    const vy = ays[aidx[aoff + i]] - bys[bidx[boff + j]];
    // Gilbert's test: V gets no closer to the origin along d than the simplex is (relative to that distance):
    // converged. Measured from vertex w0 along d, not as |P|² − P·V: P is interpolated along the edge and rounded
    // by ulps of the edge's length, which P·V multiplies by |V|, so on a long thin A − B (a segment 1e11 times
    // longer than the one crossing it) the test passed at a distance of 1e-11 of the size with the origin inside.
    const h = wx[0] * dx + wy[0] * dy; // < 0: the simplex lies behind the origin along d
    if ((vx - wx[0]) * dx + (vy - wy[0]) * dy <= -1e-14 * h) break;
    wx[wcount] = vx;
    wy[wcount] = vy;
    wi[wcount] = i;
    wj[wcount] = j;
    wcount++;
  }
  // Witness points on the cores, and the magnitude of the coordinates they are made of (for the rounding below).
  let pax = 0, pay = 0, pbx = 0, pby = 0;
  let magnitude = 0;
  for (let k = 0; k < wcount; k++) {
    const va = aidx[aoff + wi[k]];
    const vb = bidx[boff + wj[k]];
    pax += lam[k] * axs[va];
    pay += lam[k] * ays[va];
    pbx += lam[k] * bxs[vb];
    pby += lam[k] * bys[vb];
    const m = Math.abs(axs[va]) + Math.abs(ays[va]) + Math.abs(bxs[vb]) + Math.abs(bys[vb]);
    if (m > magnitude) magnitude = m;
  }
  core.iterations = iter;
  core.magnitude = magnitude;
  // The loop can stop on an edge of the simplex that passes through the origin up to rounding, and report the
  // rounding (1e-16 of the coordinates) as a distance: a square nested in a square with a vertex on the other's
  // diagonal puts a diagonal of A − B through the origin, and the support across it is the vertex solve3 just
  // dropped. So a distance within rounding of 0 is settled by boolean GJK, the test gjkIntersect makes.
  const gap = Math.abs(pbx - pax) + Math.abs(pby - pay);
  if (!overlap && gap <= NEAR_ZERO * magnitude && intersect(a, b, scratchSimplex, 0, 0)) overlap = true;
  if (overlap) {
    pbx = pax;
    pby = pay;
  }
  core.ax = pax;
  core.ay = pay;
  core.bx = pbx;
  core.by = pby;
  const ddx = pbx - pax;
  const ddy = pby - pay;
  return Math.sqrt(ddx * ddx + ddy * ddy);
}

/**
 * Distance between A and B and their closest points, written into `out`; returns the distance (0 when they overlap
 * or touch, exactly 0 whenever gjkIntersect says they overlap, and then out.ax/ay = out.bx/by is a point common to
 * both, to rounding). Runs on the cores, then takes off the radii.
 */
export function gjkDistance(a: Shape, b: Shape, out: ClosestPoints): number {
  const d = coreDistance(a, b);
  out.iterations = core.iterations;
  const pax = core.ax;
  const pay = core.ay;
  const pbx = core.bx;
  const pby = core.by;
  const ra = a.radius;
  const rb = b.radius;
  const ddx = pbx - pax;
  const ddy = pby - pay;
  if (d > 0) {
    const nx = ddx / d;
    const ny = ddy / d;
    const sepd = d - ra - rb;
    // A gap within rounding that boolean GJK on the full shapes calls an overlap (their curved supports are rounded
    // too; the cores alone were settled in coreDistance) is one: the distance is 0 whenever gjkIntersect is true.
    const rounding = NEAR_ZERO * (core.magnitude + ra + rb);
    const overlap = sepd > 0 && sepd <= rounding && (ra > 0 || rb > 0) && intersect(a, b, scratchSimplex, ra, rb);
    if (sepd > 0 && !overlap) {
      out.distance = sepd;
      out.ax = pax + ra * nx;
      out.ay = pay + ra * ny;
      out.bx = pbx - rb * nx;
      out.by = pby - rb * ny;
      out.normalX = nx;
      out.normalY = ny;
      return sepd;
    }
    // Cores apart but the radii overlap: on the line through the core points, A covers [−ra, ra] from its core
    // point and B covers [d − rb, d + rb]; a common point is the middle of the two intervals' intersection (of the
    // gap between them, when it is within rounding).
    const lo = d - rb > -ra ? d - rb : -ra;
    const hi = ra < d + rb ? ra : d + rb;
    const t = (lo + hi) / (2 * d);
    out.ax = out.bx = pax + t * ddx;
    out.ay = out.by = pay + t * ddy;
  } else {
    out.ax = out.bx = pax;
    out.ay = out.by = pay;
  }
  out.distance = 0;
  out.normalX = 0;
  out.normalY = 0;
  return 0;
}
