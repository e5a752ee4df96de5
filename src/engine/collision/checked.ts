// The module's functions that take shapes and result objects, as `physics-elements/engine` exports them: each checks
// its arguments' layout (checkShapeLayout: constant time, no vertex read) and result objects, then calls the algorithm.
// A value that is not a shape used to read undefined fields and answer quietly wrong (pointInShape({}) was true,
// aabbOf(5) a box of NaN) or throw from deep inside ("Cannot read properties of undefined"). The engine's own narrow
// phase and queries import the algorithms from their files, unchecked: its views are checked once, when built.
// Convexity and finite vertices are still assertConvex's, once per view (docs/collision.md, Bad input).
import { describeValue, finite } from '../validate.js';
import { AABB, aabbOf as aabbOfShape } from './aabb.js';
import { BoundingCircle, boundingCircleOf as boundingCircleOfShape } from './bounding-circle.js';
import { epa as epaOf, gjkEpa as gjkEpaOf } from './epa.js';
import { gjkDistance as gjkDistanceOf, gjkIntersect as gjkIntersectOf } from './gjk.js';
import { KDOP8, kdopOf as kdopOfShape } from './kdop.js';
import { polygonManifold as manifoldOf } from './manifold.js';
import { OBB, obbOf as obbOfShape } from './obb.js';
import { pointInShape as pointIn, raycast as raycastShape } from './query.js';
import { ClosestPoints, Manifold, Penetration, RayHit, Simplex } from './results.js';
import { sat as satOf } from './sat.js';
import * as shapes from './shape.js';
import { checkShapeLayout as shape, type PointLike, type Shape } from './shape.js';

/** Throws a TypeError naming `name` unless `out` is an instance of the result class (named: builds rename classes). */
function result<T>(name: string, out: T, type: abstract new () => T, typeName: string): void {
  if (!(out instanceof type)) throw new TypeError(`${name} must be a ${typeName} (new ${typeName}()), got ${describeValue(out)}`);
}

/** Throws a TypeError naming `name` unless `out` is an object to write x and y into. */
function point(name: string, out: unknown): void {
  if (out === null || typeof out !== 'object') throw new TypeError(`${name} must be an object to write x and y into, got ${describeValue(out)}`);
}

/** SAT on two convex shapes: true and the minimum translation vector in `out` when they overlap (src/engine/collision/sat.ts). */
export function sat(a: Shape, b: Shape, out: Penetration): boolean {
  shape(a, 'a');
  shape(b, 'b');
  result('out', out, Penetration, 'Penetration');
  return satOf(a, b, out);
}

/** True when A and B overlap; with `simplexOut`, the last simplex for epa() (src/engine/collision/gjk.ts). */
export function gjkIntersect(a: Shape, b: Shape, simplexOut?: Simplex): boolean {
  shape(a, 'a');
  shape(b, 'b');
  if (simplexOut !== undefined) result('simplexOut', simplexOut, Simplex, 'Simplex');
  return gjkIntersectOf(a, b, simplexOut);
}

/** Distance between A and B (0 when they overlap) and their closest points in `out` (src/engine/collision/gjk.ts). */
export function gjkDistance(a: Shape, b: Shape, out: ClosestPoints): number {
  shape(a, 'a');
  shape(b, 'b');
  result('out', out, ClosestPoints, 'ClosestPoints');
  return gjkDistanceOf(a, b, out);
}

/** EPA from the simplex gjkIntersect left: the penetration in `out` (src/engine/collision/epa.ts). */
export function epa(a: Shape, b: Shape, simplex: Simplex, out: Penetration): boolean {
  shape(a, 'a');
  shape(b, 'b');
  result('simplex', simplex, Simplex, 'Simplex');
  result('out', out, Penetration, 'Penetration');
  return epaOf(a, b, simplex, out);
}

/** Boolean GJK, then EPA: the penetration of two shapes in `out`, or out.hit = false (src/engine/collision/epa.ts). */
export function gjkEpa(a: Shape, b: Shape, out: Penetration): boolean {
  shape(a, 'a');
  shape(b, 'b');
  result('out', out, Penetration, 'Penetration');
  return gjkEpaOf(a, b, out);
}

