import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import type { Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';
import { PhysicsShapeElement } from './shape-element.js';

/**
 * A box: a rigid body with `x`, `y` at its centre, turned by `angle`; with `model="particles"`, four corner particles
 * braced by sticks.
 *
 * @summary A rigid rectangle.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsBoxElement extends PhysicsShapeElement {
  /** Width in world units (> 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) width?: number;
  /** Height in world units (> 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) height?: number;

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const width = check.number('width', this.width, { positive: true, fallback: 1 })!;
    const height = check.number('height', this.height, { positive: true, fallback: 1 })!;
    const common = this.common(check, width * height, width <= height ? 'width' : 'height', 4);
    return { desc: common && ({ type: 'box', width, height, ...common } as BodyDescription), problems: check.problems };
  }

  protected defaultStyle() {
    return { fill: '#3d7dd8', stroke: '#1f4f99' };
  }
}

if (!customElements.get('physics-box')) customElements.define('physics-box', PhysicsBoxElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-box': PhysicsBoxElement;
  }
}
