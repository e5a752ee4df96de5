// Attribute checks for the elements: a bad value is recorded as a problem naming the attribute and the value as
// written in the markup, and a fallback is used, so bad markup never throws.
import { MAX_COMPLIANCE, MAX_SPEED, MAX_WORLD_COORDINATE, nearestName } from '../engine/validate.js';

/**
 * A compliance attribute, as the engine takes it (from 0, rigid, to MAX_COMPLIANCE): checked here so that a value
 * out of range is a markup problem that leaves once fixed, like any other.
 */
export const COMPLIANCE: NumberRule = { min: 0, max: MAX_COMPLIANCE };

/**
 * A spring's stiffness, of `<physics-spring>` and `<physics-joint type="spring">` alike: > 0, and at least 1e-9 (the
 * engine's compliance 1/stiffness at most 1e9). 0 is refused: a spring of stiffness 0 pulls with no force.
 */
export const STIFFNESS: NumberRule = { positive: true, min: 1 / MAX_COMPLIANCE, fallback: 50 };

/** The engine's range for a gravity component (units/s²). */
export const GRAVITY_LIMIT = MAX_SPEED;

/** A rejected attribute value. */
export interface Problem {
  attribute: string;
  value: string;
  message: string;
}

export interface NumberRule {
  fallback?: number;
  /** Smallest allowed value (inclusive). */
  min?: number;
  max?: number;
  /** Must be > 0. */
  positive?: boolean;
  integer?: boolean;
  /**
   * A position, length or size in world units: within ±1e9 (the engine's MAX_WORLD_COORDINATE). Default: true for the
   * attribute names in COORDINATES.
   */
  coordinate?: boolean;
}

/**
 * Number attributes that are positions, lengths or sizes in world units, on every element: body and pin positions,
 * rope ends, the scene's and a box's width and height, radii, cloth spacing, link lengths and a link's lower limit (a
 * distance joint's shortest length). A point list (`points`) is checked the same way. Upper limits are not: they move
 * nothing.
 */
export const COORDINATES: ReadonlySet<string> = new Set(['x', 'y', 'x1', 'y1', 'x2', 'y2', 'width', 'height', 'radius', 'spacing', 'length', 'lower', 'points']);

const OUT_OF_RANGE = 'must be within ±1e9 (world units)';
const outOfRange = (n: number) => n > MAX_WORLD_COORDINATE || n < -MAX_WORLD_COORDINATE;

/**
 * Lit converter for number attributes: a blank value reads as NaN, which the checks report. Lit's own converter gives
 * Number("") = 0, a valid number, and no change at all where the property already is 0.
 */
export const numberAttribute = {
  fromAttribute: (value: string | null): number | null => (value === null ? null : value.trim() === '' ? NaN : Number(value)),
  toAttribute: (value: unknown): unknown => value,
};

/** Lit's declared properties of an element's class, by property name. */
type Declared = Map<PropertyKey, { attribute?: string | boolean; type?: unknown; converter?: unknown }>;

/** The property behind `attribute` on this element (Lit's declaration), or undefined. */
export function propertyOfAttribute(element: Element, attribute: string): PropertyKey | undefined {
  return declaredProperty(element, attribute)?.name;
}

/** The property name behind `attribute` on this element (Lit's declaration), or undefined. */
function declaredProperty(element: Element, attribute: string): { name: PropertyKey; type?: unknown; converter?: unknown } | undefined {
  const declared = (element.constructor as { elementProperties?: Declared }).elementProperties;
  for (const [name, o] of declared ?? []) {
    if ((typeof o.attribute === 'string' ? o.attribute : String(name).toLowerCase()) === attribute) return { name, type: o.type, converter: o.converter };
  }
  return undefined;
}

/** Whether the element may read `attribute` as a number: all but plain string attributes (Lit's default: no type, no converter). */
function numberTyped(element: Element, attribute: string): boolean {
  const p = declaredProperty(element, attribute);
  return !(p && (p.type === String || (p.type === undefined && p.converter === undefined)));
}

/**
 * The value of `attribute` as a message shows it: the text written, or what a script set the property to since
 * (`box.angle = 1e308` after `angle="0"`); '' when neither is there.
 */
export function shownValue(element: Element, attribute: string): string {
  const p = declaredProperty(element, attribute);
  const value = p ? (element as unknown as Record<PropertyKey, unknown>)[p.name] : undefined;
  if (element.getAttribute(attribute) === null && (value === undefined || value === null)) return '';
  return new Checker(element).raw(attribute, value);
}

/**
 * The `pins` attribute of `<cloth-sim>` and `<physics-cloth>` as TypeScript sees it: "top", "corners", "none", or
 * column numbers separated by spaces or commas ("0 8 16 23", "0,23"). Only the type narrows: markup with another value
 * still loads and is reported (`physics-error`).
 */
