// Edge inputs of the collision module: ray (and support) directions of any finite length, gjkDistance on overlaps that
// its distance loop only finds to rounding, and shapes too small for their squared lengths (MIN_LENGTH). Every answer
// is checked against a brute-force or analytic one (helpers.ts), never against the module itself.
import { expect } from 'chai';
import {
  ClosestPoints, Manifold, Penetration, RayHit, ShapeType, aabbOf, assertConvex, boundingCircle, boundingCircleOf, circle,
  circleView, decompose, gjkDistance, gjkEpa, gjkIntersect, kdopOf, obbFromPoints, obbOf, pointInShape, polygon,
  polygonManifold, polygonView, quickhull, raycast, sat, segment, segmentView, shapeArea, shapeCentroid, supportPoint,
  type Shape,
} from '../../../src/engine/collision/index.js';
import {
  Failures, KINDS, boundaryDistance, bruteCoreDepth, bruteSignedDistance, describeShape, make, pts, randomShape, rng,
  sizeOf, solidDistance, throwsNaming, translated, type Kind,
} from './helpers.js';

const square = (x: number, y: number, side: number) => polygon([x, y, x + side, y, x + side, y + side, x, y + side]);

/** A random point strictly inside the shape (a convex combination of its vertices, or within half the radius). */
function innerPoint(r: () => number, s: Shape): { x: number; y: number } {
  const p = pts(s);
  if (s.type === ShapeType.Circle) {
    const a = r() * 2 * Math.PI;
    const d = 0.5 * r() * s.radius;
    return { x: p[0].x + d * Math.cos(a), y: p[0].y + d * Math.sin(a) };
  }
  if (s.type === ShapeType.Segment) {
    const f = 0.1 + 0.8 * r();
    return { x: p[0].x + f * (p[1].x - p[0].x), y: p[0].y + f * (p[1].y - p[0].y) };
  }
  const w = p.map(() => 0.1 + r());
  const total = w.reduce((a, b) => a + b, 0);
  return p.reduce((c, q, k) => ({ x: c.x + (w[k] / total) * q.x, y: c.y + (w[k] / total) * q.y }), { x: 0, y: 0 });
}

/**
 * Brute force: where the ray from o along the unit direction u, known to reach the shape's solid at distance `t1`,
 * first enters it: bisection on "solidDistance is 0" over [0, t1] (60 halvings, to rounding).
 */
function bruteEntry(s: Shape, ox: number, oy: number, ux: number, uy: number, t1: number): number {
  const inside = (t: number) => solidDistance(s, ox + t * ux, oy + t * uy) === 0;
  if (inside(0)) return 0;
  let lo = 0;
  let hi = t1;
  for (let k = 0; k < 60; k++) {
    const mid = (lo + hi) / 2;
    if (inside(mid)) hi = mid;
    else lo = mid;
  }
  return hi;
}

/**
 * bruteSignedDistance for shapes of any size: it multiplies four lengths (orientation products), which underflow below
 * about 1e-77, so it runs on copies scaled by a power of two to size 1 (exact), and the answer is scaled back.
 */
function bruteAtAnySize(a: Shape, b: Shape): number {
  const k = 2 ** -Math.floor(Math.log2(sizeOf(a, b)));
  const scaled = (s: Shape) => make(s.type, pts(s).map((q) => q.x * k), pts(s).map((q) => q.y * k), s.radius * k);
  return bruteSignedDistance(scaled(a), scaled(b)) / k;
}

