// A triple buffer of frames in one (Shared)ArrayBuffer: the writer always has a slot that is neither the newest nor
// the one being read, so neither side ever waits. A sequence number says whether a newer frame exists.
// Over a SharedArrayBuffer it joins the worker and the page; over a plain ArrayBuffer it serves the main-thread mode.

const CONTROL_BYTES = 16;
const LATEST = 0;
const READING = 1;
const SEQ = 2;
const CAPACITY = 3;

export class TripleBuffer {
  readonly buffer: ArrayBuffer | SharedArrayBuffer;
  readonly capacity: number;
  private readonly control: Int32Array;
  private readonly slots: Float64Array[];
  private writing = -1;
  private lastSeq = 0;

  /** A new buffer of `capacity` floats per slot, or a view of an existing one (the reader's side). */
  constructor(source: number | ArrayBuffer | SharedArrayBuffer, shared = false) {
    if (typeof source === 'number') {
      const bytes = CONTROL_BYTES + 3 * 8 * source;
      this.buffer = shared ? new SharedArrayBuffer(bytes) : new ArrayBuffer(bytes);
      this.control = new Int32Array(this.buffer, 0, 4);
      this.control[LATEST] = -1;
      this.control[READING] = -1;
      this.control[CAPACITY] = source;
    } else {
      this.buffer = source;
      this.control = new Int32Array(this.buffer, 0, 4);
    }
    this.capacity = this.control[CAPACITY];
    this.slots = [0, 1, 2].map((k) => new Float64Array(this.buffer, CONTROL_BYTES + k * 8 * this.capacity, this.capacity));
  }

  /** Writer: a slot to fill (neither the newest nor the one being read). */
  begin(): Float64Array {
    const latest = Atomics.load(this.control, LATEST);
    const reading = Atomics.load(this.control, READING);
    let slot = 0;
    while (slot === latest || slot === reading) slot++;
    this.writing = slot;
    return this.slots[slot];
  }

  /** Writer: publishes the slot filled since begin(). Returns the new sequence number. */
  commit(): number {
    Atomics.store(this.control, LATEST, this.writing);
    this.writing = -1;
    return Atomics.add(this.control, SEQ, 1) + 1;
  }

  /** Reader: the newest frame if one was published since the last call, else null. Valid until the next call. */
  read(): Float64Array | null {
    const seq = Atomics.load(this.control, SEQ);
    if (seq === this.lastSeq) return null;
    let latest = Atomics.load(this.control, LATEST);
    if (latest < 0) return null;
    // Claim the slot, then check it is still the newest: a writer that started before the claim never writes the
    // newest slot, and every writer after the claim avoids it.
    for (;;) {
      Atomics.store(this.control, READING, latest);
      const again = Atomics.load(this.control, LATEST);
      if (again === latest) break;
      latest = again;
    }
    this.lastSeq = seq;
    return this.slots[latest];
  }
}
