// The worker posts frames and collision events as copies, never with a transfer list: a transferred ArrayBuffer is
// detached, and in V8 the first detach in a realm slows every typed-array access of optimised code there for good
// (the engine's steps 25–33% slower: publishers.ts). Checked on the worker's own endpoint over a MessageChannel.
import { expect } from 'chai';
import { workerEndpoint } from '../../../src/worker/engine.worker.js';
import type { PortMessage } from '../../../src/worker/protocol.js';

describe('engine worker: nothing it sends is detached', () => {
  it('frames and events go as copies: no transfer list, the buffers stay attached', async () => {
    const endpoint = workerEndpoint();
    const { port1, port2 } = new MessageChannel();
    const sent: { message: PortMessage; transfer: number }[] = [];
    const post = port1.postMessage.bind(port1);
    port1.postMessage = ((message: PortMessage, transfer?: Transferable[]) => {
      sent.push({ message, transfer: transfer?.length ?? 0 });
      post(message, transfer as Transferable[]);
    }) as typeof port1.postMessage;
    const received: PortMessage[] = [];
    port2.onmessage = (e: MessageEvent<PortMessage>) => received.push(e.data);
    expect(endpoint.open(1, port1 as unknown as MessagePort, false).transport).to.equal('transfer');
    // Two boxes that land on each other: contact events to send, with every frame.
    endpoint.invoke(1, 'load', [
      {
        world: {},
        params: { events: true, gravity: { x: 0, y: 10 } },
        bodies: [
          { key: 1, desc: { type: 'box', x: 5, y: 9, width: 10, height: 1, static: true } },
          { key: 2, desc: { type: 'box', x: 5, y: 7.9, width: 1, height: 1 } },
        ],
        links: [],
      },
    ]);
    endpoint.invoke(1, 'step', [30]);
    await new Promise((resolve) => setTimeout(resolve, 50));
    const frames = sent.filter((s) => s.message.type === 'frame');
    const events = sent.filter((s) => s.message.type === 'events');
    expect(frames.length, 'frames posted').to.be.greaterThan(0);
    expect(events.length, 'event batches posted').to.be.greaterThan(0);
    for (const { message, transfer } of sent) {
      expect(transfer, `${message.type} posted with a transfer list`).to.equal(0);
      if (message.type === 'frame') expect(message.buffer.byteLength, 'frame buffer detached').to.be.greaterThan(0);
      if (message.type === 'events') expect(message.data.buffer.byteLength, 'events buffer detached').to.be.greaterThan(0);
    }
    // The page got its copies: the newest frame it received counts the steps taken.
    expect(received.some((m) => m.type === 'frame')).to.equal(true);
    endpoint.close(1);
    port2.close();
  });
});
