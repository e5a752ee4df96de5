// Everything the engine worker runs, plus what the page needs from the same code: the single-file build
// (rollup.config.js) bundles this module once, as a function whose source text becomes the worker's blob: URL and
// whose return value gives the page its main-thread fallback (EngineHost and the frame buffers). One copy of the
// engine. Export only what page code imports: the rest of the engine's API is not kept, so the standalone collision
// routines, the scene catalogue and so on stay out of the file (they are in physics-elements/engine).
import './engine.worker.js';
export { EngineHost } from './engine-host.js';
export { TripleBufferPublisher, TransferPublisher } from './publishers.js';
export { TripleBuffer } from './triple-buffer.js';
// The renderer draws a ragdoll's bones as the builder joins them; shape elements check `model` against the engine's list.
export { BODY_MODELS, RAGDOLL_BONES } from '../engine/index.js';
// The page's comlink too (one copy in the single-file build).
export * as __comlink from 'comlink';
