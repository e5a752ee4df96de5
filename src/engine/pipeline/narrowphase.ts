import type { ParticleStore } from '../particles.js';
import { ColliderKind, type Colliders } from './colliders.js';
import type { Contacts } from './contacts.js';
import type { PairList } from './broadphase.js';
import { polygonView, type Shape } from '../collision/shape.js';
import { gjkDistance } from '../collision/gjk.js';
import { gjkEpa } from '../collision/epa.js';
import { ClosestPoints, Penetration } from '../collision/results.js';

export type NarrowPhaseMode = 'sat' | 'gjk';

/**
 * Turns candidate body pairs into contact features (vertex–edge, point–point) for the projection solver.
 * Polygon pairs use the separating-axis test (seed Algorithm 2) to find the reference edge; the contact points are
 * the incident edge's vertices over the reference edge, and the reference edge's vertices over the incident edge
 * (the two ends of Box2D's clipped segment, as particle features). Pairs up to `margin` apart give speculative
 * contacts that act only if the gap closes during the step.
 *
 * In 'gjk' mode the normal comes from GJK (the distance of separated parts) or GJK + EPA (the depth of overlapping
 * ones) instead of SAT, and the reference edge is the edge best aligned with it; the contacts are then clipped the
 * same way. The seed's experiment 1 compares the two.
 */
export class NarrowPhase {
  mode: NarrowPhaseMode = 'sat';
  private readonly viewA: Shape = polygonView(new Float64Array(3), new Float64Array(3), Int32Array.of(0, 1, 2));
  private readonly viewB: Shape = polygonView(new Float64Array(3), new Float64Array(3), Int32Array.of(0, 1, 2));
  private readonly closest = new ClosestPoints();
  private readonly penetration = new Penetration();
  /** Candidate pair tests and contacts of the last run (for the seed's experiment 1 and the stats overlay). */
  tests = 0;
  private edge = 0;

  private slop = 0.02;

  run(pairs: PairList, c: Colliders, p: ParticleStore, motion: Float64Array, slop: number, out: Contacts): void {
    out.count = 0;
    this.slop = slop;
    this.tests = 0;
    for (let k = 0; k < pairs.count; k++) {
      let a = pairs.a[k];
      let b = pairs.b[k];
      // A pair with a rigid body is the rigid narrow phase's (rigid-narrowphase.ts).
      if (c.kind[a] === ColliderKind.Rigid || c.kind[b] === ColliderKind.Rigid) continue;
      // Polygons first: a polygon body is always A when paired with a particle body.
      if (c.kind[a] === ColliderKind.Particles && c.kind[b] === ColliderKind.Polygon) {
        const t = a;
        a = b;
        b = t;
      }
      // The pair's reals go by typed arrays, not arguments: doubles passed to a call that is not inlined are boxed.
      this.margin[0] = motion[a] + motion[b] + slop;
      out.next[1] = Math.sqrt(c.friction[a] * c.friction[b]);
      out.next[2] = Math.max(c.restitution[a], c.restitution[b]);
      const ka = c.kind[a];
      const kb = c.kind[b];
      if (ka === ColliderKind.Polygon && kb === ColliderKind.Polygon) {
        for (let i = c.partStart[a], iEnd = i + c.partCount[a]; i < iEnd; i++) {
          for (let j = c.partStart[b], jEnd = j + c.partCount[b]; j < jEnd; j++) {
            this.polygons(c, p, i, j, a, b, out);
          }
        }
      } else if (ka === ColliderKind.Polygon) {
        const particles = c.particles[b];
        for (let q = 0; q < particles.length; q++) {
          const v = particles[q];
          for (let i = c.partStart[a], iEnd = i + c.partCount[a]; i < iEnd; i++) this.circlePolygon(c, p, i, v, a, b, out);
        }
      } else {
        const pa = c.particles[a];
        const pb = c.particles[b];
        for (let q = 0; q < pa.length; q++) for (let r = 0; r < pb.length; r++) this.circles(p, pa[q], pb[r], a, b, out, false);
      }
    }
  }

