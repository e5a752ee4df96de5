// The page's engine workers: a small pool shared by every scene. Each scene is a world in one of them (addressed by a
// world id), placed in the least-loaded worker; a new worker is made only while every worker holds a world and the
// pool is below its size. A worker whose last world closed lives on for a short grace period (a page that swaps one
// scene for another reuses it), then it is terminated. When a worker dies (an uncaught error in it, a message that
// cannot be read, or a member declaring it hung), it is terminated and every world in it is told; the other workers
// are untouched.
import * as Comlink from 'comlink';
import type { WorkerEndpoint } from './engine.worker.js';
import type { EngineApi, Transport } from './protocol.js';
import { track } from './resources.js';

/** A world's owner: told once when its worker dies. */
export interface PoolMember {
  died(reason: string): void;
}

/** One world in a pool worker, as its owner (an EngineClient) uses it. */
export interface WorldLink {
  /** The world's id in its worker. */
  readonly id: number;
  /** Which pool worker holds it (a serial number, unique on the page). */
  readonly worker: number;
  readonly transport: Transport;
  /** The world's frames, topology and events arrive here. */
  readonly port: MessagePort;
  /** Calls the world's host. */
  invoke(method: keyof EngineApi, args: unknown[]): Promise<unknown>;
  /** The worker is hung or gone (a call went unanswered): it is terminated and every world in it dies with `reason`. */
  fail(reason: string): void;
  /** Ends the world; its worker is terminated once it holds none (after the grace period). */
  close(): void;
  /** @internal Test hook: terminates the worker and tells no one (as if the browser had killed it). */
  kill(): void;
}

export interface PoolOptions {
  /** Makes a worker. */
  createWorker: () => Worker;
  /** The most workers at once (read at every placement). */
  size: () => number;
  /** Milliseconds a worker without worlds lives on before it is terminated (0: at once). Default GRACE_MS. */
  grace?: number;
}

/** How long an empty worker waits for a new world before it is terminated (ms). */
export const GRACE_MS = 1000;

/**
 * The longest delay a timer takes (ms, 2^31 − 1, about 24.8 days): a longer one overflows, and the browser fires it at
 * once (a timeout of 3e9 ms or Infinity failed every worker's start at once, "did not answer within 3000000000 ms").
 */
export const MAX_TIMER_MS = 2147483647;

/** A timeout as a timer can wait for it: at most MAX_TIMER_MS. */
export function timerDelay(ms: number): number {
  return ms > MAX_TIMER_MS ? MAX_TIMER_MS : ms;
}

/** A call that got no answer within the timeout; the message names the method. */
export class TimeoutError extends Error {
  override name = 'TimeoutError';
}

interface PoolWorker {
  readonly serial: number;
  readonly worker: Worker;
  readonly remote: Comlink.Remote<WorkerEndpoint>;
  /** Worlds opened in it, by id. */
  readonly members: Map<number, PoolMember>;
  /** Worlds being opened: how to fail each open. */
  readonly opening: Map<number, (error: Error) => void>;
  dead: boolean;
  idle: ReturnType<typeof setTimeout> | null;
  /** Removes the error listeners and terminates the worker. */
  end(): void;
}

let nextSerial = 1;
let nextWorld = 1;

/** The default size: one worker per spare core, at least one and at most two (the page's own thread needs a core). */
export function defaultPoolSize(): number {
  const cores = typeof navigator === 'object' && Number.isFinite(navigator.hardwareConcurrency) ? navigator.hardwareConcurrency : 2;
  return Math.max(1, Math.min(2, cores - 1));
}

export class WorkerPool {
  readonly #workers: PoolWorker[] = [];
  readonly #options: PoolOptions;

  constructor(options: PoolOptions) {
    this.#options = options;
  }

  /** Live workers (made and not terminated). */
  get workerCount(): number {
    return this.#workers.length;
  }

  /** Worlds (open or opening) per live worker, in the order the workers were made. */
  get loads(): number[] {
    return this.#workers.map(load);
  }

