import { Table } from '../table.js';
import { turnVector, vectorTurn, type BodyRows } from './rows.js';

/**
 * Contact points where at least one side is a rigid body, solved in the XPBD substep loop (Müller et al. 2020, §3.5).
 *
 * Side A is always a rigid body row `a`. Side B is one of:
 * - a rigid body or a particle: row `b` (a particle is a row with inverse inertia 0), anchor (rBx, rBy) in its frame;
 * - a point on an edge of a particle-built outline: rows `b` and `b2` at fraction `alpha` (b2 ≥ 0);
 * - the world (b = −1): a fixed point (rBx, rBy) in world coordinates.
 * The anchors (rAx, rAy), (rBx, rBy) are material points in each body's frame, found by the narrow phase once a step
 * on the two outlines (A's point minus B's point is depth·n). A side with a radius (`radA`, `radB` > 0) is round: its
 * normal contact point is centre ± radius·n, wherever the body has turned to since, so a rolling disc stays on the
 * ground while its material anchor (used for friction) turns away.
 *
 * Per substep, for each point: the overlap d = (qA − qB)·n (n from A to B); if d > 0 both sides move apart along n by
 * d shared by generalised inverse mass (λn); then friction: the tangential drift of the two material points since
 * the step began (for a point that lands during the step: since about the substep it lands in), (pA − pB)·t − slip,
 * is undone up to Coulomb's μ·λn (static friction holds exactly, a larger drift slides and the excess becomes slip);
 * a landing's velocity-pass impulse gets its Coulomb friction there too. After the substep's velocities are derived, the velocity pass sets each
 * acting point's normal velocity to −e times its approach speed for an impact, 0 otherwise (two points of one
 * manifold together, by a 2×2 solve, so a box dropped flat bounces flat).
 */
export class RigidContacts extends Table {
  readonly columns = [
    'a', 'b', 'b2', 'alpha', 'nx', 'ny', 'rAx', 'rAy', 'rBx', 'rBy', 'radA', 'radB', 'friction', 'restitution', 'lambdaN',
    'slip', 'allowance', 'approach', 'lift', 'ownApproach', 'touched', 'pair', 'bodyA', 'bodyB', 'depth', 'gap', 'feature', 'impulseN', 'impulseT',
    'lAx', 'lAy', 'mAx', 'mAy', 'lBx', 'lBy', 'mBx', 'mBy', 'rnA', 'rnB', 'rtA', 'rtB', 'wn', 'wt', 'kn01', 'kt01',
  ] as const;
  a = new Int32Array(16);
  b = new Int32Array(16);
  b2 = new Int32Array(16);
  alpha = new Float64Array(16);
  /** Unit normal from A to B, fixed for the step. */
  nx = new Float64Array(16);
  ny = new Float64Array(16);
  rAx = new Float64Array(16);
  rAy = new Float64Array(16);
  rBx = new Float64Array(16);
  rBy = new Float64Array(16);
  radA = new Float64Array(16);
  radB = new Float64Array(16);
  friction = new Float64Array(16);
  restitution = new Float64Array(16);
  /** Normal correction of the current substep (XPBD multiplier, in position units × mass): > 0 when the point acted. */
  lambdaN = new Float64Array(16);
  /**
   * Tangential distance the point has slid since the step began (friction holds the rest); until it first touches,
   * its whole drift (contact-solver.ts followApart: what slid through the air is not held).
   */
  slip = new Float64Array(16);
  /** Overlap tolerated this substep: an old deep overlap is pushed out at a bounded speed, not in one substep. */
  allowance = new Float64Array(16);
  /**
   * Normal speed (B relative to A, negative approaching) at impact, the fastest of the substeps in which the point
   * acted this step (contact-solver.ts keepApproach); NaN before, +∞ once it bounced.
   */
  approach = new Float64Array(16);
  /**
   * What a bounce adds to −e × approach so that the stored velocity, under position Verlet the mean over a substep,
   * leaves the contact at e × the impact speed: −a·h/2, a the two sides' relative normal acceleration by gravity.
   */
  lift = new Float64Array(16);
  /**
   * 1 once `approach` is the point's own, 0 while it is lent by its manifold partner's touch (keepApproach). It and
   * `lift` hold only while approach is a number: the narrow phase resets approach alone.
   */
  ownApproach = new Uint8Array(16);
  touched = new Uint8Array(16);
  /** 1 on the first point of a two-point manifold (its partner is the next row). */
  pair = new Uint8Array(16);
  /** Body slots of the two sides (−1 for the world), for events and sleeping. */
  bodyA = new Int32Array(16);
  bodyB = new Int32Array(16);
  /** Depth at detection (negative: a speculative gap). */
  depth = new Float64Array(16);
  /** Overlap at the last position sweep, before its correction (negative: apart). */
  gap = new Float64Array(16);
  /** Normal and tangential corrections summed over the step so far (friction's Coulomb limit compares these). */
  impulseN = new Float64Array(16);
  impulseT = new Float64Array(16);
  /**
   * Prepared each substep (contact-solver.ts): world levers of the normal points (lA, lB: a round side's along n) and
   * of the material points (mA, mB), their cross products with n and t, the weights along n and t, and on a
   * manifold's first point its two points' couplings along n and t.
   */
  lAx = new Float64Array(16);
  lAy = new Float64Array(16);
  mAx = new Float64Array(16);
  mAy = new Float64Array(16);
  lBx = new Float64Array(16);
  lBy = new Float64Array(16);
  mBx = new Float64Array(16);
  mBy = new Float64Array(16);
  rnA = new Float64Array(16);
  rnB = new Float64Array(16);
  rtA = new Float64Array(16);
  rtB = new Float64Array(16);
  wn = new Float64Array(16);
  wt = new Float64Array(16);
  kn01 = new Float64Array(16);
  kt01 = new Float64Array(16);
  /** Which bodies and features made the point (the same while they keep touching the same way); see anchorKey. */
  feature = new Float64Array(16);

