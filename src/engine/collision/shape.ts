// Convex shapes as views onto coordinate arrays (seed 2.8, 3.2). A shape does not own its geometry: vertex k is
// (xs[index[offset + k]], ys[index[offset + k]]), so a shape built over the engine's particle arrays always collides
// with the particles' current outline. The standalone constructors (polygon, circle, segment) own small arrays.
import { describeValue, finite, nonNegative } from '../validate.js';
import { AABB, aabbOf } from './aabb.js';

/** What a shape's vertices mean. A plain object rather than a const enum, so it survives isolatedModules and .d.ts. */
export const ShapeType = { Polygon: 0, Circle: 1, Segment: 2 } as const;
export type ShapeType = (typeof ShapeType)[keyof typeof ShapeType];

export interface Shape {
  type: ShapeType;
  /** Coordinate arrays: the engine's particle arrays, or the shape's own. */
  xs: Float64Array;
  ys: Float64Array;
  /** Vertex k of the shape is (xs[index[offset + k]], ys[index[offset + k]]). */
  index: Int32Array;
  offset: number;
  /** Polygon >= 3 (counter-clockwise in the math sense, convex), circle 1 (its centre), segment 2. */
  count: number;
  /** Circle radius; 0 for polygons and segments. */
  radius: number;
}

export interface PointLike {
  x: number;
  y: number;
}

/** The one concrete class behind every shape, so that hot functions see a single object layout. */
export class ShapeView implements Shape {
  constructor(
    public type: ShapeType,
    public xs: Float64Array,
    public ys: Float64Array,
    public index: Int32Array,
    public offset: number,
    public count: number,
    public radius: number,
  ) {}
}

// ---------------------------------------------------------------------------------------------------------------
// Views (no copy, no validation: call assertConvex once when the outline is first built)

/** A convex polygon over existing arrays. Vertices must be counter-clockwise (positive shoelace area). */
export function polygonView(xs: Float64Array, ys: Float64Array, index: Int32Array, offset = 0, count = index.length - offset): Shape {
  return new ShapeView(ShapeType.Polygon, xs, ys, index, offset, count, 0);
}

/** A circle whose centre is (xs[index[offset]], ys[index[offset]]). */
export function circleView(xs: Float64Array, ys: Float64Array, index: Int32Array, offset: number, radius: number): Shape {
  return new ShapeView(ShapeType.Circle, xs, ys, index, offset, 1, radius);
}

/** A segment from vertex index[offset] to vertex index[offset + 1]. */
export function segmentView(xs: Float64Array, ys: Float64Array, index: Int32Array, offset = 0): Shape {
  return new ShapeView(ShapeType.Segment, xs, ys, index, offset, 2, 0);
}

// ---------------------------------------------------------------------------------------------------------------
// Standalone shapes (own their arrays, validated)

/**
 * Largest coordinate (and radius) magnitude a shape may have. Products of two coordinates — squared lengths, areas,
 * the cross products of GJK — then stay finite with room to spare; beyond it they overflow to Infinity and the
 * narrow phase would quietly answer wrong (a box inside a polygon of coordinates 1e200 was missed).
 */
export const MAX_COORDINATE = 1e150;

/**
 * Least length of a segment or of a polygon's edge, and least radius of a circle other than 0 (a point):
 * 1/MAX_COORDINATE, so that squared lengths stay ordinary doubles (>= 1e-300). Below about 1.5e-154 they lose their
 * digits to underflow, and results divided by them: a segment 1e-310 long had an OBB axis (Infinity, NaN) and an EPA
 * depth of Infinity, a polygon with a 1e-200 edge a SAT normal of Infinity, gjkDistance on shapes 1e-160 across
 * NaN points, and two circles of radius 1e-200 overlapped for gjkEpa but not for sat.
 */
export const MIN_LENGTH = 1e-150;

/** A finite number within ±MAX_COORDINATE, or a TypeError/RangeError naming it. */
function coordinate(name: string, value: unknown): number {
  const v = finite(name, value);
  if (v > MAX_COORDINATE || v < -MAX_COORDINATE) {
    throw new RangeError(`${name} must be within ±${MAX_COORDINATE} (beyond, squared lengths and areas overflow), got ${v}`);
  }
  return v;
}

/** Throws a RangeError unless the edge (ex, ey), named `what`, is at least MIN_LENGTH long. */
function checkLength(what: string, ex: number, ey: number): void {
  const length = Math.hypot(ex, ey);
  if (length < MIN_LENGTH) {
    throw new RangeError(`${what} must be at least MIN_LENGTH = ${MIN_LENGTH} long (shorter, squared lengths underflow), got length ${length}`);
  }
}

