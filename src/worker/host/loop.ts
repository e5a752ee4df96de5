// The step loop: while playing, World.advance() takes the fixed steps real time allows (its maxCatchUpSteps caps a
// backlog) and each tick that stepped ends in one frame; step(n) takes n steps now. The clock is injectable, so tests
// drive the loop without waiting.
import type { World } from '../../engine/index.js';

export interface Clock {
  /** Milliseconds, monotonic. */
  now(): number;
  setTimeout(run: () => void, ms: number): unknown;
  clearTimeout(timer: unknown): void;
}

export const realClock: Clock = {
  now: () => performance.now(),
  setTimeout: (run, ms) => setTimeout(run, ms),
  clearTimeout: (timer) => clearTimeout(timer as ReturnType<typeof setTimeout>),
};

export interface LoopHooks {
  /** The world to step (load and reset replace it). */
  world(): World;
  /** After every step: read what the step left (collision events, broken links) before the next overwrites it. */
  afterStep(): void;
  /** After a tick that took steps: publish. */
  stepped(): void;
}

/** The most steps one step(n) call takes. */
const MAX_STEPS = 100000;

export class StepLoop {
  #running = false;
  /** A test fault (debugFault('throw')): the next tick throws. */
  failNextTick = false;
  readonly #hooks: LoopHooks;
  readonly #clock: Clock;
  #timer: unknown = null;
  #lastTick = 0;
  #stepMs = NaN;

  constructor(hooks: LoopHooks, clock: Clock = realClock) {
    this.#hooks = hooks;
    this.#clock = clock;
  }

  get running(): boolean {
    return this.#running;
  }

  /**
   * Milliseconds a step of the loop took (the world's step and what is read after it, not publishing), averaged over
   * about the last ten ticks that stepped; NaN before the first.
   */
  get stepMs(): number {
    return this.#stepMs;
  }

  /** Starts the loop; false when it was running already. */
  play(): boolean {
    if (this.#running) return false;
    this.#running = true;
    this.#lastTick = this.#clock.now();
    this.#schedule(0);
    return true;
  }

  pause(): void {
    this.#running = false;
    if (this.#timer !== null) this.#clock.clearTimeout(this.#timer);
    this.#timer = null;
  }

  /** Takes n fixed steps now (at most MAX_STEPS; anything not a number is 0), playing or not. */
  step(n: number): void {
    const count = Math.max(0, Math.min(MAX_STEPS, Math.floor(Number(n) || 0)));
    const w = this.#hooks.world();
    for (let k = 0; k < count; k++) {
      w.step();
      this.#hooks.afterStep();
    }
  }

  #schedule(ms: number): void {
    if (this.#timer !== null) this.#clock.clearTimeout(this.#timer);
    this.#timer = this.#clock.setTimeout(this.#tick, Math.max(0, ms));
  }

  #tick = (): void => {
    this.#timer = null;
    if (!this.#running) return;
    if (this.failNextTick) {
      // Uncaught on purpose: the loop stops here and the page sees the worker's error event.
      this.failNextTick = false;
      throw new Error('debug fault: the step loop threw');
    }
    const now = this.#clock.now();
    const elapsed = Math.max(0, (now - this.#lastTick) / 1000);
    this.#lastTick = now;
    const w = this.#hooks.world();
    const steps = w.advance(elapsed, this.#hooks.afterStep);
    if (steps > 0) {
      const perStep = (this.#clock.now() - now) / steps;
      this.#stepMs = Number.isNaN(this.#stepMs) ? perStep : 0.9 * this.#stepMs + 0.1 * perStep;
      this.#hooks.stepped();
    }
    // Wake up when the next step is due (variableStep worlds: one step of the elapsed time per timestep).
    this.#schedule((w.variableStep ? 1 : 1 - w.alpha) * w.timestep * 1000);
  };
}