  /**
   * The next point's reals, written by the caller before add(): nx, ny, rAx, rAy, rBx, rBy, radA, radB, alpha,
   * friction, restitution, depth, feature key. (An array rather than arguments: doubles passed to a call that is not inlined are
   * boxed, and the narrow phase adds thousands of points a step.)
   */
  readonly next = new Float64Array(13);

  /**
   * Shock propagation (see orderForShock in contact-solver.ts), set up once a step when some contact joins bodies
   * whose masses differ 10× or more: each row's level (contacts away from a static body or the world), and the first
   * points of the manifolds between bodies on different levels, lowest first. `shockCount` 0: no shock sweep.
   */
  shockReady = false;
  shockCount = 0;
  /**
   * Set by the step (the same array as StepContext.substepMotion): gravity, the substep and half of it under position Verlet (0 for the Euler
   * integrators, whose stored velocity is the one at the substep's end). A bounce's impact speed needs them
   * (keepApproach); with the defaults, 0, the approach is the stored normal speed itself.
   */
  readonly motion = new Float64Array(4);
  /**
   * Points whose B side is an edge of a particle-built outline (b2 ≥ 0), counted with the shock set-up once a step:
   * only they need the per-substep prepare pass.
   */
  edgePoints = 0;
  /**
   * Per particle row, 1 for a particle frame's (pipeline/frame-bounces.ts FrameBounces.frameRow, set with the
   * topology): a point on a frame keeps its approach with e = 0 too, and its stop is solved again with the frame as one body.
   */
  frameRow = new Uint8Array(0);
  shockOrder = new Int32Array(16);
  level = new Int32Array(16);
  /** Manifolds per level (a counting sort's buckets). */
  levelStart = new Int32Array(66);

