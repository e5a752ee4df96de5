// Loading costs of one embed in a text post, as a reader on a slow connection gets them (issue #15): cumulative
// layout shift, the main thread's long tasks while the single file loads (the biggest is its evaluation), and when the
// scene draws its first frame. Desktop (1280×800) and phone (390×844, DPR 3, touch), each over an emulated
// 1.6 Mbit/s, 150 ms RTT connection (CDP Network.emulateNetworkConditions), several runs each.
//
//   node scripts/measure-loading.mjs [--file dist/physics-elements.iife.js] [--runs 3] [--snippet reserved|bare]
//                                    [--fast] [--json] [--profile out.cpuprofile] [--trace out.json] [--thread-time]
//                                    [--max-cls 0.02]
//
// The page loads the file as the README's snippet does: a classic <script defer src> (a file ending in .bundle.js, the
// ES module, is loaded with type="module"). --snippet reserved (default): the README's snippet, <cloth-sim
// style="display:block;aspect-ratio:16/10">; bare: <cloth-sim> without it (the box is 0 px tall until the script
// arrives). --fast: no network throttling (long tasks and first frame without the download). --profile: a CPU profile
// of the first desktop run (open it in Chromium's DevTools, Performance panel). --trace: a Chromium trace of the first
// desktop run (chrome://tracing or DevTools), and what each main-thread task over 50 ms spent its time on.
// --thread-time: a light trace of every run, for the main thread's busiest tasks by CPU time (thread time) besides wall
// time: on a machine shared with other jobs a task's wall time counts the time the thread waited for a core, its
// thread time does not (but neither does it count waiting for another thread or process, e.g. a synchronous IPC).
// --max-cls: the check scripts/test.sh
// runs, exit 1 when a run's layout shift is over it (long tasks vary with the machine's load: only reported).
import { readFileSync, writeFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { gzipSync } from 'node:zlib';
import { launch, listen, root } from '../test/e2e/harness.mjs';

const args = process.argv.slice(2);
const arg = (name, fallback) => {
  const i = args.indexOf(`--${name}`);
  return i >= 0 ? args[i + 1] : fallback;
};
const bundlePath = resolve(arg('file', resolve(root, 'dist/physics-elements.iife.js')));
const asModule = bundlePath.endsWith('.bundle.js');
const profilePath = arg('profile', null);
const tracePath = arg('trace', null);
const threadTime = args.includes('--thread-time');
const maxCls = args.includes('--max-cls') ? Number(arg('max-cls')) : null;
const runs = Number(arg('runs', 3));
const snippet = arg('snippet', 'reserved');
const fast = args.includes('--fast');
const asJson = args.includes('--json');
const bundle = readFileSync(bundlePath);
// Sent gzipped, as a CDN sends it.
const gzipped = gzipSync(bundle, { level: 9 });

const paragraph = (n) =>
  `<p>Paragraph ${n}. A blogger writes about pendulums, cloth and falling boxes; the reader scrolls through the text while the
  embed loads. Lorem ipsum dolor sit amet, consectetur adipiscing elit, sed do eiusmod tempor incididunt ut labore et dolore
  magna aliqua. Ut enim ad minim veniam, quis nostrud exercitation ullamco laboris nisi ut aliquip ex ea commodo.</p>`;
const embed =
  snippet === 'bare'
    ? '<cloth-sim id="embed"></cloth-sim>'
    : '<cloth-sim id="embed" style="display:block;aspect-ratio:16/10"></cloth-sim>';
const page = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>A post</title>
<style>body { margin: 0 auto; max-width: 720px; padding: 16px; font: 17px/1.6 Georgia, serif; }</style>
<script ${asModule ? 'type="module"' : 'defer'} src="/physics-elements.js"></script></head>
<body><h1>A post with one embed</h1>
${paragraph(1)}
${embed}
${[2, 3, 4, 5, 6, 7, 8].map(paragraph).join('\n')}
</body></html>`;

const server = await listen('127.0.0.1', (req, res) => {
  if (req.url === '/physics-elements.js') {
    const gzip = /\bgzip\b/.test(req.headers['accept-encoding'] ?? '');
    res.writeHead(200, { 'content-type': 'text/javascript', 'cache-control': 'no-store', ...(gzip ? { 'content-encoding': 'gzip' } : {}) });
    res.end(gzip ? gzipped : bundle);
  } else if (req.url === '/') {
    res.writeHead(200, { 'content-type': 'text/html', 'cache-control': 'no-store' });
    res.end(page);
  } else {
    res.writeHead(404);
    res.end();
  }
});
const url = `http://127.0.0.1:${server.address().port}/`;

// Installed before the page's own scripts: layout shifts, long tasks, and the first frame the scene draws.
function observe() {
  const m = (window.__loading = { cls: 0, shifts: [], longTasks: [], firstFrame: null, ready: null });
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) {
      if (e.hadRecentInput) continue;
      m.cls += e.value;
      m.shifts.push({ at: Math.round(e.startTime), value: e.value });
    }
  }).observe({ type: 'layout-shift', buffered: true });
  new PerformanceObserver((list) => {
    for (const e of list.getEntries()) m.longTasks.push({ at: Math.round(e.startTime), ms: Math.round(e.duration) });
  }).observe({ type: 'longtask', buffered: true });
  const poll = () => {
    const el = document.getElementById('embed');
    if (el && el.renderedFrames > 0) {
      m.firstFrame = performance.now();
      return;
    }
    requestAnimationFrame(poll);
  };
  requestAnimationFrame(poll);
  addEventListener('physics-ready', () => (m.ready ??= performance.now()), true);
}

