// The base class of the body elements (<physics-box>, <physics-circle>, …). A body element draws nothing itself: it
// describes a body as plain data, and its <physics-scene> parent turns that into a body in the running engine.
import { LitElement, css, nothing } from 'lit';
import { property } from 'lit/decorators.js';
import type { BodyDescription } from '../engine/index.js';
import { finite, MIN_MASS, speed } from '../engine/validate.js';
import type { BodyStyle } from '../render/renderer.js';
import { Checker, numberAttribute, shownValue, toDegrees, type Problem } from './checks.js';
import type { ColourScheme } from './physics-scene/scheme.js';
import type { SceneHost, SceneParent } from './scene-host.js';

/**
 * x, y and angle read the live pose, so Lit's own check (new getter value vs old) would compare the pose with the old
 * declared value and miss a change whenever the body sits where it was declared. The setters compare the declared
 * values themselves and tell Lit the property changed.
 */
const DECLARED_CHANGED = { type: Number, converter: numberAttribute, hasChanged: () => true } as const;

export interface Described<T> {
  desc: T | null;
  problems: Problem[];
}

/**
 * A body inside a `<physics-scene>`. Attributes give the initial state; `x`, `y` and `angle` read the live pose
 * once the body is simulated. Changing an attribute (or property) updates the running simulation.
 */
export abstract class PhysicsBodyElement extends LitElement {
  static override styles = css`
    :host {
      display: none;
    }
  `;

  /** Total mass (> 0); default from `density` × area (a rope 1, a cloth 0.01 a particle, a ragdoll 70). */
  @property({ type: Number, converter: numberAttribute }) mass?: number;
  /**
   * Mass per unit area (> 0, default 1) when `mass` is not given: of a box, circle, polygon or soft body (a rope, cloth
   * or ragdoll reports it: give it `mass`).
   */
  @property({ type: Number, converter: numberAttribute }) density?: number;
  /** Immovable (floors, walls, obstacles). */
  @property({ type: Boolean, attribute: 'static' }) isStatic = false;
  /** Coulomb friction coefficient (>= 0). Default 0.6. */
  @property({ type: Number, converter: numberAttribute }) friction?: number;
  /**
   * Bounciness in [0, 1]: a hit leaves at this fraction of its speed (off bodies and the view's walls). Default 0.
   */
  @property({ type: Number, converter: numberAttribute }) restitution?: number;
  /** Fill colour (any CSS colour, or "none"). */
  @property() fill?: string;
  /** Outline colour (any CSS colour, or "none"). */
  @property() stroke?: string;

  /** Set by the owning scene. @internal */
  _scene: SceneHost | null = null;

  private _x?: number;
  private _y?: number;
  private _angle?: number;

  /**
   * Horizontal position in world units. Reads the live position while simulated; setting it moves the body, from
   * where it is for a shape or soft body, from its markup's other coordinates for a cloth (placed by its top-left
   * corner; its live x and y are its particles' mean) or a ragdoll (placed by its pelvis, which its live x and y read)
   * (a rope is placed by x1, y1, x2, y2 instead: its x and y only read its centroid).
   * @attr x
   */
  @property({ type: Number, converter: numberAttribute, noAccessor: true })
  get x(): number {
    const pose = this._scene?.poseOf(this);
    return pose ? pose[0] : (this._x ?? 0);
  }
  set x(value: number) {
    const old = this._x;
    if (Object.is(old, value)) return;
    this.keepLivePose('x');
    this._x = value;
    this.requestUpdate('x', old, DECLARED_CHANGED);
  }

  /**
   * Vertical position in world units (y grows downward). Live while simulated.
   * @attr y
   */
  @property({ type: Number, converter: numberAttribute, noAccessor: true })
  get y(): number {
    const pose = this._scene?.poseOf(this);
    return pose ? pose[1] : (this._y ?? 0);
  }
  set y(value: number) {
    const old = this._y;
    if (Object.is(old, value)) return;
    this.keepLivePose('y');
    this._y = value;
    this.requestUpdate('y', old, DECLARED_CHANGED);
  }

  /**
   * Rotation in degrees, clockwise on screen (as SVG's rotate()). Live while simulated. Ropes, cloths, soft bodies and
   * ragdolls are built unrotated (the value is still checked).
   * @attr angle
   */
  @property({ type: Number, converter: numberAttribute, noAccessor: true })
  get angle(): number {
    const pose = this._scene?.poseOf(this);
    return pose ? toDegrees(pose[2]) : (this._angle ?? 0);
  }
  set angle(value: number) {
    const old = this._angle;
    if (Object.is(old, value)) return;
    this.keepLivePose('angle');
    this._angle = value;
    this.requestUpdate('angle', old, DECLARED_CHANGED);
  }

  /** The parts of the pose set by property since the last update. */
  private poseSet = new Set<'x' | 'y' | 'angle'>();

  /**
   * Setting one part of a simulated body's pose moves it there from where it is: the other parts take their live
   * values, unless they too were set since the last update (`b.x += 1` put the body back at its markup y and angle).
   */
  private keepLivePose(part: 'x' | 'y' | 'angle'): void {
    const pose = this.poseIsPlacement ? this._scene?.poseOf(this) : null;
    if (pose && this.poseSet.size === 0) {
      if (part !== 'x') this._x = pose[0];
      if (part !== 'y') this._y = pose[1];
      if (part !== 'angle') this._angle = toDegrees(pose[2]);
    }
    this.poseSet.add(part);
  }

