// The engine session on its own, with fake engines: the start (prepare, connect, describe, load, ready) in tasks of
// its own after a paint, a stop in the middle of a start, where failed calls go, and the running state sent once per
// change.
import { expect } from '@open-wc/testing';
import { afterPaint, EngineSession, type Engine } from '../../../src/elements/physics-scene/session.js';
import { EngineStoppedError, TimeoutError, WorkerDiedError } from '../../../src/worker/client.js';
import type { HostError, HostScene } from '../../../src/worker/protocol.js';
import { deferred, FakeEngine, makeHost, settle, type FakeHost } from './fakes.js';

const SCENE: HostScene = { world: { bounds: null }, params: { iterations: 2 }, bodies: [], links: [], running: true };

/**
 * A session on a fake host; `wait` stands for the paint and the task a start waits for (default: none), `nearby` for
 * the scene coming near the viewport (default: none; `demand` is logged); `warm`: log the drawing library's warm-up.
 */
function rig(connect: () => Promise<Engine> = async () => new FakeEngine(), wait: (before: 'canvas' | 'engine') => Promise<void> = async () => {}, nearby?: () => Promise<void>, warm = false) {
  const host = makeHost();
  const log: string[] = [];
  const failed: string[] = [];
  const refused: HostError[] = [];
  const loaded: { engine: Engine; errors: HostError[] }[] = [];
  const session = new EngineSession(host, {
    nearby: nearby && (() => {
      log.push('wait until near');
      return nearby();
    }),
    demand: () => log.push('demand'),
    warm: warm ? () => log.push('warm') : undefined,
    wait: (before) => {
      log.push(`wait for ${before}`);
      return wait(before);
    },
    connect: () => {
      log.push('connect');
      return connect();
    },
    scene: {
      prepare: () => log.push('prepare'),
      describe: () => {
        log.push('describe');
        return SCENE;
      },
      loaded: (engine, errors) => {
        log.push('loaded');
        loaded.push({ engine, errors });
      },
      settled: () => log.push('settled'),
    },
    failed: (message) => failed.push(message),
    refused: (e) => refused.push(e),
  });
  return { host, session, log, failed, refused, loaded };
}

