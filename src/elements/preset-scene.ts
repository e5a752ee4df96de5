import { css } from 'lit';
import { property } from 'lit/decorators.js';
import { numberAttribute, type Problem } from './checks.js';
import { checkedView, type ViewSize } from './physics-scene/config.js';
import { checkSteps, PhysicsSceneElement } from './physics-scene/physics-scene.js';

/** Steps between two ticks of a preset's behaviour (a tenth of a second at the default timestep). */
const TICK_STEPS = 6;
/** How often a running preset looks at the simulated time (page clock; the behaviour itself follows the steps). */
const TICK_MS = 100;
/**
 * A preset's view in world units: its bodies are laid out for it, and a bad `width` or `height` falls back to it (the
 * `height` property's default below is written out, for the manifest's analyzer).
 */
const PRESET_VIEW: ViewSize = Object.freeze({ width: 16, height: 10 });

/**
 * What `<cloth-sim>` and `<ragdoll-sim>` share: a `<physics-scene>` whose bodies are generated, from a setup read off
 * its own attributes at each update, into a hidden part of its shadow root, so the page's markup stays one tag; the
 * setup's problems are reported like the scene's own.
 *
 * A preset may also act over time (the cloth's gusts, the ragdolls' respawn): its `tick(seconds)` runs at simulated
 * time `seconds`, between steps. While the scene runs, a timer ticks at the newest step; `step(n)` ticks every
 * TICK_STEPS steps on the way. So a paused scene stepped by script behaves as it would running, and the same steps give
 * the same ticks (no page clock in what happens).
 */
export abstract class PresetSceneElement<Setup extends { problems: Problem[] }> extends PhysicsSceneElement {
  static override styles = [
    PhysicsSceneElement.styles,
    css`
      .bodies {
        display: none;
      }
    `,
  ];

  /** World units down the view (>= 0.001). Default 10. */
  @property({ type: Number, converter: numberAttribute }) override height = 10;

  /** What a bad `width` or `height` falls back to: this preset's view, not the scene's 16 × 9. @internal */
  get viewDefaults(): ViewSize {
    return PRESET_VIEW;
  }

  /** The setup of the last update. */
  protected setup: Setup | null = null;

  private tickTimer: ReturnType<typeof setInterval> | null = null;
  private lastTicked = -1;

  /** Reads and checks the preset's attributes (problems listed, defaults used). */
  protected abstract readSetup(): Setup;

  /** True when the preset acts over time with this setup (the timer runs and step(n) ticks only then). */
  protected abstract ticks(setup: Setup): boolean;

  /**
   * The preset's behaviour at simulated time `seconds`. Resolves once the changes it made have been sent to the
   * engine (step(n) waits for that before the next steps).
   */
  protected abstract tick(seconds: number): void | Promise<void>;

  protected override get bodyContainer(): ParentNode & Node {
    return (this.renderRoot?.querySelector('.bodies') as HTMLElement | null) ?? this.renderRoot ?? this;
  }

  /** The view's width and height as the scene draws it (each its default when bad): what the bodies are laid out for. */
  protected get view(): ViewSize {
    return checkedView(this);
  }

  /** Simulated seconds at the newest step shown. */
  protected get seconds(): number {
    return this.stepCount * this.dt;
  }

  /** Seconds per step. */
  private get dt(): number {
    return Number.isFinite(this.timestep) && this.timestep > 0 ? this.timestep : 1 / 60;
  }

  /**
   * Takes `n` fixed steps now (also while paused). The preset's behaviour (gusts, respawns) runs at every sixth step
   * of the step count (0, 6, 12, …), before the steps that follow, so the same steps give the same result however
   * they are split into calls.
   */
  override async step(n = 1): Promise<number> {
    checkSteps(n);
    const total = n;
    if (total <= 0 || !this.setup || !this.ticks(this.setup)) return super.step(n);
    let count = await super.step(0);
    for (let left = total; ; ) {
      if (count % TICK_STEPS === 0 && count !== this.lastTicked) {
        this.lastTicked = count;
        // Live poses of this step (bodies a tick rebuilt come with a new topology, on its own port).
        await this.client?.synced(count);
        await this.tick(count * this.dt);
      }
      if (left <= 0) return count;
      const next = await super.step(Math.min(left, TICK_STEPS - (count % TICK_STEPS)));
      if (next <= count) return count; // no engine (stopped meanwhile)
      left -= next - count;
      count = next;
    }
  }

  /** Its generated bodies change with its behaviour (a respawn): a snapshot restores while the same bodies exist. */
  protected override get snapshotsMatchMarkup(): boolean {
    return false;
  }

  /** Rebuilds the scene from its markup, at time 0 (where the preset's behaviour starts again too). */
  override async reset(): Promise<void> {
    await super.reset();
    this.lastTicked = -1;
  }

  protected override willUpdate(changed: Map<string, unknown>): void {
    super.willUpdate(changed);
    this.setup = this.readSetup();
  }

  protected override updated(changed: Map<string, unknown>): void {
    super.updated(changed);
    this.reportPresetProblems(this.setup?.problems ?? []);
    this.runningChanged(this.running);
  }

  /** The timer runs while the scene steps by itself (the scene calls this on every change, and stop() with false). */
  protected override runningChanged(running: boolean): void {
    // Not once removed: an update after the removal (stop() resets state) must not start the timer again, which
    // would keep the element alive for good.
    const on = running && this.isConnected && this.setup !== null && this.ticks(this.setup);
    if (on && this.tickTimer === null) {
      this.tickTimer = setInterval(() => {
        const now = this.stepCount;
        if (now === this.lastTicked) return;
        this.lastTicked = now;
        void this.tick(now * this.dt);
      }, TICK_MS);
    } else if (!on && this.tickTimer !== null) {
      clearInterval(this.tickTimer);
      this.tickTimer = null;
    }
  }
}
