// A rigid body's row in the particle store and the calls on it: pose, velocities, forces, mass properties, type.
// The World checks the arguments and finds the row; these functions read and write the columns.
import { ParticleFlag, type ParticleStore } from '../particles.js';
import { BodyType, type RigidShapeSource } from './shapes.js';

/**
 * Makes row i the centre of mass of a rigid body of `source` with its origin at (x, y) turned by `angle`: mass and
 * inertia by type, the row's radius its shape's extent (what bounding boxes and sleeping measure it by).
 */
export function initRigidRow(p: ParticleStore, i: number, source: RigidShapeSource, type: BodyType, x: number, y: number, angle: number): void {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const cx = x + c * source.centroidX - s * source.centroidY;
  const cy = y + s * source.centroidX + c * source.centroidY;
  p.x[i] = p.px[i] = p.qx[i] = p.sx[i] = cx;
  p.y[i] = p.py[i] = p.qy[i] = p.sy[i] = cy;
  p.angle[i] = p.pangle[i] = p.sangle[i] = p.qangle[i] = angle;
  p.rc[i] = c;
  p.rs[i] = s;
  p.radius[i] = source.extent;
  setType(p, i, source, type);
}

/** Mass, inertia and flags of a body type (a static body also stops). */
export function setType(p: ParticleStore, i: number, source: RigidShapeSource, type: BodyType): void {
  const dynamic = type === BodyType.Dynamic;
  p.invMass[i] = dynamic ? 1 / source.mass : 0;
  p.invInertia[i] = dynamic ? 1 / source.inertia : 0;
  let flags = (p.flags[i] & ~(ParticleFlag.Static | ParticleFlag.Kinematic)) | ParticleFlag.Rigid;
  if (type === BodyType.Static) {
    flags |= ParticleFlag.Static;
    p.vx[i] = p.vy[i] = p.omega[i] = 0;
  } else if (type === BodyType.Kinematic) flags |= ParticleFlag.Kinematic;
  p.flags[i] = flags;
}

/** The body's origin and angle: the centre of mass minus its turned offset from the origin. */
export function poseOf(p: ParticleStore, i: number, source: RigidShapeSource): { x: number; y: number; angle: number } {
  const c = p.rc[i];
  const s = p.rs[i];
  return {
    x: p.x[i] - (c * source.centroidX - s * source.centroidY),
    y: p.y[i] - (s * source.centroidX + c * source.centroidY),
    angle: p.angle[i],
  };
}

/** Moves and turns the body (a teleport: velocities kept). */
export function setPose(p: ParticleStore, i: number, source: RigidShapeSource, x: number, y: number, angle: number): void {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const cx = x + c * source.centroidX - s * source.centroidY;
  const cy = y + s * source.centroidX + c * source.centroidY;
  p.px[i] += cx - p.x[i];
  p.py[i] += cy - p.y[i];
  p.x[i] = cx;
  p.y[i] = cy;
  p.pangle[i] += angle - p.angle[i];
  p.angle[i] = p.qangle[i] = angle;
  p.rc[i] = c;
  p.rs[i] = s;
}

/** An impulse (ix, iy) at world point (px, py): linear and angular velocity change at once. */
export function applyImpulseAt(p: ParticleStore, i: number, ix: number, iy: number, px: number, py: number): void {
  p.vx[i] += ix * p.invMass[i];
  p.vy[i] += iy * p.invMass[i];
  p.omega[i] += ((px - p.x[i]) * iy - (py - p.y[i]) * ix) * p.invInertia[i];
}

/** A force (fx, fy) at world point (px, py) for the next step: its torque about the centre of mass too. */
export function applyForceAt(p: ParticleStore, i: number, fx: number, fy: number, px: number, py: number): void {
  p.fx[i] += fx;
  p.fy[i] += fy;
  p.torque[i] += (px - p.x[i]) * fy - (py - p.y[i]) * fx;
}