describe('EngineSession', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  it('starts when the host connects: prepare, connect, describe, load; then loaded and ready, with the refusals', async () => {
    const engine = new FakeEngine();
    const refusal: HostError = { key: 3, field: 'radius', message: 'must be > 0' };
    engine.answers.load = () => [refusal];
    const r = rig(async () => engine);
    host = r.host;
    expect(r.session.idle).to.equal(true);
    document.body.append(host);
    expect(r.session.idle).to.equal(false);
    await r.session.ready;
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine', 'connect', 'describe', 'loaded', 'settled']);
    expect(engine.argsOf('load')).to.deep.equal([[SCENE]]);
    expect(r.loaded).to.deep.equal([{ engine, errors: [refusal] }]);
    expect(r.session.live).to.equal(engine);
    expect(r.session.shown).to.equal(engine);
    expect(r.session.generation).to.equal(1);
    expect(await r.session.whenReady()).to.equal(engine);
  });

  it('waits until the scene is near the viewport before anything (canvas, engine); whenReady() asks for the scene', async () => {
    const near = deferred<void>();
    const r = rig(undefined, undefined, () => near.promise);
    host = r.host;
    document.body.append(host);
    await settle();
    expect(r.log).to.deep.equal(['wait until near']);
    const engine = r.session.whenReady();
    expect(r.log).to.deep.equal(['wait until near', 'demand']);
    near.resolve();
    expect(await engine).to.not.equal(null);
    expect(r.log).to.deep.equal(['wait until near', 'demand', 'wait for canvas', 'prepare', 'wait for engine', 'connect', 'describe', 'loaded', 'settled']);
    // A scene that left the document while it waited: its start is stale and ends without an engine.
    const far = deferred<void>();
    const other = rig(undefined, undefined, () => far.promise);
    document.body.append(other.host);
    await settle();
    other.host.remove();
    other.session.stop();
    far.resolve();
    await settle();
    expect(other.log).to.deep.equal(['wait until near']);
    expect(other.session.engine).to.equal(null);
  });

  it('a stop while the engine is being made: that engine is disposed, nothing loads, callers of ready go on', async () => {
    const made = deferred<Engine>();
    const r = rig(() => made.promise);
    host = r.host;
    document.body.append(host);
    const ready = r.session.ready;
    await settle();
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine', 'connect']);
    r.session.stop();
    await ready;
    const engine = new FakeEngine();
    made.resolve(engine);
    await settle();
    expect(engine.disposed).to.equal(true);
    expect(engine.calls).to.deep.equal([]);
    expect(r.session.engine).to.equal(null);
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine', 'connect']);
    // The next ready waits for a new start.
    let next = false;
    void r.session.ready.then(() => (next = true));
    await settle();
    expect(next).to.equal(false);
  });

  it('waits before the canvas and again before the engine; a stop or a removal while it waits ends the start', async () => {
    const canvas = deferred<void>();
    const engineWait = deferred<void>();
    const r = rig(undefined, (before) => (before === 'canvas' ? canvas.promise : engineWait.promise));
    host = r.host;
    document.body.append(host);
    await settle();
    expect(r.log).to.deep.equal(['wait for canvas']);
    canvas.resolve();
    await settle();
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine']);
    engineWait.resolve();
    await r.session.ready;
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine', 'connect', 'describe', 'loaded', 'settled']);

    // Removed while waiting for the paint: no canvas, no engine.
    const paint = deferred<void>();
    const s = rig(undefined, () => paint.promise);
    document.body.append(s.host);
    await settle();
    s.host.remove();
    paint.resolve();
    await settle();
    expect(s.log).to.deep.equal(['wait for canvas', 'settled']);
    expect(s.session.engine).to.equal(null);
    // Stopped while waiting for the engine's turn: none is made.
    const turn = deferred<void>();
    const t = rig(undefined, (before) => (before === 'canvas' ? Promise.resolve() : turn.promise));
    document.body.append(t.host);
    await settle();
    t.session.stop();
    turn.resolve();
    await settle();
    expect(t.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine']);
    expect(t.session.engine).to.equal(null);
    t.host.remove();
  });

  it('warms the drawing library up in the task before the wait for the canvas, so the two are not one long task', async () => {
    const near = deferred<void>();
    const canvas = deferred<void>();
    const r = rig(undefined, (before) => (before === 'canvas' ? canvas.promise : Promise.resolve()), () => near.promise, true);
    host = r.host;
    document.body.append(host);
    await settle();
    expect(r.log).to.deep.equal(['wait until near']);
    near.resolve();
    await settle();
    expect(r.log).to.deep.equal(['wait until near', 'warm', 'wait for canvas']);
    canvas.resolve();
    await r.session.ready;
    expect(r.log.slice(0, 4)).to.deep.equal(['wait until near', 'warm', 'wait for canvas', 'prepare']);
  });

  it('afterPaint() resolves after the next animation frame, in a task of its own', async () => {
    const order: string[] = [];
    const done = afterPaint().then(() => order.push('after paint'));
    requestAnimationFrame(() => order.push('frame'));
    await done;
    expect(order).to.deep.equal(['frame', 'after paint']);
  });

  it('a host not in the document when its start comes round makes no engine', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    host.remove();
    await r.session.ready;
    expect(r.log).to.deep.equal(['settled']);
    expect(r.session.engine).to.equal(null);
    // Out of the page, a call has no engine coming: it fails at once (it waited for ever before).
    const error = await r.session.running('step()').then(() => null, (e: Error) => e);
    expect([error?.name, error?.message]).to.deep.equal(['EngineStoppedError', '<x-fake-host> is not in the page: add it, then call step()']);
  });

  it('routes what commands answer: a refusal to refused(), an engine error to failed(), a dead or stopped engine nowhere', async () => {
    const engine = new FakeEngine();
    const r = rig(async () => engine);
    host = r.host;
    document.body.append(host);
    await r.session.ready;
    const refusal: HostError = { key: 1, field: 'width', message: 'must be > 0' };
    engine.answers.updateBody = () => refusal;
    engine.answers.removeBody = () => {
      throw new Error('no such body');
    };
    engine.answers.removeLink = () => {
      throw new WorkerDiedError('removeLink(): the engine worker died');
    };
    engine.answers.applyImpulse = () => {
      throw new EngineStoppedError('engine stopped (applyImpulse)');
    };
    engine.answers.setVelocity = () => {
      throw new TimeoutError('setVelocity() did not answer within 8000 ms');
    };
    r.session.send('updateBody', { key: 1, desc: { type: 'box', x: 0, y: 0, width: 0, height: 1 } });
    r.session.send('removeBody', 4);
    r.session.send('removeLink', 5);
    r.session.send('applyImpulse', 1, 1, 0);
    r.session.send('setVelocity', 1, 1, 0);
    await settle();
    expect(r.refused).to.deep.equal([refusal]);
    // A timeout in a worker is its death (reported once, by recovery); on the main thread it is an engine error.
    expect(r.failed).to.deep.equal(['engine: no such body']);
    engine.mode = 'main';
    r.session.send('setVelocity', 1, 1, 0);
    await settle();
    expect(r.failed).to.deep.equal(['engine: no such body', 'engine: setVelocity() did not answer within 8000 ms']);
  });

  it('a load that fails is reported, and ready still resolves', async () => {
    const engine = new FakeEngine();
    engine.answers.load = () => {
      throw new Error('bad scene');
    };
    const r = rig(async () => engine);
    host = r.host;
    document.body.append(host);
    await r.session.ready;
    expect(r.failed).to.deep.equal(['engine: bad scene']);
    expect(r.log).to.deep.equal(['wait for canvas', 'prepare', 'wait for engine', 'connect', 'describe', 'settled']);
  });

  it('tells the engine to run or not once per change, starting from what the load said', async () => {
    const engine = new FakeEngine();
    const r = rig(async () => engine);
    host = r.host;
    document.body.append(host);
    await r.session.ready;
    // The load said running: true.
    expect(r.session.setRunning(true)).to.equal(false);
    expect(r.session.setRunning(false)).to.equal(true);
    expect(r.session.setRunning(false)).to.equal(false);
    expect(r.session.setRunning(true)).to.equal(true);
    await settle();
    expect(engine.methods.filter((m) => m === 'play' || m === 'pause')).to.deep.equal(['pause', 'play']);
    r.session.stop();
    expect(r.session.setRunning(false)).to.equal(false);
    expect(engine.disposed).to.equal(true);
  });

  it('suspend, adopt, resume: the dead engine stays shown until the new one has the scene; ready waits meanwhile', async () => {
    const first = new FakeEngine('first');
    const r = rig(async () => first);
    host = r.host;
    document.body.append(host);
    await r.session.ready;
    const shown = r.session.suspend(first);
    expect(shown).to.equal(first);
    expect([r.session.engine, r.session.live, r.session.shown]).to.deep.equal([null, null, first]);
    let ready = false;
    void r.session.ready.then(() => (ready = true));
    const second = new FakeEngine('second');
    r.session.adopt(second);
    expect([r.session.engine, r.session.live]).to.deep.equal([second, null]);
    // The replacement died too: the first dead engine stays the one shown, the second is disposed.
    expect(r.session.suspend(second)).to.equal(first);
    expect(second.disposed).to.equal(true);
    const third = new FakeEngine('third');
    r.session.adopt(third);
    await settle();
    expect(ready).to.equal(false);
    r.session.resume();
    await settle();
    expect(ready).to.equal(true);
    expect([r.session.live, r.session.shown]).to.deep.equal([third, third]);
    expect(first.disposed).to.equal(true);
  });
});
