import { grown } from '../table.js';
import type { ParticleStore } from '../particles.js';
import type { Contacts } from './contacts.js';
import type { RigidContacts } from '../rigid/contacts.js';
import { hit, impact, impactInSubstep } from '../impact.js';
import type { WallHits } from '../bounds.js';

/** What events and sleeping read of a contact table (the particle contacts and the rigid ones both have it). */
export interface ContactPairs {
  count: number;
  bodyA: Int32Array;
  bodyB: Int32Array;
  touched: Uint8Array;
  depth: Float64Array;
  nx: Float64Array;
  ny: Float64Array;
}
import { KeyTable } from './key-table.js';

/** The body handle events give the world's bounds (a rigid body landing on the bounds' floor: bodyB = WORLD_BOUNDS). */
export const WORLD_BOUNDS = -1;

/**
 * Collision events of the last step: a 'begin' when two bodies start touching, an 'end' when they stop. Filled
 * after each step from the contacts that acted; read them before the next step. Body fields hold body handles, and
 * bodyB WORLD_BOUNDS for a body and the world's bounds.
 */
export class CollisionEvents {
  count = 0;
  /** 0 = begin, 1 = end. */
  type = new Uint8Array(64);
  bodyA = new Float64Array(64);
  bodyB = new Float64Array(64);
  /**
   * Normal from A to B and the overlap when the contact was found, usually 0 as contacts are found before bodies
   * touch (begin events; 0 for end events).
   */
  normalX = new Float64Array(64);
  normalY = new Float64Array(64);
  depth = new Float64Array(64);
  /**
   * How fast the bodies approached along the normal where they met, at the start of the step they began touching
   * (units/s, ≥ 0; begin events; 0 for end events): how hard they hit, for a sound's volume or a score.
   */
  speed = new Float64Array(64);

  push(type: number, a: number, b: number, nx: number, ny: number, depth: number, speed: number): void {
    if (this.count === this.type.length) {
      const n = this.count * 2;
      this.type = grown(this.type, n);
      this.bodyA = grown(this.bodyA, n);
      this.bodyB = grown(this.bodyB, n);
      this.normalX = grown(this.normalX, n);
      this.normalY = grown(this.normalY, n);
      this.depth = grown(this.depth, n);
      this.speed = grown(this.speed, n);
    }
    const i = this.count++;
    this.type[i] = type;
    this.bodyA[i] = a;
    this.bodyB[i] = b;
    this.normalX[i] = nx;
    this.normalY[i] = ny;
    this.depth[i] = depth;
    this.speed[i] = speed;
  }
}

const SLOTS = 4194304;
/** The slot that stands for the world's bounds in a pair's key (after every body's). */
const WORLD = SLOTS - 1;

/** Turns the touching contacts of each step into begin/end events. */
export class EventTracker {
  /** Touching body pairs (lo · SLOTS + hi) → the deepest contact of the pair, this step and last step. */
  private current = new KeyTable();
  private previous = new KeyTable();

  /**
   * Off until someone reads the events (World.events): a world nobody asks for events pays nothing for them. From the
   * first read on, every step's events are collected.
   */
  active = false;
  /** End events of pairs whose body was removed since the last step: handle a, handle b, … (reported next step). */
  private ended: number[] = [];
  /** Every row's velocity and angular velocity at the start of the step, for the begin events' speeds. */
  private vx = new Float64Array(16);
  private vy = new Float64Array(16);
  private omega = new Float64Array(16);

  /** Notes the velocities the step starts from (while events are collected). */
  recordStartVelocities(p: ParticleStore): void {
    if (this.vx.length < p.count) {
      this.vx = grown(this.vx, p.count);
      this.vy = grown(this.vy, p.count);
      this.omega = grown(this.omega, p.count);
    }
    this.vx.set(p.vx.subarray(0, p.count));
    this.vy.set(p.vy.subarray(0, p.count));
    this.omega.set(p.omega.subarray(0, p.count));
  }

  /** Starts collecting: the pairs touching now are taken as already touching (no begin for them next step). */
  activate(c: ContactPairs, r: ContactPairs, walls: WallHits, owner: { ownerOf(i: number): number }): void {
    if (this.active) return;
    this.active = true;
    this.current.reset(c.count + r.count + walls.stepCount);
    this.collect(c, 0);
    this.collect(r, 1);
    this.collectWalls(walls, owner);
  }

