// The engine session of a scene: the engine client it talks to from start to stop, the generation that tells a current
// start from a stale one, the `ready` promise callers wait on, and one way to send commands whose failures are
// reported (or not: a dead worker is reported once, by recovery, not once per call it failed).
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { EngineClient, EngineStoppedError, TimeoutError, WorkerDiedError, type ClientOptions } from '../../worker/client.js';
import type { EngineApi, HostError, HostScene } from '../../worker/protocol.js';

/** What a scene uses of an engine client (an EngineClient; unit tests pass fakes). */
export type Engine = Pick<
  EngineClient,
  'mode' | 'transport' | 'worker' | 'api' | 'died' | 'latestStep' | 'frames' | 'topology' | 'poll' | 'pose' | 'lastFrame' | 'frameAt' | 'synced' | 'probe' | 'debugTerminate' | 'dispose'
>;

/** Makes an engine: a worker, or the main-thread fallback. */
export type EngineFactory = () => Promise<Engine>;

/** Starts an engine client (EngineClient.start) whose death is reported with the engine that died. */
export async function startEngine(options: Omit<ClientOptions, 'onDeath'> & { onDeath(engine: Engine, reason: string): void }): Promise<Engine> {
  let made: EngineClient | null = null;
  made = await EngineClient.start({ ...options, onDeath: (reason) => made && options.onDeath(made, reason) });
  return made;
}

/** Engine calls that answer nothing or a HostError: sent without waiting, refusals and failures reported. */
export type Command = { [K in keyof EngineApi]: ReturnType<EngineApi[K]> extends void | HostError | null ? K : never }[keyof EngineApi];

/** What the other controllers need to send commands (the session, or a fake in tests). */
export interface EngineCommands {
  /** The engine while it has the scene loaded (commands are then worth sending), else null. */
  readonly live: Engine | null;
  send<M extends Command>(method: M, ...args: Parameters<EngineApi[M]>): void;
}

/** The scene being started, as the session sees it. */
export interface SessionScene {
  /** Once the host has rendered, before the engine is made: the canvas, the markup observer. */
  prepare(): void;
  /** The scene to load, from the markup as it is now. */
  describe(): HostScene;
  /** The engine has loaded the scene (`errors`: what it refused). */
  loaded(engine: Engine, errors: HostError[]): void;
  /** The start is over, loaded or failed. */
  settled(): void;
}

export interface SessionOptions {
  connect: EngineFactory;
  /**
   * What a start waits for first: the scene near the viewport (VisibilityController.whenNear), so off-screen scenes
   * make no canvas and no world until a reader comes near. Default: nothing.
   */
  nearby?: () => Promise<void>;
  /**
   * Runs the drawing library's own code (loadP5), in the task the start resumes in once the scene is near, so that the
   * canvas, after the next paint, is a task of its own: the two together were the page's longest task.
   */
  warm?: () => void;
  /** A caller wants the engine (whenReady(), running()): the start waits for nothing (VisibilityController.demand). */
  demand?: () => void;
  /**
   * What a start waits for before each piece of its heavy work: before the canvas (p5) by default afterPaint(), before
   * the engine nextTask(). So the script's evaluation, the page's first paint, each scene's canvas and each scene's
   * worker are tasks of their own instead of one long task. Tests pass their own.
   */
  wait?: (before: 'canvas' | 'engine') => Promise<void>;
  scene: SessionScene;
  /** An engine failure worth a `physics-error` on the scene ("engine: …"). */
  failed(message: string): void;
  /** An element's description the engine refused; `sent`: the call's first argument (a keyed description, or a key). */
  refused(error: HostError, sent: unknown): void;
}

/** How long a start waits for a frame before it goes on without one (a hidden page gets no animation frames). */
const PAINT_WAIT_MS = 100;

/**
 * Resolves in a task after the next paint: a frame callback runs just before the paint, a task it queues runs after.
 * A page without frames (hidden) waits PAINT_WAIT_MS instead.
 */
export function afterPaint(): Promise<void> {
  return new Promise((resolve) => {
    const timer = setTimeout(resolve, PAINT_WAIT_MS);
    requestAnimationFrame(() =>
      setTimeout(() => {
        clearTimeout(timer);
        resolve();
      }, 0),
    );
  });
}

/** Resolves in a new task (the work before it ends one task; the browser may paint or handle input in between). */
export function nextTask(): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/** A promise callers wait on while the gate is closed. Closing an open gate makes a new promise; a closed one keeps its own. */
class Gate {
  promise!: Promise<void>;
  private release: (() => void) | null = null;

  constructor() {
    this.close();
  }

  close(): void {
    if (!this.release) this.promise = new Promise((resolve) => (this.release = resolve));
  }

  open(): void {
    this.release?.();
    this.release = null;
  }
}

/** @ignore Internal; not tagged internal, which the declarations strip, since recovery.ts's declarations name it. */
export class EngineSession implements ReactiveController, EngineCommands {
  private current: Engine | null = null;
  /** While a dead engine is replaced (and after giving up): the dead one, whose last frame stays drawn. */
  private held: Engine | null = null;
  private loaded = false;
  private starting = false;
  /** Recovery replaces the engine: `ready` stays closed until it resumes (or gives up). */
  private suspended = false;
  private gen = 0;
  /** Running state last sent to the engine (null: none sent yet). */
  private runningSent: boolean | null = null;
  private readonly gate = new Gate();

  constructor(
    private readonly host: ReactiveControllerHost & Element,
    private readonly options: SessionOptions,
  ) {
    host.addController(this);
  }

  hostConnected(): void {
    if (this.idle) void this.start();
  }

  /** The current engine, loaded or not. */
  get engine(): Engine | null {
    return this.current;
  }

