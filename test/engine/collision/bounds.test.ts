import { expect } from 'chai';
import fc from 'fast-check';
import {
  AABB, BoundingCircle, KDOP8, OBB, Penetration, ShapeType, aabbArea, aabbContains, aabbOf, aabbOverlap, boundingCircle,
  boundingCircleOf, boundingCircleOverlap, kdopContains, kdopOf, kdopOverlap, obbContains, obbFromPoints, obbOf,
  obbOverlap, polygon, quickhull, quickhullIndices, sat, type Shape,
} from '../../../src/engine/collision/index.js';
import { Failures, KINDS, make, monotoneChain, pts, randomPair, randomShape, rng, shoelace2, sizeOf, throwsNaming } from './helpers.js';

type P = { x: number; y: number };

/** Sample points of a shape's outline (a circle's at 64 angles), to check containment. */
function outline(s: Shape): P[] {
  if (s.type !== ShapeType.Circle) return pts(s);
  const c = pts(s)[0];
  return Array.from({ length: 64 }, (_, k) => ({ x: c.x + s.radius * Math.cos((k * Math.PI) / 32), y: c.y + s.radius * Math.sin((k * Math.PI) / 32) }));
}

/** A hull as a cycle starting at its lowest (x, y) point, for comparing two hull algorithms. */
function canonical(h: P[]): string {
  let start = 0;
  for (let k = 1; k < h.length; k++) if (h[k].x < h[start].x || (h[k].x === h[start].x && h[k].y < h[start].y)) start = k;
  return h.slice(start).concat(h.slice(0, start)).map((p) => `${p.x},${p.y}`).join(' ');
}

function boxPolygon(b: AABB): Shape {
  return polygon([b.minX, b.minY, b.maxX, b.minY, b.maxX, b.maxY, b.minX, b.maxY]);
}

function obbPolygon(o: OBB): Shape {
  const vx = -o.uy;
  const vy = o.ux;
  const c = [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([su, sv]) => ({
    x: o.cx + su * o.hu * o.ux + sv * o.hv * vx,
    y: o.cy + su * o.hu * o.uy + sv * o.hv * vy,
  }));
  return make(ShapeType.Polygon, c.map((p) => p.x), c.map((p) => p.y));
}

/** The 8-DOP as a polygon: its bounding box clipped by the two diagonal slabs (Sutherland–Hodgman). */
function kdopPolygon(d: KDOP8): Shape {
  let poly: P[] = [
    { x: d.min[0], y: d.min[1] }, { x: d.max[0], y: d.min[1] }, { x: d.max[0], y: d.max[1] }, { x: d.min[0], y: d.max[1] },
  ];
  const planes: [number, number, number][] = [
    [1, 1, d.max[2]], [-1, -1, -d.min[2]], [1, -1, d.max[3]], [-1, 1, -d.min[3]],
  ];
  for (const [a, b, c] of planes) {
    const next: P[] = [];
    for (let k = 0; k < poly.length; k++) {
      const p = poly[k];
      const q = poly[(k + 1) % poly.length];
      const fp = a * p.x + b * p.y - c;
      const fq = a * q.x + b * q.y - c;
      if (fp <= 0) next.push(p);
      if (fp * fq < 0) {
        const t = fp / (fp - fq);
        next.push({ x: p.x + t * (q.x - p.x), y: p.y + t * (q.y - p.y) });
      }
    }
    poly = next;
  }
  return make(ShapeType.Polygon, poly.map((p) => p.x), poly.map((p) => p.y));
}