const profiles = {
  desktop: { viewport: { width: 1280, height: 800 } },
  phone: { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true },
};

/** Self time per function (name, file:line) in a CPU profile, the 12 biggest, in ms. */
function summarize(profile) {
  const selfUs = new Map();
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  for (let i = 0; i < profile.samples.length; i++) {
    const n = byId.get(profile.samples[i]);
    const f = n.callFrame;
    const key = `${f.functionName || '(anonymous)'} ${f.url ? `${f.url.split('/').pop()}:${f.lineNumber + 1}:${f.columnNumber + 1}` : ''}`.trim();
    selfUs.set(key, (selfUs.get(key) ?? 0) + (profile.timeDeltas[i] ?? 0));
  }
  return [...selfUs].sort((a, b) => b[1] - a[1]).slice(0, 12).map(([k, us]) => `${(us / 1000).toFixed(1).padStart(7)} ms  ${k}`);
}
let profileSummary = null;

/**
 * The renderer main thread's tasks over 50 ms in a trace, each with where its time went: the trace's own events by self
 * time (layout, style, paint, commit, garbage collection, …) and, from a CPU profile taken at the same time (same
 * clock), script time by function (self time, and time under each of the task's outermost functions).
 */
function longTasksOfTrace(events, profile) {
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain');
  if (!main) return [];
  const onMain = events.filter((e) => e.pid === main.pid && e.tid === main.tid && e.ph === 'X' && e.dur !== undefined).sort((a, b) => a.ts - b.ts || b.dur - a.dur);
  // Outermost task events only (RunTask and ThreadControllerImpl::RunTask nest).
  const tasks = [];
  for (const e of onMain) {
    if (e.name !== 'RunTask' && e.name !== 'ThreadControllerImpl::RunTask') continue;
    const last = tasks[tasks.length - 1];
    if (last && e.ts < last.ts + last.dur) continue;
    tasks.push(e);
  }
  const label = (e) => {
    const d = e.args?.data ?? {};
    if (e.name === 'FunctionCall') return `call ${d.functionName || '(anonymous)'}`;
    if (e.name === 'TimerFire' || e.name === 'FireAnimationFrame' || e.name === 'EventDispatch') return `${e.name} ${d.type ?? ''}`.trim();
    return e.name;
  };
  // Samples of the profile on the trace's clock, with their stacks (outermost first).
  const samples = [];
  if (profile) {
    const byId = new Map(profile.nodes.map((n) => [n.id, n]));
    const parent = new Map();
    for (const n of profile.nodes) for (const c of n.children ?? []) parent.set(c, n.id);
    const frame = (n) => `${n.callFrame.functionName || '(anonymous)'}:${n.callFrame.lineNumber + 1}:${n.callFrame.columnNumber + 1}`;
    let t = profile.startTime;
    for (let i = 0; i < profile.samples.length; i++) {
      t += profile.timeDeltas[i] ?? 0;
      const stack = [];
      for (let id = profile.samples[i]; id !== undefined; id = parent.get(id)) {
        const n = byId.get(id);
        if (n.callFrame.functionName !== '(root)') stack.push(frame(n));
      }
      samples.push({ t, stack: stack.reverse() });
    }
  }
  const out = [];
  const start = tasks.length ? tasks[0].ts : 0;
  const ms = (us) => (us / 1000).toFixed(1);
  for (const task of tasks) {
    if (task.dur < 50000) continue;
    const end = task.ts + task.dur;
    const inside = onMain.filter((e) => e.ts >= task.ts && e.ts + e.dur <= end && e.name !== 'RunTask' && e.name !== 'ThreadControllerImpl::RunTask');
    // Self time: an event's duration minus its direct children's (events nest by time on one thread).
    const self = new Map();
    const stack = [];
    for (const e of inside) {
      while (stack.length && stack[stack.length - 1].ts + stack[stack.length - 1].dur <= e.ts) stack.pop();
      const parent = stack[stack.length - 1];
      if (parent) self.set(parent, (self.get(parent) ?? parent.dur) - e.dur);
      self.set(e, self.get(e) ?? e.dur);
      stack.push(e);
    }
    const byLabel = new Map();
    for (const [e, us] of self) byLabel.set(label(e), (byLabel.get(label(e)) ?? 0) + us);
    const top = [...byLabel].sort((a, b) => b[1] - a[1]).slice(0, 8);
    out.push(`task of ${ms(task.dur)} ms (${ms(task.tdur ?? NaN)} ms CPU) at +${ms(task.ts - start)} ms: ${top.map(([k, us]) => `${k} ${ms(us)}`).join(' | ')}`);
    const within = samples.filter((s) => s.t >= task.ts && s.t <= end);
    if (within.length > 1) {
      const per = task.dur / within.length;
      const selfBy = new Map();
      const inclBy = new Map();
      for (const s of within) {
        const leaf = s.stack[s.stack.length - 1] ?? '(none)';
        selfBy.set(leaf, (selfBy.get(leaf) ?? 0) + per);
        for (const f of new Set(s.stack)) inclBy.set(f, (inclBy.get(f) ?? 0) + per);
      }
      const show = (m, n) => [...m].sort((a, b) => b[1] - a[1]).slice(0, n).map(([k, us]) => `${k} ${ms(us)}`).join(' | ');
      out.push(`    script, self: ${show(selfBy, 8)}`);
      out.push(`    script, total: ${show(inclBy, 14)}`);
    }
  }
  return out;
}
let traceSummary = null;

