// physics-elements collision module: convex shapes over particle arrays, SAT, GJK, EPA, contact manifolds,
// bounding volumes, hulls, queries and concave decomposition. Every narrow-phase function writes into a caller-owned
// result object and allocates nothing.
export {
  ShapeType, ShapeView, polygon, circle, segment, polygonView, circleView, segmentView, counterClockwise, assertConvex,
} from './shape.js';
export type { Shape, PointLike } from './shape.js';
export { Penetration, Manifold, Simplex, ClosestPoints, RayHit } from './results.js';
// The functions that take shapes check them (their layout, in constant time) and their result objects on every call.
export {
  sat, gjkIntersect, gjkDistance, epa, gjkEpa, polygonManifold, aabbOf, boundingCircleOf, obbOf, kdopOf, pointInShape,
  raycast, shapeArea, shapeCentroid, shapeVertices, shapeSize, vertexX, vertexY, supportIndex, supportPoint,
} from './checked.js';
export { AABB, aabbOverlap, aabbContains, aabbArea } from './aabb.js';
export { BoundingCircle, boundingCircle, boundingCircleOverlap } from './bounding-circle.js';
export { OBB, obbFromPoints, obbOverlap, obbContains } from './obb.js';
export { KDOP8, kdopOverlap, kdopContains } from './kdop.js';
export { quickhull, quickhullIndices } from './hull.js';
export { decompose, decomposeToShapes, triangulate } from './decompose.js';
