import { property } from 'lit/decorators.js';
import type { LinkDescription } from '../worker/protocol.js';
import type { Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';
import { PhysicsLinkElement, type Resolve } from './link-element.js';

/**
 * Joins body `a` to body `b` (element ids) with a stick between their particles nearest to the anchor `x`, `y` (or
 * nearest to each other): a pin joint when the two particles coincide, a rigid link otherwise.
 *
 * @summary A joint between two bodies.
 * @fires physics-error - A missing id or a bad value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsJointElement extends PhysicsLinkElement {
  /** Id of the first body element. */
  @property() a?: string;
  /** Id of the second body element. */
  @property() b?: string;
  /** Rest length (>= 0); default the distance when the joint is made. */
  @property({ type: Number, converter: numberAttribute }) length?: number;
  /** Inverse stiffness (>= 0; 0 = rigid, default). */
  @property({ type: Number, converter: numberAttribute }) compliance?: number;

  describe(resolve: Resolve): Described<LinkDescription> {
    const check = new Checker(this);
    const a = this.resolveBody(check, 'a', this.a, resolve);
    const b = this.resolveBody(check, 'b', this.b, resolve);
    const length = check.number('length', this.length, { min: 0 });
    const compliance = check.number('compliance', this.compliance, { min: 0 });
    if (a === null || b === null) return { desc: null, problems: check.problems };
    if (a === b) {
      check.fail('b', this.b, 'must name a different body than a');
      return { desc: null, problems: check.problems };
    }
    return { desc: { type: 'joint', a, b, ...this.anchor(check), length, compliance }, problems: check.problems };
  }
}

if (!customElements.get('physics-joint')) customElements.define('physics-joint', PhysicsJointElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-joint': PhysicsJointElement;
  }
}
