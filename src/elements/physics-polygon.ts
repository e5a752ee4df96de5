import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import type { Described } from './body-element.js';
import { Checker } from './checks.js';
import { PhysicsShapeElement } from './shape-element.js';

/**
 * A rigid polygon, convex or concave, from `points` in body coordinates (as SVG's `<polygon points>`), placed at
 * `x`, `y` and rotated by `angle`: a rigid body (a concave one collides as convex parts and is drawn as its outline);
 * with `model="particles"`, its outline's particles braced by sticks.
 *
 * @summary A rigid polygon.
 * @fires physics-error - A bad attribute value (detail: element, attribute, value, message); bubbles to the scene.
 */
export class PhysicsPolygonElement extends PhysicsShapeElement {
  /** Outline "x,y x,y x,y …" (at least 3 points, non-zero area). */
  @property() points?: string;

  describe(): Described<BodyDescription> {
    const check = new Checker(this);
    const nums = check.numbers('points', this.points ?? '');
    let points: { x: number; y: number }[] | null = null;
    if (nums && nums.length % 2 === 0 && nums.length >= 6) {
      points = [];
      for (let k = 0; k < nums.length; k += 2) points.push({ x: nums[k], y: nums[k + 1] });
      if (Math.abs(area(points)) < 1e-12) {
        check.fail('points', this.points, 'must enclose a non-zero area');
        points = null;
      }
    } else if (nums) {
      check.fail('points', this.points, `needs at least 3 points "x,y x,y x,y", got ${nums.length / 2}`);
    } else if (this.points === undefined) {
      check.fail('points', '', 'is required: "x,y x,y x,y …"');
    }
    const common = this.common(check, points ? Math.abs(area(points)) : null, 'points', points?.length ?? 3);
    if (!points || !common) return { desc: null, problems: check.problems };
    return { desc: { type: 'polygon', points, ...common } as BodyDescription, problems: check.problems };
  }

  protected defaultStyle() {
    return { fill: '#5aa469', stroke: '#336b3f' };
  }
}

function area(points: { x: number; y: number }[]): number {
  let s = 0;
  for (let k = 0; k < points.length; k++) {
    const a = points[k];
    const b = points[(k + 1) % points.length];
    s += a.x * b.y - b.x * a.y;
  }
  return s / 2;
}

if (!customElements.get('physics-polygon')) customElements.define('physics-polygon', PhysicsPolygonElement);

declare global {
  interface HTMLElementTagNameMap {
    'physics-polygon': PhysicsPolygonElement;
  }
}
