// Fakes for the controller tests: a host element, an engine client that records calls and answers as told, and a
// clock whose time moves only when the test advances it. No worker, no wall clock.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Engine } from '../../../src/elements/physics-scene/session.js';
import type { Clock } from '../../../src/elements/physics-scene/recovery.js';
import { FrameStore, type Remote } from '../../../src/worker/client.js';
import type { EngineApi, FramePatch, HostSnapshot, Topology, Transport } from '../../../src/worker/protocol.js';

/** A custom element that hosts controllers the way a LitElement does: connect, disconnect, update(). */
export class FakeHost extends HTMLElement implements ReactiveControllerHost {
  readonly controllers: ReactiveController[] = [];
  paused = false;
  debug = false;
  requestedUpdates = 0;

  addController(controller: ReactiveController): void {
    this.controllers.push(controller);
    if (this.isConnected) controller.hostConnected?.();
  }

  removeController(controller: ReactiveController): void {
    this.controllers.splice(this.controllers.indexOf(controller), 1);
  }

  requestUpdate(): void {
    this.requestedUpdates++;
  }

  get updateComplete(): Promise<boolean> {
    return Promise.resolve(true);
  }

  connectedCallback(): void {
    for (const c of this.controllers) c.hostConnected?.();
  }

  disconnectedCallback(): void {
    for (const c of this.controllers) c.hostDisconnected?.();
  }

  /** One update cycle, as Lit runs it for controllers: hostUpdate, then hostUpdated. */
  update(): void {
    for (const c of this.controllers) c.hostUpdate?.();
    for (const c of this.controllers) c.hostUpdated?.();
  }
}
if (!customElements.get('x-fake-host')) customElements.define('x-fake-host', FakeHost);

/** A fake host, not yet in the document. */
export function makeHost(): FakeHost {
  return document.createElement('x-fake-host') as FakeHost;
}

export const SNAPSHOT: HostSnapshot = { world: { tables: [] }, bodies: [], links: [], params: {} as HostSnapshot['params'] };

/** What a fake engine answers when the test says nothing else. */
const DEFAULT_ANSWERS: Partial<Record<keyof EngineApi, (...args: never[]) => unknown>> = {
  load: () => [],
  addBody: () => null,
  updateBody: () => null,
  addLink: () => null,
  updateLink: () => null,
  setParams: () => null,
  step: (n: number) => n,
  grab: () => null,
  snapshot: () => SNAPSHOT,
  restore: () => 0,
  stateHash: () => 'hash',
};

type Answer = (...args: never[]) => unknown;

/** An engine client that records every call and answers from `answers` (a function's value, or what it throws). */
export class FakeEngine implements Engine {
  mode: 'worker' | 'main' = 'worker';
  transport: Transport = 'transfer';
  worker: number | null = 1;
  died: string | null = null;
  latestStep = 0;
  disposed = false;
  readonly frames = new FrameStore();
  topology: Topology | null = null;
  readonly calls: { method: keyof EngineApi; args: unknown[] }[] = [];
  readonly answers: Partial<Record<keyof EngineApi, Answer>> = {};
  readonly poses = new Map<number, [number, number, number]>();
  readonly probes: { reason: string; timeout: number }[] = [];
  /** The newest frame, as lastFrame() gives it. */
  frame: FramePatch | null = null;
  readonly api: Remote;

  constructor(readonly name = 'engine') {
    this.api = new Proxy({} as Remote, {
      get: (_, method: keyof EngineApi) =>
        (...args: unknown[]) => {
          this.calls.push({ method, args });
          const answer = this.answers[method] ?? DEFAULT_ANSWERS[method];
          try {
            return Promise.resolve(answer ? (answer as (...a: unknown[]) => unknown)(...args) : undefined);
          } catch (error) {
            return Promise.reject(error);
          }
        },
    });
  }

  /** The arguments of every call to `method`, in order. */
  argsOf(method: keyof EngineApi): unknown[][] {
    return this.calls.filter((c) => c.method === method).map((c) => c.args);
  }

  /** The methods called, in order. */
  get methods(): string[] {
    return this.calls.map((c) => c.method);
  }

  poll(): void {}

  pose(key: number): [number, number, number] | null {
    return this.poses.get(key) ?? null;
  }

  lastFrame(): FramePatch | null {
    return this.frame;
  }

  async frameAt(): Promise<void> {}

  async synced(): Promise<void> {}

  async probe(reason: string, timeout: number): Promise<void> {
    this.probes.push({ reason, timeout });
  }

  debugTerminate(): void {}

  dispose(): void {
    this.disposed = true;
  }
}

/** Time that moves only when advanced; intervals run as they fall due, in time order. */
export class FakeClock implements Clock {
  time = 0;
  private nextId = 1;
  private readonly timers = new Map<number, { callback: () => void; ms: number; due: number }>();

  now(): number {
    return this.time;
  }

  setInterval(callback: () => void, ms: number): number {
    const id = this.nextId++;
    this.timers.set(id, { callback, ms, due: this.time + ms });
    return id;
  }

  clearInterval(id: number): void {
    this.timers.delete(id);
  }

  /** Intervals set and not cleared. */
  get pending(): number {
    return this.timers.size;
  }

  /** Moves time on by `ms`, running every interval that falls due on the way (`between` runs before each one). */
  advance(ms: number, between: () => void = () => {}): void {
    const end = this.time + ms;
    for (;;) {
      let next: { callback: () => void; ms: number; due: number } | null = null;
      for (const t of this.timers.values()) if (t.due <= end && (!next || t.due < next.due)) next = t;
      if (!next) break;
      this.time = next.due;
      next.due += next.ms;
      between();
      next.callback();
    }
    this.time = end;
  }
}

/** Lets promise callbacks (and a task) run. */
export function settle(): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/** A promise with its resolve and reject in hand. */
export function deferred<T>(): { promise: Promise<T>; resolve: (value: T) => void; reject: (error: unknown) => void } {
  let resolve!: (value: T) => void;
  let reject!: (error: unknown) => void;
  const promise = new Promise<T>((res, rej) => {
    resolve = res;
    reject = rej;
  });
  return { promise, resolve, reject };
}
