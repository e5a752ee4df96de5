import { Table } from '../table.js';
import type { ParticleStore } from '../particles.js';
import { KeyTable } from './key-table.js';
import { BOUNCE_THRESHOLD, hit, impact } from '../impact.js';
import { setSide, type FrameBounces } from './frame-bounces.js';

/**
 * Contacts found by the narrow phase once per step, solved by projection inside every relaxation sweep (seed 4.2).
 *
 * A vertex–edge contact keeps particle `v` on the outer side of the edge `e0 → e1` (of a counter-clockwise part,
 * whose outward normal is perp(e1 − e0) = (ey, −ex)/|e|), `radius` away from it. The correction is shared by
 * inverse mass between the vertex and the edge's two particles, the edge's share split by α and 1 − α (α = where
 * the vertex projects on the edge); dividing by w_v + (1−α)²·w_e0 + α²·w_e1 makes the contact point move exactly by
 * the correction, which is Jakobsen's 1/(α² + (1−α)²) generalised to unequal masses.
 * A point–point contact (e1 = −1) keeps particles v and e0 `radius` apart: circles, or a circle on a corner.
 *
 * Each step's contacts are speculative: they are found while still `margin` apart and only act once the gap closes
 * during a substep, measured from the particles' current positions, so fast bodies cannot pass through.
 *
 * Friction is Coulomb's, on positions: the contact point's tangential motion since the substep began is undone up
 * to μ times the normal correction of this substep (static friction when it all fits, kinetic otherwise).
 */
export class Contacts extends Table {
  readonly columns = ['v', 'e0', 'e1', 'radius', 'friction', 'restitution', 'bodyA', 'bodyB', 'lambda', 'nx', 'ny', 'depth', 'normalSpeed', 'lift', 'anchor', 'touched', 'allowance', 'solvedNx', 'solvedNy', 'solvedAlpha', 'frictionSpent', 'touchSlide'] as const;
  v = new Int32Array(16);
  e0 = new Int32Array(16);
  e1 = new Int32Array(16);
  radius = new Float64Array(16);
  friction = new Float64Array(16);
  restitution = new Float64Array(16);
  /** Body slots: A owns the edge (or particle e0), B owns the vertex. */
  bodyA = new Int32Array(16);
  bodyB = new Int32Array(16);
  /** Normal correction accumulated in the current substep. */
  lambda = new Float64Array(16);
  /** Normal (from A to B) and signed gap at detection; depth > 0 means overlap. */
  nx = new Float64Array(16);
  ny = new Float64Array(16);
  depth = new Float64Array(16);
  /**
   * Relative normal speed (negative: approaching) at the hit, for restitution: at the start of the step, and for a
   * bouncy contact under gravity what the fall through its gap adds (recordApproachSpeeds).
   */
  normalSpeed = new Float64Array(16);
  /** What a bounce adds to −e × normalSpeed (impact.ts: −a·h/2 under position Verlet). */
  lift = new Float64Array(16);
  /**
   * Static friction anchor of a vertex–edge contact: the fraction along the edge where the vertex first touched it
   * (NaN until it does). Kept across steps for the same (vertex, edge) feature, so creep cannot accumulate: static
   * friction pulls the vertex back to its anchor, and the anchor moves only when the contact slips.
   */
  anchor = new Float64Array(16);
  /** 1 once the contact has acted (the bodies touched) during this step. */
  touched = new Uint8Array(16);
  /**
   * Overlap the contact tolerates in the current substep. It starts at the overlap found at detection and shrinks by
   * the most the contact may push out per substep, so an old deep overlap is recovered at a bounded speed instead of
   * in one substep (which would turn depth / h into velocity and throw bodies at their neighbours), while overlap
   * created by motion during the step is still undone at once (nothing tunnels).
   */
  allowance = new Float64Array(16);
  /** Normal and edge fraction of the last correction, reused by the velocity pass (valid while `lambda` > 0). */
  solvedNx = new Float64Array(16);
  solvedNy = new Float64Array(16);
  solvedAlpha = new Float64Array(16);
  /** The friction multipliers' sizes the position pass applied in this substep (an impact's friction budget). */
  frictionSpent = new Float64Array(16);
  /** A bouncing pair of particles' sliding speed along the tangent (−ny, nx) of where they touch (touchNormal). */
  touchSlide = new Float64Array(16);