export type ClothPinsAttribute = 'top' | 'corners' | 'none' | `${number}` | `${number} ${string}` | `${number},${string}`;

export class Checker {
  readonly problems: Problem[] = [];

  constructor(private readonly element: Element) {}

  /**
   * The value as written: the attribute's text when it is what the property holds (or is blank), else the property
   * value a script set since (`box.x = NaN` after `x="4"`: the NaN is what was refused, not the 4).
   */
  raw(attribute: string, value: unknown): string {
    const text = this.element.getAttribute(attribute);
    if (text === null) return String(value);
    if (text.trim() === '' || value === undefined || value === null) return text;
    // As the property reads its attribute: a number attribute "abc" reads NaN (the text is what was refused), a
    // string attribute such as `fill` does not (a NaN there was set by a script).
    const read = typeof value === 'number' && numberTyped(this.element, attribute) ? numberAttribute.fromAttribute(text) : text;
    return Object.is(read, value) ? text : String(value);
  }

  fail(attribute: string, value: unknown, message: string): void {
    this.problems.push({ attribute, value: this.raw(attribute, value), message });
  }

  number(attribute: string, value: unknown, rule: NumberRule = {}): number | undefined {
    // An attribute written empty (or blank) is not a number (numberAttribute reads it as NaN, Lit's own converter as 0).
    if ((value === 0 || value === '' || value === null || Number.isNaN(value)) && this.element.getAttribute(attribute)?.trim() === '') {
      this.fail(attribute, value, 'must be a number');
      return rule.fallback;
    }
    if (value === undefined || value === null || value === '') return rule.fallback;
    // A Symbol has no number (Number() would throw).
    const n = typeof value === 'number' ? value : typeof value === 'symbol' ? NaN : Number(value);
    let problem = '';
    if (!Number.isFinite(n)) problem = 'must be a finite number';
    else if (rule.integer && (!Number.isInteger(n) || n < (rule.min ?? -Infinity) || n > (rule.max ?? Infinity))) problem = `must be ${wholeNumber(rule)}`;
    else if (rule.positive && !(n > 0)) problem = 'must be a number > 0';
    else if (rule.min !== undefined && n < rule.min) problem = `must be >= ${rule.min}`;
    else if (rule.max !== undefined && n > rule.max) problem = `must be <= ${rule.max}`;
    else if ((rule.coordinate ?? COORDINATES.has(attribute)) && outOfRange(n)) problem = OUT_OF_RANGE;
    if (problem) {
      this.fail(attribute, value, problem);
      return rule.fallback;
    }
    return n;
  }

  /**
   * A turning rate in degrees per second, in radians per second: within the engine's ±1e9 rad/s (±5.7e10 °/s). A rate
   * is not reduced modulo 360 as an angle is (toRadians): 720 °/s is not 0.
   */
  rate(attribute: string, value: unknown): number | undefined {
    // No number (absent or reported): NaN, neither kept nor reported again.
    const rad = (this.number(attribute, value)! * Math.PI) / 180;
    if (Math.abs(rad) <= MAX_SPEED) return rad;
    if (rad) this.fail(attribute, value, 'must be within ±5.7e10 (degrees per second: 1e9 radians)');
  }

  oneOf<T extends string>(attribute: string, value: unknown, options: readonly T[], fallback: T): T {
    if (value === undefined || value === null || value === '') return fallback;
    if ((options as readonly unknown[]).includes(value)) return value as T;
    this.fail(attribute, value, `must be one of ${options.join(', ')}`);
    return fallback;
  }

  /** A list of numbers separated by spaces or commas ("0 9.81", "1,2 3,4"). */
  numbers(attribute: string, value: unknown): number[] | null {
    if (value === undefined || value === null) return null;
    const parts = String(value).trim().split(/[\s,]+/).filter(Boolean);
    const out = parts.map(Number);
    if (out.length === 0 || out.some((n) => !Number.isFinite(n))) {
      this.fail(attribute, value, 'must be a list of numbers');
      return null;
    }
    if (COORDINATES.has(attribute) && out.some(outOfRange)) {
      this.fail(attribute, value, `coordinates ${OUT_OF_RANGE}`);
      return null;
    }
    return out;
  }

  /**
   * A cloth's pinned top-row particles: "top", "corners", "none", or column numbers from 0 to columns − 1 separated by
   * spaces or commas. Null when absent or not one of those (reported with every form it may take).
   */
  pins(value: string | null | undefined, columns: number): 'top' | 'corners' | 'none' | number[] | null {
    if (value === undefined || value === null) return null;
    const v = value.trim();
    if (v === 'top' || v === 'corners' || v === 'none') return v;
    const list = v.split(/[\s,]+/).filter(Boolean).map(Number);
    if (list.length > 0 && list.every((c) => Number.isInteger(c) && c >= 0 && c < columns)) return list;
    this.fail('pins', value, `must be top, corners, none or column numbers from 0 to ${columns - 1}`);
    return null;
  }

