// EngineClient against a fake worker: a MessageChannel whose far end runs the worker's own endpoint (comlink, the
// frame port, the host) on this page. What the client does with answers, frames, silence and errors, without a real
// worker.
import { expect } from '@open-wc/testing';
import { EngineClient, EngineStoppedError, TimeoutError, WorkerDiedError } from '../../src/worker/client.js';
import { FakeWorker } from './fake-worker.js';
import type { HostScene, Topology } from '../../src/worker/protocol.js';
import { waitFor } from '../elements/helpers.js';

const SCENE: HostScene = {
  world: {},
  params: { gravity: { x: 0, y: 10 } },
  bodies: [
    { key: 1, desc: { type: 'circle', x: 2, y: 1, radius: 0.5 } },
    { key: 2, desc: { type: 'box', x: 5, y: 1, width: 1, height: 1 } },
  ],
  links: [],
};

/** A polygon whose origin is not its centre of mass (an L: the centre is at 0.75, 1.25 of its points). */
const L_SHAPE: HostScene = {
  world: {},
  params: { gravity: { x: 0, y: 0 } },
  bodies: [{ key: 1, desc: { type: 'polygon', x: 4, y: 3, angle: 0.5, angularVelocity: 1, points: [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 3 }, { x: 0, y: 3 }] } }],
  links: [],
};

