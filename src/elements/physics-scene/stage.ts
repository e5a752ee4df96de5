// The canvas: a p5 renderer in the scene's stage, from start to stop, showing what the scene's attributes say (viewBox,
// colours, debug drawing, hook) after each update, and the mapping between world and viewport coordinates. The renderer
// draws only when something changes (see SceneRenderer): an idle scene (paused, settled, reduced motion) costs nothing.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { finite } from '../../engine/validate.js';
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
  /** Where the canvas's corners are on screen (made and removed with the renderer). */
  private corners: CanvasCorners | null = null;

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
    this.corners = new CanvasCorners(container);
    this.renderer = (this.options.create ?? sceneRenderer)(container, () => this.options.source());
    this.renderer.setLooping(looping);
    this.apply(this.options.view());
  }

  close(): void {
    this.renderer?.dispose();
    this.renderer = null;
    this.corners?.remove();
    this.corners = null;
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

  /** A viewport point in canvas CSS pixels; NaN without a canvas (or with one seen edge-on). */
  clientToCanvas(x: number, y: number): { x: number; y: number } {
    const m = this.onScreen();
    return m ? project(invert(m), x, y) : { x: NaN, y: NaN };
  }

  /** A point in canvas CSS pixels in viewport (client) coordinates; NaN without a canvas (or with one seen edge-on). */
  canvasToClient(x: number, y: number): { x: number; y: number } {
    const m = this.onScreen();
    return m ? project(m, x, y) : { x: NaN, y: NaN };
  }

  /**
   * A world point in viewport (client) coordinates; NaN without a canvas. A TypeError for an argument that is not a
   * number, a RangeError for NaN or ±Infinity (which would also give NaN, the answer that means "not laid out").
   */
  worldToClient(x: number, y: number): { x: number; y: number } {
    checkPoint('worldToClient', x, y);
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const p = this.renderer.worldToCanvas(x, y);
    return this.canvasToClient(p.x, p.y);
  }

  /** A viewport point in world units; NaN without a canvas. Its arguments are checked as worldToClient's. */
  clientToWorld(x: number, y: number): { x: number; y: number } {
    checkPoint('clientToWorld', x, y);
    const canvas = this.canvas;
    if (!this.renderer || !canvas) return { x: NaN, y: NaN };
    const c = this.clientToCanvas(x, y);
    return this.renderer.canvasToWorld(c.x, c.y);
  }

  /**
   * Canvas CSS pixels → viewport pixels as the page shows the canvas now, or null (no canvas, or degenerate). Pointer
   * events come in viewport pixels, the view is drawn in the canvas's own CSS pixels, and a page may put any CSS
   * transforms between them (slides scaled to fit with `transform: scale()`, CSS `zoom`, a rotated or mirrored card, a
   * 3D tilt), on the scene or on an ancestor, animated or not: read each time, never kept.
   */
  private onScreen(): Matrix | null {
    const canvas = this.canvas;
    if (!canvas) return null;
    let w = canvas.clientWidth;
    let h = canvas.clientHeight;
    let corners: Point[];
    if (this.corners?.beside(canvas)) {
      // The view is drawn in the canvas's content box: a page's ::part(canvas) margin, border or padding moves it
      // from where the markers start, and padding takes from clientWidth / clientHeight.
      const style = getComputedStyle(canvas);
      const left = parseFloat(style.paddingLeft) || 0;
      const top = parseFloat(style.paddingTop) || 0;
      const x = (parseFloat(style.marginLeft) || 0) + (parseFloat(style.borderLeftWidth) || 0) + left;
      const y = (parseFloat(style.marginTop) || 0) + (parseFloat(style.borderTopWidth) || 0) + top;
      const cw = w - left - (parseFloat(style.paddingRight) || 0);
      const ch = h - top - (parseFloat(style.paddingBottom) || 0);
      corners = this.corners.read(x, y, cw, ch);
      // The view is drawn for the canvas's CSS size (p5 writes it on the canvas), which its content box shows whole:
      // smaller under box-sizing: border-box with padding or a border.
      w = parseFloat(canvas.style.width) || cw;
      h = parseFloat(canvas.style.height) || ch;
    } else {
      // A canvas that is not the renderer's own in the stage (unit tests' fakes): its box, exact for translation and
      // scale only.
      const r = canvas.getBoundingClientRect();
      corners = [[r.left, r.top], [r.right, r.top], [r.right, r.bottom], [r.left, r.bottom]];
    }
    return homography(corners, w, h);
  }
}

/** The two coordinates of a point given to `method`: finite numbers, or an error naming the method and the argument. */
function checkPoint(method: string, x: unknown, y: unknown): void {
  finite(`${method}(x, y): x`, x);
  finite(`${method}(x, y): y`, y);
}

type Point = [x: number, y: number];
/** A 3 × 3 matrix, row by row, on homogeneous points (x, y, 1). */
type Matrix = number[];