  /**
   * The largest over A's edges of the smallest signed distance of B's vertices to that edge, into this.separation[0];
   * the edge in this.edge. (Not returned: a non-inlined call would box the double on every pair test.)
   */
  private maxSeparation(vs: Int32Array, aStart: number, aCount: number, bStart: number, bCount: number, x: Float64Array, y: Float64Array): void {
    let best = -Infinity;
    let bestEdge = 0;
    for (let i = 0; i < aCount; i++) {
      const i0 = vs[aStart + i];
      const i1 = vs[aStart + (i + 1 === aCount ? 0 : i + 1)];
      const ex = x[i1] - x[i0];
      const ey = y[i1] - y[i0];
      const inv = 1 / Math.sqrt(ex * ex + ey * ey);
      const nx = ey * inv;
      const ny = -ex * inv;
      let min = Infinity;
      for (let j = 0; j < bCount; j++) {
        const q = vs[bStart + j];
        const d = (x[q] - x[i0]) * nx + (y[q] - y[i0]) * ny;
        if (d < min) min = d;
      }
      if (min > best) {
        best = min;
        bestEdge = i;
      }
    }
    this.edge = bestEdge;
    this.separation[0] = best;
  }

  private readonly separation = new Float64Array(1);
  /** The current pair's contact margin (see run). */
  private readonly margin = new Float64Array(1);
  private edgeA = 0;
  private edgeB = 0;
  private flip = false;

  /** SAT: the reference edge is the axis of least penetration (or largest gap). False when apart by > margin. */
  private satReference(vs: Int32Array, aStart: number, aCount: number, bStart: number, bCount: number, x: Float64Array, y: Float64Array): boolean {
    const margin = this.margin[0];
    this.maxSeparation(vs, aStart, aCount, bStart, bCount, x, y);
    const sepA = this.separation[0];
    if (sepA > margin) return false;
    this.edgeA = this.edge;
    this.maxSeparation(vs, bStart, bCount, aStart, aCount, x, y);
    const sepB = this.separation[0];
    if (sepB > margin) return false;
    this.edgeB = this.edge;
    // Prefer A's edge unless B's is clearly better, so the choice does not flip between steps on near-ties
    // (stacked equal boxes tie exactly) and the contacts, with their friction anchors, persist.
    this.flip = sepB > sepA + 0.1 * this.slop;
    return true;
  }

  /** GJK: the normal from the distance (apart) or EPA (overlapping), then the edges best aligned with it. */
  private gjkReference(vs: Int32Array, aStart: number, aCount: number, bStart: number, bCount: number, x: Float64Array, y: Float64Array): boolean {
    const margin = this.margin[0];
    const va = this.viewA;
    const vb = this.viewB;
    va.xs = vb.xs = x;
    va.ys = vb.ys = y;
    va.index = vb.index = vs;
    va.offset = aStart;
    va.count = aCount;
    vb.offset = bStart;
    vb.count = bCount;
    let nx: number;
    let ny: number;
    const distance = gjkDistance(va, vb, this.closest);
    // At (almost) zero distance the closest points give no trustworthy direction: treat that as touching.
    if (distance > 1e-9) {
      if (distance > margin) return false;
      nx = this.closest.normalX;
      ny = this.closest.normalY;
    } else if (gjkEpa(va, vb, this.penetration)) {
      nx = this.penetration.normalX;
      ny = this.penetration.normalY;
    } else {
      // Touching exactly, with no direction to go by: SAT decides.
      return this.satReference(vs, aStart, aCount, bStart, bCount, x, y);
    }
    const alignA = this.bestAligned(vs, aStart, aCount, x, y, nx, ny);
    this.edgeA = this.edge;
    const alignB = this.bestAligned(vs, bStart, bCount, x, y, -nx, -ny);
    this.edgeB = this.edge;
    this.flip = alignB > alignA + 1e-3;
    return true;
  }

