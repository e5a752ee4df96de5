// Fault recovery with fake engines and a fake clock: the keeper's snapshots and stall probe, a restart that restores
// the last snapshot under the last drawn frame and applies later markup, and giving up past max-restarts within the
// restart window. No worker, no wall clock.
import { expect } from '@open-wc/testing';
import { RecoveryController } from '../../../src/elements/physics-scene/recovery.js';
import { EngineSession } from '../../../src/elements/physics-scene/session.js';
import type { BodyDescription } from '../../../src/engine/index.js';
import type { FramePatch, HostScene, HostSnapshot } from '../../../src/worker/protocol.js';
import { deferred, FakeClock, FakeEngine, makeHost, settle, SNAPSHOT, type FakeHost } from './fakes.js';

const box = (x: number): BodyDescription => ({ type: 'box', x, y: 1, width: 1, height: 1 }) as BodyDescription;

interface RigOptions {
  maxRestarts?: number;
  timestep?: number;
  callTimeout?: number;
  /** Sets up the engine made `index`-th (0: the first) before it is used. */
  configure?: (engine: FakeEngine, index: number) => void;
}

function rig(options: RigOptions = {}) {
  const host = makeHost();
  const clock = new FakeClock();
  const engines: FakeEngine[] = [];
  const reports: { message: string; keep: boolean }[] = [];
  const events: string[] = [];
  let scene: HostScene = { world: { bounds: null }, params: { iterations: 1 }, bodies: [{ key: 1, desc: box(1) }], links: [], running: true };
  let grab: number | null = null;
  let running = true;
  const connect = async () => {
    const engine = new FakeEngine(`engine ${engines.length + 1}`);
    options.configure?.(engine, engines.length);
    engines.push(engine);
    return engine;
  };
  const session: EngineSession = new EngineSession(host, {
    connect,
    scene: {
      prepare: () => {},
      describe: () => scene,
      loaded: () => {
        recovery.keepSnapshot();
        recovery.watch(running);
      },
      settled: () => {},
    },
    failed: (message) => reports.push({ message, keep: true }),
    refused: () => {},
  });
  const recovery: RecoveryController = new RecoveryController(host, {
    session,
    connect,
    clock,
    scene: {
      describe: () => scene,
      limits: () => ({ maxRestarts: options.maxRestarts ?? 3, timestep: options.timestep ?? 1 / 60, callTimeout: options.callTimeout ?? 8000 }),
      grab: () => grab,
      lost: () => events.push('lost'),
      resumed: () => {
        events.push('resumed');
        recovery.watch(running);
      },
      report: (message, keep) => reports.push({ message, keep }),
      refused: () => {},
    },
  });
  /** The engine's worker dies, as EngineClient reports it (its calls fail, it is disposed, onDeath). */
  const kill = (engine: FakeEngine, reason: string) => {
    engine.died = reason;
    engine.disposed = true;
    recovery.died(engine, reason);
  };
  return {
    host, clock, engines, reports, events, session, recovery, kill,
    setScene: (s: HostScene) => (scene = s),
    setGrab: (g: number | null) => (grab = g),
    setRunning: (r: boolean) => {
      running = r;
      recovery.watch(r);
    },
  };
}

