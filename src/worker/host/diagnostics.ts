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

let repairWarned = false;

/**
 * One console warning per realm the first time a world's step had to put bodies back where they started a step
 * (pipeline/guard.ts): joints tangled beyond what the solver resolves. The page keeps running; the author learns why a
 * body stopped or jumped back.
 */
export function warnIfRowsRepaired(w: World): void {
  if (repairWarned) return;
  const { rowsRepaired } = w.diagnostics();
  if (rowsRepaired === 0) return;
  repairWarned = true;
  console.warn(
    `physics-elements: the solver put ${rowsRepaired} bod${rowsRepaired === 1 ? 'y' : 'ies'} back where a step started, ` +
      'at rest: joints it cannot resolve (limits, motors or loops among very different masses or long levers); see ' +
      "the engine reference's Known limits",
  );
}