/** Brute force: the centroid of a fan of triangles from vertex 0, on a copy scaled by a power of two to size 1. */
function bruteCentroid(s: Shape): { x: number; y: number } {
  const p = pts(s);
  const k = 2 ** -Math.floor(Math.log2(sizeOf(s)));
  const q = p.map((v) => ({ x: (v.x - p[0].x) * k, y: (v.y - p[0].y) * k }));
  if (s.type !== ShapeType.Polygon) {
    const mean = (f: (v: { x: number; y: number }) => number) => q.reduce((t, v) => t + f(v), 0) / q.length / k;
    return { x: p[0].x + mean((v) => v.x), y: p[0].y + mean((v) => v.y) };
  }
  let area = 0;
  let cx = 0;
  let cy = 0;
  for (let i = 1; i + 1 < q.length; i++) {
    const t = (q[i].x * q[i + 1].y - q[i + 1].x * q[i].y) / 2;
    area += t;
    cx += (t * (q[i].x + q[i + 1].x)) / 3;
    cy += (t * (q[i].y + q[i + 1].y)) / 3;
  }
  return { x: p[0].x + cx / area / k, y: p[0].y + cy / area / k };
}

/**
 * Whether (x, y, r) is the least circle around the shape, by bounds: it holds every vertex, and for vertices D apart at
 * most, D/2 <= r <= D/√3 (the least circle around points of diameter D), all to 1e-9 and to the rounding of the
 * centre's coordinates (64 ulps).
 */
function isLeastCircle(s: Shape, x: number, y: number, r: number): boolean {
  if (s.type === ShapeType.Circle) return x === s.xs[s.index[s.offset]] && y === s.ys[s.index[s.offset]] && r === s.radius;
  const p = pts(s);
  let d = 0;
  for (const u of p) for (const v of p) d = Math.max(d, Math.hypot(u.x - v.x, u.y - v.y));
  const rounding = 64 * Number.EPSILON * (Math.abs(x) + Math.abs(y));
  const holds = p.every((u) => Math.hypot(u.x - x, u.y - y) <= r * (1 + 1e-9) + rounding);
  return holds && r >= (d / 2) * (1 - 1e-9) - rounding && r <= (d / Math.sqrt(3)) * (1 + 1e-9) + rounding;
}

/** Every number in the list is finite. */
function allFinite(...values: number[]): boolean {
  return values.every(Number.isFinite);
}

