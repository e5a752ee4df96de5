// End-to-end: the package in an app, built by the bundlers app developers use (docs/embedding.md, "With a bundler").
//
// The tarball (`npm pack --ignore-scripts` of the dist/ just built) is installed into an empty app folder, and three
// apps are built from it there:
// - Vite 6 and webpack 5 bundle `import 'physics-elements'` (the ES module library), p5 aliased to
//   `physics-elements/p5` (the pieces the renderer draws with) as the docs say. Both must find the engine worker
//   (`new Worker(new URL('./…', import.meta.url))` in dist/lib) and bundle it as a worker of its own: when a bundler
//   misses it (as webpack did with Rollup's `new URL(…).href`), it copies the file as an asset whose bare `comlink`
//   import cannot load, and every scene warns and runs on the main thread.
// - esbuild, which does not follow that pattern, bundles `import 'physics-elements/bundle'` (the single file, whose
//   worker is a blob: URL of its own code).
// Each app is served and opened in Chromium: a <cloth-sim> and a <physics-scene> must run their engine in a worker,
// their canvases change, and the console stays clean.
// Usage: node test/e2e/bundlers.mjs   (after `npm run build`)
import { execFileSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, readdirSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { extname, join, normalize } from 'node:path';
import { build as esbuild } from 'esbuild';
import { build as vite } from 'vite';
import webpack from 'webpack';
import { animates, artifacts, checker, launch, listen, root } from './harness.mjs';

const started = Date.now();
const elapsed = () => `${((Date.now() - started) / 1000).toFixed(1)} s`;
const check = checker();
const work = mkdtempSync(join(tmpdir(), 'physics-elements-bundlers-'));
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 1 << 26 });

if (!existsSync(join(root, 'dist/lib/index.js'))) throw new Error('dist/ is missing: run npm run build first');
const [packed] = JSON.parse(npm(['pack', '--json', '--ignore-scripts', '--pack-destination', work], root).replace(/^[^[]*/, ''));
const app = join(work, 'app');
mkdirSync(app);
writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'app', private: true, type: 'module' }));
// Its dependencies (lit, comlink, p5) come from npm's cache, filled when this repository's own were installed.
npm(['install', join(work, packed.filename), '--prefer-offline', '--no-audit', '--no-fund'], app);
console.log(`${packed.filename} installed into an empty app (${elapsed()})`);

const page = (title, script) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>${title}</title><link rel="icon" href="data:,"></head>
<body><h1>${title}</h1>
<cloth-sim id="cloth" style="display:block;width:480px"></cloth-sim>
<physics-scene id="scene" width="12" height="9" style="display:block;width:480px">
  <physics-box x="6" y="8.6" width="12" height="0.8" static></physics-box>
  <physics-circle x="4" y="1" radius="0.5"></physics-circle>
  <physics-box x="7" y="0" width="1" height="1" angle="0.4"></physics-box>
