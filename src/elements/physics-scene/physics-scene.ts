// <physics-scene>: properties, public API and render. The work is done by controllers, one concern each (this
// folder): the engine session, fault recovery, markup sync, visibility, the canvas, pointer drag, problems and
// collision events. The element wires them together and is the only one that knows them all.
import { LitElement, html, nothing, type CSSResultGroup, type PropertyValues, type TemplateResult } from 'lit';
import { property, state } from 'lit/decorators.js';
import { loadP5, type DrawHook } from '../../render/renderer.js';
import { checkWorkerFactory, EngineStoppedError, maxWorkers, setMaxWorkers } from '../../worker/client.js';
import { MAX_TIMER_MS } from '../../worker/pool.js';
import type { Diagnostics, HostParams, HostScene, HostSnapshot, TopologyBody, Transport } from '../../worker/protocol.js';
import { propertyOfAttribute, type Problem } from '../checks.js';
import type { SceneHost } from '../scene-host.js';
import { CollisionEventsController } from './collisions.js';
import { changedParams, ConfigController, substepsAttribute } from './config.js';
import { firePhysicsEvent } from './events.js';
import { KeyboardController, type PickableBody } from './keyboard.js';
import { inMarkup, MarkupSync } from './markup.js';
import { BodyOutlines } from './outlines.js';
import { PointerDragController } from './pointer.js';
import { ProblemsController } from './problems.js';
import { RecoveryController } from './recovery.js';
import { ColourSchemeController, schemeProbe } from './scheme.js';
import { EngineSession, startEngine, type Engine } from './session.js';
import { StageController } from './stage.js';
import { sceneStyles } from './styles.js';
import { VisibilityController } from './visibility.js';

/** CSS pixels around a body within which a touch still takes it (a fingertip is about 8 mm wide). */
const TOUCH_SLOP = 8;
/** Velocity one press of an arrow key adds, in view heights per second. */
const KEY_PUSH = 1 / 3;
/** What a picked body is called when its element has no aria-label or title. */
const TYPE_NAMES: Partial<Record<TopologyBody['type'], string>> = { softbody: 'soft body' };

/** The most steps one step(n) takes (the engine host's cap: a call must not block its thread for minutes). */
const MAX_STEPS_PER_CALL = 100000;

/** Refuses a step(n) count that is not a whole number from 0 to MAX_STEPS_PER_CALL (it was floored or capped silently). */
export function checkSteps(n: unknown): void {
  if (typeof n !== 'number') throw new TypeError(`step(n): n must be a number of steps, got ${typeof n}`);
  if (!Number.isInteger(n) || n < 0 || n > MAX_STEPS_PER_CALL) throw new RangeError(`step(n): n must be a whole number from 0 to ${MAX_STEPS_PER_CALL}, got ${n}`);
}

/** PhysicsSceneElement.callTimeout. */
let callTimeoutMs = 8000;
/** PhysicsSceneElement.workerFactory. */
let workerFactory: (() => Worker) | null = null;

/**
 * A physics scene. Its child elements (`<physics-box>`, `<physics-circle>`, `<physics-rope>`, …) declare bodies; the
 * scene simulates them in a Web Worker at a fixed step and draws them with p5 into a canvas in its shadow root.
 * The markup is the source of truth: adding, removing or changing a child or an attribute updates the running
 * simulation. World units: `width` × `height` is the visible box (like an SVG viewBox), y grows downward.
 *
 * Embedding: the scene steps only while it is on screen and the page is visible (no frames, no engine ticks
 * otherwise); with `prefers-reduced-motion: reduce` it starts paused and shows a play control; it is focusable: Space
 * toggles pause, Tab picks the bodies one by one, the arrow keys push the picked body, Escape lets go (the Tab after it
 * leaves the scene), R resets (each told to screen readers in a live region); it gets `role="group"`, `aria-label`,
 * `aria-keyshortcuts="Space R"` and `aria-description` unless the page sets them. A touch where no body is drawn scrolls or zooms the page; a touch on a
 * body drags it. Before the script runs, a page reserves the element's box with `style="display:block;
 * aspect-ratio:16/9;overflow:hidden"` (its view's width / height), so nothing moves when it starts.
 *
 * @summary A declarative 2D physics scene.
 *
 * @fires physics-ready - The engine runs and the scene is loaded (detail: `{mode, transport}`).
 * @fires physics-collision - Two bodies began touching (detail: `{a, b, normal, depth, speed}`, a and b are the body elements, b null for the view's floor and walls). Sent only while a listener is registered on the scene itself (or `collision-events` is set): a listener added before the element is defined (by a script that runs before this library's) is not seen, so set `collision-events` then.
 * @fires physics-collision-end - Two bodies stopped touching (detail: `{a, b, normal, depth, speed}` as physics-collision's, with normal `{x: 0, y: 0}`, depth and speed 0).
 * @fires physics-error - Bad markup or a failing engine (detail: `{element, attribute, value, message}`); the rest of the scene keeps running. A dead engine worker is reported with `attribute` "worker" and restarted (up to `max-restarts` times a minute).
 *
 * @csspart stage - The box that holds the canvas.
 * @csspart canvas - The p5 canvas. A margin, border or padding given to it is allowed for: pointers and coordinates map to its content box.
 * @csspart status - The loading message shown until the engine runs.
 * @csspart error - The visible list of current problems (bad attributes, a failing engine).
 * @csspart play-button - The play control, shown when the scene started paused for `prefers-reduced-motion` or was paused with Space.
 * @csspart fallback - The box that shows the fallback content until the scene is ready.
 * @csspart focus-ring - The ring around the body picked with the keyboard.
 *
 * @slot fallback - Content shown until the scene is ready, and by browsers that never run the script (a 404, no
 * JavaScript): e.g. `<img slot="fallback" src="still.png" alt="…">`. Text written directly inside the tag is fallback
 * too. Body and link elements are never shown.
 * @slot - The scene's body and link elements (never shown themselves), and fallback text.
 *
 * @cssprop --physics-scene-aspect - Aspect ratio of the element when its height is not set (default: width / height); set on the element, in a stylesheet or on an ancestor, it overrides the view's.
 */
