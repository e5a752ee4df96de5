// Seed experiment 2 (chapter 6): the engine in a Web Worker vs on the main thread, in chromium (playwright-core,
// Debian's /usr/bin/chromium), for growing scenes, with both worker transports: SharedArrayBuffer (page served with
// COOP/COEP) and transferred ArrayBuffers (the same page without them). Per configuration: main-thread busy ms per
// frame (DevTools protocol TaskDuration / frames), frame interval mean, jitter (standard deviation), p95 and max,
// long tasks (> 50 ms), physics steps per second. Medians over --runs page loads. Writes
// bench/results/experiment2.json and experiment2.csv.
// Usage: node bench/experiment-worker.mjs [--max 2000] [--runs 3] [--seconds 3] [--bodies N] [--idle]
//   --bodies N: only scenes of N bodies; --idle: each scene paused once loaded, measured paused (main-thread ms per
//   second and drawings per second of a still picture). Either one prints its table and writes no results files.
import { writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { chromium } from 'playwright-core';
import { startDevServer } from '../scripts/dev-server.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const max = arg('max', 2000);
const runs = arg('runs', 3);
const seconds = arg('seconds', 3);
const only = arg('bodies', 0);
const idle = process.argv.includes('--idle');
const sizes = only > 0 ? [only] : [50, 100, 200, 500, 1000, 2000, 5000].filter((n) => n <= max);
const configs = [
  { name: 'main thread', worker: 'none', transfer: false },
  { name: 'worker, SharedArrayBuffer', worker: 'auto', transfer: false },
  { name: 'worker, transferred buffers', worker: 'auto', transfer: true },
];
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

const loadBefore = loadavg();
const server = await startDevServer({ config: 'bench/wds-experiment.config.mjs' });
const browser = await chromium.launch({
  executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const rows = [];
try {
  // One throwaway load so the dev server has compiled every module before anything is timed.
  {
    const page = await browser.newPage();
    await page.goto(`${server.url}/demo/bench-worker.html?n=20&seconds=0.5&warm=0.2`);
    await page.evaluate(() => window.benchResult);
    await page.close();
  }
  if (idle) console.log('| bodies (paused) | configuration | transport | main-thread ms/s | drawings/s |\n|---|---|---|---|---|');
  else {
    console.log('| bodies | configuration | transport | main-thread ms/frame | fps | frame ms (mean) | jitter ms (sd) | p95 ms | long tasks | steps/s |');
    console.log('|---|---|---|---|---|---|---|---|---|---|');
  }
  for (const n of sizes) {
    for (const c of configs) {
      const samples = [];
      for (let run = 0; run < runs; run++) {
        const context = await browser.newContext({ viewport: { width: 1000, height: 800 } });
        const page = await context.newPage();
        const errors = [];
        page.on('pageerror', (e) => errors.push(String(e)));
        const cdp = await context.newCDPSession(page);
        await cdp.send('Performance.enable');
        const url = `${server.url}/demo/bench-worker.html?n=${n}&worker=${c.worker}&seconds=${seconds}${c.transfer ? '&transport=transfer' : ''}`;
        await page.goto(url);
        // Task time is read when the page starts and ends its measuring window (window.benchPhase).
        const metric = async () => Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
        await page.waitForFunction(() => window.benchPhase === 'measuring', null, { timeout: 60000, polling: 10 });
        if (idle) {
          // Paused: a still picture. Busy time and drawings over `seconds` once the pause has taken effect.
          const drawings = () => page.evaluate(() => document.querySelector('physics-scene').renderedFrames);
          await page.evaluate(() => (document.querySelector('physics-scene').paused = true));
          await page.waitForTimeout(500);
          const [m0, d0, t0] = [await metric(), await drawings(), Date.now()];
          await page.waitForTimeout(seconds * 1000);
          const [m1, d1, t1] = [await metric(), await drawings(), Date.now()];
          await context.close();
          if (errors.length) throw new Error(`${url}: ${errors.join('; ')}`);
          samples.push({ transport: c.worker === 'none' ? 'none' : c.transfer ? 'transfer' : 'shared', mainMsPerSecond: ((m1.TaskDuration - m0.TaskDuration) * 1e6) / (t1 - t0), drawingsPerSecond: ((d1 - d0) * 1000) / (t1 - t0) });
          continue;
        }
        const m0 = await metric();
        const r = await page.evaluate(() => window.benchResult);
        const m1 = await metric();
        await context.close();
        if (errors.length) throw new Error(`${url}: ${errors.join('; ')}`);
        r.mainMsPerFrame = ((m1.TaskDuration - m0.TaskDuration) * 1000) / r.frames;
        r.scriptMsPerFrame = ((m1.ScriptDuration - m0.ScriptDuration) * 1000) / r.frames;
        samples.push(r);
      }
      const pick = (key) => median(samples.map((s) => s[key]));
      if (idle) {
        console.log(`| ${n} | ${c.name} | ${samples[0].transport} | ${pick('mainMsPerSecond').toFixed(1)} | ${pick('drawingsPerSecond').toFixed(1)} |`);
        continue;
      }
      const row = { bodies: n, configuration: c.name, worker: c.worker, transport: samples[0].transport, mode: samples[0].mode, crossOriginIsolated: samples[0].crossOriginIsolated };
      for (const key of ['mainMsPerFrame', 'scriptMsPerFrame', 'fps', 'frameMs', 'jitterMs', 'p95FrameMs', 'maxFrameMs', 'longTasks', 'longTaskMs', 'stepsPerSecond']) row[key] = pick(key);
      rows.push(row);
      console.log(`| ${n} | ${c.name} | ${row.transport} | ${row.mainMsPerFrame.toFixed(2)} | ${row.fps.toFixed(1)} | ${row.frameMs.toFixed(2)} | ${row.jitterMs.toFixed(2)} | ${row.p95FrameMs.toFixed(1)} | ${row.longTasks} | ${row.stepsPerSecond.toFixed(0)} |`);
    }
  }
} finally {
  await browser.close();
  await server.stop();
}
if (only > 0 || idle) process.exit(0);
const summary = {
  date: new Date().toISOString(),
  node: process.version,
  chromium: browser.version?.() ?? '',
  runs,
  seconds,
  max,
  statistic: 'median',
  cpus: cpus().length,
  loadavgBefore: loadBefore,
  loadavgAfter: loadavg(),
  command: `node bench/experiment-worker.mjs ${process.argv.slice(2).join(' ')}`.trim(),
};
writeFileSync(new URL('./results/experiment2.json', import.meta.url), JSON.stringify({ summary, rows }, null, 2));
const keys = Object.keys(rows[0] ?? {});
writeFileSync(new URL('./results/experiment2.csv', import.meta.url), [keys.join(','), ...rows.map((r) => keys.map((k) => JSON.stringify(r[k])).join(','))].join('\n') + '\n');
console.log('wrote bench/results/experiment2.json and experiment2.csv');