/** The renderer main thread's outermost tasks in a trace: wall and thread (CPU) time in ms, start relative to the first. */
function mainTasks(events) {
  const main = events.find((e) => e.name === 'thread_name' && e.args?.name === 'CrRendererMain');
  if (!main) return [];
  const tasks = [];
  const run = events.filter((e) => e.pid === main.pid && e.tid === main.tid && e.ph === 'X' && (e.name === 'RunTask' || e.name === 'ThreadControllerImpl::RunTask')).sort((a, b) => a.ts - b.ts || b.dur - a.dur);
  for (const e of run) {
    const last = tasks[tasks.length - 1];
    if (last && e.ts < last.end) continue;
    tasks.push({ ts: e.ts, end: e.ts + e.dur, ms: e.dur / 1000, cpu: (e.tdur ?? NaN) / 1000 });
  }
  return tasks;
}

const browser = await launch();
const results = {};
try {
  for (const [name, options] of Object.entries(profiles)) {
    results[name] = [];
    for (let run = 0; run < runs; run++) {
      const context = await browser.newContext(options);
      const tab = await context.newPage();
      await tab.addInitScript(observe);
      const cdp = await context.newCDPSession(tab);
      await cdp.send('Network.enable');
      await cdp.send('Network.setCacheDisabled', { cacheDisabled: true });
      if (!fast) {
        await cdp.send('Network.emulateNetworkConditions', {
          offline: false,
          latency: 150,
          downloadThroughput: (1.6 * 1024 * 1024) / 8,
          uploadThroughput: (750 * 1024) / 8,
        });
      }
      const profiling = profilePath && !tracePath && name === 'desktop' && run === 0;
      if (profiling) {
        await cdp.send('Profiler.enable');
        await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
        await cdp.send('Profiler.start');
      }
      const tracing = tracePath && name === 'desktop' && run === 0;
      const lightTrace = threadTime && !tracing;
      if (lightTrace) await browser.startTracing(tab, { categories: ['toplevel'] });
      if (tracing) {
        await browser.startTracing(tab, { categories: ['toplevel', 'devtools.timeline', 'disabled-by-default-devtools.timeline'] });
        await cdp.send('Profiler.enable');
        await cdp.send('Profiler.setSamplingInterval', { interval: 200 });
        await cdp.send('Profiler.start');
      }
      await tab.goto(url, { waitUntil: 'load', timeout: 120000 });
      await tab.waitForFunction(() => window.__loading.firstFrame !== null, null, { timeout: 60000 });
      let tasks = null;
      if (tracing) {
        const { profile } = await cdp.send('Profiler.stop');
        const buffer = await browser.stopTracing();
        writeFileSync(tracePath, buffer);
        const events = JSON.parse(buffer.toString()).traceEvents;
        traceSummary = longTasksOfTrace(events, profile);
        if (threadTime) tasks = mainTasks(events);
      }
      if (lightTrace) tasks = mainTasks(JSON.parse((await browser.stopTracing()).toString()).traceEvents);
      if (profiling) {
        const { profile } = await cdp.send('Profiler.stop');
        writeFileSync(profilePath, JSON.stringify(profile));
        profileSummary = summarize(profile);
      }
      // Late shifts count too: wait a moment after the first frame.
      await tab.waitForTimeout(1000);
      const m = await tab.evaluate(() => window.__loading);
      results[name].push({
        cls: Number(m.cls.toFixed(4)),
        longestTask: Math.max(0, ...m.longTasks.map((t) => t.ms)),
        longTasks: m.longTasks,
        // With --thread-time: the task with the most CPU time, and the CPU time of the longest task by wall time.
        ...(tasks && tasks.length
          ? {
              busiestTaskCpu: Math.round(Math.max(...tasks.map((t) => t.cpu))),
              longestTaskCpu: Math.round(tasks.reduce((a, b) => (b.ms > a.ms ? b : a)).cpu),
            }
          : {}),
        ready: Math.round(m.ready ?? NaN),
        firstFrame: Math.round(m.firstFrame),
        shifts: m.shifts,
      });
      await context.close();
    }
  }
} finally {
  await browser.close();
  server.close();
}

