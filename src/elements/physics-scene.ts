import { LitElement, css, html, nothing, type CSSResultGroup, type TemplateResult } from 'lit';
import { property, state } from 'lit/decorators.js';
import type { BodyDescription, Bounds } from '../engine/index.js';
import { SceneRenderer, type DrawHook } from '../render/renderer.js';
import { EngineClient, EngineStoppedError, TimeoutError, WorkerDiedError } from '../worker/client.js';
import { track } from '../worker/resources.js';
import { EVENT, type Diagnostics, type FramePatch, type HostError, type HostParams, type HostScene, type HostSnapshot, type KeyedBody, type KeyedLink, type LinkDescription, type Transport } from '../worker/protocol.js';
import { PhysicsBodyElement } from './body-element.js';
import { Checker, describeElement, displayValue, type Problem } from './checks.js';
import { PhysicsLinkElement } from './link-element.js';
import type { SceneHost } from './scene-host.js';

/** Detail of `physics-error`. */
export interface PhysicsErrorDetail {
  /** The element whose markup is wrong (a child, or the scene). */
  element: Element;
  /** The attribute at fault ("" when the problem is not one attribute's). */
  attribute: string;
  /** Its value as written. */
  value: string;
  message: string;
}

/** Detail of `physics-collision` and `physics-collision-end`. */
export interface PhysicsCollisionDetail {
  a: Element | null;
  b: Element | null;
  /** Contact normal from a to b (zero for end events). */
  normal: { x: number; y: number };
  /** Deepest overlap seen when the contact began (0 for end events). */
  depth: number;
}

/** Detail of `physics-ready`. */
export interface PhysicsReadyDetail {
  /** Where the engine runs. */
  mode: 'worker' | 'main';
  /** How states reach the page: SharedArrayBuffer, transferred ArrayBuffers, or directly (main thread). */
  transport: Transport;
}

interface Entry {
  element: PhysicsBodyElement | PhysicsLinkElement;
  kind: 'body' | 'link';
  /** JSON of the description last sent to the engine ('' = none). */
  sent: string;
  /** Problems already reported, so each is reported once per change. */
  reported: Set<string>;
}

interface Config {
  width: number;
  height: number;
  gravity: { x: number; y: number };
  iterations: number;
  substeps: number;
  timestep: number;
  broadphase: 'grid' | 'brute';
  narrowphase: 'sat' | 'gjk';
  bounds: 'view' | 'none';
  maxRestarts: number;
}

// Fault recovery. A snapshot of the whole simulation is taken from the worker about once a second while it steps
// (and after step(), reset(), restore() and the first load): a structured clone of the engine's tables, which costs
// well under a millisecond for the scenes an embed runs and a few milliseconds for the largest, so once a second keeps
// its cost negligible. A snapshot alone would rewind up to a second; the page also holds the newest frame, so after a
// restart the particles are moved to where they were last drawn (velocities from the two newest frames) on top of
// the snapshot, and the scene resumes from what the user saw. Bodies, links and parameters come from the markup,
// which stays the source of truth: what changed after the snapshot is applied again after the restore.
/** Milliseconds between snapshots while the scene steps. */
const SNAPSHOT_EVERY = 1000;
/** How often the keeper looks at the step counter (ms). */
const KEEPER_TICK = 250;
/** Restarts count within this window (ms); more than `max-restarts` in it and the scene gives up. */
const RESTART_WINDOW = 60000;
/** No new step for this long while running (ms, at least 3 fixed steps) and the worker is probed. */
const STALL_AFTER = 1500;
/** A probe unanswered for this long (ms, at most callTimeout) declares the worker dead. */
const PROBE_TIMEOUT = 1000;

const COLLISION_EVENTS = new Set(['physics-collision', 'physics-collision-end']);
const ENGINE_FIELDS: Record<string, string> = { from: 'x1', to: 'x2', origin: 'x', center: 'x', structural: 'compliance', jointCompliance: 'joint-compliance' };

/**
 * A physics scene. Its child elements (`<physics-box>`, `<physics-circle>`, `<physics-rope>`, …) declare bodies; the
 * scene simulates them in a Web Worker at a fixed step and draws them with p5 into a canvas in its shadow root.
 * The markup is the source of truth: adding, removing or changing a child or an attribute updates the running
 * simulation. World units: `width` × `height` is the visible box (like an SVG viewBox), y grows downward.
 *
 * @summary A declarative 2D physics scene.
 *
 * @fires physics-ready - The engine runs and the scene is loaded (detail: `{mode, transport}`).
 * @fires physics-collision - Two bodies began touching (detail: `{a, b, normal, depth}`, a and b are the body elements). Sent only while a listener is registered on the scene (or `collision-events` is set).
 * @fires physics-collision-end - Two bodies stopped touching (detail: `{a, b}`).
 * @fires physics-error - Bad markup or a failing engine (detail: `{element, attribute, value, message}`); the rest of the scene keeps running. A dead engine worker is reported with `attribute` "worker" and restarted (up to `max-restarts` times a minute).
 *
 * @csspart stage - The box that holds the canvas.
 * @csspart canvas - The p5 canvas.
 * @csspart status - The loading message shown until the engine runs.
 * @csspart error - The visible list of current problems (bad attributes, a failing engine).
 * @csspart play-button - The play control, shown when the scene started paused for `prefers-reduced-motion` or was paused with Space.
 *
 * Embedding: the scene steps only while it is on screen and the page is visible (no frames, no engine ticks
 * otherwise); with `prefers-reduced-motion: reduce` it starts paused and shows a play control; it is focusable and
 * Space toggles pause; it gets `role="group"`, `aria-label` and `aria-keyshortcuts="Space"` unless the page sets them.
 *
 * @cssprop --physics-scene-aspect - Aspect ratio of the element when its height is not set (default: width / height).
 */
