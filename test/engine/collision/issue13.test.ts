// Named regressions for the examples of issue 13 (contact points and manifolds right on every convex input).
import { expect } from 'chai';
import {
  Manifold, Penetration, RayHit, assertConvex, circle, gjkEpa, pointInShape, polygon, polygonManifold, polygonView,
  raycast, sat, shapeArea, type Shape,
} from '../../../src/engine/collision/index.js';
import { boundaryDistance, checkFeatures, edgeNormalOverlaps, rotated, throwsNaming } from './helpers.js';

const poly = (points: number[][]) => polygon(points.map(([x, y]) => ({ x, y })));
const man = new Manifold();
const pen = new Penetration();

/** The manifold's points as [x, y, depth] rows, sorted by x. */
function points(m: Manifold): number[][] {
  const out: number[][] = [];
  for (let k = 0; k < m.count; k++) out.push([m.pointX[k], m.pointY[k], m.depth[k] + 0]); // + 0: −0 reads as 0
  return out.sort((p, q) => p[0] - q[0]);
}

/** point ± depth/2 · normal on A's and B's outlines (within 1e-12). */
function onOutlines(a: Shape, b: Shape, x: number, y: number, depth: number, nx: number, ny: number): void {
  expect(boundaryDistance(a, x + (depth / 2) * nx, y + (depth / 2) * ny), 'on A').to.be.below(1e-12);
  expect(boundaryDistance(b, x - (depth / 2) * nx, y - (depth / 2) * ny), 'on B').to.be.below(1e-12);
}

