// Families of convex polygon pairs for the property tests (issue 13), as fast-check arbitraries: random convex,
// regular n-gons, polygons with collinear (180°) vertices, parallel faces, near-contact, slivers, identical and nested
// shapes. Each makes a pair about 1 unit in size near the origin; `placed` then moves it 1e6 away or shrinks it to
// 1e-6. Shapes are built as views (make), not with polygon(), the way the engine builds them: rounding far from the
// origin may bend a 180° corner inward by an ulp, which polygon() would rightly refuse.
import fc from 'fast-check';
import { ShapeType, type Shape } from '../../../src/engine/collision/index.js';
import { edgeNormalOverlaps, make, pts } from './helpers.js';

export type Pt = { x: number; y: number };
export interface Pair {
  a: Pt[];
  b: Pt[];
}

const unit = fc.double({ min: 0, max: 1, noNaN: true });
const angle = fc.double({ min: 0, max: 2 * Math.PI, noNaN: true, maxExcluded: true });
const sign = fc.constantFrom(-1, 1);

function transform(points: Pt[], rot: number, dx: number, dy: number, sx = 1, sy = 1): Pt[] {
  const c = Math.cos(rot);
  const s = Math.sin(rot);
  return points.map((p) => ({ x: dx + p.x * sx * c - p.y * sy * s, y: dy + p.x * sx * s + p.y * sy * c }));
}

/** Points on a unit circle at angles separated by the given gaps (normalized to one turn), counter-clockwise. */
function onCircle(gaps: number[], start: number): Pt[] {
  const total = gaps.reduce((s, g) => s + g, 0);
  let a = start;
  return gaps.map((g) => {
    const p = { x: Math.cos(a), y: Math.sin(a) };
    a += (2 * Math.PI * g) / total;
    return p;
  });
}

/** A convex polygon of 3–10 vertices: points on an ellipse (aspect up to 1:4), rotated, about `size` across. */
const convex = fc
  .record({
    gaps: fc.array(fc.double({ min: 0.15, max: 1, noNaN: true }), { minLength: 3, maxLength: 10 }),
    start: angle,
    stretch: fc.double({ min: 0.25, max: 1, noNaN: true }),
    rot: angle,
    size: fc.double({ min: 0.5, max: 1.5, noNaN: true }),
  })
  // Every gap under half a turn, so no vertex is lost to a straight angle.
  .filter(({ gaps }) => Math.max(...gaps) / gaps.reduce((s, g) => s + g, 0) < 0.45)
  .map(({ gaps, start, stretch, rot, size }) => transform(onCircle(gaps, start), rot, 0, 0, size, size * stretch));

/** Every point moved by (dx, dy). */
const shift = (p: Pt[], dx: number, dy: number) => p.map((q) => ({ x: q.x + dx, y: q.y + dy }));

/** B placed at a random distance up to `reach` (about half the pairs overlap). */
const apart = (reach: number) => fc.record({ d: fc.double({ min: 0, max: reach, noNaN: true }), dir: angle });

export const randomConvex: fc.Arbitrary<Pair> = fc
  .tuple(convex, convex, apart(2.5))
  .map(([a, b, { d, dir }]) => ({ a, b: shift(b, d * Math.cos(dir), d * Math.sin(dir)) }));

/** Regular n-gons (3–12 sides); a third of the pairs share a side count and an orientation (faces parallel, exact ties). */
export const regularPolygons: fc.Arbitrary<Pair> = fc
  .record({ na: fc.integer({ min: 3, max: 12 }), nb: fc.integer({ min: 3, max: 12 }), same: fc.boolean(), ra: angle, rb: angle, r: fc.double({ min: 0.3, max: 1.5, noNaN: true }), place: apart(2.5) })
  .map(({ na, nb, same, ra, rb, r, place }) => {
    const ngon = (n: number, rot: number, radius: number) => Array.from({ length: n }, (_, k) => ({ x: radius * Math.cos(rot + (2 * Math.PI * k) / n), y: radius * Math.sin(rot + (2 * Math.PI * k) / n) }));
    const a = ngon(na, ra, 1);
    const b = same ? ngon(na, ra, r) : ngon(nb, rb, r);
    return { a, b: shift(b, place.d * Math.cos(place.dir), place.d * Math.sin(place.dir)) };
  });

/** Splits some edges of a polygon into 2–4 pieces at 180° vertices (interpolated: straight up to rounding). */
function withCollinear(p: Pt[], splits: number[]): Pt[] {
  const out: Pt[] = [];
  for (let k = 0; k < p.length; k++) {
    const s = p[k];
    const e = p[(k + 1) % p.length];
    out.push(s);
    const pieces = splits[k % splits.length];
    for (let j = 1; j < pieces; j++) out.push({ x: s.x + ((e.x - s.x) * j) / pieces, y: s.y + ((e.y - s.y) * j) / pieces });
  }
  return out;
}

