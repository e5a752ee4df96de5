// Sizes of the builds in dist/ (run `npm run build` first), raw and `gzip -9`, in KB = 1024 bytes. Prints the README's
// table (`node scripts/sizes.mjs`), or the numbers as JSON (`--json`); `--check` (CI) also fails when a build is over
// its budget (BUDGETS below).
//
// - The single files are measured as they are.
// - The ESM library is measured twice: as its files (what a page without a bundler fetches with an import map:
//   dist/lib/index.js, every chunk it imports and the worker chunk), and as an app's bundler ships it for
//   `import 'physics-elements'` (Rollup + terser, tree-shaken, package.json's sideEffects honoured; lit and p5
//   left out). The second is "engine + elements" as the page evaluates them: the elements, the renderer, the worker
//   client and what they use of the engine (body models, checks); the engine itself is a chunk the page imports only
//   for the main-thread fallback (measured on its own row) and the worker chunk runs it (not counted: it is the same
//   engine, in the worker).
// - lit + comlink as the elements use them, and p5: the pieces the builds ship (src/render/p5/modules.js, bundled by
//   src/render/p5/bundle.mjs, which leaves out the WebGL and image code of p5's core with scripts/build/p5-trim.mjs:
//   the same module the builds inline) and the whole library, for comparison.
// - p5's share of the single file: the file with p5 minus the same file without it.
// - The WebAssembly kernel's share of the single file (issue 16: at most 10 KB gzip): the single-file build (with p5)
//   minus the same build with src/engine/kernel/choice.ts replaced by a stub that always answers 'js' (same API, so
//   the kernel's modules, wasm-kernel.ts, runs.ts, colour.ts and wasm-bytes.ts, drop out), both built here in memory
//   from rollup.config.js's singleFile(); and the module's own bytes (wasm-bytes.ts decoded), raw and gzip.
import { execFileSync } from 'node:child_process';
import { existsSync, readFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { rollup } from 'rollup';
import nodeResolve from '@rollup/plugin-node-resolve';
import terser from '@rollup/plugin-terser';
import { bundleP5 } from '../src/render/p5/bundle.mjs';
import { singleFile } from '../rollup.config.js';
import { readKernelBytes } from './build-wasm.mjs';

/**
 * The budgets the issues set, in gzip bytes, that `--check` holds the builds to: the single file with p5 (issue 15:
 * at most 175 KB) and what the WebAssembly kernel adds to it (issue 16: at most 10 KB). KB = 1024 bytes.
 */
const BUDGETS = { singleFile: 175 * 1024, kernelShare: 10 * 1024 };

const root = resolve(dirname(fileURLToPath(import.meta.url)), '..');
const dist = resolve(root, 'dist');
const gzip = (bytes) => execFileSync('gzip', ['-9c'], { input: bytes, maxBuffer: 1 << 28 }).length;

function fileSize(file) {
  if (!existsSync(file)) throw new Error(`${file} is missing: run npm run build`);
  const bytes = readFileSync(file);
  return { file: file.slice(root.length + 1), raw: bytes.length, gzip: gzip(bytes) };
}

/** A chunk of dist/lib and the chunks it loads: static imports, and worker URLs (new URL('x.js', import.meta.url)). */
function libFiles(entry) {
  const seen = new Set();
  const visit = (file) => {
    if (seen.has(file)) return;
    seen.add(file);
    const code = readFileSync(file, 'utf8');
    const deps = [
      ...[...code.matchAll(/(?:\bfrom|\bimport)\s*["'](\.\.?\/[^"']+)["']/g)].map((m) => m[1]),
      ...[...code.matchAll(/new URL\(\s*["']([^"':]+\.js)["']\s*,\s*import\.meta\.url\s*\)/g)].map((m) => m[1]),
    ];
    for (const d of deps) visit(resolve(dirname(file), d));
  };
  visit(entry);
  return [...seen];
}

/**
 * Bundles `code` (an app's entry module) with Rollup + terser as an app would; `external` stays out. Returns the entry
 * chunk (what the page loads and evaluates at once) and, apart, the chunks it only imports dynamically (`lazy`).
 */
async function bundled(name, code, external = []) {
  const id = '\0app';
  const bundle = await rollup({
    input: id,
    external,
    onwarn: () => {},
    plugins: [{ name: 'app', resolveId: (s) => (s === id ? id : null), load: (i) => (i === id ? code : null) }, nodeResolve({ browser: true }), terser()],
  });
  const { output } = await bundle.generate({ format: 'es' });
  await bundle.close();
  const measure = (chunk, file) => {
    const bytes = Buffer.from(chunk.code);
    return { file, raw: bytes.length, gzip: gzip(bytes) };
  };
  const entry = output.find((c) => c.type === 'chunk' && c.isEntry);
  const lazy = output.filter((c) => c.type === 'chunk' && !c.isEntry);
  const chunkFiles = new Set(lazy.map((c) => c.fileName));
  if (entry.imports.some((f) => chunkFiles.has(f))) throw new Error(`${name}: the entry imports chunks statically (${entry.imports.join(', ')}); count them`);
  return { entry: measure(entry, name), lazy: lazy.map((c) => measure(c, `${name}, chunk loaded on demand (${c.name})`)) };
}

const rows = [];
const add = (name, files) => rows.push({ name, files, raw: files.reduce((s, p) => s + p.raw, 0), gzip: files.reduce((s, p) => s + p.gzip, 0) });

add('single file, with p5 (the CMS embed)', [fileSize(resolve(dist, 'physics-elements.bundle.js'))]);
add('single file, without p5 (lit and comlink inside; p5 from an import map)', [fileSize(resolve(dist, 'physics-elements.no-p5.js'))]);
add('ESM library, its files as a page loads them unbundled (lit and p5 from an import map; comlink is a chunk of its own)', libFiles(resolve(dist, 'lib/index.js')).map(fileSize));
const lib = JSON.stringify(resolve(dist, 'lib/index.js'));
{
  const app = await bundled('app bundle', `import ${lib};`, [/^lit/, /^@lit/, 'p5']);
  add('**engine + elements, as the page evaluates them**: the ESM library in an app\'s bundle (`import \'physics-elements\'`), without lit and p5 (comlink, 1.5 KB, is in it)', [app.entry]);
  // The engine itself runs in the worker (its own chunk, not counted here); the page imports it only to run the
  // engine on its own thread when no worker can start (src/worker/client.ts, startMain).
  add('the engine on the page, loaded only when no worker can start (main-thread fallback)', app.lazy);
}
add('headless engine only', [fileSize(resolve(dist, 'engine/index.js'))]);
// What the elements import from lit and comlink (src/ imports lit, lit/decorators.js, lit/directives/if-defined.js).
const deps = 'export * from "lit"; export * from "lit/decorators.js"; export * from "lit/directives/if-defined.js"; export * as Comlink from "comlink";';
add('lit + comlink (for comparison)', [(await bundled('lit + comlink', deps)).entry]);
{
  const bytes = Buffer.from(await bundleP5());
  add('p5 as the builds ship it: core + shape + color + math, 2D only (docs/drawing.md)', [{ file: 'src/render/p5/modules.js, bundled and trimmed', raw: bytes.length, gzip: gzip(bytes) }]);
}
const p5 = resolve(root, 'node_modules/p5/lib/p5.esm.min.js');
if (existsSync(p5)) add('all of p5 (for comparison)', [fileSize(p5)]);
const [withP5, withoutP5] = rows;
const share = { raw: withP5.raw - withoutP5.raw, gzip: withP5.gzip - withoutP5.gzip };

/** src/engine/kernel/choice.ts's API with no kernel: every World runs the JS solver. */
function kernelStub() {
  const choice = resolve(root, 'src/engine/kernel/choice.ts');
  const STUB = '\0kernel-stub';
  return {
    name: 'kernel-stub',
    resolveId(source, importer) {
      if (!importer || !source.startsWith('.') || !source.endsWith('.js')) return null;
      return resolve(dirname(importer), source.slice(0, -3) + '.ts') === choice ? STUB : null;
    },
    load(id) {
      if (id !== STUB) return null;
      return `import { oneOf } from ${JSON.stringify(resolve(root, 'src/engine/validate.ts'))};
export const KERNELS = ['js', 'wasm', 'auto'];
let fallback = 'js';
export function setDefaultKernel(kernel) { const next = oneOf('kernel', kernel, KERNELS), previous = fallback; fallback = next; return previous; }
export function defaultKernel() { return fallback; }
export function chooseKernel(choice = fallback) {
  const requested = oneOf('kernel', choice, KERNELS);
  return { kernel: null, diagnostics: { kernel: 'js', requested, reason: requested === 'js' ? '' : 'this build has no WebAssembly kernel' } };
}
export function resetKernelModule() {}`;
    },
  };
}

/** The single file (ES module, with p5) built in memory, with `extra` plugins. */
async function singleFileBytes(extra) {
  const config = singleFile(extra);
  const bundle = await rollup({ ...config, onwarn: () => {} });
  const { output } = await bundle.generate({ format: 'es', inlineDynamicImports: true });
  await bundle.close();
  return Buffer.from(output[0].code);
}
const withKernel = await singleFileBytes([]);
const withoutKernel = await singleFileBytes([kernelStub()]);
if (withKernel.length === withoutKernel.length) throw new Error('kernel stub: the single file did not change (was choice.ts resolved elsewhere?)');
const moduleBytes = readKernelBytes();
const kernel = {
  raw: withKernel.length - withoutKernel.length,
  gzip: gzip(withKernel) - gzip(withoutKernel),
  singleFile: { raw: withKernel.length, gzip: gzip(withKernel) },
  module: { raw: moduleBytes.length, gzip: gzip(moduleBytes) },
};

if (process.argv.includes('--json')) {
  console.log(JSON.stringify({ rows, p5Share: share, kernelShare: kernel }, null, 2));
} else {
  const kb = (n) => (n / 1024).toFixed(1);
  const many = (r, key) => (r.files.length > 1 ? ` (${r.files.map((p) => kb(p[key])).join(' + ')})` : '');
  console.log('| build | file(s) | raw | gzip |\n| --- | --- | ---: | ---: |');
  for (const r of rows) {
    const files = r.files.map((p) => (p.file.includes('/') ? '`' + p.file.replace(/^node_modules\//, '').replace(/-[\w-]{8}\.js$/, '-[hash].js') + '`' : p.file)).join(' + ');
    console.log(`| ${r.name} | ${files} | ${kb(r.raw)} KB${many(r, 'raw')} | **${kb(r.gzip)} KB**${many(r, 'gzip')} |`);
  }
  console.log(`\np5's share of the single file: ${kb(share.gzip)} KB of ${kb(withP5.gzip)} KB gzip (${((100 * share.gzip) / withP5.gzip).toFixed(0)}%), ${kb(share.raw)} KB raw.`);
  console.log(
    `The WebAssembly kernel's share of the single file: ${kb(kernel.gzip)} KB gzip (${kernel.gzip} bytes), ${kb(kernel.raw)} KB raw ` +
      `(the file built with it minus without it, ${kb(kernel.singleFile.gzip)} KB gzip with it); the module itself ` +
      `${kernel.module.raw} bytes, ${kernel.module.gzip} gzip.`,
  );
}

if (process.argv.includes('--check')) {
  const checks = [
    ['the single file with p5', withP5.gzip, BUDGETS.singleFile],
    ["the WebAssembly kernel's share of the single file", kernel.gzip, BUDGETS.kernelShare],
  ];
  let over = 0;
  for (const [what, bytes, budget] of checks) {
    const ok = bytes <= budget;
    if (!ok) over++;
    console.log(`${ok ? 'within' : 'OVER'} budget: ${what}, ${bytes} bytes gzip of ${budget} (${budget - bytes} left)`);
  }
  if (over > 0) process.exit(1);
}
