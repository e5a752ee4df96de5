import { ParticleFlag, type ParticleStore } from './particles.js';
import { BOUNCE_THRESHOLD, hit, impactInSubstep } from './impact.js';
import { grown } from './table.js';
import { setSide, type FrameBounces } from './pipeline/frame-bounces.js';

/** An axis-aligned box the particles cannot leave (Jakobsen's first collision). */
export interface Bounds {
  minX: number;
  minY: number;
  maxX: number;
  maxY: number;
}

/**
 * The particles the walls pushed back in this substep, for their bounce (bounceOffBounds): per particle and axis the
 * normal speed toward the wall when it was first pushed (NaN: not pushed), how deep, and which wall (+1 the low one,
 * −1 the high one); the particles pushed, listed.
 */
export class WallHits {
  approachX = new Float64Array(0);
  approachY = new Float64Array(0);
  overlapX = new Float64Array(0);
  overlapY = new Float64Array(0);
  sideX = new Float64Array(0);
  sideY = new Float64Array(0);
  list = new Int32Array(0);
  count = 0;
  /**
   * The step's touches, for collision events: per particle the first wall it met this step (1 + the wall: 1 low x,
   * 2 high x, 3 low y, 4 high y; 0 none), its normal speed toward it and how deep it was then; the particles listed.
   */
  stepWall = new Uint8Array(0);
  stepApproach = new Float64Array(0);
  stepOverlap = new Float64Array(0);
  stepList = new Int32Array(0);
  stepCount = 0;

  /** Forgets the last step's touches. */
  beginStep(): void {
    for (let k = 0; k < this.stepCount; k++) this.stepWall[this.stepList[k]] = 0;
    this.stepCount = 0;
  }

  /** Room for n particles (grows, never in a step that does not add particles). */
  reserve(n: number): void {
    const had = this.approachX.length;
    if (had >= n) return;
    this.stepWall = grown(this.stepWall, n);
    this.stepApproach = grown(this.stepApproach, n);
    this.stepOverlap = grown(this.stepOverlap, n);
    this.stepList = grown(this.stepList, n);
    this.approachX = grown(this.approachX, n);
    this.approachY = grown(this.approachY, n);
    this.approachX.fill(NaN, had);
    this.approachY.fill(NaN, had);
    this.overlapX = grown(this.overlapX, n);
    this.overlapY = grown(this.overlapY, n);
    this.sideX = grown(this.sideX, n);
    this.sideY = grown(this.sideY, n);
    this.list = grown(this.list, this.approachX.length);
  }
}

/**
 * Projects particles (inflated by their radius) back inside the box. Friction is Coulomb's on the step's
 * tangential motion: the tangential displacement since the substep began is cancelled up to `friction` times the
 * normal correction (static when it all fits, kinetic otherwise). The first push of a substep on each axis is noted
 * in `hits` (reserved for p.count) for the particle's bounce.
 */
export function keepInBounds(p: ParticleStore, b: Bounds, friction: number, hits: WallHits): void {
  const { x, y, px, py, radius, invMass, flags } = p;
  for (let i = 0, n = p.count; i < n; i++) {
    // A rigid body meets the walls by its shape (rigid contacts with the world), not as a circle.
    if (invMass[i] === 0 || flags[i] & ParticleFlag.Rigid) continue;
    const r = radius[i];
    let dx = 0;
    let dy = 0;
    if (x[i] < b.minX + r) dx = b.minX + r - x[i];
    else if (x[i] > b.maxX - r) dx = b.maxX - r - x[i];
    if (y[i] < b.minY + r) dy = b.minY + r - y[i];
    else if (y[i] > b.maxY - r) dy = b.maxY - r - y[i];
    if (dx === 0 && dy === 0) continue;
    if (hits.stepWall[i] === 0) {
      // The step's first touch, for the collision events (a floor before a side wall when both).
      const s = (dy !== 0 ? dy : dx) > 0 ? 1 : -1;
      hits.stepWall[i] = (dy !== 0 ? 3 : 1) + (s > 0 ? 0 : 1);
      hits.stepApproach[i] = s * (dy !== 0 ? p.vy[i] : p.vx[i]);
      hits.stepOverlap[i] = s * (dy !== 0 ? dy : dx);
      hits.stepList[hits.stepCount++] = i;
    }
    // The first push of the substep on each axis, for the bounce (written out: doubles passed to a call are boxed).
    const { approachX, approachY } = hits;
    if (approachX[i] !== approachX[i] && approachY[i] !== approachY[i]) hits.list[hits.count++] = i;
    if (dx !== 0 && approachX[i] !== approachX[i]) {
      const s = dx > 0 ? 1 : -1;
      hits.sideX[i] = s;
      approachX[i] = s * p.vx[i];
      hits.overlapX[i] = s * dx;
    }
    if (dy !== 0 && approachY[i] !== approachY[i]) {
      const s = dy > 0 ? 1 : -1;
      hits.sideY[i] = s;
      approachY[i] = s * p.vy[i];
      hits.overlapY[i] = s * dy;
    }
    x[i] += dx;
    y[i] += dy;
    if (friction > 0) {
      if (dy !== 0) x[i] -= frictionShift(x[i] - px[i], Math.abs(dy) * friction);
      if (dx !== 0) y[i] -= frictionShift(y[i] - py[i], Math.abs(dx) * friction);
    }
  }
}

