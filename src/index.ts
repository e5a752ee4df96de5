// physics-elements: the element library entry. Importing it registers the elements. It exports the public API only:
// the elements, their event details, the drawing hook's types, and the headless engine (so one import gives both).
// Internals (the worker client and host, frame stores, the wire protocol) stay in their modules.
export * from './engine/index.js';
export * from './bundle.js';
