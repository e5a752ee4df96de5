// The page's side of the engine: a world in one of the page's pooled engine workers (or, with worker="none" or when no
// Worker can be made, an EngineHost on the main thread), with a timeout on every call, and the two newest published
// frames kept for the renderer. Both modes expose the same promise-returning EngineApi.
import { TripleBuffer } from './triple-buffer.js';
import { TripleBufferPublisher } from './publishers.js';
import { F, HEADER, POSE, frameLength, poseOffset, type EngineApi, type FramePatch, type PortMessage, type Topology, type Transport } from './protocol.js';
import { TimeoutError, WorkerPool, defaultPoolSize, timerDelay, type WorldLink } from './pool.js';
import { track } from './resources.js';

export { TimeoutError } from './pool.js';

export type Remote = { [K in keyof EngineApi]: (...args: Parameters<EngineApi[K]>) => Promise<ReturnType<EngineApi[K]>> };

export interface ClientOptions {
  /** 'auto' (default): a worker when possible; 'none': the main thread. */
  worker?: 'auto' | 'none';
  /**
   * Milliseconds a call (and the worker's start) may take before it fails. Default 8000. A timer waits at most
   * 2147483647 ms (2^31 − 1): a longer timeout waits that long.
   */
  timeout?: number;
  /** Makes the workers (tests replace it): the page's pool for this factory is used. */
  createWorker?: () => Worker;
  /** The pool to open the world in (default: the page's pool for `createWorker`). */
  pool?: WorkerPool;
  onTopology?: (topology: Topology) => void;
  onEvents?: (data: Float64Array, count: number) => void;
  /** Problems during start: the fallback to the main thread (and a worker death when there is no onDeath). */
  onError?: (message: string) => void;
  /**
   * The worker died after start: an uncaught exception in it (`error`), a message it sent that cannot be read
   * (`messageerror`), a call it did not answer in time (hung or terminated), or a failed probe() — of this world or
   * of any other world in the same worker. Called once; by then every pending call has failed with a
   * WorkerDiedError (the timed-out one with its TimeoutError), the worker is terminated and the client disposed. The
   * owner starts a new client if it wants one.
   */
  onDeath?: (reason: string) => void;
}

/** The bundler (rollup.config.js) emits this worker as its own chunk, or inlines it as a blob: URL. */
export function createEngineWorker(): Worker {
  return new Worker(new URL('./engine.worker.js', import.meta.url), { type: 'module' });
}

/** The most engine workers the page's scenes share (null: defaultPoolSize()). */
let workerLimit: number | null = null;

/** The most engine workers the page's pools make: `max(1, min(2, hardwareConcurrency − 1))` unless set. */
export function maxWorkers(): number {
  return workerLimit ?? defaultPoolSize();
}

/**
 * Sets the most engine workers the page's pools make (null: the default). Workers already made stay. A TypeError for
 * anything but a number or null (`"2"` is a string, not 2), a RangeError for a number that is not an integer ≥ 1.
 */
export function setMaxWorkers(limit: number | null): void {
  if (limit !== null && typeof limit !== 'number') {
    throw new TypeError(`maxWorkers must be a number (an integer of at least 1) or null for the default, got ${shown(limit)}`);
  }
  if (limit !== null && (!Number.isInteger(limit) || limit < 1)) {
    throw new RangeError(`maxWorkers must be an integer of at least 1 (or null for the default), got ${String(limit)}`);
  }
  workerLimit = limit;
}

/**
 * A worker factory as PhysicsSceneElement.workerFactory takes it: a function that returns a Worker, or null (or
 * undefined) for the default, createEngineWorker. A TypeError naming workerFactory and the value otherwise: the
 * page's pools are keyed by their factory, and `5` used as one failed later, in every scene, as "Invalid value used as
 * weak map key".
 */
export function checkWorkerFactory(factory: unknown): (() => Worker) | null {
  if (factory === null || factory === undefined) return null;
  if (typeof factory !== 'function') {
    throw new TypeError(`workerFactory must be a function that returns a Worker, or null for the default, got ${shown(factory)}`);
  }
  return factory as () => Worker;
}

/** A value as an error message shows it: a string quoted (so "2" is told from 2), others with their type when unclear. */
function shown(value: unknown): string {
  if (typeof value === 'string') return JSON.stringify(value);
  if (typeof value === 'number' || typeof value === 'boolean' || value === undefined) return String(value);
  if (typeof value === 'bigint') return `${value}n`;
  if (typeof value === 'symbol') return value.toString();
  return Array.isArray(value) ? 'an array' : 'an object';
}