if (asJson) console.log(JSON.stringify(results, null, 1));
else {
  console.log(`${bundlePath} (${(bundle.length / 1024).toFixed(0)} KB, ${(gzipped.length / 1024).toFixed(0)} KB gzip), snippet ${snippet}, ${fast ? 'no throttling' : '1.6 Mbit/s, 150 ms'}, ${runs} runs`);
  for (const [name, list] of Object.entries(results)) {
    for (const r of list) {
      console.log(
        `${name.padEnd(8)} CLS ${r.cls.toFixed(4)}  longest task ${String(r.longestTask).padStart(4)} ms` +
          (r.busiestTaskCpu !== undefined ? `  busiest task ${String(r.busiestTaskCpu).padStart(3)} ms CPU` : '') +
          `  ready ${r.ready} ms  first frame ${r.firstFrame} ms` +
          `  long tasks [${r.longTasks.map((t) => `${t.ms}@${t.at}`).join(', ')}]`,
      );
    }
  }
}
if (traceSummary) console.log(`Trace of the first desktop run in ${tracePath}; main-thread tasks over 50 ms, self time (ms) inside:\n${traceSummary.join('\n')}`);
if (profileSummary) console.log(`CPU profile of the first desktop run in ${profilePath}; self time by function:\n${profileSummary.join('\n')}`);
if (maxCls !== null) {
  const over = Object.entries(results).flatMap(([name, list]) => list.filter((r) => !(r.cls <= maxCls)).map((r) => `${name} ${r.cls}`));
  console.log(over.length ? `FAIL layout shift over ${maxCls}: ${over.join(', ')}` : `ok   layout shift ≤ ${maxCls} in every run`);
  process.exit(over.length ? 1 : 0);
}
