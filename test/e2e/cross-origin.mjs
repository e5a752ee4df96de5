// End-to-end: the single-file build embedded across origins, as a CMS page would use it from a CDN.
// A page served from 127.0.0.1 on one port loads dist/physics-elements.bundle.js from localhost on another port
// (CORS allowed, as a CDN does). <cloth-sim> and <ragdoll-sim> must run their engine in a worker (the worker is a
// blob: URL, so the other origin does not matter), animate (the canvas changes between frames), follow a mouse drag,
// and log no console errors. Screenshots go to artifacts/. Run after `npm run build`: node test/e2e/cross-origin.mjs
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { animates, artifacts, checker, collectProblems, launch, listen, root, serveFiles } from './harness.mjs';

const bundle = readFileSync(resolve(root, 'dist/physics-elements.bundle.js'));
const started = Date.now();

// The "CDN": localhost, its own port, CORS for any origin (module scripts from another origin need it).
const cdn = await listen('localhost', (req, res) => {
  if (req.url === '/physics-elements.bundle.js') {
    res.writeHead(200, { 'content-type': 'text/javascript', 'access-control-allow-origin': '*' });
    res.end(bundle);
  } else {
    res.writeHead(404);
    res.end();
  }
});
const cdnUrl = `http://localhost:${cdn.address().port}/physics-elements.bundle.js`;

// The "CMS page": 127.0.0.1, another port, no COOP/COEP headers (so no SharedArrayBuffer: transferred buffers).
const page = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>embed</title>
<style>body { margin: 20px; font: 14px system-ui; } .embed { width: 560px; height: 350px; margin-bottom: 16px; }</style>
<script type="module" src="${cdnUrl}"></script></head>
<body>
<p>A blog post with two embeds.</p>
<cloth-sim class="embed" id="cloth" columns="16" rows="10" pins="top" wind="2"></cloth-sim>
<ragdoll-sim class="embed" id="ragdolls" count="3"></ragdoll-sim>
<cloth-sim class="embed" id="fallback" worker="none" columns="8" rows="5" style="height: 150px"></cloth-sim>
</body></html>`;
const site = await serveFiles('127.0.0.1', { '/': page, '/index.html': page });
const siteUrl = `http://127.0.0.1:${site.address().port}/`;

const browser = await launch();
const check = checker();
const failures = check.failures;
try {
  const tab = await browser.newPage({ viewport: { width: 620, height: 1000 } });
  const errors = collectProblems(tab);
  await tab.goto(siteUrl);
  const info = await tab.evaluate(async () => {
    await Promise.all([customElements.whenDefined('cloth-sim'), customElements.whenDefined('ragdoll-sim')]);
    const out = {};
    for (const id of ['cloth', 'ragdolls', 'fallback']) {
      const el = document.getElementById(id);
      await el.ready;
      out[id] = { mode: el.mode, transport: el.transport, origin: location.origin };
    }
    return out;
  });
  console.log(JSON.stringify(info));
  check(info.cloth.mode === 'worker' && info.ragdolls.mode === 'worker', 'both engines run in a worker (blob: URL) on a page of another origin');
  check(info.fallback.mode === 'main', 'worker="none": the main-thread engine (the same engine code as the worker\'s) runs');
  check(info.cloth.transport === 'transfer', 'no cross-origin isolation: frames come as transferred ArrayBuffers');

  for (const id of ['cloth', 'ragdolls', 'fallback']) check(await animates(tab, id), `#${id} animates: the canvas changes between frames`);
  await tab.screenshot({ path: resolve(artifacts, 'cross-origin-1.png') });

  // Drag the bottom-middle of the cloth 160 px to the right with the mouse.
  const before = await tab.evaluate(async () => {
    const el = document.getElementById('cloth');
    const cloth = el.shadowRoot.querySelector('physics-cloth');
    // The live position of the bottom-middle particle (row 9, column 7), read from the draw hook's view.
    const p = await new Promise((ok) => {
      el.drawHook = (v) => {
        const i = v.topology.bodies[0].indices[9 * 16 + 7];
        ok({ x: v.positions[2 * i], y: v.positions[2 * i + 1] });
        el.drawHook = null;
      };
    });
    return { pose: cloth.x, at: el.worldToClient(p.x, p.y) };
  });
  await tab.mouse.move(before.at.x, before.at.y);
  await tab.mouse.down();
  for (let k = 1; k <= 16; k++) await tab.mouse.move(before.at.x + 10 * k, before.at.y, { steps: 1 });
  const after = await tab.evaluate(async (x0) => {
    const cloth = document.getElementById('cloth').shadowRoot.querySelector('physics-cloth');
    const until = performance.now() + 5000;
    while (cloth.x < x0 + 0.5 && performance.now() < until) await new Promise((r) => requestAnimationFrame(r));
    return cloth.x;
  }, before.pose);
  await tab.screenshot({ path: resolve(artifacts, 'cross-origin-2-drag.png') });
  await tab.mouse.up();
  check(after > before.pose + 0.5, `a mouse drag moves the cloth (centre x ${before.pose.toFixed(2)} -> ${after.toFixed(2)})`);
  check(errors.length === 0, `no console errors or warnings${errors.length ? `:\n  ${errors.join('\n  ')}` : ''}`);
} finally {
  await browser.close();
  cdn.close();
  site.close();
}
console.log(`cross-origin embed: ${failures.length ? `${failures.length} failed` : 'all passed'} in ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in artifacts/`);
process.exit(failures.length ? 1 : 0);
