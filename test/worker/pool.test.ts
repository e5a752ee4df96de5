// The page's pool of engine workers, with fake workers (the real endpoint behind a MessageChannel): worlds placed in
// the least-loaded worker within the pool's size, each world its own frames and state, an empty worker terminated
// after the grace period (and reused within it), and a dead worker's worlds all told while the other worker's go on.
import { expect } from '@open-wc/testing';
import { checkWorkerFactory, EngineClient, maxWorkers, setMaxWorkers } from '../../src/worker/client.js';
import { defaultPoolSize, MAX_TIMER_MS, WorkerPool, type PoolMember } from '../../src/worker/pool.js';
import type { HostScene } from '../../src/worker/protocol.js';
import { liveResources } from '../../src/worker/resources.js';
import { waitFor } from '../elements/helpers.js';
import { FakeWorker } from './fake-worker.js';

const SCENE: HostScene = {
  world: {},
  params: { gravity: { x: 0, y: 10 } },
  bodies: [{ key: 1, desc: { type: 'circle', x: 2, y: 1, radius: 0.5 } }],
  links: [],
};

/** A pool of fake workers: `made` lists them in the order made; `answer: false` makes silent ones. */
function rig(size: number, options: { grace?: number; answer?: boolean } = {}) {
  const made: FakeWorker[] = [];
  const pool = new WorkerPool({
    createWorker: () => {
      const w = new FakeWorker(options.answer ?? true);
      made.push(w);
      return w as unknown as Worker;
    },
    size: () => size,
    grace: options.grace ?? 0,
  });
  return { pool, made };
}