/** The page's pools, one per worker factory (a page normally has one). */
const pools = new WeakMap<() => Worker, WorkerPool>();

/** The page's pool of engine workers made by `createWorker`. */
export function pageWorkers(createWorker: () => Worker = createEngineWorker): WorkerPool {
  createWorker = checkWorkerFactory(createWorker) ?? createEngineWorker;
  let pool = pools.get(createWorker);
  if (!pool) {
    pool = new WorkerPool({ createWorker, size: maxWorkers });
    pools.set(createWorker, pool);
  }
  return pool;
}

/** A call that was pending (or made) when the worker died; the message names the method and the cause. */
export class WorkerDiedError extends Error {
  override name = 'WorkerDiedError';
}

/** A call on an engine its owner has stopped (disposed), or still pending when it did. */
export class EngineStoppedError extends Error {
  override name = 'EngineStoppedError';
}

/** The two newest frames, copied out of whatever carried them (no allocation unless the scene grows). */
export class FrameStore {
  prev = new Float64Array(HEADER);
  curr = new Float64Array(HEADER);
  /** performance.now() when each arrived. */
  prevAt = 0;
  currAt = 0;
  /** Frames received so far. */
  received = 0;

  accept(src: Float64Array): void {
    if (this.received > 0 && src[F.seq] === this.curr[F.seq]) return;
    const length = frameSize(src);
    const spare = this.prev;
    this.prev = this.curr;
    this.prevAt = this.currAt;
    this.curr = spare.length >= length ? spare : new Float64Array(Math.ceil(length * 1.5));
    this.curr.set(src.subarray(0, length));
    this.currAt = performance.now();
    this.received++;
  }
}

function frameSize(f: Float64Array): number {
  return frameLength(f[F.particles], f[F.bodies], f[F.contacts], f[F.debug] === 1);
}

export class EngineClient {
  readonly frames = new FrameStore();
  /** Newest topology (null until the first scene is loaded). */
  topology: Topology | null = null;
  readonly api: Remote;
  private triple: TripleBuffer | null = null;
  /** Collision events received so far: a frame says how many were sent before it (F.eventsSent). */
  private eventsReceived = 0;
  private disposed = false;
  /** Why the worker died (null while it lives). */
  private deathReason: string | null = null;
  /** Pending calls: how to fail each, and its method (for the error message). */
  private readonly pending = new Map<(error: Error) => void, string>();
  /** The pool world this client talks to (worker mode). */
  private link: WorldLink | null = null;

  private constructor(
    /** 'worker' or 'main': where the engine runs. */
    readonly mode: 'worker' | 'main',
    readonly transport: Transport,
    private readonly invoke: (method: keyof EngineApi, args: unknown[]) => Promise<unknown>,
    private readonly teardown: () => void,
    private readonly options: ClientOptions,
  ) {
    const timeout = options.timeout ?? 8000;
    this.api = new Proxy({} as Remote, {
      get: (_, method: string) => (...args: unknown[]) => this.call(method as keyof EngineApi, args, timeout),
    });
  }

  /**
   * Starts an engine. In 'auto' mode a worker that cannot be created, fails to load or does not answer in time is
   * reported through onError and replaced by the main-thread engine: the promise never hangs.
   */
  static async start(options: ClientOptions = {}): Promise<EngineClient> {
    if ((options.worker ?? 'auto') !== 'none') {
      try {
        return await EngineClient.startWorker(options);
      } catch (error) {
        options.onError?.(`engine worker failed, running on the main thread instead: ${error instanceof Error ? error.message : String(error)}`);
      }
    }
    return await EngineClient.startMain(options);
  }

  private static async startWorker(options: ClientOptions): Promise<EngineClient> {
    if (typeof Worker !== 'function') throw new Error('Worker is not available');
    const pool = options.pool ?? pageWorkers(options.createWorker);
    let client: EngineClient | null = null;
    let diedEarly: string | null = null;
    const link = await pool.open({ died: (reason) => (client ? client.die(reason) : (diedEarly = reason)) }, options.timeout ?? 8000);
    client = new EngineClient('worker', link.transport, (method, args) => link.invoke(method, args), () => link.close(), options);
    client.link = link;
    const c = client;
    link.port.onmessage = (e: MessageEvent<PortMessage>) => c.receive(e.data, link.port);
    if (diedEarly !== null) c.die(diedEarly);
    return client;
  }

