// Cloth: filled cells and grid lines, leaving out what tore. torn[n]: bit 1 = the link from grid node n to its right
// neighbour broke, bit 2 = the link down broke.
import type { BodyPainter, Pen } from './painter.js';

export const cloth: BodyPainter = {
  batch: 'cloth',
  draw(pen, group, { fill, stroke, lineWidth }) {
    const { ctx, X, Y } = pen;
    if (fill) {
      ctx.beginPath();
      for (const k of group) {
        const b = pen.topology.bodies[k];
        const idx = b.indices;
        const cols = b.columns ?? 2;
        const rows = b.rows ?? 2;
        const torn = b.torn;
        // Each row's run of whole cells as one strip (along its top edge, back along its bottom edge), not one
        // quad a cell: a 200 × 200 cloth is 199 subpaths, not 39,601, and each node is visited twice, not four times.
        // Cell n (its top-left node) is whole when none of its four links broke.
        const whole = (n: number) => !torn || (torn[n] | (torn[n + cols] & 1) | (torn[n + 1] & 2)) === 0;
        for (let r = 0; r + 1 < rows; r++) {
          const top = r * cols;
          const bottom = top + cols;
          for (let c = 0; c + 1 < cols; ) {
            if (!whole(top + c)) {
              c++;
              continue;
            }
            let end = c;
            while (end + 2 < cols && whole(top + end + 1)) end++;
            ctx.moveTo(X(idx[top + c]), Y(idx[top + c]));
            for (let q = c + 1; q <= end + 1; q++) ctx.lineTo(X(idx[top + q]), Y(idx[top + q]));
            // fill() closes each strip; closePath() would make the path quadratic in Chromium (see painter.ts).
            for (let q = end + 1; q >= c; q--) ctx.lineTo(X(idx[bottom + q]), Y(idx[bottom + q]));
            c = end + 1;
          }
        }
      }
      ctx.fillStyle = fill;
      ctx.fill();
    }
    if (stroke) {
      ctx.beginPath();
      for (const k of group) {
        const b = pen.topology.bodies[k];
        const idx = b.indices;
        const cols = b.columns ?? 2;
        const rows = b.rows ?? 2;
        const torn = b.torn;
        const every = lineStep(pen, idx, cols, rows);
        // Rows then columns as polylines (every `every`-th one, through every `every`-th node, and the last), lifting
        // the pen over broken links.
        for (const [lines, steps, along, bit] of [[rows, cols, 1, 1], [cols, rows, cols, 2]] as const) {
          for (let l = 0; l < lines; l = next(l, every, lines)) {
            const first = along === 1 ? l * cols : l;
            ctx.moveTo(X(idx[first]), Y(idx[first]));
            for (let q = 0; q + 1 < steps; ) {
              const to = next(q, every, steps);
              let whole = true;
              for (let m = q; m < to && torn; m++) if (torn[first + m * along] & bit) whole = false;
              const n = first + to * along;
              if (whole) ctx.lineTo(X(idx[n]), Y(idx[n]));
              else ctx.moveTo(X(idx[n]), Y(idx[n]));
              q = to;
            }
          }
        }
      }
      ctx.strokeStyle = stroke;
      ctx.lineWidth = lineWidth;
      ctx.stroke();
    }
  },
};

/**
 * Grid lines at least this many CSS pixels apart: denser ones merge into one colour on screen, and cost as much to
 * raster as the fill again (a 200 × 200 cloth 800 px wide has lines 4 px apart: 80,000 stroked segments a frame).
 */
const MIN_LINE_GAP = 6;

/** Every how many rows and columns a grid line is drawn: 1 while the cloth's nodes are MIN_LINE_GAP px apart or more. */
function lineStep({ X, Y }: Pen, idx: Int32Array, cols: number, rows: number): number {
  // The node spacing along the top row and down the first column (a crumpled cloth reads denser: fewer lines).
  const span = (a: number, b: number, n: number) => (n > 1 ? Math.hypot(X(idx[b]) - X(idx[a]), Y(idx[b]) - Y(idx[a])) / (n - 1) : Infinity);
  const gap = Math.max(span(0, cols - 1, cols), span(0, (rows - 1) * cols, rows));
  return gap >= MIN_LINE_GAP || !(gap > 0) ? 1 : Math.ceil(MIN_LINE_GAP / gap);
}

/** The line (or node) after `q` when drawing every `every`-th of `count`: the last one is always drawn. */
function next(q: number, every: number, count: number): number {
  return q + every < count - 1 ? q + every : q === count - 1 ? count : count - 1;
}