  /** A CSS colour, "none", or undefined. */
  color(attribute: string, value: unknown, fallback: string | null): string | null {
    if (value === undefined || value === null || value === '') return fallback;
    const v = String(value).trim();
    if (v === 'none') return null;
    if (typeof CSS !== 'undefined' && CSS.supports && !CSS.supports('color', v)) {
      this.fail(attribute, value, 'must be a CSS colour or "none"');
      return fallback;
    }
    return v;
  }

  /**
   * A colour a preset passes on to the bodies it makes: the colour, "none" (that part not drawn), or undefined when
   * absent or bad (reported): the body's own default.
   */
  colorOrNone(attribute: string, value: unknown): string | undefined {
    const colour = this.color(attribute, value, null);
    if (colour !== null) return colour;
    return typeof value === 'string' && value.trim() === 'none' ? 'none' : undefined;
  }
}

/** Characters of a value shown in warnings and the error box; the `physics-error` event carries the whole value. */
const SHOWN = 120;

/**
 * A value as shown in a message: control and format characters (bidi overrides, zero-width marks) written as \u
 * escapes, and long values cut, so a hostile value can neither reorder the message nor cost seconds of text layout.
 */
export function displayValue(value: string): string {
  let v = value.length > SHOWN ? value.slice(0, SHOWN) : value;
  if (/[\ud800-\udbff]$/.test(v)) v = v.slice(0, -1);
  v = v.replace(/[\p{Cc}\p{Cf}\u2028\u2029]/gu, (c) => {
    const code = c.codePointAt(0)!;
    return code > 0xffff ? `\\u{${code.toString(16)}}` : `\\u${code.toString(16).padStart(4, '0')}`;
  });
  return value.length > SHOWN ? `${v}… (${value.length} characters)` : v;
}

/** `<physics-box id="a">` for messages. */
export function describeElement(el: Element): string {
  const id = el.getAttribute('id');
  return `<${el.localName}${id ? ` id="${displayValue(id)}"` : ''}>`;
}

/** An angle in degrees (markup) → radians (engine); a rate is Checker.rate's. */
// (deg · π) / 180 as it always was (the golden hashes hold its doubles). Any finite angle is a pose: past 1e9 degrees
// it is taken modulo 360 (exact), which the engine's ±1e9 rad takes and a product past the largest double does not
// overflow (1e308 degrees).
export const toRadians = (deg: number): number => ((Math.abs(deg) > 1e9 ? deg % 360 : deg) * Math.PI) / 180;
export const toDegrees = (rad: number): number => (rad * 180) / Math.PI;

/** Attributes any element may carry (HTML's global attributes that a page puts on an embed). */
const GLOBAL_ATTRIBUTES = new Set([
  'id', 'class', 'style', 'slot', 'title', 'hidden', 'lang', 'dir', 'tabindex', 'role', 'part', 'exportparts', 'is',
  'nonce', 'draggable', 'translate', 'inert', 'popover', 'autofocus', 'accesskey', 'contenteditable', 'spellcheck',
  'enterkeyhint', 'inputmode', 'autocapitalize', 'itemprop', 'itemscope', 'itemtype', 'itemid', 'itemref',
]);

/**
 * The attributes of `el` that look like misspellings of its own (`radus` for `radius`): not one of its attributes, not
 * a global, `data-`, `aria-` or event attribute, and within two edits of one of its attributes (one for names of four
 * letters or fewer; none under three, where every short name is near another). Other unknown attributes are the
 * page's own and are left alone. Each is reported with the attribute it most likely meant.
 */
export function misspeltAttributes(el: Element): Problem[] {
  const known: readonly string[] = (el.constructor as { observedAttributes?: string[] }).observedAttributes ?? [];
  const problems: Problem[] = [];
  for (const { name, value } of el.attributes) {
    if (known.includes(name) || GLOBAL_ATTRIBUTES.has(name) || /^(data-|aria-|on)/.test(name) || name.length < 3) continue;
    const { nearest, distance } = nearestName(name, known);
    if (distance <= (name.length <= 4 ? 1 : 2)) problems.push({ attribute: name, value, message: `unknown attribute, ignored: did you mean ${nearest}?` });
  }
  return problems;
}

/**
 * "a whole number from 2 to 4096" (or ">= 0", "<= 9"): an integer rule's whole range in one message, so 1.5 for a
 * minimum of 2 is not told to be ">= 2".
 */
function wholeNumber(rule: NumberRule): string {
  if (rule.min !== undefined && rule.max !== undefined) return `a whole number from ${rule.min} to ${rule.max}`;
  if (rule.min !== undefined) return `a whole number >= ${rule.min}`;
  if (rule.max !== undefined) return `a whole number <= ${rule.max}`;
  return 'a whole number';
}
