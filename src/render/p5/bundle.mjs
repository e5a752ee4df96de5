// Node-side build helper (not shipped): bundles modules.js (p5's core and the addons the renderer ships) into one
// minified ES module whose default export stands for p5. p5's modular entries import CommonJS packages (omggif,
// libtess) that neither Rollup without a CommonJS plugin nor the dev server can load, so esbuild makes one module;
// scripts/build/p5-trim.mjs leaves out what p5's core carries for WebGL and images (about half of it).
// Used by rollup.config.js and web-dev-server.config.js (as what the bare specifier 'p5' resolves to) and scripts/sizes.mjs.
//
// p5's code runs on first use, not when the page loads the script: it is most of the single file's evaluation (its
// modules build prototypes, colour spaces and constants at import), and the first use is the first canvas, which a
// scene makes after the page's first paint. The default export is a stand-in for the p5 class: `new`, reading or
// setting a static (p5.disableFriendlyErrors, p5.registerAddon, …) run p5's code once and forward to the class.
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
import { p5Trim } from '../../../scripts/build/p5-trim.mjs';

/** The file the bundle is made from (modules.js). */
export const P5_MODULES = fileURLToPath(new URL('./modules.js', import.meta.url));

/** The global name esbuild's IIFE assigns; here a local of load(), never a global. */
const NAME = '__p5Modules';

let pending = null;

/** The bundle's code (made once per process). */
export function bundleP5() {
  pending ??= build({
    entryPoints: [P5_MODULES],
    bundle: true,
    format: 'iife',
    globalName: NAME,
    minify: true,
    target: 'es2022',
    platform: 'browser',
    // p5's modules end with `typeof p5 !== "undefined" && addon(p5, p5.prototype)` for the classic build, where p5 is
    // a global. In a page a global p5 can be someone else's (another p5, or an element with id="p5"): the addon then
    // throws at import. Here p5 is never a global: the free name p5 is undefined (module bindings are not touched).
    define: { p5: 'undefined' },
    // p5's core without WebGL, image loading and the other parts a 2D canvas never reaches (scripts/build/p5-trim.mjs).
    // NO_P5_TRIM=1 in the environment bundles p5 untrimmed, to tell whether a p5 problem comes from the trim.
    plugins: process.env.NO_P5_TRIM ? [] : [p5Trim()],
    write: false,
    logLevel: 'silent',
  }).then(({ outputFiles: [file] }) =>
    [
      'let loaded = null;',
      `function load() { if (!loaded) { ${file.text.trim()}; loaded = ${NAME}.default; } return loaded; }`,
      'export default new Proxy(function p5() {}, {',
      '  construct: (_, args) => Reflect.construct(load(), args),',
      '  apply: (_, self, args) => Reflect.apply(load(), self, args),',
      '  get: (_, key) => load()[key],',
      '  set: (_, key, value) => ((load()[key] = value), true),',
      '  has: (_, key) => key in load(),',
      '});',
    ].join('\n'),
  );
  return pending;
}