  add(a: number, b: number, b2: number, bodyA: number, bodyB: number, pair: number): void {
    if (this.count === this.a.length) this.reserve(1);
    const i = this.count++;
    this.shockReady = false;
    const f = this.next;
    this.a[i] = a;
    this.b[i] = b;
    this.b2[i] = b2;
    this.nx[i] = f[0];
    this.ny[i] = f[1];
    this.rAx[i] = f[2];
    this.rAy[i] = f[3];
    this.rBx[i] = f[4];
    this.rBy[i] = f[5];
    this.radA[i] = f[6];
    this.radB[i] = f[7];
    this.alpha[i] = f[8];
    this.friction[i] = f[9];
    this.restitution[i] = f[10];
    this.depth[i] = f[11];
    this.allowance[i] = f[11] > 0 ? f[11] : 0;
    this.lambdaN[i] = 0;
    this.impulseN[i] = 0;
    this.impulseT[i] = 0;
    this.slip[i] = 0;
    this.approach[i] = NaN;
    this.lift[i] = 0;
    this.ownApproach[i] = 0;
    this.touched[i] = 0;
    this.pair[i] = pair;
    this.bodyA[i] = bodyA;
    this.bodyB[i] = bodyB;
    this.gap[i] = f[11];
    this.feature[i] = f[12];
  }

  /**
   * Start of a substep: no correction yet; old overlaps may shrink by up to `maxPush` more. (prepareRigidContacts does
   * the same in its own pass when given maxPush; this stays for callers that prepare apart.)
   */
  beginSubstep(maxPush: number): void {
    const { lambdaN, allowance } = this;
    for (let i = 0, n = this.count; i < n; i++) {
      lambdaN[i] = 0;
      const left = allowance[i] - maxPush;
      allowance[i] = left > 0 ? left : 0;
    }
  }
}

/**
 * A point's feature key, into f[12] (the next point's key slot): its two body slots (B −1, the world, as 2²² − 1)
 * and the manifold's feature bits. (Written, not returned: a returned double is boxed.)
 */
export function writeAnchorKey(f: Float64Array, bodyA: number, bodyB: number, feature: number): void {
  const key = (bodyA * 4194304 + (bodyB < 0 ? 4194303 : bodyB)) * 65536 + feature;
  // The remainder only past 2⁵³ (body slots from 32768 on): a double's % is a slow library call.
  f[12] = key < 9007199254740991 ? key : key % 9007199254740991;
}

/** Doubles an entry of RigidAnchorCache's list. */
const ENTRY = 6;

/**
 * The chain of an anchor key in RigidAnchorCache's index: the key's bits above body B and the feature (body A's slot
 * while that is below 32768; past it, the key wrapped at 2⁵³ and this is just a number below 2¹⁵ that equal keys share).
 */
function chainOf(key: number): number {
  return (key / 274877906944) | 0;
}

/**
 * How much farther along its rim than its lever's tangential part m·t a round side's material point is from the
 * contact: r·asin(s) − m·t for s = m·t / r (its series to s⁷, by Horner's rule as the WebAssembly kernel computes it); 0 for a
 * side that is not round. Friction holds a material point through the step; measured along the tangent, a rim point
 * that rolls over the contact moves by r·(φ − sin φ) more than the body rolls, which a disc turning 0.7 rad a step
 * (r 0.25 at 10 units/s) asked friction to undo and could not (it slid, 14% of its speed lost in 10 s on a flat
 * floor). Measured along the rim, a disc that rolls keeps its point where it was.
 */
export function arcBeyond(mt: number, radius: number): number {
  if (!(radius > 0)) return 0;
  const s = mt / radius;
  const s2 = s * s;
  // asin(s) − s = s³/6 + 3s⁵/40 + 5s⁷/112 + …; times r: m·t·(s²/6 + …). Two more terms (to s¹¹) kept a disc turning
  // 1.3 rad a step within 0.7% of its speed instead of 5.7%, but the WebAssembly kernel's disc pile (S3) paid 19% of
  // its step for the arcs with them, 10% without. In a step where a round side with friction turns faster than
  // FAST_TURN (rim[3] = 1, set by RigidAnchorCache.restore; the kernel's lanes leave such a step to the JS solver),
  // past s = ½ (30° round the rim) the series falls short and Math.asin measures it: a ball of radius 0.1 rolling at
  // 15 units/s (2.5 rad a step) lost 30% of its speed in 10 s, now 0.5%. A lever shifted past the rim's tangent
  // (|s| > 1) goes on from asin(±1) at the rate of m·t.
  if (s2 <= 0.25 || rim[3] === 0) return mt * (s2 * (1 / 6 + s2 * (3 / 40 + s2 * (5 / 112))));
  if (s2 < 1) return radius * Math.asin(s) - mt;
  return (s > 0 ? radius : -radius) * (Math.PI / 2 - 1);
}