  /**
   * Body `slot` (handle `handleOf(slot)` until now) is being removed: its touching pairs end, reported with the next
   * step's events under the handles they had (a page tracking which bodies touch would otherwise keep them touching),
   * and leave the table (a new body in the same slot starts afresh).
   */
  bodyRemoved(slot: number, handleOf: (slot: number) => number): void {
    if (!this.active) return;
    const table = this.current;
    for (let h = 0; h < table.keys.length; h++) {
      const key = table.keys[h];
      if (key < 0) continue;
      const lo = Math.floor(key / SLOTS);
      const hi = key - lo * SLOTS;
      if (lo !== slot && hi !== slot) continue;
      this.ended.push(handleOf(lo), hi === WORLD ? WORLD_BOUNDS : handleOf(hi));
      // A tombstone: lookups probe past it, and no pair matches it.
      table.keys[h] = -2;
    }
  }

  /**
   * The contacts of both tables that acted this step (`touched`) give the touching body pairs; `handleOf` maps a
   * body slot to its handle. A contact with the world's bounds (body −1) pairs its body with WORLD_BOUNDS, the body
   * first. Pairs whose body was removed end first, under the handles they had (bodyRemoved).
   */
  update(c: Contacts, r: RigidContacts, walls: WallHits, p: ParticleStore, motion: Float64Array, owner: { ownerOf(i: number): number }, handleOf: (slot: number) => number, alive: (slot: number) => boolean, resting: (slot: number) => boolean, out: CollisionEvents): void {
    out.count = 0;
    for (let k = 0; k < this.ended.length; k += 2) out.push(1, this.ended[k], this.ended[k + 1], 0, 0, 0, 0);
    this.ended.length = 0;
    [this.current, this.previous] = [this.previous, this.current];
    const cur = this.current;
    cur.reset(c.count + r.count + walls.stepCount);
    this.collect(c, 0);
    this.collect(r, 1);
    this.collectWalls(walls, owner);
    for (let h = 0; h < cur.keys.length; h++) {
      const key = cur.keys[h];
      if (key < 0 || this.previous.find(key) >= 0) continue;
      // Which table and row: value = row · 3 + table (2: the walls' touches, by particle).
      const v = cur.values[h];
      const table = v % 3;
      const i = (v - table) / 3;
      if (table === 2) {
        const wall = walls.stepWall[i] - 1;
        const nx = wall === 0 ? -1 : wall === 1 ? 1 : 0;
        const ny = wall === 2 ? -1 : wall === 3 ? 1 : 0;
        // Its speed at the hit, as its bounce takes it (bounds.ts): the speed toward the wall then, and gravity.
        hit[0] = walls.stepApproach[i];
        hit[1] = -(motion[0] * nx + motion[1] * ny);
        impactInSubstep(walls.stepOverlap, i, motion);
        out.push(0, handleOf(owner.ownerOf(i)), WORLD_BOUNDS, nx, ny, walls.stepOverlap[i], hit[0] < 0 ? -hit[0] : 0);
        continue;
      }
      const t = table === 0 ? c : r;
      const a = t.bodyA[i];
      const b = t.bodyB[i];
      const depth = Math.max(0, t.depth[i]);
      if (t === c) this.particleNormalSpeed(c, i, p.invMass);
      else this.rigidNormalSpeed(r, i, p.invMass);
      // Its speed at the hit: gravity over the gap at detection too (impact.ts).
      hit[1] = hit[1] * (motion[0] * t.nx[i] + motion[1] * t.ny[i]);
      hit[2] = -t.depth[i];
      hit[3] = motion[3];
      impact();
      const speed = hit[0] < 0 ? -hit[0] : 0;
      // The normal runs from A to B: the world as A turns it.
      if (a < 0) out.push(0, handleOf(b), WORLD_BOUNDS, -t.nx[i], -t.ny[i], depth, speed);
      else out.push(0, handleOf(a), b < 0 ? WORLD_BOUNDS : handleOf(b), t.nx[i], t.ny[i], depth, speed);
    }
    const prev = this.previous;
    for (let h = 0; h < prev.keys.length; h++) {
      const key = prev.keys[h];
      if (key < 0 || cur.find(key) >= 0) continue;
      const lo = Math.floor(key / SLOTS);
      const hi = key - lo * SLOTS;
      if (!alive(lo) || (hi !== WORLD && !alive(hi))) continue;
      // A pair at rest (asleep, or asleep on something static) has no contacts while it sleeps: it goes on touching.
      // A ball asleep on the floor ended its pair when another body woke, and began it again when nudged.
      if (resting(lo) && (hi === WORLD || resting(hi))) {
        cur.insert(key, -1);
        continue;
      }
      out.push(1, handleOf(lo), hi === WORLD ? WORLD_BOUNDS : handleOf(hi), 0, 0, 0, 0);
    }
  }

