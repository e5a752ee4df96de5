// Collision events: gathered after every step (the next step overwrites the world's), keyed by body keys, and sent
// once per published frame, only while someone listens.
import type { World } from '../../engine/index.js';
import { EVENT } from '../protocol.js';
import type { Bindings } from './bindings.js';
import type { HostOutput } from './output.js';

export class EventQueue {
  /** Events sent so far. */
  sent = 0;
  #data = new Float64Array(EVENT * 64);
  #count = 0;

  /** Appends the events of the world's last step. */
  collect(world: World, bindings: Bindings): void {
    const e = world.events;
    if (e.count === 0) return;
    const need = (this.#count + e.count) * EVENT;
    if (need > this.#data.length) {
      const grown = new Float64Array(Math.max(need, this.#data.length * 2));
      grown.set(this.#data);
      this.#data = grown;
    }
    let o = this.#count * EVENT;
    for (let k = 0; k < e.count; k++) {
      this.#data[o++] = e.type[k];
      this.#data[o++] = bindings.keyOf(e.bodyA[k]);
      this.#data[o++] = bindings.keyOf(e.bodyB[k]);
      this.#data[o++] = e.normalX[k];
      this.#data[o++] = e.normalY[k];
      this.#data[o++] = e.depth[k];
      this.#data[o++] = e.speed[k];
    }
    this.#count += e.count;
  }

  /** Sends the gathered events (when `listening`) and empties the queue. */
  flush(listening: boolean, output: Pick<HostOutput, 'events'>): void {
    if (this.#count === 0) return;
    if (listening) {
      output.events(this.#data.slice(0, this.#count * EVENT), this.#count);
      this.sent += this.#count;
    }
    this.#count = 0;
  }

  clear(): void {
    this.#count = 0;
  }
}