const splits = fc.array(fc.integer({ min: 1, max: 4 }), { minLength: 1, maxLength: 6 });

/**
 * Polygons with 180° vertices: random convex ones with split edges, and axis-aligned boxes split at exact dyadic
 * points (exactly collinear), placed against each other face to face as in the issue's examples.
 */
export const collinearVertices: fc.Arbitrary<Pair> = fc.oneof(
  fc.tuple(convex, convex, splits, splits, apart(2.5)).map(([a, b, sa, sb, { d, dir }]) => ({
    a: withCollinear(a, sa),
    b: shift(withCollinear(b, sb), d * Math.cos(dir), d * Math.sin(dir)),
  })),
  fc
    .record({
      wa: fc.integer({ min: 1, max: 64 }), ha: fc.integer({ min: 1, max: 64 }), wb: fc.integer({ min: 1, max: 64 }), hb: fc.integer({ min: 1, max: 64 }),
      x: fc.integer({ min: -80, max: 80 }), y: fc.integer({ min: -80, max: 80 }), sa: splits, sb: splits,
    })
    .map(({ wa, ha, wb, hb, x, y, sa, sb }) => {
      const box = (x0: number, y0: number, w: number, h: number) => [{ x: x0, y: y0 }, { x: x0 + w, y: y0 }, { x: x0 + w, y: y0 + h }, { x: x0, y: y0 + h }];
      // Sixty-fourths: every coordinate is exact, and so are the split points of edges cut in 2 or 4 (exactly
      // collinear); edges cut in 3 get corners off the line by an ulp. Boxes at whole sixty-fourths also touch exactly.
      const s = 1 / 64;
      return { a: withCollinear(box(0, 0, wa * s, ha * s), sa), b: withCollinear(box(x * s, y * s, wb * s, hb * s), sb) };
    }),
);

/**
 * Parallel faces: B turned so that one of its edges is anti-parallel to one of A's, then placed with that edge from
 * 0.3 inside to 0.05 outside A's and slid along it; and pairs of rectangles turned alike.
 */
export const parallelFaces: fc.Arbitrary<Pair> = fc.oneof(
  fc
    .record({
      a: convex, b: convex, ea: fc.nat(), eb: fc.nat(),
      // Mostly overlapping or apart; touching exactly (depth 0, which fast-check's bias to bounds makes common) now and then.
      depth: fc.oneof(
        { arbitrary: fc.double({ min: 0.001, max: 0.3, noNaN: true }), weight: 6 },
        { arbitrary: fc.double({ min: -0.05, max: -0.001, noNaN: true }), weight: 3 },
        { arbitrary: fc.constant(0), weight: 1 },
      ),
      slide: fc.double({ min: -1, max: 1, noNaN: true }),
    })
    .map(({ a, b, ea, eb, depth, slide }) => {
      const i = ea % a.length;
      const j = eb % b.length;
      const a0 = a[i];
      const a1 = a[(i + 1) % a.length];
      const b0 = b[j];
      const b1 = b[(j + 1) % b.length];
      // Turn B so that its edge j runs opposite to A's edge i.
      const rot = Math.atan2(a0.y - a1.y, a0.x - a1.x) - Math.atan2(b1.y - b0.y, b1.x - b0.x);
      const bt = transform(b, rot, 0, 0);
      const len = Math.hypot(a1.x - a0.x, a1.y - a0.y);
      const tx = (a1.x - a0.x) / len;
      const ty = (a1.y - a0.y) / len;
      // B's edge start goes to A's edge midpoint, slid along it, then `depth` inwards (against A's outward normal).
      const mx = (a0.x + a1.x) / 2 + slide * len * tx - depth * ty;
      const my = (a0.y + a1.y) / 2 + slide * len * ty + depth * tx;
      return { a, b: shift(bt, mx - bt[j].x, my - bt[j].y) };
    }),
  fc
    .record({ rot: angle, wa: unit, ha: unit, wb: unit, hb: unit, x: fc.double({ min: -1.5, max: 1.5, noNaN: true }), y: fc.double({ min: -1.5, max: 1.5, noNaN: true }) })
    .map(({ rot, wa, ha, wb, hb, x, y }) => {
      const rect = (w: number, h: number) => [{ x: -w, y: -h }, { x: w, y: -h }, { x: w, y: h }, { x: -w, y: h }];
      return { a: transform(rect(0.2 + wa, 0.2 + ha), rot, 0, 0), b: transform(rect(0.2 + wb, 0.2 + hb), rot, x * Math.cos(rot) - y * Math.sin(rot), x * Math.sin(rot) + y * Math.cos(rot)) };
    }),
);