export class PhysicsSceneElement extends LitElement {
  static override styles: CSSResultGroup = sceneStyles;

  /** Makes the engine worker; replace it to load the worker from elsewhere (or to test a failing one). A function or null (the library's own worker). */
  static get workerFactory(): (() => Worker) | null {
    return workerFactory;
  }

  static set workerFactory(make: (() => Worker) | null) {
    // Anything else failed later, at the next scene's start ("Invalid value used as weak map key").
    workerFactory = checkWorkerFactory(make);
  }
  /**
   * Milliseconds an engine call (and the worker's start) may take before it fails with `physics-error` (> 0, at most
   * 2147483647: about 24.8 days, the longest delay a timer takes).
   */
  static get callTimeout(): number {
    return callTimeoutMs;
  }

  static set callTimeout(ms: number) {
    if (typeof ms !== 'number') throw new TypeError(`PhysicsSceneElement.callTimeout must be a number of milliseconds, got ${typeof ms}`);
    // Longer, a timer fires at once: 3e9 or Infinity failed every new worker's start ("did not answer within 3000000000 ms").
    if (!(ms > 0 && ms <= MAX_TIMER_MS)) throw new RangeError(`PhysicsSceneElement.callTimeout must be > 0 and at most ${MAX_TIMER_MS} (milliseconds), got ${ms}`);
    callTimeoutMs = ms;
  }

  /**
   * The most engine workers the page's scenes share: each scene is a world in the least-loaded one. Default
   * `max(1, min(2, navigator.hardwareConcurrency − 1))`; set an integer ≥ 1 (workers already made stay), or null
   * for the default.
   */
  static get maxWorkers(): number {
    return maxWorkers();
  }
  static set maxWorkers(limit: number | null) {
    setMaxWorkers(limit);
  }

