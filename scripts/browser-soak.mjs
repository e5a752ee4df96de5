// Browser soak: scenes running for minutes in chromium while their markup changes all the time, checking that the JS
// heap, the number of live workers and the number of event listeners do not grow after warm-up.
//
// The page (served by the dev server from the sources, so no build is needed) holds a <physics-scene> with a floor,
// boxes, balls, a rope and a cloth, plus a <cloth-sim> and a <ragdoll-sim>. A driver in the page, from a seeded PRNG,
// changes the markup five times a second: adds and removes bodies and links, changes attributes (colours, sizes,
// gravity, iterations, wind, count), pauses and resumes, adds and removes collision listeners, moves a scene (one
// task) and disconnects it for a while (its worker ends) before connecting it again (a new worker).
//
// Every sample puts the page back in the same state (the extra bodies removed, every attribute at its base value, all
// three scenes connected and running), waits, forces garbage collection twice (CDP HeapProfiler.collectGarbage) and
// reads: the JS heap (CDP Runtime.getHeapUsage), live workers (the page's Worker constructor and terminate() wrapped,
// and playwright's own list of the page's workers), event listeners (window and document listeners counted by
// wrapping addEventListener/removeEventListener, CDP DOMDebugger.getEventListeners on window and document, and the
// page-wide JSEventListeners of CDP Performance.getMetrics) and DOM nodes. Fails (exit 1) when, between the first
// sample after warm-up and the last, the heap grows by more than HEAP_TOLERANCE_MB and HEAP_TOLERANCE_FRACTION of the
// first, or a count of workers, window/document listeners, elements or bodies grows; also on page errors. Page-wide
// DOM nodes and listeners too, with a little slack (none with --strict).
//
// Usage: node scripts/browser-soak.mjs [--minutes N] [--seed S] [--strict]   (CI: --minutes 1; long form: --minutes 15)
import { chromium } from 'playwright-core';
import { checker } from '../test/e2e/harness.mjs';
import { startDevServer } from './dev-server.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const minutes = arg('minutes', 1);
const seed = arg('seed', 8);
const strict = process.argv.includes('--strict');
if (!(minutes > 0) || !Number.isFinite(seed)) {
  console.error('usage: node scripts/browser-soak.mjs [--minutes N] [--seed S]');
  process.exit(2);
}
/** Heap growth allowed between the first sample after warm-up and the last: both limits must be exceeded to fail. */
const HEAP_TOLERANCE_MB = 3;
const HEAP_TOLERANCE_FRACTION = 0.2;
/** Window/document listeners in flight at a sample (see the check). */
const LISTENER_SLACK = 5;
const totalMs = minutes * 60_000;
/** Warm-up: a quarter of the run, at most 2 minutes (JIT, p5 and lit caches, first workers). */
const warmupMs = Math.min(totalMs / 4, 120_000);
/** About ten samples after warm-up, at least 10 s apart. */
const sampleEveryMs = Math.max(10_000, (totalMs - warmupMs) / 10);

// The page: the sources through the dev server; counters installed before anything else runs.
const PAGE = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>browser soak</title>
<style>body { margin: 8px; font: 13px system-ui; } .scene { display: block; width: 480px; height: 270px; margin-bottom: 8px; }</style>
<script>
  // Live workers: made minus terminated. Listeners on window and document: added minus removed.
  window.__soak = { workersMade: 0, workersTerminated: 0, listeners: new Set() };
  const NativeWorker = window.Worker;
  window.Worker = class extends NativeWorker {
    constructor(...args) { super(...args); window.__soak.workersMade++; }
    terminate() { if (!this.__ended) { this.__ended = true; window.__soak.workersTerminated++; } super.terminate(); }
  };
  const add = EventTarget.prototype.addEventListener, remove = EventTarget.prototype.removeEventListener;
  const key = (t, type, l, o) => [t === window ? 'window' : 'document', type, l, typeof o === 'boolean' ? o : !!(o && o.capture)];
  const same = (a, b) => a.every((x, i) => x === b[i]);
  // A 'once' listener leaves without removeEventListener, unseen here: those are left to the CDP counts.
  EventTarget.prototype.addEventListener = function (type, l, o) {
    if ((this === window || this === document) && l && !(o && o.once)) {
      const k = key(this, type, l, o);
      if (![...window.__soak.listeners].some((x) => same(x, k))) {
        window.__soak.listeners.add(k);
        o?.signal?.addEventListener('abort', () => window.__soak.listeners.delete(k));
      }
    }
    return add.call(this, type, l, o);
  };
  EventTarget.prototype.removeEventListener = function (type, l, o) {
    if (this === window || this === document) for (const x of [...window.__soak.listeners]) if (same(x, key(this, type, l, o))) window.__soak.listeners.delete(x);
    return remove.call(this, type, l, o);
  };
