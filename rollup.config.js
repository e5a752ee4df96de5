// Builds (npm run build):
//  dist/engine/index.js             the headless engine, no dependencies (physics-elements/engine)
//  dist/lib/index.js                the element library, lit/comlink/p5 left to the consumer's bundler, worker as its own chunk
//  dist/physics-elements.iife.js    one self-contained classic script for a plain <script src="..."> (what a blog or CMS
//                                   page copies), worker inlined as a blob: URL; its exports on window.PhysicsElements
//  dist/physics-elements.bundle.js  the same as an ES module, for <script type="module" src="...">; both export the
//                                   elements, not the headless engine's API (that is dist/engine)
//  dist/physics-elements.no-p5.js   the same without p5 (size report only; needs an import map for 'p5')
// Sizes: npm run sizes (scripts/sizes.mjs).
import { rollup } from 'rollup';
import nodeResolve from '@rollup/plugin-node-resolve';
import terser from '@rollup/plugin-terser';
import { transform } from 'esbuild';
import { existsSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { bundleP5 } from './src/render/p5/bundle.mjs';

const root = dirname(fileURLToPath(import.meta.url));

/**
 * terser for every build (the engine factory inside the single file too). Measured on the single file (gzip -9, KB,
 * against terser's defaults with module: true, which @rollup/plugin-terser sets for ES outputs): passes: 2 saves 0.3;
 * a third pass nothing. Left out: pure_getters: true (0.3 KB, but it lets terser drop property reads, and lit, p5 and
 * the DOM have getters with effects), unsafe_* (under 0.1 KB each), hoist_funs (costs 1 KB), property mangling (no
 * name in this code base is provably internal: the worker protocol, comlink, the manifest and p5 all reach properties
 * by name).
 */
const minify = () => terser({ ecma: 2020, compress: { passes: 2 }, mangle: { nth_identifier: FIXED_NAMES } });

/**
 * Mangled names in one fixed order (English letter frequency), where terser's default orders the letters by how often
 * each occurs in the whole output file: a change to one module then renamed every variable of the file, and the
 * sizes of its parts (the WebAssembly kernel's share, issue 16) moved by tens of bytes with unrelated code. Plain
 * functions, no closure: @rollup/plugin-terser sends its options to worker threads as source text.
 */
const FIXED_NAMES = {
  get: function (n) {
    const leading = 'etaoinsrlcdhupmfgbyvwkxqjzETAOINSRLCDHUPMFGBYVWKXQJZ$_';
    const all = leading + '0123456789';
    let name = leading[n % 54];
    n = Math.floor(n / 54);
    while (n > 0) {
      n--;
      name += all[n % 64];
      n = Math.floor(n / 64);
    }
    return name;
  },
  consider: function () {},
  reset: function () {},
  sort: function () {},
};

/** TypeScript → JavaScript with esbuild (TypeScript 7 has no JS API for @rollup/plugin-typescript). */
function esbuildTs() {
  return {
    name: 'esbuild-ts',
    resolveId(source, importer) {
      if (importer && source.startsWith('.') && source.endsWith('.js')) {
        const ts = resolve(dirname(importer), source.slice(0, -3) + '.ts');
        if (existsSync(ts)) return ts;
      }
      return null;
    },
    async transform(code, id) {
      if (!id.endsWith('.ts')) return null;
      const out = await transform(code, {
        loader: 'ts', format: 'esm', target: 'es2022', sourcemap: true, sourcefile: id,
        tsconfigRaw: { compilerOptions: { experimentalDecorators: true, useDefineForClassFields: false } },
      });
      return { code: out.code, map: out.map };
    },
  };
}

/**
 * p5 in pieces: the bare specifier 'p5' is src/render/p5/modules.js (p5's core and the addons the renderer ships, see
 * docs/drawing.md) made into one ES module by esbuild (src/render/p5/bundle.mjs: p5's modules import CommonJS packages;
 * there p5 never looks for a global p5, which an element with id="p5" would be; scripts/build/p5-trim.mjs leaves out
 * the WebGL and image code p5's core carries). About 46 KB gzip against 304 KB for p5's lib/p5.esm.min.js. Left
 * external (external = true) for the library and the no-p5 size build.
 */
function p5Pieces({ external = false } = {}) {
  const P5_PIECES = '\0p5-pieces';
  return {
    name: 'p5-pieces',
    resolveId(source) {
      if (source === 'p5') return external ? { id: 'p5', external: true } : P5_PIECES;
      return null;
    },
    load(id) {
      return id === P5_PIECES ? bundleP5() : null;
    },
  };
}

const basePlugins = (opts = {}) => [p5Pieces(opts), esbuildTs(), nodeResolve({ browser: true })];

/**
 * `new Worker(new URL('./x.worker.js', import.meta.url), ...)`: Rollup does not follow it by itself. Emit the worker
 * as a chunk (inline = false) or bundle it into one string and load it from a blob: URL (inline = true), which is what
 * lets a page on one origin run a script served from another.
 */
function worker({ inline = false } = {}) {
  const pattern = /new\s+Worker\(\s*new\s+URL\(\s*(['"`])([^'"`]+)\1\s*,\s*import\.meta\.url\s*\)/g;
  return {
    name: 'worker',
    async transform(code, id) {
      if (!pattern.test(code)) return null;
      pattern.lastIndex = 0;
      let out = '';
      let last = 0;
      for (const m of code.matchAll(pattern)) {
        const resolved = await this.resolve(m[2], id);
        if (!resolved) this.error(`cannot resolve worker ${m[2]} from ${id}`);
        let replacement;
        if (inline) {
          // The worker's code is the shared engine function (see sharedEngine()).
          if (!out.startsWith('import { __peWorkerUrl }')) out = `import { __peWorkerUrl } from ${JSON.stringify(ENGINE_FACTORY)};\n` + out;
          replacement = 'new Worker(__peWorkerUrl()';
        } else {
          const ref = this.emitFile({ type: 'chunk', id: resolved.id, name: 'engine.worker' });
          replacement = `new Worker(import.meta.ROLLUP_FILE_URL_${ref}`;
        }
        out += code.slice(last, m.index) + replacement;
        last = m.index + m[0].length;
      }
      return { code: out + code.slice(last), map: null };
    },
    // The emitted chunk's address written as `new URL('./…', import.meta.url)`, a URL the Worker takes as it is, not
    // Rollup's default `new URL('…', import.meta.url).href`: webpack 5 bundles a worker only when it sees exactly
    // `new Worker(new URL('./…', import.meta.url))` (with `.href` it copied the file, whose bare `comlink` import
    // cannot load; Vite took both). test/e2e/bundlers.mjs builds apps with both.
    resolveFileUrl({ relativePath, format }) {
      if (inline || format !== 'es') return null;
      const path = relativePath.startsWith('.') ? relativePath : `./${relativePath}`;
      return `new URL(${JSON.stringify(path)}, import.meta.url)`;
    },
  };
}

/** Modules of the engine that both the worker and the page use. */
const SHARED_ENGINE = ['src/engine/index.ts', 'src/worker/engine-host.ts', 'src/worker/publishers.ts', 'src/worker/triple-buffer.ts'].map((f) => resolve(root, f));
const ENGINE_FACTORY = '\0engine-factory';
const COMLINK_FROM_FACTORY = '\0comlink-from-engine-factory';
const NO_ENGINE_API = '\0no-engine-api';
const ENTRY = resolve(root, 'src/index.ts');
const ENGINE_INDEX = resolve(root, 'src/engine/index.ts');

/**
 * One copy of the engine in the single-file build. src/worker/engine-bundle.ts (the worker's code and what the page
 * takes from it) is bundled once and wrapped in a function: the page calls it for the headless engine and the main-thread
 * fallback (every import of a SHARED_ENGINE module resolves to its exports), and the worker is a blob: URL of the same
 * function's source text. Before, the engine was in the file twice (the worker's string and the page's code).
 *
 * The function returns only what src/worker/engine-bundle.ts exports (what page code imports from those modules), so
 * the rest of the engine is tree-shaken. For that the single-file builds do not re-export the headless engine's API
 * (src/index.ts's `export * from './engine/index.js'` becomes an empty module here): a page that wants it imports
 * physics-elements/engine. A page module that imports an engine name the function does not return fails the build
 * ("... is not exported by \0engine-factory"): add that name to engine-bundle.ts.
 */
function sharedEngine(extra = []) {
  let factory = null;
  return {
    name: 'shared-engine',
    async buildStart() {
      const bundle = await rollup({ input: resolve(root, 'src/worker/engine-bundle.ts'), plugins: [...extra, ...basePlugins(), minify()] });
      const { output } = await bundle.generate({ format: 'es', inlineDynamicImports: true });
      for (const f of bundle.watchFiles ?? []) this.addWatchFile(f);
      await bundle.close();
      const chunk = output[0];
      // The chunk ends with its export statement; it becomes the function's return value.
      const m = /export\s*\{([^}]*)\}\s*;?\s*$/.exec(chunk.code);
      if (!m || /\bimport\.meta\b|^\s*import[\s{*]/m.test(chunk.code)) this.error('engine factory: expected one trailing export statement and no imports');
      const entries = m[1].split(',').map((spec) => spec.trim()).filter(Boolean).map((spec) => {
        const [local, exported = local] = spec.split(/\s+as\s+/);
        return `${JSON.stringify(exported)}:${local}`;
      });
      factory = { body: chunk.code.slice(0, m.index), returns: entries.join(','), exports: chunk.exports.filter((n) => n !== 'default') };
    },
    resolveId(source, importer) {
      if (source === ENGINE_FACTORY) return ENGINE_FACTORY;
      if (source === COMLINK_FROM_FACTORY) return COMLINK_FROM_FACTORY;
      if (source === 'comlink' && importer !== ENGINE_FACTORY) return COMLINK_FROM_FACTORY;
      if (!importer || importer === ENGINE_FACTORY || !source.startsWith('.') || !source.endsWith('.js')) return null;
      const target = resolve(dirname(importer), source.slice(0, -3) + '.ts');
      if (importer === ENTRY && target === ENGINE_INDEX) return NO_ENGINE_API;
      return SHARED_ENGINE.includes(target) ? ENGINE_FACTORY : null;
    },
    async load(id) {
      if (id === NO_ENGINE_API) return 'export {};';
      if (id === COMLINK_FROM_FACTORY) {
        const names = Object.keys(await import('comlink')).filter((n) => n !== 'default');
        return `import { __comlink } from ${JSON.stringify(ENGINE_FACTORY)};\n${names.map((n) => `export const ${n} = __comlink.${n};`).join('\n')}`;
      }
      if (id !== ENGINE_FACTORY) return null;
      return [
        `function __peEngine(){${factory.body};return{${factory.returns}}}`,
        'const __pe = __peEngine();',
        WORKER_SCRIPT,
        ...factory.exports.map((n) => `export const ${n} = __pe.${n};`),
      ].join('\n');
    },
  };
}

/**
 * The worker's script in the single-file build: the engine function's source text, called, as a blob: URL made once
 * per page and shared by every pool worker. Encoding that text (about 180,000 characters) into one Blob took 20-80 ms
 * on the loaded machine, mostly to flatten "(" + source + ")()" into one string, so the source is never concatenated:
 * it is encoded ahead in slices of WORKER_PIECE characters (slices of the script's own text, ~1 ms each, the first up
 * to ~10-40 ms), WORKER_SLICE_MS of them per task, from the script's evaluation on (a scene starts its engine only after
 * the page's first paint and its canvas); a worker wanted before the last slice encodes the rest at once. Slices end
 * between characters, never inside a surrogate pair.
 */
const WORKER_PIECE = 16384;
/** Milliseconds of encoding per task, at most one slice more. */
const WORKER_SLICE_MS = 6;
const WORKER_SCRIPT = `
const __peSource = __peEngine.toString();
const __pePieces = ["("];
let __peEncoded = 0;
let __peUrl = null;
function __peEncodePiece() {
  let end = Math.min(__peEncoded + ${WORKER_PIECE}, __peSource.length);
  const last = __peSource.charCodeAt(end - 1);
  if (end < __peSource.length && last >= 0xd800 && last <= 0xdbff) end--;
  __pePieces.push(new Blob([__peSource.slice(__peEncoded, end)]));
  __peEncoded = end;
  return __peEncoded < __peSource.length;
}
setTimeout(function encodeAhead() {
  const until = performance.now() + ${WORKER_SLICE_MS};
  while (__peUrl === null && __peEncodePiece()) if (performance.now() > until) return void setTimeout(encodeAhead, 0);
}, 0);
export function __peWorkerUrl() {
  if (__peUrl === null) {
    while (__peEncoded < __peSource.length) __peEncodePiece();
    __peUrl = URL.createObjectURL(new Blob([...__pePieces, ")()"], { type: "text/javascript" }));
  }
  return __peUrl;
}`;

const external = [/^lit/, /^@lit/, 'comlink', 'p5'];
/**
 * The ES module library leaves lit and p5 to the app (or the page's import map) but carries comlink, in a chunk the
 * page and the worker chunk share: a module worker does not see the page's import map, so a bare `comlink` import in
 * the worker chunk failed to load on a page without a bundler and every scene fell back to the main thread.
 */
const libExternal = external.filter((e) => e !== 'comlink');

/**
 * The library's small modules that both the page and the worker use (frame buffers, the protocol, body models and
 * checks) go in a chunk of their own, apart from the engine: otherwise Rollup puts them in the engine's chunk and a
 * page that imports the elements loads the whole engine, which it needs only for the main-thread fallback
 * (src/worker/client.ts imports it on demand). An app's bundler sees each of dist/lib's chunks as one module.
 */
const PAGE_SIDE = ['worker/triple-buffer', 'worker/publishers', 'worker/protocol', 'worker/resources', 'engine/builders/common', 'engine/builders/ragdoll', 'engine/options', 'engine/validate'].map((f) => resolve(root, `src/${f}.ts`));
const pageSideChunk = (id) => (PAGE_SIDE.includes(id) ? 'shared' : /[\\/]node_modules[\\/]comlink[\\/]/.test(id) ? 'comlink' : undefined);

/** The single-file build's input and plugins; `extra` plugins go first in both of its builds (the engine function's and
 *  the page's). scripts/sizes.mjs builds it with a plugin that swaps the WebAssembly kernel for a stub. */
export function singleFile(extra = []) {
  return { input: 'src/index.ts', plugins: [...extra, sharedEngine(extra), ...basePlugins(), worker({ inline: true }), minify()] };
}

export default [
  {
    input: { index: 'src/engine/index.ts' },
    output: { dir: 'dist/engine', format: 'es', sourcemap: true },
    plugins: [esbuildTs(), minify()],
  },
  {
    input: { index: 'src/index.ts' },
    external: libExternal,
    output: { dir: 'dist/lib', format: 'es', sourcemap: true, chunkFileNames: '[name]-[hash].js', manualChunks: pageSideChunk },
    plugins: [...basePlugins({ external: true }), worker(), minify()],
  },
  {
    ...singleFile(),
    // One build, two files: the same code as an ES module and as a classic script (its exports on window.PhysicsElements).
    output: [
      { file: 'dist/physics-elements.bundle.js', format: 'es', inlineDynamicImports: true },
      { file: 'dist/physics-elements.iife.js', format: 'iife', name: 'PhysicsElements', inlineDynamicImports: true },
    ],
  },
  {
    input: 'src/index.ts',
    output: { file: 'dist/physics-elements.no-p5.js', format: 'es', inlineDynamicImports: true },
    plugins: [sharedEngine(), ...basePlugins({ external: true }), worker({ inline: true }), minify()],
  },
];