  /**
   * The next contact's real-valued fields, filled by the caller before add(): radius, friction, restitution, normal
   * x, y, depth. (Passed in this array because doubles passed to a call that is not inlined are boxed, and the
   * narrow phase adds thousands of contacts per step.)
   */
  readonly next = new Float64Array(6);

  /** Appends a contact of vertex (or particle) v against edge e0–e1 (or particle e0 when e1 < 0), with `next`. */
  add(v: number, e0: number, e1: number, bodyA: number, bodyB: number): void {
    if (this.count === this.v.length) this.reserve(1);
    const i = this.count++;
    const f = this.next;
    this.v[i] = v;
    this.e0[i] = e0;
    this.e1[i] = e1;
    this.radius[i] = f[0];
    this.friction[i] = f[1];
    this.restitution[i] = f[2];
    this.bodyA[i] = bodyA;
    this.bodyB[i] = bodyB;
    this.lambda[i] = 0;
    this.nx[i] = f[3];
    this.ny[i] = f[4];
    this.depth[i] = f[5];
    this.normalSpeed[i] = 0;
    this.lift[i] = 0;
    this.anchor[i] = NaN;
    this.touched[i] = 0;
    this.allowance[i] = f[5] > 0 ? f[5] : 0;
    this.frictionSpent[i] = 0;
  }

  /** Start of a substep: no correction yet, and each old overlap may shrink by up to `maxPush` more. */
  beginSubstep(maxPush: number): void {
    const { lambda, allowance, frictionSpent } = this;
    for (let i = 0, n = this.count; i < n; i++) {
      lambda[i] = 0;
      frictionSpent[i] = 0;
      const a = allowance[i] - maxPush;
      allowance[i] = a > 0 ? a : 0;
    }
  }
}

/** Identifies a contact's feature pair across steps: vertex v against the edge starting at e0 (or particle e0). */
function featureKey(v: number, e0: number, e1: number): number {
  return (v * 4194304 + e0) * 2 + (e1 < 0 ? 1 : 0);
}

/** Last step's anchors by feature key. */
export class AnchorCache {
  private readonly table = new KeyTable();

  /** Remembers the anchors of every contact that has one. */
  store(c: Contacts): void {
    this.table.reset(c.count);
    for (let i = 0; i < c.count; i++) {
      const a = c.anchor[i];
      if (a === a) this.table.insert(featureKey(c.v[i], c.e0[i], c.e1[i]), a); // NaN: never touched
    }
  }

  /** Gives each new contact the anchor its feature had last step. */
  restore(c: Contacts): void {
    for (let i = 0; i < c.count; i++) {
      const slot = this.table.find(featureKey(c.v[i], c.e0[i], c.e1[i]));
      if (slot >= 0) c.anchor[i] = this.table.values[slot];
    }
  }

  snapshot(): { keys: Float64Array; values: Float64Array } {
    return this.table.snapshot();
  }

  restoreSnapshot(s: { keys: Float64Array; values: Float64Array }): void {
    this.table.restore(s);
  }
}

/** How far past an edge's ends (as a fraction of its length) a vertex still counts as touching it. */
const EDGE_OVERHANG = 0.05;

/**
 * A bouncy contact that acts in this substep with no impact taken at detection (its sides were at rest then) is an
 * impact after all when they approach at the substep's start faster than a bounce needs (the velocities still hold
 * the last substep's): in a Newton's cradle the second ball is hit within the step and meets the third. Taken at the
 * step's start only, the row of particle balls shared each hit as if inelastic: the last of five rose 7% of the drop.
 * The rigid contacts keep the fastest approach of any substep in which they act likewise (contact-solver.ts touch()).
 * A vertex on an edge takes its approach anew when it first touches in the step (`sep` its overlap then), as the
 * walls and the rigid contacts do: a particle frame's corner that landed a substep after its partner, whose bounce
 * had turned the frame, or one whose approach the frame's spin had changed since the step began, bounced on the
 * step's start's, and frames landing almost flat on a particle floor gained up to 67% of their energy. (A pair of
 * particles keeps its touch's, touchNormal(): it is marked touched before.)
 */
