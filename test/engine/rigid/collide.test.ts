// Rigid manifolds against brute force: on random convex pairs (and boxes resting on boxes) every point lies on both
// outlines with pA − pB = depth·n, the normal is a separating-axis direction whose overlap is the minimum over both
// shapes' edge normals, a pair reported apart is apart, and B's edge/α give B's point back.
import { expect } from 'chai';
import { collideCircles, collidePolygonCircle, collidePolygons, ContactManifold, type PolygonRef } from '../../../src/engine/rigid/collide.js';
import { rng } from '../collision/helpers.js';

function polygonRef(xs: number[], ys: number[]): PolygonRef {
  const n = xs.length;
  const nx = new Float64Array(n);
  const ny = new Float64Array(n);
  for (let k = 0; k < n; k++) {
    const k2 = (k + 1) % n;
    const ex = xs[k2] - xs[k];
    const ey = ys[k2] - ys[k];
    const len = Math.sqrt(ex * ex + ey * ey);
    nx[k] = ey / len;
    ny[k] = -ex / len;
  }
  return { x: Float64Array.from(xs), y: Float64Array.from(ys), nx, ny, start: 0, count: n };
}

function randomConvex(r: () => number, cx: number, cy: number, size: number): PolygonRef {
  const n = 3 + Math.floor(r() * 6);
  let angles: number[];
  for (;;) {
    angles = Array.from({ length: n }, () => r() * 2 * Math.PI).sort((a, b) => a - b);
    let ok = true;
    for (let k = 0; k < n; k++) {
      const gap = k + 1 < n ? angles[k + 1] - angles[k] : angles[0] + 2 * Math.PI - angles[k];
      if (gap < 0.2 || gap > Math.PI - 0.2) ok = false;
    }
    if (ok) break;
  }
  const stretch = 0.3 + 0.7 * r();
  const rot = r() * 2 * Math.PI;
  const xs = angles.map((a) => cx + size * Math.cos(a) * Math.cos(rot) - size * stretch * Math.sin(a) * Math.sin(rot));
  const ys = angles.map((a) => cy + size * Math.cos(a) * Math.sin(rot) + size * stretch * Math.sin(a) * Math.cos(rot));
  return polygonRef(xs, ys);
}

/** Distance from a point to a polygon's outline. */
function outlineDistance(P: PolygonRef, px: number, py: number): number {
  let best = Infinity;
  for (let k = 0; k < P.count; k++) {
    const k2 = (k + 1) % P.count;
    const ex = P.x[k2] - P.x[k];
    const ey = P.y[k2] - P.y[k];
    const t = Math.max(0, Math.min(1, ((px - P.x[k]) * ex + (py - P.y[k]) * ey) / (ex * ex + ey * ey)));
    best = Math.min(best, Math.hypot(px - P.x[k] - t * ex, py - P.y[k] - t * ey));
  }
  return best;
}

/** Overlap of the projections of A and B on an axis (negative: a gap). */
function overlapOn(A: PolygonRef, B: PolygonRef, nx: number, ny: number): number {
  let aMax = -Infinity;
  let aMin = Infinity;
  let bMax = -Infinity;
  let bMin = Infinity;
  for (let k = 0; k < A.count; k++) {
    const d = A.x[k] * nx + A.y[k] * ny;
    aMax = Math.max(aMax, d);
    aMin = Math.min(aMin, d);
  }
  for (let k = 0; k < B.count; k++) {
    const d = B.x[k] * nx + B.y[k] * ny;
    bMax = Math.max(bMax, d);
    bMin = Math.min(bMin, d);
  }
  return Math.min(aMax - bMin, bMax - aMin);
}

/** The brute-force SAT depth: minimum overlap over both shapes' edge normals (≤ 0 when a separating axis exists). */
function satDepth(A: PolygonRef, B: PolygonRef): number {
  let best = Infinity;
  for (const P of [A, B]) for (let k = 0; k < P.count; k++) best = Math.min(best, overlapOn(A, B, P.nx[k], P.ny[k]));
  return best;
}

