// physics-elements: the element library entry. It also re-exports the headless engine, so one import gives both.
export * from './engine/index.js';
