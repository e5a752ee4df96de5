// Random shapes from a fixed seed, and brute-force oracles that share no code with the algorithms under test.
import { expect } from 'chai';
import { ShapeType, ShapeView, supportPoint, type Manifold, type Shape } from '../../../src/engine/collision/index.js';

/** mulberry32: a small, fast, seedable generator (uniform in [0, 1)). */
export function rng(seed: number): () => number {
  let s = seed >>> 0;
  return () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export type Kind = 'polygon' | 'circle' | 'segment';
export const KINDS: Kind[] = ['polygon', 'circle', 'segment'];

/** A standalone shape from coordinates (no validation: tests build views the way the engine will). */
export function make(type: number, xs: number[], ys: number[], radius = 0): Shape {
  const n = xs.length;
  const index = new Int32Array(n);
  for (let k = 0; k < n; k++) index[k] = k;
  return new ShapeView(type as ShapeView['type'], Float64Array.from(xs), Float64Array.from(ys), index, 0, n, radius);
}

/**
 * A random shape of about `size` (its circumradius) centred on (cx, cy): a convex polygon of 3–8 vertices (points
 * on a circle at well-spread angles, stretched up to 1:4 and rotated), a circle, or a segment.
 */
export function randomShape(r: () => number, kind: Kind, cx: number, cy: number, size: number, minVertices = 3, maxVertices = 8): Shape {
  if (kind === 'circle') return make(ShapeType.Circle, [cx], [cy], size * (0.3 + 0.7 * r()));
  const rot = r() * 2 * Math.PI;
  const cos = Math.cos(rot);
  const sin = Math.sin(rot);
  if (kind === 'segment') {
    const h = size * (0.3 + 0.7 * r());
    return make(ShapeType.Segment, [cx - h * cos, cx + h * cos], [cy - h * sin, cy + h * sin]);
  }
  const n = minVertices + Math.floor(r() * (maxVertices - minVertices + 1));
  let angles: number[];
  for (;;) {
    angles = Array.from({ length: n }, () => r() * 2 * Math.PI).sort((a, b) => a - b);
    let ok = true;
    for (let k = 0; k < n; k++) {
      const gap = k + 1 < n ? angles[k + 1] - angles[k] : angles[0] + 2 * Math.PI - angles[k];
      if (gap < 0.15 || gap > Math.PI - 0.1) ok = false;
    }
    if (ok) break;
  }
  const stretch = 0.25 + 0.75 * r();
  const xs: number[] = [];
  const ys: number[] = [];
  for (const a of angles) {
    const u = size * Math.cos(a);
    const v = size * stretch * Math.sin(a);
    xs.push(cx + u * cos - v * sin);
    ys.push(cy + u * sin + v * cos);
  }
  return make(ShapeType.Polygon, xs, ys);
}

/** A pair at a random distance: about half overlap. */
export function randomPair(r: () => number, ka: Kind, kb: Kind, size = 1, spread = 1.4, origin = 0): [Shape, Shape] {
  const sa = size * (0.5 + r());
  const sb = size * (0.5 + r());
  const a = randomShape(r, ka, origin, origin, sa);
  const ang = r() * 2 * Math.PI;
  const d = r() * spread * (sa + sb) * 0.8;
  const b = randomShape(r, kb, origin + d * Math.cos(ang), origin + d * Math.sin(ang), sb);
  return [a, b];
}

export function translated(s: Shape, dx: number, dy: number): Shape {
  const xs: number[] = [];
  const ys: number[] = [];
  for (let k = 0; k < s.count; k++) {
    xs.push(s.xs[s.index[s.offset + k]] + dx);
    ys.push(s.ys[s.index[s.offset + k]] + dy);
  }
  return make(s.type, xs, ys, s.radius);
}

export function pts(s: Shape): { x: number; y: number }[] {
  const out = [];
  for (let k = 0; k < s.count; k++) out.push({ x: s.xs[s.index[s.offset + k]], y: s.ys[s.index[s.offset + k]] });
  return out;
}

/** Largest distance of the shape's points from its first vertex, plus radius: a size for relative tolerances. */
export function sizeOf(...shapes: Shape[]): number {
  let s = 0;
  for (const shape of shapes) {
    const p = pts(shape);
    for (const q of p) s = Math.max(s, Math.abs(q.x - p[0].x), Math.abs(q.y - p[0].y));
    s = Math.max(s, shape.radius);
  }
  return s;
}

export function segDist(px: number, py: number, ax: number, ay: number, bx: number, by: number): number {
  const ex = bx - ax;
  const ey = by - ay;
  const l2 = ex * ex + ey * ey;
  let t = l2 > 0 ? ((px - ax) * ex + (py - ay) * ey) / l2 : 0;
  t = Math.max(0, Math.min(1, t));
  const dx = px - (ax + t * ex);
  const dy = py - (ay + t * ey);
  return Math.sqrt(dx * dx + dy * dy);
}

/** Edges of a shape's core as segments (a circle's is its centre, a degenerate segment). */
function coreEdges(s: Shape): [number, number, number, number][] {
  const p = pts(s);
  if (p.length === 1) return [[p[0].x, p[0].y, p[0].x, p[0].y]];
  if (p.length === 2) return [[p[0].x, p[0].y, p[1].x, p[1].y]];
  return p.map((q, k) => [q.x, q.y, p[(k + 1) % p.length].x, p[(k + 1) % p.length].y]);
}

function segmentsCross(a: [number, number, number, number], b: [number, number, number, number]): boolean {
  const o = (ax: number, ay: number, bx: number, by: number, cx: number, cy: number) => (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  const d1 = o(a[0], a[1], a[2], a[3], b[0], b[1]);
  const d2 = o(a[0], a[1], a[2], a[3], b[2], b[3]);
  const d3 = o(b[0], b[1], b[2], b[3], a[0], a[1]);
  const d4 = o(b[0], b[1], b[2], b[3], a[2], a[3]);
  return d1 * d2 < 0 && d3 * d4 < 0;
}

/** Point strictly inside a convex CCW polygon core (false for segments and points). */
function insideCore(s: Shape, x: number, y: number): boolean {
  const p = pts(s);
  if (p.length < 3) return false;
  for (let k = 0; k < p.length; k++) {
    const a = p[k];
    const b = p[(k + 1) % p.length];
    if ((b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x) <= 0) return false;
  }
  return true;
}

/**
 * Brute force: distance between the cores (0 if they cross or one holds the other) minus the radii. Negative when the
 * radii overlap; for overlapping cores, −Infinity (depth unknown, but overlapping).
 */
export function bruteSignedDistance(a: Shape, b: Shape): number {
  const ea = coreEdges(a);
  const eb = coreEdges(b);
  for (const x of ea) for (const y of eb) if (segmentsCross(x, y)) return -Infinity;
  if (pts(a).some((q) => insideCore(b, q.x, q.y)) || pts(b).some((q) => insideCore(a, q.x, q.y))) return -Infinity;
  // Two equal polygons (or one inside the other along shared edges) neither cross nor hold a vertex strictly inside:
  // a core's centre strictly inside the other tells that they overlap.
  const centre = (s: Shape) => pts(s).reduce((c, q, _k, all) => ({ x: c.x + q.x / all.length, y: c.y + q.y / all.length }), { x: 0, y: 0 });
  const [ca, cb] = [centre(a), centre(b)];
  if (insideCore(b, ca.x, ca.y) || insideCore(a, cb.x, cb.y)) return -Infinity;
  let d = Infinity;
  for (const q of pts(a)) for (const e of eb) d = Math.min(d, segDist(q.x, q.y, e[0], e[1], e[2], e[3]));
  for (const q of pts(b)) for (const e of ea) d = Math.min(d, segDist(q.x, q.y, e[0], e[1], e[2], e[3]));
  return d - a.radius - b.radius;
}

/**
 * Brute force: how deep two shapes whose cores overlap are (bruteSignedDistance's −Infinity), the least overlap of
 * their projections over every edge normal of both cores (the face normals of the cores' Minkowski difference), plus
 * the radii. Two point cores (circles) overlap by the radii less their distance.
 */
export function bruteCoreDepth(a: Shape, b: Shape): number {
  const [pa, pb] = [pts(a), pts(b)];
  const normals: [number, number][] = [];
  for (const p of [pa, pb]) {
    for (let k = 0; k < (p.length === 2 ? 1 : p.length); k++) {
      const [u, v] = [p[k], p[(k + 1) % p.length]];
      const length = Math.hypot(v.x - u.x, v.y - u.y);
      if (p.length > 1 && length > 0) normals.push([-(v.y - u.y) / length, (v.x - u.x) / length]);
    }
  }
  if (normals.length === 0) return a.radius + b.radius - Math.hypot(pb[0].x - pa[0].x, pb[0].y - pa[0].y);
  let depth = Infinity;
  for (const [nx, ny] of normals) {
    const project = (p: { x: number; y: number }[]) => p.map((q) => q.x * nx + q.y * ny);
    const [sa, sb] = [project(pa), project(pb)];
    const overlap = Math.min(Math.max(...sa) - Math.min(...sb), Math.max(...sb) - Math.min(...sa));
    depth = Math.min(depth, overlap + a.radius + b.radius);
  }
  return depth;
}

/** Distance from (x, y) to the outline of a shape (a circle's circumference, a polygon's edges, a segment). */
export function boundaryDistance(s: Shape, x: number, y: number): number {
  if (s.type === ShapeType.Circle) {
    const c = pts(s)[0];
    return Math.abs(Math.sqrt((x - c.x) ** 2 + (y - c.y) ** 2) - s.radius);
  }
  let d = Infinity;
  for (const e of coreEdges(s)) d = Math.min(d, segDist(x, y, e[0], e[1], e[2], e[3]));
  return d;
}

/** Distance from (x, y) to the shape as a solid (0 inside). */
export function solidDistance(s: Shape, x: number, y: number): number {
  if (s.type === ShapeType.Circle) {
    const c = pts(s)[0];
    return Math.max(0, Math.sqrt((x - c.x) ** 2 + (y - c.y) ** 2) - s.radius);
  }
  if (s.type === ShapeType.Polygon && insideCore(s, x, y)) return 0;
  return boundaryDistance(s, x, y);
}

const sp = { x: 0, y: 0 };
/** Overlap of A and B along the unit direction n: max_A(n) − min_B(n) (the depth if B moved along n). */
export function overlapAlong(a: Shape, b: Shape, nx: number, ny: number): number {
  supportPoint(a, nx, ny, sp);
  const ha = sp.x * nx + sp.y * ny;
  supportPoint(b, -nx, -ny, sp);
  return ha - (sp.x * nx + sp.y * ny);
}

/** Andrew's monotone chain: hull counter-clockwise, no collinear or repeated points (the oracle for quickhull). */
export function monotoneChain(points: { x: number; y: number }[]): { x: number; y: number }[] {
  const p = points.slice().sort((a, b) => a.x - b.x || a.y - b.y);
  const cross = (o: { x: number; y: number }, a: { x: number; y: number }, b: { x: number; y: number }) =>
    (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
  const lower: { x: number; y: number }[] = [];
  for (const q of p) {
    while (lower.length >= 2 && cross(lower[lower.length - 2], lower[lower.length - 1], q) <= 0) lower.pop();
    lower.push(q);
  }
  const upper: { x: number; y: number }[] = [];
  for (let k = p.length - 1; k >= 0; k--) {
    const q = p[k];
    while (upper.length >= 2 && cross(upper[upper.length - 2], upper[upper.length - 1], q) <= 0) upper.pop();
    upper.push(q);
  }
  const hull = lower.slice(0, -1).concat(upper.slice(0, -1));
  // Collapse a hull of one repeated point.
  if (hull.length === 2 && hull[0].x === hull[1].x && hull[0].y === hull[1].y) return [hull[0]];
  if (hull.length === 0 && p.length > 0) return [p[0]];
  return hull;
}

/** Twice the signed area of a point loop. */
export function shoelace2(p: { x: number; y: number }[]): number {
  let s = 0;
  for (let k = 0; k < p.length; k++) {
    const q = p[(k + 1) % p.length];
    s += p[k].x * q.y - q.x * p[k].y;
  }
  return s;
}

/** Crossing-number point-in-polygon for any simple polygon (boundary points may go either way). */
export function insideSimple(p: { x: number; y: number }[], x: number, y: number): boolean {
  let inside = false;
  for (let i = 0, j = p.length - 1; i < p.length; j = i++) {
    if (p[i].y > y !== p[j].y > y && x < ((p[j].x - p[i].x) * (y - p[i].y)) / (p[j].y - p[i].y) + p[i].x) inside = !inside;
  }
  return inside;
}

export function throwsNaming(fn: () => unknown, type: typeof RangeError | typeof TypeError, ...words: string[]): void {
  let caught: unknown;
  try {
    fn();
  } catch (e) {
    caught = e;
  }
  expect(caught, `expected ${type.name} naming ${words.join(', ')}`).to.be.instanceOf(type);
  for (const w of words) expect((caught as Error).message).to.include(w);
}

/** Collects failures (up to a few, with context) so a loop over 10,000 cases reports why, not just that. */
export class Failures {
  count = 0;
  samples: string[] = [];
  add(message: string): void {
    this.count++;
    if (this.samples.length < 5) this.samples.push(message);
  }
  check(): void {
    expect(this.count, this.samples.join('\n')).to.equal(0);
  }
}

export function describeShape(s: Shape): string {
  return `${['polygon', 'circle', 'segment'][s.type]}(${pts(s).map((q) => `${q.x},${q.y}`).join(' ')}${s.radius ? ` r=${s.radius}` : ''})`;
}

// ---------------------------------------------------------------------------------------------------------------
// Exact predicates: yes/no answers that rounding cannot fool. Floating point first (Shewchuk's error bound for the
// orientation determinant); when the answer is within that bound of zero, exact integer arithmetic on the doubles'
// exact values (every double is m·2^e with an integer m, so a common power of two turns six of them into BigInts).

const bits = new DataView(new ArrayBuffer(8));

/** The exact value of a double as [m, e] with value = m·2^e (m a BigInt; [0n, 0] for zero). */
export function exactParts(x: number): [bigint, number] {
  if (!Number.isFinite(x)) throw new RangeError(`exactParts needs a finite number, got ${x}`);
  if (x === 0) return [0n, 0];
  bits.setFloat64(0, x);
  const hi = bits.getUint32(0);
  const lo = bits.getUint32(4);
  const biased = (hi >>> 20) & 0x7ff;
  let m = (BigInt(hi & 0xfffff) << 32n) | BigInt(lo);
  let e = -1074; // subnormal
  if (biased !== 0) {
    m |= 1n << 52n;
    e = biased - 1075;
  }
  return [hi >>> 31 ? -m : m, e];
}

/** The doubles as BigInts scaled by one common power of two (so sums and products keep their signs exactly). */
export function exactScaled(...values: number[]): bigint[] {
  const parts = values.map(exactParts);
  let e = Infinity;
  for (const [m, pe] of parts) if (m !== 0n && pe < e) e = pe;
  return parts.map(([m, pe]) => (m === 0n ? 0n : m << BigInt(pe - e)));
}

/** How often orient() had to fall back to exact arithmetic (for the tests' own logs). */
export const exactStats = { calls: 0, exact: 0 };

/** Shewchuk's ccwerrboundA: |det| above this times the sum of the two products' magnitudes has the right sign. */
const ORIENT_BOUND = (3 + 16 * 2 ** -53) * 2 ** -53;

/**
 * Sign of the orientation of (a, b, c): 1 when c is left of a → b (counter-clockwise), −1 right, 0 exactly on the
 * line. Exact for every finite input.
 */
export function orient(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  exactStats.calls++;
  const left = (bx - ax) * (cy - ay);
  const right = (by - ay) * (cx - ax);
  const det = left - right;
  const bound = ORIENT_BOUND * (Math.abs(left) + Math.abs(right));
  if (det > bound) return 1;
  if (-det > bound) return -1;
  exactStats.exact++;
  const [Ax, Ay, Bx, By, Cx, Cy] = exactScaled(ax, ay, bx, by, cx, cy);
  const d = (Bx - Ax) * (Cy - Ay) - (By - Ay) * (Cx - Ax);
  return d > 0n ? 1 : d < 0n ? -1 : 0;
}

/**
 * Whether two convex counter-clockwise polygons overlap with positive area, exactly (touching is not overlapping):
 * they do unless an edge of one has every vertex of the other on or right of its line.
 */
export function exactOverlap(a: Shape, b: Shape): boolean {
  const pa = pts(a);
  const pb = pts(b);
  const separates = (p: { x: number; y: number }[], q: { x: number; y: number }[]) => {
    for (let k = 0; k < p.length; k++) {
      const s = p[k];
      const e = p[(k + 1) % p.length];
      if (s.x === e.x && s.y === e.y) continue;
      if (q.every((v) => orient(s.x, s.y, e.x, e.y, v.x, v.y) <= 0)) return true;
    }
    return false;
  };
  return !separates(pa, pb) && !separates(pb, pa);
}

/**
 * Brute force, for convex polygons: over every edge normal of both shapes (A's outward, B's inward, so all point
 * from A to B), the overlap max_A(n) − min_B(n), measured from A's first vertex. `depth` is the least of them (the
 * penetration depth when positive), `normals` every normal with its overlap.
 */
export function edgeNormalOverlaps(a: Shape, b: Shape): { depth: number; normals: [number, number, number][] } {
  const pa = pts(a);
  const pb = pts(b);
  const o = pa[0];
  const overlap = (nx: number, ny: number) => {
    let hi = -Infinity;
    let lo = Infinity;
    for (const p of pa) hi = Math.max(hi, nx * (p.x - o.x) + ny * (p.y - o.y));
    for (const p of pb) lo = Math.min(lo, nx * (p.x - o.x) + ny * (p.y - o.y));
    return hi - lo;
  };
  const normals: [number, number, number][] = [];
  for (const [p, sign] of [[pa, 1], [pb, -1]] as const) {
    for (let k = 0; k < p.length; k++) {
      const ex = p[(k + 1) % p.length].x - p[k].x;
      const ey = p[(k + 1) % p.length].y - p[k].y;
      const len = Math.hypot(ex, ey);
      if (len === 0) continue;
      const nx = (sign * ey) / len;
      const ny = (-sign * ex) / len;
      normals.push([nx, ny, overlap(nx, ny)]);
    }
  }
  return { depth: Math.min(...normals.map((n) => n[2])), normals };
}

/** Overlap of two polygons along (nx, ny), measured from A's first vertex (fewer digits lost far from the origin). */
export function overlapAlongLocal(a: Shape, b: Shape, nx: number, ny: number): number {
  const pa = pts(a);
  const o = pa[0];
  let hi = -Infinity;
  let lo = Infinity;
  for (const p of pa) hi = Math.max(hi, nx * (p.x - o.x) + ny * (p.y - o.y));
  for (const p of pts(b)) lo = Math.min(lo, nx * (p.x - o.x) + ny * (p.y - o.y));
  return hi - lo;
}

/** Largest coordinate magnitude of the shapes' vertices. */
export function coordinateMagnitude(...shapes: Shape[]): number {
  let m = 0;
  for (const s of shapes) for (const p of pts(s)) m = Math.max(m, Math.abs(p.x), Math.abs(p.y));
  return m;
}

/** The tolerance of issue 13: 1e-9 of the shapes' size plus 64 ulps of their largest coordinate. */
export function outlineTolerance(...shapes: Shape[]): number {
  return 1e-9 * sizeOf(...shapes) + 64 * Number.EPSILON * coordinateMagnitude(...shapes);
}

/** The same shape with its vertex list starting from vertex k (the same outline). */
export function rotated(s: Shape, k: number): Shape {
  const p = pts(s);
  const q = p.map((_, j) => p[(j + k) % p.length]);
  return make(s.type, q.map((v) => v.x), q.map((v) => v.y), s.radius);
}

/**
 * Checks every contact point's feature against the geometry: the penetrating vertex V (minus its radius along the
 * normal, for a circle) pushed by depth out of the other shape (along the normal for a vertex of B, against it for a
 * vertex of A) lands on the named edge at α, and the reported point is halfway. Returns an error message or ''.
 */
export function checkFeatures(a: Shape, b: Shape, m: Manifold, tol: number): string {
  const shapes = [a, b];
  for (let k = 0; k < m.count; k++) {
    const owner = shapes[m.incident[k]];
    const other = shapes[1 - m.incident[k]];
    const s = m.incident[k] === 1 ? 1 : -1; // a vertex of B meets A's edge further along the normal, one of A back along it
    const v = pts(owner)[m.vertex[k]];
    if (!v) return `vertex ${m.vertex[k]} out of range`;
    const depth = m.depth[k];
    // Penetrating point on the owner's outline.
    const px = v.x - s * owner.radius * m.normalX;
    const py = v.y - s * owner.radius * m.normalY;
    const qx = px + s * depth * m.normalX;
    const qy = py + s * depth * m.normalY;
    if (Math.abs(m.pointX[k] - (px + qx) / 2) > tol || Math.abs(m.pointY[k] - (py + qy) / 2) > tol) return `point ${k} not halfway`;
    if (boundaryDistance(owner, px, py) > tol) return `penetrating point ${k} off its shape by ${boundaryDistance(owner, px, py)}`;
    if (m.alpha[k] < 0 || m.alpha[k] > 1) return `alpha ${m.alpha[k]}`;
    if (m.edge[k] < 0) {
      if (!(a.type === ShapeType.Circle && b.type === ShapeType.Circle)) return 'edge −1 outside circle–circle';
      if (boundaryDistance(other, qx, qy) > tol) return `counterpart ${k} off the other circle`;
      continue;
    }
    const e = pts(other);
    const e0 = e[m.edge[k]];
    const e1 = e[(m.edge[k] + 1) % e.length];
    const ex = e0.x + m.alpha[k] * (e1.x - e0.x);
    const ey = e0.y + m.alpha[k] * (e1.y - e0.y);
    if (Math.abs(ex - qx) > tol || Math.abs(ey - qy) > tol) return `α ${m.alpha[k]} on edge ${m.edge[k]} gives (${ex}, ${ey}), expected (${qx}, ${qy})`;
  }
  return '';
}