  /** The edge whose outward normal is closest to (nx, ny), in this.edge; returns the cosine. */
  private bestAligned(vs: Int32Array, start: number, count: number, x: Float64Array, y: Float64Array, nx: number, ny: number): number {
    let best = -Infinity;
    for (let i = 0; i < count; i++) {
      const i0 = vs[start + i];
      const i1 = vs[start + (i + 1 === count ? 0 : i + 1)];
      const ex = x[i1] - x[i0];
      const ey = y[i1] - y[i0];
      const cos = (ey * nx - ex * ny) / Math.sqrt(ex * ex + ey * ey);
      if (cos > best) {
        best = cos;
        this.edge = i;
      }
    }
    return best;
  }

  private polygons(c: Colliders, p: ParticleStore, partA: number, partB: number, bodyA: number, bodyB: number, out: Contacts): void {
    this.tests++;
    const margin = this.margin[0];
    const f = out.next;
    f[0] = 0;
    const vs = c.vertices;
    const { x, y } = p;
    const aStart = c.partVertexStart[partA];
    const aCount = c.partVertexCount[partA];
    const bStart = c.partVertexStart[partB];
    const bCount = c.partVertexCount[partB];
    const found = this.mode === 'gjk' ? this.gjkReference(vs, aStart, aCount, bStart, bCount, x, y) : this.satReference(vs, aStart, aCount, bStart, bCount, x, y);
    if (!found) return;
    const flip = this.flip;
    const edgeA = this.edgeA;
    const edgeB = this.edgeB;
    const refStart = flip ? bStart : aStart;
    const refCount = flip ? bCount : aCount;
    const incStart = flip ? aStart : bStart;
    const incCount = flip ? aCount : bCount;
    const refEdge = flip ? edgeB : edgeA;
    const refBody = flip ? bodyB : bodyA;
    const incBody = flip ? bodyA : bodyB;
    const r0 = vs[refStart + refEdge];
    const r1 = vs[refStart + (refEdge + 1 === refCount ? 0 : refEdge + 1)];
    const rex = x[r1] - x[r0];
    const rey = y[r1] - y[r0];
    const rlen = Math.sqrt(rex * rex + rey * rey);
    const tx = rex / rlen;
    const ty = rey / rlen;
    const nx = ty;
    const ny = -tx;
    // Incident edge: the one whose normal is most opposed to the reference normal.
    let incEdge = 0;
    let most = Infinity;
    for (let j = 0; j < incCount; j++) {
      const j0 = vs[incStart + j];
      const j1 = vs[incStart + (j + 1 === incCount ? 0 : j + 1)];
      const ex = x[j1] - x[j0];
      const ey = y[j1] - y[j0];
      const dot = (ey * nx - ex * ny) / Math.sqrt(ex * ex + ey * ey);
      if (dot < most) {
        most = dot;
        incEdge = j;
      }
    }
    const q0 = vs[incStart + incEdge];
    const q1 = vs[incStart + (incEdge + 1 === incCount ? 0 : incEdge + 1)];
    // The normal reported for events points from A to B.
    const snx = flip ? -nx : nx;
    const sny = flip ? -ny : ny;
    // Clip the incident edge to the reference edge's extent (Box2D's two clip points, as particle features): an
    // incident vertex within the extent touches the reference edge; one beyond it is replaced by the reference
    // corner it was clipped at, which touches the incident edge. Two contacts, no gap, no duplicate.
    const tolerance = 1e-4 * rlen;
    let lastCorner = -1;
    for (let k = 0; k < 2; k++) {
      const q = k === 0 ? q0 : q1;
      const along = (x[q] - x[r0]) * tx + (y[q] - y[r0]) * ty;
      if (along >= -tolerance && along <= rlen + tolerance) {
        const sep = (x[q] - x[r0]) * nx + (y[q] - y[r0]) * ny;
        if (sep <= margin) {
          f[3] = snx;
          f[4] = sny;
          f[5] = -sep;
          out.add(q, r0, r1, refBody, incBody);
        }
        continue;
      }
      const corner = along < 0 ? r0 : r1;
      if (corner === lastCorner) continue;
      lastCorner = corner;
      const qex = x[q1] - x[q0];
      const qey = y[q1] - y[q0];
      const qlen2 = qex * qex + qey * qey;
      const qinv = 1 / Math.sqrt(qlen2);
      const alpha = ((x[corner] - x[q0]) * qex + (y[corner] - y[q0]) * qey) / qlen2;
      if (alpha < 0 || alpha > 1) continue;
      const sep = ((x[corner] - x[q0]) * qey - (y[corner] - y[q0]) * qex) * qinv;
      if (sep <= margin) {
        f[3] = -snx;
        f[4] = -sny;
        f[5] = -sep;
        out.add(corner, q0, q1, incBody, refBody);
      }
    }
    // A body closing faster than about half its size per step could bring its other vertices through the reference
    // edge before its frame catches up: give them speculative contacts too.
    if (margin > 0.5 * Math.sqrt((x[q1] - x[q0]) ** 2 + (y[q1] - y[q0]) ** 2)) {
      for (let j = 0; j < incCount; j++) {
        const q = vs[incStart + j];
        if (q === q0 || q === q1) continue;
        const along = (x[q] - x[r0]) * tx + (y[q] - y[r0]) * ty;
        const sep = (x[q] - x[r0]) * nx + (y[q] - y[r0]) * ny;
        if (along >= 0 && along <= rlen && sep <= margin) {
          f[3] = snx;
          f[4] = sny;
          f[5] = -sep;
          out.add(q, r0, r1, refBody, incBody);
        }
      }
    }
  }

