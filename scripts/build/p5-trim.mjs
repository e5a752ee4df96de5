// Node-side build helper (not shipped): an esbuild plugin that makes p5 2.x's modular entries (p5/core and the addons
// src/render/p5/modules.js registers) carry only what a 2D canvas uses. Used by src/render/p5/bundle.mjs, so the
// builds, the dev server, the tests and scripts/sizes.mjs all get the same p5.
//
// p5/core is not small on its own: its `rendering` and `graphics` addons (createCanvas, createGraphics) live in one of
// p5's build chunks (dist/rendering-*.js, ~700 KB of source) together with WebGL's renderer, camera, lights,
// materials, framebuffers, image loading and saving, and p5.Graphics registers all of those on its prototype. Seven
// changes, none touching what a 2D sketch or a draw hook calls (docs/drawing.md lists that API):
//
// 1. p5's dist modules (and the CommonJS packages omggif and libtess, which only GIF decoding and WebGL tessellation
//    use) are side-effect free for the bundler: a module none of whose exports are used is left out. p5's core
//    imports ~50 modules bare (`import '../webgl/p5.Shader.js'`) only because its build chunked them so; their
//    top-level code only fills their own tables (or registers them on a global p5, which bundle.mjs defines away).
// 2. p5.Graphics (createGraphics) gets the 2D addons only: shapes, attributes, curves, vertices, custom shapes,
//    colour setting and creation, transforms, trigonometry; not image loading/drawing, pixels, 3D primitives,
//    lights and materials (the main canvas has none of those either: their addons are not registered).
//    createFramebuffer() (WebGL only) throws instead of pulling the WebGL framebuffer in.
// 3. The 2D renderer's filter() back end (a WebGL shader pipeline, reached only through the image addon's filter(),
//    which is not registered) is a stand-in that throws.
// 4. colorjs.io's gamut mapping gets the delta-E methods its default (CSS) mapping uses, not the ones only named
//    presets use (they bring the CAM16, HCT, Jzazbz and ICtCp spaces); p5 never names a preset.
// 5. p5.MediaElement and p5.File (the dom addon's, not registered) are stand-ins (see DOM_STAND_INS).
// 6. p5.Matrix (WebGL's camera and projection; in 2D only createMatrix() and worldToScreen()/screenToWorld() reach
//    it) is a stand-in that throws (MATRIX_STAND_IN).
// 7. p5's CPU image filters (image/filters.js), which the core's p5.Image carries for its filter(), are a stand-in that
//    throws (FILTERS_STAND_IN): a p5.Image comes only from the image addon (get, createImage, loadImage), not loaded.
//
// Measured (esbuild-minified bundle of modules.js, gzip -9): 116.3 KB untrimmed; 1 + 2 give 73.9, 1 + 2 + 3 give 57.5
// (none of them does much alone: p5's own chunks reference each other), 4 takes 4.0 more off (53.5), 5 2.1 (51.4),
// 6 3.7 (47.6), 7 1.5 more (the single file 1,597 bytes smaller, 6 December 2026).
//
// Every change is checked (text edits match as often as expected, stand-ins are used): if p5's or colorjs.io's files
// change shape (a new version), the build fails and says which change no longer applies, instead of shipping an
// untrimmed or broken p5.
import { readFile } from 'node:fs/promises';
import { dirname, join } from 'node:path';

/** p5's code and the CommonJS packages only its image and WebGL parts use. */
const SIDE_EFFECT_FREE = /[\\/]node_modules[\\/](?:p5[\\/]dist|omggif|libtess)[\\/]/;

const NO_WEBGL = "throw new Error(\"createFramebuffer() needs p5's WebGL renderer, which this build of p5 leaves out (docs/drawing.md)\");";

/**
 * Text changes: [file pattern, what, pattern, replacement, how many matches there must be].
 * The patterns match p5 2.3's dist files; the counts make a silent no-op impossible.
 */
