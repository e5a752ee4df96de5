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
        for (let r = 0; r + 1 < rows; r++) {
          for (let c = 0; c + 1 < cols; c++) {
            const n = r * cols + c;
            if (torn && (torn[n] | (torn[n + cols] & 1) | (torn[n + 1] & 2)) !== 0) continue;
            ctx.moveTo(X(idx[n]), Y(idx[n]));
            ctx.lineTo(X(idx[n + 1]), Y(idx[n + 1]));
            ctx.lineTo(X(idx[n + cols + 1]), Y(idx[n + cols + 1]));
            // fill() closes each cell; closePath() would make the path quadratic in Chromium (see painter.ts).
            ctx.lineTo(X(idx[n + cols]), Y(idx[n + cols]));
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