/** Up to two contact points with their features in `out`; `margin` > 0 for speculative points (src/engine/collision/manifold.ts). */
export function polygonManifold(a: Shape, b: Shape, out: Manifold, margin = 0): boolean {
  shape(a, 'a');
  shape(b, 'b');
  result('out', out, Manifold, 'Manifold');
  if (!(margin >= 0 && margin < Infinity)) throw new RangeError(`margin must be a finite number, 0 or more, got ${describeValue(margin)}`);
  return manifoldOf(a, b, out, margin);
}

/** A bounding volume of the shape written into `out`, once both are checked. */
function volume<T>(s: Shape, out: T, type: abstract new () => T, typeName: string, of: (s: Shape, out: T) => T): T {
  shape(s, 'shape');
  result('out', out, type, typeName);
  return of(s, out);
}

/** The shape's axis-aligned bounding box, radius included. */
export function aabbOf(s: Shape, out: AABB = new AABB()): AABB {
  return volume(s, out, AABB, 'AABB', aabbOfShape);
}

/** The least circle around the shape. */
export function boundingCircleOf(s: Shape, out: BoundingCircle = new BoundingCircle()): BoundingCircle {
  return volume(s, out, BoundingCircle, 'BoundingCircle', boundingCircleOfShape);
}

/** The least-area oriented box around the shape. */
export function obbOf(s: Shape, out: OBB = new OBB()): OBB {
  return volume(s, out, OBB, 'OBB', obbOfShape);
}

/** The shape's 8-direction discrete oriented polytope. */
export function kdopOf(s: Shape, out: KDOP8 = new KDOP8()): KDOP8 {
  return volume(s, out, KDOP8, 'KDOP8', kdopOfShape);
}

/** True when (x, y) is inside the shape or on its outline. */
export function pointInShape(s: Shape, x: number, y: number): boolean {
  shape(s, 'shape');
  return pointIn(s, x, y);
}

/** Where the ray from (ox, oy) along (dx, dy) first meets the shape within maxDistance, in `out` (src/engine/collision/query.ts). */
export function raycast(s: Shape, ox: number, oy: number, dx: number, dy: number, maxDistance: number, out: RayHit): boolean {
  shape(s, 'shape');
  result('out', out, RayHit, 'RayHit');
  return raycastShape(s, ox, oy, dx, dy, maxDistance, out);
}

/** Area: πr² for a circle, 0 for a segment, the shoelace area for a polygon. */
export function shapeArea(s: Shape): number {
  shape(s, 'shape');
  return shapes.shapeArea(s);
}

/** The centre of mass of the shape's area, written into `out`. */
export function shapeCentroid(s: Shape, out: PointLike = { x: 0, y: 0 }): PointLike {
  shape(s, 'shape');
  point('out', out);
  return shapes.shapeCentroid(s, out);
}

/** The vertices as new {x, y} objects. */
export function shapeVertices(s: Shape): PointLike[] {
  shape(s, 'shape');
  return shapes.shapeVertices(s);
}

/** A size for relative tolerances: the largest half-extent of the shape's bounding box, radius included. */
export function shapeSize(s: Shape): number {
  shape(s, 'shape');
  return shapes.shapeSize(s);
}

/** Index k of the vertex farthest along (dx, dy) (the first of equals). */
export function supportIndex(s: Shape, dx: number, dy: number): number {
  shape(s, 'shape');
  finite('dx', dx);
  finite('dy', dy);
  return shapes.supportIndex(s, dx, dy);
}

/** The support point of the shape along (dx, dy), written into `out`. */
export function supportPoint(s: Shape, dx: number, dy: number, out: PointLike): PointLike {
  shape(s, 'shape');
  point('out', out);
  return shapes.supportPoint(s, dx, dy, out);
}

/** x of vertex k (0 ≤ k < shape.count). */
export function vertexX(s: Shape, k: number): number {
  shape(s, 'shape');
  vertex(s, k);
  return shapes.vertexX(s, k);
}

/** y of vertex k (0 ≤ k < shape.count). */
export function vertexY(s: Shape, k: number): number {
  shape(s, 'shape');
  vertex(s, k);
  return shapes.vertexY(s, k);
}

function vertex(s: Shape, k: number): void {
  if (!Number.isInteger(k) || k < 0 || k >= s.count) throw new RangeError(`k must be a vertex number from 0 to ${s.count - 1}, got ${describeValue(k)}`);
}
