import { property } from 'lit/decorators.js';
import type { LinkDescription } from '../worker/protocol.js';
import type { Described } from './body-element.js';
import { Checker, COMPLIANCE, numberAttribute } from './checks.js';
import { PhysicsLinkElement, type Resolve } from './link-element.js';

/**
 * Pins a body (element id in `body`) to the world point `x`, `y`: a rigid body at its point there, about which it
 * can still turn (a hinge to the world); a body of particles by its particle nearest to the point (or the
 * `particle`-th of the body; of a rigid body, 0: its centre), held rigidly or, with `compliance`, like a zero-length
 * spring.
 *
 * @summary Pins a body to a point.
 * @fires physics-error - A missing id or a bad value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsPinElement extends PhysicsLinkElement {
  /** Id of the body element to pin. */
  @property() body?: string;
  /** Index of the particle within the body (whole number >= 0, less than the body's particle count; default: the one nearest to x, y). */
  @property({ type: Number, converter: numberAttribute }) particle?: number;
  /** Compliance (0 to 1e9): 0 (default) holds exactly; more pulls like a zero-length spring. */
  @property({ type: Number, converter: numberAttribute }) compliance?: number;

  describe(resolve: Resolve): Described<LinkDescription> {
    const check = new Checker(this);
    const a = this.resolveBody(check, 'body', this.body, resolve);
    const x = check.number('x', this.x);
    const y = check.number('y', this.y);
    if (x === undefined && this.x === undefined) check.fail('x', '', 'is required');
    if (y === undefined && this.y === undefined) check.fail('y', '', 'is required');
    const particle = check.number('particle', this.particle, { integer: true, min: 0 });
    const compliance = check.number('compliance', this.compliance, COMPLIANCE);
    if (a === null || x === undefined || y === undefined) return { desc: null, problems: check.problems };
    return { desc: { type: 'pin', a, x, y, particle, compliance }, problems: check.problems };
  }
}

if (!customElements.get('physics-pin')) customElements.define('physics-pin', PhysicsPinElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-pin': PhysicsPinElement;
  }
}