  /** World units across the view (>= 0.001). Default 16. */
  @property({ type: Number }) width = 16;
  /** World units down the view (>= 0.001). Default 9. */
  @property({ type: Number }) height = 9;
  /** Gravity "x y" in world units / s² (y grows downward). Default "0 9.81". */
  @property() gravity = '0 9.81';
  /** Gauss–Seidel iterations per substep. Default 1. */
  @property({ type: Number }) iterations = 1;
  /**
   * Substeps per step: "auto" (default) lets the engine choose by what moves, 6 while every moving body is a rigid
   * body and 10 when particles, ropes, cloth, soft bodies or ragdolls move; a whole number (1..1000) fixes it.
   * `diagnostics().substepCount` reads the count the engine takes.
   */
  @property({ converter: substepsAttribute }) substeps: number | 'auto' = 'auto';
  /**
   * Fixed step in seconds. Default 1/60.
   * @type {number}
   */
  @property({ type: Number }) timestep = 1 / 60;
  /** Starts (and stays) paused. */
  @property({ type: Boolean, reflect: true }) paused = false;
  /** Draws AABBs, contacts and the broad phase's grid cells. */
  @property({ type: Boolean, reflect: true }) debug = false;
  /** Broad phase: "grid" (default) or "brute". */
  @property() broadphase: 'grid' | 'brute' = 'grid';
  /** Narrow phase for polygon pairs: "sat" (default, separating axes) or "gjk" (GJK distance, EPA when overlapping). */
  @property() narrowphase: 'sat' | 'gjk' = 'sat';
  /** "view" (default): walls at the sides and bottom of the width × height box (open at the top); "none": unbounded. */
  @property() bounds: 'view' | 'none' = 'view';
  /**
   * Canvas background (CSS colour, or "none": transparent). Default "#f7f5f0", or "#1d2025" on a page whose colour
   * scheme is dark (`color-scheme: dark`, or "light dark" for a reader who prefers dark): the default colours follow it.
   */
  @property() background?: string;
  /**
   * "auto" (default): the engine runs in a Web Worker when possible; "none": on the main thread. A change that moves
   * the engine carries the simulation over (the same step and state, in an engine of the new mode); one that leaves it
   * where it runs (a bad value reads as "auto") does nothing but its report.
   */
  @property() worker: 'auto' | 'none' = 'auto';
  /**
   * The solver kernel: "auto" (default) runs the particle solver (cloth, ropes, soft bodies) in WebAssembly with SIMD
   * where the browser and the page allow it, else in JavaScript; "wasm" the same, warning when it cannot; "js" always
   * JavaScript. A strict Content-Security-Policy needs `script-src 'wasm-unsafe-eval'` for WebAssembly (without it:
   * JavaScript, and one console warning). A change keeps the scene's state. `diagnostics()` says which kernel runs.
   */
  @property() kernel: 'auto' | 'wasm' | 'js' = 'auto';
  /** Send collision events even with no listener on the scene itself (for listeners on ancestors). */
  @property({ type: Boolean, attribute: 'collision-events' }) collisionEvents = false;
  /**
   * Restarts of a dead or hung engine worker allowed within 60 s. Each fires `physics-error` ("restarting it,
   * attempt k of n") and restores the last snapshot; one more failure within the minute stops the scene with a final
   * `physics-error` and the error box. Default 3; 0 never restarts.
   */
  @property({ type: Number, attribute: 'max-restarts' }) maxRestarts = 3;
  /** How `drawHook` combines with the default drawing: "over" (default) or "replace". */
  @property({ attribute: 'draw-mode' }) drawMode: 'over' | 'replace' = 'over';
  /**
   * Custom p5 drawing, called each time the scene draws (every new frame while it moves; `view.requestDraw()` asks for
   * one more) with a DrawView (the p5 instance, the 2D context, interpolated particle positions and poses, the topology
   * and the world → canvas mapping), after the default drawing ("over") or instead ("replace"). See docs/drawing.md.
   * A function or null (undefined counts as null; a TypeError otherwise); a hook that throws is reported with one console warning, not one a
   * frame.
   */
  @property({ attribute: false, noAccessor: true })
  get drawHook(): DrawHook | null {
    return this._drawHook;
  }
  set drawHook(hook: DrawHook | null | undefined) {
    if (hook !== null && hook !== undefined && typeof hook !== 'function') throw new TypeError(`drawHook must be a function or null, got ${typeof hook}`);
    const old = this._drawHook;
    this._drawHook = hook ?? null;
    this.requestUpdate('drawHook', old);
  }
  private _drawHook: DrawHook | null = null;

  /** The loading message is shown. */
  @state() private loading = true;
  /** The engine has loaded the scene (since the last start): the fallback content is hidden. */
  @state() private loaded = false;
  /** The page wrote fallback content (an element with slot="fallback", or text in the tag): no loading message. */
  @state() private hasFallback = false;