  /** A particle with a radius against a convex part: an edge contact in an edge's region, a corner contact otherwise. */
  private circlePolygon(c: Colliders, p: ParticleStore, part: number, v: number, bodyA: number, bodyB: number, out: Contacts): void {
    this.tests++;
    const margin = this.margin[0];
    const vs = c.vertices;
    const { x, y, radius } = p;
    const start = c.partVertexStart[part];
    const count = c.partVertexCount[part];
    const r = radius[v];
    let best = -Infinity;
    let bestEdge = 0;
    for (let i = 0; i < count; i++) {
      const i0 = vs[start + i];
      const i1 = vs[start + (i + 1 === count ? 0 : i + 1)];
      const ex = x[i1] - x[i0];
      const ey = y[i1] - y[i0];
      const d = ((x[v] - x[i0]) * ey - (y[v] - y[i0]) * ex) / Math.sqrt(ex * ex + ey * ey);
      if (d > best) {
        best = d;
        bestEdge = i;
      }
    }
    if (best - r > margin) return;
    const i0 = vs[start + bestEdge];
    const i1 = vs[start + (bestEdge + 1 === count ? 0 : bestEdge + 1)];
    const ex = x[i1] - x[i0];
    const ey = y[i1] - y[i0];
    const len2 = ex * ex + ey * ey;
    const alpha = ((x[v] - x[i0]) * ex + (y[v] - y[i0]) * ey) / len2;
    if (best <= 0 || (alpha >= 0 && alpha <= 1)) {
      const inv = 1 / Math.sqrt(len2);
      const f = out.next;
      f[0] = r;
      f[3] = ey * inv;
      f[4] = -ex * inv;
      f[5] = r - best;
      out.add(v, i0, i1, bodyA, bodyB);
      return;
    }
    const corner = alpha < 0 ? i0 : i1;
    this.circles(p, corner, v, bodyA, bodyB, out, true);
  }

  /**
   * Two particles kept their radii summed apart, or b's radius alone when a is a polygon's corner. Point–point
   * contact: v = b's, e0 = a's.
   */
  private circles(p: ParticleStore, ia: number, ib: number, bodyA: number, bodyB: number, out: Contacts, corner: boolean): void {
    this.tests++;
    const { x, y } = p;
    const margin = this.margin[0];
    const r = corner ? p.radius[ib] : p.radius[ia] + p.radius[ib];
    const dx = x[ib] - x[ia];
    const dy = y[ib] - y[ia];
    const reach = r + margin;
    const d2 = dx * dx + dy * dy;
    if (d2 > reach * reach) return;
    const d = Math.sqrt(d2);
    const nx = d > 1e-12 ? dx / d : 0;
    const ny = d > 1e-12 ? dy / d : -1;
    const f = out.next;
    f[0] = r;
    f[3] = nx;
    f[4] = ny;
    f[5] = r - d;
    out.add(ib, ia, -1, bodyA, bodyB);
  }
}
