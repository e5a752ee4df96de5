// The narrow phase for pairs with a rigid body on at least one side, and a rigid body's contacts with the world's
// bounds: manifolds in world coordinates (rigid/collide.ts) turned into contact points with material anchors in
// each body's frame (rigid/contacts.ts). Pairs of particle-built bodies go to the particle narrow phase instead.
import type { ParticleStore } from '../particles.js';
import type { Bounds } from '../bounds.js';
import { ColliderKind, type Colliders } from './colliders.js';
import { partnerMotions, type PairList } from './broadphase.js';
import { collideCircles, collidePolygonCircle, collidePolygons, ContactManifold, type PolygonRef } from '../rigid/collide.js';
import { writeAnchorKey, type RigidContacts } from '../rigid/contacts.js';
import { RigidShapeKind, type RigidShapes } from '../rigid/shapes.js';
import { grown } from '../table.js';

export class RigidNarrowPhase {
  private readonly manifold = new ContactManifold();
  private readonly viewA: PolygonRef = emptyRef();
  private readonly viewB: PolygonRef = emptyRef();
  /** A particle-built convex part, loaded with its edge normals. */
  private readonly frame: PolygonRef = emptyRef();
  /**
   * The current pair's reals (a typed array: no boxed doubles across calls): friction, restitution, then A's and B's
   * radius for the points being written (0: not round). The margin goes in the manifold's query.
   */
  private readonly pair = new Float64Array(4);
  tests = 0;

  run(pairs: PairList, c: Colliders, shapes: RigidShapes, p: ParticleStore, motion: Float64Array, slop: number, out: RigidContacts): void {
    out.count = 0;
    this.tests = 0;
    // Pairs with a static side are written after the others, so the solver's sweep (in this order) ends on them:
    // the last word in a Gauss–Seidel sweep goes to the wall, and a light body pressed into it by a heavier one is
    // put back out each substep (a disc hit by a box 10× its mass at 500 units/s went through a wall 1 thick; a
    // particle-built hammer 100× heavier drove it through at 100 units/s). Box2D v3 solves static contacts last too.
    // The first pass lists the pairs with a static side (staticPairs) for the second, which then reads only them.
    if (staticPairs.length < pairs.count) staticPairs = new Int32Array(pairs.a.length);
    prefillDiscRows(out, pairs.count);
    let staticCount = 0;
    for (let pass = 0; pass < 2; pass++) for (let q = 0, end = pass === 0 ? pairs.count : staticCount; q < end; q++) {
      // A run of disc pairs (a pile's, but for the walls) in one loop of its own; the loop below takes the others.
      const first = q;
      q = discPairs(pairs, pass === 0 ? null : staticPairs, q, end, c, slop, out);
      while (discTableFull) {
        out.reserve(1);
        q = discPairs(pairs, pass === 0 ? null : staticPairs, q, end, c, slop, out);
      }
      this.tests += q - first;
      if (q === end) break;
      const k = pass === 0 ? q : staticPairs[q];
      let a = pairs.a[k];
      let b = pairs.b[k];
      if (pass === 0 && (c.isStatic[a] | c.isStatic[b]) !== 0) {
        staticPairs[staticCount++] = k;
        continue;
      }
      const aRigid = c.kind[a] === ColliderKind.Rigid;
      if (!aRigid && c.kind[b] !== ColliderKind.Rigid) continue;
      // Side A is rigid.
      if (!aRigid) {
        const t = a;
        a = b;
        b = t;
      }
      const kb = c.kind[b];
      this.margin(motion, a, b, slop);
      this.pair[0] = Math.sqrt(c.friction[a] * c.friction[b]);
      this.pair[1] = Math.max(c.restitution[a], c.restitution[b]);
      if (kb === ColliderKind.Rigid) this.rigidRigid(shapes, p, a, b, out);
      else if (kb === ColliderKind.Polygon) this.rigidFrame(c, shapes, p, a, b, out);
      else if (kb === ColliderKind.Particles) this.rigidParticles(c, shapes, p, a, b, out);
    }
  }

