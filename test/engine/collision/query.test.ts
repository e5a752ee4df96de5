import { expect } from 'chai';
import { RayHit, ShapeType, pointInShape, polygon, raycast, circle, segment } from '../../../src/engine/collision/index.js';
import { Failures, KINDS, boundaryDistance, pts, randomShape, rng, solidDistance } from './helpers.js';

describe('point in shape', () => {
  it('agrees with the distance to the solid on 10,000 random points per shape kind', () => {
    const r = rng(8001);
    const fail = new Failures();
    let inside = 0;
    let outside = 0;
    for (const kind of ['polygon', 'circle'] as const) {
      for (let k = 0; k < 10_000; k++) {
        const s = randomShape(r, kind, 0, 0, 1);
        const x = r() * 2.4 - 1.2;
        const y = r() * 2.4 - 1.2;
        const d = solidDistance(s, x, y);
        const b = boundaryDistance(s, x, y);
        if (b < 1e-12) continue; // on the outline: either answer
        const want = d === 0;
        if (pointInShape(s, x, y) !== want) fail.add(`${kind} (${x}, ${y}): expected ${want}`);
        if (want) inside++;
        else outside++;
      }
    }
    fail.check();
    expect(inside).to.be.greaterThan(3000);
    expect(outside).to.be.greaterThan(3000);
  });

  it('counts the outline as inside; a segment holds exactly its own points', () => {
    const sq = polygon([0, 0, 1, 0, 1, 1, 0, 1]);
    expect(pointInShape(sq, 1, 0.5)).to.equal(true);
    expect(pointInShape(sq, 0, 0)).to.equal(true);
    expect(pointInShape(sq, 1.0000001, 0.5)).to.equal(false);
    expect(pointInShape(circle(0, 0, 1), 0, 1)).to.equal(true);
    const s = segment(0, 0, 2, 1);
    expect(pointInShape(s, 1, 0.5)).to.equal(true);
    expect(pointInShape(s, 1, 0.51)).to.equal(false);
    expect(pointInShape(s, 4, 2)).to.equal(false);
  });
});

describe('ray casts', () => {
  for (const kind of KINDS) {
    it(`${kind}: agree with a brute-force intersection on 10,000 random rays (hit, distance, normal)`, () => {
      const r = rng(8100 + KINDS.indexOf(kind));
      const hit = new RayHit();
      const fail = new Failures();
      let hits = 0;
      let misses = 0;
      for (let k = 0; k < 10_000; k++) {
        const s = randomShape(r, kind, 0, 0, 1);
        // Origins outside the shape, aimed near it.
        const a = r() * 2 * Math.PI;
        const ox = 3 * Math.cos(a);
        const oy = 3 * Math.sin(a);
        const tx = r() * 2 - 1;
        const ty = r() * 2 - 1;
        const len = (0.1 + r()) * 3;
        const dx = (tx - ox) * len;
        const dy = (ty - oy) * len;
        const max = r() < 0.2 ? 2.5 + r() : Infinity;
        const got = raycast(s, ox, oy, dx, dy, max, hit);
        // Brute force: march along the unit ray against each outline piece.
        const dl = Math.hypot(dx, dy);
        const ux = dx / dl;
        const uy = dy / dl;
        let best = Infinity;
        if (s.type === ShapeType.Circle) {
          const c = pts(s)[0];
          const mx = ox - c.x;
          const my = oy - c.y;
          const b = mx * ux + my * uy;
          const disc = b * b - (mx * mx + my * my - s.radius * s.radius);
          if (disc >= 0 && -b - Math.sqrt(disc) >= 0) best = -b - Math.sqrt(disc);
        } else {
          const p = pts(s);
          const edges = p.length === 2 ? [[p[0], p[1]]] : p.map((q, j) => [q, p[(j + 1) % p.length]]);
          for (const [e0, e1] of edges) {
            const ex = e1.x - e0.x;
            const ey = e1.y - e0.y;
            const den = ux * ey - uy * ex;
            if (den === 0) continue;
            const wx = e0.x - ox;
            const wy = e0.y - oy;
            const t = (wx * ey - wy * ex) / den;
            const u = (wx * uy - wy * ux) / den;
            if (t >= 0 && u >= 0 && u <= 1) best = Math.min(best, t);
          }
        }
        if (best > max) best = Infinity;
        if (Math.abs(best - max) < 1e-9 || (best < Infinity && boundaryDistance(s, ox + best * ux, oy + best * uy) > 1e-9)) continue;
        if (got !== best < Infinity) {
          fail.add(`${kind}: hit ${got}, brute ${best}`);
          continue;
        }
        if (!got) {
          misses++;
          continue;
        }
        hits++;
        if (Math.abs(hit.distance - best) > 1e-9) fail.add(`distance ${hit.distance}, brute ${best}`);
        if (Math.abs(hit.x - (ox + best * ux)) > 1e-9 || Math.abs(hit.y - (oy + best * uy)) > 1e-9) fail.add('hit point');
        if (Math.abs(hit.normalX ** 2 + hit.normalY ** 2 - 1) > 1e-12) fail.add('normal not unit');
        // The normal faces the ray and is perpendicular to the outline there: stepping along it leaves the shape.
        if (hit.normalX * ux + hit.normalY * uy > 0) fail.add('normal faces away from the ray');
        if (s.type === ShapeType.Segment) {
          const p = pts(s);
          if (Math.abs(hit.normalX * (p[1].x - p[0].x) + hit.normalY * (p[1].y - p[0].y)) > 1e-12) fail.add('segment normal not perpendicular');
        } else if (solidDistance(s, hit.x + 1e-6 * hit.normalX, hit.y + 1e-6 * hit.normalY) === 0) {
          fail.add('normal points into the shape');
        } else if (s.type === ShapeType.Circle) {
          const c = pts(s)[0];
          if (Math.abs(hit.normalX * (hit.y - c.y) - hit.normalY * (hit.x - c.x)) > 1e-9) fail.add('circle normal not radial');
        }
      }
      fail.check();
      expect(hits).to.be.greaterThan(2000);
      expect(misses).to.be.greaterThan(1000);
    });
  }

  it('starts inside: distance 0 and normal −direction; zero direction and parallel segments miss', () => {
    const hit = new RayHit();
    const sq = polygon([0, 0, 2, 0, 2, 2, 0, 2]);
    expect(raycast(sq, 1, 1, 3, 4, Infinity, hit)).to.equal(true);
    expect([hit.distance, hit.normalX, hit.normalY]).to.deep.equal([0, -0.6, -0.8]);
    expect(raycast(circle(0, 0, 1), 0.5, 0, 1, 0, 10, hit)).to.equal(true);
    expect(hit.distance).to.equal(0);
    expect(raycast(sq, -1, 1, 0, 0, 10, hit)).to.equal(false);
    expect(raycast(segment(0, 0, 1, 0), -1, 0, 1, 0, 10, hit)).to.equal(false);
    expect(raycast(sq, -1, 1, 1, 0, 10, hit)).to.equal(true);
    expect([hit.distance, hit.x, hit.y, hit.normalX, hit.normalY]).to.deep.equal([1, 0, 1, -1, 0]);
    expect(raycast(sq, -1, 1, 1, 0, 0.5, hit)).to.equal(false);
    expect(raycast(circle(5, 0, 1), 0, 0, -1, 0, Infinity, hit)).to.equal(false);
  });
});
