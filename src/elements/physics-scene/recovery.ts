// Fault recovery. While the scene steps in a worker, a keeper looks at the step counter a few times a second: it keeps
// a snapshot of the whole simulation about once a second, and when no step came for a while although the scene runs,
// it probes the worker (no answer declares it dead). A dead worker (uncaught error, unanswered call, failed probe) is
// reported and replaced: a new engine loads the markup, the last snapshot is restored with the newest drawn frame laid
// over it, and markup changed since the snapshot is applied again. Past `max-restarts` restarts within a minute the
// scene gives up: the last state stays drawn and the error box says why.
//
// A snapshot is a structured clone of the engine's tables: well under a millisecond for the scenes an embed runs and a
// few milliseconds for the largest, so once a second keeps its cost negligible; a scene whose snapshots take longer
// gets them less often (at most 5% of the time). A snapshot alone would rewind up to a second; the page also holds the
// newest frame, so after a restart the particles are moved to where they were last drawn (velocities from the two
// newest frames) and the scene resumes from what the user saw. While a snapshot is being taken the worker does not
// step: that is not a stall (its answer is a sign of life; a worker that died meanwhile fails that call instead).
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { FramePatch, HostError, HostParams, HostScene, HostSnapshot } from '../../worker/protocol.js';
import type { Engine, EngineFactory, EngineSession } from './session.js';

/** Milliseconds between snapshots while the scene steps (at least). */
const SNAPSHOT_EVERY = 1000;
/** The share of the time snapshots may take: a snapshot that took t ms is followed by the next one t / share ms later. */
const SNAPSHOT_SHARE = 0.05;
/** How often the keeper looks at the step counter (ms). */
const KEEPER_TICK = 250;
/** Restarts count within this window (ms); more than `max-restarts` in it and the scene gives up. */
const RESTART_WINDOW = 60000;
/** No new step for this long while running (ms, at least 3 fixed steps) and the worker is probed. */
const STALL_AFTER = 1500;
/** A probe unanswered for this long (ms, at most the call timeout) declares the worker dead. */
const PROBE_TIMEOUT = 1000;

/** Time and timers (performance.now and window's intervals; unit tests pass a fake clock). */
export interface Clock {
  now(): number;
  setInterval(callback: () => void, ms: number): number;
  clearInterval(id: number): void;
}

export const realClock: Clock = {
  now: () => performance.now(),
  setInterval: (callback, ms) => window.setInterval(callback, ms),
  clearInterval: (id) => window.clearInterval(id),
};

/** What recovery does to the session: take a dead engine out, put a new one in. */
export type RecoverySession = Pick<EngineSession, 'engine' | 'live' | 'generation' | 'suspend' | 'adopt' | 'resume' | 'end' | 'fail'>;

/** The scene as recovery sees it. */
export interface RecoveryScene {
  /** The scene as the markup describes it now, for the new engine. */
  describe(): HostScene;
  /** `max-restarts`, the fixed step (s) and the call timeout (ms), as configured now. */
  limits(): { maxRestarts: number; timestep: number; callTimeout: number };
  /** The grab the pointer holds, or null (a snapshot notes it, so that the restore lets go of it). */
  grab(): number | null;
  /** The engine is gone: what depends on it stops (the drag, the running hooks). */
  lost(): void;
  /** Running again, or given up: the engine and the canvas are told whether to run. */
  resumed(): void;
  /** A `physics-error` about the worker on the scene (`keep`: also in the error box). */
  report(message: string, keep: boolean): void;
  /** The new engine refused an element's description. */
  refused(error: HostError): void;
}

export interface RecoveryOptions {
  session: RecoverySession;
  /** Makes the replacement engines. */
  connect: EngineFactory;
  scene: RecoveryScene;
  clock?: Clock;
}

/** @internal */
export class RecoveryController implements ReactiveController {
  /** The newest snapshot, the engine it came from (its frames may be laid over it) and the grab held then. */
  private saved: { engine: Engine; snapshot: HostSnapshot; grab: number | null } | null = null;
  /** clock.now() of each restart within the window. */
  private restarts: number[] = [];
  private stopped = false;
  private keeper: number | null = null;
  private watchStep = -1;
  private watchAt = 0;
  private snapAt = 0;
  /** Milliseconds from one snapshot to the next, from how long the last one took. */
  private snapEvery = SNAPSHOT_EVERY;
  private snapping = false;
  private readonly clock: Clock;

