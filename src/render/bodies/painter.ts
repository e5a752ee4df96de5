// How a body type is drawn: one painter per type (box.ts, circle.ts, …, listed in index.ts). Bodies are drawn in
// batches, one canvas path per pass: the bodies of one batch and one style together (all shapes of a fill, all ropes
// of a colour). What the host knows about a type is its other half, in src/worker/host/bodies/.
import { POSE, type Topology, type TopologyBody } from '../../worker/protocol.js';

export interface BodyStyle {
  /** CSS colour or null for none. */
  fill: string | null;
  stroke: string | null;
  /** Stroke width in CSS pixels. */
  lineWidth: number;
}

/** What painters draw with, for one frame. */
export interface Pen {
  ctx: CanvasRenderingContext2D;
  /** Canvas CSS pixels of particle i (a storage index) at its interpolated position. */
  readonly X: (i: number) => number;
  readonly Y: (i: number) => number;
  /** World → canvas CSS pixels: px = offsetX + x · scale, py = offsetY + y · scale. */
  scale: number;
  offsetX: number;
  offsetY: number;
  topology: Topology;
  /** Body k's pose (x, y, angle; a rigid body's centre of mass) at poses[POSE·k …], interpolated like the positions. */
  poses: Float64Array;
}

export interface BodyPainter {
  /** Painters of one batch share its draw function: their bodies of one style are drawn together. */
  readonly batch: string;
  /** Draws the bodies `group` (places in pen.topology.bodies) in one style. */
  readonly draw: (pen: Pen, group: readonly number[], style: BodyStyle) => void;
}

/**
 * Closed shapes of one style, as one path with one fill and one stroke: a rigid body its outline or disc placed at
 * its pose (then a second path: a radius line on each rigid disc, so its spin shows); a body the topology gives a
 * radius and one particle is a disc (a particle ball); any other the closed loop through its particles (the first
 * `ring` of them: a soft body's hub is not on its outline), pushed out by the particles' radius when the topology
 * gives one (a soft ring's particles collide as discs: drawn through their centres, it hovered above the floor).
 */
export const shape: BodyPainter = {
  batch: 'shape',
  draw(pen, group, { fill, stroke, lineWidth }) {
    const { ctx, X, Y } = pen;
    let spokes = false;
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      if (b.rigid) {
        spokes = rigidShape(pen, k, b) || spokes;
        continue;
      }
      const idx = b.indices;
      if (b.radius !== undefined && idx.length === 1) {
        disc(pen, idx[0], b.radius * pen.scale);
        continue;
      }
      const n = b.ring ?? idx.length;
      if (b.radius) {
        loopAround(pen, idx, n, b.radius * pen.scale);
        continue;
      }
      ctx.moveTo(X(idx[0]), Y(idx[0]));
      for (let q = 1; q < n; q++) ctx.lineTo(X(idx[q]), Y(idx[q]));
      closeLoop(ctx, X(idx[0]), Y(idx[0]), X(idx[1 % n]), Y(idx[1 % n]));
    }
    if (fill) {
      ctx.fillStyle = fill;
      ctx.fill();
    }
    if (stroke) {
      ctx.strokeStyle = stroke;
      ctx.lineWidth = lineWidth;
      ctx.stroke();
    }
    if (!spokes) return;
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      if (b.rigid && !b.outline) spoke(pen, k, b.radius ?? 0);
    }
    ctx.strokeStyle = stroke ?? SPOKE;
    ctx.lineWidth = lineWidth;
    ctx.stroke();
  },
};

/**
 * The closed loop through the first n particles of idx, each pushed out by r pixels, square to the line from the
 * particle before it to the one after (outward by the loop's turning sense): the loop runs along the outer side of
 * the particles' discs, as far out as each disc reaches.
 */
