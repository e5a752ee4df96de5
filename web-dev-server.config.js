// Shared by the demo server (`npm start`) and the test runner: TypeScript through esbuild, p5 as the builds ship it,
// `.js` worker URLs mapped to their `.ts` sources, optional cross-origin isolation (COOP/COEP), and `/` sent to the gallery.
import { esbuildPlugin } from '@web/dev-server-esbuild';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { bundleP5 } from './src/render/p5/bundle.mjs';

const root = fileURLToPath(new URL('.', import.meta.url));

/** COOP/COEP make the page cross-origin isolated, which is what unlocks SharedArrayBuffer. */
export function crossOriginIsolation({ when = () => true } = {}) {
  return (ctx, next) => {
    if (when(ctx)) {
      ctx.set('Cross-Origin-Opener-Policy', 'same-origin');
      ctx.set('Cross-Origin-Embedder-Policy', 'require-corp');
    }
    return next();
  };
}

/** `new Worker(new URL('./x.worker.js', import.meta.url))` in TS sources: serve x.worker.ts when no .js exists. */
export function jsToTs(ctx, next) {
  if ((ctx.path.startsWith('/src/') || ctx.path.startsWith('/demo/') || ctx.path.startsWith('/test/')) && ctx.path.endsWith('.js')) {
    const js = root + ctx.path.slice(1);
    if (!existsSync(js) && existsSync(js.slice(0, -3) + '.ts')) ctx.url = ctx.url.replace(/\.js(?=$|\?)/, '.ts');
  }
  return next();
}

/**
 * 'p5' is the p5 the builds ship: its core and the addons the renderer uses, made into one module by
 * src/render/p5/bundle.mjs (p5's package entry imports CommonJS a browser cannot load), so the tests and the gallery
 * draw with what a page gets.
 */
const P5_PIECES = '/__p5-pieces.js';
export const p5Esm = {
  name: 'p5-pieces',
  resolveImport({ source }) {
    if (source === 'p5') return P5_PIECES;
  },
  async serve(context) {
    if (context.path === P5_PIECES) return { body: await bundleP5(), type: 'js' };
  },
};

/** `/` is not a page: send it to the gallery, so the address the server prints works. (Dev server only: the test
 * runner serves its own pages at `/`.) */
export function rootToDemo(ctx, next) {
  if (ctx.path === '/') return ctx.redirect('/demo/');
  return next();
}

export const plugins = [p5Esm, esbuildPlugin({ ts: true, target: 'es2022', tsconfig: root + 'tsconfig.json' })];

export default {
  rootDir: root,
  nodeResolve: true,
  appIndex: undefined,
  middleware: [rootToDemo, crossOriginIsolation(), jsToTs],
  plugins,
};