function armBounce(c: Contacts, p: ParticleStore, i: number, nx: number, ny: number, alpha: number, sep: number, motion: Float64Array): void {
  const fresh = c.touched[i] === 0;
  if (!(c.restitution[i] > 0) || (!fresh && c.normalSpeed[i] < -BOUNCE_THRESHOLD)) return;
  const { vx, vy } = p;
  const iv = c.v[i];
  const i0 = c.e0[i];
  const i1 = c.e1[i];
  const ux = i1 >= 0 ? vx[iv] - (1 - alpha) * vx[i0] - alpha * vx[i1] : vx[iv] - vx[i0];
  const uy = i1 >= 0 ? vy[iv] - (1 - alpha) * vy[i0] - alpha * vy[i1] : vy[iv] - vy[i0];
  const vn = ux * nx + uy * ny;
  if (!fresh && !(vn < -BOUNCE_THRESHOLD)) return;
  c.normalSpeed[i] = vn;
  c.lift[i] = 0;
  c.nx[i] = nx;
  c.ny[i] = ny;
  c.touchSlide[i] = -ux * ny + uy * nx;
  if (!fresh) return;
  // Gravity over the gap it closed in this substep before the touch: its move less the overlap (−depth, as impact() reads it).
  c.depth[i] = vn * motion[2] - sep;
  hitSpeed(c, p, i, alpha, nx, ny, motion);
}

export function solveContacts(c: Contacts, p: ParticleStore, motion: Float64Array): void {
  const { x, y, px, py, invMass } = p;
  const { v, e0, e1, radius, friction, lambda, anchor, allowance, touched, solvedNx, solvedNy, solvedAlpha } = c;
  const n = c.count;
  for (let i = 0; i < n; i++) {
    const iv = v[i];
    const i0 = e0[i];
    const i1 = e1[i];
    const wv = invMass[iv];
    const w0 = invMass[i0];
    if (i1 >= 0) {
      const ex = x[i1] - x[i0];
      const ey = y[i1] - y[i0];
      const len2 = ex * ex + ey * ey;
      if (len2 < 1e-24) continue;
      const inv = 1 / Math.sqrt(len2);
      const nx = ey * inv;
      const ny = -ex * inv;
      const rx = x[iv] - x[i0];
      const ry = y[iv] - y[i0];
      const sep = rx * nx + ry * ny - radius[i] + allowance[i];
      if (sep >= 0) continue;
      let alpha = (rx * ex + ry * ey) / len2;
      if (alpha < -EDGE_OVERHANG || alpha > 1 + EDGE_OVERHANG) continue;
      alpha = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
      armBounce(c, p, i, nx, ny, alpha, sep, motion);
      touched[i] = 1;
      const beta = 1 - alpha;
      const w1 = invMass[i1];
      const w = wv + beta * beta * w0 + alpha * alpha * w1;
      if (w === 0) continue;
      const dl = -sep / w;
      lambda[i] += dl;
      solvedNx[i] = nx;
      solvedNy[i] = ny;
      solvedAlpha[i] = alpha;
      // Static friction holds the vertex at the point of the edge it first touched (its anchor); when that needs
      // more than μ times the normal correction, the contact slips by the excess and the anchor follows.
      const tx = ex * inv;
      const ty = ey * inv;
      const len = len2 * inv;
      if (anchor[i] !== anchor[i]) anchor[i] = alpha;
      const slide = (alpha - anchor[i]) * len;
      // Coulomb on multipliers, |λt| ≤ μ·λn, is a positional limit of μ·λn·w.
      const limit = friction[i] * lambda[i] * w;
      const undo = slide > limit ? limit : slide < -limit ? -limit : slide;
      if (undo !== slide) anchor[i] += (slide - undo) / len;
      const dt = -undo / w;
      c.frictionSpent[i] += dt < 0 ? -dt : dt;
      // Normal and friction corrections applied together.
      const cx = dl * nx + dt * tx;
      const cy = dl * ny + dt * ty;
      x[iv] += wv * cx;
      y[iv] += wv * cy;
      x[i0] -= w0 * beta * cx;
      y[i0] -= w0 * beta * cy;
      x[i1] -= w1 * alpha * cx;
      y[i1] -= w1 * alpha * cy;
    } else {
      let nx = x[iv] - x[i0];
      let ny = y[iv] - y[i0];
      const d2 = nx * nx + ny * ny;
      const r = radius[i] - allowance[i];
      if (d2 >= r * r) continue;
      const w = wv + w0;
      if (w === 0) continue;
      touched[i] = 1;
      const d = Math.sqrt(d2);
      if (d > 1e-12) {
        nx /= d;
        ny /= d;
      } else {
        nx = c.nx[i];
        ny = c.ny[i];
      }
      armBounce(c, p, i, nx, ny, 0, 0, motion);
      const dl = (r - d) / w;
      lambda[i] += dl;
      solvedNx[i] = nx;
      solvedNy[i] = ny;
      solvedAlpha[i] = 0;
      const tx = -ny;
      const ty = nx;
      const mx = x[iv] - px[iv] - (x[i0] - px[i0]);
      const my = y[iv] - py[iv] - (y[i0] - py[i0]);
      const slide = mx * tx + my * ty;
      // Coulomb on multipliers, |λt| ≤ μ·λn, is a positional limit of μ·λn·w.
      const limit = friction[i] * lambda[i] * w;
      const undo = slide > limit ? limit : slide < -limit ? -limit : slide;
      const dt = -undo / w;
      c.frictionSpent[i] += dt < 0 ? -dt : dt;
      const cx = dl * nx + dt * tx;
      const cy = dl * ny + dt * ty;
      x[iv] += wv * cx;
      y[iv] += wv * cy;
      x[i0] -= w0 * cx;
      y[i0] -= w0 * cy;
    }
  }
}

