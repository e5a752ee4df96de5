// The engine worker: one EngineHost behind comlink. Frames, topology and events go to the page on a MessagePort of
// their own (frames as a SharedArrayBuffer triple buffer or as transferred ArrayBuffers); commands come through comlink.
import * as Comlink from 'comlink';
import { EngineHost, runningInWorker } from './engine-host.js';
import { TransferPublisher, TripleBufferPublisher, type Publisher } from './publishers.js';
import type { EngineApi, PortMessage, ReturnMessage, Transport } from './protocol.js';

/** What the worker exposes through comlink: init() connects the frame port and makes the host, invoke() calls it. */
export function workerEndpoint() {
  let host: EngineHost | null = null;
  return {
    /** Connects the frame port and picks the transport: 'shared' needs a cross-origin isolated context. */
    init(port: MessagePort, wantShared: boolean): { transport: Transport; inWorker: boolean } {
      host?.dispose();
      const send = (message: PortMessage, transfer: Transferable[] = []) => port.postMessage(message, transfer);
      const shared = wantShared && typeof SharedArrayBuffer === 'function' && (globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated === true;
      let publisher: Publisher;
      if (shared) {
        publisher = new TripleBufferPublisher('shared', (buffer) => send({ type: 'shared', buffer: buffer as SharedArrayBuffer }));
      } else {
        const transfer = new TransferPublisher((buffer) => send({ type: 'frame', buffer }, [buffer]));
        port.onmessage = (e: MessageEvent<ReturnMessage>) => {
          if (e.data?.type === 'recycle') transfer.recycle(e.data.buffer);
        };
        publisher = transfer;
      }
      host = new EngineHost(publisher, {
        topology: (topology) => send({ type: 'topology', topology }),
        events: (data, count) => send({ type: 'events', data, count }, [data.buffer]),
      });
      return { transport: publisher.transport, inWorker: runningInWorker() };
    },

    /** Any EngineApi method by name. */
    invoke(method: keyof EngineApi, args: unknown[]): unknown {
      if (!host) throw new Error('engine worker: init() was not called');
      return (host[method] as (...a: unknown[]) => unknown)(...args);
    },
  };
}

export type WorkerEndpoint = ReturnType<typeof workerEndpoint>;

// The single-file build also runs this module's code on the page (its engine, for the main-thread fallback): only a
// worker exposes the endpoint.
if (runningInWorker()) Comlink.expose(workerEndpoint());
