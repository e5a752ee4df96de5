// The narrow phase for pairs with a rigid body on at least one side, and a rigid body's contacts with the world's
// bounds: manifolds in world coordinates (rigid/collide.ts) turned into contact points with material anchors in
// each body's frame (rigid/contacts.ts). Pairs of particle-built bodies go to the particle narrow phase instead.
import type { ParticleStore } from '../particles.js';
import type { Bounds } from '../bounds.js';
import { ColliderKind, type Colliders } from './colliders.js';
import type { PairList } from './broadphase.js';
import { collideCircles, collidePolygonCircle, collidePolygons, ContactManifold, type PolygonRef } from '../rigid/collide.js';
import { anchorKey, type RigidContacts } from '../rigid/contacts.js';
import { RigidShapeKind, type RigidShapes } from '../rigid/shapes.js';
import { grown } from '../table.js';

export class RigidNarrowPhase {
  private readonly manifold = new ContactManifold();
  private readonly viewA: PolygonRef = emptyRef();
  private readonly viewB: PolygonRef = emptyRef();
  /** A particle-built convex part, loaded with its edge normals. */
  private readonly frame: PolygonRef = emptyRef();
  /** The current pair's reals: margin, friction, restitution (typed array: no boxed doubles across calls). */
  private readonly pair = new Float64Array(3);
  tests = 0;

  run(pairs: PairList, c: Colliders, shapes: RigidShapes, p: ParticleStore, motion: Float64Array, slop: number, out: RigidContacts): void {
    out.count = 0;
    this.tests = 0;
    for (let k = 0; k < pairs.count; k++) {
      let a = pairs.a[k];
      let b = pairs.b[k];
      const aRigid = c.kind[a] === ColliderKind.Rigid;
      if (!aRigid && c.kind[b] !== ColliderKind.Rigid) continue;
      // Side A is rigid.
      if (!aRigid) {
        const t = a;
        a = b;
        b = t;
      }
      this.pair[0] = motion[a] + motion[b] + slop;
      this.pair[1] = Math.sqrt(c.friction[a] * c.friction[b]);
      this.pair[2] = Math.max(c.restitution[a], c.restitution[b]);
      const kb = c.kind[b];
      if (kb === ColliderKind.Rigid) this.rigidRigid(shapes, p, a, b, out);
      else if (kb === ColliderKind.Polygon) this.rigidFrame(c, shapes, p, a, b, out);
      else if (kb === ColliderKind.Particles) this.rigidParticles(c, shapes, p, a, b, out);
    }
  }

  private rigidRigid(shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const margin = this.pair[0];
    const ia = shapes.row[a];
    const ib = shapes.row[b];
    const ka = shapes.kind[a];
    const kb = shapes.kind[b];
    if (ka === RigidShapeKind.Circle && kb === RigidShapeKind.Circle) {
      this.tests++;
      if (collideCircles(p.x[ia], p.y[ia], shapes.radius[a], p.x[ib], p.y[ib], shapes.radius[b], margin, m)) this.emit(p, ia, ib, a, b, shapes.radius[a], shapes.radius[b], out);
      return;
    }
    if (ka === RigidShapeKind.Circle) {
      for (let q = shapes.partStart[b], qEnd = q + shapes.partCount[b]; q < qEnd; q++) {
        this.tests++;
        shapes.viewPart(q, this.viewB);
        if (collidePolygonCircle(this.viewB, p.x[ia], p.y[ia], shapes.radius[a], true, margin, m)) this.emit(p, ia, ib, a, b, shapes.radius[a], 0, out);
      }
      return;
    }
    for (let q = shapes.partStart[a], qEnd = q + shapes.partCount[a]; q < qEnd; q++) {
      shapes.viewPart(q, this.viewA);
      if (kb === RigidShapeKind.Circle) {
        this.tests++;
        if (collidePolygonCircle(this.viewA, p.x[ib], p.y[ib], shapes.radius[b], false, margin, m)) this.emit(p, ia, ib, a, b, 0, shapes.radius[b], out);
        continue;
      }
      for (let r = shapes.partStart[b], rEnd = r + shapes.partCount[b]; r < rEnd; r++) {
        this.tests++;
        shapes.viewPart(r, this.viewB);
        if (collidePolygons(this.viewA, this.viewB, margin, m)) this.emit(p, ia, ib, a, b, 0, 0, out);
      }
    }
  }

