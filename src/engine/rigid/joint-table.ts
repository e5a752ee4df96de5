import { Table } from '../table.js';

/** What a joint holds. */
export const enum JointKind {
  /** The two anchor points coincide; the bodies turn freely about them (angle limits and a motor optional). */
  Revolute = 0,
  /** The anchor points coincide and the relative angle is fixed. */
  Weld = 1,
  /** B slides along an axis fixed in A (translation limits optional); no relative rotation. */
  Prismatic = 2,
  /** The anchors' distance stays within [lower, upper] (rigid when equal), softly with compliance and damping. */
  Distance = 3,
}

/**
 * Joints between two rows (rigid bodies or particles; b = −1 is the world, its anchor a world point), solved as XPBD
 * positional and angular constraints at the anchors (Müller et al. 2020, §3.3–3.4):
 *   point:    Δλ = (−c − α̃λ) / (w_A + w_B + α̃),   w = 1/m + (r × n)²/I,   α̃ = compliance / h²
 *   angle:    Δλ = (−e − α̃λ) / (1/I_A + 1/I_B + α̃)
 * A motor advances its target angle by h·speed each substep and caps |λ| at the torque limit times h².
 */
export class Joints extends Table {
  readonly columns = [
    'kind', 'a', 'b', 'rAx', 'rAy', 'rBx', 'rBy', 'compliance', 'damping', 'refAngle', 'lower', 'upper', 'limit', 'motor', 'motorSpeed',
    'maxMotorTorque', 'axisX', 'axisY', 'lambda', 'lambdaY', 'lambdaAngle', 'lambdaMotor', 'slot', 'bodyA', 'bodyB', 'collide',
  ] as const;
  kind = new Uint8Array(16);
  a = new Int32Array(16);
  b = new Int32Array(16);
  /** Anchors in each body's frame (B's in world coordinates when b = −1). */
  rAx = new Float64Array(16);
  rAy = new Float64Array(16);
  rBx = new Float64Array(16);
  rBy = new Float64Array(16);
  /** Positional compliance (inverse stiffness); 0 = rigid. */
  compliance = new Float64Array(16);
  /** Damping coefficient of a soft distance joint (force per unit of relative speed along it). */
  damping = new Float64Array(16);
  /** Rest angle of A relative to B (θA − θB; B's angle is 0 for the world) for weld, prismatic and revolute limits. */
  refAngle = new Float64Array(16);
  /** Limits: relative angle (revolute), translation along the axis (prismatic), length (distance). */
  lower = new Float64Array(16);
  upper = new Float64Array(16);
  limit = new Uint8Array(16);
  motor = new Uint8Array(16);
  motorSpeed = new Float64Array(16);
  maxMotorTorque = new Float64Array(16);
  /** Prismatic axis in A's frame (unit). */
  axisX = new Float64Array(16);
  axisY = new Float64Array(16);
  /** Multipliers of this substep: distance (or the point's x) and the point's y, angle and motor. */
  lambda = new Float64Array(16);
  lambdaY = new Float64Array(16);
  lambdaAngle = new Float64Array(16);
  lambdaMotor = new Float64Array(16);
  /** Constraint registry slot (the handle's), and the body slots of the two sides (−1: world). */
  slot = new Int32Array(16);
  bodyA = new Int32Array(16);
  bodyB = new Int32Array(16);
  /** 1: the two bodies still collide with each other (by default jointed bodies do not). */
  collide = new Uint8Array(16);

  beginSubstep(): void {
    this.lambda.fill(0, 0, this.count);
    this.lambdaY.fill(0, 0, this.count);
    this.lambdaAngle.fill(0, 0, this.count);
    this.lambdaMotor.fill(0, 0, this.count);
  }
}