/**
 * arcBeyond's arguments and result, for the solver's loops: [0] m·t, [1] the radius in; [2] the arc beyond out. (An
 * array rather than arguments: doubles passed to or returned from a call that is not inlined are boxed, and the
 * sweeps make this call for every round point every substep.) [3]: 1 in a step whose arcs are measured exactly.
 */
export const rim = new Float64Array(4);

/**
 * A round side turning more than this a step (rad) makes its step's arcs exact (arcBeyond): its friction anchor goes
 * more than 0.4 rad round the rim either side of the contact, where the series falls short.
 */
export const FAST_TURN = 0.8;

/** Whether this step measures its rims' arcs exactly (set by RigidAnchorCache.restore: see FAST_TURN). */
export function arcsExact(): boolean {
  return rim[3] !== 0;
}

/** Whether a point with friction has a round side turning faster than FAST_TURN this step (of dt seconds). */
function fastRoundSide(c: RigidContacts, omega: Float64Array, dt: number): boolean {
  const fast = FAST_TURN / dt;
  const { a, b, radA, radB, friction } = c;
  for (let i = 0, n = c.count; i < n; i++) {
    if (friction[i] === 0) continue;
    if (radA[i] > 0 && Math.abs(omega[a[i]]) > fast) return true;
    if (radB[i] > 0 && b[i] >= 0 && Math.abs(omega[b[i]]) > fast) return true;
  }
  return false;
}

/** arcBeyond on `rim` (arcBeyond, small, is taken inline here). */
export function rimArc(): void {
  rim[2] = arcBeyond(rim[0], rim[1]);
}

/**
 * Last step's friction anchors by feature key (Box2D keeps impulses by feature id for warm starting; a position-based
 * solver keeps the material points instead). A point found again next step starts from the anchors it held, moved
 * by what it slid, so static friction holds a resting body where it first touched and creep cannot accumulate from
 * step to step; anchors more than `reach` from the fresh contact (the bodies moved) are dropped.
 *
 * Speed: the narrow phase meets the pairs in much the same order every step, so the anchors are kept as a list in
 * last step's order (every point, those that did not act marked as holding none) and looked up by a cursor that
 * expects the next one; only a point the cursor misses builds the index by key (once a step, and only then). The
 * index chains the held entries by the key's high bits, body A's slot (chainOf): building it is one pass of two
 * stores an entry, where a hash table was a clear of twice the list's size plus a hashed insert per entry (S2 and S3
 * build it every step: a new contact or a pair met in another order misses the cursor), and a lookup walks the few
 * points of one body. Equal keys share a chain, so it finds what a hash table by key finds: the first held entry.
 */
export class RigidAnchorCache {
  /** The chains hold this list (false: not built since the last store). */
  private tableBuilt = false;
  /** Per chain (chainOf): its first held entry, valid when chainStamp matches `stamp`; per entry: the next one or −1. */
  private chainHead = new Int32Array(64);
  private chainStamp = new Int32Array(64);
  private chainNext = new Int32Array(32);
  private stamp = 0;
  private count = 0;
  /**
   * The list, ENTRY doubles an entry, side by side (one stream for store and restore to write and read, where five
   * arrays were five): the feature key; the overlap the point still tolerated at the end of the step
   * (RigidContacts.allowance, never negative), or −1 for a point that stayed apart, listed only to keep the order and
   * holding no anchors; then A's and B's anchors (rAx, rAy, rBx, rBy).
   */
  private entries = new Float64Array(32 * ENTRY);

