// Fault recovery: a worker that is terminated, throws or hangs is found out (pending calls fail naming their method),
// reported with physics-error, replaced by a new worker and the scene restored where it was drawn last; past
// max-restarts the scene stops with a visible error. One live worker per scene throughout (each test's scene is alone
// in the page's pool; several scenes of a dying pool worker: pool.test.ts). Positions are compared at
// the moments that matter (when the death is reported, when the scene resumes), never after some wall-clock time; the
// keeper's timing itself (1.5 s without a step, a 1 s probe) is tested with a fake clock in physics-scene/recovery.
import { expect } from '@open-wc/testing';
import { PhysicsSceneElement, type PhysicsErrorDetail } from '../../src/index.js';
import { liveResources } from '../../src/worker/resources.js';
import { EngineStoppedError, TimeoutError, WorkerDiedError } from '../../src/worker/client.js';
import { mount, unmount, waitFor } from './helpers.js';

/** Tracks the workers made and still live (not terminated), by replacing the global Worker during a test. */
function trackWorkers() {
  const Real = window.Worker;
  const live = new Set<Worker>();
  let made = 0;
  class TrackedWorker extends Real {
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      made++;
      live.add(this);
    }
    override terminate(): void {
      live.delete(this);
      super.terminate();
    }
  }
  window.Worker = TrackedWorker;
  return { live, made: () => made, restore: () => (window.Worker = Real) };
}

/** Uncaught errors and unhandled rejections on the page during a test. */
function trackUncaught() {
  const seen: string[] = [];
  const onError = (e: ErrorEvent) => seen.push(`error: ${e.message}`);
  const onRejection = (e: PromiseRejectionEvent) => seen.push(`rejection: ${String(e.reason)}`);
  window.addEventListener('error', onError);
  window.addEventListener('unhandledrejection', onRejection);
  return {
    seen,
    restore: () => {
      window.removeEventListener('error', onError);
      window.removeEventListener('unhandledrejection', onRejection);
    },
  };
}

const sleep = (ms: number) => new Promise((r) => setTimeout(r, ms));

// Tall and slow, so the box is still falling after a restart: from y = 1 it reaches the floor after about 5 s.
const ATTRS = 'width="30" height="30" gravity="0 2"';
const BOX = '<physics-box id="crate" x="15" y="1" width="1" height="1"></physics-box>';

