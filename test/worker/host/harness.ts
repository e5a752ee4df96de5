// A host without a worker: a publisher that keeps every frame, an output that keeps every topology and event batch,
// and a fake clock for the step loop. Runs in Node.
import { expect } from 'chai';
import { EngineHost, type Clock } from '../../../src/worker/engine-host.js';
import { F, EVENT, HEADER, POSE, AABB, CONTACT, type Topology, type Transport } from '../../../src/worker/protocol.js';
import type { Publisher } from '../../../src/worker/publishers.js';
import type { BodyDescription } from '../../../src/engine/index.js';

/** Keeps a copy of every committed frame; `full` makes begin() refuse (every buffer in flight). */
export class RecordingPublisher implements Publisher {
  readonly transport: Transport = 'direct';
  allocated = 0;
  full = false;
  readonly frames: Float64Array[] = [];
  private current: Float64Array | null = null;

  begin(length: number): Float64Array | null {
    if (this.full) return null;
    this.current = new Float64Array(length);
    return this.current;
  }

  commit(): void {
    this.frames.push(this.current!);
    this.current = null;
  }

  dispose(): void {}
}

/** Timers run only when the test advances the time. */
export class FakeClock implements Clock {
  private time = 1000;
  private timers: { at: number; run: () => void; id: number }[] = [];
  private ids = 0;
  /** Milliseconds each reading of the clock lets pass after it (work that takes time); 0 by default. */
  readCost = 0;

  now(): number {
    const t = this.time;
    this.time += this.readCost;
    return t;
  }

  /** As Node's timers: a delay below 1 ms is 1 ms (so a loop that reschedules itself lets time pass). */
  setTimeout(run: () => void, ms: number): unknown {
    const id = ++this.ids;
    this.timers.push({ at: this.time + Math.max(1, ms), run, id });
    return id;
  }

  clearTimeout(timer: unknown): void {
    this.timers = this.timers.filter((t) => t.id !== timer);
  }

  get pending(): number {
    return this.timers.length;
  }

  /** Moves the time on by `ms`, running each timer that falls due at its own time. */
  advance(ms: number): void {
    const until = this.time + ms;
    for (;;) {
      this.timers.sort((a, b) => a.at - b.at || a.id - b.id);
      const next = this.timers[0];
      if (!next || next.at > until) break;
      this.timers.shift();
      this.time = Math.max(this.time, next.at);
      next.run();
    }
    this.time = until;
  }
}

export function makeHost() {
  const publisher = new RecordingPublisher();
  const clock = new FakeClock();
  const topologies: Topology[] = [];
  /** Every event sent, and how many batches (calls of output.events) carried them. */
  const events: number[][] = [];
  let eventBatches = 0;
  const host = new EngineHost(publisher, {
    topology: (t) => topologies.push(t),
    events: (data, count) => {
      eventBatches++;
      expect(data.length).to.equal(count * EVENT);
      for (let k = 0; k < count; k++) events.push(Array.from(data.subarray(k * EVENT, (k + 1) * EVENT)));
    },
  }, clock);
  return {
    host,
    publisher,
    clock,
    topologies,
    events,
    get eventBatches(): number {
      return eventBatches;
    },
    get topology(): Topology {
      return topologies[topologies.length - 1];
    },
    get frame(): Float64Array {
      return publisher.frames[publisher.frames.length - 1];
    },
  };
}
export interface DecodedFrame {
  seq: number;
  topology: number;
  stepCount: number;
  time: number;
  running: boolean;
  /** Particle positions: [x, y] per storage index. */
  positions: [number, number][];
  /** Per body in topology order: [x, y, angle]. */
  poses: [number, number, number][];
  aabbs: [number, number, number, number][];
  contacts: [number, number, number, number][];
}

/** Reads a frame by the layout in protocol.ts. */
export function decode(f: Float64Array): DecodedFrame {
  const n = f[F.particles];
  const b = f[F.bodies];
  const c = f[F.contacts];
  const debug = f[F.debug] === 1;
  const take = (o: number, count: number, width: number) => Array.from({ length: count }, (_, k) => Array.from(f.subarray(o + k * width, o + (k + 1) * width)));
  let o = HEADER;
  const positions = take(o, n, 2) as [number, number][];
  o += 2 * n;
  const poses = take(o, b, POSE) as [number, number, number][];
  o += POSE * b;
  const aabbs = (debug ? take(o, b, AABB) : []) as [number, number, number, number][];
  o += debug ? AABB * b : 0;
  const contacts = (debug ? take(o, c, CONTACT) : []) as [number, number, number, number][];
  return { seq: f[F.seq], topology: f[F.topology], stepCount: f[F.stepCount], time: f[F.time], running: f[F.running] === 1, positions, poses, aabbs, contacts };
}

/** One body of every type (and a static floor), keys 0…7. */
export const EVERY_TYPE: { key: number; desc: BodyDescription }[] = [
  { key: 0, desc: { type: 'box', x: 8, y: 8.5, width: 16, height: 1, static: true } },
  { key: 1, desc: { type: 'box', x: 4, y: 2, width: 1, height: 1, angle: 0.25 } },
  { key: 2, desc: { type: 'circle', x: 7, y: 1, radius: 0.5 } },
  { key: 3, desc: { type: 'polygon', x: 9, y: 2, points: [{ x: -1, y: -0.5 }, { x: 1, y: -0.5 }, { x: 1, y: 0.5 }, { x: -1, y: 0.5 }] } },
  { key: 4, desc: { type: 'rope', from: { x: 11, y: 1 }, to: { x: 14, y: 1 }, segments: 12, radius: 0.05 } },
  { key: 5, desc: { type: 'cloth', origin: { x: 1, y: 0.5 }, columns: 6, rows: 5, spacing: 0.3, pins: 'corners' } },
  { key: 6, desc: { type: 'softbody', center: { x: 13, y: 4 }, radius: 0.8, segments: 12, model: 'springs' } },
  { key: 7, desc: { type: 'ragdoll', x: 2, y: 5, height: 1.5 } },
];