/**
 * Throws a RangeError unless the points are one point (repeated or not) or spread over at least MIN_LENGTH (the larger
 * side of their bounding box): closer, the hull, circle and box built on them came out wrong or NaN.
 */
function checkSpread(name: string, xs: Float64Array, ys: Float64Array): void {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  for (let k = 0; k < xs.length; k++) {
    minX = Math.min(minX, xs[k]);
    maxX = Math.max(maxX, xs[k]);
    minY = Math.min(minY, ys[k]);
    maxY = Math.max(maxY, ys[k]);
  }
  const spread = Math.max(maxX - minX, maxY - minY);
  if (spread > 0 && spread < MIN_LENGTH) {
    throw new RangeError(`${name} must be one point or spread over at least MIN_LENGTH = ${MIN_LENGTH} (closer, squared distances underflow), got a spread of ${spread}`);
  }
}

/**
 * A power of two near 1/m (m > 0): lengths of about m times it are about 1, without rounding. Sums of products of
 * three lengths (moments, circumcentres) are formed in these units: in plain units they underflow for lengths below
 * 1e-103 and overflow above 1e103, well inside [MIN_LENGTH, MAX_COORDINATE].
 */
export function unitScale(m: number): number {
  const e = Math.floor(Math.log2(m));
  return 2 ** -(e < -1000 ? -1000 : e > 1000 ? 1000 : e);
}

/** A radius: 0 (a point) or within [MIN_LENGTH, MAX_COORDINATE], or a TypeError/RangeError naming it. */
function checkRadius(name: string, value: unknown): number {
  const r = coordinate(name, nonNegative(name, value));
  if (r > 0 && r < MIN_LENGTH) throw new RangeError(`${name} must be 0 (a point) or at least MIN_LENGTH = ${MIN_LENGTH} (smaller, its square underflows), got ${r}`);
  return r;
}

/**
 * Reads `[{x, y}, ...]` or a flat `[x0, y0, x1, y1, ...]` into two arrays, checking every number (finite, within
 * ±MAX_COORDINATE) and their spread (one point, or at least MIN_LENGTH).
 */
export function readPoints(name: string, points: unknown): { xs: Float64Array; ys: Float64Array } {
  if (!Array.isArray(points) && !ArrayBuffer.isView(points)) {
    throw new TypeError(`${name} must be an array of {x, y} points or of numbers, got ${describeValue(points)}`);
  }
  const list = points as ArrayLike<unknown>;
  if (list.length > 0 && typeof list[0] === 'number') {
    if (list.length % 2 !== 0) throw new RangeError(`${name} as a flat [x0, y0, x1, y1, ...] list needs an even length, got ${list.length}`);
    const n = list.length / 2;
    const xs = new Float64Array(n);
    const ys = new Float64Array(n);
    for (let k = 0; k < n; k++) {
      xs[k] = coordinate(`${name}[${2 * k}]`, list[2 * k]);
      ys[k] = coordinate(`${name}[${2 * k + 1}]`, list[2 * k + 1]);
    }
    checkSpread(name, xs, ys);
    return { xs, ys };
  }
  const n = list.length;
  const xs = new Float64Array(n);
  const ys = new Float64Array(n);
  for (let k = 0; k < n; k++) {
    const p = list[k] as PointLike | null | undefined;
    if (p === null || typeof p !== 'object') throw new TypeError(`${name}[${k}] must be a point {x, y}, got ${describeValue(p)}`);
    xs[k] = coordinate(`${name}[${k}].x`, p.x);
    ys[k] = coordinate(`${name}[${k}].y`, p.y);
  }
  checkSpread(name, xs, ys);
  return { xs, ys };
}

function iota(n: number): Int32Array {
  const index = new Int32Array(n);
  for (let k = 0; k < n; k++) index[k] = k;
  return index;
}

/**
 * A convex polygon that owns a copy of `points` ({x, y} objects or a flat number list). Throws a TypeError or
 * RangeError naming the argument when there are fewer than 3 points, a coordinate is not finite or beyond
 * ±MAX_COORDINATE, two consecutive points coincide or are closer than MIN_LENGTH, the area is zero, the order is
 * clockwise (fix it with counterClockwise) or the outline is not convex (split it with decompose). Collinear
 * consecutive vertices (180° corners) are allowed.
 */
export function polygon(points: readonly PointLike[] | readonly number[] | ArrayLike<number>): Shape {
  const { xs, ys } = readPoints('points', points);
  const shape = polygonView(xs, ys, iota(xs.length), 0, xs.length);
  checkConvex('points', shape);
  return shape;
}