  /** A rigid body against a particle-built outline: B's side of each point is a point on one of its edges. */
  private rigidFrame(c: Colliders, shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const margin = this.pair[0];
    const ia = shapes.row[a];
    const vs = c.vertices;
    for (let r = c.partStart[b], rEnd = r + c.partCount[b]; r < rEnd; r++) {
      const start = c.partVertexStart[r];
      const count = c.partVertexCount[r];
      this.loadFrame(vs, start, count, p);
      if (shapes.kind[a] === RigidShapeKind.Circle) {
        this.tests++;
        if (collidePolygonCircle(this.frame, p.x[ia], p.y[ia], shapes.radius[a], true, margin, m)) this.emitEdges(p, ia, vs, start, count, a, b, shapes.radius[a], out);
        continue;
      }
      for (let q = shapes.partStart[a], qEnd = q + shapes.partCount[a]; q < qEnd; q++) {
        this.tests++;
        shapes.viewPart(q, this.viewA);
        if (collidePolygons(this.viewA, this.frame, margin, m)) this.emitEdges(p, ia, vs, start, count, a, b, 0, out);
      }
    }
  }

  /** A rigid body against each particle of B as a circle of its radius (a point when 0). */
  private rigidParticles(c: Colliders, shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const margin = this.pair[0];
    const ia = shapes.row[a];
    const members = c.particles[b];
    const circle = shapes.kind[a] === RigidShapeKind.Circle;
    for (let k = 0; k < members.length; k++) {
      const ib = members[k];
      const rb = p.radius[ib];
      if (circle) {
        this.tests++;
        if (collideCircles(p.x[ia], p.y[ia], shapes.radius[a], p.x[ib], p.y[ib], rb, margin, m)) this.emit(p, ia, ib, a, b, shapes.radius[a], rb, out);
        continue;
      }
      for (let q = shapes.partStart[a], qEnd = q + shapes.partCount[a]; q < qEnd; q++) {
        this.tests++;
        shapes.viewPart(q, this.viewA);
        if (collidePolygonCircle(this.viewA, p.x[ib], p.y[ib], rb, false, margin, m)) this.emit(p, ia, ib, a, b, 0, rb, out);
      }
    }
  }

  /** Copies a particle-built convex part's vertices into the frame view, with its edges' outward unit normals. */
  private loadFrame(vs: Int32Array, start: number, count: number, p: ParticleStore): void {
    const f = this.frame;
    if (f.x.length < count) {
      f.x = grown(f.x, count);
      f.y = grown(f.y, count);
      f.nx = grown(f.nx, count);
      f.ny = grown(f.ny, count);
    }
    for (let k = 0; k < count; k++) {
      const i = vs[start + k];
      f.x[k] = p.x[i];
      f.y[k] = p.y[i];
    }
    for (let k = 0; k < count; k++) {
      const k2 = k + 1 === count ? 0 : k + 1;
      const ex = f.x[k2] - f.x[k];
      const ey = f.y[k2] - f.y[k];
      const inv = 1 / Math.sqrt(ex * ex + ey * ey);
      f.nx[k] = ey * inv;
      f.ny[k] = -ex * inv;
    }
    f.start = 0;
    f.count = count;
  }

  /** Writes the manifold's points with B's side a point on an edge of the particle-built part. */
  private emitEdges(p: ParticleStore, ia: number, vs: Int32Array, start: number, count: number, a: number, b: number, radA: number, out: RigidContacts): void {
    const m = this.manifold;
    for (let k = 0; k < m.count; k++) {
      const e = m.edgeB[k];
      const i0 = vs[start + e];
      const i1 = vs[start + (e + 1 === count ? 0 : e + 1)];
      this.point(p, k, ia, radA, 0, m.alphaB[k], 0, out);
      out.add(ia, i0, i1, a, b, m.count === 2 && k === 0 ? 1 : 0);
    }
  }

  /** Writes the manifold's points between rows ia and ib (a rigid body or a particle), each side round when radius > 0. */
  private emit(p: ParticleStore, ia: number, ib: number, a: number, b: number, radA: number, radB: number, out: RigidContacts): void {
    const m = this.manifold;
    for (let k = 0; k < m.count; k++) {
      this.point(p, k, ia, radA, radB, 0, anchorKey(a, b, m.feature[k]), out);
      // B's anchor in B's frame (a particle's frame is the world's: cos 1, sin 0).
      const f = out.next;
      const dx = m.pBx[k] - p.x[ib];
      const dy = m.pBy[k] - p.y[ib];
      const cb = p.rc[ib];
      const sb = p.rs[ib];
      f[4] = cb * dx + sb * dy;
      f[5] = -sb * dx + cb * dy;
      out.add(ia, ib, -1, a, b, m.count === 2 && k === 0 ? 1 : 0);
    }
  }