  /** @internal What is wrong: physics-error, warnings, the error box. */
  private readonly problems = new ProblemsController(this, {
    box: () => this.renderRoot?.querySelector<HTMLElement>('.error') ?? null,
    elementOf: (key) => this.markup.elementOf(key),
  });
  /** @internal The engine from start to stop, and ready. */
  private readonly session: EngineSession = new EngineSession(this, {
    connect: () => this.connect(),
    nearby: () => this.visibility.whenNear(),
    warm: loadP5,
    demand: () => this.visibility.demand(),
    scene: {
      prepare: () => {
        this.stage.open(this.renderRoot.querySelector<HTMLElement>('.stage')!, this.onScreen);
        this.markup.observe();
      },
      describe: () => this.describe(),
      loaded: (engine, errors) => {
        this.loading = false;
        this.loaded = true;
        this.recovery.keepSnapshot();
        for (const e of errors) this.problems.refused(e);
        // Visibility may have changed while the scene loaded.
        this.syncRunning();
        this.runningChanged(this.running);
        firePhysicsEvent(this, 'physics-ready', { mode: engine.mode, transport: engine.transport });
      },
      settled: () => (this.loading = false),
    },
    failed: (message) => this.problems.report(this, '', '', message),
    // A refusal of a description the element has replaced since (the reply was on its way) is not news.
    refused: (e, sent) => this.markup.isLatest(sent) && this.problems.refused(e),
  });
  /** @internal The page's colour scheme, which the default colours follow. */
  private readonly colourScheme = new ColourSchemeController(this, {
    probe: () => this.schemeProbe,
    // Also called from hostUpdate, before the first render: requestUpdate() is then part of that update.
    changed: () => {
      this.requestUpdate();
      this.markup.restyle();
    },
  });
  /** @internal The scene's attributes, checked once per update. */
  private readonly settings = new ConfigController(this, { problems: this.problems, scheme: () => this.colourScheme.scheme });
  /** @internal The canvas. */
  private readonly stage = new StageController(this, {
    source: () => this.session.shown,
    view: () => ({ ...this.settings.config, debug: this.debug, hook: this.drawHook }),
  });
  /** @internal Child elements → engine bodies and links. */
  private readonly markup = new MarkupSync({
    container: () => this.bodyContainer,
    engine: this.session,
    problems: this.problems,
    styles: this.stage,
    scheme: () => this.colourScheme.scheme,
  });
  /** @internal Snapshots, the stall probe, restarts. */
  private readonly recovery: RecoveryController = new RecoveryController(this, {
    session: this.session,
    connect: () => this.connect(),
    scene: {
      describe: () => this.describe(),
      limits: () => ({ ...this.settings.config, callTimeout: PhysicsSceneElement.callTimeout }),
      grab: () => this.pointer.grab,
      lost: () => {
        this.pointer.cancel();
        this.runningChanged(false);
        // The restarted world tells its touching pairs anew.
        this.collisions.endAll();
      },
      resumed: () => this.syncRunning(),
      report: (message, keep) => this.problems.report(this, 'worker', this.worker, message, keep),
      refused: (e) => this.problems.refused(e),
    },
  });
  /** @internal On screen, page visible, reduced motion, Space. */
  private readonly visibility = new VisibilityController(this, { changed: () => this.syncRunning(), label: () => this.defaultLabel });
  /** @internal The bodies as drawn in the newest frame: hit tests for touches, boxes and speeds for the keyboard. */
  private readonly outlines = new BodyOutlines(
    () => this.session.shown,
    () => this.stage.mapping,
  );
  /** @internal Drag and throw. */
  private readonly pointer = new PointerDragController(this, {
    engine: () => this.session.engine,
    toWorld: (x, y) => this.clientToWorld(x, y),
    hit: (x, y) => {
      const p = this.stage.clientToCanvas(x, y);
      const on = this.outlines.bodyAt(p.x, p.y, TOUCH_SLOP, (body) => this.movable(body));
      return on && this.stage.canvasToClient(on.x, on.y);
    },
  });
  /** @internal Pick, push and reset with the keyboard. */
  private readonly keyboard = new KeyboardController(this, {
    bodies: () => this.pickableBodies(),
    bounds: (key) => this.outlines.bounds(key),
    push: (key, dx, dy) => this.pushBody(key, dx, dy),
    // R on a scene stopped for good does nothing (its error box says why).
    reset: () => void this.reset().catch((error: unknown) => {
      if (!(error instanceof EngineStoppedError)) throw error;
    }),
    togglePause: () => this.visibility.toggle(),
    ring: () => this.renderRoot?.querySelector<HTMLElement>('.ring') ?? null,
    liveRegion: () => this.renderRoot?.querySelector<HTMLElement>('.announcer') ?? null,
  });
  /** @internal physics-collision events. */
  private readonly collisions = new CollisionEventsController(this, {
    always: () => this.collisionEvents,
    elementOf: (key) => this.markup.elementOf(key),
    engine: this.session,
  });

  /**
   * Resolves when the engine has loaded the scene (after each start). Asking for it starts a scene that waits to come
   * near the viewport. A scene not in the page starts once it is added: until then its `ready` waits (it never
   * rejects; the engine calls reject with an `EngineStoppedError` instead).
   */
  get ready(): Promise<void> {
    this.visibility.demand();
    return this.session.ready;
  }

  /** Where the engine runs ('worker' or 'main'), or null before it started. */
  get mode(): 'worker' | 'main' | null {
    return this.session.engine?.mode ?? null;
  }

  /** How states reach the page, or null before the engine started. */
  get transport(): Transport | null {
    return this.session.engine?.transport ?? null;
  }

