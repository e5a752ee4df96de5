// physics-elements collision module: convex shapes over particle arrays, SAT, GJK, EPA, contact manifolds,
// bounding volumes, hulls, queries and concave decomposition. Every narrow-phase function writes into a caller-owned
// result object and allocates nothing.
export {
  ShapeType, ShapeView, polygon, circle, segment, polygonView, circleView, segmentView, counterClockwise, assertConvex,
  shapeArea, shapeCentroid, shapeVertices, shapeSize, vertexX, vertexY, supportIndex, supportPoint,
} from './shape.js';
export type { Shape, PointLike } from './shape.js';
export { Penetration, Manifold, Simplex, ClosestPoints, RayHit } from './results.js';
export { sat } from './sat.js';
export { gjkIntersect, gjkDistance } from './gjk.js';
export { epa, gjkEpa } from './epa.js';
export { polygonManifold } from './manifold.js';
export { AABB, aabbOf, aabbOverlap, aabbContains, aabbArea } from './aabb.js';
export { BoundingCircle, boundingCircleOf, boundingCircle, boundingCircleOverlap } from './bounding-circle.js';
export { OBB, obbOf, obbFromPoints, obbOverlap, obbContains } from './obb.js';
export { KDOP8, kdopOf, kdopOverlap, kdopContains } from './kdop.js';
export { quickhull, quickhullIndices } from './hull.js';
export { pointInShape, raycast } from './query.js';
export { decompose, decomposeToShapes, triangulate } from './decompose.js';
