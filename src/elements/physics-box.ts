import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { PhysicsBodyElement, type Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';

/**
 * A rigid box: four corner particles braced by sticks. `x`, `y` is its centre.
 *
 * @summary A rigid rectangle.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsBoxElement extends PhysicsBodyElement {
  /** Width in world units (> 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) width?: number;
  /** Height in world units (> 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) height?: number;

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const width = check.number('width', this.width, { positive: true, fallback: 1 })!;
    const height = check.number('height', this.height, { positive: true, fallback: 1 })!;
    const desc = { type: 'box', width, height, ...this.common(check, width * height) } as BodyDescription;
    return { desc, problems: check.problems };
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
