// The engine host: owns one World, builds it from keyed plain-data descriptions, applies live edits, runs its own
// step loop and publishes each new state as one frame. The same class runs inside the worker (behind comlink) and on
// the main thread (worker="none" or no Worker available), so both modes share every line of simulation code.
// It composes the parts in host/: bindings (keys ↔ engine objects), the step loop, grab policy, snapshots, frame
// encoding, collision events and fault hooks; host/bodies/ says what each body type needs.
import type { World } from '../engine/index.js';
import { Bindings } from './host/bindings.js';
import { crossOriginIsolated, runningInWorker, warnIfKernelRefused, warnIfRowsRepaired } from './host/diagnostics.js';
import { EventQueue } from './host/events.js';
import { debugFault } from './host/faults.js';
import { FrameEncoder } from './host/frames.js';
import { grabAt, isGrab } from './host/grab.js';
import { StepLoop, type Clock } from './host/loop.js';
import type { HostOutput } from './host/output.js';
import { HostSettings } from './host/settings.js';
import { restoreSnapshot, takeSnapshot } from './host/snapshot.js';
import type {
  DebugFault, Diagnostics, EngineApi, FramePatch, HostError, HostParams, HostScene, HostSnapshot, KeyedBody, KeyedLink,
} from './protocol.js';
import type { Publisher } from './publishers.js';

/** The fields of Diagnostics the engine's World.diagnostics() gives: its kernel, and the rows its step put back. */
function worldDiagnostics(w: World): Pick<Diagnostics, 'kernel' | 'kernelRequested' | 'kernelReason' | 'rowsRepaired'> {
  const k = w.diagnostics();
  return { kernel: k.kernel, kernelRequested: k.requested, kernelReason: k.reason, rowsRepaired: k.rowsRepaired };
}

export { runningInWorker } from './host/diagnostics.js';
export type { Clock } from './host/loop.js';
export type { HostOutput } from './host/output.js';

export class EngineHost implements EngineApi {
  readonly #settings = new HostSettings();
  readonly #bindings: Bindings;
  readonly #frames: FrameEncoder;
  readonly #events = new EventQueue();
  readonly #loop: StepLoop;
  readonly #publisher: Publisher;
  readonly #output: HostOutput;
  #disposed = false;

