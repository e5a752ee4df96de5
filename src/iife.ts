// The types of physics-elements/iife: the global the classic script dist/physics-elements.iife.js makes (rollup.config.js:
// format 'iife', name 'PhysicsElements'), holding what the single file exports (physics-elements/bundle: the element
// classes and EngineStoppedError; not the headless engine's API). Types only: for a page's or an app's TypeScript (or
// checkJs) that loads the script with a plain <script src> and uses the global:
//
//   /// <reference types="physics-elements/iife" />
//   const { ClothSimElement } = window.PhysicsElements;
//
// or "types": ["physics-elements/iife"] in a tsconfig. The classes' instance types and the event details are
// importable as types from 'physics-elements/bundle'.

declare global {
  interface Window {
    /** The exports of dist/physics-elements.iife.js (the element classes and EngineStoppedError). */
    PhysicsElements: typeof import('./bundle.js');
  }
  /** The exports of dist/physics-elements.iife.js, a global of the classic script (also `window.PhysicsElements`). */
  var PhysicsElements: typeof import('./bundle.js');
}

export {};