  constructor(
    host: ReactiveControllerHost,
    private readonly options: RecoveryOptions,
  ) {
    this.clock = options.clock ?? realClock;
    host.addController(this);
  }

  /** Gave up: past max-restarts; nothing runs until the scene is started again. */
  get gaveUp(): boolean {
    return this.stopped;
  }

  /** Restarts within the window so far. */
  get restartCount(): number {
    return this.restarts.length;
  }

  /** The scene stopped: no snapshot, no restarts counted, not given up. */
  reset(): void {
    this.saved = null;
    this.restarts = [];
    this.stopped = false;
    this.snapEvery = SNAPSHOT_EVERY;
    this.watch(false);
  }

  /** Out of the document nothing watches visibility: the keeper stops (the scene's next running state restarts it). */
  hostDisconnected(): void {
    this.watch(false);
  }

  /** Keeps a recent snapshot and watches the step counter while the scene steps (`running`) in a worker. */
  watch(running: boolean): void {
    const engine = this.options.session.live;
    const on = running && !this.stopped && engine?.mode === 'worker';
    if (on === (this.keeper !== null)) return;
    if (!on) {
      this.clock.clearInterval(this.keeper!);
      this.keeper = null;
      // Stopped stepping (paused, off screen, hidden page): the state to keep is now fixed.
      this.keepSnapshot();
      return;
    }
    this.watchStep = engine!.latestStep;
    this.watchAt = this.clock.now();
    this.keeper = this.clock.setInterval(this.tick, KEEPER_TICK);
  }

  /** Asks the worker for a snapshot (one at a time) and keeps it. */
  keepSnapshot(): void {
    const { session } = this.options;
    const engine = session.live;
    if (!engine || engine.mode !== 'worker' || this.snapping) return;
    this.snapping = true;
    const asked = (this.snapAt = this.clock.now());
    const grab = this.options.scene.grab();
    engine.api
      .snapshot()
      .then(
        (snapshot) => {
          if (engine !== session.engine) return;
          this.saved = { engine, snapshot, grab };
          const now = this.clock.now();
          this.snapEvery = Math.max(SNAPSHOT_EVERY, (now - asked) / SNAPSHOT_SHARE);
          this.watchAt = now;
        },
        () => {},
      )
      .finally(() => {
        this.snapping = false;
      });
  }

  /** The current engine died or hung: report it, then restart and restore, or give up past the cap. */
  died(dead: Engine, reason: string): void {
    const { session, scene } = this.options;
    if (dead !== session.engine) return;
    // What the user sees: the dead engine's last frame (or, when a restart died, the one before it).
    const shown = session.suspend(dead);
    const saved = this.saved;
    const frame = saved && saved.engine === shown ? shown.lastFrame() : null;
    this.watch(false);
    scene.lost();
    const now = this.clock.now();
    this.restarts = this.restarts.filter((t) => now - t < RESTART_WINDOW);
    const cap = scene.limits().maxRestarts;
    if (this.restarts.length >= cap) {
      // The end: the last state stays drawn (once), the error box says why, nothing is retried.
      this.stopped = true;
      this.saved = null;
      session.end();
      scene.resumed();
      scene.report(`engine worker died (${reason}); not restarted: ${cap === 0 ? 'max-restarts is 0' : `${cap} restart${cap === 1 ? '' : 's'} within 60 s already`}, the scene is stopped`, true);
      return;
    }
    this.restarts.push(now);
    scene.report(`engine worker died (${reason}); restarting it (attempt ${this.restarts.length} of ${cap})`, false);
    void this.restart(session.generation, saved?.snapshot ?? null, frame, saved?.grab ?? null);
  }

  /**
   * The live engine is replaced by one made anew (another `worker` mode), which carries on from the old one's state:
   * paused, snapshot, then restored into the new one as after a restart (not counted as one, nothing reported).
   */
  async replace(): Promise<void> {
    const { session, scene } = this.options;
    const old = session.live!;
    const gen = session.generation;
    const grab = scene.grab();
    // Out of the session at once: calls wait for the new engine (ready), the old one's frames stay drawn meanwhile.
    session.suspend(old);
    this.watch(false);
    scene.lost();
    const snapshot = await old.api.pause().then(() => old.api.snapshot()).catch(() => null);
    await this.restart(gen, snapshot, null, grab);
  }