export class PhysicsSceneElement extends LitElement implements SceneHost {
  static override styles: CSSResultGroup = css`
    :host {
      display: block;
      position: relative;
      aspect-ratio: var(--physics-scene-aspect, 16 / 9);
      overflow: hidden;
      touch-action: none;
      user-select: none;
      -webkit-user-select: none;
      contain: layout paint;
    }
    :host([hidden]) {
      display: none;
    }
    :host(:focus-visible) {
      outline: 2px solid #2f6fb5;
      outline-offset: 2px;
    }
    .stage {
      position: absolute;
      inset: 0;
    }
    .status {
      position: absolute;
      inset: 0;
      display: flex;
      align-items: center;
      justify-content: center;
      font: 14px/1.3 system-ui, sans-serif;
      color: #5b6270;
      pointer-events: none;
    }
    .error[hidden] {
      display: none;
    }
    .error {
      position: absolute;
      left: 6px;
      right: 6px;
      bottom: 6px;
      max-height: 45%;
      overflow: auto;
      padding: 4px 8px;
      border: 1px solid #e0a090;
      border-radius: 4px;
      background: #fff3efee;
      color: #8a1c0c;
      font: 12px/1.35 system-ui, sans-serif;
      white-space: pre-wrap;
      overflow-wrap: anywhere;
    }
    .play {
      position: absolute;
      left: 50%;
      top: 50%;
      width: 56px;
      height: 56px;
      margin: -28px 0 0 -28px;
      border: 0;
      border-radius: 50%;
      background: #14181ebb;
      color: #fff;
      font: 22px/56px system-ui, sans-serif;
      cursor: pointer;
      padding: 0 0 0 4px;
    }
    .play:focus-visible {
      outline: 3px solid #fff;
      outline-offset: -6px;
    }
    ::slotted(*) {
      display: none;
    }
  `;

  /** Makes the engine worker; replace it to load the worker from elsewhere (or to test a failing one). */
  static workerFactory: (() => Worker) | null = null;
  /** Milliseconds an engine call (and the worker's start) may take before it fails with `physics-error`. */
  static callTimeout = 8000;

  /** World units across the view. Default 16. */
  @property({ type: Number }) width = 16;
  /** World units down the view. Default 9. */
  @property({ type: Number }) height = 9;
  /** Gravity "x y" in world units / s² (y grows downward). Default "0 9.81". */
  @property() gravity = '0 9.81';
  /** Gauss–Seidel iterations per substep. Default 1. */
  @property({ type: Number }) iterations = 1;
  /** Substeps per step. Default 10. */
  @property({ type: Number }) substeps = 10;
  /** Fixed step in seconds. Default 1/60. */
  @property({ type: Number }) timestep = 1 / 60;
  /** Starts (and stays) paused. */
  @property({ type: Boolean, reflect: true }) paused = false;
  /** Draws AABBs, contacts and the broad phase's grid cells. */
  @property({ type: Boolean, reflect: true }) debug = false;
  /** Broad phase: "grid" (default) or "brute". */
  @property() broadphase = 'grid';
  /** Narrow phase for polygon pairs: "sat" (default, separating axes) or "gjk" (GJK distance, EPA when overlapping). */
  @property() narrowphase = 'sat';
  /** "view" (default): walls at the sides and bottom of the width × height box (open at the top); "none": unbounded. */
  @property() bounds = 'view';
  /** Canvas background (CSS colour). Default "#f7f5f0". */
  @property() background = '#f7f5f0';
  /** "auto" (default): the engine runs in a Web Worker when possible; "none": on the main thread. */
  @property() worker = 'auto';
  /** Send collision events even with no listener on the scene itself (for listeners on ancestors). */
  @property({ type: Boolean, attribute: 'collision-events' }) collisionEvents = false;
  /**
   * Restarts of a dead or hung engine worker allowed within 60 s. Each fires `physics-error` ("restarting it,
   * attempt k of n") and restores the last snapshot; one more failure within the minute stops the scene with a final
   * `physics-error` and the error box. Default 3; 0 never restarts.
   */
  @property({ type: Number, attribute: 'max-restarts' }) maxRestarts = 3;
  /** How `drawHook` combines with the default drawing: "over" (default) or "replace". */
  @property({ attribute: 'draw-mode' }) drawMode = 'over';
  /**
   * Custom p5 drawing, called every frame with a DrawView (the p5 instance, the 2D context, interpolated particle
   * positions, the topology and the world → canvas mapping), after the default drawing ("over") or instead ("replace").
   */
  @property({ attribute: false }) drawHook: DrawHook | null = null;

  private client: EngineClient | null = null;
  /** While a dead worker is replaced (and after giving up): the dead client, whose last frame stays drawn. */
  private shown: EngineClient | null = null;
  /** The newest snapshot and the client it came from (its frames may be laid over it). */
  private saved: { client: EngineClient; snapshot: HostSnapshot; grab: number | null } | null = null;
  /** performance.now() of each restart within the window. */
  private restartTimes: number[] = [];
  private recovering = false;
  private gaveUp = false;
  private keeper: ReturnType<typeof setInterval> | null = null;
  private watchStep = -1;
  private watchAt = 0;
  private snapAt = 0;
  private snapping = false;
  private renderer: SceneRenderer | null = null;
  private generation = 0;
  private loaded = false;
  private nextKey = 1;
  private keys = new WeakMap<Element, number>();
  private readonly entries = new Map<number, Entry>();
  private readonly ownReported = new Set<string>();
  private collisionListeners = 0;
  private eventsOn = false;
  private drag: { id: number; grab: number | null; x: number; y: number; done: boolean } | null = null;
  private readonly observer = new MutationObserver(() => this.sync());
  private readyResolve: (() => void) | null = null;
  private _ready: Promise<void> = this.newReady();
  /** On screen (IntersectionObserver) and the page visible (Page Visibility). */
  private inView = true;
  private pageVisible = typeof document === 'undefined' || document.visibilityState !== 'hidden';
  /** Running state last sent to the engine (null: none sent yet). */
  private runningSent: boolean | null = null;
  private io: IntersectionObserver | null = null;
  private motionChecked = false;
  private playRequested = false;
  /** Current problems per source (an element's reported set, or 'failures'), shown in the error box. */
  private readonly problemLines = new Map<object, string[]>();
  private failures: string[] = [];
  /** The loading message is shown. */
  @state() private loading = true;
  /** The play control is shown (while paused). */
  @state() private playControl = false;
  /** The error box's lines (written straight into the DOM: problems are found during updates). */
  private errorLines: string[] = [];

