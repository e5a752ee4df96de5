// Ropes: polylines through their particles, as thick as their particles (at least the style's line width).
import type { BodyPainter } from './painter.js';

export const rope: BodyPainter = {
  batch: 'rope',
  draw(pen, group, style) {
    // The stroke's colour, else the fill's; with both "none", nothing (it was drawn in black).
    const colour = style.stroke ?? style.fill;
    if (colour === null) return;
    const { ctx, X, Y } = pen;
    let width = style.lineWidth;
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      const idx = b.indices;
      width = Math.max(width, 2 * (b.radius ?? 0) * pen.scale);
      ctx.moveTo(X(idx[0]), Y(idx[0]));
      for (let q = 1; q < idx.length; q++) ctx.lineTo(X(idx[q]), Y(idx[q]));
    }
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.stroke();
  },
};
