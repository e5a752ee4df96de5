import { property } from 'lit/decorators.js';
import { JOINT_TYPES } from '../engine/options.js';
import type { JointLink, LinkDescription } from '../worker/protocol.js';
import type { Described } from './body-element.js';
import { Checker, COMPLIANCE, numberAttribute, STIFFNESS, toRadians } from './checks.js';
import { PhysicsLinkElement, type Resolve } from './link-element.js';

/**
 * Joins body `a` to body `b` (element ids), or to the world when `b` is absent. Each end holds a rigid body at the
 * anchor point itself and a body of particles (rope, cloth, ragdoll, `model="particles"` shapes) at its particle
 * nearest to the anchor; without anchors, a rigid body at its centre and a body of particles at its particle nearest
 * to the other end. The `type`:
 *
 * - `distance` (default; the joint as it was before it had types): the ends keep their distance (`length`, default
 *   the distance when made; or between `lower` and `upper`), a stick between the anchor `x`, `y` of both ends, or
 *   between (`x1`, `y1`) on a and (`x2`, `y2`) on b;
 * - `revolute`: a hinge at the anchor `x`, `y`: a turns about it relative to b, between `lower-angle` and
 *   `upper-angle`, driven by a motor at `motor-speed` with at most `max-motor-torque`;
 * - `weld`: glued at the anchor (the relative angle fixed too); a body welded (without `compliance`) to the world or
 *   to a `static` or `kinematic` body holds as a static body does: what hits it does not move it;
 * - `prismatic`: b slides relative to a along `axis` (turning with a), between `lower` and `upper`, without turning;
 * - `spring`: a damped spring (`stiffness`, `damping`, rest `length`) between the ends, as for `distance`.
 *
 * `compliance` softens any type (0 = rigid, up to 1e9); jointed bodies do not collide unless `collide-connected`.
 *
 * @summary A joint between two bodies, or a body and the world.
 * @fires physics-error - A missing id or a bad value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsJointElement extends PhysicsLinkElement {
  /** "distance" (default), "revolute", "weld", "prismatic" or "spring". */
  @property() type?: 'revolute' | 'weld' | 'prismatic' | 'distance' | 'spring';
  /** Id of the first body element. */
  @property() a?: string;
  /** Id of the second body element; absent: the world. */
  @property() b?: string;
  /** Distance and spring: the end on `a` (with `y1`) and the end on `b` (with `x2`, `y2`), in world units. */
  @property({ type: Number, converter: numberAttribute }) x1?: number;
  @property({ type: Number, converter: numberAttribute }) y1?: number;
  @property({ type: Number, converter: numberAttribute }) x2?: number;
  @property({ type: Number, converter: numberAttribute }) y2?: number;
  /** Revolute: the lowest angle of a relative to b, in degrees from where they are when joined (clockwise on screen). */
  @property({ attribute: 'lower-angle', type: Number, converter: numberAttribute }) lowerAngle?: number;
  /** Revolute: the highest angle, in degrees (>= lower-angle). */
  @property({ attribute: 'upper-angle', type: Number, converter: numberAttribute }) upperAngle?: number;
  /** Revolute: a motor turning a relative to b at this speed, degrees per second (clockwise on screen), within ±5.7e10. */
  @property({ attribute: 'motor-speed', type: Number, converter: numberAttribute }) motorSpeed?: number;
  /** Revolute: the most torque the motor gives (>= 0; default unlimited once `motor-speed` is set). */
  @property({ attribute: 'max-motor-torque', type: Number, converter: numberAttribute }) maxMotorTorque?: number;
  /** Prismatic: the direction of sliding "dx dy" in world coordinates (default "1 0"). */
  @property() axis?: string;
  /** Prismatic: the least travel along the axis (world units); distance: the least length (>= 0). */
  @property({ type: Number, converter: numberAttribute }) lower?: number;
  /** Prismatic: the most travel along the axis; distance: the most length (>= lower). */
  @property({ type: Number, converter: numberAttribute }) upper?: number;
  /** Distance and spring: rest length (>= 0); default the distance when the joint is made. */
  @property({ type: Number, converter: numberAttribute }) length?: number;
  /** Spring: force per unit of stretch (> 0, at least 1e-9: a spring of stiffness 0 pulls with no force). Default 50. */
  @property({ type: Number, converter: numberAttribute }) stiffness?: number;
  /** Spring: force per unit of stretching speed (>= 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) damping?: number;
  /** Inverse stiffness (>= 0; 0 = rigid, default). */
  @property({ type: Number, converter: numberAttribute }) compliance?: number;
  /** The two joined bodies still collide with each other. */
  @property({ attribute: 'collide-connected', type: Boolean }) collideConnected = false;

  describe(resolve: Resolve): Described<LinkDescription> {
    const check = new Checker(this);
    const type = check.oneOf('type', this.type, JOINT_TYPES, 'distance');
    const a = this.resolveBody(check, 'a', this.a, resolve);
    const b = this.b === undefined || this.b === null ? undefined : this.resolveBody(check, 'b', this.b, resolve);
    const desc: JointLink = { type: 'joint', a: a ?? -1, b: b ?? undefined, ...this.anchor(check) };
    // Markup may hold any text (the type names the accepted values): blank is the default, as absent.
    if (this.type !== undefined && this.type !== null && (this.type as string) !== '') desc.joint = type;
    const first = this.point(check, 'x1', this.x1, 'y1', this.y1);
    if (first) [desc.x1, desc.y1] = first;
    const second = this.point(check, 'x2', this.x2, 'y2', this.y2);
    if (second) [desc.x2, desc.y2] = second;
    const lowerAngle = check.number('lower-angle', this.lowerAngle);
    const upperAngle = check.number('upper-angle', this.upperAngle);
    if (lowerAngle !== undefined && upperAngle !== undefined && upperAngle < lowerAngle) check.fail('upper-angle', this.upperAngle, `must be >= lower-angle (${lowerAngle})`);
    else {
      if (lowerAngle !== undefined) desc.lowerAngle = toRadians(lowerAngle);
      if (upperAngle !== undefined) desc.upperAngle = toRadians(upperAngle);
    }
    desc.motorSpeed = check.rate('motor-speed', this.motorSpeed);
    desc.maxMotorTorque = check.number('max-motor-torque', this.maxMotorTorque, { min: 0 });
    const axis = check.numbers('axis', this.axis);
    if (axis && (axis.length !== 2 || (axis[0] === 0 && axis[1] === 0))) check.fail('axis', this.axis, 'must be a direction "dx dy", not both 0');
    else if (axis) desc.axis = { x: axis[0], y: axis[1] };
    const lengths = type === 'distance' ? { min: 0 } : {};
    const lower = check.number('lower', this.lower, lengths);
    const upper = check.number('upper', this.upper, lengths);
    if (lower !== undefined && upper !== undefined && upper < lower) check.fail('upper', this.upper, `must be >= lower (${lower})`);
    else Object.assign(desc, { lower, upper });
    desc.length = check.number('length', this.length, { min: 0 });
    const stiffness = check.number('stiffness', this.stiffness, STIFFNESS);
    const damping = check.number('damping', this.damping, { min: 0, fallback: 1 });
    if (type === 'spring') Object.assign(desc, { stiffness, damping });
    desc.compliance = check.number('compliance', this.compliance, COMPLIANCE);
    if (this.collideConnected) desc.collideConnected = true;
    if (a === null || b === null) return { desc: null, problems: check.problems };
    if (a === b) {
      check.fail('b', this.b, 'must name a different body than a');
      return { desc: null, problems: check.problems };
    }
    return { desc, problems: check.problems };
  }
}

if (!customElements.get('physics-joint')) customElements.define('physics-joint', PhysicsJointElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-joint': PhysicsJointElement;
  }
}
