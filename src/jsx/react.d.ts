// physics-elements/react: the tags in React 19's JSX. Types only, and opt-in: a TSX file that imports
// `import type {} from 'physics-elements/react'` (or a tsconfig with "types": ["physics-elements/react"]) gets
// `<cloth-sim wind={2} kernel="wasm" onphysics-error={(e) => e.detail.message} />` checked: each tag takes React's
// props of an HTML element (key, ref to the element's class, id, className, style, children, onClick, …), its
// attributes named as in the markup (physics-elements/jsx), and optional `onphysics-*` listeners, which React 19 adds
// with addEventListener on a custom element. Needs @types/react 19 (React.JSX); the package does not depend on React.
// Hand-written (src/jsx/react.d.ts, copied into dist/types/jsx by the build): the library's own compile has no React.
import type { DetailedHTMLProps, HTMLAttributes } from 'react';
import type { PhysicsElementAttributes, PhysicsEventHandlers, PhysicsTagName } from './index.js';

/** The props of tag T in React's JSX. */
export type PhysicsElementProps<T extends PhysicsTagName> = DetailedHTMLProps<HTMLAttributes<HTMLElementTagNameMap[T]>, HTMLElementTagNameMap[T]> &
  PhysicsElementAttributes[T] &
  PhysicsEventHandlers<T, 'on'>;

/** Every tag's props. */
export type PhysicsIntrinsicElements = { [T in PhysicsTagName]: PhysicsElementProps<T> };

declare module 'react' {
  namespace JSX {
    interface IntrinsicElements extends PhysicsIntrinsicElements {}
  }
}
