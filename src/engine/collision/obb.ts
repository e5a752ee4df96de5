// Oriented bounding box (seed 5.1): the minimum-area enclosing rectangle by rotating calipers over the convex hull
// (one side of the optimum lies along a hull edge, Freeman–Shapira), and the OBB–OBB separating-axis test.
import { quickhullIndices } from './hull.js';
import { readPoints, ShapeType, type PointLike, type Shape } from './shape.js';

/** Centre (cx, cy), unit axis u = (ux, uy) and v = (−uy, ux), half-extents hu along u and hv along v. */
export class OBB {
  cx = 0;
  cy = 0;
  ux = 1;
  uy = 0;
  hu = 0;
  hv = 0;
}

/** The minimum-area rectangle around the shape (radius included), written into `out`. */
export function obbOf(shape: Shape, out: OBB = new OBB()): OBB {
  const { xs, ys, index, offset, count, radius } = shape;
  if (shape.type === ShapeType.Circle) {
    const i = index[offset];
    out.cx = xs[i];
    out.cy = ys[i];
    out.ux = 1;
    out.uy = 0;
    out.hu = out.hv = radius;
    return out;
  }
  const px = new Float64Array(count);
  const py = new Float64Array(count);
  for (let k = 0; k < count; k++) {
    px[k] = xs[index[offset + k]];
    py[k] = ys[index[offset + k]];
  }
  return minimumRectangle(px, py, out);
}

/** The minimum-area rectangle around `points` ({x, y} objects or a flat number list; at least one). */
export function obbFromPoints(points: readonly PointLike[] | readonly number[] | ArrayLike<number>, out: OBB = new OBB()): OBB {
  const { xs, ys } = readPoints('points', points);
  if (xs.length === 0) throw new RangeError('points must hold at least one point, got 0');
  return minimumRectangle(xs, ys, out);
}

function minimumRectangle(xs: Float64Array, ys: Float64Array, out: OBB): OBB {
  const h = quickhullIndices(xs, ys);
  const m = h.length;
  const hx = new Float64Array(m);
  const hy = new Float64Array(m);
  for (let k = 0; k < m; k++) {
    hx[k] = xs[h[k]];
    hy[k] = ys[h[k]];
  }
  if (m === 1) {
    out.cx = hx[0];
    out.cy = hy[0];
    out.ux = 1;
    out.uy = 0;
    out.hu = out.hv = 0;
    return out;
  }
  if (m === 2) {
    const dx = hx[1] - hx[0];
    const dy = hy[1] - hy[0];
    const len = Math.sqrt(dx * dx + dy * dy);
    out.cx = (hx[0] + hx[1]) / 2;
    out.cy = (hy[0] + hy[1]) / 2;
    out.ux = dx / len;
    out.uy = dy / len;
    out.hu = len / 2;
    out.hv = 0;
    return out;
  }
  // Calipers: for edge i (direction u, inward normal v), the points farthest along u, along −u and along v. As i
  // goes round, each of them only moves forward round the hull.
  const dot = (k: number, x: number, y: number) => hx[k] * x + hy[k] * y;
  let bestArea = Infinity;
  let jMax = -1;
  let jMin = -1;
  let jTop = -1;
  for (let i = 0; i < m; i++) {
    const i2 = i + 1 === m ? 0 : i + 1;
    const ex = hx[i2] - hx[i];
    const ey = hy[i2] - hy[i];
    const len = Math.sqrt(ex * ex + ey * ey);
    const ux = ex / len;
    const uy = ey / len;
    const vx = -uy;
    const vy = ux;
    if (jMax < 0) {
      jMax = i2;
      jTop = i2;
      jMin = i;
      for (let k = 0; k < m; k++) {
        if (dot(k, ux, uy) > dot(jMax, ux, uy)) jMax = k;
        if (dot(k, vx, vy) > dot(jTop, vx, vy)) jTop = k;
        if (dot(k, ux, uy) < dot(jMin, ux, uy)) jMin = k;
      }
    } else {
      // Advance each caliper while the next hull point is at least as far (at most m steps each).
      for (let t = 0; t < m && dot((jMax + 1) % m, ux, uy) >= dot(jMax, ux, uy); t++) jMax = (jMax + 1) % m;
      for (let t = 0; t < m && dot((jTop + 1) % m, vx, vy) >= dot(jTop, vx, vy); t++) jTop = (jTop + 1) % m;
      for (let t = 0; t < m && dot((jMin + 1) % m, ux, uy) <= dot(jMin, ux, uy); t++) jMin = (jMin + 1) % m;
    }
    const base = dot(i, vx, vy);
    const lo = dot(jMin, ux, uy);
    const hi = dot(jMax, ux, uy);
    const top = dot(jTop, vx, vy);
    const areaI = (hi - lo) * (top - base);
    if (areaI < bestArea) {
      bestArea = areaI;
      const mu = (hi + lo) / 2;
      const mv = (top + base) / 2;
      out.cx = mu * ux + mv * vx;
      out.cy = mu * uy + mv * vy;
      out.ux = ux;
      out.uy = uy;
      out.hu = (hi - lo) / 2;
      out.hv = (top - base) / 2;
    }
  }
  return out;
}

/** The boxes overlap or touch (separating axes: the two boxes' axes). */
export function obbOverlap(a: OBB, b: OBB): boolean {
  const dx = b.cx - a.cx;
  const dy = b.cy - a.cy;
  // Axes of A then of B: u and v of each.
  for (let k = 0; k < 4; k++) {
    const o = k < 2 ? a : b;
    const ax = k % 2 === 0 ? o.ux : -o.uy;
    const ay = k % 2 === 0 ? o.uy : o.ux;
    const ra = a.hu * Math.abs(a.ux * ax + a.uy * ay) + a.hv * Math.abs(-a.uy * ax + a.ux * ay);
    const rb = b.hu * Math.abs(b.ux * ax + b.uy * ay) + b.hv * Math.abs(-b.uy * ax + b.ux * ay);
    if (Math.abs(dx * ax + dy * ay) > ra + rb) return false;
  }
  return true;
}

/** (x, y) is inside or on the box, with a relative slack of 1e-9 of its size for rounding. */
export function obbContains(box: OBB, x: number, y: number, slack = 1e-9 * (box.hu + box.hv)): boolean {
  const dx = x - box.cx;
  const dy = y - box.cy;
  const u = dx * box.ux + dy * box.uy;
  const v = -dx * box.uy + dy * box.ux;
  return Math.abs(u) <= box.hu + slack && Math.abs(v) <= box.hv + slack;
}
