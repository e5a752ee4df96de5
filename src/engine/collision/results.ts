// Caller-owned result objects. The hot functions write into these instead of allocating: make one per pair slot (or
// one per thread of work) and reuse it every step.

/**
 * Minimum translation vector of two overlapping shapes. Moving B by depth·normal (or A by −depth·normal) leaves
 * them touching. The contact point is midway between the two surfaces: point + depth/2·normal lies on A's outline
 * and point − depth/2·normal on B's. Where the two shapes meet face to face (parallel faces), it is the middle of
 * the stretch where the faces overlap, whichever vertex either list starts from.
 */
export class Penetration {
  hit = false;
  /** Unit normal from A to B. */
  normalX = 0;
  normalY = 0;
  /** Penetration depth (> 0 when hit). */
  depth = 0;
  pointX = 0;
  pointY = 0;
}

/**
 * Up to two contact points of a polygon pair (or one for a pair with a circle), and for each the feature a
 * position-based response needs (seed 4.2): vertex `vertex[k]` of shape `incident[k]` (0 = A, 1 = B) penetrates edge
 * `edge[k]` of the other shape (edge e runs from vertex e to vertex (e + 1) % count) by `depth[k]` along the normal.
 * `alpha[k]` ∈ [0, 1] places the vertex's counterpart on that edge: Q = E0 + α·(E1 − E0) is where the vertex, pushed
 * by depth[k] out of the other shape — along the normal (away from A) for a vertex of B, against it (away from B) for
 * a vertex of A — meets the edge. For a vertex under the reference face this is its orthogonal projection onto the
 * edge; for a reference vertex against the incident face it is the projection along the contact normal. A face may
 * be a run of collinear edges (180° corners): `edge[k]` is then the one of them the point lies on. A circle's vertex
 * is its centre, and its penetrating point is centre ∓ radius·normal; circle–circle contacts have edge −1.
 * `point[k]` is midway between the two surfaces (between the penetrating point and Q): point + depth/2·normal lies on
 * A's outline and point − depth/2·normal on B's. The deepest point's depth is the penetration depth (the reference
 * face is the one of least penetration), and the points do not depend on where either vertex list starts.
 */
export class Manifold {
  /** Unit normal from A to B. */
  normalX = 0;
  normalY = 0;
  /** Number of contact points: 0, 1 or 2. */
  count = 0;
  depth = new Float64Array(2);
  pointX = new Float64Array(2);
  pointY = new Float64Array(2);
  incident = new Uint8Array(2);
  vertex = new Int32Array(2);
  edge = new Int32Array(2);
  alpha = new Float64Array(2);
}

/**
 * A GJK simplex in the Minkowski difference A − B: up to three points (x, y) = (ax − bx, ay − by), with the
 * points of A and B that made them. gjkIntersect leaves in it a triangle that encloses the origin when it returns
 * true; epa starts from it.
 */
export class Simplex {
  count = 0;
  x = new Float64Array(3);
  y = new Float64Array(3);
  ax = new Float64Array(3);
  ay = new Float64Array(3);
  bx = new Float64Array(3);
  by = new Float64Array(3);
}

/** Distance and closest points of two shapes (gjkDistance). */
export class ClosestPoints {
  /** Distance between the shapes; 0 when they overlap or touch. */
  distance = 0;
  /** Closest point on A. When overlapping: a point common to both shapes. */
  ax = 0;
  ay = 0;
  /** Closest point on B. */
  bx = 0;
  by = 0;
  /** Unit direction from A's closest point to B's (0, 0 when overlapping). */
  normalX = 0;
  normalY = 0;
  /** GJK iterations used. */
  iterations = 0;
}

/** Result of a ray cast. */
export class RayHit {
  hit = false;
  /** Distance from the ray's origin along its (normalized) direction. */
  distance = 0;
  /** Hit point. */
  x = 0;
  y = 0;
  /** Outward unit normal of the surface at the hit point (−direction when the ray starts inside). */
  normalX = 0;
  normalY = 0;
}
