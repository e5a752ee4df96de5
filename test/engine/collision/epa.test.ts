import { expect } from 'chai';
import {
  Penetration, Simplex, ShapeType, epa, gjkEpa, gjkIntersect, polygon, sat, supportPoint,
} from '../../../src/engine/collision/index.js';
import { Failures, KINDS, boundaryDistance, describeShape, make, overlapAlong, randomPair, rng, sizeOf } from './helpers.js';

const PAIRS = 10_000;

describe('EPA', () => {
  for (const ka of KINDS) {
    for (const kb of KINDS) {
      it(`${ka}–${kb}: depth equals SAT's within 1e-6 of the size, the normal is an MTV direction, the witness points lie on the outlines`, () => {
        const r = rng(3000 + KINDS.indexOf(ka) * 3 + KINDS.indexOf(kb));
        const ps = new Penetration();
        const pe = new Penetration();
        const fail = new Failures();
        let hits = 0;
        let sameNormal = 0;
        for (let k = 0; k < PAIRS; k++) {
          const [a, b] = randomPair(r, ka, kb, 1, 0.7);
          const s = sat(a, b, ps);
          const e = gjkEpa(a, b, pe);
          const size = sizeOf(a, b);
          if (s !== e) {
            if (Math.max(ps.depth, pe.depth) > 1e-9 * size) fail.add(`sat ${s} (${ps.depth}) epa ${e} (${pe.depth}): ${describeShape(a)} vs ${describeShape(b)}`);
            continue;
          }
          if (!s) continue;
          hits++;
          const tol = 1e-6 * size;
          if (Math.abs(pe.depth - ps.depth) > tol) fail.add(`depth sat ${ps.depth} epa ${pe.depth}: ${describeShape(a)} vs ${describeShape(b)}`);
          // The EPA normal achieves the minimum overlap (ties between facets allow another normal than SAT's).
          const along = overlapAlong(a, b, pe.normalX, pe.normalY);
          if (Math.abs(along - ps.depth) > tol) fail.add(`overlap along EPA normal ${along} vs depth ${ps.depth}`);
          if (pe.normalX * ps.normalX + pe.normalY * ps.normalY > 1 - 1e-6) sameNormal++;
          const onA = boundaryDistance(a, pe.pointX + (pe.depth / 2) * pe.normalX, pe.pointY + (pe.depth / 2) * pe.normalY);
          const onB = boundaryDistance(b, pe.pointX - (pe.depth / 2) * pe.normalX, pe.pointY - (pe.depth / 2) * pe.normalY);
          if (onA > 1e-5 * size || onB > 1e-5 * size) fail.add(`witness off the outlines by ${onA}, ${onB}: ${describeShape(a)} vs ${describeShape(b)}`);
        }
        fail.check();
        expect(hits).to.be.greaterThan(PAIRS / 3);
        // Without ties the minimum is unique: the normals agree for all but a handful.
        expect(sameNormal).to.be.greaterThan(hits * 0.99);
      });
    }
  }

  it('grows degenerate starts: a single point, a segment, a collinear triangle, and the origin on an edge', () => {
    const a = polygon([0, 0, 4, 0, 4, 2, 0, 2]);
    const b = polygon([3, 1, 6, 1, 6, 3, 3, 3]);
    const ref = new Penetration();
    expect(sat(a, b, ref)).to.equal(true);
    const out = new Penetration();
    const sp = { x: 0, y: 0 };
    const spb = { x: 0, y: 0 };
    const put = (s: Simplex, k: number, dx: number, dy: number) => {
      supportPoint(a, dx, dy, sp);
      supportPoint(b, -dx, -dy, spb);
      s.ax[k] = sp.x;
      s.ay[k] = sp.y;
      s.bx[k] = spb.x;
      s.by[k] = spb.y;
      s.x[k] = sp.x - spb.x;
      s.y[k] = sp.y - spb.y;
    };
    const starts: [string, Simplex][] = [];
    const empty = new Simplex();
    starts.push(['empty', empty]);
    const one = new Simplex();
    put(one, 0, 1, 0);
    one.count = 1;
    starts.push(['point', one]);
    const two = new Simplex();
    put(two, 0, 1, 0);
    put(two, 1, -1, 0);
    two.count = 2;
    starts.push(['segment', two]);
    const flat = new Simplex();
    put(flat, 0, 1, 0);
    put(flat, 1, -1, 0);
    flat.x[2] = (flat.x[0] + flat.x[1]) / 2;
    flat.y[2] = (flat.y[0] + flat.y[1]) / 2;
    flat.ax[2] = (flat.ax[0] + flat.ax[1]) / 2;
    flat.ay[2] = (flat.ay[0] + flat.ay[1]) / 2;
    flat.bx[2] = (flat.bx[0] + flat.bx[1]) / 2;
    flat.by[2] = (flat.by[0] + flat.by[1]) / 2;
    flat.count = 3;
    starts.push(['collinear triangle', flat]);
    const zero = new Simplex(); // a CSO point at the origin: A's (3, 1) minus B's (3, 1)
    zero.count = 1;
    zero.ax[0] = zero.bx[0] = 3;
    zero.ay[0] = zero.by[0] = 1;
    starts.push(['origin', zero]);
    for (const [name, s] of starts) {
      expect(epa(a, b, s, out), name).to.equal(true);
      expect(out.depth, name).to.be.closeTo(ref.depth, 1e-12);
      expect(out.normalX, name).to.be.closeTo(ref.normalX, 1e-12);
      expect(out.normalY, name).to.be.closeTo(ref.normalY, 1e-12);
    }
    // A triangle of A − B that does not enclose the origin makes EPA restart from boolean GJK.
    const far = new Simplex();
    put(far, 0, -1, 1);
    put(far, 1, -1, -1);
    put(far, 2, 1, -1);
    far.count = 3;
    expect([far.x[0], far.y[0], far.x[1], far.y[1], far.x[2], far.y[2]]).to.deep.equal([-6, 1, -6, -3, 1, -3]);
    expect(epa(a, b, far, out)).to.equal(true);
    expect(out.depth).to.be.closeTo(ref.depth, 1e-12);
  });

  it('reports no penetration for touching shapes and for a flat Minkowski difference', () => {
    const a = polygon([0, 0, 2, 0, 2, 2, 0, 2]);
    const out = new Penetration();
    const s = new Simplex();
    // Touching along an edge: boolean GJK says no; EPA from its simplex says no too.
    const touching = polygon([2, 0, 4, 0, 4, 2, 2, 2]);
    expect(gjkIntersect(a, touching, s)).to.equal(false);
    expect(epa(a, touching, s, out)).to.equal(false);
    expect(gjkEpa(a, touching, out)).to.equal(false);
    // Two collinear overlapping segments: A − B has no area, so no depth.
    const s1 = make(ShapeType.Segment, [0, 2], [0, 0]);
    const s2 = make(ShapeType.Segment, [1, 3], [0, 0]);
    expect(gjkEpa(s1, s2, out)).to.equal(false);
    const pt = new Simplex();
    pt.count = 1;
    pt.ax[0] = 1;
    pt.bx[0] = 1;
    expect(epa(s1, s2, pt, out)).to.equal(false);
  });

  it('terminates on curved supports: concentric and nearly touching circles', () => {
    const out = new Penetration();
    const c1 = make(ShapeType.Circle, [0], [0], 1);
    expect(gjkEpa(c1, make(ShapeType.Circle, [0], [0], 2), out)).to.equal(true);
    expect(out.depth).to.be.closeTo(3, 1e-8);
    expect(gjkEpa(c1, make(ShapeType.Circle, [1.999999], [0.000001], 1), out)).to.equal(true);
    expect(out.depth).to.be.closeTo(2 - Math.sqrt(1.999999 ** 2 + 1e-12), 1e-9);
    expect(out.normalX).to.be.closeTo(1, 1e-6);
  });
});
