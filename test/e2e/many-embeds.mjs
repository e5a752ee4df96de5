// End-to-end measurement: a text post with 8 <cloth-sim> embeds against the same post with one, as a blogger's page
// loads dist/physics-elements.bundle.js (no cross-origin isolation: frames as transferred buffers). Reports
//  - engine workers created (playwright's worker events) at load and once every cloth has been scrolled to: the page's
//    pool makes at most 2 (fails otherwise);
//  - how many cloths start at load (only those near the viewport should);
//  - when the first (visible) cloth draws its first frame, from navigation start: median over runs, and the ratio to
//    the single embed's (target ≤ 1.3);
//  - memory per extra embed, (8 embeds − 1 embed) / 7 per pair of runs, median over the pairs: the anonymous and
//    shared memory of all the browser's processes (PSS from Linux /proc, pids from CDP SystemInfo; see browserMemory) as the post loads (only the cloths
//    near the viewport started) and once all 8 have been scrolled to and run and the reader is back at the first,
//    after a garbage collection in the page; the renderer processes' share and the page's JS heap beside it, and how
//    many canvases hold pixels then (those far from the viewport give them back). Target ≤ 4 MB.
// Each run is a fresh browser. Run after `npm run build`: node test/e2e/many-embeds.mjs [--runs 5] [--strict]
// [--bundle path/to/physics-elements.bundle.js]
// (--strict: also exit non-zero when a target is missed; timing on a loaded machine is noisy, so it is off by default).
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { chromium } from 'playwright-core';
import { checker, root, serveFiles } from './harness.mjs';

const args = process.argv.slice(2);
const runsArg = args.includes('--runs') ? Number(args[args.indexOf('--runs') + 1]) : 5;
const runs = Number.isInteger(runsArg) && runsArg > 0 ? runsArg : 5;
const strict = args.includes('--strict');
const bundlePath = args.includes('--bundle') ? resolve(args[args.indexOf('--bundle') + 1]) : resolve(root, 'dist/physics-elements.bundle.js');
const bundle = readFileSync(bundlePath);
const started = Date.now();

const LOREM = 'Cloth is a grid of particles held together by distance constraints; the solver moves each pair back toward its rest length a little at every substep, and gravity and a gentle breeze do the rest. ';
const paragraph = (k) => `<p>${LOREM.repeat(3 + (k % 3))}</p>`;

/** The post: an intro, then `count` cloths with three paragraphs of text between them, then more text. */
function post(count) {
  const parts = [paragraph(0)];
  for (let k = 1; k <= 8; k++) {
    if (k <= count) parts.push(`<cloth-sim id="c${k}" class="embed" aria-label="Cloth ${k}"></cloth-sim>`);
    parts.push(paragraph(k), paragraph(k + 1), paragraph(k + 2));
  }
  // Polls each frame until the first cloth has drawn: its first-frame time on the page's clock (navigation start = 0).
  const probe = `(function poll() {
    const el = document.getElementById('c1');
    if (el && el.renderedFrames > 0) { window.__firstFrame = performance.now(); return; }
    requestAnimationFrame(poll);
  })();`;
  return `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>A post with ${count} embed${count === 1 ? '' : 's'}</title>
<style>body { margin: 0 auto; max-width: 680px; padding: 20px; font: 17px/1.6 Georgia, serif; }
.embed { display: block; width: 640px; height: 400px; margin: 24px 0; }</style>
<script>${probe}</script>
<script type="module" src="/physics-elements.bundle.js"></script></head>
<body><h1>Notes on cloth</h1>${parts.join('\n')}</body></html>`;
}

const pages = { '/one.html': post(1), '/eight.html': post(8) };
const site = await serveFiles('127.0.0.1', { '/physics-elements.bundle.js': bundle, ...pages });
const base = `http://127.0.0.1:${site.address().port}`;

