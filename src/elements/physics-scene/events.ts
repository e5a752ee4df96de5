// The events the elements fire, with their details. Every `physics-*` event bubbles and is composed (it leaves shadow
// roots), and HTMLElementEventMap (and the document's and window's maps) name its detail, so
// `scene.addEventListener('physics-error', (e) => e.detail.attribute)` is typed without a cast.
import type { Transport } from '../../worker/protocol.js';

/** Detail of `physics-error`. */
export interface PhysicsErrorDetail {
  /** The element whose markup is wrong (a child, or the scene). */
  element: Element;
  /** The attribute at fault ("" when the problem is not one attribute's). */
  attribute: string;
  /** Its value as written. */
  value: string;
  message: string;
}

/** Detail of `physics-collision` and `physics-collision-end`. */
export interface PhysicsCollisionDetail {
  a: Element | null;
  /** The other body's element; null for the view's floor and walls (`bounds="view"`). */
  b: Element | null;
  /** Contact normal from a to b (zero for end events). */
  normal: { x: number; y: number };
  /**
   * How deep the bodies overlapped when their contact was found: usually 0, since contacts are found before bodies
   * touch (0 for end events).
   */
  depth: number;
  /**
   * How fast they met: the speed along the normal at which they approached where they touched (world units per
   * second, gravity's pull over the last gap included; 0 for end events). For a sound's volume or a score.
   */
  speed: number;
}

/** Detail of `physics-ready`. */
export interface PhysicsReadyDetail {
  /** Where the engine runs. */
  mode: 'worker' | 'main';
  /** How states reach the page: SharedArrayBuffer, transferred ArrayBuffers, or directly (main thread). */
  transport: Transport;
}

/** Every `physics-*` event and its detail. */
export interface PhysicsEventDetails {
  'physics-ready': PhysicsReadyDetail;
  'physics-error': PhysicsErrorDetail;
  'physics-collision': PhysicsCollisionDetail;
  'physics-collision-end': PhysicsCollisionDetail;
}

export type PhysicsEventName = keyof PhysicsEventDetails;

/** Dispatches a `physics-*` event on `target`: bubbling and composed, like every event of the elements. @internal */
export function firePhysicsEvent<K extends PhysicsEventName>(target: EventTarget, type: K, detail: PhysicsEventDetails[K]): void {
  target.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
}

/** The `physics-*` events as DOM events: each a CustomEvent with its detail. */
export type PhysicsEventMap = { [K in PhysicsEventName]: CustomEvent<PhysicsEventDetails[K]> };

// Typed listeners on the elements, and on the document and window the events bubble to.
declare global {
  interface HTMLElementEventMap extends PhysicsEventMap {}
  interface DocumentEventMap extends PhysicsEventMap {}
  interface WindowEventMap extends PhysicsEventMap {}
}
