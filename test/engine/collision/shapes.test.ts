import { expect } from 'chai';
import fc from 'fast-check';
import { World } from '../../../src/engine/index.js';
import { handleSlot } from '../../../src/engine/handles.js';
import {
  Penetration, ShapeType, assertConvex, circle, circleView, counterClockwise, polygon, polygonView, quickhull, sat,
  segment, segmentView, shapeArea, shapeCentroid, shapeVertices, supportIndex, supportPoint, vertexX, vertexY,
} from '../../../src/engine/collision/index.js';
import * as C from '../../../src/engine/collision/index.js';
import type { Shape } from '../../../src/engine/collision/index.js';
import { throwsNaming } from './helpers.js';

describe('shapes', () => {
  it('polygon() reads {x, y} points or a flat list and owns a copy', () => {
    const pts = [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 0, y: 1 }];
    const a = polygon(pts);
    const b = polygon([0, 0, 2, 0, 2, 1, 0, 1]);
    expect(shapeVertices(a)).to.deep.equal(pts);
    expect(shapeVertices(b)).to.deep.equal(pts);
    pts[0].x = 99;
    expect(vertexX(a, 0)).to.equal(0);
    expect(a.type).to.equal(ShapeType.Polygon);
    expect(shapeArea(a)).to.equal(2);
    expect(shapeCentroid(a)).to.deep.equal({ x: 1, y: 0.5 });
    // Collinear (180°) vertices are allowed.
    expect(shapeArea(polygon([0, 0, 1, 0, 2, 0, 2, 2, 0, 2]))).to.equal(4);
  });

  it('rejects bad polygons with an error naming the argument and the value', () => {
    throwsNaming(() => polygon([0, 0, 1, 0]), RangeError, 'points', '2');
    throwsNaming(() => polygon([{ x: 0, y: 0 }, { x: NaN, y: 0 }, { x: 0, y: 1 }]), RangeError, 'points[1].x', 'NaN');
    throwsNaming(() => polygon([0, 0, 1, Infinity, 0, 1]), RangeError, 'points[3]', 'Infinity');
    throwsNaming(() => polygon([{ x: 0, y: 0 }, { x: '1', y: 0 }, { x: 0, y: 1 }] as never), TypeError, 'points[1].x', '"1"');
    throwsNaming(() => polygon([0, 0, 1, 0, 0]), RangeError, 'points', 'even');
    throwsNaming(() => polygon('square' as never), TypeError, 'points', '"square"');
    throwsNaming(() => polygon([{ x: 0, y: 0 }, 5, { x: 0, y: 1 }] as never), TypeError, 'points[1]', '5');
    // Clockwise: named, with the fix.
    throwsNaming(() => polygon([0, 0, 0, 1, 1, 1, 1, 0]), RangeError, 'points', 'counter-clockwise', 'counterClockwise');
    expect(shapeArea(polygon(counterClockwise([0, 0, 0, 1, 1, 1, 1, 0])))).to.equal(1);
    // Not convex: names the corner.
    throwsNaming(() => polygon([0, 0, 2, 0, 1, 0.5, 2, 2, 0, 2]), RangeError, 'points[2]', 'convex', 'decompose');
    // Zero area, repeated points, a self-intersecting (twice-winding) star.
    throwsNaming(() => polygon([0, 0, 1, 1, 2, 2]), RangeError, 'points', 'area');
    throwsNaming(() => polygon([0, 0, 1, 0, 1, 0, 0, 1]), RangeError, 'points[2]', 'repeats');
    const pentagram = [0, 2, 4, 1, 3].flatMap((k) => [Math.cos((2 * Math.PI * k) / 5), Math.sin((2 * Math.PI * k) / 5)]);
    throwsNaming(() => polygon(pentagram), RangeError, 'points', 'winds 2 times');
  });

  it('circle() and segment() validate their numbers', () => {
    throwsNaming(() => circle(0, 0, -1), RangeError, 'r', '-1');
    throwsNaming(() => circle(NaN, 0, 1), RangeError, 'x', 'NaN');
    throwsNaming(() => circle(0, 0, '1' as never), TypeError, 'r', '"1"');
    throwsNaming(() => segment(0, 0, 0, Infinity), RangeError, 'y2', 'Infinity');
    throwsNaming(() => segment(1, 2, 1, 2), RangeError, 'segment', 'differ');
    const c = circle(1, 2, 3);
    expect([c.type, c.count, c.radius, vertexX(c, 0), vertexY(c, 0)]).to.deep.equal([ShapeType.Circle, 1, 3, 1, 2]);
    const s = segment(0, 0, 3, 4);
    expect([s.type, s.count, s.radius]).to.deep.equal([ShapeType.Segment, 2, 0]);
  });

  it('assertConvex validates a view once: type, count, offsets, finiteness, convexity', () => {
    const xs = new Float64Array([0, 1, 1, 0, 5]);
    const ys = new Float64Array([0, 0, 1, 1, 5]);
    const index = new Int32Array([0, 1, 2, 3, 4]);
    assertConvex(polygonView(xs, ys, index, 0, 4));
    throwsNaming(() => assertConvex(polygonView(xs, ys, index, 0, 2)), RangeError, 'shape.count', 'at least 3');
    throwsNaming(() => assertConvex(polygonView(xs, ys, index, 3, 4)), RangeError, 'shape.offset', 'runs past');
    throwsNaming(() => assertConvex(polygonView(xs, ys, new Int32Array([0, 1, 9]), 0, 3)), RangeError, 'index[2]', '9');
    throwsNaming(() => assertConvex(polygonView(xs, ys, new Int32Array([0, 2, 1, 3]), 0, 4), 'body'), RangeError, 'body', 'convex');
    throwsNaming(() => assertConvex(circleView(xs, ys, index, 0, -2)), RangeError, 'shape.radius', '-2');
    throwsNaming(() => assertConvex(segmentView(xs, ys, new Int32Array([1, 1]), 0)), RangeError, 'zero length');
    throwsNaming(() => assertConvex({ ...circle(0, 0, 1), type: 7 as never }), RangeError, 'shape.type', '7');
    ys[1] = NaN;
    throwsNaming(() => assertConvex(polygonView(xs, ys, index, 0, 4)), RangeError, 'vertex 1 y', 'NaN');
  });

  it('every exported function that takes a shape or a result object refuses one that is not, naming the argument', () => {
    const c = circle(0, 0, 1);
    const p = polygon([0, 0, 1, 0, 1, 1]);
    // Before the checks: pointInShape({}) answered true, raycast({}) hit, aabbOf(5) was a box of NaN, and the
    // narrow phase threw "Cannot read properties of undefined" from inside.
    const takesShapes: Record<string, (a: unknown, b: unknown) => unknown> = {
      sat: (a, b) => C.sat(a as Shape, b as Shape, new Penetration()),
      gjkIntersect: (a, b) => C.gjkIntersect(a as Shape, b as Shape),
      gjkDistance: (a, b) => C.gjkDistance(a as Shape, b as Shape, new C.ClosestPoints()),
      gjkEpa: (a, b) => C.gjkEpa(a as Shape, b as Shape, new Penetration()),
      epa: (a, b) => C.epa(a as Shape, b as Shape, new C.Simplex(), new Penetration()),
      polygonManifold: (a, b) => C.polygonManifold(a as Shape, b as Shape, new C.Manifold()),
    };
    const takesOne: Record<string, (s: unknown) => unknown> = {
      aabbOf: (s) => C.aabbOf(s as Shape), boundingCircleOf: (s) => C.boundingCircleOf(s as Shape), obbOf: (s) => C.obbOf(s as Shape),
      kdopOf: (s) => C.kdopOf(s as Shape), pointInShape: (s) => C.pointInShape(s as Shape, 0, 0),
      raycast: (s) => C.raycast(s as Shape, 0, 0, 1, 0, 10, new C.RayHit()), shapeArea: (s) => shapeArea(s as Shape),
      shapeCentroid: (s) => shapeCentroid(s as Shape), shapeVertices: (s) => shapeVertices(s as Shape), shapeSize: (s) => C.shapeSize(s as Shape),
      supportIndex: (s) => supportIndex(s as Shape, 1, 0), supportPoint: (s) => supportPoint(s as Shape, 1, 0, { x: 0, y: 0 }),
      vertexX: (s) => vertexX(s as Shape, 0), vertexY: (s) => vertexY(s as Shape, 0),
    };
    const notShapes: [unknown, typeof TypeError | typeof RangeError, string][] = [
      [null, TypeError, 'null'], [5, TypeError, '5'], [{}, TypeError, 'Float64Array'], [{ x: 0, y: 0, radius: 1 }, TypeError, 'Float64Array'],
      [{ ...c, type: 9 }, RangeError, '9'], [{ ...p, count: 2 }, RangeError, 'count'], [{ ...p, offset: 1 }, RangeError, 'runs past'],
      [{ ...c, radius: NaN }, RangeError, 'NaN'], [{ ...c, radius: -1 }, RangeError, '-1'],
    ];
    for (const [bad, type, word] of notShapes) {
      for (const f of Object.values(takesShapes)) {
        throwsNaming(() => f(bad, c), type, 'a', word);
        throwsNaming(() => f(p, bad), type, 'b', word);
      }
      for (const [name, f] of Object.entries(takesOne)) {
        expect(() => f(bad), name).to.throw(type, 'shape');
        throwsNaming(() => f(bad), type, word);
      }
    }
    // Result objects: an instance of their class (a plain object lacks a Manifold's arrays, a number takes no field).
    throwsNaming(() => C.sat(c, p, {} as Penetration), TypeError, 'out', 'Penetration');
    throwsNaming(() => C.polygonManifold(c, p, { count: 0 } as unknown as C.Manifold), TypeError, 'out', 'Manifold');
    throwsNaming(() => C.gjkDistance(c, p, 5 as never), TypeError, 'out', 'ClosestPoints');
    throwsNaming(() => C.gjkIntersect(c, p, {} as never), TypeError, 'simplexOut', 'Simplex');
    throwsNaming(() => C.aabbOf(c, {} as never), TypeError, 'out', 'AABB');
    throwsNaming(() => C.raycast(c, 0, 0, 1, 0, 1, null as never), TypeError, 'out', 'RayHit');
    throwsNaming(() => supportPoint(c, 1, 0, null as never), TypeError, 'out');
    throwsNaming(() => C.polygonManifold(c, p, new C.Manifold(), NaN), RangeError, 'margin', 'NaN');
    throwsNaming(() => vertexX(p, 3), RangeError, 'k', '3');
    throwsNaming(() => supportIndex(p, Infinity, 0), RangeError, 'dx');
    // The good calls still answer.
    expect(C.sat(c, p, new Penetration())).to.equal(true);
    expect(C.pointInShape(p, 0.9, 0.1)).to.equal(true);
    expect(C.aabbOf(c).maxX).to.equal(1);
  });

  it('support: the farthest vertex; a circle\'s is centre + r·d/|d|', () => {
    const sq = polygon([0, 0, 2, 0, 2, 2, 0, 2]);
    expect(supportIndex(sq, 1, 0.1)).to.equal(2);
    expect(supportIndex(sq, -1, -0.1)).to.equal(0);
    const p = { x: 0, y: 0 };
    supportPoint(circle(1, 1, 2), 3, 4, p);
    expect(p.x).to.be.closeTo(1 + 2 * 0.6, 1e-15);
    expect(p.y).to.be.closeTo(1 + 2 * 0.8, 1e-15);
    supportPoint(circle(1, 1, 2), 0, 0, p); // any point of the circle for d = 0
    expect(Math.hypot(p.x - 1, p.y - 1)).to.be.closeTo(2, 1e-15);
  });

  it('views over a world\'s particle arrays collide with the particles\' current positions, without copying', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const box = [[0, 0], [1, 0], [1, 1], [0, 1]].map(([x, y]) => world.addParticle({ x, y }));
    const other = [[2, 0], [3, 0], [3, 1], [2, 1]].map(([x, y]) => world.addParticle({ x, y }));
    const p = world.particles;
    // The engine's slot of each particle is its index in the arrays: a shared index list holds both outlines.
    const slots = new Int32Array([...box, ...other].map(handleSlot));
    const a = polygonView(p.x, p.y, slots, 0, 4);
    const b = polygonView(p.x, p.y, slots, 4, 4);
    assertConvex(a);
    assertConvex(b);
    const pen = new Penetration();
    expect(sat(a, b, pen)).to.equal(false);
    for (const h of other) {
      const q = world.getPosition(h);
      world.setPosition(h, q.x - 1.25, q.y);
    }
    expect(sat(a, b, pen)).to.equal(true);
    expect(pen.depth).to.be.closeTo(0.25, 1e-12);
    expect([pen.normalX, pen.normalY]).to.deep.equal([1, -0]);
  });

  it('property (fast-check): the hull of any non-degenerate point set is a valid polygon, its reverse is rejected', () => {
    fc.assert(
      fc.property(fc.array(fc.tuple(fc.integer({ min: -1e6, max: 1e6 }), fc.integer({ min: -1e6, max: 1e6 })), { minLength: 3, maxLength: 40 }), (raw) => {
        const hull = quickhull(raw.map(([x, y]) => ({ x: x / 1000, y: y / 1000 })));
        if (hull.length < 3) return true;
        polygon(hull);
        try {
          polygon(hull.slice().reverse());
          return false;
        } catch (e) {
          return e instanceof RangeError && /counter-clockwise/.test((e as Error).message);
        }
      }),
      { seed: 7, numRuns: 1000 },
    );
  });
});