  /** `clock`: the step loop's time and timers (tests pass a fake one). */
  constructor(publisher: Publisher, output: HostOutput, clock?: Clock) {
    this.#publisher = publisher;
    this.#output = output;
    // A frame skipped for want of a transfer buffer is written when one comes back: step(n) waits for its state.
    publisher.onFree = () => this.#publish();
    this.#bindings = new Bindings(this.#settings, () => this.#frames.invalidate());
    this.#frames = new FrameEncoder(this.#bindings, publisher, output);
    this.#loop = new StepLoop(
      {
        world: () => this.#world,
        afterStep: () => this.#afterStep(),
        stepped: () => this.#publish(),
      },
      clock,
    );
  }

  // ---- scene -------------------------------------------------------------------------------------------------

  load(scene: HostScene): HostError[] {
    this.#settings.worldOptions = { ...(scene.world ?? {}) };
    const errors = this.#setParamsOnly(scene.params ?? {});
    errors.push(...this.#bindings.load(scene.bodies, scene.links));
    warnIfKernelRefused(this.#world);
    this.#events.clear();
    if (scene.running) this.play();
    else this.#publish();
    return errors;
  }

  addBody(body: KeyedBody): HostError | null {
    return this.#edited(this.#bindings.addBody(body));
  }

  updateBody(body: KeyedBody): HostError | null {
    return this.#edited(this.#bindings.updateBody(body));
  }

  removeBody(key: number): void {
    this.#edited(this.#bindings.removeBody(key));
  }

  addLink(link: KeyedLink): HostError | null {
    return this.#edited(this.#bindings.addLink(link));
  }

  updateLink(link: KeyedLink): HostError | null {
    return this.addLink(link);
  }

  removeLink(key: number): void {
    this.#edited(this.#bindings.removeLink(key));
  }

  setParams(params: Partial<HostParams>): HostError | null {
    const errors = this.#setParamsOnly(params);
    if (this.#settings.kernelDiffers(this.#world)) this.#remakeWorld();
    this.#publish();
    return errors[0] ?? null;
  }

  // ---- time --------------------------------------------------------------------------------------------------

  play(): void {
    if (!this.#disposed && this.#loop.play()) this.#publish();
  }

  pause(): void {
    this.#loop.pause();
    this.#publish();
  }

  step(n = 1): number {
    this.#loop.step(n);
    this.#publish();
    return this.#world.stepCount;
  }

  reset(): void {
    this.#bindings.rebuild();
    this.#events.clear();
    this.#publish();
  }

  // ---- interaction -------------------------------------------------------------------------------------------

  grab(x: number, y: number, stiffness?: number): number | null {
    return grabAt(this.#bindings, x, y, stiffness);
  }

  moveGrab(grab: number, x: number, y: number): void {
    if (isGrab(this.#world, grab)) this.#world.moveGrab(grab, x, y);
  }

  release(grab: number): void {
    if (isGrab(this.#world, grab)) this.#world.release(grab);
  }

  /** Refused (a speed past the engine's limit): the error names the body's key, for its element. */
  applyImpulse(key: number, ix: number, iy: number): HostError | null {
    const r = this.#bindings.bodies.get(key);
    if (!r || r.handle === null) return null;
    const handle = r.handle;
    return refusedCall(key, 'applyImpulse', () => {
      this.#world.wake(handle);
      this.#world.applyBodyImpulse(handle, ix, iy);
    });
  }

  setVelocity(key: number, vx: number, vy: number): HostError | null {
    const r = this.#bindings.bodies.get(key);
    if (!r || r.handle === null) return null;
    const w = this.#world;
    const handle = r.handle;
    return refusedCall(key, 'setVelocity', () => {
      if (r.rigid) w.setBodyVelocity(handle, vx, vy);
      else for (const h of w.bodyParticleHandles(handle)) w.setVelocity(h, vx, vy);
    });
  }

  bodiesAt(x: number, y: number): number[] {
    return this.#world.bodiesAtPoint(x, y).map((h) => this.#bindings.keyOf(h));
  }

  // ---- state -------------------------------------------------------------------------------------------------

  snapshot(): HostSnapshot {
    return takeSnapshot(this.#bindings, this.#settings, this.#frames.topology);
  }

  restore(snapshot: HostSnapshot, frame?: FramePatch | null): number {
    restoreSnapshot(this.#bindings, this.#settings, snapshot, frame);
    this.#publish();
    return this.#world.stepCount;
  }

  /** @internal Test hook: 'throw' arms the step loop to throw on its next tick; 'hang' blocks this thread (20 s at most). */
  debugFault(fault: DebugFault): void {
    debugFault(fault, this.#loop);
  }

  stateHash(): string {
    return this.#world.stateHash();
  }

  diagnostics(): Diagnostics {
    const w = this.#world;
    return {
      inWorker: runningInWorker(),
      transport: this.#publisher.transport,
      crossOriginIsolated: crossOriginIsolated(),
      running: this.#loop.running,
      stepCount: w.stepCount,
      stepMs: this.#loop.stepMs,
      substepCount: w.substepCount,
      particleCount: w.particleCount,
      bodyCount: this.#frames.bodyCount,
      linkCount: this.#bindings.activeLinks().length,
      brokenLinks: w.brokenLinkCount,
      published: this.#frames.published,
      skipped: this.#frames.skipped,
      buffersAllocated: this.#publisher.allocated,
      events: this.#settings.params.events,
      eventsSent: this.#events.sent,
      ...worldDiagnostics(w),
    };
  }

  dispose(): void {
    this.#disposed = true;
    this.#loop.pause();
    this.#publisher.dispose();
  }

  // ---- parts -------------------------------------------------------------------------------------------------

  get #world(): World {
    return this.#bindings.world;
  }

  #setParamsOnly(params: Partial<HostParams>): HostError[] {
    const errors = this.#settings.apply(this.#world, params);
    if (!this.#settings.params.events) this.#events.clear();
    return errors;
  }

  /** A world made with the kernel the params now ask for, in the state of the current one (the same handles). */
  #remakeWorld(): void {
    const snapshot = this.snapshot();
    this.#bindings.rebuild();
    restoreSnapshot(this.#bindings, this.#settings, snapshot);
    warnIfKernelRefused(this.#world);
  }

  /** After an edit: a frame with the new topology, when what is built changed. */
  #edited<T>(result: T): T {
    if (this.#frames.topology < 0) this.#publish();
    return result;
  }

  #afterStep(): void {
    const w = this.#world;
    if (this.#settings.params.events) this.#events.collect(w, this.#bindings);
    this.#bindings.forgetRetired();
    // A torn cloth is drawn without its broken links: the topology says which.
    if (w.breaks.count > 0) this.#frames.invalidate();
  }

  /** Sends the events gathered since the last frame, then the frame. */
  #publish(): void {
    if (this.#disposed) return;
    warnIfRowsRepaired(this.#world);
    this.#events.flush(this.#settings.params.events, this.#output);
    this.#frames.publish(this.#loop.running, this.#settings.params.debug, this.#events.sent);
  }
}

/** Runs a call on body `key`; the engine's refusal (a RangeError or TypeError) as a HostError naming it, else null. */
function refusedCall(key: number, call: string, run: () => void): HostError | null {
  try {
    run();
    return null;
  } catch (error) {
    if (!(error instanceof RangeError || error instanceof TypeError)) throw error;
    return { key, field: '', message: error.message, call };
  }
}