  get live(): Engine | null {
    return this.loaded ? this.current : null;
  }

  /** The engine whose frames are drawn and whose poses are read: while a dead one is replaced, the dead one. */
  get shown(): Engine | null {
    return this.held ?? this.current;
  }

  /** Resolves when the engine has loaded the scene (after each start and restart). */
  get ready(): Promise<void> {
    return this.gate.promise;
  }

  /** Counts starts and stops: work begun in an older generation is stale. */
  get generation(): number {
    return this.gen;
  }

  /** No engine and none on the way. */
  get idle(): boolean {
    return !this.current && !this.starting;
  }

  /**
   * The engine once ready, or null when there is none (never started, given up). A start waiting to be near goes on.
   * A scene not in the page has none coming: an EngineStoppedError (a call waiting for it would never settle).
   */
  async whenReady(method = 'this method'): Promise<Engine | null> {
    if (!this.host.isConnected) throw new EngineStoppedError(`<${this.host.localName}> is not in the page: add it, then call ${method}`);
    this.options.demand?.();
    await this.ready;
    return this.current;
  }

  /**
   * The engine once ready. An EngineStoppedError when there is none: the scene stopped for good after its engine
   * failed (past max-restarts), where resolving with a made-up result would hide it.
   */
  async running(method?: string): Promise<Engine> {
    const engine = await this.whenReady(method);
    if (!engine) throw new EngineStoppedError(`<${this.host.localName}> is stopped: its engine failed (see its physics-error); add it to the page again to restart it`);
    return engine;
  }

  /**
   * Makes an engine and loads the scene into it once the scene is near the viewport, after the page's next paint and
   * in tasks of their own: the canvas (p5), then the engine. A stop() meanwhile makes this start stale: it cleans up
   * and ends.
   */
  async start(): Promise<void> {
    const gen = ++this.gen;
    this.starting = true;
    const { scene } = this.options;
    const wait = this.options.wait ?? ((before) => (before === 'canvas' ? afterPaint() : nextTask()));
    const current = () => gen === this.gen && this.host.isConnected;
    try {
      await this.host.updateComplete;
      if (!current()) return;
      await this.options.nearby?.();
      if (!current()) return;
      this.options.warm?.();
      await wait('canvas');
      if (!current()) return;
      scene.prepare();
      await wait('engine');
      if (!current()) return;
      const engine = await this.options.connect();
      if (gen !== this.gen) {
        engine.dispose();
        return;
      }
      this.current = engine;
      const description = scene.describe();
      this.loaded = true;
      this.runningSent = description.running ?? null;
      const errors = await engine.api.load(description);
      if (gen !== this.gen || this.current !== engine) return;
      scene.loaded(engine, errors);
      this.gate.open();
    } catch (error) {
      if (gen === this.gen) this.fail(error);
    } finally {
      if (gen === this.gen) {
        this.starting = false;
        scene.settled();
        // Never leave callers of ready waiting, also when the start failed (a restart opens the gate itself).
        if (!this.suspended) this.gate.open();
      }
    }
  }

  /** Ends the engine (and a start under way); callers of ready are let go and the next ready waits for a new start. */
  stop(): void {
    this.gen++;
    this.starting = false;
    this.current?.dispose();
    this.current = null;
    this.held?.dispose();
    this.held = null;
    this.loaded = false;
    this.suspended = false;
    this.runningSent = null;
    this.gate.open();
    this.gate.close();
  }

  send<M extends Command>(method: M, ...args: Parameters<EngineApi[M]>): void {
    const engine = this.current;
    if (!engine) return;
    const call = engine.api[method] as (...a: unknown[]) => Promise<HostError | null | void>;
    call(...args).then(
      (refused) => refused && this.options.refused(refused, args[0]),
      (error) => this.fail(error),
    );
  }

  /** Reports a failed call, unless the failure is the engine's death or stop (reported once, elsewhere, or not at all). */
  fail(error: unknown): void {
    if (!this.current && !this.starting) return;
    // A worker that died or stopped answering is reported once, by recovery, not once per call it failed.
    if (error instanceof WorkerDiedError || (error instanceof TimeoutError && this.current?.mode !== 'main')) return;
    // Calls still pending when the scene stopped its own engine (a restart for a new worker attribute, a disconnect).
    if (error instanceof EngineStoppedError) return;
    this.options.failed(`engine: ${error instanceof Error ? error.message : String(error)}`);
  }

  /** Tells the live engine to step or not, once per change. True when it was told. */
  setRunning(running: boolean): boolean {
    if (!this.live || running === this.runningSent) return false;
    this.runningSent = running;
    this.send(running ? 'play' : 'pause');
    return true;
  }

  // ---- for recovery ------------------------------------------------------------------------------------------

  /**
   * The engine died: none until resume(), and ready waits. The dead engine stays shown, or, when a replacement died
   * too, the first dead one (its frames are what the user saw). Returns the engine shown.
   */
  suspend(dead: Engine): Engine {
    const shown = this.held ?? dead;
    this.held = shown;
    if (shown !== dead) dead.dispose();
    this.current = null;
    this.loaded = false;
    this.runningSent = null;
    this.suspended = true;
    this.gate.close();
    return shown;
  }

  /** A replacement engine, still loading. */
  adopt(engine: Engine): void {
    this.current = engine;
  }

  /** The replacement has the scene: it is live and shown, and callers of ready go on. */
  resume(): void {
    this.loaded = true;
    this.held?.dispose();
    this.held = null;
    this.suspended = false;
    this.gate.open();
  }

  /** Recovery gave up: no engine, the dead one's last frame stays drawn, callers of ready go on. */
  end(): void {
    this.suspended = false;
    this.gate.open();
  }
}
