// How the host hands a finished frame to the page. Three ways, one interface:
//  - 'shared':   a triple buffer in a SharedArrayBuffer (worker, page cross-origin isolated); no message per frame.
//  - 'transfer': ArrayBuffers from a small pool, transferred to the page and handed back (worker, not isolated).
//  - 'direct':   the same triple buffer over a plain ArrayBuffer (main-thread mode).
// None allocates per frame in the steady state: buffers are only made when the scene outgrows them.
import type { Transport } from './protocol.js';
import { TripleBuffer } from './triple-buffer.js';

export interface Publisher {
  readonly transport: Transport;
  /** A buffer of at least `length` floats to write the next frame into, or null to skip this frame. */
  begin(length: number): Float64Array | null;
  commit(): void;
  /** Buffers allocated so far. */
  readonly allocated: number;
  /**
   * Called when a frame that found no buffer (begin() gave null) could now be written: the host publishes its
   * current state then, so the newest state reaches the page even when nothing steps after it (a paused scene).
   */
  onFree?: (() => void) | null;
  dispose(): void;
}

/** Room for growth, so a scene that gains a body does not reallocate at once. */
function roomFor(length: number): number {
  return Math.max(1024, Math.ceil(length * 1.5));
}

export class TripleBufferPublisher implements Publisher {
  allocated = 0;
  private tb: TripleBuffer | null = null;

  /** `announce` tells the page about a new (grown) buffer. */
  constructor(
    readonly transport: 'shared' | 'direct',
    private readonly announce: (buffer: ArrayBuffer | SharedArrayBuffer) => void,
  ) {}

  begin(length: number): Float64Array {
    if (!this.tb || this.tb.capacity < length) {
      this.tb = new TripleBuffer(roomFor(length), this.transport === 'shared');
      this.allocated++;
      this.announce(this.tb.buffer);
    }
    return this.tb.begin();
  }

  commit(): void {
    this.tb!.commit();
  }

  dispose(): void {
    this.tb = null;
  }
}

/** Pool size: the page holds at most one buffer at a time (it copies and hands it back), so a few suffice. */
const POOL = 4;

export class TransferPublisher implements Publisher {
  readonly transport = 'transfer' as const;
  allocated = 0;
  private pool: ArrayBuffer[] = [];
  private capacity = 0;
  /** Buffers of the current capacity in existence (pooled or lent out). */
  private live = 0;
  private current: ArrayBuffer | null = null;
  /** A frame was skipped for want of a buffer since one last came back. */
  private starved = false;
  onFree: (() => void) | null = null;

  constructor(private readonly post: (buffer: ArrayBuffer) => void) {}

  begin(length: number): Float64Array | null {
    if (length > this.capacity) {
      this.capacity = roomFor(length);
      this.pool.length = 0;
      this.live = 0;
    }
    let buffer = this.pool.pop();
    if (!buffer) {
      if (this.live >= POOL) {
        this.starved = true;
        return null;
      }
      buffer = new ArrayBuffer(this.capacity * 8);
      this.live++;
      this.allocated++;
    }
    this.current = buffer;
    return new Float64Array(buffer);
  }

  commit(): void {
    const buffer = this.current!;
    this.current = null;
    this.post(buffer);
  }

  /** A buffer back from the page. Buffers of an outgrown size are dropped. */
  recycle(buffer: ArrayBuffer): void {
    if (buffer.byteLength === this.capacity * 8 && this.pool.length < POOL) this.pool.push(buffer);
    if (this.starved && this.pool.length > 0) {
      this.starved = false;
      this.onFree?.();
    }
  }

  dispose(): void {
    this.pool.length = 0;
    this.onFree = null;
  }
}
