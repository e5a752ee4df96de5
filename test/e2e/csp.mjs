// End-to-end: both builds under a strict Content-Security-Policy (no 'unsafe-eval', no 'unsafe-inline').
//
// 1. The single-file build, loaded from another origin (a "CDN" on localhost; the page on 127.0.0.1), under
//      script-src 'self' <the script's origin>; worker-src blob:
//    and 'none' for everything else (default-src 'none': no inline styles, no images, no connections; the page's own
//    stylesheet is style-src 'self', its own script 'self').
// 2. The ESM library (dist/lib) as an app's bundler ships it: Rollup resolves lit and comlink, keeps the worker chunk a
//    separate same-origin file, and leaves p5 (the app's own, unpatched) as /p5.js, so the policy is
//    script-src 'self'; worker-src 'self'. p5 2.x itself tries `new Function("")` once at import (its bundled zod
//    checks whether it may compile validators; the try fails harmlessly): that one script-src eval violation, from
//    /p5.js, is expected and reported as p5's. The single-file build ships p5 with that try removed.
// 3. The single-file build without blob: in worker-src: the worker cannot start; each element warns, sends a
//    `physics-error` and runs its engine on the main thread, and still animates. The one violation is the worker's.
// 4. The single-file build under a nonce-based policy (script-src 'nonce-…' 'strict-dynamic', no worker-src): the
//    trusted script may start its blob: worker, nothing else is needed.
// 5. The single-file build without 'wasm-unsafe-eval': the WebAssembly solver kernel (the scenes' default, kernel
//    "auto") may not compile; the scenes run the JS kernel, warn once per worker (no physics-error), and still
//    animate. The only violations are the refused compilations. Every other policy allows 'wasm-unsafe-eval', and
//    there the scenes' diagnostics() say the WebAssembly kernel runs.
//
// Each page: the elements animate (the canvas changes), the engine runs where expected (`mode` is 'worker' only once
// the worker has answered), and no CSP violation is reported (securitypolicyviolation events in the page, and the
// browser's reports to report-uri, which include the worker's). Run after `npm run build`: node test/e2e/csp.mjs
import { readFileSync, readdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { rollup } from 'rollup';
import nodeResolve from '@rollup/plugin-node-resolve';
import { animates, artifacts, checker, collectProblems, launch, listen, root } from './harness.mjs';

const started = Date.now();
const elapsed = () => `${((Date.now() - started) / 1000).toFixed(1)} s`;
const check = checker();

// The ESM library as an app bundles it (lit and comlink from node_modules; the worker chunk stays a file; p5 is /p5.js).
const lib = resolve(root, 'dist/lib');
const workerFile = readdirSync(lib)
  .filter((f) => f.endsWith('.js'))
  .map((f) => /new URL\(\s*["'](?:\.\/)?(engine\.worker-[\w-]+\.js)["']/.exec(readFileSync(resolve(lib, f), 'utf8'))?.[1])
  .find(Boolean);
if (!workerFile) throw new Error('dist/lib has no worker chunk: run npm run build');
const appId = '\0app';
const appBundle = await rollup({
  input: { app: appId, [workerFile.slice(0, -3)]: resolve(lib, workerFile) },
  external: ['p5'],
  onwarn: () => {},
  plugins: [
    {
      name: 'app',
      resolveId: (s) => (s === appId ? appId : null),
      load: (id) => (id === appId ? `import ${JSON.stringify(resolve(lib, 'index.js'))};` : null),
    },
    nodeResolve({ browser: true }),
  ],
});
const appFiles = new Map();
for (const o of (await appBundle.generate({ format: 'es', entryFileNames: '[name].js', chunkFileNames: 'chunk-[hash].js', paths: { p5: '/p5.js' } })).output) {
  if (o.type === 'chunk') appFiles.set(`/app/${o.fileName}`, o.code);
}
await appBundle.close();
appFiles.set('/p5.js', readFileSync(resolve(root, 'node_modules/p5/lib/p5.esm.min.js')));

// The "CDN" for the single file: localhost, its own port, CORS for any origin.
const bundle = readFileSync(resolve(root, 'dist/physics-elements.bundle.js'));
const cdn = await listen('localhost', (req, res) => {
  if (req.url === '/physics-elements.bundle.js') {
    res.writeHead(200, { 'content-type': 'text/javascript', 'access-control-allow-origin': '*' });
    res.end(bundle);
  } else {
    res.writeHead(404);
    res.end();
  }
});
const cdnOrigin = `http://localhost:${cdn.address().port}`;

const POLICIES = {
  single: `default-src 'none'; script-src 'self' ${cdnOrigin} 'wasm-unsafe-eval'; worker-src blob:; style-src 'self'`,
  lib: `default-src 'none'; script-src 'self' 'wasm-unsafe-eval'; worker-src 'self'; style-src 'self'`,
  'single-no-blob': `default-src 'none'; script-src 'self' ${cdnOrigin} 'wasm-unsafe-eval'; worker-src 'self'; style-src 'self'`,
  'single-nonce': `default-src 'none'; script-src 'nonce-e2e' 'strict-dynamic' 'wasm-unsafe-eval'; style-src 'self'`,
  'single-no-wasm': `default-src 'none'; script-src 'self' ${cdnOrigin}; worker-src blob:; style-src 'self'`,
};
const SINGLE = `<script type="module" src="${cdnOrigin}/physics-elements.bundle.js"></script>`;
const SCRIPTS = {
  single: SINGLE,
  lib: `<script type="module" src="/app/app.js"></script>`,
  'single-no-blob': SINGLE,
  'single-nonce': `<script type="module" nonce="e2e" src="${cdnOrigin}/physics-elements.bundle.js"></script>`,
  'single-no-wasm': SINGLE,
};
const page = (name) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>csp ${name}</title>
<link rel="stylesheet" href="/page.css">
<script src="/listen.js" nonce="e2e"></script>
${SCRIPTS[name]}</head>
<body>
<p>${name}: ${POLICIES[name]}</p>
<cloth-sim class="embed" id="cloth" columns="16" rows="10" pins="top" wind="2"></cloth-sim>
<ragdoll-sim class="embed" id="ragdolls" count="3"></ragdoll-sim>
</body></html>`;
// Runs before the module script: records physics-error events and CSP violations seen by the page.
const listenJs = `window.physicsErrors = []; window.violations = [];
document.addEventListener('physics-error', (e) => physicsErrors.push({ id: e.target.id, message: e.detail.message }), true);
document.addEventListener('securitypolicyviolation', (e) => violations.push(e.violatedDirective + ' ' + e.blockedURI + ' (' + e.sourceFile + ':' + e.lineNumber + ':' + e.columnNumber + ')'), true);`;
const css = 'body { margin: 20px; font: 14px system-ui; } .embed { width: 560px; height: 350px; margin-bottom: 16px; }';

const reports = []; // CSP reports the browser posts to report-uri (from the page and from its workers)
const site = await listen('127.0.0.1', (req, res) => {
  const url = new URL(req.url, 'http://x');
  const name = url.pathname.slice(1).replace(/\.html$/, '');
  const send = (type, body, headers = {}) => {
    res.writeHead(200, { 'content-type': type, ...headers });
    res.end(body);
  };
  if (req.method === 'POST' && url.pathname === '/csp-report') {
    let body = '';
    req.on('data', (c) => (body += c));
    req.on('end', () => {
      try {
        const r = JSON.parse(body)['csp-report'];
        const where = r['source-file'] ? ` (${r['source-file']}:${r['line-number']}:${r['column-number']})` : '';
        reports.push({ page: url.searchParams.get('page'), text: `${r['effective-directive'] ?? r['violated-directive']} ${r['blocked-uri']}${where}` });
      } catch {
        reports.push({ page: url.searchParams.get('page'), text: body });
      }
      res.writeHead(204);
      res.end();
    });
  } else if (POLICIES[name]) {
    send('text/html', page(name), { 'content-security-policy': `${POLICIES[name]}; report-uri /csp-report?page=${name}` });
  } else if (url.pathname === '/page.css') send('text/css', css);
  else if (url.pathname === '/listen.js') send('text/javascript', listenJs);
  else if (appFiles.has(url.pathname)) send('text/javascript', appFiles.get(url.pathname));
  else {
    res.writeHead(url.pathname === '/favicon.ico' ? 204 : 404);
    res.end();
  }
});
const siteUrl = `http://127.0.0.1:${site.address().port}`;

const browser = await launch();
try {
  for (const name of Object.keys(POLICIES)) {
    const fallback = name === 'single-no-blob';
    const noWasm = name === 'single-no-wasm';
    console.log(`-- ${name} (${elapsed()}): ${POLICIES[name]}`);
    const tab = await browser.newPage({ viewport: { width: 620, height: 820 } });
    const problems = collectProblems(tab);
    await tab.goto(`${siteUrl}/${name}.html`);
    const info = await tab.evaluate(async () => {
      await Promise.all([customElements.whenDefined('cloth-sim'), customElements.whenDefined('ragdoll-sim')]);
      const out = {};
      for (const id of ['cloth', 'ragdolls']) {
        const el = document.getElementById(id);
        await el.ready;
        const d = await el.diagnostics();
        out[id] = { mode: el.mode, kernel: d.kernel, reason: d.kernelReason };
      }
      return out;
    });
    const modes = Object.fromEntries(Object.entries(info).map(([id, d]) => [id, d.mode]));
    const kernels = Object.values(info).map((d) => d.kernel);
    if (noWasm) {
      check(kernels.every((k) => k === 'js') && Object.values(info).every((d) => /wasm-unsafe-eval/.test(d.reason)), `${name}: WebAssembly refused, the scenes run the JS kernel and say why (${kernels.join(', ')}: ${info.cloth.reason.slice(-80)})`);
    } else {
      check(kernels.every((k) => k === 'wasm'), `${name}: the scenes run the WebAssembly kernel (${kernels.join(', ')})`);
    }
    for (const id of ['cloth', 'ragdolls']) check(await animates(tab, id), `${name}: #${id} animates`);
    await tab.screenshot({ path: resolve(artifacts, `csp-${name}.png`) });
    await new Promise((r) => setTimeout(r, 300)); // let the last reports arrive
    const seen = await tab.evaluate(() => ({ errors: physicsErrors, violations }));
    const reported = reports.filter((r) => r.page === name).map((r) => r.text);
    await tab.close();
    const violations = [...new Set([...seen.violations, ...reported])];
    if (noWasm) {
      check(modes.cloth === 'worker' && modes.ragdolls === 'worker', `${name}: the engines run in workers (${JSON.stringify(modes)})`);
      const refused = (v) => /^script-src(-elem)? wasm-eval/.test(v);
      check(violations.length > 0 && violations.every(refused), `${name}: the only violations are the refused WebAssembly compilations (${violations.join('; ')})`);
      const warnings = problems.filter((p) => p.startsWith('warning:') && /WebAssembly kernel cannot run/.test(p));
      check(warnings.length >= 1 && warnings.length <= 2, `${name}: one warning per worker that runs the scenes (${warnings.length}: ${warnings[0]?.slice(0, 160)})`);
      check(seen.errors.length === 0, `${name}: no physics-error (${seen.errors.map((e) => e.message).join('; ')})`);
      const other = problems.filter((p) => !/WebAssembly kernel cannot run|Content Security Policy|WebAssembly/.test(p));
      check(other.length === 0, `${name}: no other console errors${other.length ? `:\n  ${other.join('\n  ')}` : ''}`);
    } else if (!fallback) {
      check(modes.cloth === 'worker' && modes.ragdolls === 'worker', `${name}: the engines run in workers (${JSON.stringify(modes)})`);
      // The app's own p5 (dist/lib leaves p5 to the app): its zod's eval try at import, nothing else.
      const p5Probe = (v) => name === 'lib' && /^script-src(-elem)? eval .*\/p5\.js:/.test(v);
      if (name === 'lib') check(violations.filter(p5Probe).length <= 1, `${name}: p5's own eval try at import (expected, not ours): ${violations.filter(p5Probe).join('; ') || 'none'}`);
      const ours = violations.filter((v) => !p5Probe(v));
      check(ours.length === 0, `${name}: no CSP violations${ours.length ? `: ${ours.join('; ')}` : ''}`);
      const other = problems.filter((p) => !(name === 'lib' && /unsafe-eval/.test(p)));
      check(other.length === 0 && seen.errors.length === 0, `${name}: no console errors or warnings, no physics-error${other.length + seen.errors.length ? `:\n  ${[...other, ...seen.errors.map((e) => e.message)].join('\n  ')}` : ''}`);
    } else {
      check(modes.cloth === 'main' && modes.ragdolls === 'main', `${name}: the engines fall back to the main thread (${JSON.stringify(modes)})`);
      const errorIds = seen.errors.filter((e) => /main thread/.test(e.message)).map((e) => e.id).sort();
      check(errorIds.join() === 'cloth,ragdolls', `${name}: each element sends a physics-error about it (${seen.errors.map((e) => `#${e.id}: ${e.message}`).join('; ')})`);
      const warnings = problems.filter((p) => p.startsWith('warning:') && /main thread/.test(p));
      check(warnings.length >= 2, `${name}: and warns in the console (${warnings.length} warnings)`);
      check(violations.length > 0 && violations.every((v) => /^worker-src blob/.test(v)), `${name}: the only violations are the blocked blob: workers (${violations.join('; ')})`);
      const other = problems.filter((p) => !/main thread|Content Security Policy|Refused to create a worker/.test(p));
      check(other.length === 0, `${name}: no other console errors${other.length ? `:\n  ${other.join('\n  ')}` : ''}`);
    }
  }
} finally {
  await browser.close();
  cdn.close();
  site.close();
}
console.log(`csp: ${check.failures.length ? `${check.failures.length} failed` : 'all passed'} in ${((Date.now() - started) / 1000).toFixed(1)} s; screenshots in artifacts/csp-*.png`);
process.exit(check.failures.length ? 1 : 0);
