// Removing a scene terminates its worker (the page's pool ends a worker without scenes after its grace period);
// connect/disconnect cycles leave no worker, timer, frame callback, listener, observer or p5 sketch behind.
import { expect } from '@open-wc/testing';
import p5 from 'p5';
import { EngineStoppedError, type PhysicsSceneElement } from '../../src/index.js';
import { liveResources } from '../../src/worker/resources.js';
import { frames, mount, unmount, waitFor } from './helpers.js';

/** Counts workers made and terminated, by replacing the global Worker for the duration of a test. */
function countWorkers() {
  const Real = window.Worker;
  const counts = { made: 0, terminated: 0, most: 0 };
  class CountingWorker extends Real {
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      counts.made++;
      counts.most = Math.max(counts.most, counts.made - counts.terminated);
    }
    override terminate(): void {
      counts.terminated++;
      super.terminate();
    }
  }
  window.Worker = CountingWorker;
  return { counts, restore: () => (window.Worker = Real) };
}

/** Tracks pending timeouts, intervals, animation frames and window/document listeners added from now on. */
function trackGlobals() {
  const timers = new Set<number>();
  const intervals = new Set<number>();
  const rafs = new Set<number>();
  const listeners = new Set<{ target: EventTarget; type: string; listener: unknown; capture: boolean; signal?: AbortSignal }>();
  const orig = {
    setTimeout: window.setTimeout,
    clearTimeout: window.clearTimeout,
    setInterval: window.setInterval,
    clearInterval: window.clearInterval,
    raf: window.requestAnimationFrame,
    caf: window.cancelAnimationFrame,
    add: EventTarget.prototype.addEventListener,
    remove: EventTarget.prototype.removeEventListener,
  };
  window.setTimeout = ((fn: TimerHandler, ms?: number, ...rest: unknown[]) => {
    const id: number = orig.setTimeout.call(window, (...a: unknown[]) => {
      timers.delete(id);
      if (typeof fn === 'function') fn(...a);
    }, ms, ...rest);
    timers.add(id);
    return id;
  }) as typeof window.setTimeout;
  window.clearTimeout = ((id?: number) => {
    if (id !== undefined) timers.delete(id);
    orig.clearTimeout.call(window, id);
  }) as typeof window.clearTimeout;
  window.setInterval = ((fn: TimerHandler, ms?: number, ...rest: unknown[]) => {
    const id: number = orig.setInterval.call(window, fn, ms, ...rest);
    intervals.add(id);
    return id;
  }) as typeof window.setInterval;
  window.clearInterval = ((id?: number) => {
    if (id !== undefined) intervals.delete(id);
    orig.clearInterval.call(window, id);
  }) as typeof window.clearInterval;
  window.requestAnimationFrame = (cb) => {
    const id = orig.raf.call(window, (t) => {
      rafs.delete(id);
      cb(t);
    });
    rafs.add(id);
    return id;
  };
  window.cancelAnimationFrame = (id) => {
    rafs.delete(id);
    orig.caf.call(window, id);
  };
  const global = (t: EventTarget) => t === window || t === document;
  EventTarget.prototype.addEventListener = function (this: EventTarget, type: string, listener: unknown, options?: unknown) {
    if (global(this) && listener) {
      const capture = typeof options === 'boolean' ? options : Boolean((options as AddEventListenerOptions | undefined)?.capture);
      listeners.add({ target: this, type, listener, capture, signal: (options as AddEventListenerOptions | undefined)?.signal });
    }
    return orig.add.call(this, type, listener as EventListener, options as AddEventListenerOptions);
  };
  EventTarget.prototype.removeEventListener = function (this: EventTarget, type: string, listener: unknown, options?: unknown) {
    if (global(this)) {
      const capture = typeof options === 'boolean' ? options : Boolean((options as EventListenerOptions | undefined)?.capture);
      for (const l of listeners) if (l.target === this && l.type === type && l.listener === listener && l.capture === capture) listeners.delete(l);
    }
    return orig.remove.call(this, type, listener as EventListener, options as EventListenerOptions);
  };
  return {
    pending: () => ({ timers: timers.size, intervals: intervals.size, frames: rafs.size, listeners: [...listeners].filter((l) => !l.signal?.aborted).map((l) => l.type) }),
    restore: () => {
      window.setTimeout = orig.setTimeout;
      window.clearTimeout = orig.clearTimeout;
      window.setInterval = orig.setInterval;
      window.clearInterval = orig.clearInterval;
      window.requestAnimationFrame = orig.raf;
      window.cancelAnimationFrame = orig.caf;
      EventTarget.prototype.addEventListener = orig.add;
      EventTarget.prototype.removeEventListener = orig.remove;
    },
  };
}