describe('issue 13 regressions', () => {
  describe('1. polygonManifold with 180° (collinear) vertices', () => {
    it('A with a 180° vertex on its top face, B poking through it: normal (0, 1), depth 1 (was (0, −1) and depth 3)', () => {
      const a = poly([[0, 0], [10, 0], [10, 1], [9, 1], [0, 1]]);
      const b = poly([[1, 3], [2, 1], [4, 0], [5, 3]]);
      expect(edgeNormalOverlaps(a, b).depth).to.equal(1);
      for (let ra = 0; ra < a.count; ra++) {
        for (let rb = 0; rb < b.count; rb++) {
          const a2 = rotated(a, ra);
          const b2 = rotated(b, rb);
          expect(polygonManifold(a2, b2, man)).to.equal(true);
          expect([man.normalX, man.normalY]).to.deep.equal([0, 1]);
          // B's corner (4, 0) is 1 deep, (2, 1) just touches the top face; both on the top face's sub-edge (9, 1)–(0, 1).
          expect(points(man)).to.deep.equal([[2, 1, 0], [4, 0.5, 1]]);
          for (let k = 0; k < man.count; k++) onOutlines(a2, b2, man.pointX[k], man.pointY[k], man.depth[k], 0, 1);
          expect(checkFeatures(a2, b2, man, 1e-12)).to.equal('');
        }
      }
    });

    it('B with a 180° vertex on its bottom face, over A\'s corner: two contacts (8, 0.75) and (10, 0.75) from any starting vertex (was one at (11, 0.75), outside A)', () => {
      const a = poly([[0, 0], [10, 0], [10, 1], [0, 1]]);
      const b = poly([[11, 0.5], [12, 0.5], [12, 2], [8, 2], [8, 0.5]]);
      for (let rb = 0; rb < b.count; rb++) {
        const b2 = rotated(b, rb);
        expect(polygonManifold(a, b2, man)).to.equal(true);
        expect([man.normalX, man.normalY]).to.deep.equal([0, 1]);
        expect(points(man)).to.deep.equal([[8, 0.75, 0.5], [10, 0.75, 0.5]]);
        for (let k = 0; k < man.count; k++) onOutlines(a, b2, man.pointX[k], man.pointY[k], man.depth[k], 0, 1);
        expect(checkFeatures(a, b2, man, 1e-12)).to.equal('');
      }
    });
  });

  describe('2. sat\'s contact point on parallel faces', () => {
    it('a box over a box\'s top corner: the middle of the faces\' overlap (3.5, 0.75) from any starting vertex (was (5, 0.75), outside A, or (3, 0.75))', () => {
      const a = poly([[0, 0], [4, 0], [4, 1], [0, 1]]);
      const b = poly([[5, 0.5], [5, 1.5], [3, 1.5], [3, 0.5]]);
      for (let ra = 0; ra < 4; ra++) {
        for (let rb = 0; rb < 4; rb++) {
          const a2 = rotated(a, ra);
          const b2 = rotated(b, rb);
          for (const run of [sat, gjkEpa]) {
            expect(run(a2, b2, pen), run.name).to.equal(true);
            expect([pen.normalX, pen.normalY, pen.depth, pen.pointX, pen.pointY], run.name).to.deep.equal([0, 1, 0.5, 3.5, 0.75]);
          }
        }
      }
    });

    it('long faces: a 110-wide box half over a 116-wide one gets its point at x = 30, on both outlines (a point 117 off an outline was seen)', () => {
      const a = poly([[0, 0], [116, 0], [116, 1], [0, 1]]);
      const b = poly([[-50, 0.5], [60, 0.5], [60, 1.5], [-50, 1.5]]);
      for (let rb = 0; rb < 4; rb++) {
        const b2 = rotated(b, rb);
        expect(sat(a, b2, pen)).to.equal(true);
        expect([pen.normalX, pen.normalY, pen.depth, pen.pointX, pen.pointY]).to.deep.equal([0, 1, 0.5, 30, 0.75]);
        onOutlines(a, b2, pen.pointX, pen.pointY, pen.depth, pen.normalX, pen.normalY);
      }
    });
  });

  describe('3. raycast', () => {
    const hit = new RayHit();
    it('on a circle of radius 0 hit head-on: the normal faces the ray (was NaN)', () => {
      expect(raycast(circle(0, 0, 0), -5, 0, 2, 0, 10, hit)).to.equal(true);
      expect([hit.distance, hit.x, hit.y, hit.normalX, hit.normalY]).to.deep.equal([5, 0, 0, -1, -0]);
    });

    it('with a NaN origin, direction or maxDistance: a RangeError naming it (was a hit at NaN)', () => {
      const box = poly([[0, 0], [1, 0], [1, 1], [0, 1]]);
      throwsNaming(() => raycast(box, NaN, 0.5, 1, 0, 10, hit), RangeError, 'ox', 'NaN');
      throwsNaming(() => raycast(box, -1, Infinity, 1, 0, 10, hit), RangeError, 'oy', 'Infinity');
      throwsNaming(() => raycast(box, -1, 0.5, NaN, 0, 10, hit), RangeError, 'dx', 'NaN');
      throwsNaming(() => raycast(box, -1, 0.5, 1, 0, NaN, hit), RangeError, 'maxDistance', 'NaN');
      throwsNaming(() => raycast(box, -1, 0.5, 1, 0, -1, hit), RangeError, 'maxDistance', '-1');
      throwsNaming(() => raycast(box, -1, 0.5, 1, '0' as never, 10, hit), TypeError, 'dy', '"0"');
      // An unbounded ray is fine.
      expect(raycast(box, -1, 0.5, 1, 0, Infinity, hit)).to.equal(true);
      expect(hit.distance).to.equal(1);
      // pointInShape too: NaN compared as inside every polygon.
      throwsNaming(() => pointInShape(box, NaN, 0.5), RangeError, 'x', 'NaN');
    });
  });

  describe('4. areas far from the origin', () => {
    it('a triangle of area 0.57 near (1e6, −1e6) measures 0.57 (was 0.57000732)', () => {
      const t = poly([[1e6, -1e6], [1e6 + 1, -1e6], [1e6 + 0.3, -1e6 + 1.14]]);
      expect(shapeArea(t)).to.be.closeTo(0.57, 1e-9);
    });

    it('a small valid triangle there is accepted, with its area (was rejected as "area −0.000061")', () => {
      const t = poly([[1e6 + 0.25, -1e6], [1e6 + 0.26, -1e6], [1e6 + 0.25, -1e6 + 0.01]]);
      // 0.01 × 0.01 / 2, up to the rounding of the coordinates themselves (1e6 + 0.26 is 1e-10 off).
      expect(shapeArea(t)).to.be.closeTo(5e-5, 1e-12);
    });
  });

  describe('5. coordinates so large that derived quantities overflow', () => {
    it('polygon(), circle() and segment-like input beyond ±1e150 throw a RangeError naming the value (1e200 was accepted, area Infinity)', () => {
      throwsNaming(() => poly([[0, 0], [1e200, 0], [0, 1e200]]), RangeError, 'points[1].x', '1e+200');
      throwsNaming(() => polygon([0, 0, 1, 0, 0, -2e150]), RangeError, 'points[5]', '-2e+150');
      throwsNaming(() => circle(0, 0, 1e151), RangeError, 'r', '1e+151');
      // A view is checked the same way, once, by assertConvex.
      const view = polygonView(Float64Array.of(0, 1e200, 0), Float64Array.of(0, 0, 1e200), Int32Array.of(0, 1, 2));
      throwsNaming(() => assertConvex(view, 'body'), RangeError, 'body vertex 1 x', '1e+200');
    });

    it('at the limit a box inside a huge square is found by sat, gjkEpa and the manifold (a 1e200 square missed it)', () => {
      const big = polygon([-1e150, -1e150, 1e150, -1e150, 1e150, 1e150, -1e150, 1e150]);
      const box = polygon([0, 0, 1, 0, 1, 1, 0, 1]);
      expect(shapeArea(big) / 4e300).to.be.closeTo(1, 1e-15);
      expect(sat(big, box, pen)).to.equal(true);
      expect(pen.depth).to.equal(1e150);
      expect(gjkEpa(big, box, pen)).to.equal(true);
      expect(pen.depth).to.equal(1e150);
      expect(polygonManifold(big, box, man)).to.equal(true);
      expect(man.depth[0]).to.equal(1e150);
    });
  });

  describe('6. which way a manifold vertex is pushed (the text now says what the code does)', () => {
    it('a vertex of B pushed by its depth along the normal, a vertex of A pushed against it, lands on the other\'s edge at α', () => {
      // The ground (A) under a box (B): the box's corners are B's vertices.
      const ground = poly([[0, 0], [10, 0], [10, 1], [0, 1]]);
      const box = poly([[4, 0.9], [6, 0.9], [6, 2.9], [4, 2.9]]);
      expect(polygonManifold(ground, box, man)).to.equal(true);
      for (let k = 0; k < 2; k++) {
        expect(man.incident[k]).to.equal(1);
        const [vx, vy] = [[4, 0.9], [6, 0.9]][man.vertex[k]];
        // Along the normal (0, 1): onto the ground's top edge (10, 1) → (0, 1) at α.
        expect([vx + man.depth[k] * man.normalX, vy + man.depth[k] * man.normalY].map((v) => Math.round(v * 1e12) / 1e12)).to.deep.equal([10 - 10 * man.alpha[k], 1].map((v) => Math.round(v * 1e12) / 1e12));
      }
      // A post (A) under a plank (B) wider than it: the post's top corners are A's vertices.
      const post = poly([[0, 0], [1, 0], [1, 1], [0, 1]]);
      const plank = poly([[-2, 0.8], [3, 0.8], [3, 1.8], [-2, 1.8]]);
      expect(polygonManifold(post, plank, man)).to.equal(true);
      for (let k = 0; k < 2; k++) {
        expect(man.incident[k]).to.equal(0);
        const [vx, vy] = [[0, 0], [1, 0], [1, 1], [0, 1]][man.vertex[k]];
        // Against the normal (0, 1): down onto the plank's bottom edge (−2, 0.8) → (3, 0.8) at α.
        expect([vx - man.depth[k] * man.normalX, vy - man.depth[k] * man.normalY].map((v) => Math.round(v * 1e12) / 1e12)).to.deep.equal([-2 + 5 * man.alpha[k], 0.8].map((v) => Math.round(v * 1e12) / 1e12));
      }
    });
  });
});