</script>
<script type="module">
  import '/src/index.js';
  const SEED = ${seed};
  let a = SEED >>> 0;
  const rand = () => { a = (a + 0x6d2b79f5) >>> 0; let t = a; t = Math.imul(t ^ (t >>> 15), t | 1); t ^= t + Math.imul(t ^ (t >>> 7), t | 61); return ((t ^ (t >>> 14)) >>> 0) / 4294967296; };
  const pick = (xs) => xs[Math.floor(rand() * xs.length)];
  const BASE = {
    scene: { width: '16', height: '9', gravity: '0 9.81', iterations: '1', background: '#f7f5f0' },
    cloth: { columns: '14', rows: '10', wind: '2' },
    ragdolls: { count: '3', obstacles: 'stairs' },
  };
  const page = document.createElement('div');
  page.innerHTML = \`
    <physics-scene id="scene" class="scene">
      <physics-box id="floor" static x="8" y="8.6" width="16" height="0.8"></physics-box>
      <physics-box id="b1" x="3" y="2" width="1" height="1"></physics-box>
      <physics-box id="b2" x="5" y="1" width="1.2" height="0.6" angle="20"></physics-box>
      <physics-circle id="c1" x="8" y="1" radius="0.5" restitution="0.5"></physics-circle>
      <physics-circle id="c2" x="10" y="2" radius="0.3"></physics-circle>
      <physics-rope x1="12" y1="0.5" x2="15" y2="0.5" segments="12"></physics-rope>
      <physics-cloth x="1" y="0.5" columns="6" rows="5" spacing="0.3"></physics-cloth>
      <physics-joint a="b1" b="b2"></physics-joint>
    </physics-scene>
    <cloth-sim id="cloth" class="scene"></cloth-sim>
    <ragdoll-sim id="ragdolls" class="scene"></ragdoll-sim>\`;
  document.body.append(page);
  const scene = document.getElementById('scene');
  const cloth = document.getElementById('cloth');
  const ragdolls = document.getElementById('ragdolls');
  const setBase = (el, base) => { for (const [k, v] of Object.entries(base)) el.setAttribute(k, v); };
  setBase(scene, BASE.scene); setBase(cloth, BASE.cloth); setBase(ragdolls, BASE.ragdolls);
  const extras = [];
  const detached = new Map();
  const listeners = [];
  let ops = 0, reconnects = 0, added = 0;
  const shapes = [
    () => \`<physics-box x="\${1 + rand() * 14}" y="\${rand() * 2}" width="\${0.3 + rand()}" height="\${0.3 + rand()}" angle="\${rand() * 90}" fill="hsl(\${Math.floor(rand() * 360)} 60% 50%)"></physics-box>\`,
    () => \`<physics-circle x="\${1 + rand() * 14}" y="\${rand() * 2}" radius="\${0.2 + rand() * 0.4}"></physics-circle>\`,
    () => \`<physics-polygon x="\${1 + rand() * 14}" y="\${rand() * 2}" points="0,0 1,0 0.5,0.8"></physics-polygon>\`,
    () => \`<physics-softbody x="\${2 + rand() * 12}" y="1" radius="0.6" segments="10"></physics-softbody>\`,
    () => \`<physics-ragdoll x="\${2 + rand() * 12}" y="1" height="1.2"></physics-ragdoll>\`,
    () => \`<physics-spring a="b1" b="c1" stiffness="\${10 + rand() * 50}"></physics-spring>\`,
  ];
  const scenes = [scene, cloth, ragdolls];
  const mutations = [
    // Add a body or a link (at most 25 extras), or remove one.
    () => {
      if (extras.length < 25 && rand() < 0.6) {
        const t = document.createElement('template');
        t.innerHTML = pick(shapes)();
        const el = t.content.firstElementChild;
        scene.append(el);
        extras.push(el);
        added++;
      } else if (extras.length) extras.splice(Math.floor(rand() * extras.length), 1)[0].remove();
    },
    () => extras.length && extras.splice(Math.floor(rand() * extras.length), 1)[0].remove(),
    // Attributes of bodies and scenes.
    () => scene.querySelector('#' + pick(['b1', 'b2', 'c1', 'c2'])).setAttribute('fill', pick(['#c0392b', '#2e86de', 'none', 'rebeccapurple'])),
    () => scene.querySelector('#' + pick(['b1', 'b2'])).setAttribute('width', String(0.5 + rand())),
    () => scene.setAttribute('gravity', \`\${(rand() - 0.5) * 4} \${5 + rand() * 10}\`),
    () => scene.setAttribute('iterations', String(1 + Math.floor(rand() * 3))),
    () => scene.setAttribute('background', pick(['#f7f5f0', '#eef', 'none'])),
    () => cloth.setAttribute('wind', String(Math.round((rand() - 0.5) * 8))),
    () => ragdolls.setAttribute('count', String(1 + Math.floor(rand() * 5))),
    () => ragdolls.setAttribute('obstacles', pick(['stairs', 'pegs', 'none'])),
    () => cloth.setAttribute('columns', String(8 + Math.floor(rand() * 10))),
    // Pause and resume.
    () => { const s = pick(scenes); s.paused ? s.play() : s.pause(); },
    // Collision listeners come and go.
    () => {
      if (listeners.length < 4 && rand() < 0.5) { const f = () => {}; scene.addEventListener('physics-collision', f); listeners.push(f); }
      else if (listeners.length) scene.removeEventListener('physics-collision', listeners.pop());
    },
    // A move (disconnect and connect in one task: the engine is kept).
    () => { const s = pick(scenes); if (s.isConnected) { const parent = s.parentNode; const next = s.nextSibling; parent.insertBefore(s, next); } },
    // Disconnect a scene for a while (its worker ends), or connect a disconnected one again (a new worker).
    () => {
      if (detached.size && rand() < 0.7) {
        const [s, where] = detached.entries().next().value;
        detached.delete(s);
        where.parent.insertBefore(s, where.next);
        reconnects++;
      } else {
        const s = pick(scenes);
        if (!s.isConnected) return;
        detached.set(s, { parent: s.parentNode, next: s.nextSibling });
        s.remove();
      }
    },
  ];
  let timer = null;
  const errors = [];
  for (const s of scenes) s.addEventListener('physics-error', (e) => errors.push(\`\${e.detail.attribute}: \${e.detail.message}\`));
  window.soak = {
    start() { timer ??= setInterval(() => { ops++; pick(mutations)(); }, 200); },
    stop() { clearInterval(timer); timer = null; },
    /** Back to the base markup: extras removed, base attributes, every scene connected and running, no extra listeners. */
    async canonical() {
      this.stop();
      for (const el of extras.splice(0)) el.remove();
      for (const [s, where] of detached) where.parent.insertBefore(s, where.next);
      detached.clear();
      for (const f of listeners.splice(0)) scene.removeEventListener('physics-collision', f);
      setBase(scene, BASE.scene); setBase(cloth, BASE.cloth); setBase(ragdolls, BASE.ragdolls);
      for (const id of ['b1', 'b2', 'c1', 'c2']) document.getElementById(id).removeAttribute('fill');
      document.getElementById('b1').setAttribute('width', '1');
      document.getElementById('b2').setAttribute('width', '1.2');
      for (const s of scenes) s.play();
      await Promise.all(scenes.map((s) => s.ready));
      // Every scene steps again.
      const counts = scenes.map((s) => s.stepCount);
      const until = performance.now() + 10000;
      while (scenes.some((s, k) => s.stepCount <= counts[k]) && performance.now() < until) await new Promise((r) => setTimeout(r, 50));
      return scenes.map((s, k) => s.stepCount > counts[k]);
    },
    async counts() {
      const { liveResources } = await import('/src/worker/resources.js');
      const all = document.querySelectorAll('*').length + scenes.reduce((n, s) => n + s.shadowRoot.querySelectorAll('*').length, 0);
      return {
        workers: window.__soak.workersMade - window.__soak.workersTerminated,
        workersMade: window.__soak.workersMade,
        listeners: window.__soak.listeners.size,
        resources: liveResources(),
        elements: all,
        bodies: (await scene.diagnostics()).bodyCount,
        ops, reconnects, added,
        errors: errors.splice(0),
      };
    },
  };
  window.soakReady = true;
</script></head><body></body></html>`;

