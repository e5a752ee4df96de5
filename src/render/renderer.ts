// Draws the newest physics state with p5 into a canvas inside a shadow root. Positions are interpolated between the
// two newest published frames, the world's viewBox is fitted into the element's box keeping its aspect ratio
// (like SVG's preserveAspectRatio="xMidYMid meet"), and bodies are drawn in batches: one canvas path per style.
//
// Drawing only when something changes: p5 does not loop (noLoop); while the scene is on screen the renderer looks once
// an animation frame whether there is anything new to show (a frame that moved something, the interpolation still on
// its way, a resize, a style, view or hook change) and asks p5 for one redraw() if so. A paused or settled scene (its
// frames repeat the positions already drawn) and a reduced-motion one cost no drawing at all.
//
// Set-up in tasks of their own: p5's instance (and the default canvas it always makes) in the task that makes the
// renderer, the real canvas in the next task, so neither adds up with the other into one long task while a page loads.
//
// Memory: a canvas costs its backing store (width × height × 4 bytes at the pixel density) and the compositor's copies
// of it. A scene farther than about a viewport from the screen gives its backing store back (the canvas is 0 × 0 pixels,
// its CSS box unchanged) and takes it back, drawing what it last showed at once, when it comes near again: a post with
// many scenes holds the pixels of those a reader can see or is about to.
import p5 from 'p5';
import { F, HEADER, POSE, aabbOffset, frameLength, poseOffset, type LinkEnd, type Topology } from '../worker/protocol.js';
import type { FrameStore } from '../worker/client.js';
import { track } from '../worker/resources.js';
import { PAINTERS, type BodyPainter, type BodyStyle, type Pen } from './bodies/index.js';

/** CSS pixels kept free around the world box: half a body outline's width (1.5 px), rounded up. */
export const EDGE_MARGIN = 1;

export type { BodyStyle } from './bodies/index.js';

const TAU = Math.PI * 2;

/** What a custom drawing hook receives each frame. */
export interface DrawView {
  /** The p5 instance (instance mode): use its drawing functions, in canvas CSS pixels. */
  p: p5;
  /** The canvas 2D context, for batched drawing. */
  ctx: CanvasRenderingContext2D;
  /** Interpolated particle positions in world units: x at 2·i, y at 2·i + 1 (i = particle storage index). */
  positions: Float64Array;
  /**
   * Interpolated body poses in world units and radians: x, y, angle at 3·k … 3·k + 2 (k = place in topology.bodies).
   * A rigid body's pose is its centre of mass (its topology `center` says where that is in its own coordinates).
   */
  poses: Float64Array;
  topology: Topology;
  /** The newest frame (see F in worker/protocol.ts for its header). */
  frame: Float64Array;
  /** World → canvas CSS pixels: px = offsetX + x · scale, py = offsetY + y · scale. */
  scale: number;
  offsetX: number;
  offsetY: number;
  /** Blend factor between the two newest frames that was used. */
  alpha: number;
  /**
   * Draws again at the next animation frame. A scene draws only when something changes (docs/drawing.md): a hook that
   * animates by itself while the scene is idle calls this to be drawn again.
   */
  requestDraw: () => void;
}

export type DrawHook = (view: DrawView) => void;

/** Where the renderer reads frames from (an EngineClient). */
export interface FrameSource {
  readonly frames: FrameStore;
  readonly topology: Topology | null;
  poll(): void;
}

/** Bodies drawn together: one painter batch, one style (see bodies/painter.ts). */
interface Group {
  style: BodyStyle;
  painter: BodyPainter;
  /** Places in the topology's bodies. */
  bodies: number[];
}

/** How near the viewport a canvas keeps its pixels: within one viewport's size of it (as a scene starts). */
const KEEP_MARGIN = '100% 100% 100% 100%';

/** Resolves in a new task (setTimeout 0: the browser may paint or handle input in between). */
const nextTask = (): Promise<void> => new Promise((resolve) => setTimeout(resolve, 0));

let firstColorMethods: Map<string, unknown> | null = null;