function loopAround({ ctx, X, Y }: Pen, idx: Int32Array, n: number, r: number): void {
  let area = 0;
  for (let q = 0; q < n; q++) {
    const a = idx[q];
    const b = idx[(q + 1) % n];
    area += X(a) * Y(b) - X(b) * Y(a);
  }
  const out = area >= 0 ? r : -r;
  // The first two points, for closeLoop (four locals: nothing allocated a frame).
  let x0 = 0;
  let y0 = 0;
  let x1 = 0;
  let y1 = 0;
  for (let q = 0; q < n; q++) {
    const i = idx[q];
    const prev = idx[(q + n - 1) % n];
    const next = idx[(q + 1) % n];
    const tx = X(next) - X(prev);
    const ty = Y(next) - Y(prev);
    const length = Math.hypot(tx, ty);
    const k = length > 0 ? out / length : 0;
    const x = X(i) + ty * k;
    const y = Y(i) - tx * k;
    if (q === 0) ctx.moveTo(x, y);
    else ctx.lineTo(x, y);
    if (q === 0) {
      x0 = x1 = x;
      y0 = y1 = y;
    } else if (q === 1) {
      x1 = x;
      y1 = y;
    }
  }
  closeLoop(ctx, x0, y0, x1, y1);
}

/** A radius line's colour on a disc drawn without a stroke. */
const SPOKE = 'rgba(0, 0, 0, 0.45)';

/** A rigid body k as a subpath at its pose: its outline turned by its angle, or a disc; true for a disc. */
function rigidShape({ ctx, poses, scale, offsetX, offsetY }: Pen, k: number, b: TopologyBody): boolean {
  const o = POSE * k;
  const x = offsetX + poses[o] * scale;
  const y = offsetY + poses[o + 1] * scale;
  const v = b.outline;
  if (!v) {
    const r = (b.radius ?? 0) * scale;
    ctx.moveTo(x + r, y);
    ctx.arc(x, y, r, 0, Math.PI * 2);
    return true;
  }
  const c = Math.cos(poses[o + 2]) * scale;
  const s = Math.sin(poses[o + 2]) * scale;
  ctx.moveTo(x + c * v[0] - s * v[1], y + s * v[0] + c * v[1]);
  for (let q = 2; q < v.length; q += 2) ctx.lineTo(x + c * v[q] - s * v[q + 1], y + s * v[q] + c * v[q + 1]);
  const q1 = v.length > 2 ? 2 : 0;
  closeLoop(ctx, x + c * v[0] - s * v[1], y + s * v[0] + c * v[1], x + c * v[q1] - s * v[q1 + 1], y + s * v[q1] + c * v[q1 + 1]);
  return false;
}

/**
 * Ends an outline's subpath at its first point (x0, y0), then goes on to its second (x1, y1): the stroke joins at the
 * first corner as at the others, and one stroke() or fill() of the path covers the doubled edge once. Not
 * closePath(): with many subpaths in one path Chromium makes it quadratic (measured: 2,500 closed quads took 45 ms to
 * fill and 10,000 took 650, against 3 and 16 without; a 200×200 cloth froze the page).
 */
function closeLoop(ctx: CanvasRenderingContext2D, x0: number, y0: number, x1: number, y1: number): void {
  ctx.lineTo(x0, y0);
  ctx.lineTo(x1, y1);
}

/** A line from the centre of rigid disc k to its rim along its angle. */
function spoke({ ctx, poses, scale, offsetX, offsetY }: Pen, k: number, radius: number): void {
  const o = POSE * k;
  const x = offsetX + poses[o] * scale;
  const y = offsetY + poses[o + 1] * scale;
  const r = radius * scale;
  ctx.moveTo(x, y);
  ctx.lineTo(x + r * Math.cos(poses[o + 2]), y + r * Math.sin(poses[o + 2]));
}

/** A full circle of radius r (pixels) around particle i, as a subpath of the current path. */
export function disc({ ctx, X, Y }: Pen, i: number, r: number): void {
  ctx.moveTo(X(i) + r, Y(i));
  ctx.arc(X(i), Y(i), r, 0, Math.PI * 2);
}
