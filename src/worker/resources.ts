// Live resource counts, for leak tests and the diagnostics panel: every worker, main-thread engine loop, p5
// instance, observer and global listener the library creates is counted here and uncounted when released.
const counts = { workers: 0, hosts: 0, sketches: 0, observers: 0, listeners: 0, pendingCalls: 0 };

export type ResourceName = keyof typeof counts;

export function track(name: ResourceName, delta: 1 | -1): void {
  counts[name] += delta;
}

/** A copy of the current counts: workers not terminated, main-thread engines not disposed, and so on. */
export function liveResources(): Readonly<typeof counts> {
  return { ...counts };
}
