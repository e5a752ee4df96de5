import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { PhysicsBodyElement, type Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';
import { SCHEME_COLOURS, type ColourScheme } from './physics-scene/scheme.js';

/**
 * A rope (or, with `rigid`, a chain of sticks) from (`x1`, `y1`) to (`x2`, `y2`). `x`, `y` read its live centroid.
 *
 * @summary A rope or chain.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsRopeElement extends PhysicsBodyElement {
  /** The first end's x (pinned with the default `pin="start"`). Default 0. */
  @property({ type: Number, converter: numberAttribute }) x1?: number;
  /** The first end's y. Default 0. */
  @property({ type: Number, converter: numberAttribute }) y1?: number;
  /** The second end's x. Default x1 + 4. */
  @property({ type: Number, converter: numberAttribute }) x2?: number;
  /** The second end's y. Default y1. */
  @property({ type: Number, converter: numberAttribute }) y2?: number;
  /** Number of links (whole number 1..10000). Default 20. */
  @property({ type: Number, converter: numberAttribute }) segments?: number;
  /** Link length as a multiple of the straight distance / segments (> 0); above 1 the rope sags. Default 1. */
  @property({ type: Number, converter: numberAttribute }) slack?: number;
  /** Which ends are pinned where they start: "start" (default), "end", "both" or "none". */
  @property() pin?: 'start' | 'end' | 'both' | 'none';
  /** Thickness as a radius in world units (>= 0). Default 0.05. */
  @property({ type: Number, converter: numberAttribute }) radius?: number;
  /** Links are rigid sticks (a chain) instead of slack rope links. */
  @property({ type: Boolean }) rigid = false;
  /** Collides with other bodies (as circles of `radius`). */
  @property({ type: Boolean }) collide = false;

  /** Placed by its ends (x1, y1, x2, y2), not by its particles' mean (PhysicsBodyElement.poseIsPlacement). */
  protected override get poseIsPlacement(): boolean {
    return false;
  }

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const from = { x: check.number('x1', this.x1, { fallback: 0 })!, y: check.number('y1', this.y1, { fallback: 0 })! };
    const to = { x: check.number('x2', this.x2, { fallback: from.x + 4 })!, y: check.number('y2', this.y2, { fallback: from.y })! };
    const segments = check.number('segments', this.segments, { integer: true, min: 1, max: 10000, fallback: 20 })!;
    const slack = check.number('slack', this.slack, { positive: true, fallback: 1 })!;
    const pin = check.oneOf('pin', this.pin, ['start', 'end', 'both', 'none'] as const, 'start');
    const radius = check.number('radius', this.radius, { min: 0, fallback: 0.05 })!;
    const out: Record<string, unknown> = { type: 'rope', from, to, segments, slack, radius, ropeLike: !this.rigid, collide: this.collide };
    out.pinStart = pin === 'start' || pin === 'both';
    out.pinEnd = pin === 'end' || pin === 'both';
    this.unused(check, 'x', 'y', 'angle');
    this.material(check, out, null);
    return { desc: out as unknown as BodyDescription, problems: check.problems };
  }

  protected defaultStyle(scheme: ColourScheme) {
    return { fill: null, stroke: SCHEME_COLOURS[scheme].rope };
  }
}

if (!customElements.get('physics-rope')) customElements.define('physics-rope', PhysicsRopeElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-rope': PhysicsRopeElement;
  }
}