  constructor() {
    super();
    this.addEventListener('keydown', this.onKeyDown);
  }

  /** Resolves when the engine has loaded the scene (after each start). */
  get ready(): Promise<void> {
    return this._ready;
  }

  /** Where the engine runs ('worker' or 'main'), or null before it started. */
  get mode(): 'worker' | 'main' | null {
    return this.client?.mode ?? null;
  }

  /** How states reach the page, or null before the engine started. */
  get transport(): Transport | null {
    return this.client?.transport ?? null;
  }

  /** Frames drawn so far. */
  get renderedFrames(): number {
    return this.renderer?.drawn ?? 0;
  }

  /** The canvas, once p5 has made it. */
  get canvas(): HTMLCanvasElement | null {
    return this.renderer?.canvas ?? null;
  }

  /** Where the body elements live. Presets built on this class may keep generated bodies elsewhere. */
  protected get bodyContainer(): ParentNode & Node {
    return this;
  }

  /** Extra shadow content of a preset (e.g. its generated body elements). */
  protected renderBodies(): TemplateResult | typeof nothing {
    return nothing;
  }

  /** Added to `gravity` when sent to the engine (a preset's wind). */
  private gravityOffset = { x: 0, y: 0 };
  private readonly presetReported = new Set<string>();

  /** A preset's uniform extra acceleration (e.g. wind), added to `gravity`. */
  protected setGravityOffset(x: number, y: number): void {
    if (x === this.gravityOffset.x && y === this.gravityOffset.y) return;
    this.gravityOffset = { x, y };
    if (this.client && this.loaded) this.client.api.setParams({ gravity: this.effectiveGravity(this.config()) }).catch((e) => this.reportFailure(e));
  }

  private effectiveGravity(config: Config): { x: number; y: number } {
    return { x: config.gravity.x + this.gravityOffset.x, y: config.gravity.y + this.gravityOffset.y };
  }

  /** Reports a preset's own attribute problems (the current set: fixed ones leave the error box). */
  protected reportPresetProblems(problems: Problem[]): void {
    this.reportProblems(this, problems, this.presetReported);
  }

  /** Called when the scene starts or stops stepping (pause, scrolled away, hidden page). */
  protected runningChanged(_running: boolean): void {}

  /** The default `aria-label`. */
  protected get defaultLabel(): string {
    return 'Physics simulation';
  }

  /** True while the engine steps: not paused, on screen and the page visible. */
  get running(): boolean {
    return !this.paused && this.inView && this.pageVisible;
  }

  /** True while the element is on screen and the page is visible (frames are drawn). */
  get onScreen(): boolean {
    return this.inView && this.pageVisible;
  }

  // ---- public methods ----------------------------------------------------------------------------------------

  /** Runs the simulation (clears `paused`). */
  play(): void {
    this.playRequested = true;
    this.paused = false;
  }

  /** Stops the simulation (sets `paused`). */
  pause(): void {
    this.paused = true;
  }

  /** Takes `n` fixed steps now (also while paused). Resolves to the step count. */
  async step(n = 1): Promise<number> {
    await this.ready;
    const c = this.client;
    if (!c) return 0;
    const count = await c.api.step(n);
    await c.frameAt(count);
    this.keepSnapshot();
    return count;
  }

  /** Steps taken, as of the newest frame received. */
  get stepCount(): number {
    return (this.shown ?? this.client)?.latestStep ?? 0;
  }

  /** Rebuilds the scene from its markup, at time 0. */
  async reset(): Promise<void> {
    await this.ready;
    await this.client?.api.reset();
    await this.client?.frameAt(0);
    this.keepSnapshot();
  }

  /** Where and how the engine runs, and what it holds. */
  async diagnostics(): Promise<Diagnostics & { mode: 'worker' | 'main' }> {
    await this.ready;
    if (!this.client) throw new Error('<physics-scene> is not running');
    return { ...(await this.client.api.diagnostics()), mode: this.client.mode };
  }

  /** A hash of the full simulation state: equal markup and equal steps give equal hashes in every mode. */
  async stateHash(): Promise<string> {
    await this.ready;
    return this.client ? this.client.api.stateHash() : '';
  }

  /** The whole simulation state as plain data. */
  async snapshot(): Promise<HostSnapshot> {
    await this.ready;
    if (!this.client) throw new Error('<physics-scene> is not running');
    return this.client.api.snapshot();
  }

  /** Puts back a state from snapshot() (of this scene's markup). */
  async restore(snapshot: HostSnapshot): Promise<void> {
    await this.ready;
    await this.client?.api.restore(snapshot);
    this.keepSnapshot();
  }

  /** A world point in viewport (client) coordinates, e.g. to place an overlay or synthesise pointer events. */
  worldToClient(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const r = canvas.getBoundingClientRect();
    const p = this.renderer.worldToCanvas(x, y);
    return { x: r.left + p.x, y: r.top + p.y };
  }

  /** A viewport point in world units. */
  clientToWorld(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const r = canvas.getBoundingClientRect();
    return this.renderer.canvasToWorld(x - r.left, y - r.top);
  }

  // ---- lifecycle ---------------------------------------------------------------------------------------------

  override connectedCallback(): void {
    super.connectedCallback();
    if (!this.hasAttribute('tabindex')) this.tabIndex = 0;
    if (!this.hasAttribute('role')) this.setAttribute('role', 'group');
    if (!this.hasAttribute('aria-label') && !this.hasAttribute('aria-labelledby')) this.setAttribute('aria-label', this.defaultLabel);
    if (!this.hasAttribute('aria-keyshortcuts')) this.setAttribute('aria-keyshortcuts', 'Space');
    if (!this.motionChecked) {
      this.motionChecked = true;
      if (!this.paused && !this.playRequested && typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches) {
        this.paused = true;
        this.playControl = true;
      }
    }
    this.watchVisibility(true);
    if (!this.client && !this.starting) void this.start();
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    this.watchVisibility(false);
    // A move (disconnect then connect in the same task) keeps the running engine.
    queueMicrotask(() => {
      if (!this.isConnected) this.stop();
    });
  }