/**
 * p5 2.x's colour addon wraps p5.Color.prototype's set…/_get… methods again in every sketch's presetup, each wrapper
 * holding its sketch and the wrapper before it, so every sketch ever made (canvas and listeners included) stays
 * reachable: one canvas per reconnect. Keep the methods as the first sketch left them and put them back after each
 * later sketch's presetup, so the chain never grows (we never change p5's colour mode, so any sketch's wrappers
 * behave alike). At most the first sketch stays reachable.
 */
function pinColorDecorators(): void {
  const proto = (p5 as unknown as { Color?: { prototype: Record<string, unknown> } }).Color?.prototype;
  if (!proto) return;
  if (!firstColorMethods) {
    // Plain methods only: reading an accessor on the prototype itself would throw.
    firstColorMethods = new Map();
    for (const [k, d] of Object.entries(Object.getOwnPropertyDescriptors(proto))) if (typeof d.value === 'function' && k !== 'constructor') firstColorMethods.set(k, d.value);
    return;
  }
  for (const [k, v] of firstColorMethods) if (proto[k] !== v) proto[k] = v;
}

/** Header fields that change what is drawn (not the sequence number, step, time, stamp or running flag). */
const DRAWN_HEADER = [F.topology, F.particles, F.bodies, F.contacts, F.debug, F.cellSize, F.links];

/**
 * Whether frame `f` draws as `shown` does: the same topology and counts and the same positions, poses (and debug
 * boxes and contacts). A settled world's frames keep coming with a new step count and the same content.
 */
function sameContent(f: Float64Array, shown: Float64Array): boolean {
  for (const k of DRAWN_HEADER) if (f[k] !== shown[k]) return false;
  const length = frameLength(f[F.particles], f[F.bodies], f[F.contacts], f[F.debug] === 1);
  for (let i = HEADER; i < length; i++) if (f[i] !== shown[i]) return false;
  return true;
}

/**
 * Runs p5's code if it has not run yet: the builds' p5 is a stand-in that evaluates p5's modules on first use
 * (src/render/p5/bundle.mjs). A scene calls this a task before it makes its canvas, so evaluating p5 and setting up
 * the canvas do not add up to one long task. (With p5 imported whole this reads a static and costs nothing.)
 */
export function loadP5(): void {
  void (p5 as unknown as { VERSION?: string }).VERSION;
}

export class SceneRenderer {
  /** World units shown across and down (the viewBox, origin at the top-left). */
  viewWidth = 16;
  viewHeight = 9;
  background = '#f7f5f0';
  debug = false;
  /** 'over': the hook draws on top of the default drawing; 'replace': instead of it. */
  drawMode: 'over' | 'replace' = 'over';
  hook: DrawHook | null = null;
  /** The hook whose throw was warned of last (warned once per hook). */
  private hookWarned: DrawHook | null = null;
  /** The clock interpolation reads, on performance.now()'s scale (frames are stamped with it on arrival); tests set it. */
  now: () => number = () => performance.now();
  /** Frames drawn (for tests and diagnostics). */
  drawn = 0;

  private readonly styles = new Map<number, BodyStyle>();
  private groups: Group[] = [];
  private groupsFor: Topology | null = null;
  private positions = new Float64Array(64);
  private poses = new Float64Array(3 * 16);
  private readonly instance: p5;
  private readonly observer: ResizeObserver;
  /** Watches the canvas come near the viewport or go far from it (null where there is no IntersectionObserver). */
  private readonly nearObserver: IntersectionObserver | null = null;
  /** Far from the viewport: the canvas has given its pixels back (0 × 0) until it comes near again. */
  private released = false;
  /** Far from the viewport, as the near-watch last said (a canvas made far away gives its pixels back once made). */
  private far = false;
  /** The 2D context's state (fill, stroke, line width, font, …) when the pixels were given back, to put back with them. */
  private releasedState: Record<string, unknown> = {};
  /** The size the ResizeObserver last reported (CSS pixels), or null before its first report. */
  private observedSize: { width: number; height: number } | null = null;
  /** Device pixels per CSS pixel of the element as the ResizeObserver last measured them (null: not reported). */
  private observedRatio: number | null = null;
  private view: DrawView | null = null;
  private ownHooks: unknown[] = [];
  private scale = 1;
  private offsetX = 0;
  private offsetY = 0;
  private cssWidth = 1;
  private cssHeight = 1;
  private ready = false;
  private removed = false;
  /** Watching for changes each animation frame (on screen), or not at all. */
  private looping = true;
  /** The watch's pending animation frame (0: none). */
  private watchRequest = 0;
  /** Something other than the frames changed (style, size): draw at the next look. */
  private dirty = true;
  /** What the last drawing showed: the frame's drawn content (see sameContent), how far it had blended, the view. */
  private shown = new Float64Array(HEADER);
  private shownAlpha = 1;
  private shownReceived = -1;
  private shownTopology: Topology | null = null;
  private shownView: unknown[] = [];

