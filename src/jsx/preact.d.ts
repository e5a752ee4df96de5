// physics-elements/preact: the tags in Preact's JSX (Preact 10). Types only, and opt-in: a TSX file that imports
// `import type {} from 'physics-elements/preact'` (or a tsconfig with "types": ["physics-elements/preact"]) gets each
// tag checked with Preact's props of an HTML element (key, ref, id, class, style, children, onClick, …), its attributes
// named as in the markup (physics-elements/jsx) and optional `onphysics-*` listeners (Preact adds a listener for
// `on` + the event's name). Hand-written (src/jsx/preact.d.ts, copied into dist/types/jsx by the build).
import type { JSX } from 'preact';
import type { PhysicsElementAttributes, PhysicsEventHandlers, PhysicsTagName } from './index.js';

/** The props of tag T in Preact's JSX. */
export type PhysicsElementProps<T extends PhysicsTagName> = JSX.HTMLAttributes<HTMLElementTagNameMap[T]> & PhysicsElementAttributes[T] & PhysicsEventHandlers<T, 'on'>;

/** Every tag's props. */
export type PhysicsIntrinsicElements = { [T in PhysicsTagName]: PhysicsElementProps<T> };

declare module 'preact' {
  namespace JSX {
    interface IntrinsicElements extends PhysicsIntrinsicElements {}
  }
}
