import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import type { Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';
import { PhysicsShapeElement } from './shape-element.js';

/**
 * A ball: a rigid disc that spins and rolls (drawn with a radius line, so its turning shows), `x`, `y` at its centre;
 * with `model="particles"`, one particle colliding as a circle, which does not turn.
 *
 * @summary A ball.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsCircleElement extends PhysicsShapeElement {
  /** Radius in world units (> 0). Default 0.5. */
  @property({ type: Number, converter: numberAttribute }) radius?: number;

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    // A bad radius (0, -1, "abc", past 1e9) is reported and falls back to the default 0.5, as a box's width does.
    const radius = check.number('radius', this.radius, { positive: true, fallback: 0.5 })!;
    const common = this.common(check, Math.PI * radius ** 2, 'radius', 1);
    // Left out only when no mass can be made (a radius too small for density × area: reported on density or radius).
    return { desc: common && ({ type: 'circle', radius, ...common } as BodyDescription), problems: check.problems };
  }

  protected defaultStyle() {
    return { fill: '#e0823d', stroke: '#9c5220' };
  }
}

if (!customElements.get('physics-circle')) customElements.define('physics-circle', PhysicsCircleElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-circle': PhysicsCircleElement;
  }
}