const EDITS = [
  [/[\\/]p5[\\/]dist[\\/]rendering-[\w-]+\.js$/, 'p5.Graphics: 2D addons only', /^[ \t]*(?:loadingDisplaying|image|pixels|primitives3D|light|material)\(p5, p5\.Graphics\.prototype\);[ \t]*$/gm, '', 6],
  [/[\\/]p5[\\/]dist[\\/]rendering-[\w-]+\.js$/, 'createFramebuffer() without WebGL', /return new Framebuffer\(this\._renderer, options\);/g, NO_WEBGL, 2],
];

/** What the 2D renderer's `filterRenderer` getter constructs instead of p5's WebGL FilterRenderer2D. */
const FILTER_STAND_IN = `export default class FilterRenderer2D {
  constructor() { throw new Error("filter() needs p5's image addon, which this build of p5 leaves out (docs/drawing.md)"); }
}`;

/**
 * colorjs.io's gamut mapping (toGamut, reached from p5's colour conversions) imports every delta-E method for the
 * presets a caller may name; the default mapping (CSS's, the only one p5 uses) needs deltaEOK and the module names
 * deltaE2000 itself. The other methods bring their colour spaces (CAM16, HCT, Jzazbz, ICtCp).
 */
const DELTA_E_STAND_IN = `import deltaE76 from "./deltaE76.js";
import deltaE2000 from "./deltaE2000.js";
import deltaEOK from "./deltaEOK.js";
export { deltaE76, deltaE2000, deltaEOK };
export default { deltaE76, deltaE2000, deltaEOK };`;

/**
 * p5.MediaElement (createVideo, createAudio) and p5.File (a file dropped on an element) belong to the dom addon, which
 * the builds do not register; the core names them only to test `instanceof MediaElement` and in p5.Element's drop().
 * No MediaElement can exist without the addon, so the test is always false with an empty class.
 */
const DOM_STAND_INS = {
  MediaElement: 'export class MediaElement {}\nexport default function media() {}',
  File: `export class File {
  static _load() { throw new Error("drop() needs p5's dom addon, which this build of p5 leaves out (docs/drawing.md)"); }
}
export default function file() {}`,
};

/**
 * p5.Matrix: the 4×4 and 3×3 matrices of WebGL's camera, which p5's core imports for the 2D renderer's
 * getWorldToScreenMatrix() (worldToScreen(), screenToWorld()) and the math addon's createMatrix(); no drawing call
 * of a 2D sketch (transforms use the canvas' own) constructs one.
 */
const MATRIX_STAND_IN = `export class Matrix {
  constructor() { throw new Error("p5.Matrix (createMatrix, worldToScreen) needs p5's WebGL code, which this build of p5 leaves out (docs/drawing.md)"); }
}`;

/**
 * p5's CPU image filters (p5.Image's filter(), the pixels addon's): the 2D core imports them for p5.Image, which only
 * the image addon's functions (get, loadImage, createImage) make; that addon is not registered.
 */
const FILTERS_STAND_IN = `export default {
  apply() { throw new Error("filter() needs p5's image addon, which this build of p5 leaves out (docs/drawing.md)"); }
};`;