describe('RecoveryController', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  async function started(options: RigOptions = {}) {
    const r = rig(options);
    host = r.host;
    document.body.append(host);
    await r.session.ready;
    await settle();
    return r;
  }

  it('while the scene steps: a snapshot about once a second; stopped stepping: one more, then no keeper', async () => {
    const r = await started();
    const [engine] = r.engines;
    // One snapshot right after the load.
    expect(engine.argsOf('snapshot').length).to.equal(1);
    expect(r.clock.pending).to.equal(1);
    // One call at a time: each answers (a settle) before the next second is up.
    for (let k = 0; k < 3; k++) {
      r.clock.advance(1000, () => engine.latestStep++);
      await settle();
    }
    expect(engine.argsOf('snapshot').length).to.equal(4);
    r.setRunning(false);
    expect(r.clock.pending).to.equal(0);
    await settle();
    expect(engine.argsOf('snapshot').length).to.equal(5);
    r.clock.advance(5000, () => engine.latestStep++);
    expect(engine.argsOf('snapshot').length).to.equal(5);
    expect(engine.probes).to.deep.equal([]);
  });

  it('no new step for 1.5 s while running: one probe with a 1 s timeout (the call timeout if shorter); steps keep it quiet', async () => {
    const r = await started({ callTimeout: 800 });
    const [engine] = r.engines;
    r.clock.advance(10000, () => engine.latestStep++);
    // The snapshot asked for on the way answers.
    await settle();
    expect(engine.probes).to.deep.equal([]);
    // Frozen: nothing for 1.5 s (the keeper looks every 250 ms), then a probe, then another 1.5 s later.
    r.clock.advance(1499);
    expect(engine.probes).to.deep.equal([]);
    r.clock.advance(1);
    expect(engine.probes).to.deep.equal([{ reason: 'no new frame for 1500 ms while running and no answer to a probe within 800 ms', timeout: 800 }]);
    r.clock.advance(1500);
    expect(engine.probes.length).to.equal(2);
  });

  it('a slow fixed step waits for three steps before probing', async () => {
    const r = await started({ timestep: 1 });
    const [engine] = r.engines;
    r.clock.advance(2999);
    expect(engine.probes).to.deep.equal([]);
    r.clock.advance(1);
    expect(engine.probes.map((p) => [p.reason, p.timeout])).to.deep.equal([['no new frame for 3000 ms while running and no answer to a probe within 1000 ms', 1000]]);
  });

  it('a snapshot still being taken is no stall: no probe while it is pending; its answer is a sign of life', async () => {
    const r = await started();
    const [engine] = r.engines;
    const answer = deferred<HostSnapshot>();
    engine.answers.snapshot = () => answer.promise;
    // Paused and running again: a snapshot of the paused state is asked for, and takes long (a very large scene).
    r.setRunning(false);
    r.setRunning(true);
    r.clock.advance(10000);
    expect(engine.probes).to.deep.equal([]);
    answer.resolve(SNAPSHOT);
    await settle();
    // Measured from the answer: 1.5 s more without a step, then the probe.
    r.clock.advance(1499);
    expect(engine.probes).to.deep.equal([]);
    r.clock.advance(1);
    expect(engine.probes.length).to.equal(1);
  });

  it('a slow snapshot spaces out the next ones (at most 5% of the time): one that took 2 s, the next 40 s later', async () => {
    const r = await started();
    const [engine] = r.engines;
    const answer = deferred<HostSnapshot>();
    engine.answers.snapshot = () => answer.promise;
    r.clock.advance(1000, () => engine.latestStep++);
    expect(engine.argsOf('snapshot').length).to.equal(2);
    r.clock.advance(2000, () => engine.latestStep++);
    answer.resolve(SNAPSHOT);
    await settle();
    r.clock.advance(37999, () => engine.latestStep++);
    expect(engine.argsOf('snapshot').length).to.equal(2);
    r.clock.advance(1, () => engine.latestStep++);
    expect(engine.argsOf('snapshot').length).to.equal(3);
  });

  it('a dead worker: reported once, a new engine restores the last snapshot under the last drawn frame, the scene resumes', async () => {
    const r = await started();
    const [first] = r.engines;
    const snapshot: HostSnapshot = { ...SNAPSHOT, bodies: [{ key: 1, desc: box(1), handle: 0, pose: [1, 1, 0] }] };
    first.answers.snapshot = () => snapshot;
    r.clock.advance(1000, () => first.latestStep++);
    await settle();
    const frame: FramePatch = { topology: 1, stepCount: 61, time: 1, positions: new Float64Array([1, 2]), velocities: null };
    first.frame = frame;
    let ready = false;
    r.kill(first, 'uncaught error in the worker: boom');
    void r.session.ready.then(() => (ready = true));
    expect(r.reports).to.deep.equal([{ message: 'engine worker died (uncaught error in the worker: boom); restarting it (attempt 1 of 3)', keep: false }]);
    expect(r.events).to.deep.equal(['lost']);
    expect(r.session.live).to.equal(null);
    // The dead engine's last frame stays drawn meanwhile.
    expect(r.session.shown).to.equal(first);
    expect(r.clock.pending).to.equal(0);
    await settle();
    const second = r.engines[1];
    expect(second.methods.slice(0, 2)).to.deep.equal(['load', 'restore']);
    expect(second.argsOf('load')[0][0]).to.deep.include({ running: false });
    expect(second.argsOf('restore')).to.deep.equal([[snapshot, frame]]);
    expect(ready).to.equal(true);
    expect(r.session.live).to.equal(second);
    expect(r.session.shown).to.equal(second);
    expect(r.events).to.deep.equal(['lost', 'resumed']);
    expect(r.recovery.restartCount).to.equal(1);
    // Watching again, and keeping snapshots of the new engine.
    expect(r.clock.pending).to.equal(1);
    expect(second.argsOf('snapshot').length).to.equal(1);
    expect(r.reports.length).to.equal(1);
  });

  it('markup changed after the snapshot wins after the restore; a grab held then is let go', async () => {
    const r = await started();
    const [first] = r.engines;
    first.answers.snapshot = () => ({
      ...SNAPSHOT,
      bodies: [{ key: 1, desc: box(1), handle: 0, pose: [] }, { key: 2, desc: box(2), handle: 1, pose: [] }],
      links: [{ key: 9, desc: { type: 'joint', a: 1, b: 2 }, handles: [], pa: 0, pb: 0 }],
    });
    r.setGrab(7);
    r.clock.advance(1000, () => first.latestStep++);
    await settle();
    // Since: body 1 moved in the markup, body 2 and the link removed, body 3 added.
    r.setScene({ world: { bounds: null }, params: { iterations: 4 }, bodies: [{ key: 1, desc: box(5) }, { key: 3, desc: box(3) }], links: [], running: true });
    r.kill(first, 'gone');
    await settle();
    const second = r.engines[1];
    expect(second.argsOf('updateBody')).to.deep.equal([[{ key: 1, desc: box(5) }], [{ key: 3, desc: box(3) }]]);
    expect(second.argsOf('removeBody')).to.deep.equal([[2]]);
    expect(second.argsOf('removeLink')).to.deep.equal([[9]]);
    expect(second.argsOf('setParams')).to.deep.equal([[{ iterations: 4 }]]);
    expect(second.argsOf('release')).to.deep.equal([[7]]);
  });

  it('a snapshot the new engine cannot restore: said so, and the scene starts again from its markup', async () => {
    const r = await started({
      configure: (engine, index) => {
        if (index === 1)
          engine.answers.restore = () => {
            throw new Error('topology mismatch');
          };
      },
    });
    const [first] = r.engines;
    r.kill(first, 'gone');
    await settle();
    const second = r.engines[1];
    expect(r.reports.map((x) => x.message)).to.deep.equal([
      'engine worker died (gone); restarting it (attempt 1 of 3)',
      'engine: the last snapshot could not be restored, the scene restarts from its markup (topology mismatch)',
    ]);
    expect(second.methods.filter((m) => m === 'load').length).to.equal(2);
    expect(r.session.live).to.equal(second);
  });

  it('past max-restarts within 60 s: exactly that many restarts, then a final report, no engine, nothing runs', async () => {
    const r = await started({ maxRestarts: 2 });
    for (let k = 0; k < 2; k++) {
      r.clock.advance(5000, () => r.engines[k].latestStep++);
      r.kill(r.engines[k], `fault ${k + 1}`);
      await settle();
      expect(r.session.live).to.equal(r.engines[k + 1]);
    }
    r.clock.advance(5000, () => r.engines[2].latestStep++);
    r.kill(r.engines[2], 'fault 3');
    await r.session.ready;
    await settle();
    expect(r.engines.length).to.equal(3);
    expect(r.reports).to.deep.equal([
      { message: 'engine worker died (fault 1); restarting it (attempt 1 of 2)', keep: false },
      { message: 'engine worker died (fault 2); restarting it (attempt 2 of 2)', keep: false },
      { message: 'engine worker died (fault 3); not restarted: 2 restarts within 60 s already, the scene is stopped', keep: true },
    ]);
    expect(r.recovery.gaveUp).to.equal(true);
    expect(r.session.engine).to.equal(null);
    // The last state stays drawn; no keeper, however long.
    expect(r.session.shown).to.equal(r.engines[2]);
    r.setRunning(true);
    expect(r.clock.pending).to.equal(0);
    r.clock.advance(120000);
    expect(r.engines.length).to.equal(3);
    // A stop (the scene removed, or its worker attribute changed) starts afresh.
    r.session.stop();
    r.recovery.reset();
    expect([r.recovery.gaveUp, r.recovery.restartCount]).to.deep.equal([false, 0]);
  });

  it('restarts count within a minute: one allowed, a second death 60 s later restarts again', async () => {
    const r = await started({ maxRestarts: 1 });
    r.kill(r.engines[0], 'first');
    await settle();
    r.clock.advance(30000, () => r.engines[1].latestStep++);
    r.clock.advance(30000, () => r.engines[1].latestStep++);
    r.kill(r.engines[1], 'second');
    await settle();
    expect(r.reports.map((x) => x.message)).to.deep.equal([
      'engine worker died (first); restarting it (attempt 1 of 1)',
      'engine worker died (second); restarting it (attempt 1 of 1)',
    ]);
    expect(r.session.live).to.equal(r.engines[2]);
    // Within the minute of that restart, the next death is the end.
    r.clock.advance(59000, () => r.engines[2].latestStep++);
    r.kill(r.engines[2], 'third');
    expect(r.reports[2]).to.deep.equal({ message: 'engine worker died (third); not restarted: 1 restart within 60 s already, the scene is stopped', keep: true });
  });

  it('max-restarts 0 never restarts', async () => {
    const r = await started({ maxRestarts: 0 });
    r.kill(r.engines[0], 'gone');
    await settle();
    expect(r.engines.length).to.equal(1);
    expect(r.reports).to.deep.equal([{ message: 'engine worker died (gone); not restarted: max-restarts is 0, the scene is stopped', keep: true }]);
  });

  it('a replacement that dies while loading: another attempt; the first dead engine stays the one drawn', async () => {
    const r: Awaited<ReturnType<typeof started>> = await started({
      configure: (engine, index) => {
        // The second engine dies before answering its load.
        if (index === 1)
          engine.answers.load = () => {
            r.kill(engine, 'second');
            throw new Error('load(): no answer, the engine worker died');
          };
      },
    });
    const [first] = r.engines;
    r.kill(first, 'first');
    await settle();
    const second = r.engines[1];
    expect(r.engines.length).to.equal(3);
    expect(r.session.live).to.equal(r.engines[2]);
    expect(r.reports.map((x) => x.message)).to.deep.equal([
      'engine worker died (first); restarting it (attempt 1 of 3)',
      'engine worker died (second); restarting it (attempt 2 of 3)',
    ]);
    expect(first.disposed && second.disposed).to.equal(true);
  });

  it('an engine that is not current (already replaced) dying is ignored; a main-thread engine has no keeper', async () => {
    const r = await started();
    const [first] = r.engines;
    r.kill(first, 'first');
    await settle();
    r.kill(first, 'again');
    expect(r.reports.length).to.equal(1);
    r.engines[1].mode = 'main';
    r.setRunning(false);
    r.setRunning(true);
    expect(r.clock.pending).to.equal(0);
  });
});
