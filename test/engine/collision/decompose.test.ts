import { expect } from 'chai';
import { Penetration, assertConvex, decompose, decomposeToShapes, polygon, sat, triangulate } from '../../../src/engine/collision/index.js';
import { Failures, insideSimple, rng, shoelace2, throwsNaming } from './helpers.js';

type P = { x: number; y: number };

/** A random star-shaped (hence simple) polygon: sorted angles, random radii; often very concave. */
function star(r: () => number, n: number): P[] {
  let angles: number[];
  do angles = Array.from({ length: n }, () => r() * 2 * Math.PI).sort((a, b) => a - b);
  while (angles.some((a, k) => (k + 1 < n ? angles[k + 1] : angles[0] + 2 * Math.PI) - a > Math.PI - 0.2));
  const out: P[] = [];
  for (let k = 0; k < n; k++) {
    if (k > 0 && angles[k] - angles[k - 1] < 1e-3) continue;
    const rad = 0.2 + r() * 2;
    out.push({ x: rad * Math.cos(angles[k]), y: rad * Math.sin(angles[k]) });
  }
  return out;
}

/** A comb: a spine with teeth, highly non-star-shaped. */
function comb(teeth: number, depth = 3): P[] {
  const p: P[] = [{ x: 0, y: 0 }, { x: 2 * teeth - 1, y: 0 }];
  for (let t = teeth - 1; t >= 0; t--) {
    p.push({ x: 2 * t + 1, y: depth }, { x: 2 * t, y: depth });
    if (t > 0) p.push({ x: 2 * t, y: 1 }, { x: 2 * t - 1, y: 1 });
  }
  return p;
}

/** A zigzag band: a strip of constant thickness folded n times (reflex vertices on both sides). */
function zigzag(n: number): P[] {
  const bottom: P[] = [];
  const top: P[] = [];
  for (let i = 0; i <= n; i++) {
    bottom.push({ x: i, y: (i % 2) * 1.2 });
    top.push({ x: i, y: (i % 2) * 1.2 + 1 });
  }
  return bottom.concat(top.reverse());
}

function reflexCount(p: P[]): number {
  const ccw = shoelace2(p) > 0 ? 1 : -1;
  let n = 0;
  for (let k = 0; k < p.length; k++) {
    const a = p[(k + p.length - 1) % p.length];
    const b = p[k];
    const c = p[(k + 1) % p.length];
    if (ccw * ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x)) < 0) n++;
  }
  return n;
}

/** Checks a decomposition; returns an error message or ''. */
function checkParts(p: P[], parts: number[][]): string {
  const area = Math.abs(shoelace2(p)) / 2;
  let sum = 0;
  const used = new Set<number>();
  const shapes = [];
  for (const part of parts) {
    const q = part.map((i) => p[i]);
    part.forEach((i) => used.add(i));
    try {
      const s = polygon(q);
      assertConvex(s);
      shapes.push(s);
    } catch (e) {
      return `part not convex and counter-clockwise: ${(e as Error).message}`;
    }
    sum += shoelace2(q) / 2;
    // Inside the polygon: the part's centroid (parts are convex, so it is interior to the part).
    const cx = q.reduce((s, v) => s + v.x, 0) / q.length;
    const cy = q.reduce((s, v) => s + v.y, 0) / q.length;
    if (!insideSimple(p, cx, cy)) return 'a part lies outside the polygon';
  }
  if (Math.abs(sum - area) > 1e-9 * area) return `areas sum to ${sum}, polygon ${area}`;
  if (used.size !== p.length) return `${p.length - used.size} input points are on no part`;
  // Pairwise disjoint: neighbours share an edge, so they may touch but not overlap.
  const pen = new Penetration();
  for (let i = 0; i < shapes.length; i++) {
    for (let j = i + 1; j < shapes.length; j++) {
      if (sat(shapes[i], shapes[j], pen) && pen.depth > 1e-9 * Math.sqrt(area)) return `parts ${i} and ${j} overlap by ${pen.depth}`;
    }
  }
  const r = reflexCount(p);
  if (parts.length > 2 * r + 1) return `${parts.length} parts for ${r} reflex vertices (Hertel–Mehlhorn allows 2r + 1)`;
  return '';
}