/** How much of a tangential displacement `t` friction removes, given the most it may remove. */
export function frictionShift(t: number, limit: number): number {
  if (t > limit) return limit;
  if (t < -limit) return -limit;
  return t;
}

/**
 * The velocity pass of the walls, after a substep's velocities are derived: a particle the walls pushed back while
 * approaching faster than BOUNCE_THRESHOLD leaves with −e × the speed it hit with (impact()), e its body's
 * restitution (`restitution` per body slot, `ownerOf` a particle's body slot or −1: e 0, it stays as the push left
 * it, at rest along the wall's normal), and the walls' `friction` acts on the bounce's impulse. `motion` is [gx, gy,
 * h, half], gravity and the substep as impact() takes them. Clears `hits` for the next substep.
 */
export function bounceOffBounds(hits: WallHits, p: ParticleStore, owner: { ownerOf(i: number): number }, restitution: Float64Array, friction: number, motion: Float64Array, bounces: FrameBounces): void {
  wallFriction[0] = friction;
  const { approachX, approachY, sideX, sideY } = hits;
  for (let k = 0; k < hits.count; k++) {
    const i = hits.list[k];
    const body = owner.ownerOf(i);
    const e = body >= 0 ? restitution[body] : 0;
    // A particle frame's corner that hits with e = 0 stops, and its frame with it (frame-bounces.ts): stopped alone,
    // the corner stood while the rest of the frame came on, and the frame rebounded at a quarter of its approach.
    const stop = e === 0 && bounces.frameRow[i] === 1;
    // The speed each wall sends it off at (NaN: no bounce off it).
    let vx = NaN;
    let vy = NaN;
    if ((e > 0 || stop) && approachX[i] === approachX[i]) {
      hit[0] = approachX[i];
      hit[1] = sideX[i] * motion[0];
      impactInSubstep(hits.overlapX, i, motion);
      if (hit[0] < -BOUNCE_THRESHOLD) {
        if (stop) wallBounce(bounces, p, i, 0, sideX[i] > 0 ? 1 : -1, true, wallFriction);
        else vx = sideX[i] * (-e * hit[0] + hit[1]);
      }
    }
    if ((e > 0 || stop) && approachY[i] === approachY[i]) {
      hit[0] = approachY[i];
      hit[1] = sideY[i] * motion[1];
      impactInSubstep(hits.overlapY, i, motion);
      if (hit[0] < -BOUNCE_THRESHOLD) {
        if (stop) wallBounce(bounces, p, i, 1, sideY[i] > 0 ? 1 : -1, true, wallFriction);
        else vy = sideY[i] * (-e * hit[0] + hit[1]);
      }
    }
    // Coulomb's friction on a bounce's impulse, along the wall (keepInBounds' covered the push out of the overlap
    // only: a ball bouncing at 45° kept 7–12.6 of its 14.1 sideways, μ 0.5, e 1). Into a corner, what runs along
    // one wall bounces off the other.
    if (vx === vx) {
      if (friction > 0 && vy !== vy) p.vy[i] -= frictionShift(p.vy[i], friction * Math.abs(vx - p.vx[i]));
      p.vx[i] = vx;
      wallBounce(bounces, p, i, 0, sideX[i] > 0 ? 1 : -1, false, wallFriction);
    }
    if (vy === vy) {
      if (friction > 0 && vx !== vx) p.vx[i] -= frictionShift(p.vx[i], friction * Math.abs(vy - p.vy[i]));
      p.vy[i] = vy;
      wallBounce(bounces, p, i, 1, sideY[i] > 0 ? 1 : -1, false, wallFriction);
    }
    approachX[i] = NaN;
    approachY[i] = NaN;
  }
  hits.count = 0;
}

/** The walls' friction, for wallBounce (a double passed to a call V8 does not inline is boxed). */
const wallFriction = new Float64Array(1);

/**
 * Particle i's bounce off a wall on `axis` (x 0, y 1; `side` +1 the low wall), for its frame (frame-bounces.ts): at
 * the normal speed it has now, or (`stop`, e = 0) at rest along the wall's normal; `friction` [0], the walls'.
 */
function wallBounce(bounces: FrameBounces, p: ParticleStore, i: number, axis: 0 | 1, side: 1 | -1, stop: boolean, friction: Float64Array): void {
  const k = bounces.add();
  setSide(bounces, k, 0, -1, -1);
  setSide(bounces, k, 1, i, -1);
  bounces.nx[k] = axis === 0 ? side : 0;
  bounces.ny[k] = axis === 1 ? side : 0;
  bounces.target[k] = stop ? 0 : side * (axis === 0 ? p.vx[i] : p.vy[i]);
  // Friction with its stop (e = 0) only (frame-bounces.ts).
  bounces.friction[k] = stop ? friction[0] : 0;
}
