import { property } from 'lit/decorators.js';
import type { LinkDescription } from '../worker/protocol.js';
import type { Described } from './body-element.js';
import { Checker, numberAttribute, STIFFNESS } from './checks.js';
import { PhysicsLinkElement, type Resolve } from './link-element.js';

/**
 * A damped Hooke spring between body `a` and body `b` (element ids), attached to a rigid body at the anchor `x`, `y`
 * (or its centre) and to a body of particles at its particle nearest to the anchor (or to the other end).
 * `<physics-joint type="spring">` is the same with an end on each body (`x1`, `y1`, `x2`, `y2`) or on the world.
 *
 * @summary A spring between two bodies.
 * @fires physics-error - A missing id or a bad value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsSpringElement extends PhysicsLinkElement {
  /** Id of the first body element. */
  @property() a?: string;
  /** Id of the second body element. */
  @property() b?: string;
  /** Hooke constant (force per unit length, > 0, at least 1e-9: a spring of stiffness 0 pulls with no force). Default 50. */
  @property({ type: Number, converter: numberAttribute }) stiffness?: number;
  /** Damping (force per unit relative speed, >= 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) damping?: number;
  /** Rest length (>= 0); default the distance when the spring is made. */
  @property({ type: Number, converter: numberAttribute }) length?: number;

  describe(resolve: Resolve): Described<LinkDescription> {
    const check = new Checker(this);
    const a = this.resolveBody(check, 'a', this.a, resolve);
    const b = this.resolveBody(check, 'b', this.b, resolve);
    const stiffness = check.number('stiffness', this.stiffness, STIFFNESS)!;
    const damping = check.number('damping', this.damping, { min: 0, fallback: 1 });
    const length = check.number('length', this.length, { min: 0 });
    if (a === null || b === null) return { desc: null, problems: check.problems };
    if (a === b) {
      check.fail('b', this.b, 'must name a different body than a');
      return { desc: null, problems: check.problems };
    }
    return { desc: { type: 'spring', a, b, ...this.anchor(check), stiffness, damping, length }, problems: check.problems };
  }
}

if (!customElements.get('physics-spring')) customElements.define('physics-spring', PhysicsSpringElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-spring': PhysicsSpringElement;
  }
}