const CHILDREN = `<physics-box x="5" y="9" width="10" height="1" static></physics-box><physics-circle x="5" y="2" radius="0.5"></physics-circle><physics-cloth x="1" y="1" columns="5" rows="4"></physics-cloth>`;

function allZero(): boolean {
  const r = liveResources();
  return r.workers === 0 && r.hosts === 0 && r.sketches === 0 && r.observers === 0 && r.pendingCalls === 0;
}

describe('<physics-scene> lifecycle', () => {
  it('removing the element terminates its worker', async () => {
    const w = countWorkers();
    try {
      const scene = await mount('width="10" height="10"', CHILDREN);
      expect(scene.mode).to.equal('worker');
      expect(w.counts.made).to.equal(1);
      expect(liveResources().workers).to.equal(1);
      expect(liveResources().sketches).to.equal(1);
      unmount(scene);
      await waitFor(() => w.counts.terminated === 1, 'the worker to be terminated');
      expect(liveResources()).to.deep.include({ workers: 0, sketches: 0, observers: 0 });
      // Moving a scene (disconnect and connect in one task) keeps its engine.
      const moved = await mount('width="10" height="10"', CHILDREN);
      const box = moved.parentElement!;
      document.body.append(document.createElement('div'));
      document.body.lastElementChild!.append(moved);
      await frames(2);
      expect(w.counts.made).to.equal(2);
      expect(w.counts.terminated).to.equal(1);
      expect(moved.mode).to.equal('worker');
      box.remove();
      moved.parentElement!.remove();
      await waitFor(() => w.counts.terminated === 2, 'the moved scene\'s worker to be terminated');
    } finally {
      w.restore();
    }
  });

  it('50 connect/disconnect cycles leave no worker, timer, frame callback, listener, observer or sketch behind', async () => {
    const w = countWorkers();
    const g = trackGlobals();
    const p5Hooks = () => (p5 as unknown as { lifecycleHooks: { remove: unknown[] } }).lifecycleHooks.remove.length;
    const hooksBefore = p5Hooks();
    try {
      let ready = 0;
      for (let k = 0; k < 50; k++) {
        const worker = k % 2 === 0 ? 'auto' : 'none';
        const stage = Math.floor(k / 2) % 4;
        const scene: PhysicsSceneElement = await mount(`width="10" height="10" worker="${worker}"`, CHILDREN, { ready: false, width: 120, height: 120 });
        // Leave at once, after a frame (the start still waits for its turn), once the engine is made (maybe still
        // loading), or once running: every stage of the start must clean up.
        if (stage === 1) await frames(1);
        if (stage === 2) await waitFor(() => scene.client !== null, 'the engine made');
        if (stage === 3) {
          await scene.ready;
          if (scene.mode) ready++;
        }
        unmount(scene);
        await Promise.resolve();
      }
      expect(ready).to.be.greaterThan(10);
      await waitFor(() => allZero() && w.counts.terminated === w.counts.made, 'every resource to be released');
      // Let stray callbacks fire, then check that nothing is pending.
      await new Promise((r) => setTimeout(r, 150));
      await frames(2);
      expect(liveResources()).to.deep.equal({ workers: 0, hosts: 0, sketches: 0, observers: 0, listeners: 0, pendingCalls: 0 });
      // Scenes removed before their start's turn (it waits for a paint and a task) never open a world; the 'auto'
      // ones left once their engine was made or running did (12 of the 25), all in the page's pool: one worker at a
      // time, reused while it is in its grace period (a new one only when a cycle took longer than that).
      expect(w.counts.made).to.be.within(1, 12);
      expect(w.counts.most).to.equal(1);
      expect(w.counts.terminated).to.equal(w.counts.made);
      const pending = g.pending();
      expect(pending.timers, 'pending timeouts').to.equal(0);
      expect(pending.intervals, 'running intervals').to.equal(0);
      expect(pending.frames, 'pending animation frames').to.equal(0);
      expect(pending.listeners, 'window/document listeners').to.deep.equal([]);
      // p5 keeps a static list of per-sketch hooks; the renderer takes its own off again.
      expect(p5Hooks()).to.equal(hooksBefore);
    } finally {
      g.restore();
      w.restore();
    }
  });

  it('removed <cloth-sim> and <ragdoll-sim> elements stop their behaviour timer and report not running', async () => {
    const g = trackGlobals();
    try {
      for (const tag of ['cloth-sim', 'ragdoll-sim', 'cloth-sim', 'ragdoll-sim']) {
        const box = document.createElement('div');
        box.style.cssText = 'width: 320px; height: 200px;';
        const preset = document.createElement(tag) as PhysicsSceneElement;
        box.append(preset);
        document.body.append(box);
        await preset.ready;
        // Running, its gusts or respawns tick on a timer.
        try {
          await waitFor(() => preset.running && g.pending().intervals > 0, `${tag} running with its timer`);
        } finally {
          box.remove();
        }
        await frames(2);
        expect(preset.running, `${tag}.running once removed`).to.equal(false);
        expect(preset.onScreen, `${tag}.onScreen once removed`).to.equal(false);
      }
      await waitFor(() => liveResources().workers === 0, 'the pool\'s worker to end');
      // Before the fix an update after the removal started the preset's timer again, for good: the element (its
      // shadow tree, its listeners) was never freed.
      expect(g.pending().intervals, 'intervals left running').to.equal(0);
    } finally {
      g.restore();
    }
  });

  it('a new worker mode carries the scene over to an engine in that mode (same step, same state), in one update; a value that leaves the mode as it is changes nothing', async () => {
    const warnings: string[] = [];
    const warn = console.warn;
    console.warn = (...args: unknown[]) => warnings.push(args.join(' '));
    let scene: PhysicsSceneElement | null = null;
    try {
      scene = await mount('width="10" height="10" paused', CHILDREN);
      const errors: string[] = [];
      scene.addEventListener('physics-error', (e) => errors.push(`${e.detail.attribute}=${e.detail.value}`));
      expect(scene.mode).to.equal('worker');
      await scene.step(60);
      const ball = scene.querySelector('physics-circle')!;
      let y = ball.y;
      expect(y).to.be.above(2.5);
      let hash = await scene.stateHash();
      // "abc" is reported and falls back to "auto", where the engine runs already: the same engine goes on.
      const engine = scene.client;
      scene.setAttribute('worker', 'abc');
      await scene.updateComplete;
      expect(errors).to.deep.equal(['worker=abc']);
      expect(warnings.filter((w) => w.includes('worker="abc"'))).to.have.length(1);
      expect(scene.client === engine, 'the same engine').to.equal(true);
      expect([scene.stepCount, await scene.stateHash()]).to.deep.equal([60, hash]);
      for (const [worker, mode, steps] of [['none', 'main', 60], ['auto', 'worker', 90], ['', 'worker', 120]] as const) {
        // Blank (the default, as absent) is markup the property's type leaves out.
        (scene as { worker: string }).worker = worker;
        await scene.updateComplete;
        // The engine in the new mode goes on from where the old one was: the same step, the same state.
        expect(await scene.stateHash(), `the state after worker="${worker}"`).to.equal(hash);
        expect([scene.mode, scene.stepCount], `after worker="${worker}"`).to.deep.equal([mode, steps]);
        expect(ball.y).to.equal(y);
        expect(scene.paused).to.equal(true);
        expect(await scene.step(30)).to.equal(steps + 30);
        hash = await scene.stateHash();
        y = ball.y;
      }
      expect(errors).to.deep.equal(['worker=abc']);
      expect(warnings.filter((w) => w.includes('scheduled an update')), warnings.join('\n')).to.deep.equal([]);
    } finally {
      console.warn = warn;
      unmount(scene);
      // The pool's worker ends after its grace period: later tests count the workers they make.
      await waitFor(() => liveResources().workers === 0, 'the pool\'s worker to end');
    }
  });

  it('calls on a scene not in the page, never added or removed, fail at once with EngineStoppedError', async () => {
    const never = document.createElement('physics-scene');
    const removed = await mount('width="10" height="10" paused', CHILDREN);
    unmount(removed);
    for (const s of [never, removed]) {
      for (const [name, call] of [['step', () => s.step(1)], ['reset', () => s.reset()], ['stateHash', () => s.stateHash()], ['diagnostics', () => s.diagnostics()], ['snapshot', () => s.snapshot()]] as const) {
        const error = await call().then(() => null, (e: Error) => e);
        expect(error?.name, name).to.equal('EngineStoppedError');
        // The class the package exports, for `instanceof`; the sentence names the element and the call.
        expect(error, name).to.be.instanceOf(EngineStoppedError);
        expect(error?.message, name).to.equal(`<physics-scene> is not in the page: add it, then call ${name}()`);
      }
    }
    // A preset says its own tag.
    const cloth = document.createElement('cloth-sim');
    const error = await cloth.step(1).then(() => null, (e: Error) => e);
    expect(error?.message).to.equal('<cloth-sim> is not in the page: add it, then call step()');
    await waitFor(() => liveResources().workers === 0, 'the pool\'s worker to end');
  });
});