/**
 * Memory of the browser in MB (Linux /proc smaps_rollup): its processes' proportional share of anonymous and shared
 * (shmem) pages, summed over all of them (browser, GPU, utility, renderers: a canvas' pixels live in the renderer and,
 * with software compositing, its shared bitmaps in the GPU process too), and of the renderer processes alone. File
 * pages (Chromium's own code, fonts) are left out: they are shared with every other Chromium on the machine, so their
 * share swings by tens of MB as other browsers start and stop, and they are not what an embed costs.
 */
async function browserMemory(browser) {
  const cdp = await browser.newBrowserCDPSession();
  const { processInfo } = await cdp.send('SystemInfo.getProcessInfo');
  await cdp.detach();
  let renderer = 0;
  let total = 0;
  for (const p of processInfo) {
    try {
      const text = readFileSync(`/proc/${p.id}/smaps_rollup`, 'utf8');
      const kb = (field) => Number(new RegExp(`^${field}:\\s+(\\d+) kB`, 'm').exec(text)?.[1] ?? 0);
      const own = kb('Pss_Anon') + kb('Pss_Shmem');
      total += own;
      if (p.type === 'renderer') renderer += own;
    } catch {
      // A process that ended meanwhile.
    }
  }
  return { renderer: renderer / 1024, total: total / 1024 };
}

/**
 * Chromium as harness.mjs launches it, with gc() exposed: the page and its workers collect their garbage before each
 * measurement (frames cross from the workers as new buffers every step, so a worker's heap holds tens of MB of garbage
 * or none depending on when its last collection ran: the measurement's biggest noise without this).
 */
function launch() {
  return chromium.launch({
    executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--js-flags=--expose-gc'],
  });
}

/** Full garbage collections in the page and in every worker, twice, then a moment for the memory to be given back. */
async function gc(tab) {
  for (let k = 0; k < 2; k++) {
    await tab.evaluate(() => globalThis.gc());
    for (const w of tab.workers()) await w.evaluate(() => globalThis.gc?.()).catch(() => {});
  }
  await tab.waitForTimeout(500);
}

/** The page's JS heap in use, MB (the workers' heaps are in the renderer's PSS). */
async function jsHeap(tab) {
  const cdp = await tab.context().newCDPSession(tab);
  const { usedSize } = await cdp.send('Runtime.getHeapUsage');
  await cdp.detach();
  return usedSize / 2 ** 20;
}

