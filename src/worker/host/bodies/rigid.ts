// Rigid bodies (the engine's rigid model of boxes, polygons and circles): one particle, the centre of mass, with an
// angle. Measured once when built: where that centre is in the body's own coordinates and the outline about it, for
// the topology; every frame then gives the centre and the angle (no allocation, no trigonometry).
import type { BodyDescription, Handle, World } from '../../../engine/index.js';
import { ParticleFlag } from '../../../engine/particles.js';
import type { TopologyBody } from '../../protocol.js';
import type { BodyDescriptor } from './descriptor.js';

export interface RigidFacts {
  /** The centre of mass in the body's own coordinates (where its description placed its points). */
  center: [number, number];
  /** The outline about the centre of mass (x0, y0, x1, y1, …, unturned), or null for a disc. */
  outline: Float64Array | null;
  /** A disc's radius (0 with an outline). */
  radius: number;
}

/** The facts of a body just built (or restored), or null when it is not a rigid body. */
export function rigidFacts(w: World, handle: Handle, desc: BodyDescription, descriptor: BodyDescriptor): RigidFacts | null {
  const idx = w.bodyParticleIndices(handle);
  const p = w.particles;
  if (idx.length !== 1 || (p.flags[idx[0]] & ParticleFlag.Rigid) === 0) return null;
  const i = idx[0];
  const pose = w.bodyPose(handle);
  const c = Math.cos(pose.angle);
  const s = Math.sin(pose.angle);
  const dx = p.x[i] - pose.x;
  const dy = p.y[i] - pose.y;
  const cx = c * dx + s * dy;
  const cy = -s * dx + c * dy;
  const points = descriptor.rigidOutline?.(desc as never);
  const outline = points ? Float64Array.from(points.flatMap((q) => [q.x - cx, q.y - cy])) : null;
  return { center: [cx, cy], outline, radius: outline ? 0 : p.radius[i] };
}

/** The topology's drawing facts of a rigid body. */
export function describeRigid(t: TopologyBody, facts: RigidFacts): void {
  t.rigid = true;
  t.center = [facts.center[0], facts.center[1]];
  if (facts.outline) t.outline = facts.outline.slice();
  else t.radius = facts.radius;
}

/** Writes the pose of rigid body row i (its centre of mass and angle) to out[o], out[o + 1], out[o + 2]. */
export function writeRigidPose(out: Float64Array, o: number, i: number, x: Float64Array, y: Float64Array, angle: Float64Array): void {
  out[o] = x[i];
  out[o + 1] = y[i];
  out[o + 2] = angle[i];
}

/** Writes the bounding box (minX, minY, maxX, maxY) of rigid body row i, turned by its angle, to out[o…o + 3]. */
export function writeRigidBox(out: Float64Array, o: number, facts: RigidFacts, cx: number, cy: number, angle: number): void {
  const v = facts.outline;
  if (!v) {
    out[o] = cx - facts.radius;
    out[o + 1] = cy - facts.radius;
    out[o + 2] = cx + facts.radius;
    out[o + 3] = cy + facts.radius;
    return;
  }
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  let x0 = Infinity;
  let y0 = Infinity;
  let x1 = -Infinity;
  let y1 = -Infinity;
  for (let k = 0; k < v.length; k += 2) {
    const x = cx + c * v[k] - s * v[k + 1];
    const y = cy + s * v[k] + c * v[k + 1];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
  }
  out[o] = x0;
  out[o + 1] = y0;
  out[o + 2] = x1;
  out[o + 3] = y1;
}
