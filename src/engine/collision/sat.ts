// Separating-axis test with minimum translation vector (seed 3.1, Algorithm 2), fixed per GUIDE.md: the normal is
// signed to point from A to B, and each candidate axis is tested in the one direction that is a facet of the
// Minkowski difference (Box2D's max-separation form), so the depth is exactly the MTV length even when one shape
// contains the other. Shapes that only touch are not a hit.
import type { Penetration } from './results.js';
import { ShapeType, type Shape } from './shape.js';
import { ax, ay, bx, by, load, maxSeparation, pointSeparation, sep } from './scratch.js';

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
  const nax = sep.nx;
  const nay = sep.ny;
  const vb = sep.vertex;
  maxSeparation(bx, by, m, ax, ay, n, 0);
  const sepB = sep.value;
  if (sepB >= 0) return miss(out);
  if (sepA === -Infinity && sepB === -Infinity) return miss(out); // two points: no area to overlap
  if (sepA >= sepB) {
    // Facet of A: B's deepest vertex sits depth below it.
    const depth = -sepA;
    out.hit = true;
    out.normalX = nax;
    out.normalY = nay;
    out.depth = depth;
    out.pointX = bx[vb] + 0.5 * depth * nax;
    out.pointY = by[vb] + 0.5 * depth * nay;
  } else {
    // Facet of B (normal m points from B to A): A's deepest vertex sits depth below it.
    const depth = -sepB;
    const va = sep.vertex;
    out.hit = true;
    out.normalX = -sep.nx;
    out.normalY = -sep.ny;
    out.depth = depth;
    out.pointX = ax[va] + 0.5 * depth * sep.nx;
    out.pointY = ay[va] + 0.5 * depth * sep.ny;
  }
  return true;
}

/** Polygon (or segment) P against circle C; `flip` when C is shape A. */
function polygonCircle(p: Shape, c: Shape, flip: boolean, out: Penetration): boolean {
  const ci = c.index[c.offset];
  const cx = c.xs[ci];
  const cy = c.ys[ci];
  const r = c.radius;
  const { xs, ys, index, offset, count } = p;
  pointSeparation(p, cx, cy, r);
  if (sep.value >= r) return miss(out);
  const best = sep.value;
  const bestI = sep.edge;
  const bnx = sep.nx;
  const bny = sep.ny;
  let nx: number;
  let ny: number;
  let depth: number;
  if (best === -Infinity) {
    // Every edge has zero length: P is a point.
    const v = index[offset];
    const dx = cx - xs[v];
    const dy = cy - ys[v];
    const d = Math.sqrt(dx * dx + dy * dy);
    if (d >= r) return miss(out);
    nx = d > 0 ? dx / d : 1;
    ny = d > 0 ? dy / d : 0;
    depth = r - d;
  } else if (best <= 0) {
    // Centre inside P: push out through the nearest edge.
    nx = bnx;
    ny = bny;
    depth = r - best;
  } else {
    const i1 = index[offset + bestI];
    const i2 = index[offset + (bestI + 1 === count ? 0 : bestI + 1)];
    const x1 = xs[i1];
    const y1 = ys[i1];
    const x2 = xs[i2];
    const y2 = ys[i2];
    const ex = x2 - x1;
    const ey = y2 - y1;
    let vx = NaN;
    let vy = 0;
    if ((cx - x1) * ex + (cy - y1) * ey <= 0) {
      vx = x1;
      vy = y1;
    } else if ((cx - x2) * ex + (cy - y2) * ey >= 0) {
      vx = x2;
      vy = y2;
    }
    if (vx === vx) {
      // Vertex region: the axis through the nearest vertex.
      const dx = cx - vx;
      const dy = cy - vy;
      const d = Math.sqrt(dx * dx + dy * dy);
      if (d >= r) return miss(out);
      nx = dx / d;
      ny = dy / d;
      depth = r - d;
    } else {
      nx = bnx;
      ny = bny;
      depth = r - best;
    }
  }
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