/** One load of a post in a fresh browser: first-frame time, workers, starts at load, memory as loaded and once every cloth was scrolled in. */
async function load(name, count) {
  const browser = await launch();
  try {
    const tab = await browser.newPage({ viewport: { width: 1000, height: 800 } });
    let workersMade = 0;
    tab.on('worker', () => workersMade++);
    const problems = [];
    tab.on('pageerror', (e) => problems.push(String(e)));
    tab.on('console', (m) => m.type() === 'error' && problems.push(m.text()));
    await tab.goto(`${base}${name}`);
    await tab.waitForFunction(() => window.__firstFrame !== undefined, null, { timeout: 30000 });
    const firstFrame = await tab.evaluate(() => window.__firstFrame);
    // Settle: whatever starts at load has started (the near ones), then count.
    await tab.waitForTimeout(2000);
    const startedAtLoad = await tab.evaluate(() => [...document.querySelectorAll('cloth-sim')].filter((el) => el.client !== null).length);
    const workersAtLoad = workersMade;
    await gc(tab);
    const loaded = await browserMemory(browser);
    // Scroll each cloth into view and wait for it to draw; then back to the top, where the first one runs.
    for (let k = 1; k <= count; k++) {
      await tab.evaluate((id) => document.getElementById(id).scrollIntoView({ block: 'center' }), `c${k}`);
      await tab.waitForFunction((id) => document.getElementById(id).renderedFrames > 0, `c${k}`, { timeout: 30000 });
    }
    await tab.evaluate(() => window.scrollTo(0, 0));
    await tab.waitForTimeout(2000);
    await gc(tab);
    const all = await browserMemory(browser);
    // Canvases that hold pixels now (a scene far from the viewport gives them back).
    const canvases = await tab.evaluate(() => [...document.querySelectorAll('cloth-sim')].filter((el) => el.canvas && el.canvas.width * el.canvas.height > 0).length);
    const memory = { loaded: loaded.total, loadedRenderer: loaded.renderer, pss: all.total, renderer: all.renderer, heap: await jsHeap(tab), canvases };
    return { firstFrame, startedAtLoad, workersAtLoad, workersMade, liveWorkers: tab.workers().length, memory, problems };
  } finally {
    await browser.close();
  }
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const check = checker();
try {
  const one = [];
  const eight = [];
  for (let r = 0; r < runs; r++) {
    // Alternate the order, so a machine getting busier or quieter affects both alike.
    const pair = r % 2 === 0 ? [['one', 1], ['eight', 8]] : [['eight', 8], ['one', 1]];
    for (const [kind, count] of pair) {
      const result = await load(`/${kind}.html`, count);
      (kind === 'one' ? one : eight).push(result);
      const m = result.memory;
      console.log(
        `run ${r + 1} ${kind}: first frame ${result.firstFrame.toFixed(0)} ms, cloths started at load ${result.startedAtLoad}/${count}, workers ${result.workersMade}, ` +
          `memory (browser / renderers) at load ${m.loaded.toFixed(1)} / ${m.loadedRenderer.toFixed(1)} MB, all ran ${m.pss.toFixed(1)} / ${m.renderer.toFixed(1)} MB, ` +
          `canvases with pixels ${m.canvases}, JS heap ${m.heap.toFixed(1)} MB`,
      );
    }
  }
  const t1 = median(one.map((r) => r.firstFrame));
  const t8 = median(eight.map((r) => r.firstFrame));
  const ratio = t8 / t1;
  const most = Math.max(...eight.map((r) => r.workersMade));
  const full = eight[0];
  // Per run, the two posts loaded side by side; the median over runs (one sample of a loaded machine's memory is noise).
  const perRun = (field) => median(eight.map((e, k) => (e.memory[field] - one[k].memory[field]) / 7));
  const perLoaded = perRun('loaded');
  const perPss = perRun('pss');
  const perRenderer = perRun('renderer');
  const perHeap = perRun('heap');
  console.log(`\nworkers with 8 embeds: ${most} made (at load ${full.workersAtLoad}, once all 8 ran ${full.workersMade}, live ${full.liveWorkers})`);
  console.log(`cloths started at load: ${median(eight.map((r) => r.startedAtLoad))} of 8 (the rest wait until scrolled near)`);
  console.log(`first visible cloth's first frame: 1 embed ${t1.toFixed(0)} ms, 8 embeds ${t8.toFixed(0)} ms (medians of ${runs}): ${ratio.toFixed(2)}x`);
  console.log(
    `memory per extra embed (anonymous + shared PSS, the whole browser): ${perLoaded.toFixed(2)} MB as loaded (only the near ones started), ${perPss.toFixed(2)} MB once all 8 ran ` +
      `(reader back at the first; renderer processes alone ${perRenderer.toFixed(2)} MB, JS heap of the page ${perHeap.toFixed(2)} MB); medians of ${runs} paired runs`,
  );
  check(most <= 2, `at most 2 engine workers for 8 embeds (${most})`);
  check(eight.every((r) => r.problems.length === 0) && one.every((r) => r.problems.length === 0), 'no page errors');
  const targets = [
    [ratio <= 1.3, `first visible cloth within 1.3x the single embed's first-frame time (${ratio.toFixed(2)}x)`],
    [perLoaded <= 4, `at most 4 MB per extra embed as the post loads (${perLoaded.toFixed(2)} MB)`],
    [perPss <= 4, `at most 4 MB per extra embed once all 8 run (${perPss.toFixed(2)} MB)`],
  ];
  for (const [ok, what] of targets) {
    if (strict) check(ok, what);
    else console.log(`${ok ? 'met ' : 'MISS'} target: ${what}`);
  }
} finally {
  site.close();
}
console.log(`many embeds: ${check.failures.length ? `${check.failures.length} failed` : 'all passed'} in ${((Date.now() - started) / 1000).toFixed(1)} s`);
process.exit(check.failures.length ? 1 : 0);
