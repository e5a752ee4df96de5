// physics-elements/vue: the tags in Vue's GlobalComponents, which vue-tsc (Vue's language tools) checks templates
// against. Types only, and opt-in: `import type {} from 'physics-elements/vue'` in a .ts file of the app (or a
// tsconfig with "types": ["physics-elements/vue"]). Each tag takes Vue's props of an HTML element (id, class, style,
// onClick, …), its attributes named as in the markup (physics-elements/jsx), and `@physics-*` listeners with the
// event's typed detail. The shape is the one Vue's guide gives for custom elements not built with Vue (a constructor
// whose instance has $props and $emit; do not read those two on an element). The app still tells Vue's compiler that
// the tags are custom elements (compilerOptions.isCustomElement). vue-tsc may camel-case a hyphenated attribute before
// it checks it (collision-events as collisionEvents), so each takes both spellings. Hand-written (src/jsx/vue.d.ts, copied into
// dist/types/jsx by the build).
import type { EmitFn, HTMLAttributes, PublicProps } from 'vue';
import type { PhysicsEventMap } from '../elements/physics-scene/events.js';
import type { PhysicsElementAttributes, PhysicsEventsOf, PhysicsTagName } from './index.js';

/** "collision-events" → "collisionEvents". */
type Camel<S extends string> = S extends `${infer Head}-${infer Rest}` ? `${Head}${Capitalize<Camel<Rest>>}` : S;

/** Attributes A also under their camel-cased names. */
type BothSpellings<A> = A & { [K in keyof A as K extends string ? Camel<K> : K]: A[K] };

/** Tag T as a Vue component type: the element, with the props and events a template may give it. */
export type PhysicsElementComponent<T extends PhysicsTagName> = new () => HTMLElementTagNameMap[T] & {
  /** @deprecated For templates' prop types only: not on the element. */
  $props: HTMLAttributes & BothSpellings<PhysicsElementAttributes[T]> & PublicProps;
  /** @deprecated For templates' event types only: not on the element. */
  $emit: EmitFn<{ [E in PhysicsEventsOf<T>]: (event: PhysicsEventMap[E]) => void }>;
};

/** Every tag as a Vue component type. */
export type PhysicsGlobalComponents = { [T in PhysicsTagName]: PhysicsElementComponent<T> };

declare module 'vue' {
  interface GlobalComponents extends PhysicsGlobalComponents {}
}
