// A stand-in for the engine worker: a MessageChannel whose far end runs the worker's own endpoint (comlink, the frame
// ports, a host per world) on this page. Tests make it fall silent, throw or vanish without a real worker.
import * as Comlink from 'comlink';
import { workerEndpoint } from '../../src/worker/engine.worker.js';

/** Looks like a Worker to the client and the pool. `mute` drops every message from then on (a hung worker). */
export class FakeWorker extends EventTarget {
  mute = false;
  terminated = false;
  readonly port: MessagePort;
  /** The endpoint behind it (null for a worker that never answers). */
  readonly endpoint: ReturnType<typeof workerEndpoint> | null;

  constructor(answer: boolean) {
    super();
    const channel = new MessageChannel();
    this.port = channel.port1;
    this.port.onmessage = (e) => {
      if (!this.mute) this.dispatchEvent(new MessageEvent('message', { data: e.data }));
    };
    this.endpoint = answer ? workerEndpoint() : null;
    if (this.endpoint) Comlink.expose(this.endpoint, channel.port2);
  }

  postMessage(data: unknown, transfer: Transferable[] = []): void {
    if (!this.mute) this.port.postMessage(data, transfer);
  }

  terminate(): void {
    this.terminated = true;
    this.mute = true;
    this.port.close();
  }

  /** An uncaught error inside it, as the browser reports one. */
  crash(message: string): ErrorEvent {
    const event = new ErrorEvent('error', { message, cancelable: true });
    this.dispatchEvent(event);
    return event;
  }
}
