// The canvas: a p5 renderer in the scene's stage, from start to stop, showing what the scene's attributes say (viewBox,
// colours, debug drawing, hook) after each update, and the mapping between world and viewport coordinates. The renderer
// draws only when something changes (see SceneRenderer): an idle scene (paused, settled, reduced motion) costs nothing.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { SceneRenderer, type BodyStyle, type DrawHook, type FrameSource } from '../../render/renderer.js';

/** World → canvas CSS pixels: px = offsetX + x · scale, py = offsetY + y · scale. */
export interface ViewMapping {
  scale: number;
  offsetX: number;
  offsetY: number;
}

/** What the canvas shows, from the scene's attributes. */
export interface StageView {
  width: number;
  height: number;
  background: string;
  debug: boolean;
  drawMode: 'over' | 'replace';
  hook: DrawHook | null;
}

/** What the stage needs of a renderer (a SceneRenderer; unit tests pass fakes). */
export type Renderer = Pick<
  SceneRenderer,
  'viewWidth' | 'viewHeight' | 'background' | 'debug' | 'drawMode' | 'hook' | 'drawn' | 'canvas' | 'setLooping' | 'setStyle' | 'deleteStyle' | 'worldToCanvas' | 'canvasToWorld' | 'dispose'
> &
  Partial<Pick<SceneRenderer, 'drawPending'>>;

export type RendererFactory = (container: HTMLElement, source: () => FrameSource | null) => Renderer;

export interface StageOptions {
  /** The engine whose frames are drawn. */
  source(): FrameSource | null;
  /** What the canvas shows, as the scene's attributes say now. */
  view(): StageView;
  /** Makes the renderer (default: a SceneRenderer). */
  create?: RendererFactory;
}

const sceneRenderer: RendererFactory = (container, source) => new SceneRenderer(container, source);

/** @internal */
export class StageController implements ReactiveController {
  private renderer: Renderer | null = null;

  constructor(
    host: ReactiveControllerHost,
    private readonly options: StageOptions,
  ) {
    host.addController(this);
  }

  /** The view follows the scene's attributes after each update. */
  hostUpdated(): void {
    this.apply(this.options.view());
  }

  /** Frames drawn so far (0 without a renderer). */
  get drawn(): number {
    return this.renderer?.drawn ?? 0;
  }

  /** True while the canvas does not show the newest frame or a change yet (see SceneRenderer.drawPending). */
  get drawPending(): boolean {
    return this.renderer?.drawPending ?? false;
  }

  /** The canvas, once p5 has made it. */
  get canvas(): HTMLCanvasElement | null {
    return this.renderer?.canvas ?? null;
  }

  /**
   * A renderer in `container`, drawing what changes (new frames that move something, resizes, style and view changes)
   * at the next animation frame, or nothing at all (`looping` false: off screen or stopped).
   */
  open(container: HTMLElement, looping: boolean): void {
    this.renderer = (this.options.create ?? sceneRenderer)(container, () => this.options.source());
    this.renderer.setLooping(looping);
    this.apply(this.options.view());
  }

  close(): void {
    this.renderer?.dispose();
    this.renderer = null;
  }

  private apply(view: StageView): void {
    const r = this.renderer;
    if (!r) return;
    r.viewWidth = view.width;
    r.viewHeight = view.height;
    r.background = view.background;
    r.debug = view.debug;
    r.drawMode = view.drawMode;
    r.hook = view.hook;
  }

  setLooping(on: boolean): void {
    this.renderer?.setLooping(on);
  }

  setStyle(key: number, style: BodyStyle): void {
    this.renderer?.setStyle(key, style);
  }

  deleteStyle(key: number): void {
    this.renderer?.deleteStyle(key);
  }

  /** World → canvas CSS pixels as the canvas is drawn now (px = offsetX + x · scale), or null without a canvas. */
  get mapping(): ViewMapping | null {
    const r = this.renderer;
    if (!r || !this.canvas) return null;
    const origin = r.worldToCanvas(0, 0);
    const unit = r.worldToCanvas(1, 0);
    return { scale: unit.x - origin.x, offsetX: origin.x, offsetY: origin.y };
  }

  /** A viewport point in canvas CSS pixels; NaN without a canvas. */
  clientToCanvas(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!canvas) return { x: NaN, y: NaN };
    const { left, top, scaleX, scaleY } = onScreen(canvas);
    return { x: (x - left) / scaleX, y: (y - top) / scaleY };
  }

  /** A point in canvas CSS pixels in viewport (client) coordinates; NaN without a canvas. */
  canvasToClient(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!canvas) return { x: NaN, y: NaN };
    const { left, top, scaleX, scaleY } = onScreen(canvas);
    return { x: left + x * scaleX, y: top + y * scaleY };
  }

  /** A world point in viewport (client) coordinates; NaN without a canvas. */
  worldToClient(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const p = this.renderer.worldToCanvas(x, y);
    return this.canvasToClient(p.x, p.y);
  }

  /** A viewport point in world units; NaN without a canvas. */
  clientToWorld(x: number, y: number): { x: number; y: number } {
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const c = this.clientToCanvas(x, y);
    return this.renderer.canvasToWorld(c.x, c.y);
  }
}

/**
 * Where the canvas is on screen: its top-left corner in viewport pixels and viewport pixels per CSS pixel of its own
 * layout. They differ from 1 when a page scales the scene (slides scaled to fit the window with `transform: scale()`,
 * CSS `zoom`): pointer events come in viewport pixels, the view is drawn in the canvas's CSS pixels.
 */
function onScreen(canvas: HTMLCanvasElement): { left: number; top: number; scaleX: number; scaleY: number } {
  const r = canvas.getBoundingClientRect();
  const w = canvas.clientWidth;
  const h = canvas.clientHeight;
  return { left: r.left, top: r.top, scaleX: w > 0 && r.width > 0 ? r.width / w : 1, scaleY: h > 0 && r.height > 0 ? r.height / h : 1 };
}
