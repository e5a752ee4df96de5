// Mass properties against exact area integrals: boxes, discs, an L shape, polygons far from the origin, and random
// convex polygons against a numerical integration of ∫(x² + y²) dA over a fine grid.
import { expect } from 'chai';
import { capsuleMass, circleMass, combineMass, polygonMass } from '../../../src/engine/rigid/mass.js';
import { rng } from '../collision/helpers.js';

function box(cx: number, cy: number, w: number, h: number): { xs: number[]; ys: number[] } {
  return { xs: [cx - w / 2, cx + w / 2, cx + w / 2, cx - w / 2], ys: [cy - h / 2, cy - h / 2, cy + h / 2, cy + h / 2] };
}

describe('rigid mass properties', () => {
  it("a box's inertia is m(w² + h²)/12 about its centre, its centroid the centre", () => {
    for (const [w, h, density] of [[1, 1, 1], [2, 0.5, 3], [0.01, 7, 0.2]]) {
      const { xs, ys } = box(3, -4, w, h);
      const m = polygonMass(xs, ys, density);
      expect(m.area).to.be.closeTo(w * h, 1e-12 * w * h);
      expect(m.mass).to.be.closeTo(density * w * h, 1e-12);
      expect(m.centroidX).to.be.closeTo(3, 1e-12);
      expect(m.centroidY).to.be.closeTo(-4, 1e-12);
      expect(m.inertia).to.be.closeTo((m.mass * (w * w + h * h)) / 12, 1e-12 * m.mass * (w * w + h * h));
    }
  });

  it('a disc: m r²/2; a capsule: a rectangle and a disc split in two', () => {
    const d = circleMass(1, 2, 0.5, 2);
    expect(d.mass).to.be.closeTo(2 * Math.PI * 0.25, 1e-12);
    expect(d.inertia).to.be.closeTo((d.mass * 0.25) / 2, 1e-12);
    // Capsule of length 0 is a disc.
    const c0 = capsuleMass(0, 0, 0, 0, 0.5, 1);
    expect(c0.inertia).to.be.closeTo(circleMass(0, 0, 0.5, 1).inertia, 1e-12);
    // Long capsule (L = 4, r = 0.5): exact ∫(x² + y²) dA by integrating the outline numerically.
    const cap = capsuleMass(-2, 0, 2, 0, 0.5, 1);
    const exact = gridInertia((x, y) => (Math.abs(x) <= 2 ? Math.abs(y) <= 0.5 : (Math.abs(x) - 2) ** 2 + y * y <= 0.25), -2.5, 2.5, -0.5, 0.5, 2000);
    expect(cap.area).to.be.closeTo(4 + Math.PI * 0.25, 1e-12);
    expect(cap.inertia).to.be.closeTo(exact.inertia, 2e-3 * exact.inertia);
  });

  it('an L-shaped polygon matches the exact area integrals (area 3, centroid (5/6, 5/6), I = 11/6)', () => {
    // [0,2]×[0,1] ∪ [0,1]×[1,2], counter-clockwise.
    const xs = [0, 2, 2, 1, 1, 0];
    const ys = [0, 0, 1, 1, 2, 2];
    const m = polygonMass(xs, ys, 1);
    expect(m.area).to.be.closeTo(3, 1e-14);
    expect(m.centroidX).to.be.closeTo(5 / 6, 1e-14);
    expect(m.centroidY).to.be.closeTo(5 / 6, 1e-14);
    expect(m.inertia).to.be.closeTo(11 / 6, 1e-14);
    // The same as two rectangles combined.
    const a = box(1, 0.5, 2, 1);
    const b = box(0.5, 1.5, 1, 1);
    const both = combineMass([polygonMass(a.xs, a.ys, 1), polygonMass(b.xs, b.ys, 1)]);
    expect(both.inertia).to.be.closeTo(11 / 6, 1e-14);
    expect(both.centroidX).to.be.closeTo(5 / 6, 1e-14);
  });

  it('keeps its digits far from the origin (a triangle near (1e6, −1e6))', () => {
    const xs = [1e6, 1e6 + 1.2, 1e6 + 0.3];
    const ys = [-1e6, -1e6, -1e6 + 0.95];
    const m = polygonMass(xs, ys, 1);
    // (The inputs themselves are rounded to ~1e-10 there.)
    expect(m.area).to.be.closeTo(0.57, 1e-9);
    const near = polygonMass([0, 1.2, 0.3], [0, 0, 0.95], 1);
    expect(m.inertia).to.be.closeTo(near.inertia, 1e-9 * near.inertia);
    expect(m.centroidX - 1e6).to.be.closeTo(near.centroidX, 1e-9);
  });

  it('random convex polygons: area, centroid and inertia agree with a grid integration', () => {
    const random = rng(12345);
    for (let t = 0; t < 20; t++) {
      const n = 3 + Math.floor(random() * 6);
      const angles = Array.from({ length: n }, () => random() * 2 * Math.PI).sort((p, q) => p - q);
      const rx = 0.5 + random() * 2;
      const ry = 0.5 + random() * 2;
      const ox = (random() - 0.5) * 10;
      const oy = (random() - 0.5) * 10;
      const xs = angles.map((a) => ox + rx * Math.cos(a));
      const ys = angles.map((a) => oy + ry * Math.sin(a));
      const m = polygonMass(xs, ys, 1.7);
      const inside = (x: number, y: number) => {
        for (let k = 0; k < n; k++) {
          const k2 = (k + 1) % n;
          if ((xs[k2] - xs[k]) * (y - ys[k]) - (ys[k2] - ys[k]) * (x - xs[k]) < 0) return false;
        }
        return true;
      };
      const g = gridInertia(inside, ox - rx, ox + rx, oy - ry, oy + ry, 800);
      expect(m.area).to.be.closeTo(g.area, 5e-3 * g.area);
      expect(m.centroidX).to.be.closeTo(g.cx, 5e-3 * (rx + ry));
      expect(m.centroidY).to.be.closeTo(g.cy, 5e-3 * (rx + ry));
      expect(m.inertia / 1.7).to.be.closeTo(g.inertia, 1e-2 * g.inertia);
    }
  });
});

/** Area, centroid and polar moment about the centroid (density 1) of a region, by the midpoint rule on an n×n grid. */
function gridInertia(inside: (x: number, y: number) => boolean, x0: number, x1: number, y0: number, y1: number, n: number) {
  const dx = (x1 - x0) / n;
  const dy = (y1 - y0) / n;
  let area = 0;
  let sx = 0;
  let sy = 0;
  let sxx = 0;
  for (let i = 0; i < n; i++) {
    const x = x0 + (i + 0.5) * dx;
    for (let j = 0; j < n; j++) {
      const y = y0 + (j + 0.5) * dy;
      if (!inside(x, y)) continue;
      area += dx * dy;
      sx += x * dx * dy;
      sy += y * dx * dy;
      sxx += (x * x + y * y) * dx * dy;
    }
  }
  const cx = sx / area;
  const cy = sy / area;
  return { area, cx, cy, inertia: sxx - area * (cx * cx + cy * cy) };
}