/**
 * A circle of centre (x, y) and radius r (coordinates within ±MAX_COORDINATE; r is 0, a point, or from MIN_LENGTH
 * to MAX_COORDINATE).
 */
export function circle(x: number, y: number, r: number): Shape {
  const xs = new Float64Array([coordinate('x', x)]);
  const ys = new Float64Array([coordinate('y', y)]);
  return circleView(xs, ys, iota(1), 0, checkRadius('r', r));
}

/** A segment from (x1, y1) to (x2, y2); the endpoints must differ, by at least MIN_LENGTH. */
export function segment(x1: number, y1: number, x2: number, y2: number): Shape {
  const xs = new Float64Array([coordinate('x1', x1), coordinate('x2', x2)]);
  const ys = new Float64Array([coordinate('y1', y1), coordinate('y2', y2)]);
  if (xs[0] === xs[1] && ys[0] === ys[1]) throw new RangeError(`segment endpoints must differ, got (${x1}, ${y1}) twice`);
  checkLength(`segment (x1, y1) to (x2, y2), here (${x1}, ${y1}) to (${x2}, ${y2}),`, xs[1] - xs[0], ys[1] - ys[0]);
  return segmentView(xs, ys, iota(2), 0);
}

/** The same points, counter-clockwise (reversed when their shoelace area is negative). Returns a new array of {x, y}. */
export function counterClockwise(points: readonly PointLike[] | readonly number[] | ArrayLike<number>): PointLike[] {
  const { xs, ys } = readPoints('points', points);
  const out: PointLike[] = [];
  for (let k = 0; k < xs.length; k++) out.push({ x: xs[k], y: ys[k] });
  if (shoelace(xs, ys, iota(xs.length), 0, xs.length) < 0) out.reverse();
  return out;
}

// ---------------------------------------------------------------------------------------------------------------
// Validation

/**
 * Twice the signed area, Σ x_i·y_{i+1} − x_{i+1}·y_i: positive when counter-clockwise in the math sense. Summed
 * relative to the first vertex: far from the origin the products of absolute coordinates would cancel away the
 * digits of a small area (a triangle of area 0.57 near (1e6, −1e6) came out 0.57000732).
 */
export function shoelace(xs: Float64Array, ys: Float64Array, index: Int32Array, offset: number, count: number): number {
  const ox = xs[index[offset]];
  const oy = ys[index[offset]];
  let s = 0;
  for (let k = 1; k + 1 < count; k++) {
    const i = index[offset + k];
    const j = index[offset + k + 1];
    s += (xs[i] - ox) * (ys[j] - oy) - (xs[j] - ox) * (ys[i] - oy);
  }
  return s;
}

/**
 * Throws a TypeError or RangeError naming `name` unless `shape` is laid out as a shape: its type, arrays, count for the
 * type, offset within its index and radius (0 or more). Constant time: it reads no vertex (assertConvex does), so the
 * functions the module exports check their shapes with it on every call.
 */
export function checkShapeLayout(shape: unknown, name: string): asserts shape is Shape {
  if (shape === null || typeof shape !== 'object') {
    throw new TypeError(`${name} must be a shape (polygon(), circle(), segment() or a view), got ${describeValue(shape)}`);
  }
  const { xs, ys, index, offset, count, type, radius } = shape as Shape;
  if (!(xs instanceof Float64Array) || !(ys instanceof Float64Array) || !(index instanceof Int32Array)) {
    throw new TypeError(`${name} must be a shape (polygon(), circle(), segment() or a view): ${name}.xs, .ys must be Float64Arrays and ${name}.index an Int32Array, got ${describeValue(shape)}`);
  }
  const expected = type === ShapeType.Circle ? 1 : type === ShapeType.Segment ? 2 : type === ShapeType.Polygon ? -1 : -2;
  if (expected === -2) throw new RangeError(`${name}.type must be ShapeType.Polygon, Circle or Segment, got ${describeValue(type)}`);
  if (!Number.isInteger(count) || (expected > 0 ? count !== expected : count < 3)) {
    throw new RangeError(`${name}.count must be ${expected > 0 ? expected : 'at least 3'} for this type, got ${describeValue(count)}`);
  }
  if (!Number.isInteger(offset) || offset < 0 || offset + count > index.length) {
    throw new RangeError(`${name}.offset ${describeValue(offset)} with count ${count} runs past ${name}.index (length ${index.length})`);
  }
  if (!(radius >= 0 && radius <= MAX_COORDINATE)) checkRadius(`${name}.radius`, radius);
}

