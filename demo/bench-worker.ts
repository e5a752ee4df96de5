// Experiment 2's page: a <physics-scene> with n bodies (a mix of boxes and circles falling into a container), on the
// main thread (?worker=none) or in a worker, measured from the page: frame intervals (rAF), long tasks, the scene's
// mode and transport. bench/experiment-worker.mjs adds main-thread busy time from the DevTools protocol.
import '../src/index.js';

const q = new URLSearchParams(location.search);
const n = Number(q.get('n') ?? 200);
const worker = q.get('worker') ?? 'auto';
const warm = Number(q.get('warm') ?? 1);
const seconds = Number(q.get('seconds') ?? 3);

let longTasks: number[] = [];
new PerformanceObserver((list) => longTasks.push(...list.getEntries().map((e) => e.duration))).observe({ type: 'longtask' });

// A container as wide as needed for n bodies about 40% packed in a 16:9 view.
const width = Math.max(16, Math.sqrt((n * 1.0) / 0.4) * 1.33);
const height = (width * 9) / 16;
const scene = document.createElement('physics-scene') as HTMLElement & { ready: Promise<void>; mode: string | null; transport: string | null; stepCount: number; renderedFrames: number };
scene.setAttribute('width', String(width));
scene.setAttribute('height', String(height));
scene.setAttribute('worker', worker);
scene.setAttribute('gravity', '0 9.81');
const columns = Math.floor((width - 2) / 1.2);
for (let k = 0; k < n; k++) {
  const x = 1.2 + (k % columns) * 1.2 + (Math.floor(k / columns) % 2) * 0.3;
  const y = height - 1 - Math.floor(k / columns) * 1.2;
  const b = document.createElement(k % 2 ? 'physics-circle' : 'physics-box');
  b.setAttribute('x', x.toFixed(2));
  b.setAttribute('y', (y - height * 0.3).toFixed(2));
  if (k % 2) b.setAttribute('radius', '0.45');
  else b.setAttribute('width', '0.9'), b.setAttribute('height', '0.9');
  scene.append(b);
}
document.getElementById('host')!.append(scene);

async function measure() {
  await scene.ready;
  await new Promise((r) => setTimeout(r, warm * 1000));
  longTasks = [];
  (window as unknown as { benchPhase: string }).benchPhase = 'measuring';
  const intervals: number[] = [];
  const steps0 = scene.stepCount;
  const t0 = performance.now();
  await new Promise<void>((resolve) => {
    let last = performance.now();
    const tick = (now: number) => {
      intervals.push(now - last);
      last = now;
      if (now - t0 < seconds * 1000) requestAnimationFrame(tick);
      else resolve();
    };
    requestAnimationFrame((now) => {
      last = now;
      requestAnimationFrame(tick);
    });
  });
  const elapsed = performance.now() - t0;
  (window as unknown as { benchPhase: string }).benchPhase = 'done';
  const mean = intervals.reduce((a, b) => a + b, 0) / intervals.length;
  const sd = Math.sqrt(intervals.reduce((a, b) => a + (b - mean) ** 2, 0) / intervals.length);
  const sorted = [...intervals].sort((a, b) => a - b);
  const result = {
    n,
    worker,
    mode: scene.mode,
    transport: scene.transport,
    crossOriginIsolated,
    frames: intervals.length,
    fps: (intervals.length * 1000) / elapsed,
    frameMs: mean,
    jitterMs: sd,
    p95FrameMs: sorted[Math.floor(sorted.length * 0.95)],
    maxFrameMs: sorted[sorted.length - 1],
    longTasks: longTasks.length,
    longTaskMs: longTasks.reduce((a, b) => a + b, 0),
    stepsPerSecond: ((scene.stepCount - steps0) * 1000) / elapsed,
    elapsedMs: elapsed,
  };
  document.getElementById('out')!.textContent = JSON.stringify(result, null, 1);
  return result;
}
(window as unknown as { benchResult: Promise<unknown> }).benchResult = measure();