  constructor(
    private readonly container: HTMLElement,
    private readonly source: () => FrameSource | null,
  ) {
    // p5 pushes a 'remove' hook per instance onto a static list and never takes it off, which would keep every
    // removed sketch (and its canvas) alive: note ours, and take them off after remove().
    // Set here, not when this module loads: the builds' p5 runs its code on first use (src/render/p5/bundle.mjs), which
    // is the first canvas, after the page's first paint.
    p5.disableFriendlyErrors = true;
    const hooks = (p5 as unknown as { lifecycleHooks?: { remove?: unknown[] } }).lifecycleHooks?.remove;
    const before = hooks ? hooks.length : 0;
    this.instance = new p5((s: p5) => {
      // p5 2.x shows a loading spinner while setup runs: a fixed-position div over the page and, once per document, a
      // <style> element in document.head, which a Content-Security-Policy without 'unsafe-inline' refuses (a
      // violation on every page). The element shows its own loading state: mark p5's spinner as already shown (its
      // presetup hook then does nothing; postsetup calls remove() and clears the field).
      (s as unknown as { _loadingIndicator: { remove(): void } | null })._loadingIndicator = { remove() {} };
      // p5 awaits setup: the instance and its default 100 × 100 canvas are this task's work, the canvas the next's.
      s.setup = async () => {
        // p5's default canvas, replaced in the next task: never seen.
        (s as unknown as { canvas?: HTMLCanvasElement }).canvas?.style.setProperty('visibility', 'hidden');
        await nextTask();
        if (this.removed) {
          // Disposed before p5 finished starting: remove() found no canvas to stop then; stop it now.
          s.noLoop();
          void s.remove();
          return;
        }
        pinColorDecorators();
        // The ResizeObserver's size when it has reported one (no layout to force), else the box as laid out now.
        const { width, height } = this.observedSize ?? this.boxSize();
        const renderer = s.createCanvas(width, height);
        // p5 makes the canvas at the display's density rounded up; only a density it did not choose costs a resize.
        const density = this.density();
        if (s.pixelDensity() !== density) s.pixelDensity(density);
        const canvas = (renderer as unknown as { elt: HTMLCanvasElement }).elt;
        canvas.setAttribute('part', 'canvas');
        canvas.style.display = 'block';
        this.cssWidth = width;
        this.cssHeight = height;
        this.ready = true;
        // p5 draws once after set-up; from then on only redraw() draws (see watch()).
        s.noLoop();
        if (this.looping) this.watchSoon();
        else if (this.far) this.release();
      };
      s.draw = () => this.draw(s);
    }, container);
    this.ownHooks = hooks ? hooks.slice(before) : [];
    track('sketches', 1);
    this.observer = new ResizeObserver((entries) => {
      const entry = entries[entries.length - 1];
      const box = entry?.contentRect;
      if (box) this.observedSize = { width: Math.max(1, Math.round(box.width)), height: Math.max(1, Math.round(box.height)) };
      const devicePixels = entry?.devicePixelContentBoxSize?.[0]?.inlineSize;
      if (box && devicePixels && box.width > 0) this.observedRatio = devicePixels / box.width;
      this.resize();
    });
    this.observer.observe(container);
    track('observers', 1);
    if (typeof IntersectionObserver === 'function') {
      this.nearObserver = new IntersectionObserver(
        (entries) => {
          const e = entries[entries.length - 1];
          if (e) this.setNear(e.isIntersecting);
        },
        { rootMargin: KEEP_MARGIN },
      );
      this.nearObserver.observe(container);
      track('observers', 1);
    }
  }

