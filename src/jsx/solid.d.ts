// physics-elements/solid: the tags in Solid's JSX. Types only, and opt-in: a TSX file that imports
// `import type {} from 'physics-elements/solid'` (or a tsconfig with "types": ["physics-elements/solid"]) gets each tag
// checked with Solid's props of an HTML element (ref, id, class, style, children, onClick, …), its attributes named as
// in the markup (physics-elements/jsx) and optional `on:physics-*` listeners (Solid's `on:` adds a listener for the
// exact event name). Solid sets a custom element's dynamic props as properties, the name camel-cased: write
// `prop:isStatic={…}` for a dynamic `static` (a literal `static` is an attribute of the template). Hand-written
// (src/jsx/solid.d.ts, copied into dist/types/jsx by the build).
import type { JSX } from 'solid-js';
import type { PhysicsElementAttributes, PhysicsEventHandlers, PhysicsTagName } from './index.js';

/** The props of tag T in Solid's JSX. */
export type PhysicsElementProps<T extends PhysicsTagName> = JSX.HTMLAttributes<HTMLElementTagNameMap[T]> & PhysicsElementAttributes[T] & PhysicsEventHandlers<T, 'on:'>;

/** Every tag's props. */
export type PhysicsIntrinsicElements = { [T in PhysicsTagName]: PhysicsElementProps<T> };

declare module 'solid-js' {
  namespace JSX {
    interface IntrinsicElements extends PhysicsIntrinsicElements {}
  }
}
