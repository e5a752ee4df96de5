// Bodies where they are drawn, answered at once from the newest frame: which body is under a point (a touchstart must
// decide synchronously whether it blocks the page's scroll, with no time to ask the worker) and the box around a body
// (the keyboard's focus ring). The renderer's own painters trace the bodies onto a scratch 2D context whose fill() and
// stroke() test the point (isPointInPath / isPointInStroke) instead of painting and whose path calls grow a bounding
// box: what counts as hit is what is drawn, for every body type, without a second description of the shapes.
import { PAINTERS, type BodyStyle, type Pen } from '../../render/bodies/index.js';
import type { FrameSource } from '../../render/renderer.js';
import { F, HEADER, POSE, poseOffset, type Topology, type TopologyBody } from '../../worker/protocol.js';
import type { ViewMapping } from './stage.js';

/** A box in canvas CSS pixels. */
export interface Box {
  left: number;
  top: number;
  right: number;
  bottom: number;
}

/** A body under a point, and the point on it where to take it (canvas CSS pixels). */
export interface Touching {
  body: TopologyBody;
  x: number;
  y: number;
}

/** A point near a body but not on it is moved onto it: the nearest on rings of PROBE_DIRECTIONS points around it. */
const PROBE_RINGS = 4;
const PROBE_DIRECTIONS = 12;

/** Every painter runs both its passes (fill and stroke) with this style; the colours are never painted. */
const TRACE_STYLE: BodyStyle = { fill: '#000', stroke: '#000', lineWidth: 1 };
/** The same with hairline outlines: a point on it is inside the body's shape, not on its outline's stroke. */
const INSIDE_STYLE: BodyStyle = { ...TRACE_STYLE, lineWidth: 1e-3 };

/** Path calls whose points (x, y pairs among their arguments, at these places) bound what they add. */
const POINTS: Record<string, number[]> = {
  moveTo: [0],
  lineTo: [0],
  quadraticCurveTo: [0, 2],
  bezierCurveTo: [0, 2, 4],
  arcTo: [0, 2],
};
/** Transform calls: the tracer follows the context's matrix after each. */
const TRANSFORMS = ['setTransform', 'transform', 'translate', 'rotate', 'scale', 'resetTransform', 'save', 'restore'];
/** Calls that paint without the path: nothing to trace, and nothing is painted. */
const PAINTS = ['fillRect', 'strokeRect', 'clearRect', 'fillText', 'strokeText', 'drawImage', 'putImageData'];

/**
 * A 2D context for painters that paints nothing: fill() and stroke() test a point against the current path (within
 * `slop` CSS pixels), and the path's points grow a box. A Proxy over a real context (1 × 1 pixels) that keeps the
 * state (line width, transform) and answers the exact tests; path calls are only recorded, and handed to it when the
 * point is near the path's box (so tracing thousands of bodies costs the browser's path code only for the few near).
 */
class Tracer {
  /** What painters draw with. */
  readonly ctx: CanvasRenderingContext2D;
  /** Some fill or stroke since begin() covers the point. */
  hit = false;
  /** The box of everything filled or stroked since begin() (strokes widened by half their width). */
  readonly box: Box = { left: Infinity, top: Infinity, right: -Infinity, bottom: -Infinity };
  private readonly real: CanvasRenderingContext2D;
  /** The current path: its box, and its calls (method, arguments) since beginPath(). */
  private readonly path: Box = { left: Infinity, top: Infinity, right: -Infinity, bottom: -Infinity };
  private readonly names: string[] = [];
  private readonly args: unknown[][] = [];
  private count = 0;
  /** The real context holds the current path. */
  private built = false;
  private matrix: DOMMatrix | null = null;
  private px = NaN;
  private py = NaN;
  private slop = 0;

