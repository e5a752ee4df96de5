// Where the engine runs and what it is doing, for tests and the diagnostics panel.
import type { World } from '../../engine/index.js';

export function runningInWorker(): boolean {
  const scope = (globalThis as { WorkerGlobalScope?: { new (): unknown } }).WorkerGlobalScope;
  return typeof scope === 'function' && globalThis instanceof scope;
}

export function crossOriginIsolated(): boolean {
  return Boolean((globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated);
}

let kernelWarned = false;

/**
 * One console warning per realm (page or worker) when the page's Content-Security-Policy refused the WebAssembly
 * kernel a scene asked for ('auto' falls back to JS silently where WebAssembly or SIMD is missing: nothing to fix).
 */
export function warnIfKernelRefused(w: World): void {
  const { kernel, requested, reason } = w.diagnostics();
  if (kernelWarned || kernel === 'wasm' || requested !== 'auto' || !/refused/.test(reason)) return;
  kernelWarned = true;
  console.warn(`physics-elements: the WebAssembly kernel cannot run, using the JS solver: ${reason}`);
}