  /**
   * Opens a world for `member` in the least-loaded worker (a new one while the pool has room and every worker holds a
   * world). Fails when the worker cannot be made, fails to load or does not answer within `timeout` ms (a worker that
   * does not answer is terminated, and the worlds in it die). A timeout past MAX_TIMER_MS waits MAX_TIMER_MS.
   */
  async open(member: PoolMember, timeout: number): Promise<WorldLink> {
    timeout = timerDelay(timeout);
    const w = this.#place();
    const id = nextWorld++;
    if (w.idle !== null) clearTimeout(w.idle);
    w.idle = null;
    const channel = new MessageChannel();
    const wantShared = typeof SharedArrayBuffer === 'function' && globalThis.crossOriginIsolated === true;
    let timer: ReturnType<typeof setTimeout> | undefined;
    try {
      const info = await new Promise<{ transport: Transport }>((resolve, reject) => {
        w.opening.set(id, reject);
        timer = setTimeout(() => {
          const error = new TimeoutError(`the worker did not answer within ${timeout} ms`);
          reject(error);
          this.#die(w, error.message, error.message);
        }, timeout);
        w.remote.open(id, Comlink.transfer(channel.port2, [channel.port2]), wantShared).then(resolve, reject);
      });
      if (w.dead) throw new Error('the worker died while the world was opened');
      w.members.set(id, member);
      return this.#link(w, id, info.transport, channel.port1);
    } catch (error) {
      channel.port1.close();
      w.opening.delete(id);
      this.#release(w);
      throw error;
    } finally {
      clearTimeout(timer);
      w.opening.delete(id);
    }
  }

  #link(w: PoolWorker, id: number, transport: Transport, port: MessagePort): WorldLink {
    let closed = false;
    return {
      id,
      worker: w.serial,
      transport,
      port,
      invoke: (method, args) => w.remote.invoke(id, method, args).catch(retyped),
      fail: (reason) => this.#die(w, reason, reason),
      close: () => {
        if (closed) return;
        closed = true;
        port.close();
        if (w.dead || !w.members.delete(id)) return;
        // Fire and forget: the worker may be gone meanwhile, and a terminated one answers nothing.
        w.remote.close(id).catch(() => {});
        this.#release(w);
      },
      kill: () => w.worker.terminate(),
    };
  }

  /** The least-loaded live worker, or a new one while there is room and none is empty. */
  #place(): PoolWorker {
    let best: PoolWorker | null = null;
    for (const w of this.#workers) if (!best || load(w) < load(best)) best = w;
    if (best && (load(best) === 0 || this.#workers.length >= Math.max(1, this.#options.size()))) return best;
    return this.#make();
  }

  #make(): PoolWorker {
    const worker = this.#options.createWorker();
    track('workers', 1);
    const w: PoolWorker = {
      serial: nextSerial++,
      worker,
      remote: Comlink.wrap<WorkerEndpoint>(worker),
      members: new Map(),
      opening: new Map(),
      dead: false,
      idle: null,
      end: () => {
        worker.removeEventListener('error', onError);
        worker.removeEventListener('messageerror', onError);
        w.remote[Comlink.releaseProxy]();
        worker.terminate();
        track('workers', -1);
      },
    };
    const onError = (event: ErrorEvent | MessageEvent) => {
      const message = 'message' in event && typeof event.message === 'string' && event.message ? event.message : 'the worker script failed to load';
      // Handled here: not also reported as an uncaught error of the page.
      if (w.members.size > 0) event.preventDefault();
      const reason = event.type === 'messageerror' ? 'a message from the worker could not be read' : `uncaught error in the worker: ${message}`;
      this.#die(w, reason, message);
    };
    worker.addEventListener('error', onError);
    worker.addEventListener('messageerror', onError);
    this.#workers.push(w);
    return w;
  }

  /** A world closed or failed to open: an empty worker is terminated after the grace period. */
  #release(w: PoolWorker): void {
    if (w.dead || load(w) > 0 || w.idle !== null) return;
    const grace = this.#options.grace ?? GRACE_MS;
    if (grace <= 0) this.#terminate(w);
    else w.idle = setTimeout(() => this.#terminate(w), grace);
  }

  #terminate(w: PoolWorker): void {
    if (w.dead) return;
    w.dead = true;
    if (w.idle !== null) clearTimeout(w.idle);
    w.idle = null;
    this.#workers.splice(this.#workers.indexOf(w), 1);
    w.end();
  }

  /** The worker is dead: terminated, worlds being opened fail with `loadMessage`, opened ones die with `reason`. */
  #die(w: PoolWorker, reason: string, loadMessage: string): void {
    if (w.dead) return;
    this.#terminate(w);
    for (const fail of [...w.opening.values()]) fail(new Error(loadMessage));
    const members = [...w.members.values()];
    w.members.clear();
    for (const m of members) m.died(reason);
  }
}

function load(w: PoolWorker): number {
  return w.members.size + w.opening.size;
}

/**
 * A TypeError or RangeError thrown in the worker arrives as a plain Error with its name (comlink keeps the name and the
 * message, not the class): it is given its class back, so that `instanceof` tells it as the API documents it.
 */
function retyped(error: unknown): never {
  const Class = error instanceof Error && (error.name === 'TypeError' ? TypeError : error.name === 'RangeError' ? RangeError : null);
  throw Class ? new Class((error as Error).message) : error;
}