export function p5Trim() {
  return {
    name: 'p5-trim',
    setup(build) {
      const applied = new Map(EDITS.map((e) => [e, 0]));
      const standIns = { filterRenderer2D: 0, filters: 0, deltaE: 0, MediaElement: 0, File: 0, Matrix: 0 };
      build.onStart(() => {
        applied.forEach((_, e) => applied.set(e, 0));
        for (const k in standIns) standIns[k] = 0;
      });

      build.onResolve({ filter: /filterRenderer2D\.js$/ }, (args) =>
        /[\\/]p5[\\/]dist[\\/]/.test(args.importer) ? (standIns.filterRenderer2D++, { path: 'filterRenderer2D', namespace: 'p5-trim' }) : null,
      );
      build.onLoad({ filter: /^filterRenderer2D$/, namespace: 'p5-trim' }, () => ({ contents: FILTER_STAND_IN, loader: 'js' }));

      build.onResolve({ filter: /(?:^|\/)image\/filters\.js$|^\.\/filters\.js$/ }, (args) =>
        /[\\/]p5[\\/]dist[\\/]/.test(args.importer) ? (standIns.filters++, { path: 'filters', namespace: 'p5-trim' }) : null,
      );
      build.onLoad({ filter: /^filters$/, namespace: 'p5-trim' }, () => ({ contents: FILTERS_STAND_IN, loader: 'js' }));

      build.onResolve({ filter: /(?:^|\/)p5\.(?:MediaElement|File)\.js$/ }, (args) => {
        if (!/[\\/]p5[\\/]dist[\\/]/.test(args.importer)) return null;
        const name = /MediaElement/.test(args.path) ? 'MediaElement' : 'File';
        standIns[name]++;
        return { path: name, namespace: 'p5-trim' };
      });
      build.onLoad({ filter: /^(?:MediaElement|File)$/, namespace: 'p5-trim' }, (args) => ({ contents: DOM_STAND_INS[args.path], loader: 'js' }));

      build.onResolve({ filter: /(?:^|\/)Matrices\/Matrix\.js$/ }, (args) =>
        /[\\/]p5[\\/]dist[\\/]/.test(args.importer) ? (standIns.Matrix++, { path: 'Matrix', namespace: 'p5-trim' }) : null,
      );
      build.onLoad({ filter: /^Matrix$/, namespace: 'p5-trim' }, () => ({ contents: MATRIX_STAND_IN, loader: 'js' }));

      build.onResolve({ filter: /^\.\/deltaE\/index\.js$/ }, (args) =>
        /[\\/]colorjs\.io[\\/]src[\\/]toGamut\.js$/.test(args.importer)
          ? (standIns.deltaE++, { path: 'deltaE', namespace: 'p5-trim', pluginData: { resolveDir: join(dirname(args.importer), 'deltaE') } })
          : null,
      );
      build.onLoad({ filter: /^deltaE$/, namespace: 'p5-trim' }, (args) => ({ contents: DELTA_E_STAND_IN, loader: 'js', resolveDir: args.pluginData.resolveDir }));

      // Mark resolved modules side-effect free (esbuild's onResolve can say so; package.json's sideEffects would too).
      build.onResolve({ filter: /.*/ }, async (args) => {
        if (args.pluginData?.p5Trim || args.kind === 'entry-point') return null;
        const { path, importer, namespace, resolveDir, kind, with: attributes } = args;
        const r = await build.resolve(path, { importer, namespace, resolveDir, kind, with: attributes, pluginData: { p5Trim: true } });
        if (r.errors.length) return { errors: r.errors };
        const { errors, warnings, ...resolved } = r;
        return { ...resolved, pluginData: args.pluginData, ...(SIDE_EFFECT_FREE.test(r.path) ? { sideEffects: false } : {}) };
      });

      build.onLoad({ filter: /[\\/]p5[\\/]dist[\\/].*\.js$/ }, async (args) => {
        const edits = EDITS.filter(([file]) => file.test(args.path));
        if (edits.length === 0) return null;
        let code = await readFile(args.path, 'utf8');
        for (const edit of edits) {
          const [, , pattern, replacement] = edit;
          code = code.replace(pattern, () => (applied.set(edit, applied.get(edit) + 1), replacement));
        }
        return { contents: code, loader: 'js' };
      });

      build.onEnd((result) => {
        for (const [name, n] of Object.entries(standIns)) {
          if (n === 0) result.errors.push({ text: `p5-trim: the ${name} stand-in was never used (p5's or colorjs.io's files changed: update scripts/build/p5-trim.mjs)` });
        }
        for (const [edit, n] of applied) {
          if (n !== edit[4]) {
            result.errors.push({ text: `p5-trim: "${edit[1]}" matched ${n} times, expected ${edit[4]} (p5's files changed: update scripts/build/p5-trim.mjs)` });
          }
        }
      });
    },
  };
}