  /** Remembers the anchors of every point that acted and of rigid, particle or world B (not particle edges). */
  store(c: RigidContacts, r: BodyRows): void {
    this.tableBuilt = false;
    const count = c.count;
    if (this.entries.length < count * ENTRY) this.entries = new Float64Array(2 * count * ENTRY);
    const entries = this.entries;
    const { rc, rs } = r;
    // The columns in locals: read through `c` they are loaded again for every point.
    const { b, b2, feature, touched, slip: slips, nx, ny, rAx, rAy, rBx, rBy, allowance } = c;
    let e = 0;
    for (let i = 0; i < count; i++) {
      if (b2[i] >= 0) continue;
      entries[e] = feature[i];
      if (!touched[i]) {
        entries[e + 1] = -1;
        e += ENTRY;
        continue;
      }
      // B's anchor moves along the tangent by what slid this step: that much is no longer held back.
      const slip = slips[i];
      const tx = -ny[i] * slip;
      const ty = nx[i] * slip;
      const ib = b[i];
      let bx = rBx[i];
      let by = rBy[i];
      if (ib < 0) {
        bx += tx;
        by += ty;
      } else if (slip !== 0) {
        // The slide, turned into B's frame.
        const cb = rc[ib];
        const sb = rs[ib];
        bx += cb * tx + sb * ty;
        by += -sb * tx + cb * ty;
      }
      entries[e + 1] = allowance[i];
      entries[e + 2] = rAx[i];
      entries[e + 3] = rAy[i];
      entries[e + 4] = bx;
      entries[e + 5] = by;
      e += ENTRY;
    }
    this.count = e / ENTRY;
  }

  /** The chains of the stored list's held entries, each in list order (so a lookup finds a key's first entry). */
  private build(): void {
    const entries = this.entries;
    const n = this.count;
    if (this.chainNext.length < n) this.chainNext = new Int32Array(2 * n);
    // A new stamp invalidates every chain head at once (no clearing pass); it wraps long before it could repeat.
    this.stamp = this.stamp === 0x7fffffff ? 1 : this.stamp + 1;
    const stamp = this.stamp;
    const next = this.chainNext;
    for (let k = n - 1; k >= 0; k--) {
      if (entries[k * ENTRY + 1] < 0) continue;
      const h = chainOf(entries[k * ENTRY]);
      if (h >= this.chainHead.length) this.growChains(h + 1);
      const head = this.chainHead;
      if (this.chainStamp[h] === stamp) next[k] = head[h];
      else {
        next[k] = -1;
        this.chainStamp[h] = stamp;
      }
      head[h] = k;
    }
    this.tableBuilt = true;
  }

  private growChains(size: number): void {
    const n = Math.max(size, 2 * this.chainHead.length);
    const head = new Int32Array(n);
    const stamp = new Int32Array(n);
    head.set(this.chainHead);
    stamp.set(this.chainStamp);
    this.chainHead = head;
    this.chainStamp = stamp;
  }

  /**
   * Index in the stored list of `key` (its anchors when it holds any), or −1; `cursor` is where the list is expected
   * to match.
   */
  private lookup(key: number, cursor: number): number {
    if (cursor < this.count && this.entries[cursor * ENTRY] === key) return cursor;
    if (!this.tableBuilt) this.build();
    const h = chainOf(key);
    if (h >= this.chainHead.length || this.chainStamp[h] !== this.stamp) return -1;
    const entries = this.entries;
    const next = this.chainNext;
    for (let k = this.chainHead[h]; k >= 0; k = next[k]) if (entries[k * ENTRY] === key) return k;
    return -1;
  }