/**
 * Records each contact's approach speed at the start of the step (restitution needs the speed before impact): the
 * relative normal velocity of the contact's point, vertex minus the edge point under it (or particle e0), negative
 * when approaching; a bouncy contact then adds what gravity adds on the way to the hit (hitSpeed). Written in place
 * rather than by a helper returning a number: a non-inlined call returns its double boxed, and this runs for every
 * contact every step. `motion`: the step's [gx, gy, h, half] (StepContext.substepMotion).
 */
export function recordApproachSpeeds(c: Contacts, p: ParticleStore, motion: Float64Array): void {
  const { x, y, vx, vy } = p;
  const { v, e0, e1, normalSpeed } = c;
  for (let i = 0, n = c.count; i < n; i++) {
    const iv = v[i];
    const i0 = e0[i];
    const i1 = e1[i];
    if (i1 >= 0) {
      const ex = x[i1] - x[i0];
      const ey = y[i1] - y[i0];
      const len2 = ex * ex + ey * ey;
      if (len2 < 1e-24) {
        normalSpeed[i] = 0;
        continue;
      }
      const inv = 1 / Math.sqrt(len2);
      let alpha = ((x[iv] - x[i0]) * ex + (y[iv] - y[i0]) * ey) / len2;
      alpha = alpha < 0 ? 0 : alpha > 1 ? 1 : alpha;
      const rvx = vx[iv] - (1 - alpha) * vx[i0] - alpha * vx[i1];
      const rvy = vy[iv] - (1 - alpha) * vy[i0] - alpha * vy[i1];
      normalSpeed[i] = (rvx * ey - rvy * ex) * inv;
      if (c.restitution[i] > 0) hitSpeed(c, p, i, alpha, ey * inv, -ex * inv, motion);
      continue;
    }
    let nx = x[iv] - x[i0];
    let ny = y[iv] - y[i0];
    const d = Math.sqrt(nx * nx + ny * ny);
    if (d > 1e-12) {
      nx /= d;
      ny /= d;
    } else {
      nx = c.nx[i];
      ny = c.ny[i];
    }
    normalSpeed[i] = (vx[iv] - vx[i0]) * nx + (vy[iv] - vy[i0]) * ny;
    // An impact acts along the line of centres where they will touch (touchNormal), which turns from the one now as
    // a glancing pair closes: its speed along this one bounced them too hard (a glancing elastic hit gained up to 26%
    // of its energy), and a stop (e = 0) along the overlap's turned the pair up to 1.8° off at 60 units/s.
    const bouncy = c.restitution[i] > 0;
    if (bouncy || normalSpeed[i] < -BOUNCE_THRESHOLD) touchNormal(c, p, i);
    if (bouncy) hitSpeed(c, p, i, 0, c.nx[i], c.ny[i], motion);
  }
}

/**
 * Particles v and e0 of contact i, apart now, meet where |d + u·t| = R (d their offset, u their relative velocity,
 * R the contact's radius): that line of centres (where they pass closest, if they miss) into the contact's normal
 * (nx, ny), and their speed along it into normalSpeed. Already overlapping or parting: the line of centres now.
 */