describe('collision edge inputs', () => {
  describe('raycast: a direction of any finite non-zero length', () => {
    it('the reviewer\'s square: directions (1e-200, 0) and (1e200, 0) hit as (1, 0) does, at 5 with normal (−1, 0)', () => {
      const sq = square(0, 0, 1);
      const hit = new RayHit();
      for (const dx of [1, 1e-200, 1e200, Number.MIN_VALUE, Number.MAX_VALUE]) {
        expect(raycast(sq, -5, 0.5, dx, 0, Infinity, hit), `direction (${dx}, 0)`).to.equal(true);
        expect([hit.distance, hit.x, hit.y, hit.normalX, hit.normalY]).to.deep.equal([5, 0, 0.5, -1, 0]);
      }
      // Both components at the extremes: the direction (−1, 1)/√2 exactly, onto the right side of a square.
      for (const k of [Number.MIN_VALUE, 1e-300, 1e300, Number.MAX_VALUE]) {
        expect(raycast(square(-10, 8.5, 1), 0, 0, -k, k, Infinity, hit), `direction (−${k}, ${k})`).to.equal(true);
        expect(hit.distance).to.be.closeTo(9 * Math.SQRT2, 1e-14);
        expect(hit.x).to.be.closeTo(-9, 1e-14);
        expect(hit.y).to.be.closeTo(9, 1e-14);
        expect([hit.normalX, hit.normalY]).to.deep.equal([1, 0]);
      }
      // A circle and a segment the same way.
      expect(raycast(circle(3, 0, 1), 0, 0, 1e-250, 0, Infinity, hit)).to.equal(true);
      expect([hit.distance, hit.normalX]).to.deep.equal([2, -1]);
      expect(raycast(segment(3, -1, 3, 1), 0, 0, 1e250, 0, Infinity, hit)).to.equal(true);
      expect([hit.distance, hit.normalX]).to.deep.equal([3, -1]);
    });

    it('random directions scaled by 1e-300..1e300 hit where a brute-force bisection says, and miss shapes behind them', () => {
      const r = rng(9101);
      const hit = new RayHit();
      const fail = new Failures();
      let hits = 0;
      for (let k = 0; k < 6000; k++) {
        const kind = KINDS[k % 3];
        const size = 10 ** (r() * 6 - 3);
        const c = (r() - 0.5) * 100 * size;
        const s = randomShape(r, kind, c, c, size);
        // From a point outside the shape's bounding circle, aimed at a point inside it: a hit, where the bisection
        // says. Aimed away from the shape: a miss.
        const from = r() * 2 * Math.PI;
        const ox = c + 3 * size * Math.cos(from);
        const oy = c + 3 * size * Math.sin(from);
        const target = innerPoint(r, s);
        const t1 = Math.hypot(target.x - ox, target.y - oy);
        const ux = (target.x - ox) / t1;
        const uy = (target.y - oy) / t1;
        const scale = 10 ** (r() * 600 - 300);
        const [dx, dy] = [ux * scale, uy * scale];
        const where = `${describeShape(s)} from (${ox}, ${oy}) along (${dx}, ${dy})`;
        if (!raycast(s, ox, oy, dx, dy, Infinity, hit)) {
          fail.add(`missed: ${where}`);
          continue;
        }
        hits++;
        const expected = kind === 'segment' ? t1 : bruteEntry(s, ox, oy, ux, uy, t1);
        if (Math.abs(hit.distance - expected) > 1e-9 * size) fail.add(`distance ${hit.distance}, brute force ${expected}: ${where}`);
        if (Math.abs(Math.hypot(hit.normalX, hit.normalY) - 1) > 1e-12) fail.add(`normal (${hit.normalX}, ${hit.normalY}) is not a unit vector: ${where}`);
        if (boundaryDistance(s, hit.x, hit.y) > 1e-9 * size) fail.add(`hit point (${hit.x}, ${hit.y}) off the outline: ${where}`);
        if (raycast(s, ox, oy, -dx, -dy, Infinity, hit)) fail.add(`hit a shape behind the ray: ${where}`);
      }
      fail.check();
      expect(hits).to.equal(6000);
    });

    it('a zero direction still misses; a non-finite one throws naming it', () => {
      const hit = new RayHit();
      expect(raycast(square(0, 0, 1), -5, 0.5, 0, 0, Infinity, hit)).to.equal(false);
      expect(raycast(square(0, 0, 1), -5, 0.5, -0, 0, Infinity, hit)).to.equal(false);
      throwsNaming(() => raycast(square(0, 0, 1), -5, 0.5, Infinity, 0, 10, hit), RangeError, 'dx', 'Infinity');
      throwsNaming(() => raycast(square(0, 0, 1), -5, 0.5, 1, -Infinity, 10, hit), RangeError, 'dy', '-Infinity');
    });

    it('supportPoint normalises the same way: a circle\'s support along (0, 1e-200) or (0, 1e200) is centre + (0, r)', () => {
      const c = circle(1, 2, 3);
      const p = { x: 0, y: 0 };
      for (const d of [1e-200, 1e200, Number.MIN_VALUE, Number.MAX_VALUE]) {
        expect(supportPoint(c, 0, d, p), `(0, ${d})`).to.deep.equal({ x: 1, y: 5 });
        expect(supportPoint(c, -d, 0, p), `(−${d}, 0)`).to.deep.equal({ x: -2, y: 2 });
        supportPoint(c, d, d, p);
        expect(p.x).to.be.closeTo(1 + 3 * Math.SQRT1_2, 1e-15);
        expect(p.y).to.be.closeTo(2 + 3 * Math.SQRT1_2, 1e-15);
      }
      throwsNaming(() => supportPoint(c, NaN, 0, p), RangeError, 'dx', 'NaN');
      throwsNaming(() => supportPoint(c, 0, Infinity, p), RangeError, 'dy', 'Infinity');
    });
  });

  describe('gjkDistance: exactly 0 whenever the shapes overlap', () => {
    it('the reviewer\'s 1×1 square inside a 1000×1000 square (a vertex on its diagonal): 0, and a common point', () => {
      const big = square(0, 0, 1000);
      const small = square(400, 400, 1);
      const cp = new ClosestPoints();
      expect(gjkIntersect(big, small)).to.equal(true);
      for (const [a, b] of [[big, small], [small, big]]) {
        expect(gjkDistance(a, b, cp)).to.equal(0);
        expect([cp.distance, cp.normalX, cp.normalY]).to.deep.equal([0, 0, 0]);
        expect([cp.ax, cp.ay]).to.deep.equal([cp.bx, cp.by]);
        expect(solidDistance(big, cp.ax, cp.ay)).to.equal(0);
        expect(solidDistance(small, cp.ax, cp.ay)).to.be.at.most(1e-12);
      }
    });

    it('random shapes nested in a polygon with a vertex (or centre) on one of its diagonals: 0 both ways; EPA\'s depth is the brute-force one', () => {
      const r = rng(9202);
      const cp = new ClosestPoints();
      const pen = new Penetration();
      const fail = new Failures();
      for (let k = 0; k < 4000; k++) {
        const size = 10 ** (r() * 8 - 4);
        const off = r() < 0.5 ? 0 : (r() - 0.5) * 1e4 * size;
        // Half the outer shapes are axis-aligned squares (their diagonal is exactly y − x = const), the rest random
        // convex polygons with 4 to 8 vertices.
        const outer = k % 2 === 0 ? square(off, off, 2 * size) : randomShape(r, 'polygon', off, off, size, 4, 8);
        const p = pts(outer);
        const i = Math.floor(r() * p.length);
        const j = (i + 2 + Math.floor(r() * (p.length - 3))) % p.length; // not a neighbour of i
        const f = 0.3 + 0.4 * r();
        const vx = p[i].x + f * (p[j].x - p[i].x);
        const vy = p[i].y + f * (p[j].y - p[i].y);
        const kind: Kind = KINDS[Math.floor(r() * 3)];
        const small = 1e-3 * size * (0.5 + r());
        let inner: Shape;
        if (kind === 'circle') inner = make(ShapeType.Circle, [vx], [vy], small);
        else {
          // A shape with vertex 0 at (vx, vy), pointing into the outer polygon's centre.
          const shape = randomShape(r, kind, 0, 0, small);
          const q = pts(shape)[0];
          inner = translated(shape, vx - q.x, vy - q.y);
        }
        if (bruteSignedDistance(outer, inner) !== -Infinity) continue; // the inner shape pokes out: not this case
        const where = `${describeShape(outer)} and ${describeShape(inner)}`;
        if (!gjkIntersect(outer, inner)) fail.add(`gjkIntersect misses: ${where}`);
        for (const [a, b] of [[outer, inner], [inner, outer]]) {
          const d = gjkDistance(a, b, cp);
          if (d !== 0) fail.add(`distance ${d}: ${where}`);
          const tol = 1e-9 * sizeOf(a, b) + 64 * Number.EPSILON * Math.abs(off);
          if (solidDistance(a, cp.ax, cp.ay) > tol || solidDistance(b, cp.bx, cp.by) > tol) fail.add(`common point (${cp.ax}, ${cp.ay}) outside: ${where}`);
        }
        // EPA on shapes with a radius works from the cores' distance: a circle centred on the diagonal was given a
        // depth of about r instead of the centre's depth + r.
        if (kind === 'circle') {
          const expected = bruteCoreDepth(outer, inner);
          if (!gjkEpa(outer, inner, pen) || Math.abs(pen.depth - expected) > 1e-9 * size) fail.add(`gjkEpa depth ${pen.depth}, brute force ${expected}: ${where}`);
        }
      }
      fail.check();
    });

    it('random pairs moved to within rounding of touching: gjkIntersect true means distance 0, false means the brute-force distance', () => {
      const r = rng(9303);
      const cp = new ClosestPoints();
      const fail = new Failures();
      let overlapping = 0;
      for (const ka of KINDS) {
        for (const kb of KINDS) {
          for (let k = 0; k < 400; k++) {
            const size = 10 ** (r() * 8 - 4);
            const off = r() < 0.3 ? 10 ** (r() * 6) : 0;
            const a = randomShape(r, ka, off, off, size);
            const b0 = randomShape(r, kb, off, off, size * (0.2 + r()));
            // Bisect along a random direction to where gjkIntersect changes its answer; take either side.
            const ang = r() * 2 * Math.PI;
            const [ux, uy] = [Math.cos(ang), Math.sin(ang)];
            let lo = 0;
            let hi = 10 * size;
            for (let t = 0; t < 80; t++) {
              const m = (lo + hi) / 2;
              if (gjkIntersect(a, translated(b0, m * ux, m * uy))) lo = m;
              else hi = m;
            }
            const m = k % 2 === 0 ? lo : hi;
            const b = translated(b0, m * ux, m * uy);
            const d = gjkDistance(a, b, cp);
            const where = `${describeShape(a)} and ${describeShape(b)}`;
            if (gjkIntersect(a, b)) {
              overlapping++;
              if (d !== 0) fail.add(`gjkIntersect says overlapping, distance ${d}: ${where}`);
            } else {
              const brute = Math.max(0, bruteSignedDistance(a, b));
              if (Math.abs(d - brute) > 1e-9 * sizeOf(a, b) + 64 * Number.EPSILON * off) fail.add(`distance ${d}, brute force ${brute}: ${where}`);
            }
          }
        }
      }
      fail.check();
      expect(overlapping).to.be.greaterThan(1000);
    });

    it('a short shape crossing a long one (aspect 1e3 to 1e15): 0 whenever gjkIntersect says they overlap, and where the brute force says so', () => {
      const r = rng(9606);
      const cp = new ClosestPoints();
      const fail = new Failures();
      let overlapping = 0;
      for (let k = 0; k < 6000; k++) {
        const long = 10 ** (r() * 4);
        const a = randomShape(r, k % 2 === 0 ? 'segment' : 'polygon', 0, 0, long);
        const p = pts(a);
        const f = r();
        const b = randomShape(r, KINDS[k % 3], p[0].x + f * (p[1].x - p[0].x), p[0].y + f * (p[1].y - p[0].y), long * 10 ** (-3 - 12 * r()));
        const intersect = gjkIntersect(a, b);
        const brute = bruteSignedDistance(a, b);
        if (brute === -Infinity) overlapping++;
        for (const [x, y] of [[a, b], [b, a]]) {
          const d = gjkDistance(x, y, cp);
          // Gilbert's stopping test ran on the closest point interpolated along A − B's long edge, whose rounding
          // (ulps of the long size) it multiplied by the long size: it stopped up to 6e-9 of the size away.
          if (intersect && d !== 0) fail.add(`gjkIntersect says overlapping, distance ${d} (${d / long} of the size): ${describeShape(x)} and ${describeShape(y)}`);
          if (brute === -Infinity && d > 1e-13 * long) fail.add(`overlapping, distance ${d}: ${describeShape(x)} and ${describeShape(y)}`);
        }
      }
      fail.check();
      expect(overlapping).to.be.greaterThan(3000);
    });
  });

  describe('shapes too small for their squared lengths (MIN_LENGTH = 1e-150)', () => {
    it('the reviewer\'s segment(0, 0, 1e-310, 0) is refused, naming its endpoints', () => {
      throwsNaming(() => segment(0, 0, 1e-310, 0), RangeError, 'segment', 'x2', '1e-310', 'MIN_LENGTH');
      throwsNaming(() => segment(1e-151, 0, 0, 1e-151), RangeError, 'segment', '1e-151');
      // As a view it is refused by assertConvex; at MIN_LENGTH a segment is accepted and its results are finite.
      throwsNaming(() => assertConvex(segmentView(new Float64Array([0, 1e-310]), new Float64Array([0, 0]), new Int32Array([0, 1]))), RangeError, 'shape', '1e-310', 'MIN_LENGTH');
      const s = segment(0, 0, 1e-150, 0);
      const pen = new Penetration();
      expect(gjkEpa(s, circle(0, 0, 1), pen)).to.equal(true);
      expect(pen.depth).to.equal(1);
      expect(allFinite(pen.normalX, pen.normalY, pen.pointX, pen.pointY)).to.equal(true);
      const box = obbOf(s);
      expect([box.ux, box.uy, box.hu, box.hv]).to.deep.equal([1, 0, 5e-151, 0]);
    });

    it('polygons with an edge under MIN_LENGTH and circles with a radius under it (other than 0, a point) are refused too', () => {
      throwsNaming(() => polygon([0, 0, 1e-310, 0, 1e-310, 1e-310, 0, 1e-310]), RangeError, 'points', 'spread of 1e-310', 'MIN_LENGTH');
      throwsNaming(() => polygon([0, 0, 1e-151, 0, 1e-151, 1e-151, 0, 1e-151]), RangeError, 'points', 'spread of 1e-151');
      // A unit square with one corner cut by 1e-200: its edge normal came out as (−Infinity, −Infinity) in sat.
      throwsNaming(() => polygon([1e-200, 0, 1, 0, 1, 1, 0, 1, 0, 1e-200]), RangeError, 'points[4]', 'points[0]', 'MIN_LENGTH');
      throwsNaming(() => assertConvex(polygonView(new Float64Array([1e-200, 1, 1, 0, 0]), new Float64Array([0, 0, 1, 1, 1e-200]), new Int32Array([0, 1, 2, 3, 4]))), RangeError, 'shape[4]', 'MIN_LENGTH');
      throwsNaming(() => circle(0, 0, 1e-320), RangeError, 'r', '1e-320', 'MIN_LENGTH');
      throwsNaming(() => circle(0, 0, 1e-200), RangeError, 'r', '1e-200');
      throwsNaming(() => assertConvex(circleView(new Float64Array([0]), new Float64Array([0]), new Int32Array([0]), 0, 1e-200)), RangeError, 'shape.radius', '1e-200');
      // Two circles of radius 1e-200 were a hit for gjkEpa and not for sat; a radius of 0 (a point) is still a circle.
      expect(circle(0, 0, 0).radius).to.equal(0);
      expect(circle(0, 0, 1e-150).radius).to.equal(1e-150);
      expect(shapeArea(square(0, 0, 1e-150))).to.equal(1e-300 / 1);
    });

    it('point lists spread over less than MIN_LENGTH are refused by quickhull, boundingCircle, obbFromPoints and decompose; from it to 1e149 they give the scaled answers', () => {
      const tiny = [0, 0, 2e-200, 0, 2e-200, 2e-200, 0, 2e-200];
      // They gave a hull of 2 points, a circle of radius 0 and an OBB axis of NaN.
      throwsNaming(() => quickhull(tiny), RangeError, 'points', 'spread of 2e-200', 'MIN_LENGTH');
      throwsNaming(() => boundingCircle(tiny), RangeError, 'points', 'spread of 2e-200');
      throwsNaming(() => obbFromPoints(tiny), RangeError, 'points', 'spread of 2e-200');
      throwsNaming(() => decompose(tiny), RangeError, 'points', 'spread of 2e-200');
      // One point, repeated, is not spread at all.
      expect(boundingCircle([1e-300, 0, 1e-300, 0])).to.deep.include({ x: 1e-300, y: 0, r: 0 });
      // The 3-4-5 right triangle (least circle: on the hypotenuse, radius 2.5; least box: area 12; centroid (2, 4/3))
      // scaled by powers of two from 2^-490 to 2^490: the same answers, scaled (the circumcentre and the centroid
      // multiply three lengths: they underflowed below about 1e-103 and overflowed above 1e103).
      for (let e = -490; e <= 490; e += 10) {
        const k = 2 ** e;
        const tri = [0, 0, 3 * k, 0, 3 * k, 4 * k];
        expect(quickhull(tri), `2^${e}`).to.have.length(3);
        expect(boundingCircle(tri), `2^${e}`).to.deep.include({ x: 1.5 * k, y: 2 * k, r: 2.5 * k });
        const box = obbFromPoints(tri);
        expect(box.hu * box.hv * 4, `2^${e}`).to.be.closeTo(12 * k * k, 1e-12 * k * k);
        const c = shapeCentroid(polygon(tri));
        expect(c.x / k, `2^${e}`).to.be.closeTo(2, 1e-15);
        expect(c.y / k, `2^${e}`).to.be.closeTo(4 / 3, 1e-15);
        expect(boundingCircleOf(polygon([0, 0, 3 * k, 0, 3 * k, 4 * k, 0.5 * k, 1.5 * k])).r / k, `2^${e}`).to.equal(2.5);
      }
    });

    it('random shapes of every size from MIN_LENGTH to 1e140, placed on a vertex, an edge, the centre or a hair away from one another: finite results, the brute-force distance, centroid and least circle', () => {
      const r = rng(9404);
      const pen = new Penetration();
      const cp = new ClosestPoints();
      const man = new Manifold();
      const hit = new RayHit();
      const fail = new Failures();
      let tested = 0;
      for (let k = 0; k < 6000; k++) {
        const ka = KINDS[k % 3];
        const kb = KINDS[Math.floor(k / 3) % 3];
        // Sizes from 2·MIN_LENGTH to 1e140 (most of them small), and a partner from 1e-20 to 1e20 times that.
        const sa = 2e-150 * 10 ** (r() < 0.7 ? r() * 100 : r() * 290);
        const sb = Math.max(2e-150, sa * 10 ** (r() * 40 - 20));
        const off = r() < 0.5 ? 0 : sa * 10 ** (r() * 6);
        if (off + 2 * (sa + sb) > 1e149) continue;
        const a = randomShape(r, ka, off, off, sa);
        const p = pts(a);
        const v = Math.floor(r() * p.length);
        const w = (v + 1) % p.length;
        const f = r();
        const mode = k % 4;
        const [cx, cy] =
          mode === 0 ? [p[v].x, p[v].y]
          : mode === 1 ? [p[v].x + f * (p[w].x - p[v].x), p[v].y + f * (p[w].y - p[v].y)]
          : mode === 2 ? [off, off]
          : [p[v].x + sa * 10 ** (-r() * 100), p[v].y];
        const b = randomShape(r, kb, cx, cy, sb);
        try {
          assertConvex(a);
          assertConvex(b);
        } catch {
          continue; // rounding made a vertex repeat or bend: not a valid shape
        }
        tested++;
        const where = `${describeShape(a)} and ${describeShape(b)}`;
        for (const [x, y] of [[a, b], [b, a]]) {
          if (sat(x, y, pen) && !allFinite(pen.depth, pen.normalX, pen.normalY, pen.pointX, pen.pointY)) fail.add(`sat: ${where}`);
          if (gjkEpa(x, y, pen) && !allFinite(pen.depth, pen.normalX, pen.normalY, pen.pointX, pen.pointY)) fail.add(`gjkEpa: ${where}`);
          gjkDistance(x, y, cp);
          if (!allFinite(cp.distance, cp.ax, cp.ay, cp.bx, cp.by, cp.normalX, cp.normalY)) fail.add(`gjkDistance: ${where}`);
          polygonManifold(x, y, man);
          for (let q = 0; q < man.count; q++) {
            if (!allFinite(man.normalX, man.normalY, man.depth[q], man.pointX[q], man.pointY[q], man.alpha[q])) fail.add(`polygonManifold: ${where}`);
          }
          const box = obbOf(x);
          const bc = boundingCircleOf(x);
          const ab = aabbOf(x);
          const kd = kdopOf(x);
          const c = shapeCentroid(x);
          if (!allFinite(box.cx, box.cy, box.ux, box.uy, box.hu, box.hv, bc.x, bc.y, bc.r, ab.minX, ab.maxY, ...kd.min, ...kd.max, c.x, c.y, shapeArea(x))) fail.add(`bounds: ${where}`);
          // The centroid and the least circle multiply three lengths: for shapes 1e-120 across they came out at the
          // first vertex and with radius 0, for 1e120 at Infinity.
          const bcx = bruteCentroid(x);
          const tol = 1e-9 * sizeOf(x) + 64 * Number.EPSILON * (Math.abs(bcx.x) + Math.abs(bcx.y));
          if (!(Math.abs(c.x - bcx.x) <= tol && Math.abs(c.y - bcx.y) <= tol)) fail.add(`centroid (${c.x}, ${c.y}), brute force (${bcx.x}, ${bcx.y}): ${describeShape(x)}`);
          if (!isLeastCircle(x, bc.x, bc.y, bc.r)) fail.add(`bounding circle (${bc.x}, ${bc.y}) r ${bc.r}: ${describeShape(x)}`);
          const q = pts(y)[0];
          pointInShape(x, q.x, q.y);
          if (raycast(x, q.x, q.y, r() - 0.5, r() - 0.5, Infinity, hit) && !allFinite(hit.distance, hit.x, hit.y, hit.normalX, hit.normalY)) fail.add(`raycast: ${where}`);
        }
        // The distance against brute force where it is clearly apart (the products of four lengths in GJK's
        // triangle case underflowed for shapes 1e-80 across: weights 0/0).
        const brute = bruteAtAnySize(a, b);
        const size = sizeOf(a, b);
        const d = gjkDistance(a, b, cp);
        // (Overlapping or not is only known to the rounding of the coordinates: 64 ulps of the largest.)
        const rounding = 64 * Number.EPSILON * Math.max(...[...pts(a), ...pts(b)].map((q) => Math.abs(q.x) + Math.abs(q.y)));
        if (brute > 1e-6 * size && Math.abs(d - brute) > 1e-9 * brute + rounding) fail.add(`distance ${d}, brute force ${brute}: ${where}`);
        if (brute === -Infinity && d > rounding) fail.add(`overlapping, distance ${d}: ${where}`);
        if (gjkIntersect(a, b) && d !== 0) fail.add(`gjkIntersect says overlapping, distance ${d}: ${where}`);
      }
      fail.check();
      expect(tested).to.be.greaterThan(4000);
    });

    it('a circle centred exactly on a vertex of a polygon or segment: sat and the manifold give a unit normal and the depth r (was NaN)', () => {
      const r = rng(9505);
      const pen = new Penetration();
      const man = new Manifold();
      const fail = new Failures();
      for (let k = 0; k < 4000; k++) {
        const size = 10 ** (r() * 10 - 5);
        const shape = randomShape(r, k % 2 === 0 ? 'polygon' : 'segment', (r() - 0.5) * size, (r() - 0.5) * size, size);
        const p = pts(shape)[Math.floor(r() * shape.count)];
        const c = make(ShapeType.Circle, [p.x], [p.y], size * 10 ** (r() * 4 - 2));
        const where = `${describeShape(shape)} and a circle on (${p.x}, ${p.y})`;
        // On its outline the circle overlaps the shape by its radius, the least overlap over all directions.
        for (const [a, b] of [[shape, c], [c, shape]]) {
          if (!sat(a, b, pen)) fail.add(`sat misses: ${where}`);
          else if (!(Math.abs(Math.hypot(pen.normalX, pen.normalY) - 1) < 1e-12) || Math.abs(pen.depth - c.radius) > 1e-9 * c.radius) {
            fail.add(`sat normal (${pen.normalX}, ${pen.normalY}), depth ${pen.depth} for r ${c.radius}: ${where}`);
          }
          polygonManifold(a, b, man);
          if (man.count !== 1 || !(Math.abs(Math.hypot(man.normalX, man.normalY) - 1) < 1e-12) || !allFinite(man.pointX[0], man.pointY[0])) {
            fail.add(`manifold normal (${man.normalX}, ${man.normalY}), ${man.count} points: ${where}`);
          }
        }
      }
      fail.check();
    });
  });
});
