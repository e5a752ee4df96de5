import { grown } from '../table.js';
import type { Contacts } from './contacts.js';
import { KeyTable } from './key-table.js';

/**
 * Collision events of the last step: a 'begin' when two bodies start touching, an 'end' when they stop. Filled
 * after each step from the contacts that acted; read them before the next step. Body fields hold body handles.
 */
export class CollisionEvents {
  count = 0;
  /** 0 = begin, 1 = end. */
  type = new Uint8Array(64);
  bodyA = new Float64Array(64);
  bodyB = new Float64Array(64);
  /** Normal from A to B and the deepest overlap seen (begin events; 0 for end events). */
  normalX = new Float64Array(64);
  normalY = new Float64Array(64);
  depth = new Float64Array(64);

  push(type: number, a: number, b: number, nx: number, ny: number, depth: number): void {
    if (this.count === this.type.length) {
      const n = this.count * 2;
      this.type = grown(this.type, n);
      this.bodyA = grown(this.bodyA, n);
      this.bodyB = grown(this.bodyB, n);
      this.normalX = grown(this.normalX, n);
      this.normalY = grown(this.normalY, n);
      this.depth = grown(this.depth, n);
    }
    const i = this.count++;
    this.type[i] = type;
    this.bodyA[i] = a;
    this.bodyB[i] = b;
    this.normalX[i] = nx;
    this.normalY[i] = ny;
    this.depth[i] = depth;
  }
}

const SLOTS = 4194304;

/** Turns the touching contacts of each step into begin/end events. */
export class EventTracker {
  /** Touching body pairs (lo · SLOTS + hi) → the deepest contact of the pair, this step and last step. */
  private current = new KeyTable();
  private previous = new KeyTable();

  /**
   * `touched[i]` says whether contact i acted this step; `handleOf` maps a body slot to its handle.
   * Pairs whose body was removed end silently (their handles are gone).
   */
  update(c: Contacts, touched: Uint8Array, handleOf: (slot: number) => number, alive: (slot: number) => boolean, out: CollisionEvents): void {
    out.count = 0;
    [this.current, this.previous] = [this.previous, this.current];
    const cur = this.current;
    cur.reset(c.count);
    for (let i = 0; i < c.count; i++) {
      if (!touched[i]) continue;
      const a = c.bodyA[i];
      const b = c.bodyB[i];
      const lo = a < b ? a : b;
      const hi = a < b ? b : a;
      const key = lo * SLOTS + hi;
      const slot = cur.insert(key, i);
      // Keep the deepest contact of the pair for the event's normal and depth.
      if (c.depth[i] > c.depth[cur.values[slot]]) cur.values[slot] = i;
    }
    for (let h = 0; h < cur.keys.length; h++) {
      const key = cur.keys[h];
      if (key === -1 || this.previous.find(key) >= 0) continue;
      const i = cur.values[h];
      out.push(0, handleOf(c.bodyA[i]), handleOf(c.bodyB[i]), c.nx[i], c.ny[i], Math.max(0, c.depth[i]));
    }
    const prev = this.previous;
    for (let h = 0; h < prev.keys.length; h++) {
      const key = prev.keys[h];
      if (key === -1 || cur.find(key) >= 0) continue;
      const lo = Math.floor(key / SLOTS);
      const hi = key - lo * SLOTS;
      if (!alive(lo) || !alive(hi)) continue;
      out.push(1, handleOf(lo), handleOf(hi), 0, 0, 0);
    }
  }

  clear(): void {
    this.current.reset(0);
    this.previous.reset(0);
  }
}