  /** Frames drawn so far (a scene draws only when something changes: an idle scene's count stays put). */
  get renderedFrames(): number {
    return this.stage.drawn;
  }

  /** @internal True while the canvas does not show the newest frame or a change yet (tests wait for it to clear). */
  get drawPending(): boolean {
    return this.stage.drawPending;
  }

  /** The canvas, once p5 has made it. */
  get canvas(): HTMLCanvasElement | null {
    return this.stage.canvas;
  }

  /** True while the engine steps: not paused, on screen, the page visible, and not stopped after an engine failure. */
  get running(): boolean {
    return this.visibility.running && !this.recovery.gaveUp;
  }

  /** True while the element is in the document, on screen and the page is visible (frames are drawn). */
  get onScreen(): boolean {
    return this.visibility.onScreen;
  }

  /** Steps taken, as of the newest frame received. */
  get stepCount(): number {
    return this.session.shown?.latestStep ?? 0;
  }

  // ---- for presets -------------------------------------------------------------------------------------------

  /** Where the body elements live. Presets built on this class may keep generated bodies elsewhere. */
  protected get bodyContainer(): ParentNode & Node {
    return this;
  }

  /** Extra shadow content of a preset (e.g. its generated body elements). */
  protected renderBodies(): TemplateResult | typeof nothing {
    return nothing;
  }

  /** A preset's uniform extra acceleration (e.g. wind), added to `gravity`. */
  protected setGravityOffset(x: number, y: number): void {
    if (this.settings.setGravityOffset(x, y) && this.session.live) this.session.send('setParams', { gravity: this.params().gravity });
  }

  /** Reports a preset's own attribute problems (the current set: fixed ones leave the error box). */
  protected reportPresetProblems(problems: Problem[]): void {
    this.problems.set('preset', this, problems);
  }

  /**
   * Whether restore() asks a snapshot's bodies to be described as the markup describes them now (false: the same keys
   * suffice; a preset's own behaviour changes its generated bodies, and its snapshots must still restore).
   */
  protected get snapshotsMatchMarkup(): boolean {
    return true;
  }

  /** Called when the scene starts or stops stepping (pause, scrolled away, hidden page). */
  protected runningChanged(_running: boolean): void {}

  /** The default `aria-label`. */
  protected get defaultLabel(): string {
    return 'Physics simulation';
  }

  // ---- public methods ----------------------------------------------------------------------------------------

  /** Runs the simulation (clears `paused`). */
  play(): void {
    this.visibility.play();
  }

  /** Stops the simulation (sets `paused`). */
  pause(): void {
    this.paused = true;
  }

  /**
   * Takes `n` fixed steps now (also while paused). Resolves to the step count once the page has the state after them:
   * body elements' `x`, `y` and `angle` then read it (also of bodies a markup change rebuilt just before). On a scene
   * not in the page, or stopped after its engine failed past `max-restarts`, this and the other engine calls (reset,
   * stateHash, diagnostics, snapshot, restore) reject with an `EngineStoppedError`. `n` is a whole number from 0 to 100,000 (a RangeError or TypeError otherwise).
   */
  async step(n = 1): Promise<number> {
    checkSteps(n);
    const engine = await this.session.running('step()');
    const count = await engine.api.step(n);
    // The frame with the topology it was drawn with: a rebuild's topology travels apart from the frame, and without it
    // the rebuilt bodies have no pose yet.
    await engine.synced(count);
    this.recovery.keepSnapshot();
    return count;
  }

  /** Rebuilds the scene from its markup, at time 0. */
  async reset(): Promise<void> {
    const engine = await this.session.running('reset()');
    // Before the call: begins of the new world may arrive before its reply does.
    this.collisions.endAll();
    await engine.api.reset();
    await engine.synced(0);
    this.recovery.keepSnapshot();
  }

  /** Where and how the engine runs, and what it holds (`substepCount`: the substeps a step takes now). */
  async diagnostics(): Promise<Diagnostics & { mode: 'worker' | 'main' }> {
    const engine = await this.session.running('diagnostics()');
    return { ...(await engine.api.diagnostics()), mode: engine.mode };
  }

  /** A hash of the full simulation state: equal markup and equal steps give equal hashes in every mode. */
  async stateHash(): Promise<string> {
    return (await this.session.running('stateHash()')).api.stateHash();
  }

  /**
   * The whole simulation state as data: objects and typed arrays, which structuredClone(), postMessage and IndexedDB
   * keep, and JSON does not. restore() takes it back while the markup is as it was.
   */
  async snapshot(): Promise<HostSnapshot> {
    return (await this.session.running('snapshot()')).api.snapshot();
  }

