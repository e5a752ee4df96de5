// The exact predicates the property tests lean on (helpers.ts): they must be right where floating point is not.
import { expect } from 'chai';
import { ShapeType } from '../../../src/engine/collision/index.js';
import { exactOverlap, exactParts, make, orient } from './helpers.js';

describe('exact predicates of the test helpers', () => {
  it('exactParts reads a double\'s exact value m·2^e (normal, subnormal, negative, zero)', () => {
    const value = ([m, e]: [bigint, number]) => Number(m) * 2 ** e;
    for (const x of [1, -1, 0.1, 1e6 + 0.3, -2.5e-300, 5e-324, Number.MAX_VALUE, 0]) expect(value(exactParts(x)), String(x)).to.equal(x);
    expect(exactParts(0.5)).to.deep.equal([1n << 52n, -53]);
  });

  it('orient is exact where floating point is wrong: p = (0.5 + i·u, 0.5 + j·u) against the diagonal through (12, 12) and (24, 24)', () => {
    // Kettner et al.'s classroom example: the sign is that of j − i, but the naive determinant gets many wrong.
    const u = 2 ** -53;
    let naiveWrong = 0;
    for (let i = 0; i < 64; i++) {
      for (let j = 0; j < 64; j++) {
        const px = 0.5 + i * u;
        const py = 0.5 + j * u;
        expect(orient(px, py, 12, 12, 24, 24), `i ${i}, j ${j}`).to.equal(Math.sign(j - i));
        const naive = Math.sign((12 - px) * (24 - py) - (12 - py) * (24 - px));
        if (naive !== Math.sign(j - i)) naiveWrong++;
      }
    }
    expect(naiveWrong, 'cases the naive determinant gets wrong').to.be.greaterThan(100);
  });

  it('exactOverlap: touching exactly is not overlapping, one ulp further is; far from the origin too', () => {
    const box = (x0: number, y0: number, x1: number, y1: number) => make(ShapeType.Polygon, [x0, x1, x1, x0], [y0, y0, y1, y1]);
    for (const o of [0, 1e6, -1e15]) {
      const a = box(o, o, o + 1, o + 1);
      const step = 2 ** (Math.max(0, Math.floor(Math.log2(Math.abs(o) + 1))) - 52); // one ulp of the coordinates
      expect(exactOverlap(a, box(o + 1, o, o + 2, o + 1)), `edge to edge at ${o}`).to.equal(false);
      expect(exactOverlap(a, box(o + 1 - step, o, o + 2, o + 1)), `one ulp in at ${o}`).to.equal(true);
      expect(exactOverlap(a, box(o + 1, o + 1, o + 2, o + 2)), `corner to corner at ${o}`).to.equal(false);
      expect(exactOverlap(a, a), `identical at ${o}`).to.equal(true);
    }
    // A triangle's corner exactly on a long diagonal edge, then nudged across it by an ulp.
    const tri = make(ShapeType.Polygon, [0, 3, 0], [0, 0, 1]); // hypotenuse from (3, 0) to (0, 1)
    const onEdge = (x: number, y: number) => make(ShapeType.Polygon, [x, x + 1, x + 1], [y, y, y + 1]);
    expect(exactOverlap(tri, onEdge(1.5, 0.5))).to.equal(false); // (1.5, 0.5) is on the hypotenuse exactly
    expect(exactOverlap(tri, onEdge(1.5 - 2 ** -52, 0.5))).to.equal(true);
  });
});
