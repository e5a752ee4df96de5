// The base class of elements that link bodies by id (<physics-joint>, <physics-spring>, <physics-pin>).
import { LitElement, css, nothing } from 'lit';
import { property } from 'lit/decorators.js';
import type { LinkDescription } from '../worker/protocol.js';
import type { Described } from './body-element.js';
import { Checker, numberAttribute } from './checks.js';
import type { SceneHost } from './scene-host.js';

/** Finds the body key of an element id in the scene, or null. */
export type Resolve = (id: string) => number | null;

export abstract class PhysicsLinkElement extends LitElement {
  static override styles = css`
    :host {
      display: none;
    }
  `;

  /**
   * Anchor point in world units (with `y`; one without the other is no anchor): a rigid body is held at this point, a
   * body of particles at its particle nearest to it. Without one, a rigid body at its centre, a body of particles at
   * its particle nearest to the other (a `<physics-pin>` needs both: they are the world point it pins to).
   */
  @property({ type: Number, converter: numberAttribute }) x?: number;
  /** Anchor point's y (with `x`). */
  @property({ type: Number, converter: numberAttribute }) y?: number;

  /** Set by the owning scene. @internal */
  _scene: SceneHost | null = null;

  /** @internal */
  abstract describe(resolve: Resolve): Described<LinkDescription>;

  /** Resolves an id attribute to a body key, recording a problem when it names no body of the scene. */
  protected resolveBody(check: Checker, attribute: string, id: string | undefined, resolve: Resolve): number | null {
    if (!id) {
      check.fail(attribute, id ?? '', 'must name the id of a body element in the same scene');
      return null;
    }
    const key = resolve(id);
    // The message does not repeat the id: the warning shows it (escaped and cut) as the attribute's value.
    if (key === null) check.fail(attribute, id, 'names no body element of this scene');
    return key;
  }

  protected anchor(check: Checker): { x?: number; y?: number } {
    const p = this.point(check, 'x', this.x, 'y', this.y);
    return p ? { x: p[0], y: p[1] } : {};
  }

  /** A point from two coordinate attributes, each checked; one without the other is no point. */
  protected point(check: Checker, xName: string, x: unknown, yName: string, y: unknown): [number, number] | null {
    const px = check.number(xName, x);
    const py = check.number(yName, y);
    return px !== undefined && py !== undefined ? [px, py] : null;
  }

  protected override render() {
    return nothing;
  }

  protected override updated(): void {
    this._scene?.childChanged(this);
  }
}