  /**
   * Puts back a state from snapshot(), of this scene with its markup as it is now (the same bodies and links, the same
   * attributes but colours). Rejects with a TypeError for anything but a snapshot (JSON loses its typed arrays: keep
   * the object, or copy it with structuredClone()) and a RangeError for another scene's snapshot, or one taken before
   * the markup changed; the simulation is then left as it was.
   */
  async restore(snapshot: HostSnapshot): Promise<void> {
    const engine = await this.session.running('restore()');
    const s = snapshot as unknown as Record<string, unknown> | null;
    // Which of a snapshot's four objects it lacks (null: it is no object at all).
    const lacks = s === null || typeof s !== 'object' ? null : ['world', 'bodies', 'links', 'params'].filter((k) => typeof s[k] !== 'object' || s[k] === null);
    if (!lacks || lacks.length > 0 || !Array.isArray(s!.bodies) || !Array.isArray(s!.links)) {
      throw new TypeError(`restore() takes an object snapshot() gave, got ${lacks ? `an object without its ${lacks.join(', ') || 'bodies and links as arrays'}` : String(s)}`);
    }
    const mismatch = this.markup.mismatch(snapshot, this.snapshotsMatchMarkup);
    if (mismatch) throw new RangeError(mismatch);
    this.collisions.endAll();
    await engine.api.restore(snapshot);
    this.recovery.keepSnapshot();
  }

  /** A world point in viewport (client) coordinates, e.g. to place an overlay or synthesise pointer events. */
  worldToClient(x: number, y: number): { x: number; y: number } {
    return this.stage.worldToClient(x, y);
  }

  /** A viewport point in world units. */
  clientToWorld(x: number, y: number): { x: number; y: number } {
    return this.stage.clientToWorld(x, y);
  }

  /** Live pose [x, y, angle (radians)] of a body element of this scene, or null before it is simulated. @internal */
  poseOf(child: Element): [number, number, number] | null {
    return this.markup.poseOf(child);
  }

  /** A child added in this task asks for its scene host (SceneParent): it is adopted now. @internal */
  _hostOf(child: Element): SceneHost | null {
    return inMarkup(child, this.bodyContainer) ? this.markup.hostOf(child) : null;
  }

  /** The engine client (null while there is none): for diagnostics and tests. @internal */
  get client(): Engine | null {
    return this.session.engine;
  }

  /**
   * @internal Test hook: makes the engine worker fail. 'terminate' ends it from outside and tells no one (found by
   * the stall watch), 'throw' makes its step loop throw, 'hang' blocks it (calls then time out).
   */
  async _debugFault(fault: 'terminate' | 'throw' | 'hang'): Promise<void> {
    const engine = this.session.engine;
    if (!engine || engine.mode !== 'worker') throw new Error('_debugFault: no engine worker');
    if (fault === 'terminate') engine.debugTerminate();
    else await engine.api.debugFault(fault);
  }

  // ---- lifecycle ---------------------------------------------------------------------------------------------

  override connectedCallback(): void {
    // A scene stopped after its engine failed starts afresh when put in the page again, a move in one task too (which
    // otherwise keeps what it has): its controllers back to their start before they connect (the session then starts
    // a new engine). Kept, the move started an engine under a scene still stopped: running false, the error box up.
    if (this.recovery?.gaveUp) this.stop();
    super.connectedCallback();
    // Known before the first render (slotchange comes after it), so the loading message never flashes over it.
    this.fallbackChanged();
  }

  /**
   * The first render waits for a task of its own: elements already in the page upgrade while the script is evaluated,
   * and rendering them there made that one long task (the page reserves the box meanwhile; see styles.ts).
   */
  protected override scheduleUpdate(): void | Promise<unknown> {
    if (this.hasUpdated) return super.scheduleUpdate();
    return new Promise<void>((resolve) => setTimeout(resolve, 0)).then(() => super.scheduleUpdate());
  }

  /** What shows the fallback content between the shadow root's creation and the first render (createRenderRoot). */
  private fallbackUntilRendered: HTMLElement | null = null;
  /** Tells the page's colour scheme (scheme.ts); in the shadow root from its creation, beside what render() writes. */
  private schemeProbe: HTMLElement | null = null;

  /**
   * The shadow root is attached when the element connects, but the first render waits a task (scheduleUpdate): an
   * empty shadow root would hide the page's fallback content for a frame or two (an image blinking out as the script
   * arrives). Until then the root holds the fallback box with its two slots, as render() writes it.
   */
  protected override createRenderRoot(): HTMLElement | DocumentFragment {
    const root = super.createRenderRoot();
    const box = document.createElement('div');
    box.className = 'fallback';
    box.append(document.createElement('slot'), document.createElement('slot'));
    box.firstElementChild!.setAttribute('name', 'fallback');
    root.append(box);
    this.fallbackUntilRendered = box;
    this.schemeProbe = schemeProbe();
    root.append(this.schemeProbe);
    return root;
  }