/**
 * Four zero-size, invisible markers at the canvas's corners, in its container beside it: a zero-size box's
 * getBoundingClientRect() is where that point of the canvas's plane is on screen, after every transform on the way
 * (the canvas's own bounding box says where the corners are only without rotation, skew or perspective). Out of flow
 * (absolute), zero-size, hidden and inert to the pointer and to assistive technology: no layout, paint or focus.
 */
class CanvasCorners {
  private readonly marks: HTMLElement[];
  /** The content box (its offset from the canvas's margin box, and its size) the markers are placed for. */
  private placed = '';

  constructor(private readonly container: HTMLElement) {
    this.marks = [0, 1, 2, 3].map(() => {
      const m = document.createElement('div');
      m.setAttribute('aria-hidden', 'true');
      Object.assign(m.style, { position: 'absolute', width: '0', height: '0', margin: '0', visibility: 'hidden', pointerEvents: 'none' });
      return m;
    });
    // First in the container, before the canvas p5 appends: with no left / top, an absolute box sits at its static
    // position, where the canvas (a block, the container's only child in flow) begins, whatever the padding.
    container.prepend(...this.marks);
  }

  /** Whether the markers sit beside `canvas` (they describe its plane only there). */
  beside(canvas: HTMLCanvasElement): boolean {
    return canvas.parentNode === this.container;
  }

  /**
   * The viewport positions of the corners (0, 0), (w, 0), (w, h), (0, h) of the canvas's content box, which starts
   * (x, y) from its margin box, as laid out now.
   */
  read(x: number, y: number, w: number, h: number): Point[] {
    const placed = `${x} ${y} ${w} ${h}`;
    if (placed !== this.placed) {
      // Margins move each marker from the canvas's top-left corner to its own (written only when the box changes).
      this.placed = placed;
      this.marks[0].style.marginLeft = this.marks[3].style.marginLeft = `${x}px`;
      this.marks[1].style.marginLeft = this.marks[2].style.marginLeft = `${x + w}px`;
      this.marks[0].style.marginTop = this.marks[1].style.marginTop = `${y}px`;
      this.marks[2].style.marginTop = this.marks[3].style.marginTop = `${y + h}px`;
    }
    return this.marks.map((m) => {
      const r = m.getBoundingClientRect();
      return [r.left, r.top];
    });
  }

  remove(): void {
    for (const m of this.marks) m.remove();
  }
}

/**
 * The projective map taking canvas points (0, 0), (w, 0), (w, h), (0, h) to the viewport points `q` (Heckbert's
 * square-to-quad): exact for any 2D transform (affine) and for 3D ones, which show a plane in perspective. Without
 * rotation, skew or perspective it is x · scale + offset, as computed from the canvas's box. Null when the corners do
 * not make a convex quadrilateral turning one way: a zero-size canvas, a plane seen edge-on, or one reaching behind the
 * viewer (Chromium puts all four corners on one point then).
 */
function homography(q: Point[], w: number, h: number): Matrix | null {
  if (!(w > 0 && h > 0)) return null;
  // The turn at each corner (cross product of the edges in and out): all one sign (a mirror turns the other way).
  const turns = q.map(([ax, ay], i) => {
    const [[bx, by], [cx, cy]] = [q[(i + 1) % 4], q[(i + 2) % 4]];
    return (bx - ax) * (cy - by) - (by - ay) * (cx - bx);
  });
  if (!turns.every((t) => t > 1e-9) && !turns.every((t) => t < -1e-9)) return null;
  const [[x0, y0], [x1, y1], [x2, y2], [x3, y3]] = q;
  // Unit square → quad; sx, sy are 0 for a parallelogram (affine: g = k = 0).
  const sx = x0 - x1 + x2 - x3;
  const sy = y0 - y1 + y2 - y3;
  const dx1 = x1 - x2, dx2 = x3 - x2, dy1 = y1 - y2, dy2 = y3 - y2;
  const det = dx1 * dy2 - dx2 * dy1;
  const g = (sx * dy2 - dx2 * sy) / det;
  const k = (dx1 * sy - sx * dy1) / det;
  // Then canvas pixels → unit square (x / w, y / h).
  return [(x1 - x0 + g * x1) / w, (x3 - x0 + k * x3) / h, x0, (y1 - y0 + g * y1) / w, (y3 - y0 + k * y3) / h, y0, g / w, k / h, 1];
}

/** The inverse map (its adjugate: a projective map is the same up to scale). */
function invert([a, b, c, d, e, f, g, h, i]: Matrix): Matrix {
  return [e * i - f * h, c * h - b * i, b * f - c * e, f * g - d * i, a * i - c * g, c * d - a * f, d * h - e * g, b * g - a * h, a * e - b * d];
}

function project(m: Matrix, x: number, y: number): { x: number; y: number } {
  const z = m[6] * x + m[7] * y + m[8];
  return { x: (m[0] * x + m[1] * y + m[2]) / z, y: (m[3] * x + m[4] * y + m[5]) / z };
}
