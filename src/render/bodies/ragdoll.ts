// Ragdolls: bones (the builder's RAGDOLL_BONES) as thick strokes, heads as discs of the topology's radius.
import { RAGDOLL_BONES } from '../../engine/index.js';
import { disc, type BodyPainter } from './painter.js';

export const ragdoll: BodyPainter = {
  batch: 'ragdoll',
  draw(pen, group, style) {
    // One colour for the figure, the stroke's (else the fill's); with both "none", nothing (it was drawn in #333).
    const colour = style.stroke ?? style.fill;
    if (colour === null) return;
    const { ctx, X, Y } = pen;
    let width = 2;
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      const idx = b.indices;
      width = Math.max(width, (b.radius ?? 0.1) * 0.7 * pen.scale);
      for (let q = 0; q < RAGDOLL_BONES.length; q++) {
        const bone = RAGDOLL_BONES[q];
        ctx.moveTo(X(idx[bone[0]]), Y(idx[bone[0]]));
        ctx.lineTo(X(idx[bone[1]]), Y(idx[bone[1]]));
      }
    }
    ctx.strokeStyle = colour;
    ctx.lineWidth = width;
    ctx.stroke();
    ctx.beginPath();
    for (const k of group) {
      const b = pen.topology.bodies[k];
      disc(pen, b.indices[0], (b.radius ?? 0.1) * pen.scale);
    }
    ctx.fillStyle = style.fill ?? colour;
    ctx.fill();
  },
};