  override addEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | AddEventListenerOptions): void {
    if (!listener) return;
    super.addEventListener(type, listener, options);
    if (COLLISION_EVENTS.has(type) && listener) {
      this.collisionListeners++;
      this.updateEventFlag();
    }
  }

  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | EventListenerOptions): void {
    if (!listener) return;
    super.removeEventListener(type, listener, options);
    if (COLLISION_EVENTS.has(type) && listener && this.collisionListeners > 0) {
      this.collisionListeners--;
      this.updateEventFlag();
    }
  }

  protected override render() {
    return html`<div
        class="stage"
        part="stage"
        @pointerdown=${this.onPointerDown}
        @pointermove=${this.onPointerMove}
        @pointerup=${this.onPointerUp}
        @pointercancel=${this.onPointerUp}
      ></div>
      ${this.loading ? html`<div class="status" part="status" role="status">Loading simulation…</div>` : nothing}
      ${this.playControl && this.paused
        ? html`<button class="play" part="play-button" type="button" aria-label="Play the simulation" @click=${this.onPlayClick}>▶</button>`
        : nothing}
      <div class="error" part="error" role="alert" hidden></div>
      ${this.renderBodies()}
      <slot></slot>`;
  }

  protected override updated(changed: Map<string, unknown>): void {
    const config = this.config();
    this.style.setProperty('--physics-scene-aspect', `${config.width} / ${config.height}`);
    const r = this.renderer;
    if (r) this.applyView(r, config);
    if (changed.has('worker') && changed.get('worker') !== undefined && this.client) {
      this.stop();
      void this.start();
      return;
    }
    const c = this.client;
    if (!c || !this.loaded) return;
    const params: Partial<HostParams> = {};
    if (changed.has('gravity')) params.gravity = this.effectiveGravity(config);
    if (changed.has('iterations')) params.iterations = config.iterations;
    if (changed.has('substeps')) params.substeps = config.substeps;
    if (changed.has('timestep')) params.timestep = config.timestep;
    if (changed.has('broadphase')) params.broadphase = config.broadphase;
    if (changed.has('narrowphase')) params.narrowphase = config.narrowphase;
    if (changed.has('debug')) params.debug = this.debug;
    if (changed.has('width') || changed.has('height') || changed.has('bounds')) params.bounds = this.viewBounds(config);
    if (Object.keys(params).length > 0) c.api.setParams(params).then((e) => e && this.reportHostError(e), (e) => this.reportFailure(e));
    if (changed.has('paused')) this.syncRunning();
  }

  protected override firstUpdated(): void {
    this.showErrors();
  }

  protected override willUpdate(changed: Map<string, unknown>): void {
    if (changed.has('paused') && !this.paused) this.playControl = false;
  }

  // ---- embedding: visibility, keyboard ---------------------------------------------------------------------------

  private watching = false;

  private watchVisibility(on: boolean): void {
    if (on === this.watching) return;
    this.watching = on;
    if (on) {
      if (typeof IntersectionObserver === 'function') {
        // Until the observer's first report (the next frame): assumed on screen.
        this.io = new IntersectionObserver((entries) => {
          const e = entries[entries.length - 1];
          if (!e) return;
          this.inView = e.isIntersecting;
          this.syncRunning();
        });
        this.io.observe(this);
        track('observers', 1);
      }
      this.pageVisible = document.visibilityState !== 'hidden';
      document.addEventListener('visibilitychange', this.onVisibility);
      track('listeners', 1);
    } else {
      if (this.io) {
        this.io.disconnect();
        this.io = null;
        track('observers', -1);
      }
      document.removeEventListener('visibilitychange', this.onVisibility);
      track('listeners', -1);
    }
  }

  private readonly onVisibility = (): void => {
    this.pageVisible = document.visibilityState !== 'hidden';
    this.syncRunning();
  };

  /** Tells the engine to step or not (paused, off screen, hidden page) and the renderer to draw or not. */
  private syncRunning(): void {
    this.renderer?.setLooping(this.onScreen && !this.gaveUp);
    this.updateKeeper();
    const c = this.client;
    if (!c || !this.loaded) return;
    const run = this.running;
    if (run === this.runningSent) return;
    this.runningSent = run;
    (run ? c.api.play() : c.api.pause()).catch((e) => this.reportFailure(e));
    this.runningChanged(run);
  }

  private readonly onKeyDown = (event: Event): void => {
    const e = event as KeyboardEvent;
    if ((e.key !== ' ' && e.code !== 'Space') || e.composedPath()[0] !== this || e.altKey || e.ctrlKey || e.metaKey) return;
    e.preventDefault();
    if (e.repeat) return;
    if (this.paused) this.play();
    else {
      this.pause();
      this.playControl = true;
    }
  };

  private readonly onPlayClick = (e: Event): void => {
    e.stopPropagation();
    this.play();
    this.focus();
  };

  private starting = false;

  private newReady(): Promise<void> {
    return new Promise((resolve) => (this.readyResolve = resolve));
  }

  private async start(): Promise<void> {
    const gen = ++this.generation;
    this.starting = true;
    try {
      await this.updateComplete;
      if (gen !== this.generation || !this.isConnected) return;
      const stage = this.renderRoot.querySelector('.stage') as HTMLElement;
      this.renderer = new SceneRenderer(stage, () => this.shown ?? this.client);
      this.renderer.setLooping(this.onScreen);
      this.applyView(this.renderer, this.config());
      this.observer.observe(this.bodyContainer, { childList: true, subtree: true, attributes: true, attributeFilter: ['id'] });
      const client = await this.newClient();
      if (gen !== this.generation) {
        client.dispose();
        return;
      }
      this.client = client;
      const scene = this.collect();
      this.loaded = true;
      this.runningSent = scene.running ?? null;
      const errors = await client.api.load(scene);
      if (gen !== this.generation || this.client !== client) return;
      this.loading = false;
      this.keepSnapshot();
      for (const e of errors) this.reportHostError(e);
      // Visibility may have changed while the scene loaded.
      this.syncRunning();
      this.runningChanged(this.running);
      this.dispatch('physics-ready', { mode: client.mode, transport: client.transport } satisfies PhysicsReadyDetail);
      this.readyResolve?.();
    } catch (error) {
      if (gen === this.generation) this.reportFailure(error);
    } finally {
      if (gen === this.generation) {
        this.starting = false;
        this.loading = false;
        // Never leave callers of ready waiting, also when the start failed (a restart resolves its own).
        if (!this.recovering) this.readyResolve?.();
      }
    }
  }

  /** Starts an engine whose worker's death goes to workerDied(). */
  private async newClient(): Promise<EngineClient> {
    let made: EngineClient | null = null;
    made = await EngineClient.start({
      worker: this.worker === 'none' ? 'none' : 'auto',
      timeout: PhysicsSceneElement.callTimeout,
      createWorker: PhysicsSceneElement.workerFactory ?? undefined,
      onEvents: (data, count) => this.dispatchCollisions(data, count),
      onError: (message) => this.report(this, 'worker', this.worker, message),
      onDeath: (reason) => made && this.workerDied(made, reason),
    });
    return made;
  }

  // ---- fault recovery ----------------------------------------------------------------------------------------

  /** The current worker died or hung: report it, then restart and restore, or give up past the cap. */
  private workerDied(dead: EngineClient, reason: string): void {
    if (dead !== this.client) return;
    // What the user sees: the dead worker's last frame (or, when a restart died, the one before it).
    const source = this.shown ?? dead;
    const saved = this.saved;
    const frame = saved && saved.client === source ? source.lastFrame() : null;
    this.shown = source;
    if (source !== dead) dead.dispose();
    this.client = null;
    this.loaded = false;
    this.runningSent = null;
    this.drag = null;
    this.recovering = true;
    this.updateKeeper();
    this.runningChanged(false);
    const now = performance.now();
    this.restartTimes = this.restartTimes.filter((t) => now - t < RESTART_WINDOW);
    const cap = this.config().maxRestarts;
    if (this.restartTimes.length >= cap) {
      // The end: the last state stays drawn (once), the error box says why, nothing is retried.
      this.gaveUp = true;
      this.recovering = false;
      this.saved = null;
      this.renderer?.setLooping(false);
      this.report(this, 'worker', this.worker, `engine worker died (${reason}); not restarted: ${cap === 0 ? 'max-restarts is 0' : `${cap} restart${cap === 1 ? '' : 's'} within 60 s already`}, the scene is stopped`);
      this.readyResolve?.();
      return;
    }
    this.restartTimes.push(now);
    this.report(this, 'worker', this.worker, `engine worker died (${reason}); restarting it (attempt ${this.restartTimes.length} of ${cap})`, false);
    // Calls made meanwhile wait for the new engine.
    this._ready = this.newReady();
    void this.restart(this.generation, saved?.snapshot ?? null, frame, saved?.grab ?? null);
  }

  /** A new engine loaded from the markup, then the last snapshot (and frame) restored and later markup changes applied. */
  private async restart(gen: number, snapshot: HostSnapshot | null, frame: FramePatch | null, grab: number | null): Promise<void> {
    const client = await this.newClient();
    if (gen !== this.generation) {
      client.dispose();
      return;
    }
    this.client = client;
    if (client.died !== null) {
      this.workerDied(client, client.died);
      return;
    }
    try {
      const scene = this.collect();
      await client.api.load({ ...scene, running: false });
      let step = 0;
      if (snapshot) {
        let restored = true;
        try {
          step = await client.api.restore(snapshot, frame);
        } catch (error) {
          if (client.died !== null) throw error;
          restored = false;
          this.report(this, 'worker', this.worker, `engine: the last snapshot could not be restored, the scene restarts from its markup (${error instanceof Error ? error.message : String(error)})`, false);
          await client.api.load({ ...scene, running: false });
        }
        if (restored) await this.reapply(client, scene, snapshot, grab);
      }
      // Poses read right after ready are the restored ones.
      await client.synced(step);
      if (gen !== this.generation || this.client !== client) return;
      this.loaded = true;
      this.shown?.dispose();
      this.shown = null;
      this.recovering = false;
      this.syncRunning();
      this.keepSnapshot();
      this.readyResolve?.();
    } catch (error) {
      // The new worker died too: workerDied() has taken over (another attempt, or the end).
      if (gen !== this.generation || this.client !== client || client.died !== null) return;
      this.reportFailure(error);
      this.loaded = true;
      this.shown = null;
      this.recovering = false;
      this.syncRunning();
      this.readyResolve?.();
    }
  }

  /** After a restore: the markup as it is now wins over the snapshot's descriptions, and the current parameters. */
  private async reapply(client: EngineClient, scene: HostScene, snapshot: HostSnapshot, grab: number | null): Promise<void> {
    const calls: Promise<unknown>[] = [];
    const report = (e: HostError | null) => e && this.reportHostError(e);
    const bodies = new Map(snapshot.bodies.map((b) => [b.key, JSON.stringify(b.desc)]));
    const links = new Map(snapshot.links.map((l) => [l.key, JSON.stringify(l.desc)]));
    for (const b of scene.bodies) if (bodies.get(b.key) !== JSON.stringify(b.desc)) calls.push(client.api.updateBody(b).then(report));
    for (const key of bodies.keys()) if (!scene.bodies.some((b) => b.key === key)) calls.push(client.api.removeBody(key));
    for (const l of scene.links) if (links.get(l.key) !== JSON.stringify(l.desc)) calls.push(client.api.updateLink(l).then(report));
    for (const key of links.keys()) if (!scene.links.some((l) => l.key === key)) calls.push(client.api.removeLink(key));
    if (scene.params) calls.push(client.api.setParams(scene.params));
    // A drag held when the snapshot was taken has no pointer any more.
    if (grab !== null) calls.push(client.api.release(grab));
    await Promise.all(calls);
  }

  /** Keeps a recent snapshot and watches the step counter while the scene steps in a worker. */
  private updateKeeper(): void {
    const on = this.running && this.loaded && !this.gaveUp && this.client?.mode === 'worker';
    if (on === (this.keeper !== null)) return;
    if (!on) {
      clearInterval(this.keeper!);
      this.keeper = null;
      // Stopped stepping (paused, off screen, hidden page): the state to keep is now fixed.
      this.keepSnapshot();
      return;
    }
    this.watchStep = this.client!.latestStep;
    this.watchAt = performance.now();
    this.keeper = setInterval(this.keep, KEEPER_TICK);
  }

  private readonly keep = (): void => {
    const c = this.client;
    if (!c || !this.loaded) return;
    const now = performance.now();
    const step = c.latestStep;
    if (step !== this.watchStep) {
      this.watchStep = step;
      this.watchAt = now;
      if (now - this.snapAt >= SNAPSHOT_EVERY) this.keepSnapshot();
      return;
    }
    const stall = Math.max(STALL_AFTER, 3000 * this.config().timestep);
    if (now - this.watchAt < stall) return;
    // No step for a while although the scene runs: terminated or hung? One probe; no answer declares it dead.
    this.watchAt = now;
    const timeout = Math.min(PROBE_TIMEOUT, PhysicsSceneElement.callTimeout);
    void c.probe(`no new frame for ${Math.round(stall)} ms while running and no answer to a probe within ${timeout} ms`, timeout);
  };

  /** Asks the worker for a snapshot (one at a time) and keeps it. */
  private keepSnapshot(): void {
    const c = this.client;
    if (!c || c.mode !== 'worker' || !this.loaded || this.snapping) return;
    this.snapping = true;
    this.snapAt = performance.now();
    const grab = this.drag?.grab ?? null;
    c.api.snapshot().then(
      (snapshot) => {
        if (c === this.client) this.saved = { client: c, snapshot, grab };
      },
      () => {},
    ).finally(() => {
      this.snapping = false;
    });
  }

  /**
   * @internal Test hook: makes the engine worker fail. 'terminate' ends it from outside and tells no one (found by
   * the stall watch), 'throw' makes its step loop throw, 'hang' blocks it (calls then time out).
   */
  async _debugFault(fault: 'terminate' | 'throw' | 'hang'): Promise<void> {
    const c = this.client;
    if (!c || c.mode !== 'worker') throw new Error('_debugFault: no engine worker');
    if (fault === 'terminate') c.debugTerminate();
    else await c.api.debugFault(fault);
  }

  private stop(): void {
    this.generation++;
    this.starting = false;
    this.observer.disconnect();
    this.client?.dispose();
    this.client = null;
    this.shown?.dispose();
    this.shown = null;
    this.saved = null;
    this.restartTimes = [];
    this.recovering = false;
    this.gaveUp = false;
    this.updateKeeper();
    this.runningChanged(false);
    this.renderer?.dispose();
    this.renderer = null;
    this.loaded = false;
    this.loading = true;
    this.runningSent = null;
    this.failures = [];
    this.problemLines.clear();
    this.refreshErrors();
    this.drag = null;
    for (const e of this.entries.values()) e.element._scene = null;
    this.entries.clear();
    this.keys = new WeakMap();
    this.readyResolve?.();
    this._ready = this.newReady();
  }

  // ---- configuration -----------------------------------------------------------------------------------------

  private config(): Config {
    const check = new Checker(this);
    const width = check.number('width', this.width, { positive: true, fallback: 16 })!;
    const height = check.number('height', this.height, { positive: true, fallback: 9 })!;
    let gravity = { x: 0, y: 9.81 };
    const g = check.numbers('gravity', this.gravity);
    if (g && g.length === 2) gravity = { x: g[0], y: g[1] };
    else if (g) check.fail('gravity', this.gravity, 'must be two numbers "x y"');
    const iterations = check.number('iterations', this.iterations, { integer: true, min: 1, max: 1000, fallback: 1 })!;
    const substeps = check.number('substeps', this.substeps, { integer: true, min: 1, max: 1000, fallback: 10 })!;
    const timestep = check.number('timestep', this.timestep, { positive: true, max: 1, fallback: 1 / 60 })!;
    const broadphase = check.oneOf('broadphase', this.broadphase, ['grid', 'brute'] as const, 'grid');
    const narrowphase = check.oneOf('narrowphase', this.narrowphase, ['sat', 'gjk'] as const, 'sat');
    const bounds = check.oneOf('bounds', this.bounds, ['view', 'none'] as const, 'view');
    check.oneOf('worker', this.worker, ['auto', 'none'] as const, 'auto');
    const maxRestarts = check.number('max-restarts', this.maxRestarts, { integer: true, min: 0, max: 100, fallback: 3 })!;
    check.oneOf('draw-mode', this.drawMode, ['over', 'replace'] as const, 'over');
    check.color('background', this.background, null);
    this.reportProblems(this, check.problems, this.ownReported);
    return { width, height, gravity, iterations, substeps, timestep, broadphase, narrowphase, bounds, maxRestarts };
  }

  private applyView(r: SceneRenderer, config: Config): void {
    r.viewWidth = config.width;
    r.viewHeight = config.height;
    r.background = new Checker(this).color('background', this.background, '#f7f5f0') ?? 'transparent';
    r.debug = this.debug;
    r.drawMode = this.drawMode === 'replace' ? 'replace' : 'over';
    r.hook = this.drawHook;
  }

  // ---- children ----------------------------------------------------------------------------------------------

  private childElements(): (PhysicsBodyElement | PhysicsLinkElement)[] {
    const out: (PhysicsBodyElement | PhysicsLinkElement)[] = [];
    for (const el of Array.from(this.bodyContainer.children)) {
      if (el instanceof PhysicsBodyElement || el instanceof PhysicsLinkElement) out.push(el);
    }
    return out;
  }

  /** Reads every child into a scene description for load(). */
  private collect(): HostScene {
    const config = this.config();
    const bodies: KeyedBody[] = [];
    const links: KeyedLink[] = [];
    const children = this.childElements();
    // A restart keeps the keys of children it knows (the snapshot names them) and forgets removed ones.
    const present = new Set<Element>(children);
    for (const [key, e] of [...this.entries]) {
      if (present.has(e.element)) continue;
      if (e.kind === 'body') this.renderer?.deleteStyle(key);
      e.element._scene = null;
      this.entries.delete(key);
      this.keys.delete(e.element);
    }
    for (const el of children) if (el instanceof PhysicsBodyElement) {
      const key = this.keys.get(el) ?? this.adopt(el, 'body');
      const desc = this.describeBody(this.entries.get(key)!);
      if (desc) bodies.push({ key, desc });
    }
    for (const el of children) if (el instanceof PhysicsLinkElement) {
      const key = this.keys.get(el) ?? this.adopt(el, 'link');
      const desc = this.describeLink(this.entries.get(key)!);
      if (desc) links.push({ key, desc });
    }
    return {
      world: {
        // Walls at the sides and a floor at the bottom; open at the top, so bodies may start above the view.
        bounds: this.viewBounds(config),
      },
      params: {
        gravity: this.effectiveGravity(config),
        iterations: config.iterations,
        substeps: config.substeps,
        timestep: config.timestep,
        broadphase: config.broadphase,
        narrowphase: config.narrowphase,
        debug: this.debug,
        events: this.wantsEvents(),
      },
      bodies,
      links,
      running: this.running,
    };
  }

  /** Walls at the sides and a floor at the bottom; open at the top, so bodies may start above the view. */
  private viewBounds(config: { bounds: 'view' | 'none'; width: number; height: number }): Bounds | null {
    return config.bounds === 'view' ? { minX: 0, minY: -1e6, maxX: config.width, maxY: config.height } : null;
  }

  private adopt(el: PhysicsBodyElement | PhysicsLinkElement, kind: 'body' | 'link'): number {
    const key = this.nextKey++;
    this.keys.set(el, key);
    this.entries.set(key, { element: el, kind, sent: '', reported: new Set() });
    el._scene = this;
    return key;
  }

  private describeBody(entry: Entry): BodyDescription | null {
    const el = entry.element as PhysicsBodyElement;
    const { desc, problems } = el.describe();
    const check = new Checker(el);
    const style = el.styleOf(check);
    this.reportProblems(el, [...problems, ...check.problems], entry.reported);
    const key = this.keys.get(el)!;
    this.renderer?.setStyle(key, style);
    entry.sent = desc ? JSON.stringify(desc) : '';
    return desc;
  }

  private describeLink(entry: Entry): LinkDescription | null {
    const el = entry.element as PhysicsLinkElement;
    const { desc, problems } = el.describe((id) => this.resolve(id));
    this.reportProblems(el, problems, entry.reported);
    entry.sent = desc ? JSON.stringify(desc) : '';
    return desc;
  }

  private resolve(id: string): number | null {
    for (const [key, e] of this.entries) if (e.kind === 'body' && e.element.id === id) return key;
    return null;
  }

  /** Child list changed: add new children, remove gone ones, re-resolve links. */
  private sync(): void {
    const c = this.client;
    if (!c || !this.loaded) return;
    const children = this.childElements();
    const present = new Set<Element>(children);
    for (const [key, e] of [...this.entries]) {
      if (present.has(e.element)) continue;
      if (e.kind === 'body') {
        c.api.removeBody(key).catch((err) => this.reportFailure(err));
        this.renderer?.deleteStyle(key);
      } else {
        c.api.removeLink(key).catch((err) => this.reportFailure(err));
      }
      e.element._scene = null;
      this.entries.delete(key);
      this.keys.delete(e.element);
    }
    for (const el of children) {
      if (this.keys.has(el) || !(el instanceof PhysicsBodyElement)) continue;
      const key = this.adopt(el, 'body');
      const desc = this.describeBody(this.entries.get(key)!);
      if (desc) c.api.addBody({ key, desc }).then((e) => e && this.reportHostError(e), (err) => this.reportFailure(err));
    }
    for (const el of children) if (!this.keys.has(el) && el instanceof PhysicsLinkElement) this.adopt(el, 'link');
    this.refreshLinks();
  }

  /** Re-describes every link (ids may now name other bodies) and sends the ones that changed. */
  private refreshLinks(): void {
    const c = this.client;
    if (!c) return;
    for (const [key, e] of this.entries) {
      if (e.kind !== 'link') continue;
      const before = e.sent;
      const desc = this.describeLink(e);
      if (e.sent === before) continue;
      if (desc) c.api.updateLink({ key, desc }).then((err) => err && this.reportHostError(err), (err) => this.reportFailure(err));
      else c.api.removeLink(key).catch((err) => this.reportFailure(err));
    }
  }

  /** @internal */
  childChanged(child: Element): void {
    const c = this.client;
    if (!c || !this.loaded) return;
    const key = this.keys.get(child);
    if (key === undefined) {
      this.sync();
      return;
    }
    const e = this.entries.get(key)!;
    if (e.kind === 'link') {
      this.refreshLinks();
      return;
    }
    const before = e.sent;
    const desc = this.describeBody(e);
    if (e.sent !== before) {
      if (desc) c.api.updateBody({ key, desc }).then((err) => err && this.reportHostError(err), (err) => this.reportFailure(err));
      else c.api.removeBody(key).catch((err) => this.reportFailure(err));
    }
    this.refreshLinks();
  }

  /** @internal */
  poseOf(child: Element): [number, number, number] | null {
    const key = this.keys.get(child);
    const c = this.shown ?? this.client;
    return key === undefined || !c ? null : c.pose(key);
  }

  /** @internal */
  applyImpulse(child: Element, ix: number, iy: number): void {
    const key = this.keys.get(child);
    if (key !== undefined && this.client && Number.isFinite(ix) && Number.isFinite(iy)) this.client.api.applyImpulse(key, ix, iy).catch((e) => this.reportFailure(e));
  }

  /** @internal */
  setVelocity(child: Element, vx: number, vy: number): void {
    const key = this.keys.get(child);
    if (key !== undefined && this.client && Number.isFinite(vx) && Number.isFinite(vy)) this.client.api.setVelocity(key, vx, vy).catch((e) => this.reportFailure(e));
  }

  // ---- events ------------------------------------------------------------------------------------------------

  private wantsEvents(): boolean {
    return this.collisionEvents || this.collisionListeners > 0;
  }

  private updateEventFlag(): void {
    const on = this.wantsEvents();
    if (on === this.eventsOn) return;
    this.eventsOn = on;
    if (this.client && this.loaded) this.client.api.setParams({ events: on }).catch((e) => this.reportFailure(e));
  }

  private dispatchCollisions(data: Float64Array, count: number): void {
    for (let k = 0; k < count; k++) {
      const o = k * EVENT;
      const a = this.entries.get(data[o + 1])?.element ?? null;
      const b = this.entries.get(data[o + 2])?.element ?? null;
      const detail: PhysicsCollisionDetail = { a, b, normal: { x: data[o + 3], y: data[o + 4] }, depth: data[o + 5] };
      this.dispatch(data[o] === 0 ? 'physics-collision' : 'physics-collision-end', detail);
    }
  }

  private dispatch(type: string, detail: unknown, target: Element = this): void {
    target.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }

  private reportProblems(el: Element, problems: Problem[], reported: Set<string>): void {
    const now = new Set<string>();
    const lines: string[] = [];
    for (const p of problems) {
      const id = `${p.attribute}\u0000${p.value}\u0000${p.message}`;
      now.add(id);
      lines.push(problemText(el, p.attribute, p.value, p.message));
      if (!reported.has(id)) this.report(el, p.attribute, p.value, p.message, false);
    }
    reported.clear();
    for (const id of now) reported.add(id);
    if (lines.length > 0) this.problemLines.set(reported, lines);
    else this.problemLines.delete(reported);
    this.refreshErrors();
  }

  /** A console warning naming the element, the attribute and the value, and a `physics-error` event. */
  private report(el: Element, attribute: string, value: string, message: string, keep = true): void {
    const text = problemText(el, attribute, value, message);
    console.warn(text);
    const detail: PhysicsErrorDetail = { element: el, attribute, value, message };
    this.dispatch('physics-error', detail, el.isConnected ? el : this);
    if (keep) {
      this.failures = [...this.failures.slice(-4), text];
      this.refreshErrors();
    }
  }

  /** The visible error box: every current markup problem and the latest engine failures. */
  private refreshErrors(): void {
    const lines = [...[...this.problemLines.values()].flat(), ...this.failures];
    if (lines.join('\n') === this.errorLines.join('\n')) return;
    this.errorLines = lines;
    this.showErrors();
  }

  private showErrors(): void {
    const box = this.renderRoot?.querySelector<HTMLElement>('.error');
    if (!box) return;
    const text = this.errorLines.join('\n');
    if (box.textContent !== text) box.textContent = text;
    box.hidden = this.errorLines.length === 0;
  }

  private reportHostError(e: HostError): void {
    const entry = this.entries.get(e.key);
    const el = entry?.element ?? this;
    const attribute = ENGINE_FIELDS[e.field] ?? e.field;
    this.report(el, attribute, attribute ? (el.getAttribute(attribute) ?? '') : '', e.message);
  }

  private reportFailure(error: unknown): void {
    if (!this.client && !this.starting) return;
    // A worker that died or stopped answering is reported once, by workerDied(), not once per call it failed.
    if (error instanceof WorkerDiedError || (error instanceof TimeoutError && this.client?.mode !== 'main')) return;
    // Calls still pending when the scene stopped its own engine (a restart for a new worker attribute, a disconnect).
    if (error instanceof EngineStoppedError) return;
    this.report(this, '', '', `engine: ${error instanceof Error ? error.message : String(error)}`);
  }

  // ---- pointer -----------------------------------------------------------------------------------------------

  private readonly onPointerDown = (e: PointerEvent): void => {
    const c = this.client;
    if (!c || !this.renderer || this.drag || (e.pointerType === 'mouse' && e.button !== 0)) return;
    const p = this.clientToWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    try {
      (e.currentTarget as Element).setPointerCapture(e.pointerId);
    } catch {
      // Synthetic events have no active pointer to capture.
    }
    const drag = { id: e.pointerId, grab: null as number | null, x: p.x, y: p.y, done: false };
    this.drag = drag;
    e.preventDefault();
    c.api.grab(p.x, p.y).then(
      (g) => {
        if (g === null) {
          if (this.drag === drag) this.drag = null;
          return;
        }
        if (drag.done || this.client !== c) {
          c.api.release(g).catch(() => {});
          return;
        }
        drag.grab = g;
        c.api.moveGrab(g, drag.x, drag.y).catch(() => {});
      },
      () => {
        if (this.drag === drag) this.drag = null;
      },
    );
  };

  private readonly onPointerMove = (e: PointerEvent): void => {
    const d = this.drag;
    if (!d || e.pointerId !== d.id || !this.client) return;
    const p = this.clientToWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    d.x = p.x;
    d.y = p.y;
    if (d.grab !== null) this.client.api.moveGrab(d.grab, p.x, p.y).catch(() => {});
  };

  private readonly onPointerUp = (e: PointerEvent): void => {
    const d = this.drag;
    if (!d || e.pointerId !== d.id) return;
    d.done = true;
    this.drag = null;
    if (d.grab !== null) this.client?.api.release(d.grab).catch(() => {});
    try {
      (e.currentTarget as Element).releasePointerCapture(e.pointerId);
    } catch {
      // Not captured.
    }
  };
}

function problemText(el: Element, attribute: string, value: string, message: string): string {
  return `${describeElement(el)} ${attribute ? `${attribute}="${displayValue(value)}"` : ''}: ${message}`;
}

if (!customElements.get('physics-scene')) customElements.define('physics-scene', PhysicsSceneElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-scene': PhysicsSceneElement;
  }
}