  /**
   * Gives each new point the anchors its feature held last step, when they are within `reach` of the fresh ones (else
   * a round side's fresh anchor is turned back half the step's turn of its body), and no more overlap allowance than it
   * had left: an old overlap keeps shrinking at maxPushSpeed from step to step
   * (taken afresh from each step's depth, a deep overlap under a load that pushes back as fast would never clear).
   */
  restore(c: RigidContacts, reach: number, r: BodyRows, dt: number): void {
    const reach2 = reach * reach;
    const entries = this.entries;
    const stored = this.count;
    // The columns in locals: read through `c` they are loaded again for every point.
    const { b2, feature, allowance, rAx, rAy, rBx, rBy, radA, radB, a: A, b: B } = c;
    const omega = r.omega;
    rim[3] = fastRoundSide(c, omega, dt) ? 1 : 0;
    let cursor = 0;
    for (let i = 0, n = c.count; i < n; i++) {
      if (b2[i] >= 0) continue;
      const key = feature[i];
      // The list's order holds (most points): no call.
      const k = cursor < stored && entries[cursor * ENTRY] === key ? cursor : this.lookup(key, cursor);
      if (k >= 0) {
        cursor = k + 1;
        const e = k * ENTRY;
        const allow = entries[e + 1];
        if (allow >= 0) {
          if (allow < allowance[i]) allowance[i] = allow;
          const ax = entries[e + 2];
          const ay = entries[e + 3];
          const bx = entries[e + 4];
          const by = entries[e + 5];
          // Measured from the fresh anchors as turned below (to first order: a turn is a small fraction of a radian).
          const tA = radA[i] > 0 ? -0.5 * omega[A[i]] * dt : 0;
          const tB = radB[i] > 0 && B[i] >= 0 ? -0.5 * omega[B[i]] * dt : 0;
          const dax = ax - (rAx[i] - tA * rAy[i]);
          const day = ay - (rAy[i] + tA * rAx[i]);
          const dbx = bx - (rBx[i] - tB * rBy[i]);
          const dby = by - (rBy[i] + tB * rBx[i]);
          if (dax * dax + day * day <= reach2 && dbx * dbx + dby * dby <= reach2) {
            rAx[i] = ax;
            rAy[i] = ay;
            rBx[i] = bx;
            rBy[i] = by;
            continue;
          }
        }
      }
      // A fresh anchor of a round side is a material point of its rim, held through the step. Found at the contact,
      // it turned ahead of it as the body rolled, and static friction held that point instead, so that the body ended
      // a step rolling at v = ω·r·cos(turn) (a disc spun onto a floor 0.3% fast at r 0.5, 1.9% slow at r 0.25 and
      // 12 rad/s). The point at the contact half-way through the step is the one half the step's turn behind it.
      // Turned, the anchors are shifted along the tangent (the side that is not round, else both halves) so that
      // the point starts the step where it was found: no drift for friction to undo in its first substep (a disc
      // rolling at 10 units/s was kicked back and forth every step, 1.2% of its speed lost in 10 s).
      if (radA[i] > 0 || (radB[i] > 0 && B[i] >= 0)) turnRoundAnchors(c, r, i, dt);
    }
  }

  snapshot(): { keys: Float64Array; held: Uint8Array; rA: Float64Array; rB: Float64Array; allow: Float64Array } {
    const n = this.count;
    const entries = this.entries;
    const keys = new Float64Array(n);
    const held = new Uint8Array(n);
    const rA = new Float64Array(2 * n);
    const rB = new Float64Array(2 * n);
    const allow = new Float64Array(n);
    for (let k = 0; k < n; k++) {
      const e = k * ENTRY;
      keys[k] = entries[e];
      // The arrays as they were kept before the entries were packed (a point that stayed apart: zeros).
      if (entries[e + 1] < 0) continue;
      held[k] = 1;
      allow[k] = entries[e + 1];
      rA[2 * k] = entries[e + 2];
      rA[2 * k + 1] = entries[e + 3];
      rB[2 * k] = entries[e + 4];
      rB[2 * k + 1] = entries[e + 5];
    }
    return { keys, held, rA, rB, allow };
  }