  constructor() {
    const canvas = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(1, 1) : document.createElement('canvas');
    const real = canvas.getContext('2d') as CanvasRenderingContext2D;
    this.real = real;
    const own = new Map<PropertyKey, unknown>();
    own.set('beginPath', () => {
      reset(this.path);
      this.count = 0;
      this.built = false;
      if (this.matrix) this.recordMatrix();
    });
    own.set('closePath', () => this.record('closePath', []));
    own.set('fill', (...args: unknown[]) => this.filled(args[0] === 'evenodd' ? 'evenodd' : 'nonzero'));
    own.set('stroke', () => this.stroked());
    for (const [name, at] of Object.entries(POINTS)) {
      own.set(name, (...args: number[]) => {
        for (const k of at) this.grow(args[k], args[k + 1], 0);
        this.record(name, args);
      });
    }
    own.set('arc', (...args: number[]) => {
      this.grow(args[0], args[1], args[2]);
      this.record('arc', args);
    });
    own.set('ellipse', (...args: number[]) => {
      this.grow(args[0], args[1], Math.max(args[2], args[3]));
      this.record('ellipse', args);
    });
    for (const name of ['rect', 'roundRect']) {
      own.set(name, (...args: unknown[]) => {
        const [x, y, w, h] = args as number[];
        this.grow(x, y, 0);
        this.grow(x + w, y + h, 0);
        this.grow(x + w, y, 0);
        this.grow(x, y + h, 0);
        this.record(name, args);
      });
    }
    for (const name of TRANSFORMS) {
      own.set(name, (...args: unknown[]) => {
        (real[name as keyof CanvasRenderingContext2D] as (...a: unknown[]) => void)(...args);
        const m = real.getTransform();
        this.matrix = m.isIdentity ? null : m;
        this.recordMatrix();
      });
    }
    for (const name of PAINTS) own.set(name, () => {});
    const bound = new Map<PropertyKey, unknown>();
    this.ctx = new Proxy(real, {
      get(target, prop) {
        if (own.has(prop)) return own.get(prop);
        const value = Reflect.get(target, prop, target);
        if (typeof value !== 'function') return value;
        let fn = bound.get(prop);
        if (!fn) bound.set(prop, (fn = (value as (...a: unknown[]) => unknown).bind(target)));
        return fn;
      },
      set(target, prop, value) {
        return Reflect.set(target, prop, value, target);
      },
    });
  }

  /** Starts a trace: the point to test (canvas CSS pixels; NaN tests nothing) and how near counts as on it. */
  begin(x: number, y: number, slop: number): void {
    this.px = x;
    this.py = y;
    this.slop = slop;
    this.hit = false;
    reset(this.box);
    reset(this.path);
    this.count = 0;
    this.built = false;
    this.real.resetTransform();
    this.matrix = null;
  }

  private record(name: string, args: unknown[]): void {
    this.names[this.count] = name;
    this.args[this.count] = args;
    this.count++;
    this.built = false;
  }

  /** The transform from here on in the path (absolute, so that the path can be built again from its calls). */
  private recordMatrix(): void {
    const m = this.matrix;
    this.record('setTransform', m ? [m.a, m.b, m.c, m.d, m.e, m.f] : [1, 0, 0, 1, 0, 0]);
  }

  /** Builds the recorded path in the real context (for its exact tests), leaving its transform as it was. */
  private build(): void {
    if (this.built) return;
    const real = this.real;
    const now = real.getTransform();
    real.resetTransform();
    real.beginPath();
    for (let k = 0; k < this.count; k++) (real[this.names[k] as keyof CanvasRenderingContext2D] as (...a: unknown[]) => void)(...this.args[k]);
    real.setTransform(now);
    this.built = true;
  }

