import { expect } from 'chai';
import { ClosestPoints, ShapeType, gjkDistance, polygon, sat, Penetration } from '../../../src/engine/collision/index.js';
import {
  Failures, KINDS, boundaryDistance, bruteSignedDistance, describeShape, make, randomPair, rng, sizeOf, solidDistance,
} from './helpers.js';

const PAIRS = 10_000;

describe('GJK distance', () => {
  for (const ka of KINDS) {
    for (const kb of KINDS) {
      it(`${ka}–${kb}: equals the brute-force vertex–edge minimum (relative 1e-9) and the closest points lie on the shapes`, () => {
        const r = rng(4000 + KINDS.indexOf(ka) * 3 + KINDS.indexOf(kb));
        const cp = new ClosestPoints();
        const pen = new Penetration();
        const fail = new Failures();
        let separated = 0;
        let overlapping = 0;
        for (let k = 0; k < PAIRS; k++) {
          const [a, b] = randomPair(r, ka, kb, 1, 2.2);
          const size = sizeOf(a, b);
          const d = gjkDistance(a, b, cp);
          const brute = bruteSignedDistance(a, b);
          if (d !== cp.distance) fail.add('return value differs from out.distance');
          if (brute > 0) {
            separated++;
            if (Math.abs(d - brute) > 1e-9 * Math.max(brute, 1e-3 * size)) fail.add(`distance ${d} brute ${brute}: ${describeShape(a)} vs ${describeShape(b)}`);
            const onA = boundaryDistance(a, cp.ax, cp.ay);
            const onB = boundaryDistance(b, cp.bx, cp.by);
            if (onA > 1e-9 * size || onB > 1e-9 * size) fail.add(`closest points off the shapes by ${onA}, ${onB}`);
            const gap = Math.sqrt((cp.bx - cp.ax) ** 2 + (cp.by - cp.ay) ** 2);
            if (Math.abs(gap - d) > 1e-9 * size) fail.add(`|pB − pA| = ${gap} but distance ${d}`);
            if (Math.abs(cp.normalX * (cp.bx - cp.ax) + cp.normalY * (cp.by - cp.ay) - d) > 1e-9 * size) fail.add('normal is not (pB − pA)/d');
          } else if (brute < 0) {
            overlapping++;
            if (d !== 0) fail.add(`overlapping but distance ${d}`);
            // A common point: in (or on) both shapes.
            const inA = solidDistance(a, cp.ax, cp.ay);
            const inB = solidDistance(b, cp.bx, cp.by);
            if (inA > 1e-9 * size || inB > 1e-9 * size) fail.add(`common point outside by ${inA}, ${inB}: ${describeShape(a)} vs ${describeShape(b)}`);
            // SAT finds the overlap unless it is within rounding of touching (pen.depth is not written on a miss).
            if (sat(a, b, pen) !== true && brute < -1e-9 * size) fail.add(`sat misses an overlap (brute ${brute}): ${describeShape(a)} vs ${describeShape(b)}`);
          }
        }
        fail.check();
        expect(separated).to.be.greaterThan(PAIRS / 4);
        expect(overlapping).to.be.greaterThan(PAIRS / 10);
      });
    }
  }

  it('handles parallel edges, touching shapes and a shape inside another', () => {
    const cp = new ClosestPoints();
    const a = polygon([0, 0, 2, 0, 2, 2, 0, 2]);
    expect(gjkDistance(a, polygon([3, 0.5, 4, 0.5, 4, 1.5, 3, 1.5]), cp)).to.be.closeTo(1, 1e-15);
    expect(cp.ax).to.equal(2);
    expect(cp.bx).to.equal(3);
    expect(cp.normalX).to.equal(1);
    expect(gjkDistance(a, polygon([2, 0, 3, 0, 3, 1, 2, 1]), cp)).to.equal(0);
    expect(gjkDistance(a, polygon([0.5, 0.5, 1, 0.5, 1, 1]), cp)).to.equal(0);
    const c = make(ShapeType.Circle, [5], [1], 1);
    expect(gjkDistance(a, c, cp)).to.be.closeTo(2, 1e-15);
    expect(cp.bx).to.be.closeTo(4, 1e-15);
    expect(gjkDistance(c, make(ShapeType.Circle, [5.5], [1], 0.1), cp)).to.equal(0);
  });
});
