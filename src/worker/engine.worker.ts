// The engine worker: several worlds, one EngineHost each, addressed by a world id the page chose (the page's pool puts
// many scenes in one worker). Commands come through comlink; each world's frames, topology and events go to its own
// element on a MessagePort of their own (frames as a SharedArrayBuffer triple buffer or as transferred ArrayBuffers).
import * as Comlink from 'comlink';
import { EngineHost, runningInWorker } from './engine-host.js';
import { TransferPublisher, TripleBufferPublisher, type Publisher } from './publishers.js';
import type { EngineApi, PortMessage, ReturnMessage, Transport } from './protocol.js';

/** What the worker exposes through comlink: open() makes a world on its frame port, invoke() calls it, close() ends it. */
export function workerEndpoint() {
  const worlds = new Map<number, { host: EngineHost; port: MessagePort }>();
  const close = (id: number) => {
    const world = worlds.get(id);
    if (!world) return;
    worlds.delete(id);
    world.host.dispose();
    world.port.close();
  };
  return {
    /** Makes world `id` (replacing one of that id) on its frame port; 'shared' frames need a cross-origin isolated context. */
    open(id: number, port: MessagePort, wantShared: boolean): { transport: Transport; inWorker: boolean } {
      close(id);
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
      const host = new EngineHost(publisher, {
        topology: (topology) => send({ type: 'topology', topology }),
        events: (data, count) => send({ type: 'events', data, count }, [data.buffer]),
      });
      worlds.set(id, { host, port });
      return { transport: publisher.transport, inWorker: runningInWorker() };
    },

    /** Ends world `id`: its step loop stops, its port closes (nothing when there is no such world). */
    close,

    /** Any EngineApi method of world `id` by name. */
    invoke(id: number, method: keyof EngineApi, args: unknown[]): unknown {
      const world = worlds.get(id);
      if (!world) throw new Error(`engine worker: no world ${id} (closed, or never opened)`);
      return (world.host[method] as (...a: unknown[]) => unknown)(...args);
    },

    /** The ids of the worlds this worker holds. */
    worlds(): number[] {
      return [...worlds.keys()];
    },
  };
}

export type WorkerEndpoint = ReturnType<typeof workerEndpoint>;

// The single-file build also runs this module's code on the page (its engine, for the main-thread fallback): only a
// worker exposes the endpoint.
if (runningInWorker()) Comlink.expose(workerEndpoint());