  /**
   * The engine on the page's own thread. Imported only here, on first use: a page whose engine runs in a worker never
   * loads or evaluates the engine's code itself (in the library build it is a chunk of its own; the single file has
   * the engine once anyway, for the worker's script).
   */
  private static async startMain(options: ClientOptions): Promise<EngineClient> {
    const { EngineHost } = await import('./engine-host.js');
    let client: EngineClient;
    const publisher = new TripleBufferPublisher('direct', (buffer) => {
      client.triple = new TripleBuffer(buffer);
    });
    const host = new EngineHost(publisher, {
      topology: (topology) => client.receive({ type: 'topology', topology }, null),
      events: (data, count) => client.receive({ type: 'events', data, count }, null),
    });
    track('hosts', 1);
    client = new EngineClient(
      'main',
      'direct',
      async (method, args) => (host[method] as (...a: unknown[]) => unknown)(...args),
      () => {
        host.dispose();
        track('hosts', -1);
      },
      options,
    );
    return client;
  }

  private call(method: keyof EngineApi, args: unknown[], timeout: number, hung?: string): Promise<unknown> {
    // A longer delay overflows the timer, which then fires at once.
    timeout = timerDelay(timeout);
    if (this.deathReason !== null) return Promise.reject(new WorkerDiedError(`${method}(): the engine worker died (${this.deathReason})`));
    if (this.disposed) return Promise.reject(new EngineStoppedError(`engine stopped (${method})`));
    return new Promise((resolve, reject) => {
      const fail = (error: Error) => {
        clearTimeout(timer);
        this.pending.delete(fail);
        track('pendingCalls', -1);
        reject(error);
      };
      const timer = setTimeout(() => {
        fail(new TimeoutError(`${method}() did not answer within ${timeout} ms`));
        // A worker that does not answer is hung or gone: nothing else it was asked will be answered either, for this
        // world or any other in it.
        if (this.mode === 'worker') this.workerFailed(hung ?? `${method}() did not answer within ${timeout} ms`);
      }, timeout);
      this.pending.set(fail, method);
      track('pendingCalls', 1);
      this.invoke(method, args).then(
        (value) => {
          if (!this.pending.has(fail)) return;
          clearTimeout(timer);
          this.pending.delete(fail);
          track('pendingCalls', -1);
          this.poll();
          resolve(value);
        },
        (error) => {
          if (this.pending.has(fail)) fail(error instanceof Error ? error : new Error(String(error)));
        },
      );
    });
  }

  private failAll(error: (method: string) => Error): void {
    for (const [fail, method] of [...this.pending]) fail(error(method));
  }

  /** The worker is dead or hung: pending calls fail naming their method, the worker is terminated, onDeath is told. */
  private die(reason: string): void {
    if (this.disposed || this.deathReason !== null) return;
    this.poll();
    this.deathReason = reason;
    this.failAll((method) => new WorkerDiedError(`${method}(): no answer, the engine worker died (${reason})`));
    this.dispose();
    if (this.options.onDeath) this.options.onDeath(reason);
    else this.options.onError?.(`engine worker died: ${reason}`);
  }

  /** The worker is hung or gone: every world in it dies (this one too), or just this client when it has no pool world. */
  private workerFailed(reason: string): void {
    if (this.link && !this.disposed) this.link.fail(reason);
    else this.die(reason);
  }

  /** Which pool worker holds this world (a serial number unique on the page), or null on the main thread. */
  get worker(): number | null {
    return this.link?.worker ?? null;
  }

  /** Why the worker died, or null. */
  get died(): string | null {
    return this.deathReason;
  }

  /**
   * A sign of life from a worker that sends no frames although it should: one cheap call; no answer within
   * `timeout` ms declares the worker dead (onDeath) with `reason`.
   */
  async probe(reason: string, timeout: number): Promise<void> {
    if (this.mode !== 'worker' || !this.alive) return;
    await this.call('diagnostics', [], timeout, reason).catch(() => {});
  }

