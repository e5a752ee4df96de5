// Builds (npm run build):
//  dist/engine/index.js             the headless engine, no dependencies (physics-elements/engine)
//  dist/lib/index.js                the element library, lit/comlink/p5 left to the consumer's bundler, worker as its own chunk
//  dist/physics-elements.bundle.js  one self-contained file for <script type="module" src="...">, worker inlined as a blob: URL
//  dist/physics-elements.no-p5.js   the same without p5 (size report only; needs an import map for 'p5')
import { rollup } from 'rollup';
import nodeResolve from '@rollup/plugin-node-resolve';
import terser from '@rollup/plugin-terser';
import { transform } from 'esbuild';
import { existsSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = dirname(fileURLToPath(import.meta.url));
const P5_ESM = resolve(root, 'node_modules/p5/lib/p5.esm.min.js');

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

/** p5 v2's package entry imports CommonJS dependencies; use its self-contained ESM build (or leave it external). */
function p5Esm({ external = false } = {}) {
  return {
    name: 'p5-esm',
    resolveId(source) {
      if (source === 'p5') return external ? { id: 'p5', external: true } : P5_ESM;
      return null;
    },
  };
}

const basePlugins = (opts = {}) => [p5Esm(opts), esbuildTs(), nodeResolve({ browser: true })];

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
          const bundle = await rollup({ input: resolved.id, plugins: [...basePlugins(), terser()] });
          const { output } = await bundle.generate({ format: 'es', inlineDynamicImports: true });
          await bundle.close();
          for (const f of bundle.watchFiles ?? []) this.addWatchFile(f);
          replacement = `new Worker(URL.createObjectURL(new Blob([${JSON.stringify(output[0].code)}], { type: 'text/javascript' }))`;
        } else {
          const ref = this.emitFile({ type: 'chunk', id: resolved.id, name: 'engine.worker' });
          replacement = `new Worker(import.meta.ROLLUP_FILE_URL_${ref}`;
        }
        out += code.slice(last, m.index) + replacement;
        last = m.index + m[0].length;
      }
      return { code: out + code.slice(last), map: null };
    },
  };
}

const external = [/^lit/, /^@lit/, 'comlink', 'p5'];

export default [
  {
    input: { index: 'src/engine/index.ts' },
    output: { dir: 'dist/engine', format: 'es', sourcemap: true },
    plugins: [esbuildTs(), terser()],
  },
  {
    input: { index: 'src/index.ts' },
    external,
    output: { dir: 'dist/lib', format: 'es', sourcemap: true, chunkFileNames: '[name]-[hash].js' },
    plugins: [...basePlugins({ external: true }), worker(), terser()],
  },
  {
    input: 'src/index.ts',
    output: { file: 'dist/physics-elements.bundle.js', format: 'es', inlineDynamicImports: true },
    plugins: [...basePlugins(), worker({ inline: true }), terser()],
  },
  {
    input: 'src/index.ts',
    output: { file: 'dist/physics-elements.no-p5.js', format: 'es', inlineDynamicImports: true },
    plugins: [...basePlugins({ external: true }), worker({ inline: true }), terser()],
  },
];