  /** A point of the current path (in the painter's coordinates), `r` around it. */
  private grow(x: number, y: number, r: number): void {
    const m = this.matrix;
    if (!m) {
      extend(this.path, x - r, y - r, x + r, y + r);
      return;
    }
    // The box of the transformed square around the point (a rotated circle stays within it).
    for (const [dx, dy] of [[-r, -r], [r, -r], [-r, r], [r, r]]) {
      const px = m.a * (x + dx) + m.c * (y + dy) + m.e;
      const py = m.b * (x + dx) + m.d * (y + dy) + m.f;
      extend(this.path, px, py, px, py);
    }
  }

  private filled(rule: CanvasFillRule): void {
    const p = this.path;
    extend(this.box, p.left, p.top, p.right, p.bottom);
    if (this.hit || !this.near(this.slop)) return;
    this.build();
    this.hit = this.real.isPointInPath(this.px, this.py, rule) || (this.slop > 0 && this.inStroke(2 * this.slop));
  }

  private stroked(): void {
    const p = this.path;
    const half = this.real.lineWidth / 2;
    extend(this.box, p.left - half, p.top - half, p.right + half, p.bottom + half);
    const width = Math.max(this.real.lineWidth, 2 * this.slop);
    if (this.hit || !this.near(width / 2)) return;
    this.build();
    this.hit = this.inStroke(width);
  }

  /** The point is within `pad` of the current path's box (the cheap test before the browser's exact one). */
  private near(pad: number): boolean {
    const p = this.path;
    return this.px >= p.left - pad && this.px <= p.right + pad && this.py >= p.top - pad && this.py <= p.bottom + pad;
  }

  /** The point is on the current path stroked `width` wide. */
  private inStroke(width: number): boolean {
    const real = this.real;
    const before = real.lineWidth;
    real.lineWidth = width;
    const inside = real.isPointInStroke(this.px, this.py);
    real.lineWidth = before;
    return inside;
  }
}

function reset(b: Box): void {
  b.left = b.top = Infinity;
  b.right = b.bottom = -Infinity;
}

function extend(b: Box, left: number, top: number, right: number, bottom: number): void {
  if (left < b.left) b.left = left;
  if (top < b.top) b.top = top;
  if (right > b.right) b.right = right;
  if (bottom > b.bottom) b.bottom = bottom;
}

/** @internal The newest frame's bodies as drawn: hit tests, boxes and velocities, for the pointer and the keyboard. */
export class BodyOutlines {
  private tracer: Tracer | null = null;
  /** The frame and mapping being traced (read by the pen's X and Y). */
  private frame: Float64Array = new Float64Array(HEADER);
  private view: ViewMapping = { scale: 1, offsetX: 0, offsetY: 0 };
  private readonly one = [0];
  private pen: Pen | null = null;
  /** The frame (and where in it) the pen's poses view. */
  private posesOf: Float64Array | null = null;
  private posesAt = 0;

  constructor(
    /** The engine whose newest frame is traced (null: none). */
    private readonly source: () => FrameSource | null,
    /** World → canvas CSS pixels as drawn (null: no canvas). */
    private readonly mapping: () => ViewMapping | null,
  ) {}

  /**
   * The body drawn at canvas point (x, y) or within `slop` CSS pixels of it, among those `include` accepts (the last
   * one in the topology when several are), with a point on it where to take it: (x, y) itself when it is on the body,
   * else a point on the body near it. Null when there is none.
   */
  bodyAt(x: number, y: number, slop: number, include: (body: TopologyBody) => boolean = () => true): Touching | null {
    const t = this.newest();
    if (!t || !Number.isFinite(x) || !Number.isFinite(y)) return null;
    let found = -1;
    for (let k = 0; k < t.bodies.length; k++) if (include(t.bodies[k]) && this.trace(t, k, x, y, slop).hit) found = k;
    if (found < 0) return null;
    const body = t.bodies[found];
    const inside = (px: number, py: number) => this.trace(t, found, px, py, 0, INSIDE_STYLE).hit;
    if (inside(x, y)) return { body, x, y };
    // Within the slop only: the nearest of a few points around (x, y) inside the body, one ring deeper when that is
    // inside too (the engine takes a body at a point inside its shape, not on its edge).
    for (let ring = 1; ring <= PROBE_RINGS; ring++) {
      for (let q = 0; q < PROBE_DIRECTIONS; q++) {
        const a = (2 * Math.PI * q) / PROBE_DIRECTIONS;
        const at = (j: number) => [x + ((slop * j) / PROBE_RINGS) * Math.cos(a), y + ((slop * j) / PROBE_RINGS) * Math.sin(a)] as const;
        if (!inside(...at(ring))) continue;
        const [px, py] = inside(...at(ring + 1)) ? at(ring + 1) : at(ring);
        return { body, x: px, y: py };
      }
    }
    return { body, x, y };
  }