describe('EngineClient (fake worker)', () => {
  const clients: EngineClient[] = [];
  afterEach(() => clients.splice(0).forEach((c) => c.dispose()));

  async function start(worker: FakeWorker, options: Parameters<typeof EngineClient.start>[0] = {}) {
    const client = await EngineClient.start({ createWorker: () => worker as unknown as Worker, timeout: 2000, ...options });
    clients.push(client);
    return client;
  }

  it('drives the host behind the worker: answers, topology and frames on the frame port, poses by key', async () => {
    const topologies: Topology[] = [];
    const client = await start(new FakeWorker(true), { onTopology: (t) => topologies.push(t) });
    expect([client.mode, client.transport]).to.deep.equal(['worker', 'shared']);
    expect(await client.api.load(SCENE)).to.deep.equal([]);
    await client.synced(0);
    expect(topologies.map((t) => t.bodies.map((b) => b.key))).to.deep.equal([[1, 2]]);
    expect(client.pose(1)).to.deep.equal([2, 1, 0]);
    expect(client.pose(99)).to.equal(null);
    // Half a second of free fall: y = 1 + g t² / 2 up to the integrator's error.
    expect(await client.api.step(30)).to.equal(30);
    await client.synced(30);
    expect(client.latestStep).to.equal(30);
    expect(client.pose(1)![1]).to.be.closeTo(1 + 0.5 * 10 * 0.5 ** 2, 0.05);
    // The same calls on the main thread give the same state.
    const main = await EngineClient.start({ worker: 'none' });
    clients.push(main);
    await main.api.load(SCENE);
    await main.api.step(30);
    expect([main.mode, main.transport]).to.deep.equal(['main', 'direct']);
    expect(await main.api.stateHash()).to.equal(await client.api.stateHash());
    expect((await client.api.diagnostics()).stepCount).to.equal(30);
  });

  it('pose() answers a rigid body\'s origin (where it was described), though a frame holds its centre of mass', async () => {
    const client = await start(new FakeWorker(true));
    await client.api.load(L_SHAPE);
    await client.synced(0);
    const [x, y, angle] = client.pose(1)!;
    expect(x).to.be.closeTo(4, 1e-12);
    expect(y).to.be.closeTo(3, 1e-12);
    expect(angle).to.equal(0.5);
    // Turning about its centre of mass at 1 rad/s for half a second: the origin swings around that centre.
    await client.api.step(30);
    await client.synced(30);
    const [cx, cy] = [4 + Math.cos(0.5) * 0.75 - Math.sin(0.5) * 1.25, 3 + Math.sin(0.5) * 0.75 + Math.cos(0.5) * 1.25];
    const [x1, y1, a1] = client.pose(1)!;
    expect(a1).to.be.closeTo(1, 1e-9);
    expect(x1).to.be.closeTo(cx - (Math.cos(1) * 0.75 - Math.sin(1) * 1.25), 1e-9);
    expect(y1).to.be.closeTo(cy - (Math.sin(1) * 0.75 + Math.cos(1) * 1.25), 1e-9);
  });

  it('lastFrame() holds the newest positions and, from the two newest frames, velocities', async () => {
    const client = await start(new FakeWorker(true));
    await client.api.load(SCENE);
    await client.synced(0);
    expect(client.lastFrame()!.velocities).to.equal(null);
    await client.api.step(10);
    await client.api.step(1);
    await client.synced(11);
    const f = client.lastFrame()!;
    // Two rigid bodies: a particle each (their centres of mass), and a pose each.
    expect([f.stepCount, f.positions.length, f.poses!.length]).to.deep.equal([11, 2 * 2, 2 * 3]);
    expect(f.positions[1]).to.equal(client.pose(1)![1]);
    // Falling: about g·t downward at t = 11/60 s, nothing sideways, not turning.
    expect(f.velocities![0]).to.equal(0);
    expect(f.velocities![1]).to.be.closeTo(10 * 11 / 60, 0.2);
    expect(Array.from(f.spins!)).to.deep.equal([0, 0]);
  });

  it('synced(n) waits for the collision events sent before step n\'s frame, though a shared frame overtakes them', async () => {
    const received: number[] = [];
    const client = await start(new FakeWorker(true), { onEvents: (data, count) => received.push(count) });
    expect(client.transport).to.equal('shared');
    // Hold every events message back 100 ms: the frame of the same step is in the shared buffer long before.
    const port = (client as unknown as { link: { port: MessagePort } }).link.port;
    const deliver = port.onmessage!;
    port.onmessage = (e: MessageEvent) => (e.data.type === 'events' ? setTimeout(() => deliver.call(port, e), 100) : deliver.call(port, e));
    await client.api.load({
      world: {},
      params: { gravity: { x: 0, y: 10 }, events: true },
      bodies: [
        { key: 1, desc: { type: 'box', x: 5, y: 9.5, width: 10, height: 1, static: true } },
        { key: 2, desc: { type: 'box', x: 5, y: 8.5, width: 1, height: 1 } },
      ],
      links: [],
    });
    await client.synced(0);
    // The box rests on the floor from the start: its pair begins at the first step.
    await client.api.step(1);
    await client.synced(1);
    expect(client.latestStep).to.equal(1);
    expect(received).to.deep.equal([1]);
  });

  it('a worker that never answers at start: the main thread instead, and onError says why', async () => {
    const worker = new FakeWorker(false);
    const errors: string[] = [];
    const client = await start(worker, { timeout: 100, onError: (m) => errors.push(m) });
    expect(client.mode).to.equal('main');
    expect(errors).to.deep.equal(['engine worker failed, running on the main thread instead: the worker did not answer within 100 ms']);
    expect(worker.terminated).to.equal(true);
    expect(await client.api.load(SCENE)).to.deep.equal([]);
  });

  it('a call without an answer fails with a TimeoutError naming it; the worker is declared dead, once', async () => {
    const worker = new FakeWorker(true);
    const deaths: string[] = [];
    const client = await start(worker, { timeout: 1000, onDeath: (r) => deaths.push(r) });
    await client.api.load(SCENE);
    worker.mute = true;
    const step = client.api.step(1);
    const hash = client.api.stateHash();
    const [a, b] = await Promise.allSettled([step, hash]);
    expect(a.status === 'rejected' && a.reason).to.be.instanceOf(TimeoutError);
    expect((a as PromiseRejectedResult).reason.message).to.equal('step() did not answer within 1000 ms');
    expect(b.status === 'rejected' && b.reason).to.be.instanceOf(Error);
    expect(deaths).to.deep.equal(['step() did not answer within 1000 ms']);
    expect([client.alive, client.died, worker.terminated]).to.deep.equal([false, 'step() did not answer within 1000 ms', true]);
    let late: unknown = null;
    await client.api.step(1).catch((e) => (late = e));
    expect(late).to.be.instanceOf(WorkerDiedError);
  });

  it('an error in the worker fails pending calls with WorkerDiedError and is reported once', async () => {
    const worker = new FakeWorker(true);
    const deaths: string[] = [];
    const client = await start(worker, { onDeath: (r) => deaths.push(r) });
    await client.api.load(SCENE);
    worker.mute = true;
    const pending = client.api.step(5).catch((e) => e);
    worker.dispatchEvent(new ErrorEvent('error', { message: 'boom', cancelable: true }));
    worker.dispatchEvent(new ErrorEvent('error', { message: 'again', cancelable: true }));
    const error = await pending;
    expect(error).to.be.instanceOf(WorkerDiedError);
    expect(error.message).to.equal('step(): no answer, the engine worker died (uncaught error in the worker: boom)');
    expect(deaths).to.deep.equal(['uncaught error in the worker: boom']);
    expect(worker.terminated).to.equal(true);
  });

  it('dispose(): pending and later calls fail with EngineStoppedError', async () => {
    const worker = new FakeWorker(true);
    const client = await start(worker);
    await client.api.load(SCENE);
    worker.mute = true;
    const pending = client.api.step(1).catch((e) => e);
    client.dispose();
    expect(await pending).to.be.instanceOf(EngineStoppedError);
    expect(await client.api.step(1).catch((e) => e)).to.be.instanceOf(EngineStoppedError);
    expect(client.alive).to.equal(false);
    // Its worker, holding no other world, is terminated after the pool's grace period.
    expect(worker.terminated).to.equal(false);
    await waitFor(() => worker.terminated, 'the empty worker to be terminated');
  });
});