  /** The manifold's query margin: both bodies' motion this step and the contact slop. */
  private margin(motion: Float64Array, a: number, b: number, slop: number): void {
    this.manifold.query[0] = motion[a] + motion[b] + slop;
  }

  /** The circle of body slot s (row i) as the manifold's query circle at `at` (1: A's, 4: B's in collideCircles). */
  private circle(shapes: RigidShapes, p: ParticleStore, s: number, i: number, at: number): void {
    const q = this.manifold.query;
    q[at] = p.x[i];
    q[at + 1] = p.y[i];
    q[at + 2] = shapes.radius[s];
  }

  private rigidRigid(shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const ia = shapes.row[a];
    const ib = shapes.row[b];
    const ka = shapes.kind[a];
    const kb = shapes.kind[b];
    this.pair[2] = ka === RigidShapeKind.Circle ? shapes.radius[a] : 0;
    this.pair[3] = kb === RigidShapeKind.Circle ? shapes.radius[b] : 0;
    if (ka === RigidShapeKind.Circle && kb === RigidShapeKind.Circle) {
      this.tests++;
      this.circle(shapes, p, a, ia, 1);
      this.circle(shapes, p, b, ib, 4);
      if (collideCircles(m)) this.emit(p, ia, ib, a, b, out);
      return;
    }
    if (ka === RigidShapeKind.Circle) {
      this.circle(shapes, p, a, ia, 1);
      this.sweep(p, ia, ib, shapes.radius[a]);
      for (let q = shapes.partStart[b], qEnd = q + shapes.partCount[b]; q < qEnd; q++) {
        this.tests++;
        shapes.viewPart(q, this.viewB);
        if (collidePolygonCircle(this.viewB, true, m)) this.emit(p, ia, ib, a, b, out);
      }
      m.query[9] = 0;
      return;
    }
    if (kb === RigidShapeKind.Circle) {
      this.circle(shapes, p, b, ib, 1);
      this.sweep(p, ib, ia, shapes.radius[b]);
    }
    for (let q = shapes.partStart[a], qEnd = q + shapes.partCount[a]; q < qEnd; q++) {
      shapes.viewPart(q, this.viewA);
      if (kb === RigidShapeKind.Circle) {
        this.tests++;
        if (collidePolygonCircle(this.viewA, false, m)) this.emit(p, ia, ib, a, b, out);
        continue;
      }
      for (let r = shapes.partStart[b], rEnd = r + shapes.partCount[b]; r < rEnd; r++) {
        this.tests++;
        shapes.viewPart(r, this.viewB);
        if (collidePolygons(this.viewA, this.viewB, m)) this.emit(p, ia, ib, a, b, out);
      }
    }
    m.query[9] = 0;
  }

  /**
   * The query's sweep for a rigid disc (row `disc`, radius r) against a rigid polygon (row `polygon`): the disc's
   * velocity relative to the polygon's, over LOOKAHEAD_STEPS, unless the polygon turns more than 0.1 rad in that time
   * (its corners do not move straight) or the disc closes in too slowly to matter (SLOW_TURN: a disc at rest on a floor).
   */
  private sweep(p: ParticleStore, disc: number, polygon: number, r: number): void {
    const q = this.manifold.query;
    const reach = LOOKAHEAD_STEPS * discRecords.dt[0];
    const vx = p.vx[disc] - p.vx[polygon];
    const vy = p.vy[disc] - p.vy[polygon];
    const turn = p.omega[polygon] * reach;
    q[7] = vx;
    q[8] = vy;
    q[9] = turn * turn <= 0.01 && (vx * vx + vy * vy) * reach * reach > SLOW_TURN * SLOW_TURN * r * r ? reach : 0;
  }