describe('concave decomposition', () => {
  it('splits 3,000 random star-shaped polygons into convex, disjoint parts whose areas sum to the polygon\'s', () => {
    const r = rng(9001);
    const fail = new Failures();
    let concave = 0;
    for (let k = 0; k < 3000; k++) {
      const p = star(r, 3 + Math.floor(r() * 25));
      if (p.length < 3) continue;
      const input = k % 2 === 0 ? p : p.slice().reverse(); // either orientation
      const parts = decompose(input);
      const err = checkParts(input, parts);
      if (err) fail.add(`${err}: ${JSON.stringify(input)}`);
      if (parts.length > 1) concave++;
    }
    fail.check();
    expect(concave).to.be.greaterThan(2000);
  });

  it('handles combs, spirals, collinear points and convex input', () => {
    for (const p of [comb(2), comb(7), zigzag(3), zigzag(20)]) {
      expect(checkParts(p, decompose(p)), JSON.stringify(p)).to.equal('');
    }
    // Straight (180°) vertices stay on the part holding their edge.
    const lshape = [0, 0, 1, 0, 2, 0, 3, 0, 3, 1, 2, 1, 1, 1, 1, 2, 1, 3, 0, 3, 0, 2, 0, 1];
    const pts = Array.from({ length: lshape.length / 2 }, (_, k) => ({ x: lshape[2 * k], y: lshape[2 * k + 1] }));
    const parts = decompose(lshape);
    expect(parts.length).to.equal(2);
    expect(checkParts(pts, parts)).to.equal('');
    // A convex polygon is one part; a triangle too.
    const square = decompose([0, 0, 2, 0, 2, 2, 0, 2]);
    expect(square.length).to.equal(1);
    expect(square[0].slice().sort()).to.deep.equal([0, 1, 2, 3]);
    expect(decompose([0, 0, 1, 0, 0, 1])).to.deep.equal([[0, 1, 2]]);
    expect(decompose([0, 0, 0, 1, 1, 0])).to.deep.equal([[2, 1, 0]]);
    const shapes = decomposeToShapes(lshape);
    expect(shapes.length).to.equal(2);
  });

  it('triangulates into n − 2 triangles of the right total area', () => {
    const r = rng(9002);
    for (let k = 0; k < 200; k++) {
      const p = star(r, 5 + Math.floor(r() * 30));
      const t = triangulate(p);
      expect(t.length).to.equal(p.length - 2);
      const sum = t.reduce((s, tri) => s + shoelace2(tri.map((i) => p[i])) / 2, 0);
      expect(sum).to.be.closeTo(Math.abs(shoelace2(p)) / 2, 1e-9);
      for (const tri of t) expect(shoelace2(tri.map((i) => p[i]))).to.be.greaterThan(0);
    }
  });

  it('rejects invalid outlines with an error naming points', () => {
    throwsNaming(() => decompose([0, 0, 1, 1]), RangeError, 'points', '2');
    throwsNaming(() => decompose([0, 0, 3, 2, 3, 0, 0, 3]), RangeError, 'points', 'simple');
    throwsNaming(() => decompose([0, 0, 1, 0, 1, 0, 0, 1]), RangeError, 'points[2]', 'repeats');
    throwsNaming(() => decompose([0, 0, 1, 0, 2, 0]), RangeError, 'points', 'area');
    throwsNaming(() => decompose([0, 0, 1, 0, NaN, 1]), RangeError, 'points[4]', 'NaN');
    throwsNaming(() => decompose([{ x: 0, y: 0 }, { x: 1, y: 0 }, null as unknown as P]), TypeError, 'points[2]');
    // Touching at a vertex (a figure eight through one point) is not simple either.
    throwsNaming(() => decompose([0, 0, 2, 0, 1, 1, 2, 2, 0, 2, 1, 1]), RangeError, 'points', 'simple');
    // Folding back along an edge.
    throwsNaming(() => decompose([0, 0, 2, 0, 1, 0, 1, 1]), RangeError, 'points', 'fold');
  });
});