function touchNormal(c: Contacts, p: ParticleStore, i: number): void {
  const iv = c.v[i];
  const i0 = c.e0[i];
  const dx = p.x[iv] - p.x[i0];
  const dy = p.y[iv] - p.y[i0];
  const ux = p.vx[iv] - p.vx[i0];
  const uy = p.vy[iv] - p.vy[i0];
  const uu = ux * ux + uy * uy;
  const du = dx * ux + dy * uy;
  const R = c.radius[i];
  const gap = dx * dx + dy * dy - R * R;
  let t = 0;
  if (gap > 0 && du < 0 && uu > 0) {
    const disc = du * du - uu * gap;
    t = disc > 0 ? (-du - Math.sqrt(disc)) / uu : -du / uu;
  }
  const nx = dx + ux * t;
  const ny = dy + uy * t;
  const n = Math.sqrt(nx * nx + ny * ny);
  if (!(n > 1e-12)) {
    // Coincident and at rest relative to each other: the normal the contact has, and its slide along that.
    c.touchSlide[i] = uy * c.nx[i] - ux * c.ny[i];
    return;
  }
  c.nx[i] = nx / n;
  c.ny[i] = ny / n;
  c.normalSpeed[i] = (ux * nx + uy * ny) / n;
  c.touchSlide[i] = (uy * nx - ux * ny) / n;
}

/**
 * Contact i's normal speed at the hit (impact()), from its speed at the start of the step, along (nx, ny) from the
 * edge point at fraction `alpha` (or particle e0) to the vertex: gravity moves the movable sides alike, and over the
 * gap at detection (−depth) it adds √(2·a·gap). A particle ball with e = 0.8 dropped from 2 on a particle floor rose
 * to 1.252 instead of 1.28. (Called for bouncy contacts only: its doubles are boxed.)
 */
function hitSpeed(c: Contacts, p: ParticleStore, i: number, alpha: number, nx: number, ny: number, motion: Float64Array): void {
  const { invMass } = p;
  const i1 = c.e1[i];
  const share = (invMass[c.v[i]] > 0 ? 1 : 0) - (1 - alpha) * (invMass[c.e0[i]] > 0 ? 1 : 0) - (i1 >= 0 && invMass[i1] > 0 ? alpha : 0);
  hit[0] = c.normalSpeed[i];
  hit[1] = share * (motion[0] * nx + motion[1] * ny);
  hit[2] = -c.depth[i];
  hit[3] = motion[3];
  impact();
  c.normalSpeed[i] = hit[0];
  c.lift[i] = hit[1];
}

/**
 * The velocity pass after a substep (Müller et al. 2020): for every contact that acted in this substep, the relative
 * normal velocity becomes −e·(approach speed) for an impact that bounces and 0 otherwise. Without it, pushing a
 * penetration out within one substep of length h would leave the bodies flying apart at depth / h, and resting
 * stacks would keep a residual normal jitter that lets them creep.
 */