  /**
   * Particle contact i's normal speed at the step's start, B's vertex relative to A's edge point (negative:
   * approaching), into hit[0]; into hit[1] how much of gravity moves them apart (B's movable share less A's).
   */
  private particleNormalSpeed(c: Contacts, i: number, invMass: Float64Array): void {
    const { vx, vy } = this;
    const v = c.v[i];
    const e0 = c.e0[i];
    const e1 = c.e1[i];
    const al = e1 >= 0 ? c.solvedAlpha[i] : 0;
    const ux = vx[v] - (1 - al) * vx[e0] - (e1 >= 0 ? al * vx[e1] : 0);
    const uy = vy[v] - (1 - al) * vy[e0] - (e1 >= 0 ? al * vy[e1] : 0);
    hit[0] = ux * c.nx[i] + uy * c.ny[i];
    hit[1] = (invMass[v] > 0 ? 1 : 0) - (1 - al) * (invMass[e0] > 0 ? 1 : 0) - (e1 >= 0 && invMass[e1] > 0 ? al : 0);
  }

  /** Rigid contact i's normal speed at the step's start, B's point relative to A's, and gravity's share, into hit. */
  private rigidNormalSpeed(r: RigidContacts, i: number, invMass: Float64Array): void {
    const { vx, vy, omega } = this;
    const a = r.a[i];
    let share = invMass[a] > 0 ? -1 : 0;
    let ux = -(vx[a] - omega[a] * r.lAy[i]);
    let uy = -(vy[a] + omega[a] * r.lAx[i]);
    const b = r.b[i];
    if (b >= 0) {
      const b2 = r.b2[i];
      if (b2 >= 0) {
        const al = r.alpha[i];
        ux += (1 - al) * vx[b] + al * vx[b2];
        uy += (1 - al) * vy[b] + al * vy[b2];
        share += (1 - al) * (invMass[b] > 0 ? 1 : 0) + (invMass[b2] > 0 ? al : 0);
      } else {
        ux += vx[b] - omega[b] * r.lBy[i];
        uy += vy[b] + omega[b] * r.lBx[i];
        share += invMass[b] > 0 ? 1 : 0;
      }
    }
    hit[0] = ux * r.nx[i] + uy * r.ny[i];
    hit[1] = share;
  }

  /**
   * Adds the touching pairs of one table to `current` with their deepest contact (value row · 3 + table). A pair's
   * contacts are all in one table: the rigid narrow phase takes every pair with a rigid body.
   */
  private collect(t: ContactPairs, table: number): void {
    const cur = this.current;
    for (let i = 0; i < t.count; i++) {
      if (!t.touched[i]) continue;
      const a = t.bodyA[i] < 0 ? WORLD : t.bodyA[i];
      const b = t.bodyB[i] < 0 ? WORLD : t.bodyB[i];
      if (a === b) continue;
      const lo = a < b ? a : b;
      const hi = a < b ? b : a;
      const slot = cur.insert(lo * SLOTS + hi, i * 3 + table);
      const v = cur.values[slot];
      if (v % 3 === table && t.depth[i] > t.depth[(v - table) / 3]) cur.values[slot] = i * 3 + table;
    }
  }

  /**
   * Adds the bodies whose particles the bounds' walls pushed this step, paired with the world (value particle · 3 + 2):
   * the deepest of its particles speaks for a body, as the deepest contact does for a pair (a particle of no body
   * makes no event).
   */
  private collectWalls(walls: WallHits, owner: { ownerOf(i: number): number }): void {
    const cur = this.current;
    const overlap = walls.stepOverlap;
    for (let k = 0; k < walls.stepCount; k++) {
      const i = walls.stepList[k];
      const body = owner.ownerOf(i);
      if (body < 0) continue;
      const slot = cur.insert(body * SLOTS + WORLD, i * 3 + 2);
      const v = cur.values[slot];
      if (v % 3 === 2 && overlap[i] > overlap[(v - 2) / 3]) cur.values[slot] = i * 3 + 2;
    }
  }

  clear(): void {
    this.current.reset(0);
    this.previous.reset(0);
    this.ended.length = 0;
  }
}
