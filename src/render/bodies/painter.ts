// How a body type is drawn: one painter per type (box.ts, circle.ts, …, listed in index.ts). Bodies are drawn in
// batches, one canvas path per pass: the bodies of one batch and one style together (all shapes of a fill, all ropes
// of a colour). What the host knows about a type is its other half, in src/worker/host/bodies/.
import type { Topology } from '../../worker/protocol.js';

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
  /** CSS pixels per world unit. */
  scale: number;
  topology: Topology;
  /** The newest frame: body k's pose (x, y, angle) is at frame[poseAt + POSE·k]. */
  frame: Float64Array;
  poseAt: number;
}

export interface BodyPainter {
  /** Painters of one batch share its draw function: their bodies of one style are drawn together. */
  readonly batch: string;
  /** Draws the bodies `group` (places in pen.topology.bodies) in one style. */
  readonly draw: (pen: Pen, group: readonly number[], style: BodyStyle) => void;
}

/**
 * Closed shapes of one style, as one path with one fill and one stroke: a body the topology gives a radius and one
 * particle is a disc (a ball), any other the closed loop through its particles (the first `ring` of them: a soft
 * body's hub is not on its outline).
 */
export const shape: BodyPainter = {
  batch: 'shape',
  draw(pen, group, { fill, stroke, lineWidth }) {
    const { ctx, X, Y } = pen;
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      const idx = b.indices;
      if (b.radius !== undefined && idx.length === 1) {
        disc(pen, idx[0], b.radius * pen.scale);
        continue;
      }
      const n = b.ring ?? idx.length;
      ctx.moveTo(X(idx[0]), Y(idx[0]));
      for (let q = 1; q < n; q++) ctx.lineTo(X(idx[q]), Y(idx[q]));
      ctx.closePath();
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
  },
};

/** A full circle of radius r (pixels) around particle i, as a subpath of the current path. */
export function disc({ ctx, X, Y }: Pen, i: number, r: number): void {
  ctx.moveTo(X(i) + r, Y(i));
  ctx.arc(X(i), Y(i), r, 0, Math.PI * 2);
}