/**
 * Near contact: a pair moved along its least-overlap normal until it touches, then by a gap of ±(0.5–2)·1e-9 of its
 * size (apart or overlapping by a hair).
 */
export const nearContact: fc.Arbitrary<Pair> = fc
  .record({ pair: fc.oneof(randomConvex, parallelFaces), gap: fc.double({ min: 0.5, max: 2, noNaN: true }), side: sign })
  .map(({ pair, gap, side }) => {
    const a = make(ShapeType.Polygon, pair.a.map((p) => p.x), pair.a.map((p) => p.y));
    const b = make(ShapeType.Polygon, pair.b.map((p) => p.x), pair.b.map((p) => p.y));
    const { normals } = edgeNormalOverlaps(a, b);
    let best = normals[0];
    for (const n of normals) if (n[2] < best[2]) best = n;
    const move = best[2] + side * gap * 1e-9;
    return { a: pair.a, b: shift(pair.b, move * best[0], move * best[1]) };
  });

/** Slivers: a rectangle or triangle 1 long and 1e-4 wide (aspect 1e4), against a random polygon or another sliver. */
export const slivers: fc.Arbitrary<Pair> = fc
  .record({ triangle: fc.boolean(), rot: angle, other: fc.oneof(convex, fc.constant(null)), rot2: angle, place: apart(2) })
  .map(({ triangle, rot, other, rot2, place }) => {
    const w = 1e-4;
    const sliver = (r: number) => transform(triangle ? [{ x: -0.5, y: 0 }, { x: 0.5, y: 0 }, { x: 0, y: w }] : [{ x: -0.5, y: -w / 2 }, { x: 0.5, y: -w / 2 }, { x: 0.5, y: w / 2 }, { x: -0.5, y: w / 2 }], r, 0, 0);
    const b = other ?? sliver(rot2);
    return { a: sliver(rot), b: shift(b, place.d * Math.cos(place.dir), place.d * Math.sin(place.dir)) };
  });

/** Identical shapes (the same outline, listed from another vertex or not) and nested ones (B inside A, shrunk and moved). */
export const identicalAndNested: fc.Arbitrary<Pair> = fc
  .record({ a: convex, nested: fc.boolean(), start: fc.nat(), shrink: fc.double({ min: 0.05, max: 0.9, noNaN: true }), wobble: unit, dir: angle })
  .map(({ a, nested, start, shrink, wobble, dir }) => {
    if (!nested) return { a, b: a.map((_, k) => a[(k + start) % a.length]) };
    // Shrunk about the centroid of the vertices, then moved by less than the room left (stays inside: convexity).
    const cx = a.reduce((s, p) => s + p.x, 0) / a.length;
    const cy = a.reduce((s, p) => s + p.y, 0) / a.length;
    const inner = a.map((p) => ({ x: cx + shrink * (p.x - cx), y: cy + shrink * (p.y - cy) }));
    const room = (1 - shrink) * 0.2 * wobble;
    return { a, b: shift(inner, room * Math.cos(dir), room * Math.sin(dir)) };
  });

export const FAMILIES: [string, fc.Arbitrary<Pair>][] = [
  ['random convex', randomConvex],
  ['regular n-gons', regularPolygons],
  ['collinear (180°) vertices', collinearVertices],
  ['parallel faces', parallelFaces],
  ['near contact (gap ±1e-9·size)', nearContact],
  ['slivers (aspect 1e4)', slivers],
  ['identical and nested', identicalAndNested],
];

/** Where a family's pair is put: as made, 1e6 from the origin, or shrunk to 1e-6. */
export type Placement = 'unit' | 'far' | 'tiny';
export const PLACEMENTS: Placement[] = ['unit', 'far', 'tiny'];

export const placed = (family: fc.Arbitrary<Pair>, placement: Placement) =>
  fc.record({ pair: family, sx: sign, sy: sign, ra: fc.nat(), rb: fc.nat() }).map(({ pair, sx, sy, ra, rb }) => {
    const move = (p: Pt[]) =>
      placement === 'far' ? p.map((q) => ({ x: q.x + sx * 1e6, y: q.y + sy * 1e6 })) : placement === 'tiny' ? p.map((q) => ({ x: q.x * 1e-6, y: q.y * 1e-6 })) : p;
    const a = move(pair.a);
    const b = move(pair.b);
    return {
      a: make(ShapeType.Polygon, a.map((p) => p.x), a.map((p) => p.y)),
      b: make(ShapeType.Polygon, b.map((p) => p.x), b.map((p) => p.y)),
      /** Starting vertices for the list-rotation check. */
      ra,
      rb,
    };
  });

/** A shape's vertices as text, for failure messages. */
export function show(s: Shape): string {
  return `[${pts(s).map((p) => `[${p.x},${p.y}]`).join(',')}]`;
}
