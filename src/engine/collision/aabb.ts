// Axis-aligned bounding box (seed 5.1, Algorithm 7).
import type { Shape } from './shape.js';

export class AABB {
  minX = 0;
  minY = 0;
  maxX = 0;
  maxY = 0;
}

/** The smallest axis-aligned box around the shape (radius included), written into `out`. */
export function aabbOf(shape: Shape, out: AABB = new AABB()): AABB {
  const { xs, ys, index, offset, count, radius } = shape;
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let k = 0; k < count; k++) {
    const i = index[offset + k];
    const x = xs[i];
    const y = ys[i];
    if (x < minX) minX = x;
    if (x > maxX) maxX = x;
    if (y < minY) minY = y;
    if (y > maxY) maxY = y;
  }
  out.minX = minX - radius;
  out.minY = minY - radius;
  out.maxX = maxX + radius;
  out.maxY = maxY + radius;
  return out;
}

/** Algorithm 7: the boxes overlap or touch (a conservative test for a broad phase). */
export function aabbOverlap(a: AABB, b: AABB): boolean {
  return !(a.maxX < b.minX || a.minX > b.maxX || a.maxY < b.minY || a.minY > b.maxY);
}

/** (x, y) is inside or on the box. */
export function aabbContains(box: AABB, x: number, y: number): boolean {
  return x >= box.minX && x <= box.maxX && y >= box.minY && y <= box.maxY;
}

export function aabbArea(box: AABB): number {
  return (box.maxX - box.minX) * (box.maxY - box.minY);
}