  /** The canvas, once made (p5's default canvas before it does not count). */
  get canvas(): HTMLCanvasElement | null {
    return this.ready ? this.container.querySelector('canvas') : null;
  }

  /** True while the canvas has given its pixels back (far from the viewport): it is 0 × 0 until it comes near again. */
  get isReleased(): boolean {
    return this.released;
  }

  /**
   * Near the viewport (true): the canvas has its pixels and shows the scene, drawn at once if it had given them back.
   * Far (false): it gives them back. Called by the renderer's own IntersectionObserver; also for tests.
   */
  setNear(near: boolean): void {
    this.far = !near;
    if (near) this.restore();
    else this.release();
  }

  /** Gives the canvas' backing store back: 0 × 0 pixels, the CSS box unchanged, the context's state kept aside. */
  private release(): void {
    if (this.released || !this.ready || this.removed) return;
    const canvas = this.canvas;
    const ctx = this.instance.drawingContext as CanvasRenderingContext2D | undefined;
    if (!canvas || !ctx) return;
    const state: Record<string, unknown> = {};
    for (const key in ctx) {
      const value = (ctx as unknown as Record<string, unknown>)[key];
      if (typeof value !== 'object' && typeof value !== 'function') state[key] = value;
    }
    this.releasedState = state;
    this.released = true;
    canvas.width = 0;
    canvas.height = 0;
  }

  /** Takes the pixels back at the current size and draws what was last shown (or anything newer) at once. */
  private restore(): void {
    if (!this.released || this.removed) return;
    this.released = false;
    // resizeCanvas sets the canvas' pixel size and the density's scale; the context's state goes back as it was.
    this.instance.resizeCanvas(this.cssWidth, this.cssHeight, true);
    const ctx = this.instance.drawingContext as unknown as Record<string, unknown>;
    for (const [key, value] of Object.entries(this.releasedState)) {
      try {
        ctx[key] = value;
      } catch {
        // A read-only property.
      }
    }
    this.releasedState = {};
    this.dirty = true;
    void this.instance.redraw();
  }

  /**
   * Looks for something new to draw every animation frame and draws it (true, default), or does not look at all (false:
   * off screen or stopped; no frame callbacks, no CPU).
   */
  setLooping(on: boolean): void {
    if (on === this.looping || this.removed) return;
    this.looping = on;
    // On screen is near: a canvas whose near-watch has not told it yet takes its pixels back now.
    if (on) this.restore();
    if (on && this.ready) this.watchSoon();
    if (!on && this.watchRequest) {
      cancelAnimationFrame(this.watchRequest);
      this.watchRequest = 0;
    }
  }

  /**
   * Draws again at the next animation frame on screen, even if nothing the renderer knows of has changed (a draw hook
   * that animates by itself calls it from the hook to be drawn again).
   */
  requestDraw(): void {
    this.dirty = true;
  }

  /**
   * True while the canvas does not show the newest frame or a change yet (it will at the next animation frame on
   * screen); false once it does (tests wait for that instead of counting drawings).
   */
  get drawPending(): boolean {
    return !this.removed && (!this.ready || this.changed());
  }

  /** True once p5 has made the canvas. */
  get isReady(): boolean {
    return this.ready;
  }

  setStyle(key: number, style: BodyStyle): void {
    this.styles.set(key, style);
    this.groupsFor = null;
    this.dirty = true;
  }

  deleteStyle(key: number): void {
    this.styles.delete(key);
    this.groupsFor = null;
    this.dirty = true;
  }

  /** World point → canvas CSS pixels (relative to the canvas' top-left corner). */
  worldToCanvas(x: number, y: number): { x: number; y: number } {
    this.fit();
    return { x: this.offsetX + x * this.scale, y: this.offsetY + y * this.scale };
  }

  canvasToWorld(x: number, y: number): { x: number; y: number } {
    this.fit();
    return { x: (x - this.offsetX) / this.scale, y: (y - this.offsetY) / this.scale };
  }

  /** Device pixels per CSS pixel of the canvas. */
  get pixelRatio(): number {
    return this.ready ? this.instance.pixelDensity() : 1;
  }