  /** Point k's reals shared by every kind of B into out.next: normal, A's anchor in A's frame, radii, α, material, depth. */
  private point(p: ParticleStore, k: number, ia: number, radA: number, radB: number, alpha: number, key: number, out: RigidContacts): void {
    const m = this.manifold;
    const f = out.next;
    const dx = m.pAx[k] - p.x[ia];
    const dy = m.pAy[k] - p.y[ia];
    const ca = p.rc[ia];
    const sa = p.rs[ia];
    f[0] = m.nx;
    f[1] = m.ny;
    f[2] = ca * dx + sa * dy;
    f[3] = -sa * dx + ca * dy;
    f[4] = 0;
    f[5] = 0;
    f[6] = radA;
    f[7] = radB;
    f[8] = alpha;
    f[9] = this.pair[1];
    f[10] = this.pair[2];
    f[11] = m.depth[k];
    f[12] = key;
  }
}

function emptyRef(): PolygonRef {
  return { x: new Float64Array(8), y: new Float64Array(8), nx: new Float64Array(8), ny: new Float64Array(8), start: 0, count: 0 };
}

/**
 * A rigid body's contacts with the world's bounds (four walls, static, B = the world): every vertex of its parts, or
 * its disc, within the margin of a wall.
 */
export function boundsContacts(bounds: Bounds, shapes: RigidShapes, c: Colliders, p: ParticleStore, motion: Float64Array, slop: number, friction: number, out: RigidContacts): void {
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    if (c.kind[s] !== ColliderKind.Rigid || c.isStatic[s]) continue;
    // Quick reject: the body's grown AABB is inside the walls.
    if (c.minX[s] > bounds.minX && c.maxX[s] < bounds.maxX && c.minY[s] > bounds.minY && c.maxY[s] < bounds.maxY) continue;
    const i = shapes.row[s];
    const margin = motion[s] + slop;
    for (let wall = 0; wall < 4; wall++) {
      // Wall normal from the body (A) into the wall (B), and the wall's line n·q = level.
      const nx = wall === 0 ? -1 : wall === 1 ? 1 : 0;
      const ny = wall === 2 ? -1 : wall === 3 ? 1 : 0;
      const level = wall === 0 ? -bounds.minX : wall === 1 ? bounds.maxX : wall === 2 ? -bounds.minY : bounds.maxY;
      const first = out.count;
      if (shapes.kind[s] === RigidShapeKind.Circle) {
        const r = shapes.radius[s];
        const depth = p.x[i] * nx + p.y[i] * ny + r - level;
        if (depth >= -margin) wallPoint(out, p, i, s, nx, ny, r * nx, r * ny, r, depth, friction, c.restitution[s], wall);
        continue;
      }
      for (let q = shapes.partStart[s], qEnd = q + shapes.partCount[s]; q < qEnd; q++) {
        for (let v = shapes.partVertexStart[q], vEnd = v + shapes.partVertexCount[q]; v < vEnd; v++) {
          const depth = shapes.wx[v] * nx + shapes.wy[v] * ny - level;
          if (depth >= -margin) wallPoint(out, p, i, s, nx, ny, shapes.wx[v] - p.x[i], shapes.wy[v] - p.y[i], 0, depth, friction, c.restitution[s], ((v - shapes.partVertexStart[shapes.partStart[s]]) & 8191) * 4 + wall);
        }
      }
      // Two points on one wall (a box lying on the floor) are solved together in the velocity pass.
      if (out.count - first === 2) out.pair[first] = 1;
    }
  }
}

/**
 * One point of a body (row i, slot s) against a wall with normal n (from the body into the wall): A's point is at
 * world offset (ox, oy) from its centre, `depth` past the wall; the wall's point is A's pushed back onto the wall.
 */
function wallPoint(out: RigidContacts, p: ParticleStore, i: number, s: number, nx: number, ny: number, ox: number, oy: number, radA: number, depth: number, friction: number, restitution: number, feature: number): void {
  const f = out.next;
  const ca = p.rc[i];
  const sa = p.rs[i];
  f[0] = nx;
  f[1] = ny;
  f[2] = ca * ox + sa * oy;
  f[3] = -sa * ox + ca * oy;
  f[4] = p.x[i] + ox - depth * nx;
  f[5] = p.y[i] + oy - depth * ny;
  f[6] = radA;
  f[7] = 0;
  f[8] = 0;
  f[9] = friction;
  f[10] = restitution;
  f[11] = depth;
  f[12] = anchorKey(s, -1, feature);
  out.add(i, -1, -1, s, -1, 0);
}