  restoreSnapshot(s: { keys: Float64Array; held: Uint8Array; rA: Float64Array; rB: Float64Array; allow: Float64Array }): void {
    const n = s.keys.length;
    this.count = n;
    this.entries = new Float64Array(Math.max(n, 32) * ENTRY);
    const entries = this.entries;
    for (let k = 0; k < n; k++) {
      const e = k * ENTRY;
      entries[e] = s.keys[k];
      if (s.held[k] === 0) {
        entries[e + 1] = -1;
        continue;
      }
      entries[e + 1] = s.allow[k];
      entries[e + 2] = s.rA[2 * k];
      entries[e + 3] = s.rA[2 * k + 1];
      entries[e + 4] = s.rB[2 * k];
      entries[e + 5] = s.rB[2 * k + 1];
    }
    this.tableBuilt = false;
  }
}

/**
 * A fresh point i's anchors on its round sides, turned back half the step's turn of their bodies and shifted along the
 * tangent so that the point starts the step where it was found (RigidAnchorCache.restore says why). One call a point,
 * its sums in locals: three quarters of a disc pile's points are fresh every step (pairs within reach that did not
 * touch), and the calls and scratch arrays of the helpers it once made cost 10% of the pile's detection.
 */
function turnRoundAnchors(c: RigidContacts, r: BodyRows, i: number, dt: number): void {
  const { rc, rs, omega } = r;
  const a = c.a[i];
  const b = c.b[i];
  const nx = c.nx[i];
  const ny = c.ny[i];
  const radA = c.radA[i];
  const radB = c.radB[i];
  const roundA = radA > 0;
  const roundB = radB > 0 && b >= 0;
  let ax = c.rAx[i];
  let ay = c.rAy[i];
  let bx = c.rBx[i];
  let by = c.rBy[i];
  // Pass 0 measures the point as found (A's material point minus B's along the tangent, rims along their arc), turns
  // the round sides' anchors; pass 1 measures it again: `moved` is what the turn moved it.
  let found = 0;
  let moved = 0;
  for (let pass = 0; pass < 2; pass++) {
    const mAx = rc[a] * ax - rs[a] * ay;
    const mAy = rs[a] * ax + rc[a] * ay;
    const tA = -mAx * ny + mAy * nx;
    let offset = tA + arcBeyond(tA, radA);
    if (b < 0) offset -= -bx * ny + by * nx;
    else {
      const mBx = rc[b] * bx - rs[b] * by;
      const mBy = rs[b] * bx + rc[b] * by;
      const tB = -mBx * ny + mBy * nx;
      offset -= tB + arcBeyond(tB, radB);
    }
    if (pass === 1) {
      moved = offset - found;
      break;
    }
    found = offset;
    if (roundA) {
      vectorTurn[0] = -0.5 * omega[a] * dt;
      turnVector(c.rAx, c.rAy, i);
      ax = c.rAx[i];
      ay = c.rAy[i];
    }
    if (roundB) {
      vectorTurn[0] = -0.5 * omega[b] * dt;
      turnVector(c.rBx, c.rBy, i);
      bx = c.rBx[i];
      by = c.rBy[i];
    }
  }
  // Shared between round sides, else all on the side that is not round; each moved in its body's frame (or the world's).
  const dA = roundB ? (roundA ? -0.5 * moved : -moved) : 0;
  const dB = roundB ? (roundA ? 0.5 * moved : 0) : moved;
  if (dA !== 0) {
    const tx = -ny * dA;
    const ty = nx * dA;
    c.rAx[i] = ax + (rc[a] * tx + rs[a] * ty);
    c.rAy[i] = ay + (-rs[a] * tx + rc[a] * ty);
  }
  if (dB !== 0) {
    const cs = b < 0 ? 1 : rc[b];
    const sn = b < 0 ? 0 : rs[b];
    const tx = -ny * dB;
    const ty = nx * dB;
    c.rBx[i] = bx + (cs * tx + sn * ty);
    c.rBy[i] = by + (-sn * tx + cs * ty);
  }
}
