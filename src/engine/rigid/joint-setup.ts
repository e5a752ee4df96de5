// From JointOptions (world-space anchors where the bodies are now) to a joint row (anchors in each body's frame).
// Setup-time code: it checks every option and names the one at fault.
import type { ParticleStore } from '../particles.js';
import type { JointOptions, Vec2 } from '../options.js';
import { compliance, coordinate, finite, flag, nonNegative, oneOf, speed, stiffness } from '../validate.js';
import { JOINT_TYPES } from '../options.js';
import { JointKind } from './joint-table.js';

/** A joint's side: a row of the particle store (−1: the world). */
export interface JointSide {
  row: number;
  /** True for a rigid body (turns; its anchor may be off its centre); false for a particle or the world. */
  rigid: boolean;
}

/** The values of a Joints row. */
export type JointRow = Record<'kind' | 'a' | 'b' | 'rAx' | 'rAy' | 'rBx' | 'rBy' | 'compliance' | 'damping' | 'refAngle' | 'lower' | 'upper' | 'limit' | 'motor' | 'motorSpeed' | 'maxMotorTorque' | 'axisX' | 'axisY' | 'bodyA' | 'bodyB' | 'collide', number>;

/** A point {x, y}: an anchor (`check` coordinate: within ±1e9) or a direction (finite). */
function vec(name: string, v: unknown, check: (name: string, value: unknown) => number = coordinate): Vec2 {
  if (v == null || typeof v !== 'object') throw new TypeError(`${name} must be a point {x, y}, got ${String(v)}`);
  const p = v as Vec2;
  return { x: check(`${name}.x`, p.x), y: check(`${name}.y`, p.y) };
}

/** A side's anchor in its own frame: a rigid body's point turned back; a particle's is itself; the world's is the point. */
function local(p: ParticleStore, side: JointSide, at: Vec2): Vec2 {
  if (side.row < 0) return at;
  if (!side.rigid) return { x: 0, y: 0 };
  const dx = at.x - p.x[side.row];
  const dy = at.y - p.y[side.row];
  const c = p.rc[side.row];
  const s = p.rs[side.row];
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}

function centre(p: ParticleStore, side: JointSide, fallback: Vec2): Vec2 {
  return side.row < 0 ? fallback : { x: p.x[side.row], y: p.y[side.row] };
}

/** Checks `o` for sides A and B and returns the joint's row. */
export function jointRow(o: JointOptions, A: JointSide, B: JointSide, p: ParticleStore): JointRow {
  const type = oneOf('type', o.type, JOINT_TYPES);
  const angleA = A.row < 0 ? 0 : p.angle[A.row];
  const angleB = B.row < 0 ? 0 : p.angle[B.row];
  const row: JointRow = {
    kind: 0, a: A.row, b: B.row, rAx: 0, rAy: 0, rBx: 0, rBy: 0, compliance: compliance('compliance', o.compliance ?? 0), damping: 0,
    refAngle: angleA - angleB, lower: 0, upper: 0, limit: 0, motor: 0, motorSpeed: 0, maxMotorTorque: 0, axisX: 1, axisY: 0, bodyA: -1, bodyB: -1,
    collide: flag('collideConnected', o.collideConnected ?? false) ? 1 : 0,
  };
  const aCentre = centre(p, A, { x: 0, y: 0 });
  // A particle side is held at the particle itself: that is the natural default anchor.
  const anchor = o.anchor !== undefined ? vec('anchor', o.anchor) : !B.rigid && B.row >= 0 ? centre(p, B, aCentre) : aCentre;
  if (type === 'distance' || type === 'spring') {
    const at = o.anchorA !== undefined ? vec('anchorA', o.anchorA) : o.anchor !== undefined ? anchor : aCentre;
    const bt = o.anchorB !== undefined ? vec('anchorB', o.anchorB) : o.anchor !== undefined ? anchor : centre(p, B, aCentre);
    const ra = local(p, A, at);
    const rb = local(p, B, bt);
    Object.assign(row, { kind: JointKind.Distance, rAx: ra.x, rAy: ra.y, rBx: rb.x, rBy: rb.y });
    const length = o.length === undefined ? Math.sqrt((bt.x - at.x) ** 2 + (bt.y - at.y) ** 2) : coordinate('length', nonNegative('length', o.length));
    row.lower = o.lower === undefined ? length : coordinate('lower', nonNegative('lower', o.lower));
    // An upper bound moves nothing (the bodies only ever reach it from within): any, as Infinity is.
    row.upper = o.upper === undefined ? length : o.upper === Infinity ? Infinity : nonNegative('upper', o.upper);
    if (row.lower > row.upper) throw new RangeError(`lower (${row.lower}) must be <= upper (${row.upper})`);
    if (type === 'spring') {
      row.compliance = 1 / stiffness('stiffness', o.stiffness);
      row.damping = nonNegative('damping', o.damping ?? 0);
    }
    return row;
  }
  const ra = local(p, A, anchor);
  const rb = local(p, B, anchor);
  Object.assign(row, { rAx: ra.x, rAy: ra.y, rBx: rb.x, rBy: rb.y });
  if (type === 'weld') {
    row.kind = JointKind.Weld;
    return row;
  }
  if (type === 'prismatic') {
    row.kind = JointKind.Prismatic;
    const axis = o.axis === undefined ? { x: 1, y: 0 } : vec('axis', o.axis, finite);
    // A direction of huge or tiny components is scaled first: its square overflowed to ∞ (the axis became (0, 0) and
    // held nothing) or underflowed to 0 (refused as no direction).
    const big = Math.max(Math.abs(axis.x), Math.abs(axis.y));
    if (big > 1e150 || (big > 0 && big < 1e-150)) {
      axis.x /= big;
      axis.y /= big;
    }
    const len = Math.sqrt(axis.x * axis.x + axis.y * axis.y);
    if (!(len > 0)) throw new RangeError(`axis must be a non-zero direction, got ${JSON.stringify(o.axis)}`);
    // The axis in A's frame (it turns with A).
    const c = A.row < 0 ? 1 : p.rc[A.row];
    const s = A.row < 0 ? 0 : p.rs[A.row];
    row.axisX = (c * axis.x + s * axis.y) / len;
    row.axisY = (-s * axis.x + c * axis.y) / len;
    limits(row, o.lower, o.upper, 'lower', 'upper');
    return row;
  }
  row.kind = JointKind.Revolute;
  limits(row, o.lowerAngle, o.upperAngle, 'lowerAngle', 'upperAngle');
  if (o.maxMotorTorque !== undefined || o.motorSpeed !== undefined) {
    row.motor = 1;
    row.motorSpeed = speed('motorSpeed', o.motorSpeed ?? 0);
    row.maxMotorTorque = o.maxMotorTorque === undefined ? Infinity : nonNegative('maxMotorTorque', o.maxMotorTorque);
  }
  return row;
}

/** Both limits given: the joint is limited to [lower, upper] (bounds only: they move nothing, so any finite value). */
function limits(row: JointRow, lower: number | undefined, upper: number | undefined, lowerName: string, upperName: string): void {
  if (lower === undefined && upper === undefined) return;
  const lo = lower === undefined ? -Infinity : lower === -Infinity ? -Infinity : finite(lowerName, lower);
  const hi = upper === undefined ? Infinity : upper === Infinity ? Infinity : finite(upperName, upper);
  if (lo > hi) throw new RangeError(`${lowerName} (${lo}) must be <= ${upperName} (${hi})`);
  row.lower = lo;
  row.upper = hi;
  row.limit = 1;
}