/** Throws unless `shape` is valid: a convex counter-clockwise polygon, a circle of finite radius, or a proper segment. */
export function assertConvex(shape: Shape, name = 'shape'): void {
  checkShapeLayout(shape, name);
  const { xs, ys, index, offset, count, type } = shape;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    if (i < 0 || i >= xs.length || i >= ys.length) throw new RangeError(`${name}.index[${offset + k}] = ${i} is outside the coordinate arrays`);
    coordinate(`${name} vertex ${k} x`, xs[i]);
    coordinate(`${name} vertex ${k} y`, ys[i]);
  }
  checkRadius(`${name}.radius`, shape.radius);
  if (type !== ShapeType.Circle && shape.radius !== 0) throw new RangeError(`${name}.radius must be 0 for a polygon or segment, got ${shape.radius}`);
  if (type === ShapeType.Segment) {
    const i = index[offset];
    const j = index[offset + 1];
    if (xs[i] === xs[j] && ys[i] === ys[j]) throw new RangeError(`${name} is a segment of zero length`);
    checkLength(`${name} (a segment from (${xs[i]}, ${ys[i]}) to (${xs[j]}, ${ys[j]}))`, xs[j] - xs[i], ys[j] - ys[i]);
  }
  if (type === ShapeType.Polygon) checkConvex(name, shape);
}

/** Relative tolerance of the convexity test: a corner may bend inward by this fraction of its edges' lengths. */
const CONVEX_TOLERANCE = 1e-12;

function checkConvex(name: string, shape: Shape): void {
  const { xs, ys, index, offset, count } = shape;
  if (count < 3) throw new RangeError(`${name} must have at least 3 points, got ${count}`);
  let turning = 0;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + ((k + 1) % count)];
    const l = index[offset + ((k + 2) % count)];
    const ex = xs[j] - xs[i];
    const ey = ys[j] - ys[i];
    if (ex === 0 && ey === 0) throw new RangeError(`${name}[${(k + 1) % count}] repeats ${name}[${k}] (${xs[i]}, ${ys[i]}): edges must have non-zero length`);
    checkLength(`the edge ${name}[${k}] to ${name}[${(k + 1) % count}], (${xs[i]}, ${ys[i]}) to (${xs[j]}, ${ys[j]}),`, ex, ey);
    const fx = xs[l] - xs[j];
    const fy = ys[l] - ys[j];
    const cross = ex * fy - ey * fx;
    const dot = ex * fx + ey * fy;
    const scale = Math.sqrt(ex * ex + ey * ey) * Math.sqrt(fx * fx + fy * fy); // (not the root of the product: it overflows)
    if (cross < -CONVEX_TOLERANCE * scale) {
      const area = shoelace(xs, ys, index, offset, count);
      if (area < 0 && isConvexClockwise(shape)) {
        throw new RangeError(`${name} must be counter-clockwise (positive shoelace area), got a clockwise outline of area ${-area / 2}; use counterClockwise(points)`);
      }
      throw new RangeError(`${name} must be convex, but the corner at ${name}[${(k + 1) % count}] (${xs[j]}, ${ys[j]}) turns clockwise; use decompose(points) for concave outlines`);
    }
    turning += Math.atan2(cross, dot);
  }
  const area = shoelace(xs, ys, index, offset, count);
  if (!(area > 0)) throw new RangeError(`${name} must enclose a non-zero area, got area ${area / 2}`);
  // All corners turn left; a convex outline turns exactly once (a pentagram turns twice).
  if (turning > 2 * Math.PI + 1e-6) throw new RangeError(`${name} must be convex, but its outline winds ${Math.round(turning / (2 * Math.PI))} times (self-intersecting)`);
}

function isConvexClockwise(shape: Shape): boolean {
  const { xs, ys, index, offset, count } = shape;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + ((k + 1) % count)];
    const l = index[offset + ((k + 2) % count)];
    const cross = (xs[j] - xs[i]) * (ys[l] - ys[j]) - (ys[j] - ys[i]) * (xs[l] - xs[j]);
    if (cross > 0) return false;
  }
  return true;
}

// ---------------------------------------------------------------------------------------------------------------
// Reading shapes (allocating helpers for setup code and tests; the hot paths read the arrays directly)

/** x of vertex k. */
export function vertexX(shape: Shape, k: number): number {
  return shape.xs[shape.index[shape.offset + k]];
}

/** y of vertex k. */
export function vertexY(shape: Shape, k: number): number {
  return shape.ys[shape.index[shape.offset + k]];
}

