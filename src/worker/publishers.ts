// How the host hands a finished frame to the page. Three ways, one interface:
//  - 'shared':   a triple buffer in a SharedArrayBuffer (worker, page cross-origin isolated); no message per frame.
//  - 'transfer': each frame posted to the page as a message, a copy of the worker's one frame buffer (worker, not
//                isolated). The name is the transport's public one (physics-ready's detail); the buffers are no longer
//                transferred: see MessagePublisher.
//  - 'direct':   the same triple buffer over a plain ArrayBuffer (main-thread mode).
// None allocates per frame in the steady state in the worker: buffers are only made when the scene outgrows them.
import type { Transport } from './protocol.js';
import { TripleBuffer } from './triple-buffer.js';

export interface Publisher {
  readonly transport: Transport;
  /** A buffer of at least `length` floats to write the next frame into, or null to skip this frame. */
  begin(length: number): Float64Array | null;
  commit(): void;
  /** Buffers allocated so far. */
  readonly allocated: number;
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

/**
 * Frames as messages: the worker keeps one buffer, writes each frame into it and posts it, which copies it (a
 * structured clone). Transferring the buffer instead would detach it, and in V8 the first ArrayBuffer detached in a
 * realm (worker) slows every typed-array access of optimised code there for good: the engine's steps ran 25–33% slower
 * (S3 3.2 -> 4.0 ms, S1 0.60 -> 0.80 ms CPU per step in Node after one detach). The copy costs a memcpy of the frame
 * (a 2,000-body frame is tens of KB); the page copies what it receives into its own frame store anyway.
 */
export class MessagePublisher implements Publisher {
  readonly transport = 'transfer' as const;
  allocated = 0;
  private frame: Float64Array | null = null;

  constructor(private readonly post: (buffer: ArrayBuffer) => void) {}

  begin(length: number): Float64Array {
    if (!this.frame || this.frame.length < length) {
      this.frame = new Float64Array(roomFor(length));
      this.allocated++;
    }
    return this.frame;
  }

  commit(): void {
    this.post(this.frame!.buffer as ArrayBuffer);
  }

  dispose(): void {
    this.frame = null;
  }
}
