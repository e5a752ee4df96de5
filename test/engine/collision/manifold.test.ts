import { expect } from 'chai';
import { Manifold, Penetration, ShapeType, polygon, polygonManifold, sat } from '../../../src/engine/collision/index.js';
import { bruteSignedDistance, Failures, KINDS, checkFeatures, describeShape, make, overlapAlong, randomPair, rng, sizeOf } from './helpers.js';

const PAIRS = 10_000;

describe('contact manifold', () => {
  for (const ka of KINDS) {
    for (const kb of KINDS) {
      it(`${ka}–${kb}: hits with SAT, its points lie on both outlines, and α reproduces the point on the edge`, () => {
        const r = rng(5000 + KINDS.indexOf(ka) * 3 + KINDS.indexOf(kb));
        const m = new Manifold();
        const pen = new Penetration();
        const fail = new Failures();
        let hits = 0;
        let two = 0;
        for (let k = 0; k < PAIRS; k++) {
          const [a, b] = randomPair(r, ka, kb, 1, 0.9);
          const size = sizeOf(a, b);
          const tol = 1e-9 * size;
          const s = sat(a, b, pen);
          const hit = polygonManifold(a, b, m);
          if (s !== hit) {
            // Only within rounding of touching may the two differ: the oracle says how far apart they are (SAT's
            // depth is not written on a miss, so it cannot say).
            const brute = bruteSignedDistance(a, b);
            if (Math.abs(brute) > tol) fail.add(`sat ${s} manifold ${hit}, brute ${brute}: ${describeShape(a)} vs ${describeShape(b)}`);
            continue;
          }
          if (!hit) {
            if (m.count !== 0) fail.add('count on a miss');
            continue;
          }
          hits++;
          if (m.count === 2) two++;
          if (m.count < 1 || m.count > 2) fail.add(`count ${m.count}`);
          if (Math.abs(m.normalX ** 2 + m.normalY ** 2 - 1) > 1e-12) fail.add('normal not unit');
          // The reference face is the one of least penetration: the deepest point is SAT's depth, and so is the
          // overlap along the normal.
          let deepest = -Infinity;
          for (let j = 0; j < m.count; j++) deepest = Math.max(deepest, m.depth[j]);
          if (Math.abs(deepest - pen.depth) > tol) fail.add(`manifold depth ${deepest}, SAT ${pen.depth}: ${describeShape(a)} vs ${describeShape(b)}`);
          const along = overlapAlong(a, b, m.normalX, m.normalY);
          if (Math.abs(along - pen.depth) > tol) fail.add(`overlap along the normal ${along}, SAT depth ${pen.depth}`);
          const err = checkFeatures(a, b, m, tol * 10);
          if (err) fail.add(`${err}: ${describeShape(a)} vs ${describeShape(b)}`);
        }
        fail.check();
        expect(hits).to.be.greaterThan(PAIRS / 4);
        if (ka !== 'circle' && kb !== 'circle' && !(ka === 'segment' && kb === 'segment')) expect(two).to.be.greaterThan(0);
      });
    }
  }

  it('a box resting on a box: two points, the full depth, features on the right shapes', () => {
    const ground = polygon([0, 0, 10, 0, 10, 1, 0, 1]);
    const box = polygon([4, 0.9, 6, 0.9, 6, 2.9, 4, 2.9]);
    const m = new Manifold();
    expect(polygonManifold(ground, box, m)).to.equal(true);
    expect(m.count).to.equal(2);
    expect([m.normalX, m.normalY]).to.deep.equal([0, 1]);
    for (let k = 0; k < 2; k++) {
      expect(m.depth[k]).to.be.closeTo(0.1, 1e-12);
      expect(m.incident[k]).to.equal(1); // the box's bottom corners
      expect(m.edge[k]).to.equal(2); // the ground's top edge, (10, 1) → (0, 1)
    }
    expect([...m.vertex].sort()).to.deep.equal([0, 1]);
    expect([...m.alpha].map((a) => Math.round(a * 1e12) / 1e12).sort()).to.deep.equal([0.4, 0.6]);
    // The same pair the other way round: normal flips, features swap sides.
    expect(polygonManifold(box, ground, m)).to.equal(true);
    expect(m.normalY).to.equal(-1);
    for (let k = 0; k < m.count; k++) expect(m.incident[k]).to.equal(0);
  });

  it('a box wider than its support: the support corners clip the box edge (reference vertices on the incident edge)', () => {
    const post = polygon([0, 0, 1, 0, 1, 1, 0, 1]);
    const plank = polygon([-2, 0.8, 3, 0.8, 3, 1.8, -2, 1.8]);
    const m = new Manifold();
    expect(polygonManifold(post, plank, m)).to.equal(true);
    expect(m.count).to.equal(2);
    expect(m.normalY).to.be.closeTo(1, 1e-15);
    for (let k = 0; k < 2; k++) {
      expect(m.incident[k]).to.equal(0); // the post's top corners
      expect(m.edge[k]).to.equal(0); // the plank's bottom edge (−2, 0.8) → (3, 0.8)
      expect(m.depth[k]).to.be.closeTo(0.2, 1e-12);
    }
    expect([...m.alpha].map((a) => Math.round(a * 1e12) / 1e12).sort()).to.deep.equal([0.4, 0.6]);
  });

  it('near-parallel faces: whichever face is the reference, the contacts are the same corners on the same edge', () => {
    // A plank resting 0.2 deep on a narrow post, tilted by ±θ: level, the faces tie and the post's top is the
    // reference; tilted either way the plank's bottom is the face of least penetration. From one step to the next the
    // reference face switches, but the contacts must not jump: the post's two top corners on the plank's bottom edge.
    const post = polygon([0, 0, 1, 0, 1, 1, 0, 1]);
    const plankAt = (theta: number) => {
      const c = Math.cos(theta);
      const s = Math.sin(theta);
      return polygon([[-2.5, -0.5], [2.5, -0.5], [2.5, 0.5], [-2.5, 0.5]].flatMap(([x, y]) => [0.5 + x * c - y * s, 1.3 + x * s + y * c]));
    };
    const level = new Manifold();
    expect(polygonManifold(post, plankAt(0), level)).to.equal(true);
    const m = new Manifold();
    const references = new Set<string>();
    for (const theta of [0, -1e-6, -1e-9, -1e-12, 1e-12, 1e-9, 1e-6]) {
      const plank = plankAt(theta);
      expect(polygonManifold(post, plank, m)).to.equal(true);
      expect(m.count).to.equal(2);
      references.add(m.normalX === 0 ? 'post' : 'plank');
      for (let k = 0; k < 2; k++) {
        // The same feature (the two may come in the other order), with its point, depth and α moved by the tilt only.
        const j = m.vertex[0] === level.vertex[k] ? 0 : 1;
        expect([m.incident[j], m.vertex[j], m.edge[j]]).to.deep.equal([level.incident[k], level.vertex[k], level.edge[k]]);
        expect(m.pointX[j]).to.be.closeTo(level.pointX[k], 3 * Math.abs(theta) + 1e-12);
        expect(m.pointY[j]).to.be.closeTo(level.pointY[k], 3 * Math.abs(theta) + 1e-12);
        expect(m.depth[j]).to.be.closeTo(level.depth[k], 3 * Math.abs(theta) + 1e-12);
        expect(m.alpha[j]).to.be.closeTo(level.alpha[k], 3 * Math.abs(theta) + 1e-12);
      }
      expect(checkFeatures(post, plank, m, 1e-12)).to.equal('');
    }
    // Both faces did serve as the reference (the post's normal is exactly (0, 1), the plank's is tilted).
    expect([...references].sort()).to.deep.equal(['plank', 'post']);
  });

  it('with a margin, reports speculative contacts of shapes a little apart (negative depth)', () => {
    const a = polygon([0, 0, 1, 0, 1, 1, 0, 1]);
    const b = polygon([0, 1.05, 1, 1.05, 1, 2, 0, 2]);
    const m = new Manifold();
    expect(polygonManifold(a, b, m)).to.equal(false);
    expect(polygonManifold(a, b, m, 0.1)).to.equal(true);
    expect(m.count).to.equal(2);
    expect(m.depth[0]).to.be.closeTo(-0.05, 1e-12);
    expect(polygonManifold(a, b, m, 0.04)).to.equal(false);
    const c = make(ShapeType.Circle, [0.5], [1.5], 0.4);
    expect(polygonManifold(a, c, m)).to.equal(false);
    expect(polygonManifold(a, c, m, 0.2)).to.equal(true);
    expect(m.depth[0]).to.be.closeTo(-0.1, 1e-12);
  });
});