export function solveContactVelocities(c: Contacts, p: ParticleStore, h: number, bounces: FrameBounces): void {
  const { vx, vy, invMass } = p;
  const { v, e0, e1, lambda, restitution, friction, normalSpeed, solvedNx, solvedNy, solvedAlpha } = c;
  const frameRow = bounces.frameRow;
  for (let i = 0, n = c.count; i < n; i++) {
    if (lambda[i] <= 0) continue;
    // The direction and edge fraction of this substep's correction: the positions barely moved since. A pair of
    // particles meeting at speed bounces or stops along the line of centres where they touched (touchNormal), once.
    const touchBounce = e1[i] < 0 && normalSpeed[i] < -BOUNCE_THRESHOLD;
    const nx = touchBounce ? c.nx[i] : solvedNx[i];
    const ny = touchBounce ? c.ny[i] : solvedNy[i];
    const alpha = solvedAlpha[i];
    const beta = 1 - alpha;
    const iv = v[i];
    const i0 = e0[i];
    const i1 = e1[i];
    const wv = invMass[iv];
    const w0 = invMass[i0];
    let vn: number;
    let w: number;
    let w1 = 0;
    if (i1 >= 0) {
      w1 = invMass[i1];
      vn = (vx[iv] - beta * vx[i0] - alpha * vx[i1]) * nx + (vy[iv] - beta * vy[i0] - alpha * vy[i1]) * ny;
      w = wv + beta * beta * w0 + alpha * alpha * w1;
    } else {
      vn = (vx[iv] - vx[i0]) * nx + (vy[iv] - vy[i0]) * ny;
      w = wv + w0;
    }
    if (w === 0) continue;
    let target = 0;
    // A bouncy contact approaching faster now than it was found, after the impulses of this sweep so far, bounces on
    // that: a partner's bounce just gave it (a cradle's second ball, pushed into the third in the substep the first hit
    // it, while all three were at rest at its start), as the rigid points do.
    const bouncy = restitution[i] > 0;
    const approach = bouncy && vn < -BOUNCE_THRESHOLD && vn < normalSpeed[i] ? vn : normalSpeed[i];
    // An impact (once): its bounce, and Coulomb's friction on its impulse below.
    const impact = approach < -BOUNCE_THRESHOLD;
    // A bouncy pair separating (as found, or after its bounce) goes on at up to that speed, as a rigid point does: a
    // target of 0 pulled it back whenever an overlap left for later substeps (maxPushSpeed) made it act again, and a
    // Newton's cradle of particle balls 1.001 apart shared each hit (1.5 and 1.5 where 0 and 3).
    if (!impact && bouncy && approach > 0) target = vn < 0 ? 0 : vn < approach ? vn : approach;
    if (bouncy && impact) target = -restitution[i] * approach + (approach === normalSpeed[i] ? c.lift[i] : 0);
    // For a particle frame on either side (frame-bounces.ts): its bounce, or with e = 0 its stop (target 0). Stopped
    // here alone, the corners that touched stood still while the rest of the frame came on, and its sticks sprang
    // the squeeze back out: two frames parted at a quarter of their approach.
    if (impact && (bouncy || frameRow[iv] === 1 || frameRow[i0] === 1 || (i1 >= 0 && frameRow[i1] === 1))) {
      const k = bounces.add();
      setSide(bounces, k, 0, i0, i1);
      bounces.alpha[2 * k] = i1 >= 0 ? alpha : 0;
      setSide(bounces, k, 1, iv, -1);
      bounces.nx[k] = nx;
      bounces.ny[k] = ny;
      bounces.target[k] = target;
      // Friction with its stop (e = 0) only (frame-bounces.ts).
      bounces.friction[k] = bouncy ? 0 : friction[i];
    }
    const dl = (target - vn) / w;
    // An impact's friction, Coulomb's on its whole impulse (from its approach to the target): the position pass
    // spent some (frictionSpent), the rest acts here, toward no sliding. The position pass's anchor starts where the
    // contact is found overlapping, so there it barely acts: a particle ball thrown at 45° onto a particle floor
    // kept 6.1 of its 7.1 sideways (3.5 with μ = 0.5), and one that bounced all of it.
    let dt = 0;
    let slide = 0;
    if (touchBounce || (impact && friction[i] > 0)) {
      slide = (i1 >= 0 ? vx[iv] - beta * vx[i0] - alpha * vx[i1] : vx[iv] - vx[i0]) * -ny + (i1 >= 0 ? vy[iv] - beta * vy[i0] - alpha * vy[i1] : vy[iv] - vy[i0]) * nx;
      if (touchBounce) {
        // The position pass pushed the pair apart along their line of centres now, which also slid them along the
        // touch's tangent (an elastic glancing hit off by 1–3% in speed): back to the slide they met with.
        dt = (c.touchSlide[i] - slide) / w;
        slide = c.touchSlide[i];
      }
    }
    if (impact && friction[i] > 0) {
      const budget = (friction[i] * (target - approach)) / w - (touchBounce ? 0 : c.frictionSpent[i] / h);
      if (budget > 0) {
        const stop = -slide / w;
        dt += stop > budget ? budget : stop < -budget ? -budget : stop;
      }
    }
    // Once per impact; a bounce is remembered as the speed it left with (above).
    if (impact) normalSpeed[i] = restitution[i] > 0 ? target : 0;
    // The normal impulse along n and the friction along t = (−ny, nx).
    const cx = dl * nx - dt * ny;
    const cy = dl * ny + dt * nx;
    vx[iv] += wv * cx;
    vy[iv] += wv * cy;
    if (i1 >= 0) {
      vx[i0] -= w0 * beta * cx;
      vy[i0] -= w0 * beta * cy;
      vx[i1] -= w1 * alpha * cx;
      vy[i1] -= w1 * alpha * cy;
    } else {
      vx[i0] -= w0 * cx;
      vy[i0] -= w0 * cy;
    }
  }
}