  /** The box around body `key` as drawn in the newest frame, in canvas CSS pixels, or null when it is not there. */
  bounds(key: number): Box | null {
    const t = this.newest();
    const k = t ? t.bodies.findIndex((b) => b.key === key) : -1;
    if (!t || k < 0) return null;
    const { box } = this.trace(t, k, NaN, NaN, 0);
    return Number.isFinite(box.left) && Number.isFinite(box.top) && Number.isFinite(box.right) && Number.isFinite(box.bottom) ? { ...box } : null;
  }

  /**
   * Velocity of body `key` (world units / s) from its pose in the two newest frames, or null when they cannot tell
   * (one frame, another topology, the same step).
   */
  velocity(key: number): { x: number; y: number } | null {
    const src = this.source();
    const t = this.newest();
    if (!src || !t || src.frames.received < 2) return null;
    const { curr: f, prev: p } = src.frames;
    const dt = f[F.time] - p[F.time];
    const k = t.bodies.findIndex((b) => b.key === key);
    if (k < 0 || p[F.topology] !== f[F.topology] || p[F.particles] !== f[F.particles] || !(dt > 0)) return null;
    const o = poseOffset(f[F.particles]) + POSE * k;
    const v = { x: (f[o] - p[o]) / dt, y: (f[o + 1] - p[o + 1]) / dt };
    return Number.isFinite(v.x) && Number.isFinite(v.y) ? v : null;
  }

  /** The topology of the newest frame (with the frame and mapping in place for the pen), or null. */
  private newest(): Topology | null {
    const src = this.source();
    const view = this.mapping();
    if (!src || !view || !(view.scale > 0)) return null;
    src.poll();
    const t = src.topology;
    const f = src.frames.curr;
    if (!t || src.frames.received === 0 || f[F.topology] !== t.version) return null;
    this.frame = f;
    this.view = view;
    return t;
  }

  /** Body k of `t` traced by its painter, testing canvas point (x, y). */
  private trace(t: Topology, k: number, x: number, y: number, slop: number, style = TRACE_STYLE): Tracer {
    const tracer = (this.tracer ??= new Tracer());
    const f = this.frame;
    const pen = (this.pen ??= {
      ctx: tracer.ctx,
      X: (i: number) => this.view.offsetX + this.frame[HEADER + 2 * i] * this.view.scale,
      Y: (i: number) => this.view.offsetY + this.frame[HEADER + 2 * i + 1] * this.view.scale,
      scale: 1,
      offsetX: 0,
      offsetY: 0,
      topology: t,
      poses: f,
    });
    pen.scale = this.view.scale;
    pen.offsetX = this.view.offsetX;
    pen.offsetY = this.view.offsetY;
    pen.topology = t;
    // The newest frame's poses, not blended with the frame before (at most a frame from what is drawn).
    const at = poseOffset(f[F.particles]);
    if (this.posesOf !== f || this.posesAt !== at) {
      pen.poses = f.subarray(at);
      this.posesOf = f;
      this.posesAt = at;
    }
    tracer.begin(x, y, slop);
    this.one[0] = k;
    PAINTERS[t.bodies[k].type]?.draw(pen, this.one, style);
    return tracer;
  }
}
