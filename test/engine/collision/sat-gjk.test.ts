import { expect } from 'chai';
import { ClosestPoints, Penetration, gjkDistance, gjkIntersect, sat } from '../../../src/engine/collision/index.js';
import {
  Failures, KINDS, boundaryDistance, bruteSignedDistance, describeShape, randomPair, rng, sizeOf, translated,
} from './helpers.js';

const PAIRS = 10_000;

describe('SAT and boolean GJK', () => {
  for (const ka of KINDS) {
    for (const kb of KINDS) {
      it(`agree with each other and with brute force on ${PAIRS} random ${ka}–${kb} pairs`, () => {
        const r = rng(1000 + KINDS.indexOf(ka) * 3 + KINDS.indexOf(kb));
        const pen = new Penetration();
        const cp = new ClosestPoints();
        const fail = new Failures();
        let hits = 0;
        let misses = 0;
        let ambiguous = 0;
        for (let k = 0; k < PAIRS; k++) {
          const [a, b] = randomPair(r, ka, kb);
          const size = sizeOf(a, b);
          const s = sat(a, b, pen);
          const g = gjkIntersect(a, b);
          const brute = bruteSignedDistance(a, b);
          // Pairs within rounding of touching may go either way.
          const margin = s ? pen.depth : gjkDistance(a, b, cp);
          if (margin < 1e-9 * size && Math.abs(brute) < 1e-9 * size) {
            ambiguous++;
            continue;
          }
          if (s !== g || s !== brute < 0) fail.add(`sat ${s} gjk ${g} brute ${brute}: ${describeShape(a)} vs ${describeShape(b)}`);
          if (s) hits++;
          else misses++;
        }
        fail.check();
        // Both outcomes are well represented, and near-touching pairs are rare.
        expect(hits).to.be.greaterThan(PAIRS / 5);
        expect(misses).to.be.greaterThan(PAIRS / 5);
        expect(ambiguous).to.be.lessThan(PAIRS / 100);
      });
    }
  }
});

describe('SAT minimum translation vector', () => {
  for (const ka of KINDS) {
    for (const kb of KINDS) {
      it(`${ka}–${kb}: B moved by depth + ε along the normal is apart, by depth − ε still overlaps; the contact point sits between the outlines`, () => {
        const r = rng(2000 + KINDS.indexOf(ka) * 3 + KINDS.indexOf(kb));
        const pen = new Penetration();
        const other = new Penetration();
        const fail = new Failures();
        let checked = 0;
        for (let k = 0; k < PAIRS; k++) {
          const [a, b] = randomPair(r, ka, kb, 1, 0.8);
          if (!sat(a, b, pen)) continue;
          const size = sizeOf(a, b);
          const eps = 1e-7 * size;
          const { normalX: nx, normalY: ny, depth } = pen;
          if (Math.abs(nx * nx + ny * ny - 1) > 1e-12) fail.add(`normal not unit: ${nx}, ${ny}`);
          if (depth <= 2 * eps) continue;
          checked++;
          const out = translated(b, (depth + eps) * nx, (depth + eps) * ny);
          if (sat(a, out, other) || gjkIntersect(a, out)) fail.add(`still overlapping after depth + ε: ${describeShape(a)} vs ${describeShape(b)} n ${nx},${ny} d ${depth}`);
          const inside = translated(b, (depth - eps) * nx, (depth - eps) * ny);
          if (!sat(a, inside, other) || !gjkIntersect(a, inside)) fail.add(`apart after depth − ε: ${describeShape(a)} vs ${describeShape(b)}`);
          // point ± depth/2 · n lie on A's and B's outlines.
          const onA = boundaryDistance(a, pen.pointX + (depth / 2) * nx, pen.pointY + (depth / 2) * ny);
          const onB = boundaryDistance(b, pen.pointX - (depth / 2) * nx, pen.pointY - (depth / 2) * ny);
          if (onA > 1e-9 * size || onB > 1e-9 * size) fail.add(`contact point off the outlines by ${onA}, ${onB}`);
        }
        fail.check();
        expect(checked).to.be.greaterThan(PAIRS / 3);
      });
    }
  }
});