  dispose(): void {
    if (this.removed) return;
    this.removed = true;
    if (this.watchRequest) cancelAnimationFrame(this.watchRequest);
    this.watchRequest = 0;
    this.observer.disconnect();
    track('observers', -1);
    if (this.nearObserver) {
      this.nearObserver.disconnect();
      track('observers', -1);
    }
    const hooks = (p5 as unknown as { lifecycleHooks?: { remove?: unknown[] } }).lifecycleHooks?.remove;
    const own = this.ownHooks;
    void Promise.resolve(this.instance.remove() as unknown).finally(() => {
      for (const h of own) {
        const i = hooks ? hooks.indexOf(h) : -1;
        if (i >= 0) hooks!.splice(i, 1);
      }
    });
    track('sketches', -1);
  }

  private boxSize(): { width: number; height: number } {
    const r = this.container.getBoundingClientRect();
    return { width: Math.max(1, Math.round(r.width)), height: Math.max(1, Math.round(r.height)) };
  }

  /**
   * Device pixels per CSS pixel for the canvas, 1 to 3: the display's, or what the ResizeObserver measured where that
   * differs (a CSS `zoom` on an ancestor: under zoom 2 the canvas was drawn at half the pixels it shows, blurred).
   */
  private density(): number {
    const display = window.devicePixelRatio || 1;
    const measured = this.observedRatio ?? display;
    return Math.max(1, Math.min(3, Math.abs(measured / display - 1) > 0.02 ? measured : display));
  }

  private resize(): void {
    if (!this.ready || this.removed) return;
    const density = this.density();
    if (density !== this.instance.pixelDensity() && !this.released) {
      this.dirty = true;
      this.instance.pixelDensity(density);
    }
    const { width, height } = this.observedSize ?? this.boxSize();
    if (width === this.cssWidth && height === this.cssHeight) return;
    this.cssWidth = width;
    this.cssHeight = height;
    // Without pixels: the new size is taken with them.
    if (this.released) return;
    // Resizing clears the canvas: p5's resizeCanvas() redraws at once (before the page paints), whatever the frames.
    this.dirty = true;
    this.instance.resizeCanvas(width, height);
  }

  private watchSoon(): void {
    if (!this.watchRequest && !this.removed) this.watchRequest = requestAnimationFrame(this.watch);
  }

  /** Once an animation frame while on screen: one redraw if there is anything new to show. */
  private readonly watch = (): void => {
    this.watchRequest = 0;
    if (!this.looping || this.removed) return;
    this.watchSoon();
    this.restore();
    if (this.changed()) void this.instance.redraw();
  };

  /** The values of what decides the drawing besides the frames and styles (the view and the hook). */
  private viewNow(): unknown[] {
    return [this.viewWidth, this.viewHeight, this.background, this.debug, this.drawMode, this.hook, this.cssWidth, this.cssHeight];
  }

  /**
   * Whether a drawing now would differ from the last: something marked it (dirty), the view or topology changed, the
   * blend between the two newest frames had not reached the newest, or a frame arrived whose drawn content differs
   * from what is shown (a hook is given every new frame: it may draw the time or anything else in it).
   */
  private changed(): boolean {
    const src = this.source();
    if (!src) return false;
    src.poll();
    const t = src.topology;
    const frames = src.frames;
    if (!t || frames.received === 0 || frames.curr[F.topology] !== t.version) return false;
    const view = this.viewNow();
    if (this.dirty || this.shownAlpha < 1 || t !== this.shownTopology || view.some((v, k) => v !== this.shownView[k])) return true;
    if (frames.received === this.shownReceived) return false;
    if (this.hook !== null || !sameContent(frames.curr, this.shown)) return true;
    // Compared once: the same content as shown.
    this.shownReceived = frames.received;
    return false;
  }

