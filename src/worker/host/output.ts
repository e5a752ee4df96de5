import type { Topology } from '../protocol.js';

/** Where the host sends what is not a frame. */
export interface HostOutput {
  topology(topology: Topology): void;
  events(data: Float64Array, count: number): void;
}