  /** A rigid body against a particle-built outline: B's side of each point is a point on one of its edges. */
  private rigidFrame(c: Colliders, shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const ia = shapes.row[a];
    const vs = c.vertices;
    const round = shapes.kind[a] === RigidShapeKind.Circle;
    this.pair[2] = round ? shapes.radius[a] : 0;
    this.pair[3] = 0;
    if (round) this.circle(shapes, p, a, ia, 1);
    for (let r = c.partStart[b], rEnd = r + c.partCount[b]; r < rEnd; r++) {
      const start = c.partVertexStart[r];
      const count = c.partVertexCount[r];
      this.loadFrame(vs, start, count, p);
      if (round) {
        this.tests++;
        if (collidePolygonCircle(this.frame, true, m)) this.emitEdges(p, ia, vs, start, count, a, b, out);
        continue;
      }
      for (let q = shapes.partStart[a], qEnd = q + shapes.partCount[a]; q < qEnd; q++) {
        this.tests++;
        shapes.viewPart(q, this.viewA);
        if (collidePolygons(this.viewA, this.frame, m)) this.emitEdges(p, ia, vs, start, count, a, b, out);
      }
    }
  }

  /** A rigid body against each particle of B as a circle of its radius (a point when 0). */
  private rigidParticles(c: Colliders, shapes: RigidShapes, p: ParticleStore, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const q = m.query;
    const ia = shapes.row[a];
    const members = c.particles[b];
    const round = shapes.kind[a] === RigidShapeKind.Circle;
    this.pair[2] = round ? shapes.radius[a] : 0;
    if (round) this.circle(shapes, p, a, ia, 1);
    for (let k = 0; k < members.length; k++) {
      const ib = members[k];
      this.pair[3] = p.radius[ib];
      if (round) {
        this.tests++;
        q[4] = p.x[ib];
        q[5] = p.y[ib];
        q[6] = p.radius[ib];
        if (collideCircles(m)) this.emit(p, ia, ib, a, b, out);
        continue;
      }
      q[1] = p.x[ib];
      q[2] = p.y[ib];
      q[3] = p.radius[ib];
      for (let part = shapes.partStart[a], end = part + shapes.partCount[a]; part < end; part++) {
        this.tests++;
        shapes.viewPart(part, this.viewA);
        if (collidePolygonCircle(this.viewA, false, m)) this.emit(p, ia, ib, a, b, out);
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
  private emitEdges(p: ParticleStore, ia: number, vs: Int32Array, start: number, count: number, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    for (let k = 0; k < m.count; k++) {
      const e = m.edgeB[k];
      this.point(p, k, ia, a, -1, out);
      out.next[8] = m.alphaB[k];
      out.add(ia, vs[start + e], vs[start + (e + 1 === count ? 0 : e + 1)], a, b, m.count === 2 && k === 0 ? 1 : 0);
    }
  }

  /**
   * Writes the manifold's points between rows ia and ib (a rigid body or a particle), round sides per pair[2, 3],
   * straight into the columns (the values RigidContacts.add writes from `next` after point(), without that round trip).
   * B's anchor is in B's frame (a particle's frame is the world's: cos 1, sin 0).
   */
  private emit(p: ParticleStore, ia: number, ib: number, a: number, b: number, out: RigidContacts): void {
    const m = this.manifold;
    const pr = this.pair;
    const n = m.count;
    if (out.count + n > out.a.length) out.reserve(n);
    out.shockReady = false;
    const nx = m.nx;
    const ny = m.ny;
    const xa = p.x[ia];
    const ya = p.y[ia];
    const xb = p.x[ib];
    const yb = p.y[ib];
    const ca = p.rc[ia];
    const sa = p.rs[ia];
    const cb = p.rc[ib];
    const sb = p.rs[ib];
    for (let k = 0; k < n; k++) {
      const i = out.count++;
      const dax = m.pAx[k] - xa;
      const day = m.pAy[k] - ya;
      const dbx = m.pBx[k] - xb;
      const dby = m.pBy[k] - yb;
      const depth = m.depth[k];
      out.a[i] = ia;
      out.b[i] = ib;
      out.b2[i] = -1;
      out.nx[i] = nx;
      out.ny[i] = ny;
      out.rAx[i] = ca * dax + sa * day;
      out.rAy[i] = -sa * dax + ca * day;
      out.rBx[i] = cb * dbx + sb * dby;
      out.rBy[i] = -sb * dbx + cb * dby;
      out.radA[i] = pr[2];
      out.radB[i] = pr[3];
      out.alpha[i] = 0;
      out.friction[i] = pr[0];
      out.restitution[i] = pr[1];
      out.depth[i] = depth;
      out.allowance[i] = depth > 0 ? depth : 0;
      out.lambdaN[i] = 0;
      out.impulseN[i] = 0;
      out.impulseT[i] = 0;
      out.slip[i] = 0;
      out.approach[i] = NaN;
      out.touched[i] = 0;
      out.pair[i] = n === 2 && k === 0 ? 1 : 0;
      out.bodyA[i] = a;
      out.bodyB[i] = b;
      out.gap[i] = depth;
      // writeAnchorKey(…, a, b, feature): b is a body slot here.
      const key = (a * 4194304 + b) * 65536 + m.feature[k];
      out.feature[i] = key < 9007199254740991 ? key : key % 9007199254740991;
    }
  }

  /**
   * Point k's reals into out.next: normal, A's anchor in A's frame, A's radius, material, depth, and the feature key
   * its friction anchors persist by (b −1: a particle-built part's edge point, whose anchors are not kept).
   */
  private point(p: ParticleStore, k: number, ia: number, a: number, b: number, out: RigidContacts): void {
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
    f[6] = this.pair[2];
    f[7] = 0;
    f[8] = 0;
    f[9] = this.pair[0];
    f[10] = this.pair[1];
    f[11] = m.depth[k];
    if (b >= 0) writeAnchorKey(f, a, b, m.feature[k]);
    else f[12] = 0;
  }
}

/**
 * The pairs from q on (pair order[q], or q itself when order is null) while both sides are rigid discs, and moving
 * when order is null (the first pass leaves the pairs with a static side for the second, which lists them in order):
 * each pair within reach gets its one point written straight into `out`, without the manifold, with the same
 * arithmetic as collideCircles followed by emit (the same doubles, so results do not change), and the pair's friction
 * and restitution. One loop with the columns in locals (a pile's 27,000 pairs), reading each side's record in
 * discRecords (one cache line a body, written with the AABBs); returns the first pair it did not take.
 */
function discPairs(pairs: PairList, order: Int32Array | null, q: number, end: number, c: Colliders, slop: number, out: RigidContacts): number {
  const pairA = pairs.a;
  const pairB = pairs.b;
  const isStatic = c.isStatic;
  const discs = discRecords.data;
  const colA = out.a;
  const colB = out.b;
  const colNx = out.nx;
  const colNy = out.ny;
  const colRAx = out.rAx;
  const colRAy = out.rAy;
  const colRBx = out.rBx;
  const colRBy = out.rBy;
  const colRadA = out.radA;
  const colRadB = out.radB;
  const colFriction = out.friction;
  const colRestitution = out.restitution;
  const colDepth = out.depth;
  const colAllowance = out.allowance;
  const colBodyA = out.bodyA;
  const colBodyB = out.bodyB;
  const colGap = out.gap;
  const colFeature = out.feature;
  const restitution = c.restitution;
  const memo = frictionMemo;
  const count0 = out.count;
  // The table grows only at a new high of points, as add() grows it: when full, the caller grows it and calls again.
  const capacity = colA.length;
  let i = count0;
  discTableFull = false;
  for (; q < end; q++) {
    const k = order === null ? q : order[q];
    const a = pairA[k];
    const b = pairB[k];
    // Each side's record (discRecords): centre, radius (−1: not a rigid disc), motion, rotation, friction, row.
    const oa = 8 * a;
    const ob = 8 * b;
    const ra = discs[oa + 2];
    const rb = discs[ob + 2];
    if (ra < 0 || rb < 0 || (order === null && (isStatic[a] | isStatic[b]) !== 0)) break;
    const ax = discs[oa];
    const ay = discs[oa + 1];
    const bx = discs[ob];
    const by = discs[ob + 1];
    const dx = bx - ax;
    const dy = by - ay;
    const reach = ra + rb + (discs[oa + 3] + discs[ob + 3] + slop);
    const d2 = dx * dx + dy * dy;
    if (d2 > reach * reach) continue;
    if (i === capacity) {
      discTableFull = true;
      break;
    }
    const d = Math.sqrt(d2);
    let nx = d > 1e-12 ? dx / d : 0;
    let ny = d > 1e-12 ? dy / d : -1;
    let depth = ra + rb - d;
    if (depth < 0) {
      // Apart, within reach: the normal is the line of centres where they will touch, not where they are. Until the
      // step's substeps bring them together the centres move on, and a fast glancing hit (60 units/s, discs 1 across)
      // pushed along today's line of centres left up to 30° off the line it meets on. Straight motion at the step's
      // velocities (gravity is the same for both, unless one side is static): |d + v·t| = ra + rb at the first t.
      const rowA = discs[oa + 7] | 0;
      const rowB = discs[ob + 7] | 0;
      const vx = discRecords.vx[rowB] - discRecords.vx[rowA];
      const vy = discRecords.vy[rowB] - discRecords.vy[rowA];
      const along = dx * vx + dy * vy;
      const v2 = vx * vx + vy * vy;
      // Closing in so slowly that the line of centres turns by less than SLOW_TURN over the look-ahead (a pile at
      // rest): it stays as it is, without the square roots.
      const ahead = LOOKAHEAD_STEPS * discRecords.dt[0];
      if (along < 0 && v2 * ahead * ahead > SLOW_TURN * SLOW_TURN * (ra + rb) * (ra + rb)) {
        const reachSq = d2 - (ra + rb) * (ra + rb);
        const discriminant = along * along - v2 * reachSq;
        if (discriminant >= 0) {
          // The smaller root, in the form that needs no division by |v|² (which may be 0). Past the look-ahead (a
          // resting pair barely closing in) the line of centres now stays.
          const t = reachSq / (Math.sqrt(discriminant) - along);
          const hx = dx + vx * t;
          const hy = dy + vy * t;
          const h = Math.sqrt(hx * hx + hy * hy);
          if (t <= ahead && h > 1e-12) {
            nx = hx / h;
            ny = hy / h;
            // The gap along that normal, as the solver measures it: (ra + rb) − (centre B − centre A)·n.
            depth = ra + rb - (dx * nx + dy * ny);
          }
        }
      }
    }
    // The contact points on each disc, then their offsets from the centres turned into each body's frame.
    const aX = ax + ra * nx - ax;
    const aY = ay + ra * ny - ay;
    const bX = bx - rb * nx - bx;
    const bY = by - rb * ny - by;
    const ca = discs[oa + 4];
    const sa = discs[oa + 5];
    const cb = discs[ob + 4];
    const sb = discs[ob + 5];
    colA[i] = discs[oa + 7];
    colB[i] = discs[ob + 7];
    colNx[i] = nx;
    colNy[i] = ny;
    colRAx[i] = ca * aX + sa * aY;
    colRAy[i] = -sa * aX + ca * aY;
    colRBx[i] = cb * bX + sb * bY;
    colRBy[i] = -sb * bX + cb * bY;
    colRadA[i] = ra;
    colRadB[i] = rb;
    // The pair's friction, sqrt(μa·μb): a pile's discs mostly share one material, so the last pair's root is reused
    // for the same two values (a non-zero root only: the same double either way, signs of zero included).
    const fa = discs[oa + 6];
    const fb = discs[ob + 6];
    if (fa !== memo[0] || fb !== memo[1] || memo[2] === 0) {
      memo[0] = fa;
      memo[1] = fb;
      memo[2] = Math.sqrt(fa * fb);
    }
    colFriction[i] = memo[2];
    colRestitution[i] = Math.max(restitution[a], restitution[b]);
    colDepth[i] = depth;
    colAllowance[i] = depth > 0 ? depth : 0;
    if (i >= prefilled) writeDiscConstants(out, i);
    colBodyA[i] = a;
    colBodyB[i] = b;
    colGap[i] = depth;
    // writeAnchorKey(…, a, b, 0): b ≥ 0 here.
    const key = (a * 4194304 + b) * 65536;
    colFeature[i] = key < 9007199254740991 ? key : key % 9007199254740991;
    i++;
  }
  if (i > count0) {
    out.count = i;
    out.shockReady = false;
  }
  return q;
}

/**
 * Per body slot, 8 reals written with its AABB each step (updateBoundingBoxes) for discPairs, which then reads one
 * cache line a body instead of a dozen columns: x, y (its row's centre), radius (−1: not a rigid disc), motion (as the
 * step's `motion`, grown bodies included), cos, sin (its row's rotation), friction, row. Scratch of a detection.
 */
export const discRecords = {
  data: new Float64Array(128),
  /** The rows' velocity columns and the step's dt, for the normal of a disc pair apart. */
  vx: new Float64Array(0),
  vy: new Float64Array(0),
  dt: new Float64Array(1),
};

/**
 * How far ahead (in steps) a disc found apart is followed on its straight path to where it will touch (discPairs,
 * RigidNarrowPhase.sweep): about a step is where the straight path holds; two leave room for gravity's pull on a ball
 * against a static body, which the path leaves out.
 */
const LOOKAHEAD_STEPS = 2;

/** A pair closing in too slowly to turn its contact normal by this much (rad) over the look-ahead keeps it as found. */
const SLOW_TURN = 1e-3;

/** Set by discPairs when it stopped at a pair within reach because the table is full. */
let discTableFull = false;

/**
 * Rows [0, prefilled) of the contact columns hold a disc row's constant columns (b2 −1, no alpha, no impulses, no
 * slip, approach NaN, untouched, single point), filled for the whole range at the start of the narrow phase (a
 * memset each) instead of nine stores per disc pair in discPairs(). Every other writer of a row writes these columns
 * itself, so the prefill never shows in its rows.
 */
let prefilled = 0;

/** Fills the disc rows' constant columns for the first min(rows, capacity) rows (see `prefilled`). */
function prefillDiscRows(out: RigidContacts, rows: number): void {
  const n = rows < out.a.length ? rows : out.a.length;
  out.b2.fill(-1, 0, n);
  out.alpha.fill(0, 0, n);
  out.lambdaN.fill(0, 0, n);
  out.impulseN.fill(0, 0, n);
  out.impulseT.fill(0, 0, n);
  out.slip.fill(0, 0, n);
  out.approach.fill(NaN, 0, n);
  out.touched.fill(0, 0, n);
  out.pair.fill(0, 0, n);
  prefilled = n;
}

/** A disc row's constant columns for row i (past the prefilled rows). */
function writeDiscConstants(out: RigidContacts, i: number): void {
  out.b2[i] = -1;
  out.alpha[i] = 0;
  out.lambdaN[i] = 0;
  out.impulseN[i] = 0;
  out.impulseT[i] = 0;
  out.slip[i] = 0;
  out.approach[i] = NaN;
  out.touched[i] = 0;
  out.pair[i] = 0;
}

/** The disc pairs' last friction values μa, μb and their root (discPairs()). */
const frictionMemo = new Float64Array([NaN, NaN, 0]);

/** Indices into the pair list of the pairs with a static side, in order (scratch of RigidNarrowPhase.run). */
let staticPairs = new Int32Array(256);

function emptyRef(): PolygonRef {
  return { x: new Float64Array(8), y: new Float64Array(8), nx: new Float64Array(8), ny: new Float64Array(8), start: 0, count: 0, internal: null };
}

/**
 * A rigid body's contacts with the world's bounds (four walls, static, B = the world): every vertex of its parts, or
 * its disc, within the margin of a wall. The margin is the body's own motion this step plus the largest motion of
 * the bodies it may touch (its broad-phase pairs): a slow, light body that a fast, heavy one hits mid-step is driven
 * as far as the hitter moves, and contacts are found once a step, so without a wall point already there it would be
 * pushed through the wall (a 0.06 disc 1.1 from the wall, hit by a 30-mass frame at 500 units/s, ended 5.2 past it).
 */
export function boundsContacts(bounds: Bounds, shapes: RigidShapes, c: Colliders, p: ParticleStore, motion: Float64Array, pairs: PairList, slop: number, friction: number, out: RigidContacts): void {
  w6[6] = friction;
  const pushed = partnerMotions(c, pairs, motion);
  for (let k = 0; k < c.activeCount; k++) {
    const s = c.active[k];
    if (c.kind[s] !== ColliderKind.Rigid || c.isStatic[s]) continue;
    // Quick reject: the body's grown AABB, grown again by how far a partner may push it, is inside the walls.
    const e = pushed[s];
    if (c.minX[s] - e > bounds.minX && c.maxX[s] + e < bounds.maxX && c.minY[s] - e > bounds.minY && c.maxY[s] + e < bounds.maxY) continue;
    const i = shapes.row[s];
    const margin = motion[s] + e + slop;
    w6[7] = c.restitution[s];
    for (let wall = 0; wall < 4; wall++) {
      // Wall normal from the body (A) into the wall (B), and the wall's line n·q = level.
      const nx = wall === 0 ? -1 : wall === 1 ? 1 : 0;
      const ny = wall === 2 ? -1 : wall === 3 ? 1 : 0;
      const level = wall === 0 ? -bounds.minX : wall === 1 ? bounds.maxX : wall === 2 ? -bounds.minY : bounds.maxY;
      const first = out.count;
      if (shapes.kind[s] === RigidShapeKind.Circle) {
        const r = shapes.radius[s];
        const depth = p.x[i] * nx + p.y[i] * ny + r - level;
        if (depth < -margin) continue;
        w6[0] = nx;
        w6[1] = ny;
        w6[2] = r * nx;
        w6[3] = r * ny;
        w6[4] = r;
        w6[5] = depth;
        wallPoint(out, p, i, s, wall);
        continue;
      }
      for (let q = shapes.partStart[s], qEnd = q + shapes.partCount[s]; q < qEnd; q++) {
        for (let v = shapes.partVertexStart[q], vEnd = v + shapes.partVertexCount[q]; v < vEnd; v++) {
          const depth = shapes.wx[v] * nx + shapes.wy[v] * ny - level;
          if (depth < -margin) continue;
          w6[0] = nx;
          w6[1] = ny;
          w6[2] = shapes.wx[v] - p.x[i];
          w6[3] = shapes.wy[v] - p.y[i];
          w6[4] = 0;
          w6[5] = depth;
          wallPoint(out, p, i, s, ((v - shapes.partVertexStart[shapes.partStart[s]]) & 8191) * 4 + wall);
        }
      }
      // Two points on one wall (a box lying on the floor) are solved together in the velocity pass.
      if (out.count - first === 2) out.pair[first] = 1;
    }
  }
}

/** The wall point being written: [nx, ny, A's point's offset x, y from its centre, A's radius, depth]. */
const w6 = new Float64Array(8);

/**
 * One point of a body (row i, slot s) against a wall with normal w6[0, 1] (from the body into the wall): A's point is
 * at offset w6[2, 3] from its centre, w6[5] past the wall; the wall's point is A's pushed back onto the wall. The
 * walls' friction is in w6[6], the body's restitution in w6[7].
 */
function wallPoint(out: RigidContacts, p: ParticleStore, i: number, s: number, feature: number): void {
  const f = out.next;
  const ca = p.rc[i];
  const sa = p.rs[i];
  const nx = w6[0];
  const ny = w6[1];
  const ox = w6[2];
  const oy = w6[3];
  const depth = w6[5];
  f[0] = nx;
  f[1] = ny;
  f[2] = ca * ox + sa * oy;
  f[3] = -sa * ox + ca * oy;
  f[4] = p.x[i] + ox - depth * nx;
  f[5] = p.y[i] + oy - depth * ny;
  f[6] = w6[4];
  f[7] = 0;
  f[8] = 0;
  f[9] = w6[6];
  f[10] = w6[7];
  f[11] = depth;
  writeAnchorKey(f, s, -1, feature);
  out.add(i, -1, -1, s, -1, 0);
}