  /**
   * The newest frame as a patch for restore() after a restart: positions and poses, and velocities and angular
   * velocities from the two newest frames when both have the same topology and different steps. Null before any frame.
   */
  lastFrame(): FramePatch | null {
    this.poll();
    const fs = this.frames;
    if (fs.received === 0) return null;
    const f = fs.curr;
    const n = f[F.particles];
    const b = f[F.bodies];
    const positions = f.slice(HEADER, HEADER + 2 * n);
    const at = poseOffset(n);
    const poses = f.slice(at, at + POSE * b);
    let velocities: Float64Array | null = null;
    let spins: Float64Array | null = null;
    const p = fs.prev;
    const dt = f[F.time] - p[F.time];
    if (fs.received > 1 && p[F.topology] === f[F.topology] && p[F.particles] === n && p[F.stepCount] < f[F.stepCount] && dt > 0) {
      velocities = new Float64Array(2 * n);
      for (let k = 0; k < 2 * n; k++) velocities[k] = (f[HEADER + k] - p[HEADER + k]) / dt;
      // Rigid bodies' angles are summed, never wrapped: their difference is the turn between the frames.
      spins = new Float64Array(b);
      for (let k = 0; k < b; k++) spins[k] = (f[at + POSE * k + 2] - p[at + POSE * k + 2]) / dt;
    }
    return { topology: f[F.topology], stepCount: f[F.stepCount], time: f[F.time], positions, velocities, poses, spins };
  }

  /**
   * Internal test hook (not tagged internal: session.ts's declarations name it): terminates the worker from outside and
   * tells no one (as if the browser had killed it); every world in it stops.
   */
  debugTerminate(): void {
    this.link?.kill();
  }

  private receive(message: PortMessage, port: MessagePort | null): void {
    if (this.disposed) return;
    switch (message.type) {
      case 'frame':
        this.frames.accept(new Float64Array(message.buffer));
        port?.postMessage({ type: 'recycle', buffer: message.buffer }, [message.buffer]);
        break;
      case 'shared':
        this.triple = new TripleBuffer(message.buffer);
        this.poll();
        break;
      case 'topology':
        this.topology = message.topology;
        this.options.onTopology?.(message.topology);
        break;
      case 'events':
        this.eventsReceived += message.count;
        this.options.onEvents?.(message.data, message.count);
        break;
    }
  }

  /** Takes the newest frame from the shared (or main-thread) triple buffer, if there is a newer one. */
  poll(): void {
    const f = this.triple?.read();
    if (f) this.frames.accept(f);
  }

  /**
   * The pose [x, y, angle] of a body in the newest frame, or null: where its origin is (the x, y it was described at;
   * a rigid body's frame pose is its centre of mass) and its angle.
   */
  pose(key: number): [number, number, number] | null {
    this.poll();
    const t = this.topology;
    const f = this.frames.curr;
    if (!t || this.frames.received === 0 || f[F.topology] !== t.version) return null;
    const k = t.bodies.findIndex((b) => b.key === key);
    if (k < 0) return null;
    const o = poseOffset(f[F.particles]) + POSE * k;
    const [x, y, angle] = [f[o], f[o + 1], f[o + 2]];
    const center = t.bodies[k].center;
    if (!center) return [x, y, angle];
    const c = Math.cos(angle);
    const s = Math.sin(angle);
    return [x - (c * center[0] - s * center[1]), y - (s * center[0] + c * center[1]), angle];
  }

  /** Step count of the newest frame received. */
  get latestStep(): number {
    this.poll();
    return this.frames.received > 0 ? this.frames.curr[F.stepCount] : 0;
  }

  /**
   * Resolves once a frame of step `step` (or, for step 0, any frame after a reset) has arrived, with the collision
   * events sent before it: frames, events and replies travel on different ports (a shared frame on none), so a reply
   * can overtake its frame and a shared frame its events.
   */
  async frameAt(step: number, timeout = 2000): Promise<void> {
    const until = performance.now() + timeout;
    const seen = this.frames.received;
    for (;;) {
      this.poll();
      const f = this.frames.curr;
      const s = this.frames.received > 0 ? f[F.stepCount] : -1;
      const arrived = step === 0 ? this.frames.received > seen || s === 0 : s >= step;
      if (arrived && this.eventsReceived >= f[F.eventsSent]) return;
      if (this.disposed || performance.now() > until) return;
      await new Promise((r) => setTimeout(r, 0));
    }
  }

  /** Resolves once a frame of step `step` or later has arrived together with its topology (or after `timeout` ms). */
  async synced(step: number, timeout = 2000): Promise<void> {
    const until = performance.now() + timeout;
    await this.frameAt(step, timeout);
    while (!this.disposed && performance.now() < until && (this.frames.received === 0 || this.topology?.version !== this.frames.curr[F.topology])) {
      await new Promise((r) => setTimeout(r, 0));
      this.poll();
    }
  }

  get alive(): boolean {
    return !this.disposed;
  }

  dispose(): void {
    if (this.disposed) return;
    this.disposed = true;
    this.failAll((method) => new EngineStoppedError(`engine stopped (${method})`));
    this.teardown();
    this.triple = null;
  }
}
