// Integer handles: a slot index plus a generation counter, packed into one safe integer. A handle stays valid while
// its object lives; once the object is removed its slot may be reused, but with a new generation, so the old handle
// is recognised as stale instead of silently pointing at a newcomer (the scheme of Box2D v3's ids).
import { describeValue } from './validate.js';

export type Handle = number;

const SLOT_BITS = 22;
const SLOT_COUNT = 1 << SLOT_BITS; // 4,194,304 slots per registry
const SLOT_MASK = SLOT_COUNT - 1;

export const MAX_SLOTS = SLOT_COUNT;

export function handleSlot(handle: Handle): number {
  return handle & SLOT_MASK;
}

export function handleGeneration(handle: Handle): number {
  return Math.floor(handle / SLOT_COUNT);
}

export function makeHandle(slot: number, generation: number): Handle {
  return generation * SLOT_COUNT + slot;
}

/**
 * Slot bookkeeping for one kind of object. Slots are handed out lowest-free-last (a LIFO free list), which is
 * deterministic: the same sequence of adds and removes always gives the same handles.
 */
export class HandleRegistry {
  generation = new Uint32Array(64);
  alive = new Uint8Array(64);
  /** Highest slot ever used + 1. */
  high = 0;
  private free: number[] = [];

  /** The most live objects allowed at once (a page must not freeze building a million bodies by mistake). */
  limit = SLOT_COUNT;
  private live = 0;

  constructor(readonly what: string, private readonly limitName = '', private readonly plural = `${what}s`) {}

  /** Throws the limit's RangeError unless `n` more fit (checked before making what needs them). */
  ensureRoom(n: number): void {
    if (this.live + n > this.limit) {
      throw new RangeError(`too many ${this.plural}: the limit is ${this.limit}${this.limitName ? ` (world option limits.${this.limitName})` : ''}`);
    }
  }

  allocate(): Handle {
    this.ensureRoom(1);
    this.live++;
    let slot: number;
    if (this.free.length > 0) slot = this.free.pop()!;
    else {
      if (this.high >= SLOT_COUNT) throw new RangeError(`too many ${this.what}s: the limit is ${SLOT_COUNT}`);
      slot = this.high++;
      if (slot >= this.alive.length) this.grow(Math.max(slot + 1, this.alive.length * 2));
    }
    this.alive[slot] = 1;
    return makeHandle(slot, this.generation[slot]);
  }

  release(handle: Handle): number {
    const slot = this.slotOf(handle);
    this.live--;
    this.alive[slot] = 0;
    this.generation[slot]++;
    this.free.push(slot);
    return slot;
  }

  isValid(handle: unknown): handle is Handle {
    if (typeof handle !== 'number' || !Number.isSafeInteger(handle) || handle < 0) return false;
    const slot = handleSlot(handle);
    return slot < this.high && this.alive[slot] === 1 && this.generation[slot] === handleGeneration(handle);
  }

  /** The slot of a live handle; throws a TypeError/RangeError naming `argName` otherwise. */
  slotOf(handle: unknown, argName = `${this.what} handle`): number {
    if (typeof handle !== 'number' || !Number.isSafeInteger(handle) || handle < 0) {
      throw new TypeError(`${argName} must be a ${this.what} handle (a whole number), got ${describeValue(handle)}`);
    }
    if (!this.isValid(handle)) throw new RangeError(`${argName} ${handle} is not a live ${this.what} (removed or never created)`);
    return handleSlot(handle);
  }

  handleOf(slot: number): Handle {
    return makeHandle(slot, this.generation[slot]);
  }

  private grow(capacity: number): void {
    const g = new Uint32Array(capacity);
    g.set(this.generation);
    this.generation = g;
    const a = new Uint8Array(capacity);
    a.set(this.alive);
    this.alive = a;
  }

  snapshot(): RegistrySnapshot {
    return { generation: this.generation.slice(0, this.high), alive: this.alive.slice(0, this.high), high: this.high, free: this.free.slice() };
  }

  restore(s: RegistrySnapshot): void {
    this.generation = new Uint32Array(Math.max(64, s.high));
    this.generation.set(s.generation);
    this.alive = new Uint8Array(Math.max(64, s.high));
    this.alive.set(s.alive);
    this.high = s.high;
    this.free = s.free.slice();
    this.live = s.high - s.free.length;
  }
}

export interface RegistrySnapshot {
  generation: Uint32Array;
  alive: Uint8Array;
  high: number;
  free: number[];
}