const check = checker();
const server = await startDevServer();
const browser = await chromium.launch({
  executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
  // Real timers in a page that is not on screen, so the scenes keep stepping for the whole run.
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync', '--disable-background-timer-throttling', '--disable-renderer-backgrounding', '--disable-backgrounding-occluded-windows'],
});
const t0 = Date.now();
const mb = (bytes) => (bytes / 1048576).toFixed(2);
try {
  const page = await browser.newPage({ viewport: { width: 520, height: 900 } });
  const pageErrors = [];
  page.on('pageerror', (e) => pageErrors.push(String(e)));
  page.on('console', (m) => m.type() === 'error' && pageErrors.push(m.text()));
  await page.route(`${server.url}/soak.html`, (route) =>
    route.fulfill({ body: PAGE, contentType: 'text/html', headers: { 'Cross-Origin-Opener-Policy': 'same-origin', 'Cross-Origin-Embedder-Policy': 'require-corp' } }),
  );
  await page.goto(`${server.url}/soak.html`);
  await page.waitForFunction(() => window.soakReady, null, { timeout: 60000 });
  const cdp = await page.context().newCDPSession(page);
  await cdp.send('Performance.enable');

  /** Listeners on an object of the page, as CDP sees them. */
  const cdpListeners = async (expression) => {
    const { result } = await cdp.send('Runtime.evaluate', { expression });
    const { listeners } = await cdp.send('DOMDebugger.getEventListeners', { objectId: result.objectId });
    await cdp.send('Runtime.releaseObject', { objectId: result.objectId });
    return listeners.length;
  };

  const samples = [];
  const sample = async (label) => {
    const stepping = await page.evaluate(() => window.soak.canonical());
    await page.waitForTimeout(1000);
    for (let k = 0; k < 2; k++) await cdp.send('HeapProfiler.collectGarbage');
    const heap = await cdp.send('Runtime.getHeapUsage');
    const metrics = Object.fromEntries((await cdp.send('Performance.getMetrics')).metrics.map((m) => [m.name, m.value]));
    const counts = await page.evaluate(() => window.soak.counts());
    const s = {
      label,
      minute: (Date.now() - t0) / 60000,
      heapMB: heap.usedSize / 1048576,
      workers: counts.workers,
      browserWorkers: page.workers().length,
      listeners: counts.listeners,
      cdpListeners: (await cdpListeners('window')) + (await cdpListeners('document')),
      jsEventListeners: metrics.JSEventListeners,
      nodes: metrics.Nodes,
      elements: counts.elements,
      bodies: counts.bodies,
      ops: counts.ops,
      reconnects: counts.reconnects,
      workersMade: counts.workersMade,
      stepping: stepping.every(Boolean),
      resources: counts.resources,
    };
    samples.push(s);
    console.log(
      `${label.padEnd(10)} t=${s.minute.toFixed(1)} min  heap ${mb(heap.usedSize)} MB  workers ${s.workers} (browser ${s.browserWorkers}, made ${s.workersMade})  ` +
        `listeners ${s.listeners} (CDP window+document ${s.cdpListeners}, page-wide ${s.jsEventListeners})  nodes ${s.nodes}  elements ${s.elements}  bodies ${s.bodies}  ` +
        `mutations ${s.ops}, reconnects ${s.reconnects}${s.stepping ? '' : '  NOT STEPPING'}`,
    );
    await page.evaluate(() => window.soak.start());
  };

  console.log(`browser soak: ${minutes} min, seed ${seed}, warm-up ${(warmupMs / 60000).toFixed(2)} min, a sample every ${(sampleEveryMs / 1000).toFixed(0)} s`);
  await sample('start');
  await page.waitForTimeout(warmupMs);
  await sample('warm');
  while (Date.now() - t0 < totalMs) {
    await page.waitForTimeout(Math.min(sampleEveryMs, Math.max(1000, totalMs - (Date.now() - t0))));
    await sample(Date.now() - t0 >= totalMs ? 'end' : 'sample');
  }

  const warm = samples[1];
  const last = samples[samples.length - 1];
  const after = samples.slice(1);
  const growth = last.heapMB - warm.heapMB;
  const allowed = Math.max(HEAP_TOLERANCE_MB, HEAP_TOLERANCE_FRACTION * warm.heapMB);
  console.log(
    `\nheap after GC: start ${samples[0].heapMB.toFixed(2)} MB, after warm-up ${warm.heapMB.toFixed(2)} MB, end ${last.heapMB.toFixed(2)} MB ` +
      `(growth ${growth >= 0 ? '+' : ''}${growth.toFixed(2)} MB, allowed ${allowed.toFixed(2)} MB; range after warm-up ${Math.min(...after.map((s) => s.heapMB)).toFixed(2)}-${Math.max(...after.map((s) => s.heapMB)).toFixed(2)} MB)`,
  );
  console.log(`${last.ops} markup mutations, ${last.reconnects} reconnects, ${last.workersMade} workers made in ${((Date.now() - t0) / 60000).toFixed(1)} min\n`);
  check(growth <= allowed, `heap growth after warm-up ${growth.toFixed(2)} MB <= ${allowed.toFixed(2)} MB (max of ${HEAP_TOLERANCE_MB} MB and ${HEAP_TOLERANCE_FRACTION * 100}% of ${warm.heapMB.toFixed(2)} MB)`);
  for (const key of ['workers', 'browserWorkers', 'bodies']) {
    const values = after.map((s) => s[key]);
    check(Math.max(...values) <= warm[key], `${key} do not grow after warm-up: ${values.join(', ')}`);
  }
  // Window/document listeners: a few come and go with what is in flight when a sample is taken (seen: 71-75 in a
  // 10-minute run, back to 71 at the end); a leak grows with the mutations, so the last sample may exceed the first
  // after warm-up by at most LISTENER_SLACK.
  for (const key of ['listeners', 'cdpListeners']) {
    const values = after.map((s) => s[key]);
    check(last[key] <= warm[key] + LISTENER_SLACK, `${key} (window + document) do not grow after warm-up: ${values.join(', ')} (last <= first + ${LISTENER_SLACK})`);
  }
  // Page-wide DOM nodes and listeners (Performance.getMetrics) include nodes no longer in the document but not freed:
  // that is how p5 keeping every sketch alive showed (one canvas and about 15 listeners per reconnect, see
  // pinColorDecorators in src/render/renderer.ts). A little slack for what is in flight; --strict allows none.
  for (const [key, slack] of [['nodes', 3], ['jsEventListeners', 10]]) {
    const values = after.map((s) => s[key]);
    const allowed = strict ? 0 : slack;
    check(last[key] <= warm[key] + allowed, `page-wide ${key} do not grow after warm-up: ${values.join(', ')} (last <= first + ${allowed})`);
  }
  // Scenes share the page's worker pool, so a reconnect need not make a worker: count the reconnects themselves.
  check(last.reconnects > 3, `scenes were disconnected and connected again (${last.reconnects} reconnects; ${last.workersMade} workers made, the page's pool)`);
  const nodes = after.map((s) => s.elements);
  check(Math.max(...nodes) <= warm.elements, `elements (page and shadow roots) do not grow: ${nodes.join(', ')}`);
  check(samples.every((s) => s.stepping), 'every scene steps again at every sample');
  check(pageErrors.length === 0, `no page errors${pageErrors.length ? `: ${pageErrors.slice(0, 5).join(' | ')}` : ''}`);
} finally {
  await browser.close();
  await server.stop();
}
if (check.failures.length) {
  console.log(`\n${check.failures.length} check(s) failed`);
  process.exit(1);
}
console.log('browser soak passed');
