import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { PhysicsBodyElement, type Described } from './body-element.js';
import { Checker, COMPLIANCE, numberAttribute, type ClothPinsAttribute } from './checks.js';

/**
 * A cloth of `columns` × `rows` particles `spacing` apart, its top-left corner at `x`, `y`, hanging from `pins`.
 *
 * @summary A cloth.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsClothElement extends PhysicsBodyElement {
  /** Particles across (whole number 2..4096). Default 12. */
  @property({ type: Number, converter: numberAttribute }) columns?: number;
  /** Particles down (whole number 2..4096). Default 10. */
  @property({ type: Number, converter: numberAttribute }) rows?: number;
  /** Rest distance between neighbours in world units (> 0). Default 0.3. */
  @property({ type: Number, converter: numberAttribute }) spacing?: number;
  /** Pinned top-row particles: "top" (default), "corners", "none" or column indices "0 5 11". */
  @property() pins?: ClothPinsAttribute;
  /** Compliance of the structural links (0 to 1e9; 0 = inextensible, default). */
  @property({ type: Number, converter: numberAttribute }) compliance?: number;
  /** Compliance of diagonal shear links (0 to 1e9; none when absent). */
  @property({ type: Number, converter: numberAttribute }) shear?: number;
  /** Compliance of bend links two particles apart (0 to 1e9; none when absent). */
  @property({ type: Number, converter: numberAttribute }) bend?: number;
  /** Tearing: a link stretched past its rest length by this fraction breaks for good (> 0, e.g. 0.3); off when absent. */
  @property({ type: Number, converter: numberAttribute }) tear?: number;
  /** Collides with other bodies (its particles as small circles). */
  @property({ type: Boolean }) collide = false;

  /** Placed by its top-left corner, not by its particles' mean (PhysicsBodyElement.poseIsPlacement). */
  protected override get poseIsPlacement(): boolean {
    return false;
  }

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const { x, y } = this.declared;
    const origin = { x: check.number('x', x, { fallback: 0 })!, y: check.number('y', y, { fallback: 0 })! };
    const columns = check.number('columns', this.columns, { integer: true, min: 2, max: 4096, fallback: 12 })!;
    const rows = check.number('rows', this.rows, { integer: true, min: 2, max: 4096, fallback: 10 })!;
    const spacing = check.number('spacing', this.spacing, { positive: true, fallback: 0.3 })!;
    const pins = check.pins(this.pins, columns) ?? 'top';
    const out: Record<string, unknown> = { type: 'cloth', origin, columns, rows, spacing, pins, collide: this.collide, radius: this.collide ? spacing * 0.3 : 0 };
    const compliance = check.number('compliance', this.compliance, COMPLIANCE);
    if (compliance !== undefined) out.structural = compliance;
    const shear = check.number('shear', this.shear, COMPLIANCE);
    if (shear !== undefined) out.shear = shear;
    const bend = check.number('bend', this.bend, COMPLIANCE);
    if (bend !== undefined) out.bend = bend;
    const tear = check.number('tear', this.tear, { positive: true });
    if (tear !== undefined) out.tear = tear;
    this.unused(check, 'angle');
    this.material(check, out, null);
    return { desc: out as unknown as BodyDescription, problems: check.problems };
  }

  protected defaultStyle() {
    return { fill: '#9cc3ec', stroke: '#2f6fb5' };
  }
}

if (!customElements.get('physics-cloth')) customElements.define('physics-cloth', PhysicsClothElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-cloth': PhysicsClothElement;
  }
}
