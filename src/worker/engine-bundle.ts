// Everything the engine worker runs, plus what the page needs from the same code: the single-file build
// (rollup.config.js) bundles this module once, as a function whose source text becomes the worker's blob: URL and
// whose return value gives the page the headless engine and its main-thread fallback. One copy of the engine.
import './engine.worker.js';
export * from '../engine/index.js';
export { EngineHost } from './engine-host.js';
export { TripleBufferPublisher, TransferPublisher } from './publishers.js';
export { TripleBuffer } from './triple-buffer.js';
// The page's comlink too (one copy in the single-file build).
export * as __comlink from 'comlink';