  /** A new engine loaded from the markup, then the last snapshot (and frame) restored and later markup changes applied. */
  private async restart(gen: number, snapshot: HostSnapshot | null, frame: FramePatch | null, grab: number | null): Promise<void> {
    const { session, scene } = this.options;
    const engine = await this.options.connect();
    if (gen !== session.generation) {
      engine.dispose();
      return;
    }
    session.adopt(engine);
    if (engine.died !== null) {
      this.died(engine, engine.died);
      return;
    }
    try {
      const description = scene.describe();
      await engine.api.load({ ...description, running: false });
      let step = 0;
      if (snapshot) {
        let restored = true;
        try {
          step = await engine.api.restore(snapshot, frame);
        } catch (error) {
          if (engine.died !== null) throw error;
          restored = false;
          scene.report(`engine: the last snapshot could not be restored, the scene restarts from its markup (${error instanceof Error ? error.message : String(error)})`, false);
          await engine.api.load({ ...description, running: false });
        }
        if (restored) await this.reapply(engine, description, snapshot, grab);
      }
      // Poses read right after ready are the restored ones.
      await engine.synced(step);
      if (gen !== session.generation || session.engine !== engine) return;
      session.resume();
      scene.resumed();
      this.keepSnapshot();
    } catch (error) {
      // The new worker died too: died() has taken over (another attempt, or the end).
      if (gen !== session.generation || session.engine !== engine || engine.died !== null) return;
      session.fail(error);
      session.resume();
      scene.resumed();
    }
  }

  /** After a restore: the markup as it is now wins over the snapshot's descriptions, and the current parameters. */
  private async reapply(engine: Engine, scene: HostScene, snapshot: HostSnapshot, grab: number | null): Promise<void> {
    const calls: Promise<unknown>[] = [];
    const report = (e: HostError | null) => e && this.options.scene.refused(e);
    const bodies = new Map(snapshot.bodies.map((b) => [b.key, JSON.stringify(b.desc)]));
    const links = new Map(snapshot.links.map((l) => [l.key, JSON.stringify(l.desc)]));
    for (const b of scene.bodies) if (bodies.get(b.key) !== JSON.stringify(b.desc)) calls.push(engine.api.updateBody(b).then(report));
    for (const key of bodies.keys()) if (!scene.bodies.some((b) => b.key === key)) calls.push(engine.api.removeBody(key));
    for (const l of scene.links) if (links.get(l.key) !== JSON.stringify(l.desc)) calls.push(engine.api.updateLink(l).then(report));
    for (const key of links.keys()) if (!scene.links.some((l) => l.key === key)) calls.push(engine.api.removeLink(key));
    // The parameters changed since (setting one as it was would still wake the bodies: not the snapshot's state).
    const params: Record<string, unknown> = { ...scene.params };
    for (const k in params) if (JSON.stringify(params[k]) === JSON.stringify(snapshot.params[k as keyof HostParams])) delete params[k];
    calls.push(engine.api.setParams(params));
    // A drag held when the snapshot was taken has no pointer any more.
    if (grab !== null) calls.push(engine.api.release(grab));
    await Promise.all(calls);
  }

  /** Every KEEPER_TICK while the scene steps in a worker: a snapshot now and then, a probe when no step came. */
  private readonly tick = (): void => {
    const engine = this.options.session.live;
    if (!engine) return;
    const now = this.clock.now();
    const step = engine.latestStep;
    if (step !== this.watchStep) {
      this.watchStep = step;
      this.watchAt = now;
      if (now - this.snapAt >= this.snapEvery) this.keepSnapshot();
      return;
    }
    const limits = this.options.scene.limits();
    const stall = Math.max(STALL_AFTER, 3000 * limits.timestep);
    if (this.snapping || now - this.watchAt < stall) return;
    // No step for a while although the scene runs: terminated or hung? One probe; no answer declares it dead.
    this.watchAt = now;
    const timeout = Math.min(PROBE_TIMEOUT, limits.callTimeout);
    void engine.probe(`no new frame for ${Math.round(stall)} ms while running and no answer to a probe within ${timeout} ms`, timeout);
  };
}
