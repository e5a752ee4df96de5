// Node-side build helper (not shipped): bundles modules.js (p5's core and the addons the renderer ships) into one
// minified ES module whose default export is p5. p5's modular entries import CommonJS packages (omggif, libtess) that
// neither Rollup without a CommonJS plugin nor the dev server can load, so esbuild makes one ES module of them.
// Used by rollup.config.js and web-dev-server.config.js (as what the bare specifier 'p5' resolves to) and scripts/sizes.mjs.
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';

/** The file the bundle is made from (modules.js). */
export const P5_MODULES = fileURLToPath(new URL('./modules.js', import.meta.url));

let pending = null;

/** The bundle's code (made once per process). */
export function bundleP5() {
  pending ??= build({
    entryPoints: [P5_MODULES],
    bundle: true,
    format: 'esm',
    minify: true,
    target: 'es2022',
    platform: 'browser',
    // p5's modules end with `typeof p5 !== "undefined" && addon(p5, p5.prototype)` for the classic build, where p5 is
    // a global. In a page a global p5 can be someone else's (another p5, or an element with id="p5"): the addon then
    // throws at import. Here p5 is never a global: the free name p5 is undefined (module bindings are not touched).
    define: { p5: 'undefined' },
    write: false,
    logLevel: 'silent',
  }).then((result) => result.outputFiles[0].text);
  return pending;
}