  /** Notes what this drawing shows, for changed(). */
  private remember(t: Topology, frames: FrameStore, alpha: number): void {
    const f = frames.curr;
    const length = frameLength(f[F.particles], f[F.bodies], f[F.contacts], f[F.debug] === 1);
    if (this.shown.length < length) this.shown = new Float64Array(Math.ceil(length * 1.5));
    this.shown.set(f.subarray(0, length));
    // Between two frames of the same content every blend is the newest frame: nothing left to blend (a settled world
    // that is still stepping would otherwise be redrawn every animation frame).
    this.shownAlpha = alpha < 1 && sameContent(frames.prev, f) ? 1 : alpha;
    this.shownReceived = frames.received;
    this.shownTopology = t;
    this.shownView = this.viewNow();
  }

  /**
   * viewBox fit: the whole world box visible, centred, aspect ratio kept, within EDGE_MARGIN of the canvas' edges so
   * an outline on the view's floor or walls (centred on the body's edge) is drawn whole.
   */
  private fit(): void {
    const w = this.cssWidth - 2 * EDGE_MARGIN;
    const h = this.cssHeight - 2 * EDGE_MARGIN;
    const s = Math.min(w / this.viewWidth, h / this.viewHeight);
    this.scale = s > 0 && Number.isFinite(s) ? s : 1;
    this.offsetX = (this.cssWidth - this.viewWidth * this.scale) / 2;
    this.offsetY = (this.cssHeight - this.viewHeight * this.scale) / 2;
  }

  private rebuildGroups(t: Topology): void {
    const byKey = new Map<string, Group>();
    this.groups = [];
    t.bodies.forEach((body, k) => {
      const style = this.styles.get(body.key) ?? { fill: '#888888', stroke: null, lineWidth: 1 };
      const painter = PAINTERS[body.type];
      const id = `${painter.batch}|${style.fill}|${style.stroke}|${style.lineWidth}`;
      let g = byKey.get(id);
      if (!g) {
        g = { style, painter, bodies: [] };
        byKey.set(id, g);
        this.groups.push(g);
      }
      g.bodies.push(k);
    });
    this.groupsFor = t;
  }

  private draw(s: p5): void {
    const src = this.source();
    if (!src || this.removed) return;
    src.poll();
    const t = src.topology;
    const frames = src.frames;
    const f = frames.curr;
    if (!t || frames.received === 0 || f[F.topology] !== t.version) return;
    // Cleared before the hook runs: a hook that animates by itself calls requestDraw() to be drawn again.
    this.dirty = false;
    this.fit();
    if (this.groupsFor !== t) this.rebuildGroups(t);
    const alpha = this.interpolate(frames);
    const ctx = s.drawingContext as CanvasRenderingContext2D;
    // The background straight on the context: p5's background() parses a colour object every frame.
    ctx.save();
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    if (this.background === 'transparent') ctx.clearRect(0, 0, ctx.canvas.width, ctx.canvas.height);
    else {
      ctx.fillStyle = this.background;
      ctx.fillRect(0, 0, ctx.canvas.width, ctx.canvas.height);
    }
    ctx.restore();
    if (this.drawMode === 'over' || !this.hook) this.drawBodies(ctx, t);
    if (this.debug) this.drawDebug(ctx, t, f);
    if (this.hook) {
      ctx.save();
      forgetCachedStyles(s);
      try {
        const v = (this.view ??= { p: s, ctx, positions: this.positions, poses: this.poses, topology: t, frame: f, scale: 1, offsetX: 0, offsetY: 0, alpha, requestDraw: () => this.requestDraw() });
        v.ctx = ctx;
        v.positions = this.positions;
        v.poses = this.poses;
        v.topology = t;
        v.frame = f;
        v.scale = this.scale;
        v.offsetX = this.offsetX;
        v.offsetY = this.offsetY;
        v.alpha = alpha;
        this.hook(v);
      } catch (error) {
        // Once per hook: a hook that throws does so every frame, and sixty warnings a second bury the first.
        if (this.hookWarned !== this.hook) console.warn('<physics-scene> draw hook threw (warned once for this hook):', error);
        this.hookWarned = this.hook;
      }
      ctx.restore();
    }
    this.remember(t, frames, alpha);
    this.drawn++;
  }