describe('bounding volumes', () => {
  it('AABB, bounding circle, OBB and 8-DOP contain every point of 10,000 random shapes, and are tight', () => {
    const r = rng(6001);
    const fail = new Failures();
    const box = new AABB();
    const circ = new BoundingCircle();
    const obb = new OBB();
    const dop = new KDOP8();
    for (let k = 0; k < 10_000; k++) {
      const s = randomShape(r, KINDS[k % 3], r() * 10 - 5, r() * 10 - 5, 0.1 + r() * 3);
      const size = sizeOf(s);
      const tol = 1e-9 * size;
      aabbOf(s, box);
      boundingCircleOf(s, circ);
      obbOf(s, obb);
      kdopOf(s, dop);
      const o = outline(s);
      for (const p of o) {
        const grow = new AABB();
        Object.assign(grow, { minX: box.minX - tol, minY: box.minY - tol, maxX: box.maxX + tol, maxY: box.maxY + tol });
        if (!aabbContains(grow, p.x, p.y)) fail.add('AABB misses a point');
        if (Math.hypot(p.x - circ.x, p.y - circ.y) > circ.r + tol) fail.add('circle misses a point');
        if (!obbContains(obb, p.x, p.y)) fail.add('OBB misses a point');
        const dd = new KDOP8();
        for (let j = 0; j < 4; j++) {
          dd.min[j] = dop.min[j] - 2 * tol;
          dd.max[j] = dop.max[j] + 2 * tol;
        }
        if (!kdopContains(dd, p.x, p.y)) fail.add('8-DOP misses a point');
      }
      // Tight: some point touches each side of the AABB and each slab of the 8-DOP.
      const touches = (f: (p: P) => number, v: number) => o.some((p) => Math.abs(f(p) - v) <= 1e-6 * size + 1e-12);
      if (s.type !== ShapeType.Circle) {
        const sides: [string, (p: P) => number, number][] = [['minX', (p) => p.x, box.minX], ['maxX', (p) => p.x, box.maxX], ['minY', (p) => p.y, box.minY], ['maxY', (p) => p.y, box.maxY]];
        for (const [side, f, v] of sides) if (!touches(f, v)) fail.add(`AABB not tight at ${side}`);
        const axes: ((p: P) => number)[] = [(p) => p.x, (p) => p.y, (p) => p.x + p.y, (p) => p.x - p.y];
        for (let k = 0; k < 4; k++) {
          if (!touches(axes[k], dop.min[k]) || !touches(axes[k], dop.max[k])) fail.add(`8-DOP not tight on slab ${k}`);
        }
        // OBB: no larger than the AABB, and some point on each of its four sides.
        if (4 * obb.hu * obb.hv > aabbArea(box) * (1 + 1e-12) + tol) fail.add(`OBB area ${4 * obb.hu * obb.hv} > AABB ${aabbArea(box)}`);
        const u = (p: P) => (p.x - obb.cx) * obb.ux + (p.y - obb.cy) * obb.uy;
        const v = (p: P) => -(p.x - obb.cx) * obb.uy + (p.y - obb.cy) * obb.ux;
        if (!touches(u, obb.hu) || !touches(u, -obb.hu) || !touches(v, obb.hv) || !touches(v, -obb.hv)) fail.add('OBB not tight');
      } else {
        if (Math.abs(circ.r - s.radius) > tol) fail.add('circle bound of a circle');
        // A circle's box and slabs are its centre's ± r (± r·√2 on the diagonals' unnormalized axes).
        const r = s.radius;
        const r2 = r * Math.SQRT2;
        if (Math.abs(box.maxX - box.minX - 2 * r) > tol || Math.abs(box.maxY - box.minY - 2 * r) > tol) fail.add('AABB of a circle not 2r wide');
        if (Math.abs(dop.max[2] - dop.min[2] - 2 * r2) > 2 * tol || Math.abs(dop.max[3] - dop.min[3] - 2 * r2) > 2 * tol) fail.add('8-DOP of a circle not tight');
      }
    }
    fail.check();
  });

  it('the OBB is the minimum-area rectangle (brute force over every hull edge direction) and finds rotated rectangles', () => {
    const r = rng(6002);
    const fail = new Failures();
    const obb = new OBB();
    for (let k = 0; k < 2000; k++) {
      const n = 3 + Math.floor(r() * 30);
      const points = Array.from({ length: n }, () => ({ x: r() * 4 - 2, y: r() * 2 - 1 }));
      obbFromPoints(points, obb);
      const hull = monotoneChain(points);
      let best = Infinity;
      for (let i = 0; i < hull.length; i++) {
        const q = hull[(i + 1) % hull.length];
        const len = Math.hypot(q.x - hull[i].x, q.y - hull[i].y);
        const ux = (q.x - hull[i].x) / len;
        const uy = (q.y - hull[i].y) / len;
        const us = points.map((p) => p.x * ux + p.y * uy);
        const vs = points.map((p) => -p.x * uy + p.y * ux);
        best = Math.min(best, (Math.max(...us) - Math.min(...us)) * (Math.max(...vs) - Math.min(...vs)));
      }
      if (Math.abs(4 * obb.hu * obb.hv - best) > 1e-9 * best) fail.add(`OBB area ${4 * obb.hu * obb.hv}, brute force ${best}`);
    }
    for (let k = 0; k < 200; k++) {
      const a = r() * Math.PI;
      const w = 0.5 + r() * 3;
      const h = 0.5 + r() * 3;
      const c = Math.cos(a);
      const s = Math.sin(a);
      const corners = [[-w, -h], [w, -h], [w, h], [-w, h], [0, 0], [w / 2, h / 3]].map(([x, y]) => ({ x: 1 + x * c - y * s, y: 2 + x * s + y * c }));
      obbFromPoints(corners, obb);
      if (Math.abs(obb.hu * obb.hv - w * h) > 1e-9 * w * h) fail.add(`rotated rectangle area ${4 * obb.hu * obb.hv} vs ${4 * w * h}`);
      if (Math.abs(obb.cx - 1) > 1e-9 || Math.abs(obb.cy - 2) > 1e-9) fail.add('rotated rectangle centre');
    }
    fail.check();
  });

  it('the bounding circle is the smallest (brute force over pairs and triples)', () => {
    const r = rng(6003);
    const fail = new Failures();
    const circ = new BoundingCircle();
    for (let k = 0; k < 2000; k++) {
      const n = 1 + Math.floor(r() * 9);
      const p = Array.from({ length: n }, () => ({ x: r() * 2, y: r() * 2 }));
      boundingCircle(p, circ);
      const encloses = (cx: number, cy: number, rr: number) => p.every((q) => Math.hypot(q.x - cx, q.y - cy) <= rr * (1 + 1e-9) + 1e-12);
      let best = n === 1 ? 0 : Infinity;
      for (let i = 0; i < n; i++) {
        for (let j = i + 1; j < n; j++) {
          const cx = (p[i].x + p[j].x) / 2;
          const cy = (p[i].y + p[j].y) / 2;
          const rr = Math.hypot(p[i].x - cx, p[i].y - cy);
          if (encloses(cx, cy, rr)) best = Math.min(best, rr);
          for (let l = j + 1; l < n; l++) {
            const bx = p[j].x - p[i].x, by = p[j].y - p[i].y, qx = p[l].x - p[i].x, qy = p[l].y - p[i].y;
            const d = 2 * (bx * qy - by * qx);
            if (d === 0) continue;
            const ux = (qy * (bx * bx + by * by) - by * (qx * qx + qy * qy)) / d;
            const uy = (bx * (qx * qx + qy * qy) - qx * (bx * bx + by * by)) / d;
            if (encloses(p[i].x + ux, p[i].y + uy, Math.hypot(ux, uy))) best = Math.min(best, Math.hypot(ux, uy));
          }
        }
      }
      if (!encloses(circ.x, circ.y, circ.r)) fail.add('does not enclose');
      if (Math.abs(circ.r - best) > 1e-9 * Math.max(best, 1)) fail.add(`radius ${circ.r}, brute force ${best}`);
    }
    fail.check();
    throwsNaming(() => boundingCircle([]), RangeError, 'points', '0');
    throwsNaming(() => obbFromPoints([{ x: 0, y: NaN }]), RangeError, 'points[0].y', 'NaN');
  });

  it('overlap tests: AABB and OBB agree with SAT on their rectangles, 8-DOP with SAT on its octagon, and all are conservative', () => {
    const r = rng(6004);
    const fail = new Failures();
    const pen = new Penetration();
    const a1 = new AABB(), a2 = new AABB(), o1 = new OBB(), o2 = new OBB(), d1 = new KDOP8(), d2 = new KDOP8();
    const c1 = new BoundingCircle(), c2 = new BoundingCircle();
    let shapeHits = 0;
    let boxOnly = 0;
    let dopOnly = 0;
    for (let k = 0; k < 10_000; k++) {
      const [a, b] = randomPair(r, KINDS[k % 3], KINDS[Math.floor(k / 3) % 3], 1, 1.8);
      aabbOf(a, a1);
      aabbOf(b, a2);
      obbOf(a, o1);
      obbOf(b, o2);
      kdopOf(a, d1);
      kdopOf(b, d2);
      boundingCircleOf(a, c1);
      boundingCircleOf(b, c2);
      const boxes = aabbOverlap(a1, a2);
      const obbs = obbOverlap(o1, o2);
      const dops = kdopOverlap(d1, d2);
      if (boxes !== sat(boxPolygon(a1), boxPolygon(a2), pen)) fail.add('aabbOverlap vs SAT on the boxes');
      if (o1.hv > 0 && o2.hv > 0 && obbs !== sat(obbPolygon(o1), obbPolygon(o2), pen)) fail.add('obbOverlap vs SAT on the boxes');
      if (dops !== sat(kdopPolygon(d1), kdopPolygon(d2), pen)) fail.add('kdopOverlap vs SAT on the octagons');
      if (sat(a, b, pen)) {
        shapeHits++;
        if (!boxes || !obbs || !dops || !boundingCircleOverlap(c1, c2)) fail.add('a bounding volume misses an overlap');
      }
      // The 8-DOP lies inside the AABB: it never overlaps where the boxes do not.
      if (dops && !boxes) fail.add('8-DOP overlap without AABB overlap');
      if (boxes && !dops) dopOnly++;
      if (boxes && !sat(a, b, pen)) boxOnly++;
    }
    fail.check();
    expect(shapeHits).to.be.greaterThan(1000);
    expect(dopOnly).to.be.greaterThan(0); // the diagonals reject some pairs the boxes accept
    expect(boxOnly).to.be.greaterThan(dopOnly);
  });
});

