import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { PhysicsBodyElement, type Described } from './body-element.js';
import { Checker, COMPLIANCE, numberAttribute } from './checks.js';
import { SCHEME_COLOURS, type ColourScheme } from './physics-scene/scheme.js';

/**
 * A stick-figure ragdoll whose pelvis is at `x`, `y`: bones as sticks, joints with angle limits.
 *
 * @summary A ragdoll.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsRagdollElement extends PhysicsBodyElement {
  /** Height from feet to the top of the head, in world units (> 0). Default 1.8. */
  @property({ type: Number, converter: numberAttribute }) height?: number;
  /** Compliance of the joint limits (0 to 1e9; 0 = hard stops, default). */
  @property({ type: Number, converter: numberAttribute, attribute: 'joint-compliance' }) jointCompliance?: number;

  /** Placed by its pelvis, not by its particles' mean (PhysicsBodyElement.poseIsPlacement). */
  protected override get poseIsPlacement(): boolean {
    return false;
  }

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const { x, y } = this.declared;
    const out: Record<string, unknown> = {
      type: 'ragdoll',
      x: check.number('x', x, { fallback: 0 }),
      y: check.number('y', y, { fallback: 0 }),
      height: check.number('height', this.height, { positive: true, fallback: 1.8 }),
    };
    const jc = check.number('joint-compliance', this.jointCompliance, COMPLIANCE);
    if (jc !== undefined) out.jointCompliance = jc;
    this.unused(check, 'angle');
    this.material(check, out, null);
    return { desc: out as unknown as BodyDescription, problems: check.problems };
  }

  protected defaultStyle(scheme: ColourScheme) {
    return { fill: null, stroke: SCHEME_COLOURS[scheme].ragdoll };
  }
}

if (!customElements.get('physics-ragdoll')) customElements.define('physics-ragdoll', PhysicsRagdollElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-ragdoll': PhysicsRagdollElement;
  }
}