  /** Blends the two newest frames into `positions` and `poses` (angles the short way round); returns the blend factor. */
  private interpolate(frames: FrameStore): number {
    const f = frames.curr;
    const prev = frames.prev;
    const n = f[F.particles];
    const b = f[F.bodies];
    if (this.positions.length < 2 * n) this.positions = new Float64Array(Math.ceil(2 * n * 1.5));
    if (this.poses.length < POSE * b) this.poses = new Float64Array(Math.ceil(POSE * b * 1.5));
    const pos = this.positions;
    const poses = this.poses;
    const at = poseOffset(n);
    let alpha = 1;
    const interval = (f[F.time] - prev[F.time]) * 1000;
    if (frames.received > 1 && prev[F.topology] === f[F.topology] && prev[F.particles] === n && interval > 0 && f[F.running]) {
      alpha = Math.min(1, Math.max(0, (this.now() - frames.currAt) / interval));
    }
    if (alpha >= 1) {
      for (let i = 0; i < 2 * n; i++) pos[i] = f[HEADER + i];
      for (let i = 0; i < POSE * b; i++) poses[i] = f[at + i];
    } else {
      const a = alpha;
      const c = 1 - alpha;
      for (let i = 0; i < 2 * n; i++) pos[i] = prev[HEADER + i] * c + f[HEADER + i] * a;
      for (let o = 0; o < POSE * b; o += POSE) {
        poses[o] = prev[at + o] * c + f[at + o] * a;
        poses[o + 1] = prev[at + o + 1] * c + f[at + o + 1] * a;
        const from = prev[at + o + 2];
        let turn = f[at + o + 2] - from;
        turn -= TAU * Math.round(turn / TAU);
        poses[o + 2] = from + turn * a;
      }
    }
    return alpha;
  }

  /** World → canvas pixels of particle i at the interpolated position (bound once, no allocation per frame). */
  private readonly X = (i: number): number => this.offsetX + this.positions[2 * i] * this.scale;
  private readonly Y = (i: number): number => this.offsetY + this.positions[2 * i + 1] * this.scale;
  /** What painters draw with, updated each frame. */
  private readonly pen: Pen = { ctx: null!, X: this.X, Y: this.Y, scale: 1, offsetX: 0, offsetY: 0, topology: null!, poses: this.poses };
  /** Canvas pixels of the link end last placed (see place()). */
  private readonly end = new Float64Array(2);

  private drawBodies(ctx: CanvasRenderingContext2D, t: Topology): void {
    const { pen } = this;
    pen.ctx = ctx;
    pen.scale = this.scale;
    pen.offsetX = this.offsetX;
    pen.offsetY = this.offsetY;
    pen.topology = t;
    pen.poses = this.poses;
    ctx.lineJoin = 'round';
    ctx.lineCap = 'round';
    for (const g of this.groups) g.painter.draw(pen, g.bodies, g.style);
    if (t.links.length > 0) this.drawLinks(ctx, t);
  }

  /**
   * Joints, springs and pins: a thin line between the ends, an arm from a rigid body's centre to its end, and a dot
   * where a pivot (pin, revolute, weld) holds the ends together.
   */
  private drawLinks(ctx: CanvasRenderingContext2D, t: Topology): void {
    const { end } = this;
    ctx.beginPath();
    for (const l of t.links) {
      this.arm(ctx, l.a);
      this.arm(ctx, l.b);
      this.place(l.a);
      ctx.moveTo(end[0], end[1]);
      this.place(l.b);
      ctx.lineTo(end[0], end[1]);
      if (l.pivot) {
        ctx.moveTo(end[0] + 3, end[1]);
        ctx.arc(end[0], end[1], 3, 0, TAU);
      }
    }
    ctx.strokeStyle = '#555';
    ctx.lineWidth = 1.5;
    ctx.stroke();
  }

  /** A line from a rigid body's centre to a link end off its centre. */
  private arm(ctx: CanvasRenderingContext2D, e: LinkEnd): void {
    if (e.body < 0 || (e.x === 0 && e.y === 0)) return;
    const o = POSE * e.body;
    ctx.moveTo(this.offsetX + this.poses[o] * this.scale, this.offsetY + this.poses[o + 1] * this.scale);
    this.place(e);
    ctx.lineTo(this.end[0], this.end[1]);
  }