describe('quickhull', () => {
  it('equals the monotone-chain hull on 10,000 random point sets, with duplicates and collinear points', () => {
    const r = rng(7001);
    const fail = new Failures();
    for (let k = 0; k < 10_000; k++) {
      const n = 1 + Math.floor(r() * 40);
      // Small integer grids give many exact duplicates and collinear triples; the rest are real coordinates.
      const grid = k % 2 === 0;
      const points = Array.from({ length: n }, () => (grid ? { x: Math.floor(r() * 6), y: Math.floor(r() * 6) } : { x: r() * 100 - 50, y: r() * 100 - 50 }));
      if (k % 7 === 0) points.push(...points.slice(0, 5)); // repeat some
      const q = quickhull(points);
      const m = monotoneChain(points);
      if (canonical(q) !== canonical(m)) fail.add(`quickhull ${canonical(q)} vs monotone chain ${canonical(m)}`);
      if (q.length >= 3 && !(shoelace2(q) > 0)) fail.add('not counter-clockwise');
    }
    fail.check();
  });

  it('handles degenerate input: all equal, all collinear, large sets on a circle', () => {
    expect(quickhull([{ x: 1, y: 1 }, { x: 1, y: 1 }])).to.deep.equal([{ x: 1, y: 1 }]);
    expect(quickhull([0, 0, 1, 1, 2, 2, 3, 3, 1, 1])).to.deep.equal([{ x: 0, y: 0 }, { x: 3, y: 3 }]);
    expect(quickhull([0, 5, 0, 1, 0, 3])).to.deep.equal([{ x: 0, y: 1 }, { x: 0, y: 5 }]);
    expect(quickhull([])).to.deep.equal([]);
    const n = 20_000;
    const xs = new Float64Array(n);
    const ys = new Float64Array(n);
    const r = rng(7002);
    for (let k = 0; k < n; k++) {
      const a = r() * 2 * Math.PI;
      const rr = k % 2 === 0 ? 1 : r();
      xs[k] = rr * Math.cos(a);
      ys[k] = rr * Math.sin(a);
    }
    const h = quickhullIndices(xs, ys);
    const ref = monotoneChain(Array.from(xs, (x, k) => ({ x, y: ys[k] })));
    expect(h.length).to.equal(ref.length);
    throwsNaming(() => quickhull([{ x: 0, y: 0 }, { x: Infinity, y: 0 }]), RangeError, 'points[1].x', 'Infinity');
  });

  it('property (fast-check): the hull contains every point and is convex', () => {
    fc.assert(
      fc.property(fc.array(fc.record({ x: fc.integer({ min: -1000, max: 1000 }), y: fc.integer({ min: -1000, max: 1000 }) }), { minLength: 3, maxLength: 60 }), (points) => {
        const h = quickhull(points);
        if (h.length < 3) return true;
        for (let k = 0; k < h.length; k++) {
          const a = h[k];
          const b = h[(k + 1) % h.length];
          const c = h[(k + 2) % h.length];
          if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) <= 0) return false;
          for (const p of points) if ((b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x) < 0) return false;
        }
        return true;
      }),
      { seed: 42, numRuns: 2000 },
    );
  });
});