describe('fault recovery', () => {
  const timeout = PhysicsSceneElement.callTimeout;
  let scene: PhysicsSceneElement | null = null;
  let workers: ReturnType<typeof trackWorkers>;
  let uncaught: ReturnType<typeof trackUncaught>;
  let errors: PhysicsErrorDetail[];
  /** The box's y when each physics-error was fired (the dead engine's last frame) and when the scene was ready again. */
  let atError: number[];
  let atResume: Promise<number>[];

  beforeEach(async () => {
    // The page's pool ends a worker without scenes after a grace period: every test counts workers from none.
    await waitFor(() => liveResources().workers === 0, 'no engine worker left from before');
    workers = trackWorkers();
    uncaught = trackUncaught();
    errors = [];
    atError = [];
    atResume = [];
  });
  afterEach(() => {
    unmount(scene);
    scene = null;
    workers.restore();
    uncaught.restore();
    PhysicsSceneElement.callTimeout = timeout;
  });

  const mountScene = async (attrs = ATTRS, children = BOX) => {
    scene = await mount(attrs, children, {
      before: (s) =>
        s.addEventListener('physics-error', (e) => {
          errors.push(e.detail);
          const box = s.querySelector('physics-box')!;
          atError.push(box.y);
          // Read as soon as ready resolves: before any frame of the new engine's stepping can arrive.
          atResume.push(s.ready.then(() => box.y));
        }),
    });
    expect(scene.mode).to.equal('worker');
    return scene;
  };

  const errorBox = (s: PhysicsSceneElement) => s.shadowRoot!.querySelector<HTMLElement>('.error')!;

  /** Kills the worker with `fault` once the box has fallen below `y`, and checks that the scene resumes from there. */
  async function killAndResume(s: PhysicsSceneElement, fault: 'terminate' | 'throw', below: number, errorCount: number) {
    const box = s.querySelector('physics-box')!;
    await waitFor(() => box.y > below, `the box to fall below y = ${below}`);
    const stepBefore = s.stepCount;
    await s._debugFault(fault);
    await waitFor(() => errors.length === errorCount, 'physics-error');
    const yKill = atError[errorCount - 1];
    const yAfter = await atResume[errorCount - 1];
    await s.ready;
    expect(s.mode).to.equal('worker');
    // Where it was drawn last, not back at its start (y = 1) nor a second back.
    expect(yKill).to.be.above(below);
    expect(Math.abs(yAfter - yKill), `y ${yAfter} after the restart, ${yKill} at the kill`).to.be.below(0.3);
    expect(s.stepCount).to.be.at.least(stepBefore);
    // And it goes on falling.
    await waitFor(() => box.y > yAfter + 0.5, 'the box to keep falling');
    expect(s.stepCount).to.be.above(stepBefore);
    expect(workers.live.size, 'live workers').to.equal(1);
    return { yKill, yAfter };
  }

  it('a terminated worker: physics-error, a new worker, the box resumes where it was last drawn and keeps falling', async () => {
    const s = await mountScene();
    const box = s.querySelector('physics-box')!;
    expect(box.y).to.be.closeTo(1, 0.01);
    await waitFor(() => box.y > 3, 'the box to fall');
    const t0 = performance.now();
    await s._debugFault('terminate');
    // Nothing tells the page: the box stands still until the stall watch finds the worker dead.
    await sleep(100);
    const yDead = box.y;
    await sleep(200);
    expect(box.y).to.equal(yDead);
    expect(errors.length).to.equal(0);
    await waitFor(() => errors.length === 1, 'physics-error');
    // Not before 1.5 s without a step (then a probe unanswered for 1 s; later on a loaded machine).
    expect(performance.now() - t0, 'ms to notice the terminated worker').to.be.at.least(1400);
    expect(errors[0].element).to.equal(s);
    expect(errors[0].attribute).to.equal('worker');
    // Found by the stall watch's probe; or, when the worker was killed while taking a snapshot (the watch then waits
    // for it), by that call's timeout.
    expect(errors[0].message).to.match(/engine worker died \((no new frame for 1500 ms while running and no answer to a probe within 1000 ms|snapshot\(\) did not answer within \d+ ms)\); restarting it \(attempt 1 of 3\)/);
    expect(atError[0]).to.equal(yDead);
    const yAfter = await atResume[0];
    await s.ready;
    expect(s.mode).to.equal('worker');
    expect(Math.abs(yAfter - yDead), `y ${yAfter} after the restart, ${yDead} when it died`).to.be.below(0.3);
    expect(yAfter - 1).to.be.above(1.9);
    await waitFor(() => box.y > yAfter + 0.5, 'the box to keep falling');
    expect(workers.made()).to.equal(2);
    expect(workers.live.size).to.equal(1);
    expect(liveResources().workers).to.equal(1);
    // A recovered scene shows no error box (the restart was an event and a warning).
    expect(errorBox(s).hidden).to.equal(true);
    expect(errors.length).to.equal(1);
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('an exception thrown in the worker\'s step loop: physics-error naming it, a new worker, the scene resumes', async () => {
    const s = await mountScene();
    await killAndResume(s, 'throw', 2.5, 1);
    expect(errors[0].message).to.match(/engine worker died \(uncaught error in the worker: .*debug fault: the step loop threw\); restarting it \(attempt 1 of 3\)/);
    expect(workers.made()).to.equal(2);
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('a turning rigid box resumes at the angle it was drawn at last (not the snapshot\'s, up to a second older) and keeps turning', async () => {
    // 90°/s: a snapshot a second old would be 90° behind.
    const s = await mountScene('width="30" height="30" gravity="0 0"', '<physics-box id="crate" x="15" y="15" width="4" height="1" angular-velocity="90"></physics-box>');
    const box = s.querySelector('physics-box')!;
    let angleAtError = Number.NaN;
    let angleAtResume: Promise<number> | null = null;
    s.addEventListener('physics-error', () => {
      angleAtError = box.angle;
      angleAtResume = s.ready.then(() => box.angle);
    });
    await waitFor(() => box.angle > 150, 'the box to turn past 150°');
    await s._debugFault('throw');
    await waitFor(() => errors.length === 1, 'physics-error');
    const after = await angleAtResume!;
    await s.ready;
    expect(angleAtError).to.be.above(150);
    expect(Math.abs(after - angleAtError), `${after}° after the restart, ${angleAtError}° at the kill`).to.be.below(10);
    // Still turning, about its centre, at the same rate (its angular velocity came back from the two newest frames).
    const t0 = s.stepCount;
    await waitFor(() => box.angle > after + 45 && s.stepCount > t0 + 20, 'the box to keep turning');
    expect((box.angle - after) / ((s.stepCount - t0) / 60)).to.be.closeTo(90, 15);
    expect(box.x).to.be.closeTo(15, 0.01);
    expect(box.y).to.be.closeTo(15, 0.01);
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('markup changed after the last snapshot still applies after the restore; untouched bodies keep their place', async () => {
    const s = await mountScene(ATTRS, `${BOX}
      <physics-circle id="ball" x="5" y="1" radius="0.5"></physics-circle>
      <physics-box id="gone" x="25" y="1" width="1" height="1"></physics-box>`);
    const box = s.querySelector('physics-box')!;
    const ball = s.querySelector<HTMLElement & { x: number; y: number }>('physics-circle')!;
    await waitFor(() => box.y > 3, 'the box to fall');
    await s._debugFault('terminate');
    // While the dead worker is not yet found out: a body removed, one added, one moved by its markup.
    s.querySelector('#gone')!.remove();
    const added = document.createElement('physics-box');
    added.id = 'added';
    for (const [k, v] of Object.entries({ x: '20', y: '2', width: '2', height: '1' })) added.setAttribute(k, v);
    s.append(added);
    ball.setAttribute('x', '8');
    ball.setAttribute('y', '1');
    await waitFor(() => errors.length === 1, 'physics-error');
    const yAfter = await atResume[0];
    await s.ready;
    const d = await s.diagnostics();
    expect(d.bodyCount).to.equal(3);
    expect(Math.abs(yAfter - atError[0])).to.be.below(0.3);
    // The moved ball was rebuilt at its new markup position (it fell from y = 1 since), the added box is there.
    expect(ball.x).to.be.closeTo(8, 0.05);
    expect(ball.y).to.be.below(2);
    const a = added as HTMLElement & { x: number; y: number };
    expect(a.x).to.be.closeTo(20, 0.05);
    expect(a.y).to.be.within(2, 3);
    expect(errors.length).to.equal(1);
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('past max-restarts: exactly that many restarts, then a final physics-error, the error box, no worker, no more work', async () => {
    const s = await mountScene(`${ATTRS} max-restarts="2"`);
    for (let k = 1; k <= 2; k++) {
      await killAndResume(s, 'throw', 1 + 1.5 * k, k);
      expect(errors[k - 1].message).to.match(new RegExp(`restarting it \\(attempt ${k} of 2\\)`));
    }
    expect(workers.made()).to.equal(3);
    await s._debugFault('throw');
    await waitFor(() => errors.length === 3, 'the final physics-error');
    expect(errors[2].attribute).to.equal('worker');
    expect(errors[2].message).to.match(/engine worker died \(uncaught error in the worker: .*\); not restarted: 2 restarts within 60 s already, the scene is stopped/);
    const box = errorBox(s);
    expect(box.hidden).to.equal(false);
    expect(box.textContent).to.match(/not restarted: 2 restarts within 60 s/);
    expect(s.mode).to.equal(null);
    await s.ready;
    // Stopped, and saying so: not running, and every engine call rejects with an EngineStoppedError.
    expect(s.running).to.equal(false);
    for (const call of [() => s.step(1), () => s.reset(), () => s.stateHash(), () => s.diagnostics(), () => s.snapshot()]) {
      const error = await call().then(() => null, (e: unknown) => e);
      expect(error, String(call)).to.be.instanceOf(EngineStoppedError);
      expect((error as Error).message).to.match(/is stopped: its engine failed/);
    }
    // Nothing happens any more: no restart, no worker, no pending call, no drawing.
    const drawn = s.renderedFrames;
    await sleep(2600);
    expect(errors.length).to.equal(3);
    expect(workers.made()).to.equal(3);
    expect(workers.live.size).to.equal(0);
    expect(liveResources()).to.deep.include({ workers: 0, hosts: 0, pendingCalls: 0 });
    expect(s.renderedFrames - drawn).to.be.at.most(1);
    expect(uncaught.seen).to.deep.equal([]);
    // Put in the page again (later than the same task, which is a move that keeps what it has), it starts afresh.
    const parent = s.parentElement!;
    s.remove();
    await sleep(0);
    parent.append(s);
    await s.ready;
    expect(await s.step(2)).to.be.greaterThan(0);
    expect(s.running).to.equal(true);
  });

  it('stopped after its engine failed, put in the page again starts afresh, also when moved within one task', async () => {
    // A move in one task keeps a running engine; a stopped scene's move used to start a new engine but leave the scene
    // stopped: physics-ready again, step() working, yet running false, no stepping of its own and the error box up.
    const s = await mountScene(`${ATTRS} max-restarts="0"`);
    const parent = s.parentElement!;
    for (const move of ['in one task', 'a task later']) {
      const failed = errors.length + 1;
      await s._debugFault('throw');
      await waitFor(() => errors.length === failed, 'the physics-error');
      expect(errors[failed - 1].message, move).to.match(/the scene is stopped/);
      expect(s.running, move).to.equal(false);
      s.remove();
      if (move === 'a task later') await sleep(0);
      parent.append(s);
      await s.ready;
      expect(s.mode, move).to.equal('worker');
      expect(s.running, move).to.equal(true);
      expect(errorBox(s).hidden, move).to.equal(true);
      const stepped = s.stepCount;
      await waitFor(() => s.stepCount > stepped + 5, `stepping of its own after a move ${move}`);
    }
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('a hung worker: a call fails with a TimeoutError naming it within callTimeout, others with WorkerDiedError; then a restart', async () => {
    // The default callTimeout (8 s): it is also how long a worker may take to start, which a loaded machine may need
    // (a shorter one would fail the start of the next worker, not the hung call).
    const ms = PhysicsSceneElement.callTimeout;
    const s = await mountScene();
    const box = s.querySelector('physics-box')!;
    await waitFor(() => box.y > 2, 'the box to fall');
    // Paused, the scene makes no calls of its own (snapshots, probes): the two below are the only ones pending.
    s.pause();
    await waitFor(() => liveResources().pendingCalls === 0, 'no pending call');
    await s._debugFault('hang');
    await sleep(100);
    const t0 = performance.now();
    const hash = s.stateHash().then(() => null, (e: unknown) => e);
    const diagnostics = s.diagnostics().then(() => null, (e: unknown) => e);
    const e1 = await hash;
    const elapsed = performance.now() - t0;
    const e2 = await diagnostics;
    expect(e1).to.be.instanceOf(TimeoutError);
    expect((e1 as Error).message).to.equal(`stateHash() did not answer within ${ms} ms`);
    expect(elapsed).to.be.at.least(ms - 50);
    expect(e2).to.be.instanceOf(WorkerDiedError);
    expect((e2 as Error).message).to.equal(`diagnostics(): no answer, the engine worker died (stateHash() did not answer within ${ms} ms)`);
    await waitFor(() => errors.length === 1, 'physics-error');
    expect(errors[0].message).to.equal(`engine worker died (stateHash() did not answer within ${ms} ms); restarting it (attempt 1 of 3)`);
    // The hung worker is terminated (it does not spin on), and the new one answers, still paused where it was.
    await s.ready;
    await waitFor(() => workers.live.size === 1, 'one live worker (the new one)');
    expect(await s.stateHash()).to.match(/\S/);
    const y = box.y;
    expect(y).to.be.above(2);
    s.play();
    const step = s.stepCount;
    await waitFor(() => s.stepCount > step + 10, 'the scene to step again');
    expect(box.y).to.be.above(y);
    expect(uncaught.seen).to.deep.equal([]);
  });

  it('a snapshot taken before the first step restores a world that moves (the state kept right after load)', async () => {
    const s = await mountScene(`${ATTRS} paused`);
    const box = s.querySelector('physics-box')!;
    const snap = await s.snapshot();
    await s.step(30);
    await s.restore(snap);
    expect(s.stepCount).to.equal(0);
    await s.step(60);
    // One second at g = 2 from rest: about 1 unit down.
    expect(box.y).to.be.closeTo(2, 0.1);
  });

  it('the number of live workers stays one per scene through repeated restarts, and zero once removed', async () => {
    const s = await mountScene(`${ATTRS} max-restarts="5"`);
    const faults = ['throw', 'terminate', 'throw'] as const;
    for (let k = 0; k < faults.length; k++) {
      await killAndResume(s, faults[k], 1.6 + 0.6 * k, k + 1);
      expect(workers.live.size, `live workers after restart ${k + 1}`).to.equal(1);
      expect(liveResources().workers).to.equal(1);
      expect(workers.made()).to.equal(k + 2);
    }
    unmount(s);
    scene = null;
    await waitFor(() => workers.live.size === 0, 'the last worker to be terminated');
    expect(liveResources()).to.deep.include({ workers: 0, pendingCalls: 0 });
    expect(uncaught.seen).to.deep.equal([]);
  });
});
