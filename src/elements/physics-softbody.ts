import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { PhysicsBodyElement, type Described } from './body-element.js';
import { Checker, COMPLIANCE, numberAttribute } from './checks.js';
import { MAX_PRESSURE } from '../engine/validate.js';

/**
 * A deformable ring centred at `x`, `y`: a pressurised loop (default) or a mass–spring wheel.
 *
 * @summary A soft body.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsSoftbodyElement extends PhysicsBodyElement {
  /** Radius in world units (> 0). Default 1. */
  @property({ type: Number, converter: numberAttribute }) radius?: number;
  /** Particles on the ring (whole number 3..4096). Default 16. */
  @property({ type: Number, converter: numberAttribute }) segments?: number;
  /** Rest area as a multiple of the drawn area (pressure model, > 0, at most 1e6). Default 1. */
  @property({ type: Number, converter: numberAttribute }) pressure?: number;
  /** "pressure" (default) or "springs". */
  @property() model?: 'pressure' | 'springs';
  /** Compliance of the ring's links (0 to 1e9). Default 0.0001. */
  @property({ type: Number, converter: numberAttribute }) compliance?: number;

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const { x, y } = this.declared;
    const center = { x: check.number('x', x, { fallback: 0 })!, y: check.number('y', y, { fallback: 0 })! };
    const radius = check.number('radius', this.radius, { positive: true, fallback: 1 })!;
    const segments = check.number('segments', this.segments, { integer: true, min: 3, max: 4096, fallback: 16 })!;
    const pressure = check.number('pressure', this.pressure, { positive: true, max: MAX_PRESSURE, fallback: 1 })!;
    const model = check.oneOf('model', this.model, ['pressure', 'springs'] as const, 'pressure');
    const out: Record<string, unknown> = { type: 'softbody', center, radius, segments, pressure, model };
    const compliance = check.number('compliance', this.compliance, COMPLIANCE);
    if (compliance !== undefined) out.compliance = compliance;
    this.unused(check, 'angle');
    // The engine spreads the mass over the ring's particles (the hub of the springs model takes a share as big).
    const weighed = this.material(check, out, Math.PI * radius * radius, 'radius', segments);
    if (!weighed || check.problems.some((p) => p.attribute === 'radius')) return { desc: null, problems: check.problems };
    return { desc: out as unknown as BodyDescription, problems: check.problems };
  }

  /** A static ring's particles are pinned: the engine gives them no mass to check. */
  protected override get staticHasMass(): boolean {
    return false;
  }

  protected defaultStyle() {
    return { fill: '#d45d79', stroke: '#8f2f47' };
  }
}

if (!customElements.get('physics-softbody')) customElements.define('physics-softbody', PhysicsSoftbodyElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-softbody': PhysicsSoftbodyElement;
  }
}