  /**
   * Whether the live pose is where x, y and angle place the body (a shape's centre, a soft body's), so that setting one
   * part keeps the others live. A cloth's x, y are its top-left corner, while its pose is its particles' mean (a
   * ragdoll's are its pelvis, which a fall moves with the rest): `cloth.y = 0.5` took the mean for x and rebuilt the cloth 2.75 to the right, into the wall.
   */
  protected get poseIsPlacement(): boolean {
    return true;
  }

  /** The declared (markup) position and angle, not the live pose. */
  protected get declared(): { x: unknown; y: unknown; angle: unknown } {
    return { x: this._x, y: this._y, angle: this._angle };
  }

  /**
   * Changes the body's velocity by impulse / mass (world units · mass / s). Like setVelocity(), it acts on the body as
   * the markup describes it now, also right after a change of its attributes or after the element was added. Throws a
   * TypeError for a value that is not a number, a RangeError for NaN or ±Infinity; an impulse that would give the body
   * a speed past ±1e9 units/s is refused by the engine with a `physics-error`.
   */
  applyImpulse(ix: number, iy: number): void {
    // Checked here, where the caller can catch it (the speed it adds, by the body's mass, is checked by the engine:
    // past ±1e9 units/s it is refused with a physics-error).
    this.host()?.applyImpulse(this, finite('ix', ix), finite('iy', iy));
  }

  /**
   * Sets the body's velocity (world units / s): a rigid body's, or every particle's of a body of particles. A change of
   * attributes made just before (in the same task) reaches the engine first, so the body it builds gets the velocity.
   * Throws a TypeError for a value that is not a number, a RangeError for NaN, ±Infinity or a speed past ±1e9.
   */
  setVelocity(vx: number, vy: number): void {
    this.host()?.setVelocity(this, speed('vx', vx), speed('vy', vy));
  }

  /** The scene running this body; asked of the parent scene when this element was added in the current task. */
  private host(): SceneHost | null {
    // The parent, or the one above it (a paragraph a CMS wrapped the line in: the scene decides, markup.ts isWrapper).
    const parent = this.parentElement as (Element & Partial<SceneParent>) | null;
    const scene = parent?._hostOf ? parent : (parent?.parentElement as (Element & Partial<SceneParent>) | null);
    return this._scene ?? scene?._hostOf?.(this) ?? null;
  }

  /** The body as plain data for the engine, or null with problems when the markup cannot make one. @internal */
  abstract describe(): Described<BodyDescription>;

  /** Default colours of this kind of body on a page of this colour scheme. */
  protected abstract defaultStyle(scheme: ColourScheme): { fill: string | null; stroke: string | null };

  /** Drawing style from `fill` / `stroke`, the defaults those of the page's colour scheme. @internal */
  styleOf(check: Checker = new Checker(this), scheme: ColourScheme = 'light'): BodyStyle {
    const d = this.defaultStyle(scheme);
    const fallbackFill = this.isStatic && d.fill ? '#8a8f98' : d.fill;
    return {
      fill: check.color('fill', this.fill, fallbackFill),
      stroke: check.color('stroke', this.stroke, d.stroke),
      lineWidth: 1.5,
    };
  }

  /** Checks pose attributes this kind of body does not use, so a bad value is reported all the same. */
  protected unused(check: Checker, ...names: ('x' | 'y' | 'angle')[]): void {
    const declared = this.declared;
    for (const name of names) check.number(name, declared[name]);
  }

  /** Whether the engine weighs this body when it is static too (a rigid body or frame: setBodyType may make it dynamic). */
  protected get staticHasMass(): boolean {
    return true;
  }

  /**
   * Mass, density, friction, restitution. With an `area`, a mass from density × area (density 1 when not given) must
   * leave each of the body's `particles` (1 for a rigid body) at least the engine's smallest mass: too small, it is
   * reported on `density` when written, else on `size` (the attribute that makes the area), and false returned: the
   * body is left out, as the engine would refuse it. A static body too, unless `staticHasMass` is false.
   */
  protected material(check: Checker, out: Record<string, unknown>, area: number | null, size = '', particles = 1): boolean {
    const mass = check.number('mass', this.mass, { positive: true, min: MIN_MASS });
    const density = check.number('density', this.density, { positive: true });
    if (area === null && density !== undefined) check.fail('density', this.density, `does not apply to <${this.localName}>: set mass (the whole body's)`);
    // The mass the engine makes from density (default 1) × area, when no mass is written.
    const total = area === null ? NaN : (density ?? 1) * area;
    if (mass !== undefined) out.mass = mass;
    else if (area !== null && (!this.isStatic || this.staticHasMass) && !(total >= MIN_MASS * particles && Number.isFinite(total))) {
      const blame = density !== undefined || !size ? 'density' : size;
      const each = particles > 1 ? `, ${total / particles} for each of its ${particles} particles` : '';
      const rule = Number.isFinite(total) ? `below the smallest, ${MIN_MASS}${particles > 1 ? ' each' : ''}: set mass, or a larger size` : 'not a finite number: set mass';
      check.fail(blame, shownValue(this, blame), `gives a mass of ${total} (density × area${each}), ${rule}`);
      return false;
    } else if (density !== undefined && area !== null && area > 0) out.mass = total;
    if (this.isStatic) out.static = true;
    const friction = check.number('friction', this.friction, { min: 0 });
    if (friction !== undefined) out.friction = friction;
    const restitution = check.number('restitution', this.restitution, { min: 0, max: 1 });
    if (restitution !== undefined) out.restitution = restitution;
    if (this.id) out.id = this.id;
    return true;
  }

  protected override render() {
    return nothing;
  }

  protected override updated(): void {
    this.poseSet.clear();
    this._scene?.childChanged(this);
  }
}