</physics-scene>
${script}
</body></html>`;
writeFileSync(join(app, 'library.js'), "import 'physics-elements';\n");
writeFileSync(join(app, 'single-file.js'), "import 'physics-elements/bundle';\n");

// ---- the builds --------------------------------------------------------------------------------------------------

const builds = {};

async function timed(name, make) {
  const t = Date.now();
  try {
    await make();
    builds[name] = join(app, `dist-${name}`);
    console.log(`${name}: built (${((Date.now() - t) / 1000).toFixed(1)} s)`);
  } catch (e) {
    check(false, `${name}: the app builds (${String(e.message ?? e).split('\n')[0]})`);
  }
}

await timed('vite', async () => {
  writeFileSync(join(app, 'index.html'), page('Vite', '<script type="module" src="./library.js"></script>'));
  await vite({
    root: app,
    configFile: false,
    logLevel: 'error',
    // Exactly `p5` (not `p5/core`, which the aliased module imports).
    resolve: { alias: [{ find: /^p5$/, replacement: 'physics-elements/p5' }] },
    build: { outDir: join(app, 'dist-vite'), emptyOutDir: true, chunkSizeWarningLimit: 4096 },
  });
});

await timed('webpack', async () => {
  const compiler = webpack({
    mode: 'production',
    context: app,
    entry: './library.js',
    output: { path: join(app, 'dist-webpack'), filename: 'main.js', clean: true },
    performance: { hints: false },
    resolve: { alias: { p5$: 'physics-elements/p5' } },
  });
  const stats = await new Promise((ok, fail) => compiler.run((err, s) => (err ? fail(err) : ok(s))));
  await new Promise((ok) => compiler.close(ok));
  if (stats.hasErrors()) throw new Error(stats.toString({ all: false, errors: true }));
  writeFileSync(join(app, 'dist-webpack/index.html'), page('webpack', '<script src="./main.js"></script>'));
});

await timed('esbuild', async () => {
  mkdirSync(join(app, 'dist-esbuild'));
  await esbuild({ absWorkingDir: app, entryPoints: ['single-file.js'], bundle: true, minify: true, format: 'esm', outfile: 'dist-esbuild/main.js', logLevel: 'error' });
  writeFileSync(join(app, 'dist-esbuild/index.html'), page('esbuild', '<script type="module" src="./main.js"></script>'));
});

// What each bundler made of the engine worker: its own chunk (a worker bundle), never the library's file copied as it is.
const emitted = (name) => (builds[name] ? readdirSync(join(builds[name], name === 'vite' ? 'assets' : '.')) : []);
for (const name of ['vite', 'webpack']) {
  const dir = join(builds[name] ?? '-', name === 'vite' ? 'assets' : '.');
  const copied = emitted(name).filter((f) => f.endsWith('.js') && /\bfrom\s*["']comlink["']|import\s*["']comlink["']/.test(readFileSync(join(dir, f), 'utf8')));
  if (builds[name]) check(copied.length === 0, `${name}: no file still imports bare "comlink" (the worker was bundled, not copied)${copied.length ? `: ${copied.join(', ')}` : ''}`);
}

// ---- each app in Chromium ----------------------------------------------------------------------------------------

const TYPES = { '.html': 'text/html; charset=utf-8', '.js': 'text/javascript; charset=utf-8' };
const browser = await launch();
try {
  for (const [name, dir] of Object.entries(builds)) {
    const server = await listen('127.0.0.1', (req, res) => {
      const path = new URL(req.url, 'http://x').pathname;
      const file = normalize(join(dir, decodeURIComponent(path === '/' ? '/index.html' : path)));
      if (!file.startsWith(dir + '/') || !existsSync(file)) {
        res.writeHead(404);
        res.end();
        return;
      }
      res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
      res.end(readFileSync(file));
    });
    const tab = await browser.newPage({ viewport: { width: 640, height: 900 } });
    const problems = [];
    tab.on('console', (m) => ['error', 'warning'].includes(m.type()) && problems.push(`${m.type()}: ${m.text()}`));
    tab.on('pageerror', (e) => problems.push(`pageerror: ${e}`));
    tab.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    tab.on('response', (r) => r.status() >= 400 && problems.push(`${r.status()}: ${r.url()}`));
    try {
      await tab.goto(`http://127.0.0.1:${server.address().port}/`);
      const modes = await tab.evaluate(async () => {
        const defined = await Promise.race([customElements.whenDefined('physics-scene').then(() => true), new Promise((r) => setTimeout(() => r(false), 20000))]);
        if (!defined) return null;
        const out = {};
        for (const id of ['cloth', 'scene']) {
          const el = document.getElementById(id);
          await Promise.race([el.ready, new Promise((r) => setTimeout(r, 20000))]);
          out[id] = el.mode;
        }
        return out;
      });
      check(modes !== null, `${name}: the app defines the elements`);
      if (modes) {
        check(modes.cloth === 'worker' && modes.scene === 'worker', `${name}: both engines run in a worker (${modes.cloth}, ${modes.scene})`);
        for (const id of ['cloth', 'scene']) check(await animates(tab, id), `${name}: #${id}'s canvas changes`);
      }
      check(problems.length === 0, `${name}: no console errors or warnings${problems.length ? `:\n  ${problems.join('\n  ')}` : ''}`);
      await tab.screenshot({ path: join(artifacts, `bundlers-${name}.png`) });
    } finally {
      await tab.close();
      server.close();
    }
  }
} finally {
  await browser.close();
  rmSync(work, { recursive: true, force: true });
}
console.log(`bundlers: ${check.failures.length ? `${check.failures.length} failed` : 'all passed'} in ${elapsed()}; screenshots in artifacts/`);
process.exit(check.failures.length ? 1 : 0);