  /** Puts the canvas pixels of a link end into `end`: on a rigid body turned with it, a particle, or a world point. */
  private place(e: LinkEnd): void {
    let x = e.x;
    let y = e.y;
    if (e.body >= 0) {
      const o = POSE * e.body;
      const c = Math.cos(this.poses[o + 2]);
      const s = Math.sin(this.poses[o + 2]);
      x = this.poses[o] + c * e.x - s * e.y;
      y = this.poses[o + 1] + s * e.x + c * e.y;
    } else if (e.particle >= 0) {
      x = this.positions[2 * e.particle];
      y = this.positions[2 * e.particle + 1];
    }
    this.end[0] = this.offsetX + x * this.scale;
    this.end[1] = this.offsetY + y * this.scale;
  }

  private drawDebug(ctx: CanvasRenderingContext2D, t: Topology, f: Float64Array): void {
    const s = this.scale;
    const ox = this.offsetX;
    const oy = this.offsetY;
    const n = f[F.particles];
    const b = f[F.bodies];
    if (!f[F.debug]) return;
    // Grid cells of the broad phase.
    const cell = f[F.cellSize];
    if (cell > 0 && this.viewWidth / cell < 400 && this.viewHeight / cell < 400) {
      ctx.beginPath();
      for (let x = 0; x <= this.viewWidth; x += cell) {
        ctx.moveTo(ox + x * s, oy);
        ctx.lineTo(ox + x * s, oy + this.viewHeight * s);
      }
      for (let y = 0; y <= this.viewHeight; y += cell) {
        ctx.moveTo(ox, oy + y * s);
        ctx.lineTo(ox + this.viewWidth * s, oy + y * s);
      }
      ctx.strokeStyle = 'rgba(0, 0, 0, 0.12)';
      ctx.lineWidth = 1;
      ctx.stroke();
    }
    // AABBs.
    let o = aabbOffset(n, b);
    ctx.beginPath();
    for (let k = 0; k < b && k < t.bodies.length; k++) {
      const x0 = f[o++];
      const y0 = f[o++];
      const x1 = f[o++];
      const y1 = f[o++];
      if (Number.isFinite(x0)) ctx.rect(ox + x0 * s, oy + y0 * s, (x1 - x0) * s, (y1 - y0) * s);
    }
    ctx.strokeStyle = 'rgba(200, 0, 200, 0.8)';
    ctx.lineWidth = 1;
    ctx.stroke();
    // Contacts: a dot and the normal.
    const c = f[F.contacts];
    ctx.beginPath();
    const dots = o;
    for (let k = 0; k < c; k++) {
      const x = ox + f[o] * s;
      const y = oy + f[o + 1] * s;
      ctx.moveTo(x, y);
      ctx.lineTo(x + f[o + 2] * 12, y + f[o + 3] * 12);
      o += 4;
    }
    ctx.strokeStyle = '#d00';
    ctx.lineWidth = 1.5;
    ctx.stroke();
    ctx.beginPath();
    o = dots;
    for (let k = 0; k < c; k++) {
      const x = ox + f[o] * s;
      const y = oy + f[o + 1] * s;
      ctx.moveTo(x + 2.5, y);
      ctx.arc(x, y, 2.5, 0, Math.PI * 2);
      o += 4;
    }
    ctx.fillStyle = '#d00';
    ctx.fill();
  }
}

/**
 * p5 2.x skips setting the context's fillStyle/strokeStyle when the colour asked for equals the one it set last
 * (Renderer2D's _cachedFillStyle/_cachedStrokeStyle). The bodies are drawn on the context directly and the hook's
 * own state is restored after it, so from the second frame on a hook's p.fill('#c0392b') matched p5's cache and
 * drew in the last body's colour. Forgetting the cache before each hook makes p5 set the colours again. A no-op if
 * a later p5 keeps them elsewhere (test/render: the hook's colours on the canvas, frame after frame, catch that).
 */
function forgetCachedStyles(s: p5): void {
  const states = (s as unknown as { _renderer?: { states?: { setValue?: (key: string, value: unknown) => void } } })._renderer?.states;
  if (typeof states?.setValue !== 'function') return;
  states.setValue('_cachedFillStyle', undefined);
  states.setValue('_cachedStrokeStyle', undefined);
}