describe('WorkerPool (fake workers)', () => {
  const clients: EngineClient[] = [];
  afterEach(() => clients.splice(0).forEach((c) => c.dispose()));

  async function client(pool: WorkerPool, deaths: string[] = []) {
    const c = await EngineClient.start({ pool, timeout: 2000, onDeath: (r) => deaths.push(r) });
    clients.push(c);
    return c;
  }

  it('the default size: one worker per spare core, at least 1 and at most 2; maxWorkers overrides it and checks its value', () => {
    const cores = navigator.hardwareConcurrency;
    expect(defaultPoolSize()).to.equal(Math.max(1, Math.min(2, cores - 1)));
    expect(maxWorkers()).to.equal(defaultPoolSize());
    setMaxWorkers(3);
    expect(maxWorkers()).to.equal(3);
    setMaxWorkers(null);
    expect(maxWorkers()).to.equal(defaultPoolSize());
    for (const bad of [0, -1, 1.5, Number.NaN]) {
      expect(() => setMaxWorkers(bad), String(bad)).to.throw(RangeError, /maxWorkers must be an integer of at least 1.*got/);
    }
    // Not a number at all: a TypeError, the value shown as what it is ("2" was reported as "got 2", a RangeError).
    for (const [bad, got] of [['2', 'got "2"'], [undefined, 'got undefined'], [true, 'got true'], [{}, 'got an object']] as const) {
      expect(() => setMaxWorkers(bad as unknown as number), String(bad)).to.throw(TypeError, `maxWorkers must be a number (an integer of at least 1) or null for the default, ${got}`);
    }
    expect(maxWorkers()).to.equal(defaultPoolSize());
  });

  it('a worker factory is a function or null: anything else is a TypeError naming workerFactory, or a clear fallback to the main thread', async () => {
    const f = () => new FakeWorker(true) as unknown as Worker;
    expect(checkWorkerFactory(f)).to.equal(f);
    expect(checkWorkerFactory(null)).to.equal(null);
    expect(checkWorkerFactory(undefined)).to.equal(null);
    for (const [bad, got] of [[5, 'got 5'], ['x', 'got "x"'], [{}, 'got an object'], [true, 'got true']] as const) {
      expect(() => checkWorkerFactory(bad), String(bad)).to.throw(TypeError, `workerFactory must be a function that returns a Worker, or null for the default, ${got}`);
    }
    // Given to a client (as the scene passes PhysicsSceneElement.workerFactory): the main thread, told why (it was
    // "Invalid value used as weak map key").
    const errors: string[] = [];
    const c = await EngineClient.start({ createWorker: 5 as unknown as () => Worker, timeout: 2000, onError: (m) => errors.push(m) });
    clients.push(c);
    expect(c.mode).to.equal('main');
    expect(errors).to.deep.equal(['engine worker failed, running on the main thread instead: workerFactory must be a function that returns a Worker, or null for the default, got 5']);
  });

  it('places five worlds in two workers, least-loaded first; each world keeps its own state and frames', async () => {
    const { pool, made } = rig(2);
    const cs: EngineClient[] = [];
    for (let k = 0; k < 5; k++) cs.push(await client(pool));
    expect(made.length).to.equal(2);
    expect(pool.loads).to.deep.equal([3, 2]);
    expect(cs.map((c) => c.worker)).to.deep.equal([cs[0].worker, cs[1].worker, cs[0].worker, cs[1].worker, cs[0].worker]);
    expect(new Set(made.map((w) => w.endpoint!.worlds().length))).to.deep.equal(new Set([3, 2]));
    for (const c of cs) await c.api.load(SCENE);
    // Stepping world 0 moves only world 0, though worlds 2 and 4 share its worker.
    expect(await cs[0].api.step(30)).to.equal(30);
    await cs[0].synced(30);
    const start = await cs[2].api.stateHash();
    expect(await cs[4].api.stateHash()).to.equal(start);
    expect(await cs[0].api.stateHash()).to.not.equal(start);
    expect(cs.map((c) => c.latestStep)).to.deep.equal([30, 0, 0, 0, 0]);
    expect(cs[0].pose(1)![1]).to.be.closeTo(1 + 0.5 * 10 * 0.5 ** 2, 0.05);
    expect(cs[2].pose(1)![1]).to.equal(1);
    // A running world steps on its own clock while its neighbour stays paused.
    await cs[2].api.play();
    await waitFor(() => cs[2].latestStep > 5, 'world 2 to run');
    expect((await cs[4].api.diagnostics()).running).to.equal(false);
    expect(await cs[4].api.stateHash()).to.equal(start);
  });

  it('a closed world frees its place: the next world goes to the emptier worker; the last one out ends the worker', async () => {
    const { pool, made } = rig(2);
    const [a, b, c] = [await client(pool), await client(pool), await client(pool)];
    expect(pool.loads).to.deep.equal([2, 1]);
    a.dispose();
    c.dispose();
    expect(pool.loads).to.deep.equal([1]);
    expect(made.map((w) => w.terminated)).to.deep.equal([true, false]);
    const d = await client(pool);
    expect(d.worker).to.not.equal(b.worker);
    expect(made.length).to.equal(3);
    b.dispose();
    d.dispose();
    expect(pool.workerCount).to.equal(0);
    expect(made.every((w) => w.terminated)).to.equal(true);
  });

  it('an empty worker lives on for the grace period (a new world reuses it), then it is terminated', async () => {
    const { pool, made } = rig(2, { grace: 200 });
    const before = liveResources().workers;
    (await client(pool)).dispose();
    expect([made.length, made[0].terminated, pool.workerCount]).to.deep.equal([1, false, 1]);
    const again = await client(pool);
    expect(made.length).to.equal(1);
    again.dispose();
    await waitFor(() => made[0].terminated, 'the grace period to end');
    expect(pool.workerCount).to.equal(0);
    expect(liveResources().workers).to.equal(before);
  });

  it('an error in a worker: every world in it dies with the reason, the other worker\'s worlds go on; the next world gets a new worker', async () => {
    const { pool, made } = rig(2);
    const deaths: string[][] = [[], [], [], []];
    const cs: EngineClient[] = [];
    for (let k = 0; k < 4; k++) cs.push(await client(pool, deaths[k]));
    for (const c of cs) await c.api.load(SCENE);
    const pending = cs[0].api.step(1000).catch((e: Error) => e.message);
    const event = made[0].crash('boom');
    expect(event.defaultPrevented, 'handled, not an uncaught page error').to.equal(true);
    expect(deaths).to.deep.equal([['uncaught error in the worker: boom'], [], ['uncaught error in the worker: boom'], []]);
    expect(cs.map((c) => c.alive)).to.deep.equal([false, true, false, true]);
    expect(await pending).to.match(/step\(\): no answer, the engine worker died \(uncaught error in the worker: boom\)|engine stopped/);
    expect([made[0].terminated, made[1].terminated]).to.deep.equal([true, false]);
    expect(await cs[1].api.step(3)).to.equal(3);
    expect(await cs[3].api.step(2)).to.equal(2);
    // Replacements: a new worker (there is room), not the survivor already holding two.
    const r = await client(pool);
    expect(made.length).to.equal(3);
    expect(r.worker).to.not.equal(cs[1].worker);
    expect(pool.loads).to.deep.equal([2, 1]);
  });

  it('a timeout past the longest timer delay (3e9 ms, Infinity) waits 2147483647 ms: the world opens and its calls are answered', async () => {
    const { pool } = rig(1);
    // The delays the pool and the client give their timers (a longer one overflows, and the timer fires at once).
    const delays: number[] = [];
    const real = window.setTimeout;
    window.setTimeout = ((run: TimerHandler, ms?: number, ...rest: unknown[]) => {
      delays.push(ms ?? 0);
      return real(run, ms, ...rest);
    }) as typeof window.setTimeout;
    try {
      for (const timeout of [3e9, Infinity]) {
        delays.length = 0;
        const deaths: string[] = [];
        const errors: string[] = [];
        const c = await EngineClient.start({ pool, timeout, onDeath: (r) => deaths.push(r), onError: (m) => errors.push(m) });
        clients.push(c);
        await c.api.load(SCENE);
        expect(await c.api.step(2), String(timeout)).to.equal(2);
        expect([c.mode, deaths, errors], String(timeout)).to.deep.equal(['worker', [], []]);
        expect(Math.max(...delays), String(timeout)).to.equal(MAX_TIMER_MS);
        expect(MAX_TIMER_MS).to.equal(2 ** 31 - 1);
      }
    } finally {
      window.setTimeout = real;
    }
  });

  it('a call one world got no answer to declares the worker dead for all its worlds, once each', async () => {
    const { pool, made } = rig(1);
    const deaths: string[][] = [[], []];
    const a = await EngineClient.start({ pool, timeout: 300, onDeath: (r) => deaths[0].push(r) });
    const b = await EngineClient.start({ pool, timeout: 300, onDeath: (r) => deaths[1].push(r) });
    clients.push(a, b);
    expect(a.worker).to.equal(b.worker);
    made[0].mute = true;
    const [x, y] = await Promise.allSettled([a.api.stateHash(), b.api.diagnostics()]);
    expect(x.status).to.equal('rejected');
    expect(y.status).to.equal('rejected');
    expect(deaths[0]).to.have.length(1);
    expect(deaths[0][0]).to.match(/\(\) did not answer within 300 ms$/);
    expect(deaths[1]).to.deep.equal(deaths[0]);
    expect(made[0].terminated).to.equal(true);
    expect(pool.workerCount).to.equal(0);
  });

  it('a worker that never answers: the opens waiting on it fail with a TimeoutError, it is terminated, nothing is left', async () => {
    const { pool, made } = rig(1, { answer: false });
    const member: PoolMember = { died: () => expect.fail('not opened, so never told of a death') };
    const results = await Promise.allSettled([pool.open(member, 150), pool.open(member, 150)]);
    expect(made.length).to.equal(1);
    expect(results.map((r) => r.status)).to.deep.equal(['rejected', 'rejected']);
    expect((results[0] as PromiseRejectedResult).reason.message).to.equal('the worker did not answer within 150 ms');
    expect(made[0].terminated).to.equal(true);
    expect(pool.workerCount).to.equal(0);
  });

  it('a worker that cannot be made (a strict CSP): open fails with its error and nothing is counted', async () => {
    const before = liveResources().workers;
    const pool = new WorkerPool({
      createWorker: () => {
        throw new DOMException('Refused to create a worker', 'SecurityError');
      },
      size: () => 2,
    });
    const error = await pool.open({ died: () => {} }, 1000).catch((e: Error) => e);
    expect((error as Error).message).to.equal('Refused to create a worker');
    expect([pool.workerCount, liveResources().workers]).to.deep.equal([0, before]);
  });

  it('a worker killed from outside (debugTerminate) is found by the next unanswered call, and all its worlds are told', async () => {
    const { pool, made } = rig(2);
    const deaths: string[][] = [[], [], []];
    const cs: EngineClient[] = [];
    for (let k = 0; k < 3; k++) cs.push(await EngineClient.start({ pool, timeout: 300, onDeath: (r) => deaths[k].push(r) }));
    clients.push(...cs);
    cs[0].debugTerminate();
    expect(made[0].terminated).to.equal(true);
    await cs[2].probe('no answer to a probe', 200);
    expect(deaths).to.deep.equal([['no answer to a probe'], [], ['no answer to a probe']]);
    expect(cs[1].alive).to.equal(true);
    expect(await cs[1].api.step(1)).to.equal(1);
  });
});