  protected override update(changed: PropertyValues): void {
    // Replaced by render()'s own fallback box in the same task: nothing is painted in between.
    this.fallbackUntilRendered?.remove();
    this.fallbackUntilRendered = null;
    super.update(changed);
  }

  override disconnectedCallback(): void {
    super.disconnectedCallback();
    // A move (disconnect then connect in the same task) keeps the running engine.
    queueMicrotask(() => {
      if (!this.isConnected) this.stop();
    });
  }

  /** Each property's value before an attribute first set it (its default): what it reads once the attribute is removed. */
  private readonly unsetValues = new Map<PropertyKey, unknown>();

  override attributeChangedCallback(name: string, old: string | null, value: string | null): void {
    const property = propertyOfAttribute(this, name);
    const self = this as unknown as Record<PropertyKey, unknown>;
    if (property !== undefined && !this.unsetValues.has(property)) this.unsetValues.set(property, self[property]);
    super.attributeChangedCallback(name, old, value);
    // Lit reads a removed attribute as null: the property takes its default again, as the scene does (a removed
    // width read null while the view went back to 16 wide). Booleans read false (paused, whose reflection calls
    // this with the property already set, must not take that back).
    if (value === null && property !== undefined && self[property] === null) self[property] = this.unsetValues.get(property);
    // A new value its property reads the same (NaN for "abc" and "xyz") is still checked and reported anew.
    if (old !== value && !this.isUpdatePending) this.requestUpdate();
  }

  /** @ignore Typed listeners for the `physics-*` events (HTMLElementEventMap). */
  override addEventListener<K extends keyof HTMLElementEventMap>(type: K, listener: (this: HTMLElement, ev: HTMLElementEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  /** @ignore */
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | AddEventListenerOptions): void {
    if (!listener) return;
    // Collision events' listeners are kept by their controller (the engine collects events while there are any).
    // Controllers add listeners of their own while the element is made, before the collision controller exists.
    if (this.collisions?.addListener(type, listener, options, (wrapper, o) => super.addEventListener(type, wrapper, o))) return;
    super.addEventListener(type, listener, options);
  }

  /** @ignore */
  override removeEventListener<K extends keyof HTMLElementEventMap>(type: K, listener: (this: HTMLElement, ev: HTMLElementEventMap[K]) => unknown, options?: boolean | EventListenerOptions): void;
  /** @ignore */
  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | EventListenerOptions): void;
  override removeEventListener(type: string, listener: EventListenerOrEventListenerObject | null, options?: boolean | EventListenerOptions): void {
    if (!listener) return;
    if (this.collisions?.removeListener(type, listener, options, (wrapper, o) => super.removeEventListener(type, wrapper, o))) return;
    super.removeEventListener(type, listener, options);
  }

  protected override render() {
    return html`<div class="sizer"></div>
      <div class="fallback" part="fallback" ?hidden=${this.loaded}>
        <slot name="fallback" @slotchange=${this.fallbackChanged}></slot><slot @slotchange=${this.fallbackChanged}></slot>
      </div>
      <div
        class="stage"
        part="stage"
        @pointerdown=${this.pointer.down}
        @pointermove=${this.pointer.move}
        @pointerup=${this.pointer.up}
        @pointercancel=${this.pointer.up}
        @touchstart=${{ handleEvent: this.pointer.touchStart, passive: false }}
      ></div>
      ${this.loading && !this.hasFallback ? html`<div class="status" part="status" role="status" lang="en" dir="ltr">Loading simulation…</div>` : nothing}
      <div class="ring" part="focus-ring" hidden></div>
      <div class="announcer" aria-live="polite" aria-atomic="true" lang="en"></div>
      ${this.visibility.playControl && this.paused
        ? html`<button class="play" part="play-button" type="button" lang="en" aria-label="Play the simulation" @click=${this.visibility.onPlayClick}>▶</button>`
        : nothing}
      <div class="error" part="error" role="alert" lang="en" dir="ltr" hidden></div>
      ${this.renderBodies()}`;
  }

  /** Fallback content: an element with slot="fallback", or text (not only white space) among the children. */
  private readonly fallbackChanged = (): void => {
    this.hasFallback = [...this.childNodes].some((n) =>
      n.nodeType === Node.TEXT_NODE ? n.textContent!.trim() !== '' : n instanceof Element && n.getAttribute('slot') === 'fallback',
    );
  };

