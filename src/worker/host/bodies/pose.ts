// Reading a body's pose (x, y, angle) from its particles, as its descriptor's PoseModel says: once at build (the
// basis), then for every body of every frame (no allocation).
import type { BodyDescription } from '../../../engine/index.js';
import type { PoseBasis, PoseModel } from './descriptor.js';

/** Rigid shapes (boxes, polygons): the described origin, turning with the body. */
export const RIGID: PoseModel = { described: true, turns: true };
/** One particle standing for a shape (a ball): the described origin; a lone particle has no turn to show. */
export const DISC: PoseModel = { described: true };
/** Deformable bodies (ropes, cloth, soft rings): the particles' mean. */
export const CENTROID: PoseModel = {};

/** Angle of the first edge (particle 0 → 1), 0 for a lone particle. */
function edgeAngle(idx: Int32Array, x: Float64Array, y: Float64Array): number {
  return idx.length >= 2 ? Math.atan2(y[idx[1]] - y[idx[0]], x[idx[1]] - x[idx[0]]) : 0;
}

const NO_BASIS: PoseBasis = [0, 0, 0, 0];

/** The basis of a body just built (its particles at x, y). */
export function measurePose(m: PoseModel, desc: BodyDescription, idx: Int32Array, x: Float64Array, y: Float64Array): PoseBasis {
  const mean = new Float64Array(3);
  writePose(CENTROID, mean, 0, idx, x, y, NO_BASIS);
  const d = desc as { x?: unknown; y?: unknown; angle?: unknown };
  return [
    edgeAngle(idx, x, y),
    m.described && typeof d.x === 'number' ? d.x - mean[0] : 0,
    m.described && typeof d.y === 'number' ? d.y - mean[1] : 0,
    typeof d.angle === 'number' ? d.angle : 0,
  ];
}

/** Writes the body's x, y and angle to out[o], out[o + 1], out[o + 2]. */
export function writePose(m: PoseModel, out: Float64Array, o: number, idx: Int32Array, x: Float64Array, y: Float64Array, b: PoseBasis): void {
  const a = m.anchor;
  if (a !== undefined && a < idx.length) {
    out[o] = x[idx[a]];
    out[o + 1] = y[idx[a]];
    out[o + 2] = b[3];
    return;
  }
  let mx = 0;
  let my = 0;
  for (let q = 0; q < idx.length; q++) {
    mx += x[idx[q]];
    my += y[idx[q]];
  }
  const theta = m.turns ? edgeAngle(idx, x, y) - b[0] : 0;
  const cos = Math.cos(theta);
  const sin = Math.sin(theta);
  out[o] = mx / idx.length + b[1] * cos - b[2] * sin;
  out[o + 1] = my / idx.length + b[1] * sin + b[2] * cos;
  out[o + 2] = b[3] + theta;
}
