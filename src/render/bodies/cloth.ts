// Cloth: filled cells and grid lines, leaving out what tore. torn[n]: bit 1 = the link from grid node n to its right
// neighbour broke, bit 2 = the link down broke.
import type { BodyPainter } from './painter.js';

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
        // Rows then columns as polylines, lifting the pen over broken links.
        for (const [lines, steps, along, bit] of [[rows, cols, 1, 1], [cols, rows, cols, 2]] as const) {
          for (let l = 0; l < lines; l++) {
            let n = along === 1 ? l * cols : l;
            ctx.moveTo(X(idx[n]), Y(idx[n]));
            for (let q = 1; q < steps; q++, n += along) {
              const next = n + along;
              if (torn && torn[n] & bit) ctx.moveTo(X(idx[next]), Y(idx[next]));
              else ctx.lineTo(X(idx[next]), Y(idx[next]));
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
