/**
 * An open-addressing hash table from integer keys (0 ≤ key < 2⁵³) to numbers, in typed arrays: what the contact
 * anchors and the collision events remember from one step to the next. Cleared and refilled every step; its arrays
 * only grow.
 */
export class KeyTable {
  keys = new Float64Array(64).fill(-1);
  values = new Float64Array(64);
  private mask = 63;
  size = 0;

  /** Empties the table, with room for `capacity` keys at no more than half load. */
  reset(capacity: number): void {
    let n = this.keys.length;
    while (n < capacity * 2) n *= 2;
    if (n !== this.keys.length) {
      this.keys = new Float64Array(n);
      this.values = new Float64Array(n);
      this.mask = n - 1;
    }
    this.keys.fill(-1);
    this.size = 0;
  }

  /** The slot holding `key`, or −1. */
  find(key: number): number {
    let h = spread(key) & this.mask;
    while (this.keys[h] !== -1) {
      if (this.keys[h] === key) return h;
      h = (h + 1) & this.mask;
    }
    return -1;
  }

  /** The slot for `key`, added with `value` if it was not there (an existing value is left as it is). */
  insert(key: number, value: number): number {
    let h = spread(key) & this.mask;
    while (this.keys[h] !== -1) {
      if (this.keys[h] === key) return h;
      h = (h + 1) & this.mask;
    }
    this.keys[h] = key;
    this.values[h] = value;
    this.size++;
    return h;
  }

  snapshot(): { keys: Float64Array; values: Float64Array } {
    return { keys: this.keys.slice(), values: this.values.slice() };
  }

  restore(s: { keys: Float64Array; values: Float64Array }): void {
    this.keys = s.keys.slice();
    this.values = s.values.slice();
    this.mask = this.keys.length - 1;
    this.size = 0;
    for (let h = 0; h < this.keys.length; h++) if (this.keys[h] !== -1) this.size++;
  }
}

/** Mixes a key's high and low 32 bits into a well-spread 32-bit hash. */
function spread(key: number): number {
  // The low and high 32 bits of a whole number below 2^53 (`>>> 0` keeps the low bits; % and a division cost twice as much).
  const lo = key >>> 0;
  const hi = (key / 4294967296) >>> 0;
  return Math.imul(lo ^ Math.imul(hi, 0x9e3779b1), 0x85ebca6b) ^ (lo >>> 15);
}
