// The base class of the shapes (<physics-box>, <physics-polygon>, <physics-circle>): rigid bodies by default, or
// frames of particles (`model="particles"`), placed at x, y and turned by `angle`, with a velocity, an angular velocity
// and, for rigid ones, kinematic motion.
import { property } from 'lit/decorators.js';
import { BODY_MODELS } from '../engine/index.js';
import { MAX_SPEED } from '../engine/validate.js';
import { PhysicsBodyElement } from './body-element.js';
import { Checker, numberAttribute, toRadians } from './checks.js';

export abstract class PhysicsShapeElement extends PhysicsBodyElement {
  /**
   * "rigid" (default): a rigid body that turns and rolls, with a moment of inertia from its shape. "particles": a
   * frame of particles held by sticks (a ball: one particle), as the thesis built it.
   */
  @property() model?: 'rigid' | 'particles';
  /**
   * Moved by its velocity and angular velocity alone (a moving platform, a turning drum): it pushes what it touches
   * and nothing pushes it. Rigid model only; not with `static`. Toggling it on a running scene keeps the body where it is.
   */
  @property({ type: Boolean }) kinematic = false;
  /**
   * Initial velocity "vx vy" in world units per second (y grows downward), each within ±1e9. Changing it sets the
   * body's velocity.
   */
  @property() velocity?: string;
  /**
   * Initial angular velocity in degrees per second, clockwise on screen (as `angle`), within ±5.7e10 (1e9 radians).
   * Changing it sets the body's angular velocity.
   */
  @property({ attribute: 'angular-velocity', type: Number, converter: numberAttribute }) angularVelocity?: number;

  /**
   * Position, angle, motion and material fields of a shape of this area (`size`: the attribute that makes it, which a
   * mass too small is reported on; `corners`: its particles in the particle model); null when it can have no mass.
   */
  protected common(check: Checker, area: number | null, size: string, corners: number): Record<string, unknown> | null {
    const out: Record<string, unknown> = {};
    const { x, y, angle } = this.declared;
    out.x = check.number('x', x, { fallback: 0 });
    out.y = check.number('y', y, { fallback: 0 });
    out.angle = toRadians(check.number('angle', angle, { fallback: 0 })!);
    const weighed = this.material(check, out, area, size, this.model === 'particles' ? corners : 1);
    this.motion(check, out);
    // No mass the engine can take: the body is left out (its problem reported).
    return weighed ? out : null;
  }

  private motion(check: Checker, out: Record<string, unknown>): void {
    const model = check.oneOf('model', this.model, BODY_MODELS, 'rigid');
    // Markup may hold any text (the type names the accepted values): blank is the default, as absent.
    if (this.model !== undefined && this.model !== null && (this.model as string) !== '') out.model = model;
    if (this.kinematic) {
      if (this.isStatic) check.fail('kinematic', '', 'cannot be combined with static (a body is one or the other)');
      else if (model !== 'rigid') check.fail('kinematic', '', 'needs model="rigid" (a frame of particles has no prescribed motion)');
      else out.kinematic = true;
    }
    const velocity = check.numbers('velocity', this.velocity);
    if (velocity && velocity.length !== 2) check.fail('velocity', this.velocity, `must be two numbers "vx vy", got ${velocity.length}`);
    else if (velocity && velocity.some((v) => Math.abs(v) > MAX_SPEED)) check.fail('velocity', this.velocity, 'must be within ±1e9 (world units per second)');
    else if (velocity) [out.vx, out.vy] = velocity;
    out.angularVelocity = check.rate('angular-velocity', this.angularVelocity);
  }
}