/** The vertices as new {x, y} objects. */
export function shapeVertices(shape: Shape): PointLike[] {
  const out: PointLike[] = [];
  for (let k = 0; k < shape.count; k++) out.push({ x: vertexX(shape, k), y: vertexY(shape, k) });
  return out;
}

/** Area: πr² for a circle, 0 for a segment, the shoelace area for a polygon. */
export function shapeArea(shape: Shape): number {
  if (shape.type === ShapeType.Circle) return Math.PI * shape.radius * shape.radius;
  if (shape.type === ShapeType.Segment) return 0;
  return shoelace(shape.xs, shape.ys, shape.index, shape.offset, shape.count) / 2;
}

/** The centre of mass of the shape's area (of its vertices' mean for a zero-area polygon), written into `out`. */
export function shapeCentroid(shape: Shape, out: PointLike = { x: 0, y: 0 }): PointLike {
  const { xs, ys, index, offset, count } = shape;
  const ox = xs[index[offset]];
  const oy = ys[index[offset]];
  // In units of the shape's size (by a power of two, exactly): the moments multiply three lengths, and a polygon
  // 1e-120 across had its centroid at its first vertex (underflow), one 1e120 across at Infinity.
  let size = 0;
  for (let k = 1; k < count; k++) {
    const i = index[offset + k];
    size = Math.max(size, Math.abs(xs[i] - ox), Math.abs(ys[i] - oy));
  }
  const s = size > 0 ? unitScale(size) : 1;
  let a = 0;
  let cx = 0;
  let cy = 0;
  let mx = 0;
  let my = 0;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const j = index[offset + (k + 1 === count ? 0 : k + 1)];
    const x0 = (xs[i] - ox) * s;
    const y0 = (ys[i] - oy) * s;
    const x1 = (xs[j] - ox) * s;
    const y1 = (ys[j] - oy) * s;
    const c = x0 * y1 - x1 * y0;
    a += c;
    cx += (x0 + x1) * c;
    cy += (y0 + y1) * c;
    mx += x0;
    my += y0;
  }
  if (shape.type === ShapeType.Polygon && a !== 0) {
    out.x = ox + cx / (3 * a) / s;
    out.y = oy + cy / (3 * a) / s;
  } else {
    out.x = ox + mx / count / s;
    out.y = oy + my / count / s;
  }
  return out;
}

// ---------------------------------------------------------------------------------------------------------------
// Support mapping (seed 3.2): the point of the shape farthest along a direction

/** Index k of the vertex farthest along (dx, dy) (the first of equals). */
export function supportIndex(shape: Shape, dx: number, dy: number): number {
  const { xs, ys, index, offset, count } = shape;
  let best = 0;
  let bestDot = xs[index[offset]] * dx + ys[index[offset]] * dy;
  for (let k = 1; k < count; k++) {
    const i = index[offset + k];
    const d = xs[i] * dx + ys[i] * dy;
    if (d > bestDot) {
      bestDot = d;
      best = k;
    }
  }
  return best;
}

/**
 * The support point of the shape along (dx, dy), written into `out`: the farthest vertex, pushed out by the radius
 * along d/|d| (a circle's support is centre + r·d/|d|; any point of it for d = 0). Throws a TypeError or RangeError
 * naming dx or dy when it is not a finite number.
 */
export function supportPoint(shape: Shape, dx: number, dy: number, out: PointLike): PointLike {
  if (!(Number.isFinite(dx) && Number.isFinite(dy))) {
    finite('dx', dx);
    finite('dy', dy);
  }
  const k = supportIndex(shape, dx, dy);
  const i = shape.index[shape.offset + k];
  out.x = shape.xs[i];
  out.y = shape.ys[i];
  const r = shape.radius;
  if (r > 0) {
    // Normalised through the larger component, as raycast does: dx² + dy² underflows to 0 for |d| = 1e-200 and
    // overflows for 1e200 (the point came out at (1, 0) from the centre, or at the centre).
    const m = Math.max(Math.abs(dx), Math.abs(dy));
    if (m > 0) {
      const ux = dx / m;
      const uy = dy / m;
      const len = Math.sqrt(ux * ux + uy * uy);
      out.x += (r * ux) / len;
      out.y += (r * uy) / len;
    } else {
      out.x += r;
    }
  }
  return out;
}

/** A size for relative tolerances: the largest half-extent of the shape's bounding box, radius included. */
export function shapeSize(shape: Shape): number {
  const box = aabbOf(shape, sizeBox);
  const w = box.maxX - box.minX;
  const h = box.maxY - box.minY;
  return (w > h ? w : h) / 2;
}
const sizeBox = new AABB();