describe('rigid manifolds', () => {
  it('random convex pairs: points on both outlines, pA − pB = depth·n, n a minimum-overlap axis, misses are apart', () => {
    const r = rng(2026);
    const out = new ContactManifold();
    let hits = 0;
    for (let t = 0; t < 4000; t++) {
      const A = randomConvex(r, 0, 0, 1);
      const B = randomConvex(r, (r() - 0.5) * 3.5, (r() - 0.5) * 3.5, 0.3 + r());
      const depth = satDepth(A, B);
      out.query[0] = 0;
      const hit = collidePolygons(A, B, out);
      if (!hit) {
        // Nothing reported: the shapes are apart (or touch within rounding).
        expect(depth, `pair ${t}`).to.be.lessThan(1e-9);
        continue;
      }
      hits++;
      expect(depth, `pair ${t} reported overlapping`).to.be.greaterThan(-1e-9);
      // The normal is a face normal of one shape, pointing from A to B, whose overlap is the minimum (within the
      // reference-face tolerance).
      expect(Math.hypot(out.nx, out.ny)).to.be.closeTo(1, 1e-12);
      expect(overlapOn(A, B, out.nx, out.ny)).to.be.closeTo(depth, 5e-4 + 1e-9);
      let deepest = -Infinity;
      for (let k = 0; k < out.count; k++) {
        expect(outlineDistance(A, out.pAx[k], out.pAy[k]), `pair ${t} pA`).to.be.lessThan(1e-9);
        expect(outlineDistance(B, out.pBx[k], out.pBy[k]), `pair ${t} pB`).to.be.lessThan(1e-9);
        const dx = out.pAx[k] - out.pBx[k];
        const dy = out.pAy[k] - out.pBy[k];
        expect(dx - out.depth[k] * out.nx).to.be.closeTo(0, 1e-9);
        expect(dy - out.depth[k] * out.ny).to.be.closeTo(0, 1e-9);
        expect(out.depth[k]).to.be.at.most(depth + 5e-4 + 1e-9);
        deepest = Math.max(deepest, out.depth[k]);
        // B's edge and fraction give B's point back.
        const e = out.edgeB[k];
        const e2 = (e + 1) % B.count;
        const al = out.alphaB[k];
        expect(B.x[e] + al * (B.x[e2] - B.x[e])).to.be.closeTo(out.pBx[k], 1e-9);
        expect(B.y[e] + al * (B.y[e2] - B.y[e])).to.be.closeTo(out.pBy[k], 1e-9);
      }
      expect(deepest).to.be.greaterThan(-1e-9);
    }
    expect(hits).to.be.greaterThan(1000);
  });

  it('the reference face is the edge of largest separation, the first of equal ones (quads and other polygons, exact ties of grid-aligned boxes)', () => {
    // From the definition: for each side the smallest signed distance of the other's vertices to each edge, the first
    // edge where that is largest, and B's edge only when it beats A's by the tolerance; read back from the feature
    // bits (reference edge, which side). Quadrilaterals take their own path in maxSeparation: boxes on a grid (ties
    // everywhere), rotated boxes, any quads, and polygons of 3-8 vertices for the general loop.
    const r = rng(77);
    const out = new ContactManifold();
    const box = (cx: number, cy: number, w: number, h: number, turn: number): PolygonRef => {
      const c = Math.cos(turn);
      const s = Math.sin(turn);
      const xs = [-w, w, w, -w].map((x, k) => cx + c * x - s * [-h, -h, h, h][k]);
      const ys = [-w, w, w, -w].map((x, k) => cy + s * x + c * [-h, -h, h, h][k]);
      return polygonRef(xs, ys);
    };
    const separation = (P: PolygonRef, Q: PolygonRef): [number, number] => {
      let best = -Infinity;
      let edge = 0;
      for (let i = 0; i < P.count; i++) {
        let min = Infinity;
        for (let j = 0; j < Q.count; j++) min = Math.min(min, (Q.x[j] - P.x[i]) * P.nx[i] + (Q.y[j] - P.y[i]) * P.ny[i]);
        if (min > best) {
          best = min;
          edge = i;
        }
      }
      return [best, edge];
    };
    let checked = 0;
    for (let t = 0; t < 6000; t++) {
      const kind = t % 4;
      let A: PolygonRef;
      let B: PolygonRef;
      if (kind === 0) {
        // Unit boxes on a half-shifted grid, touching exactly or one step apart (a pyramid's neighbours).
        A = box(Math.floor(r() * 5) * 0.5, Math.floor(r() * 5), 0.5, 0.5, 0);
        B = box(A.x[0] + 0.5 + Math.floor(r() * 3) * 0.5, A.y[0] + 0.5 + Math.floor(r() * 3) - 1, 0.5, 0.5, 0);
      } else if (kind === 1) {
        A = box(0, 0, 0.5, 0.5, r() * 7);
        B = box((r() - 0.5) * 2, (r() - 0.5) * 2, 0.2 + r(), 0.2 + r(), r() * 7);
      } else {
        A = randomConvex(r, 0, 0, 1);
        B = randomConvex(r, (r() - 0.5) * 3, (r() - 0.5) * 3, 0.3 + r());
      }
      out.query[0] = 0.05;
      if (!collidePolygons(A, B, out)) continue;
      const [sepA, edgeA] = separation(A, B);
      const [sepB, edgeB] = separation(B, A);
      const flip = sepB > sepA + 5e-4;
      expect((out.feature[0] & 32768) !== 0, `pair ${t}: reference side`).to.equal(flip);
      expect((out.feature[0] >> 8) & 127, `pair ${t}: reference edge`).to.equal(flip ? edgeB : edgeA);
      checked++;
    }
    expect(checked).to.be.above(2500);
  });

  it('a box resting on a wider box: two points at the bottom corners, normal straight down', () => {
    const ground = polygonRef([-5, 5, 5, -5], [0, 0, 1, 1]);
    // y down: a unit box sitting on the ground's top face (y = 0) from above, sunk by 0.01.
    const box = polygonRef([-0.5, 0.5, 0.5, -0.5], [-0.99, -0.99, 0.01, 0.01]);
    const out = new ContactManifold();
    out.query[0] = 0;
    expect(collidePolygons(box, ground, out)).to.equal(true);
    expect(out.count).to.equal(2);
    expect([out.nx, out.ny]).to.deep.equal([0, 1]);
    const xs = [out.pAx[0], out.pAx[1]].sort((p, q) => p - q);
    expect(xs[0]).to.be.closeTo(-0.5, 1e-12);
    expect(xs[1]).to.be.closeTo(0.5, 1e-12);
    for (let k = 0; k < 2; k++) expect(out.depth[k]).to.be.closeTo(0.01, 1e-12);
    // Speculative: lifted 0.05 with a margin of 0.1, two points of depth −0.05; with margin 0.01, none.
    const lifted = polygonRef([-0.5, 0.5, 0.5, -0.5], [-1.05, -1.05, -0.05, -0.05]);
    out.query[0] = 0.1;
    expect(collidePolygons(lifted, ground, out)).to.equal(true);
    expect(out.count).to.equal(2);
    expect(out.depth[0]).to.be.closeTo(-0.05, 1e-12);
    out.query[0] = 0.01;
    expect(collidePolygons(lifted, ground, out)).to.equal(false);
  });

  it('polygon–circle swept: a circle apart and closing in takes the normal where its straight path first touches (brute force: the path sampled)', () => {
    const r = rng(1234);
    const out = new ContactManifold();
    const closest = (P: PolygonRef, px: number, py: number): [number, number] => {
      let best = Infinity;
      let at: [number, number] = [0, 0];
      for (let k = 0; k < P.count; k++) {
        const k2 = (k + 1) % P.count;
        const ex = P.x[k2] - P.x[k];
        const ey = P.y[k2] - P.y[k];
        const t = Math.max(0, Math.min(1, ((px - P.x[k]) * ex + (py - P.y[k]) * ey) / (ex * ex + ey * ey)));
        const d = Math.hypot(px - P.x[k] - t * ex, py - P.y[k] - t * ey);
        if (d < best) [best, at] = [d, [P.x[k] + t * ex, P.y[k] + t * ey]];
      }
      return at;
    };
    let hits = 0;
    let corners = 0;
    let grazing = 0;
    for (let trial = 0; trial < 1500; trial++) {
      const P = randomConvex(r, 0, 0, 1);
      const rad = 0.1 + 0.6 * r();
      const angle = r() * 2 * Math.PI;
      const cx = (1.2 + rad + r()) * Math.cos(angle);
      const cy = (1.2 + rad + r()) * Math.sin(angle);
      if (outlineDistance(P, cx, cy) <= rad) continue;
      // Aimed roughly at the polygon, often past its corners; up to 3 units within the sweep's time of 1.
      const aim = angle + Math.PI + (r() - 0.5) * 1.6;
      const speed = 3 * r();
      const vx = speed * Math.cos(aim);
      const vy = speed * Math.sin(aim);
      // The oracle: the first time on the path within 1 that the circle touches (fine samples, then bisection).
      const gap = (t: number) => outlineDistance(P, cx + vx * t, cy + vy * t) - rad;
      const N = 4000;
      let touch = -1;
      let least = Infinity;
      for (let i = 1; i <= N && touch < 0; i++) {
        least = Math.min(least, gap(i / N));
        if (gap(i / N) <= 0) {
          let lo = (i - 1) / N;
          let hi = i / N;
          for (let b = 0; b < 60; b++) [lo, hi] = gap((lo + hi) / 2) <= 0 ? [lo, (lo + hi) / 2] : [(lo + hi) / 2, hi];
          touch = hi;
        }
      }
      // Paths that come within 10⁻⁶ of touching, or touch for less than a sample: not decided by the samples.
      if (touch < 0 && least < 1e-3) {
        grazing++;
        continue;
      }
      for (const circleIsA of [false, true]) {
        out.query.set([10, cx, cy, rad, 0, 0, 0, vx, vy, 0]);
        expect(collidePolygonCircle(P, circleIsA, out)).to.equal(true);
        const still = [out.nx, out.ny, out.depth[0]];
        out.query.set([10, cx, cy, rad, 0, 0, 0, vx, vy, 1]);
        expect(collidePolygonCircle(P, circleIsA, out)).to.equal(true);
        const sign = circleIsA ? -1 : 1;
        const at = `trial ${trial}, circle ${circleIsA ? 'A' : 'B'}`;
        if (touch < 0) {
          // No touch within the sweep: as found where it is.
          expect([out.nx, out.ny, out.depth[0]], at).to.deep.equal(still);
          continue;
        }
        const hx = cx + vx * touch;
        const hy = cy + vy * touch;
        const [qx, qy] = closest(P, hx, hy);
        const d = Math.hypot(hx - qx, hy - qy);
        expect(sign * out.nx, at).to.be.closeTo((hx - qx) / d, 1e-6);
        expect(sign * out.ny, at).to.be.closeTo((hy - qy) / d, 1e-6);
        // The gap along that normal, as the solver measures it (negative: apart), and B's point back from edge/α.
        const [px, py] = circleIsA ? [out.pBx[0], out.pBy[0]] : [out.pAx[0], out.pAy[0]];
        expect(outlineDistance(P, px, py), at).to.be.lessThan(1e-9);
        expect(out.depth[0], at).to.be.closeTo(rad - ((cx - px) * (hx - qx) + (cy - py) * (hy - qy)) / d, 1e-9);
        expect(out.depth[0], at).to.be.lessThan(0);
        if (circleIsA) {
          const e = out.edgeB[0];
          const e2 = (e + 1) % P.count;
          const al = out.alphaB[0];
          expect(P.x[e] + al * (P.x[e2] - P.x[e]), at).to.be.closeTo(px, 1e-9);
          expect(P.y[e] + al * (P.y[e2] - P.y[e]), at).to.be.closeTo(py, 1e-9);
        }
        if (!circleIsA) {
          hits++;
          if (Array.from(P.x).some((x, k) => Math.hypot(x - qx, P.y[k] - qy) < 1e-9)) corners++;
        }
      }
    }
    console.log(`      swept circles: ${hits} paths touching (${corners} at a corner), ${grazing} grazing left out`);
    // Enough of each kind to mean something: faces and corners met first, paths that miss.
    expect(hits).to.be.greaterThan(300);
    expect(corners).to.be.greaterThan(50);
    expect(hits - corners).to.be.greaterThan(50);
    expect(grazing).to.be.lessThan(50);
  });

  it('polygon–circle and circle–circle: points on both outlines, either side as A', () => {
    const r = rng(77);
    const out = new ContactManifold();
    for (let t = 0; t < 2000; t++) {
      const P = randomConvex(r, 0, 0, 1);
      const cx = (r() - 0.5) * 4;
      const cy = (r() - 0.5) * 4;
      const rad = 0.1 + r();
      for (const circleIsA of [false, true]) {
        out.query.set([0, cx, cy, rad]);
        if (!collidePolygonCircle(P, circleIsA, out)) {
          // Apart: the centre is farther than the radius from the polygon (and outside it).
          expect(outlineDistance(P, cx, cy)).to.be.greaterThan(rad - 1e-9);
          continue;
        }
        const [px, py, sx, sy] = circleIsA ? [out.pBx[0], out.pBy[0], out.pAx[0], out.pAy[0]] : [out.pAx[0], out.pAy[0], out.pBx[0], out.pBy[0]];
        expect(outlineDistance(P, px, py)).to.be.lessThan(1e-9);
        expect(Math.hypot(sx - cx, sy - cy)).to.be.closeTo(rad, 1e-9);
        expect(out.pAx[0] - out.pBx[0]).to.be.closeTo(out.depth[0] * out.nx, 1e-9);
        expect(out.pAy[0] - out.pBy[0]).to.be.closeTo(out.depth[0] * out.ny, 1e-9);
        // Depth is the radius minus the centre's signed distance to the polygon.
        const inside = Array.from({ length: P.count }, (_, k) => (cx - P.x[k]) * P.nx[k] + (cy - P.y[k]) * P.ny[k]).every((s) => s <= 0);
        const signed = inside ? -outlineDistance(P, cx, cy) : outlineDistance(P, cx, cy);
        expect(out.depth[0]).to.be.closeTo(rad - signed, 1e-9);
      }
    }
    const circles = (ax: number, ay: number, ra: number, bx: number, by: number, rb: number, margin: number) => {
      out.query.set([margin, ax, ay, ra, bx, by, rb]);
      return collideCircles(out);
    };
    expect(circles(0, 0, 1, 1.5, 0, 1, 0)).to.equal(true);
    expect([out.nx, out.ny, out.depth[0], out.pAx[0], out.pBx[0]]).to.deep.equal([1, 0, 0.5, 1, 0.5]);
    expect(circles(0, 0, 1, 2.5, 0, 1, 0.4)).to.equal(false);
    expect(circles(0, 0, 1, 2.5, 0, 1, 0.6)).to.equal(true);
    expect(out.depth[0]).to.be.closeTo(-0.5, 1e-12);
  });
});
