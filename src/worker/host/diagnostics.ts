// Where the engine runs and what it is doing, for tests and the diagnostics panel.
export function runningInWorker(): boolean {
  const scope = (globalThis as { WorkerGlobalScope?: { new (): unknown } }).WorkerGlobalScope;
  return typeof scope === 'function' && globalThis instanceof scope;
}

export function crossOriginIsolated(): boolean {
  return Boolean((globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated);
}