  protected override willUpdate(changed: PropertyValues): void {
    // A `worker` that changes where the engine runs ("none": the main thread; anything else, "auto" or a bad value
    // reported, a worker) replaces the engine: a loaded one carries its state over (recovery), one still starting
    // starts again. Here, before the render: the state stop() resets is part of this update (in updated() it
    // scheduled another); start() waits for the update to complete.
    const engine = this.session.engine;
    if (!changed.has('worker') || !engine || engine.mode === (this.worker === 'none' ? 'main' : 'worker')) return;
    if (this.session.live) void this.recovery.replace();
    else {
      this.stop();
      void this.session.start();
    }
  }

  protected override updated(changed: PropertyValues): void {
    const { width, height } = this.settings.config;
    // The view's ratio under its own name: a page's --physics-scene-aspect (on the element, in a stylesheet, or
    // inherited) takes precedence over it (styles.ts), where writing that property here overwrote the page's.
    this.style.setProperty('--physics-scene-view-aspect', `${width} / ${height}`);
    if (!this.session.live) return;
    const params = changedParams(changed.keys(), this.params());
    if (Object.keys(params).length > 0) this.session.send('setParams', params);
    if (changed.has('paused')) this.syncRunning();
  }

  // ---- wiring ------------------------------------------------------------------------------------------------

  private params(): HostParams {
    return this.settings.params(this.collisions.wanted);
  }

  /** The whole scene for load(), as the markup is now: the view's walls, the parameters and every child. */
  private describe(): HostScene {
    this.settings.read();
    const { bounds, ...params } = this.params();
    return { world: { bounds }, params, ...this.markup.collect(), running: this.running };
  }

  /** Starts an engine whose events, complaints and death reach the controllers. */
  private connect(): Promise<Engine> {
    return startEngine({
      worker: this.settings.config.worker,
      timeout: PhysicsSceneElement.callTimeout,
      createWorker: PhysicsSceneElement.workerFactory ?? undefined,
      onEvents: this.collisions.dispatch,
      onError: (message) => this.problems.report(this, 'worker', this.worker, message),
      onDeath: (engine, reason) => this.recovery.died(engine, reason),
    });
  }

  /** Tells the engine to step or not (paused, off screen, hidden page), the canvas to draw or not, the keeper to watch. */
  private syncRunning(): void {
    const running = this.running;
    this.stage.setLooping(this.onScreen && !this.recovery.gaveUp);
    this.recovery.watch(running);
    if (this.session.setRunning(running)) this.runningChanged(running);
  }

  /** A body a finger or the keyboard may move: any but a static one. */
  private movable(body: TopologyBody): boolean {
    return !this.markup.elementOf(body.key)?.hasAttribute('static');
  }

  /** The bodies the keyboard picks, in the engine's order, each called by its element's label or its type. */
  private pickableBodies(): PickableBody[] {
    const bodies = this.session.shown?.topology?.bodies ?? [];
    return bodies
      .filter((b) => this.movable(b))
      .map((b) => {
        const el = this.markup.elementOf(b.key);
        return { key: b.key, label: el?.getAttribute('aria-label') || el?.getAttribute('title') || TYPE_NAMES[b.type] || b.type };
      });
  }

  /**
   * One press of an arrow key: adds KEY_PUSH × the view's height per second to the body's velocity in direction
   * (dx, dy), the same for a light and a heavy body (as a drag moves both), up to three presses' worth.
   */
  private pushBody(key: number, dx: number, dy: number): void {
    const dv = KEY_PUSH * this.settings.config.height;
    const v = this.outlines.velocity(key) ?? { x: 0, y: 0 };
    const along = v.x * dx + v.y * dy;
    const added = Math.min(dv, Math.max(0, 3 * dv - along));
    if (Number.isFinite(added)) this.session.send('setVelocity', key, v.x + dx * added, v.y + dy * added);
  }

  /** The engine is ended (the scene left the page, or its worker attribute changed): each concern back to its start. */
  private stop(): void {
    this.session.stop();
    this.recovery.reset();
    this.runningChanged(false);
    this.stage.close();
    this.loading = true;
    this.loaded = false;
    this.problems.clear();
    // The pairs the page was told of end (a worker change restarts the scene with the same elements).
    this.collisions.endAll();
    this.pointer.cancel();
    this.keyboard.cancel();
    this.markup.reset();
  }
}

if (!customElements.get('physics-scene')) customElements.define('physics-scene', PhysicsSceneElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-scene': PhysicsSceneElement;
  }
}
