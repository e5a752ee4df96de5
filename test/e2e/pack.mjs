// End-to-end: the package as npm ships it, embedded the way a blogger would.
//
// 1. `npm pack` (its prepack builds) makes the tarball. Its files must hold the three browser builds, the types, the
//    manifest and the README; package.json must not be private. The README's first HTML snippet must load a file the
//    tarball holds, at this version's CDN address.
// 2. The tarball is installed into an empty folder (`npm install <tarball>`, npm's cache first; with no registry at
//    all, the tarball is unpacked there instead, as the browser builds need nothing else), and that
//    folder is served from a second origin (a "CDN" on localhost, with CORS, at jsDelivr's path layout; and once more
//    without CORS).
// 3. Pages on the first origin (127.0.0.1) embed the installed files: the README's snippet as written (the classic
//    script, dist/physics-elements.iife.js, in a plain <script src>), the same from the CDN without CORS, and the ES
//    module single file with <script type="module">. In each, <cloth-sim> and <ragdoll-sim> run their engine in a
//    worker (a blob: URL, so the other origin does not matter), their canvases change, and the console stays clean.
//    The ES module file in a plain <script src> (the mix-up the README warns about) must fail with a SyntaxError.
//
// In Chromium (playwright-core) and in Firefox ESR (puppeteer-core over WebDriver BiDi) where /usr/bin/firefox-esr is
// installed (`apt-get install -y firefox-esr`); without it the Firefox part prints SKIP and why.
// Usage: node test/e2e/pack.mjs [--no-build]   (--no-build: npm pack --ignore-scripts, for a dist/ just built)
import { execFileSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, extname, join, normalize, resolve } from 'node:path';
import { animates, artifacts, checker, launch, listen, root } from './harness.mjs';

const started = Date.now();
const elapsed = () => `${((Date.now() - started) / 1000).toFixed(1)} s`;
const check = checker();
const pkg = JSON.parse(readFileSync(resolve(root, 'package.json'), 'utf8'));
const work = mkdtempSync(join(tmpdir(), 'physics-elements-pack-'));
const npm = (args, cwd) => execFileSync('npm', args, { cwd, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'], maxBuffer: 1 << 26 });

// ---- 1. the tarball ----------------------------------------------------------------------------------------------

check(pkg.private !== true, 'package.json is not private');
check(/\bnpm run build\b/.test(pkg.scripts?.prepack ?? ''), `prepack builds ("${pkg.scripts?.prepack}")`);
const build = !process.argv.includes('--no-build');
console.log(`npm pack${build ? ' (prepack: npm run build)' : ' --ignore-scripts'} ...`);
const [packed] = JSON.parse(npm(['pack', '--json', '--pack-destination', work, ...(build ? [] : ['--ignore-scripts'])], root).replace(/^[^[]*/, ''));
const files = new Set(packed.files.map((f) => f.path));
console.log(`${packed.filename}: ${(packed.size / 1024).toFixed(0)} KB, ${packed.entryCount} files (${elapsed()})`);
for (const f of ['dist/physics-elements.iife.js', 'dist/physics-elements.bundle.js', 'dist/lib/index.js', 'dist/engine/index.js', 'dist/types/index.d.ts', 'custom-elements.json', 'README.md', 'package.json']) {
  check(files.has(f), `the tarball holds ${f}`);
}
const stray = [...files].filter((f) => /^(test|demo|bench|scripts|artifacts|node_modules)\//.test(f));
check(stray.length === 0, `no tests, demos, benchmarks or scripts in the tarball${stray.length ? `: ${stray.slice(0, 5).join(', ')}` : ''}`);

// The README's first HTML snippet is the one a blogger copies: this version's CDN address of a file in the tarball.
const readme = readFileSync(resolve(root, 'README.md'), 'utf8');
const snippet = /```html\n([\s\S]*?)```/.exec(readme)?.[1] ?? '';
const cdnPrefix = `https://cdn.jsdelivr.net/npm/${pkg.name}@${pkg.version}/`;
const snippetFile = new RegExp(`<script (?:defer )?src="${cdnPrefix.replace(/[.]/g, '\\.')}([^"]+)"></script>`).exec(snippet)?.[1];
check(snippetFile !== undefined, `the README's first snippet loads ${cdnPrefix}… with a plain <script src>`);
check(files.has(snippetFile), `that file (${snippetFile}) is in the tarball`);

// ---- 2. installed into an empty folder, served from a second origin ----------------------------------------------

const site = join(work, 'site');
execFileSync('mkdir', ['-p', site]);
writeFileSync(join(site, 'package.json'), JSON.stringify({ name: 'blog', private: true }));
const installed = join(site, 'node_modules', pkg.name);
try {
  npm(['install', join(work, packed.filename), '--prefer-offline', '--no-audit', '--no-fund'], site);
  console.log(`npm install <tarball>: done (${elapsed()})`);
} catch (e) {
  // No registry (its dependencies' metadata not in npm's cache): the browser builds need only the tarball's own files.
  console.log(`npm install <tarball> failed (${String(e.stderr ?? e).split('\n').find((l) => /error/.test(l)) ?? e}): unpacking the tarball instead`);
  execFileSync('mkdir', ['-p', installed]);
  execFileSync('tar', ['-xzf', join(work, packed.filename), '-C', installed, '--strip-components=1']);
}
check(existsSync(join(installed, snippetFile ?? '-')), `installed: node_modules/${pkg.name}/${snippetFile} (${elapsed()})`);
check(!/\bexport\s*\{/.test(readFileSync(join(installed, snippetFile ?? 'package.json'), 'utf8').slice(-4000)), `${snippetFile} is a classic script (it does not end in an export statement)`);

/**
 * The type-only entries as an app's TypeScript uses them from the installed package (--strict; moduleResolution
 * bundler, nodenext and node16): physics-elements/react (React 19's JSX), physics-elements/iife (window.PhysicsElements)
 * and the literal unions of the enum-like properties. Each has a sample that must compile and a "wrong" one whose
 * marked lines (`// wrong: …`), and only those, must fail to: a misspelt kernel, a word for a number, an unknown
 * attribute. physics-elements/jsx must name custom-elements.json's attributes, tag by tag. The package does not
 * depend on React: this checkout's @types/react is used when it has one, else a minimal stand-in (REACT_STUB) is
 * written into the sample folder's node_modules/@types/react, laid out as @types/react 19 is. The entries for Preact,
 * Solid and Vue are compiled against stand-ins of the parts they use (FRAMEWORK_STUBS) in the same way.
 */
function typeOnlyEntries(tsc, frameworkEntries) {
  // A folder of its own, of ES modules ("type": "module": what an app on Node 16+ resolution writes TSX in).
  const app = join(site, 'typed');
  mkdirSync(app, { recursive: true });
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'typed-app', private: true, type: 'module' }));
  const modules = join(site, 'node_modules');
  const realReact = resolve(root, 'node_modules/@types/react');
  const stubs = { ...FRAMEWORK_STUBS, ...(existsSync(realReact) ? {} : REACT_STUB) };
  for (const [path, text] of Object.entries(stubs)) {
    mkdirSync(dirname(join(modules, path)), { recursive: true });
    writeFileSync(join(modules, path), text);
  }
  for (const name of existsSync(realReact) ? ['@types/react', 'csstype'] : []) {
    if (existsSync(resolve(root, 'node_modules', name))) cpSync(resolve(root, 'node_modules', name), join(modules, name), { recursive: true, dereference: true });
  }
  console.log(`React's types for the JSX samples: ${existsSync(realReact) ? "this checkout's @types/react" : 'a minimal stand-in (no @types/react in node_modules)'}`);

  // physics-elements/jsx names every attribute of custom-elements.json, and no other.
  const manifest = JSON.parse(readFileSync(join(installed, 'custom-elements.json'), 'utf8'));
  const tagAttributes = manifest.modules.flatMap((m) => m.declarations ?? []).filter((d) => d.tagName).map((d) => [d.tagName, (d.attributes ?? []).map((a) => a.name)]);
  const union = (names) => names.map((n) => `'${n}'`).join(' | ') || 'never';
  writeFileSync(join(app, 'manifest.mts'), `import type { PhysicsElementAttributes, PhysicsTagName } from '${pkg.name}/jsx';
type Equal<A, B> = (<T>() => T extends A ? 1 : 2) extends <T>() => T extends B ? 1 : 2 ? true : false;
declare function same<T extends true>(): void;
same<Equal<PhysicsTagName, ${union(tagAttributes.map(([tag]) => tag))}>>();
${tagAttributes.map(([tag, names]) => `same<Equal<keyof PhysicsElementAttributes['${tag}'], ${union(names)}>>();`).join('\n')}
`);
  for (const [name, text] of Object.entries(TYPE_SAMPLES)) writeFileSync(join(app, name), text.replace(/physics-elements(?=[/'"])/g, pkg.name));

  const frameworks = { 'physics-elements/preact': 'preact.tsx', 'physics-elements/solid': 'solid.tsx', 'physics-elements/vue': 'vue.mts' };
  for (const f of frameworkEntries) {
    const entry = `${pkg.name}/${f.replace(/^dist\/types\/jsx\/|\.d\.ts$/g, '')}`;
    check(entry === `${pkg.name}/react` || frameworks[entry.replace(pkg.name, 'physics-elements')] !== undefined, `${f} (${entry}) has a sample here`);
  }
  const groups = [
    ["physics-elements/react: React 19's JSX", ['react.tsx'], ['react-wrong.tsx'], ['--jsx', 'react-jsx']],
    ["physics-elements/preact: Preact's JSX (stand-in)", ['preact.tsx'], ['preact-wrong.tsx'], ['--jsx', 'react-jsx', '--jsxImportSource', 'preact']],
    ["physics-elements/solid: Solid's JSX (stand-in)", ['solid.tsx'], ['solid-wrong.tsx'], ['--jsx', 'preserve', '--jsxImportSource', 'solid-js']],
    ["physics-elements/vue: Vue's GlobalComponents (stand-in)", ['vue.mts'], ['vue-wrong.mts'], []],
    ['physics-elements/jsx: the attributes of custom-elements.json', ['manifest.mts'], [], []],
    ['physics-elements/iife: window.PhysicsElements, from TypeScript and from a checked classic script', ['iife.mts', 'iife.js'], ['iife-wrong.mts'], ['--allowJs', '--checkJs']],
    ["the literal unions of the elements' enum-like properties", ['unions.mts'], ['unions-wrong.mts'], []],
  ];
  const compile = (options, inputs) => {
    try {
      execFileSync(process.execPath, [tsc, ...options, ...inputs], { cwd: app, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
      return '';
    } catch (e) {
      return `${e.stdout ?? ''}${e.stderr ?? ''}`.trim() || String(e);
    }
  };
  for (const resolution of ['bundler', 'nodenext', 'node16']) {
    const options = ['--noEmit', '--strict', '--target', 'es2022', '--lib', 'es2022,dom,dom.iterable', '--types', '', '--module', resolution === 'bundler' ? 'esnext' : resolution, '--moduleResolution', resolution];
    for (const [what, good, wrong, extra] of groups) {
      const out = compile([...options, ...extra], good);
      check(out === '', `${what} (moduleResolution ${resolution}): the sample compiles${out ? `:\n  ${out.split('\n').slice(0, 12).join('\n  ')}` : ''}`);
      for (const file of wrong) {
        const marked = readFileSync(join(app, file), 'utf8').split('\n').flatMap((line, i) => (/\/\/ wrong: /.test(line) ? [i + 1] : []));
        const errors = [...compile([...options, ...extra], [file]).matchAll(/^(\S+?)\((\d+),\d+\): error (TS\d+)/gm)];
        // An error of the set-up (no JSX runtime, no IntrinsicElements, a module not found) is not the one looked for.
        const setup = errors.filter((m) => ['TS2307', 'TS2875', 'TS7026', 'TS7006', 'TS1541'].includes(m[3])).map((m) => `${m[1]}:${m[2]} ${m[3]}`);
        const failed = [...new Set(errors.map((m) => (m[1] === file ? Number(m[2]) : `${m[1]}:${m[2]}`)))].concat(setup);
        const same = failed.length === marked.length && marked.every((l) => failed.includes(l));
        check(marked.length > 0 && same, `${what} (moduleResolution ${resolution}): ${file} fails on its ${marked.length} marked lines${same ? '' : ` (lines ${marked.join(', ')}), not on ${failed.join(', ') || 'none'}`}`);
      }
    }
  }
}

/** The samples of typeOnlyEntries(). */
const TYPE_SAMPLES = {
  'react.tsx': `import type {} from 'physics-elements/react';
import { useRef } from 'react';
import type { ClothSimElement, PhysicsCollisionDetail, PhysicsErrorDetail } from 'physics-elements';

export function Embed() {
  const sim = useRef<ClothSimElement>(null);
  const onError = (e: CustomEvent<PhysicsErrorDetail>) => console.warn(e.detail.attribute, e.detail.message);
  return (
    <div className="post">
      <cloth-sim ref={sim} wind="2" gusts={0.4} kernel="wasm" pins="0 8 16 23" tear="0.3" paused collision-events onphysics-error={onError} style={{ width: '100%' }} />
      <ragdoll-sim count={3} obstacles="pegs" respawn={false} obstacle-fill="#888" substeps="auto" />
      <physics-scene id="scene" width={16} height="9" gravity="0 9.81" worker="none" broadphase="brute" narrowphase="gjk" bounds="none" draw-mode="over" max-restarts={1}
        onphysics-ready={(e) => e.detail.mode === 'worker'} onphysics-collision={(e) => { const d: PhysicsCollisionDetail = e.detail; return d.speed; }} onphysics-collision-end={(e) => e.detail.a}>
        <physics-box id="crate" x={4} y="2" width={1} height={1} angle={15} static fill="#c84" model="particles" />
        <physics-circle id="ball" x={8} y={1} radius={0.5} restitution={0.8} kinematic velocity="1 0" angular-velocity={90} />
        <physics-polygon x={5} y={5} points="0 0 1 0 0 1" density={2} />
        <physics-rope id="rope" x1={2} y1={1} x2={6} y2={1} segments={20} slack="1.2" pin="both" rigid collide />
        <physics-cloth x={1} y={1} columns={12} rows={10} spacing={0.3} pins="corners" shear={0.001} bend={0.01} />
        <physics-softbody x={5} y={3} radius={1} segments={16} pressure={1.2} model="springs" compliance={0.0001} />
        <physics-ragdoll x={12} y={2} height={1.6} joint-compliance={0} mass={70} />
        <physics-joint type="revolute" a="crate" b="ball" x={5} y={2} lower-angle={-30} upper-angle="30" motor-speed={90} max-motor-torque={10} collide-connected onphysics-error={(e) => e.detail.element} />
        <physics-joint type="prismatic" a="crate" axis="1 0" lower={0} upper={2} />
        <physics-spring a="crate" b="ball" stiffness={50} damping={1} length={2} />
        <physics-pin body="rope" particle={0} x={2} y={1} compliance={0} />
        <p slot="fallback">A cloth and a crate.</p>
      </physics-scene>
    </div>
  );
}
`,
  'react-wrong.tsx': `import type {} from 'physics-elements/react';
export const kernel = <physics-scene kernel="wsam" />; // wrong: not a kernel
export const wind = <cloth-sim wind="strong" />; // wrong: not a number
export const model = <physics-box model="rigidd" />; // wrong: not a model
export const joint = <physics-joint type="hinge" />; // wrong: not a joint type
export const respawn = <ragdoll-sim respawn="off" />; // wrong: a property set from JSX takes a boolean
export const pins = <cloth-sim pins="left" />; // wrong: not top, corners, none or column numbers
export const unknown = <physics-box radius={1} />; // wrong: a box has no radius
export const ready = <physics-scene onphysics-ready={(e: CustomEvent<{ nope: 1 }>) => e} />; // wrong: the detail is PhysicsReadyDetail
export const ok = <physics-scene kernel="js" />;
`,
  'preact.tsx': `import type {} from 'physics-elements/preact';
import type { PhysicsErrorDetail } from 'physics-elements';
export const embed = (
  <div class="post">
    <cloth-sim wind="2" kernel="wasm" pins="0 8" paused collision-events onphysics-error={(e) => { const d: PhysicsErrorDetail = e.detail; return d; }} ref={(el) => { if (el) el.wind = 2; }} />
    <physics-scene width={16} onphysics-collision={(e) => e.detail.speed}>
      <physics-box id="crate" x={4} y="2" static model="particles" />
      <physics-joint type="revolute" a="crate" lower-angle={-30} />
    </physics-scene>
  </div>
);
`,
  'preact-wrong.tsx': `import type {} from 'physics-elements/preact';
export const kernel = <physics-scene kernel="wsam" />; // wrong: not a kernel
export const wind = <cloth-sim wind="strong" />; // wrong: not a number
export const unknown = <physics-box radius={1} />; // wrong: a box has no radius
`,
  'solid.tsx': `import type {} from 'physics-elements/solid';
import type { PhysicsErrorDetail } from 'physics-elements';
export const embed = (
  <div class="post">
    <cloth-sim wind="2" kernel="wasm" pins="0 8" paused collision-events on:physics-error={(e) => { const d: PhysicsErrorDetail = e.detail; return d; }} />
    <physics-scene width={16} on:physics-collision={(e) => e.detail.speed}>
      <physics-box id="crate" x={4} y="2" static model="particles" />
      <physics-joint type="revolute" a="crate" lower-angle={-30} />
    </physics-scene>
  </div>
);
`,
  'solid-wrong.tsx': `import type {} from 'physics-elements/solid';
export const kernel = <physics-scene kernel="wsam" />; // wrong: not a kernel
export const wind = <cloth-sim wind="strong" />; // wrong: not a number
export const unknown = <physics-box radius={1} />; // wrong: a box has no radius
`,
  'vue.mts': `import type {} from 'physics-elements/vue';
import type { GlobalComponents } from 'vue';
import type { PhysicsErrorDetail } from 'physics-elements';
// What vue-tsc checks a template's <cloth-sim wind="2" @physics-error="…"> against.
type Props<T extends keyof GlobalComponents> = GlobalComponents[T] extends new () => { $props: infer P } ? P : never;
type Emit<T extends keyof GlobalComponents> = GlobalComponents[T] extends new () => { $emit: infer E } ? E : never;
export const sim: Props<'cloth-sim'> = { wind: '2', kernel: 'wasm', pins: '0 8', paused: true, 'collision-events': true, maxRestarts: 1, class: 'post' };
export const box: Props<'physics-box'> = { id: 'crate', x: 4, static: true, model: 'particles' };
export function listen(emit: Emit<'physics-scene'>, detail: PhysicsErrorDetail) {
  emit('physics-error', new CustomEvent('physics-error', { detail }));
}
export const teleport: GlobalComponents['Teleport'] | null = null;
`,
  'vue-wrong.mts': `import type {} from 'physics-elements/vue';
import type { GlobalComponents } from 'vue';
type Props<T extends keyof GlobalComponents> = GlobalComponents[T] extends new () => { $props: infer P } ? P : never;
type Emit<T extends keyof GlobalComponents> = GlobalComponents[T] extends new () => { $emit: infer E } ? E : never;
export const kernel: Props<'physics-scene'> = { kernel: 'wsam' }; // wrong: not a kernel
export const wind: Props<'cloth-sim'> = { wind: 'strong' }; // wrong: not a number
export const camel: Props<'physics-joint'> = { lowerAngle: 'low' }; // wrong: not a number, camel-cased as vue-tsc may
export function listen(emit: Emit<'physics-box'>) {
  emit('physics-ready', new CustomEvent('physics-ready')); // wrong: a body fires physics-error only
}
`,
  'iife.mts': `/// <reference types="physics-elements/iife" />
import type { ClothSimElement } from 'physics-elements/bundle';
// A page that loads dist/physics-elements.iife.js with <script src> and uses its global.
const { ClothSimElement: Cloth, PhysicsSceneElement, EngineStoppedError } = window.PhysicsElements;
export const defined: boolean = customElements.get('cloth-sim') === Cloth && PhysicsElements.RagdollSimElement === globalThis.PhysicsElements.RagdollSimElement;
export const sim: ClothSimElement = new Cloth();
PhysicsSceneElement.callTimeout = 5000;
export const stopped = (e: unknown): boolean => e instanceof EngineStoppedError;
`,
  'iife.js': `/// <reference types="physics-elements/iife" />
// A page's classic script after <script src=".../physics-elements.iife.js">, checked (checkJs).
const scene = document.querySelector('physics-scene');
if (scene instanceof window.PhysicsElements.PhysicsSceneElement) scene.kernel = 'js';
window.PhysicsElements.PhysicsSceneElement.maxWorkers = 2;
`,
  'iife-wrong.mts': `/// <reference types="physics-elements/iife" />
export const engine = window.PhysicsElements.World; // wrong: the headless engine is not in the single file
export const nope = PhysicsElements.ClothSim; // wrong: no such export
export const ok = window.PhysicsElements.ClothSimElement;
`,
  'unions.mts': `import 'physics-elements';
import type { ClothPinsAttribute } from 'physics-elements';
const scene = document.querySelector('physics-scene')!;
scene.kernel = 'wasm';
scene.worker = 'none';
scene.broadphase = 'brute';
scene.narrowphase = 'gjk';
scene.bounds = 'none';
scene.drawMode = 'replace';
scene.substeps = 'auto';
export const kernel: 'auto' | 'wasm' | 'js' = scene.kernel;
document.querySelector('cloth-sim')!.pins = '0 8 16 23';
document.querySelector('physics-cloth')!.pins = 'corners';
document.querySelector('ragdoll-sim')!.obstacles = 'pegs';
document.querySelector('physics-box')!.model = 'particles';
document.querySelector('physics-softbody')!.model = 'springs';
document.querySelector('physics-rope')!.pin = 'both';
document.querySelector('physics-joint')!.type = 'prismatic';
export const pins: ClothPinsAttribute[] = ['top', 'corners', 'none', '3', '0,23'];
`,
  'unions-wrong.mts': `import 'physics-elements';
const scene = document.querySelector('physics-scene')!;
scene.kernel = 'wsam'; // wrong: not a kernel
scene.worker = 'off'; // wrong: auto or none
scene.drawMode = 'under'; // wrong: over or replace
document.querySelector('cloth-sim')!.pins = 'left'; // wrong: not top, corners, none or column numbers
document.querySelector('physics-box')!.model = 'soft'; // wrong: rigid or particles
document.querySelector('physics-rope')!.pin = 'top'; // wrong: start, end, both or none
document.querySelector('physics-joint')!.type = 'hinge'; // wrong: not a joint type
document.querySelector('ragdoll-sim')!.obstacles = 'stairs';
`,
};

/** A minimal stand-in for @types/react 19 (the package does not install React): its layout (export =, namespace React,
 *  React.JSX, react/jsx-runtime re-exporting it) and the element props physics-elements/react takes from it. */
const REACT_STUB = {
  '@types/react/package.json': JSON.stringify({ name: '@types/react', version: '19.0.0-stand-in', types: 'index.d.ts', exports: { '.': { types: './index.d.ts' }, './jsx-runtime': { types: './jsx-runtime.d.ts' } } }),
  '@types/react/index.d.ts': `export = React;
export as namespace React;
declare namespace React {
  type Key = string | number | bigint;
  interface RefObject<T> { current: T }
  type Ref<T> = ((instance: T | null) => void) | RefObject<T | null> | null;
  interface Attributes { key?: Key | null }
  interface ClassAttributes<T> extends Attributes { ref?: Ref<T> }
  interface ReactElement { type: unknown; props: unknown; key: string | null }
  type ReactNode = ReactElement | string | number | bigint | boolean | null | undefined | Iterable<ReactNode>;
  interface CSSProperties { [property: string]: string | number | undefined }
  interface DOMAttributes<T> { children?: ReactNode; onClick?: (event: MouseEvent & { currentTarget: T }) => void }
  interface HTMLAttributes<T> extends DOMAttributes<T> { id?: string; className?: string; style?: CSSProperties; slot?: string; title?: string; hidden?: boolean; role?: string; tabIndex?: number }
  type DetailedHTMLProps<E extends HTMLAttributes<T>, T> = ClassAttributes<T> & E;
  type ElementType = string | ((props: any) => ReactNode);
  const Fragment: unique symbol;
  function useRef<T>(initial: T | null): RefObject<T | null>;
  namespace JSX {
    type ElementType = React.ElementType;
    interface Element extends ReactElement {}
    interface ElementAttributesProperty { props: {} }
    interface ElementChildrenAttribute { children: {} }
    interface IntrinsicAttributes extends Attributes {}
    interface IntrinsicClassAttributes<T> extends ClassAttributes<T> {}
    interface IntrinsicElements {
      div: DetailedHTMLProps<HTMLAttributes<HTMLDivElement>, HTMLDivElement>;
      p: DetailedHTMLProps<HTMLAttributes<HTMLParagraphElement>, HTMLParagraphElement>;
    }
  }
}
`,
  '@types/react/jsx-runtime.d.ts': `import * as React from './';
export { Fragment, JSX } from './';
export function jsx(type: React.ElementType, props: unknown, key?: React.Key): React.ReactElement;
export function jsxs(type: React.ElementType, props: unknown, key?: React.Key): React.ReactElement;
`,
};

/** Stand-ins for Preact 10, Solid 1 and Vue 3.5 (none installed): the layout of the declarations each entry augments
 *  (checked against the real packages when the entries were written) and the element props it takes from them. */
const FRAMEWORK_STUBS = {
  'preact/package.json': JSON.stringify({ name: 'preact', version: '10.0.0-stand-in', types: 'index.d.ts', exports: { '.': { types: './index.d.ts' }, './jsx-runtime': { types: './jsx-runtime/index.d.ts' } } }),
  'preact/index.d.ts': `import { JSXInternal } from './jsx';
export import JSX = JSXInternal;
export interface VNode<P = {}> { type: unknown; props: P }
export interface Attributes { key?: string | number }
export interface ClassAttributes<T> extends Attributes { ref?: ((instance: T | null) => void | (() => void)) | { current: T | null } }
export type ComponentChildren = VNode<any> | string | number | boolean | null | undefined | ComponentChildren[];
export const Fragment: unique symbol;
`,
  'preact/jsx.d.ts': `import { ClassAttributes, ComponentChildren, VNode } from './index';
export namespace JSXInternal {
  interface Element extends VNode<any> {}
  interface ElementChildrenAttribute { children: any }
  interface IntrinsicAttributes { key?: any }
  interface HTMLAttributes<RefType extends EventTarget = EventTarget> extends ClassAttributes<RefType> { id?: string; class?: string; style?: string | { [property: string]: string | number }; slot?: string; children?: ComponentChildren; onClick?: (event: MouseEvent) => void }
  interface IntrinsicElements { div: HTMLAttributes<HTMLDivElement> }
}
`,
  'preact/jsx-runtime/index.d.ts': `import { VNode } from 'preact';
export { Fragment } from 'preact';
export { JSXInternal as JSX } from '../jsx';
export function jsx(type: unknown, props: unknown, key?: string): VNode<any>;
export function jsxs(type: unknown, props: unknown, key?: string): VNode<any>;
`,
  'solid-js/package.json': JSON.stringify({ name: 'solid-js', version: '1.0.0-stand-in', types: 'index.d.ts', exports: { '.': { types: './index.d.ts' }, './jsx-runtime': { types: './jsx-runtime.d.ts' } } }),
  'solid-js/index.d.ts': `import type { JSX } from './jsx';
export type { JSX };
`,
  'solid-js/jsx.d.ts': `export namespace JSX {
  type Element = Node | Element[] | (string & {}) | number | boolean | null | undefined;
  interface ElementChildrenAttribute { children: {} }
  interface CustomAttributes<T> { ref?: T | ((el: T) => void); classList?: { [k: string]: boolean | undefined } }
  interface DOMAttributes<T> extends CustomAttributes<T> { children?: Element; onClick?: (event: MouseEvent & { currentTarget: T }) => void }
  interface HTMLAttributes<T> extends DOMAttributes<T> { id?: string; class?: string; style?: string | { [property: string]: string | number | undefined }; slot?: string }
  interface IntrinsicElements { div: HTMLAttributes<HTMLDivElement> }
}
`,
  'solid-js/jsx-runtime.d.ts': `export * from './jsx';
`,
  'vue/package.json': JSON.stringify({ name: 'vue', version: '3.5.0-stand-in', types: 'index.d.ts', exports: { '.': { types: './index.d.ts' } } }),
  'vue/index.d.ts': `export interface HTMLAttributes { id?: string; class?: unknown; style?: unknown; slot?: string; onClick?: (payload: MouseEvent) => void }
export interface VNodeProps { key?: PropertyKey; ref?: unknown }
export interface AllowedComponentProps { class?: unknown; style?: unknown }
export interface ComponentCustomProps {}
export type PublicProps = VNodeProps & AllowedComponentProps & ComponentCustomProps;
type UnionToIntersection<U> = (U extends any ? (k: U) => void : never) extends (k: infer I) => void ? I : never;
export type EmitFn<Options = Record<string, any>, Event extends keyof Options = keyof Options> = UnionToIntersection<{
  [key in Event]: Options[key] extends (...args: infer Args) => any ? (event: key, ...args: Args) => void : (event: key, ...args: any[]) => void;
}[Event]>;
export interface DefineComponent<P = {}> { new (): { $props: P } }
export interface GlobalComponents { Teleport: DefineComponent<{ to: string }> }
`,
};

// ---- 2b. an app's TypeScript and Node ---------------------------------------------------------------------------
// Every "types" of package.json's exports is in the tarball; physics-elements/bundle declares what the single file
// exports. An app's TypeScript (bundler and nodenext resolution), against the installed package, sees each tag in
// HTMLElementTagNameMap and each physics-* event's detail (--strict), also through physics-elements/bundle (esbuild's
// import), and compiles the docs' samples; the type-only entries (JSX, window.PhysicsElements) and the literal unions
// compile in their samples and fail where their wrong samples are marked (typeOnlyEntries, above); the headless engine
// runs in plain Node, by import and by require.
for (const [path, target] of Object.entries(pkg.exports)) {
  if (typeof target === 'object' && target.types) check(files.has(target.types.replace(/^\.\//, '')), `exports["${path}"].types (${target.types}) is in the tarball`);
  // TypeScript's moduleResolution node10 (TypeScript 5's default for module commonjs) ignores "exports".
  if (typeof target === 'object' && target.types && path !== '.') check(pkg.typesVersions?.['*']?.[path.slice(2)]?.[0] === target.types, `typesVersions gives "${path.slice(2)}" its types for TypeScript's node10 resolution`);
}
const bundleNames = (src) => new Set([...(/export\s*\{([^}]*)\}\s*;?\s*$/.exec(src)?.[1] ?? '').matchAll(/(?:\bas\s+)?(\w+)\s*(?:,|$)/g)].map((m) => m[1]));
const declaredNames = (dts) => new Set([...dts.matchAll(/^export \{([^}]*)\} from/gm)].flatMap((m) => m[1].split(',').map((n) => n.trim()).filter(Boolean)));
if (existsSync(join(installed, 'dist/types/bundle.d.ts'))) {
  const [shipped, declared] = [bundleNames(readFileSync(join(installed, 'dist/physics-elements.bundle.js'), 'utf8')), declaredNames(readFileSync(join(installed, 'dist/types/bundle.d.ts'), 'utf8'))];
  check(shipped.size > 10 && [...shipped].sort().join() === [...declared].sort().join(), `dist/types/bundle.d.ts declares the ${shipped.size} names the single file exports${[...shipped].sort().join() === [...declared].sort().join() ? '' : `: ${[...shipped].filter((n) => !declared.has(n))} undeclared, ${[...declared].filter((n) => !shipped.has(n))} not exported`}`);
}
if (existsSync(join(site, 'node_modules', 'lit'))) {
  const app = join(site, 'app');
  execFileSync('mkdir', ['-p', app]);
  // The samples of README.md and docs/*.md that use the package (``` js blocks that import it or call a scene), each a
  // module of its own, checked as JavaScript (checkJs, --strict but for null checks: a script's querySelector).
  const samples = ['README.md', ...readdirSync(resolve(root, 'docs')).filter((f) => f.endsWith('.md')).map((f) => `docs/${f}`)].flatMap((doc) =>
    [...readFileSync(resolve(root, doc), 'utf8').matchAll(/```js\n([\s\S]*?)```/g)].map((m) => ({ doc, code: m[1] })));
  const used = samples.filter(({ code }) => /'physics-elements(\/engine)?'|\b(scene|world)\./.test(code) && !/from '(?!physics-elements)/.test(code));
  used.forEach(({ doc, code }, i) => {
    // A sample that continues another (`scene.…`, `world.…` without making it) gets a scene or a world.
    const scene = /\bscene\./.test(code) && !/\bconst scene\b/.test(code) ? "const scene = document.querySelector('physics-scene');\n" : '';
    const world = /\bworld\./.test(code) && !/\b(const|let) \{? ?world\b/.test(code) ? "import { World } from 'physics-elements/engine';\nconst world = new World();\n" : '';
    writeFileSync(join(app, `sample-${i + 1}.mjs`), `// ${doc}\nimport 'physics-elements';\n${scene}${world}${code}export {};\n`);
  });
  const readmeJs = used.filter(({ doc }) => doc === 'README.md').map(({ code }) => code);
  const tags = { 'physics-scene': 'PhysicsSceneElement', 'cloth-sim': 'ClothSimElement', 'ragdoll-sim': 'RagdollSimElement', 'physics-box': 'PhysicsBoxElement', 'physics-circle': 'PhysicsCircleElement', 'physics-polygon': 'PhysicsPolygonElement', 'physics-rope': 'PhysicsRopeElement', 'physics-cloth': 'PhysicsClothElement', 'physics-softbody': 'PhysicsSoftbodyElement', 'physics-ragdoll': 'PhysicsRagdollElement', 'physics-joint': 'PhysicsJointElement', 'physics-spring': 'PhysicsSpringElement', 'physics-pin': 'PhysicsPinElement' };
  for (const [name, from] of [['types.mts', 'physics-elements'], ['bundle.mts', 'physics-elements/bundle']]) {
    writeFileSync(join(app, name), `import * as P from '${from}';
${Object.entries(tags).map(([tag, cls]) => `export const ${cls.replace('Element', '')}: P.${cls} | null = document.querySelector('${tag}');`).join('\n')}
const scene = document.querySelector('physics-scene')!, box = document.querySelector('physics-box')!;
scene.addEventListener('physics-ready', (e) => { const d: P.PhysicsReadyDetail = e.detail; return d.mode === 'worker' && d.transport; });
scene.addEventListener('physics-collision', (e) => { const a: Element | null = e.detail.b; return [a, e.detail.normal.x, e.detail.depth, e.detail.speed]; });
scene.addEventListener('physics-collision-end', (e) => e.detail.speed);
box.addEventListener('physics-error', (e) => { const s: string = e.detail.attribute + e.detail.value + e.detail.message; return [s, e.detail.element]; });
document.addEventListener('physics-error', (e) => e.detail.attribute);
// @ts-expect-error no such detail field
scene.addEventListener('physics-error', (e) => e.detail.nope);
// @ts-expect-error internal (a test hook): not in the declarations
void scene._debugFault('hang');
scene.paused = true;
export const n: Promise<number> = scene.step(60), h: Promise<string> = scene.stateHash();
scene.drawHook = ({ p, positions, topology, scale, offsetX, offsetY }) => { for (const b of topology.bodies) for (const i of b.indices) p.circle(offsetX + positions[2 * i] * scale, offsetY + positions[2 * i + 1] * scale, 4); };
scene.snapshot().then((s: P.HostSnapshot) => scene.restore(s), (e) => e instanceof P.EngineStoppedError);
`);
  }
  // Every declaration file in the tarball, the internal modules' too ("./dist/*"), compiles (--stripInternal left none
  // naming what it stripped).
  const declarations = execFileSync('find', ['dist/types', '-name', '*.d.ts'], { cwd: installed, encoding: 'utf8' }).trim().split('\n').sort();
  // (The framework entries, physics-elements/react and the like, augment a framework's module: checked below.)
  const frameworkEntries = declarations.filter((f) => /^dist\/types\/jsx\/(?!index\.)/.test(f));
  writeFileSync(join(app, 'all.mts'), declarations.filter((f) => !frameworkEntries.includes(f)).map((f, i) => `import type * as d${i} from '${pkg.name}/${f.replace(/\.d\.ts$/, '.js')}';\n`).join(''));
  const tsc = resolve(root, 'node_modules/typescript/bin/tsc');
  for (const resolution of ['bundler', 'nodenext']) {
    const options = ['--noEmit', '--target', 'es2022', '--lib', 'es2022,dom,dom.iterable', '--types', '', '--module', resolution === 'bundler' ? 'esnext' : 'nodenext', '--moduleResolution', resolution];
    for (const [what, extra, inputs] of [
      ['the typed elements and events, from physics-elements and physics-elements/bundle', ['--strict'], ['types.mts', 'bundle.mts']],
      ...(resolution === 'bundler' ? [[`the package's ${declarations.length} declaration files`, ['--strict'], ['all.mts']]] : []),
      [`the ${used.length} samples of README.md and docs/*.md that use the package, as JavaScript`, ['--strict', '--strictNullChecks', 'false', '--allowJs', '--checkJs'], used.map((_, i) => `sample-${i + 1}.mjs`)],
    ]) {
      let out = '';
      try {
        execFileSync(process.execPath, [tsc, ...options, ...extra, ...inputs], { cwd: app, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] });
      } catch (e) {
        out = `${e.stdout ?? ''}${e.stderr ?? ''}`.trim() || String(e);
      }
      check(out === '', `an app's TypeScript (moduleResolution ${resolution}) compiles ${what}${out ? `:\n  ${out.split('\n').slice(0, 12).join('\n  ')}` : ''}`);
    }
  }
  typeOnlyEntries(tsc, frameworkEntries);
  // The README's engine sample, as written, in plain Node (import), and the engine by require() (Node >= 20.19).
  const engineSample = readmeJs.find((code) => code.includes("from 'physics-elements/engine'")) ?? '';
  writeFileSync(join(app, 'engine.mjs'), engineSample);
  const printed = execFileSync(process.execPath, ['engine.mjs'], { cwd: app, encoding: 'utf8' });
  const comment = /console\.log\(.*\/\/.*?(\{[^}]*\})/.exec(engineSample)?.[1];
  check(comment !== undefined && printed.replace(/\s+/g, ' ').includes(comment.replace(/\s+/g, ' ')), `node runs the README's engine sample from the installed package and prints what its comment says (${printed.trim()})`);
  writeFileSync(join(app, 'require.cjs'), "const { World, createBox } = require('physics-elements/engine'); const w = new World(); const b = createBox(w, { x: 0, y: 0, width: 1, height: 1 }); for (let i = 0; i < 60; i++) w.step(); console.log(w.bodyPose(b.body).y.toFixed(3));");
  const [major, minor] = process.versions.node.split('.').map(Number);
  if (major > 22 || (major === 22 && minor >= 12) || (major === 20 && minor >= 19)) {
    let required = '';
    try {
      required = execFileSync(process.execPath, ['--no-warnings', 'require.cjs'], { cwd: app, encoding: 'utf8', stdio: ['ignore', 'pipe', 'pipe'] }).trim();
    } catch (e) {
      required = String(e.stderr ?? e).split('\n').find((l) => /Error/.test(l)) ?? String(e);
    }
    check(required === '4.905', `require('physics-elements/engine') works in CommonJS (${required})`);
  }
  console.log(`(TypeScript and Node checks done, ${elapsed()})`);
} else {
  console.log('SKIP the TypeScript and Node checks: the tarball was unpacked without its dependencies (lit, p5)');
}

const TYPES = { '.js': 'text/javascript', '.mjs': 'text/javascript', '.json': 'application/json', '.map': 'application/json', '.ts': 'text/plain' };
// /npm/<name>@<version>/<file> as jsDelivr lays it out; /nocors/npm/… the same without Access-Control-Allow-Origin.
const cdn = await listen('localhost', (req, res) => {
  const url = new URL(req.url, 'http://x');
  const cors = !url.pathname.startsWith('/nocors/');
  const path = url.pathname.replace(/^\/nocors/, '');
  const prefix = `/npm/${pkg.name}@${pkg.version}/`;
  const file = path.startsWith(prefix) ? normalize(join(installed, decodeURIComponent(path.slice(prefix.length)))) : '';
  if (!file.startsWith(installed + '/') || !existsSync(file)) {
    res.writeHead(404);
    res.end();
    return;
  }
  res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream', ...(cors ? { 'access-control-allow-origin': '*' } : {}) });
  res.end(readFileSync(file));
});
const cdnBase = `http://localhost:${cdn.address().port}`;
const local = (url) => url.replace('https://cdn.jsdelivr.net', cdnBase);

// ---- 3. pages on the first origin ------------------------------------------------------------------------------

const post = (head, body) => `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><title>a blog post</title><link rel="icon" href="data:,">
<style>body { margin: 20px; max-width: 560px; font: 16px/1.5 Georgia, serif; } cloth-sim, ragdoll-sim { margin: 12px 0; }</style>${head}</head>
<body><h1>A blog post</h1><p>Some text before the embed.</p>
${body}
<ragdoll-sim id="dolls" count="3"></ragdoll-sim>
<p>Some text after it.</p></body></html>`;
/** The import map of the library's page: lit and p5 (the packages it leaves to the app), at their ES module entries. */
const LIB_IMPORTS = {
  lit: '/modules/lit/index.js',
  'lit/': '/modules/lit/',
  '@lit/reactive-element': '/modules/@lit/reactive-element/reactive-element.js',
  '@lit/reactive-element/': '/modules/@lit/reactive-element/',
  'lit-html': '/modules/lit-html/lit-html.js',
  'lit-html/': '/modules/lit-html/',
  'lit-element/': '/modules/lit-element/',
  p5: '/modules/p5/lib/p5.esm.min.js',
};
// The snippet as the README has it (its element gets an id so the checks can find it).
const asWritten = local(snippet).replace('<cloth-sim', '<cloth-sim id="cloth"');
const moduleUrl = `${cdnBase}/npm/${pkg.name}@${pkg.version}/dist/physics-elements.bundle.js`;
const pages = {
  '/readme.html': { what: "the README's snippet (classic script, defer, CDN with CORS)", html: post('', asWritten) },
  '/nocors.html': { what: 'the classic script from a CDN without CORS', html: post('', asWritten.replace(cdnBase, `${cdnBase}/nocors`)) },
  '/module.html': { what: 'the ES module single file with <script type="module">', html: post(`<script type="module" src="${moduleUrl}"></script>`, '<cloth-sim id="cloth"></cloth-sim>') },
  '/mixup.html': { what: 'the ES module file in a plain <script src>', html: post(`<script src="${moduleUrl}"></script>`, '<cloth-sim id="cloth"></cloth-sim>'), fails: true },
  // The ES module library unbundled, on the page's own origin (a module worker's script must be), lit and p5 from an
  // import map. A module worker does not see the page's import map: its chunk must import nothing by a bare name.
  '/lib.html': { what: 'the ES module library with lit and p5 from an import map (same origin)', html: post(`<script type="importmap">${JSON.stringify({ imports: LIB_IMPORTS })}</script><script type="module" src="/site/dist/lib/index.js"></script>`, '<cloth-sim id="cloth"></cloth-sim>') },
};
const server = await listen('127.0.0.1', (req, res) => {
  const path = new URL(req.url, 'http://x').pathname;
  // /site/… the installed package, /modules/… the packages the import map names (this checkout's, as an app has its own).
  const [base, rest] = path.startsWith('/site/') ? [installed, path.slice(6)] : path.startsWith('/modules/') ? [resolve(root, 'node_modules'), path.slice(9)] : [];
  const file = base ? normalize(join(base, decodeURIComponent(rest))) : '';
  if (file.startsWith(base + '/') && existsSync(file)) {
    res.writeHead(200, { 'content-type': TYPES[extname(file)] ?? 'application/octet-stream' });
    res.end(readFileSync(file));
    return;
  }
  const page = pages[path];
  res.writeHead(page ? 200 : 404, page ? { 'content-type': 'text/html' } : {});
  res.end(page?.html ?? '');
});
const siteUrl = `http://127.0.0.1:${server.address().port}`;

/** The checks of one page in one browser; `tab` is a playwright or puppeteer page, `problems` its console lines. */
async function checkPage(browserName, tab, problems, path) {
  const page = pages[path];
  problems.length = 0;
  await tab.goto(siteUrl + path);
  const label = `${browserName}: ${page.what}`;
  if (page.fails) {
    await new Promise((r) => setTimeout(r, 1500));
    const defined = await tab.evaluate(() => customElements.get('cloth-sim') !== undefined);
    check(!defined && problems.some((p) => /SyntaxError|export/i.test(p)), `${label}: fails loudly (${problems.find((p) => /export/i.test(p)) ?? problems[0] ?? 'no error'})`);
    return;
  }
  const info = await tab.evaluate(async () => {
    const defined = Promise.all([customElements.whenDefined('cloth-sim'), customElements.whenDefined('ragdoll-sim')]);
    // A script that fails to load defines nothing: a failed check, not a hung run.
    if (!(await Promise.race([defined.then(() => true), new Promise((r) => setTimeout(r, 20000, false))]))) return null;
    const out = {};
    for (const id of ['cloth', 'dolls']) {
      const el = document.getElementById(id);
      await Promise.race([el.ready, new Promise((r) => setTimeout(r, 20000))]);
      out[id] = { mode: el.mode, height: Math.round(el.getBoundingClientRect().height) };
    }
    out.global = typeof window.PhysicsElements?.PhysicsSceneElement === 'function' && window.PhysicsElements.PhysicsSceneElement === customElements.get('physics-scene');
    return out;
  });
  check(info !== null, `${label}: the elements are defined`);
  if (info === null) return;
  check(info.cloth.mode === 'worker' && info.dolls.mode === 'worker', `${label}: both engines run in a worker (${info.cloth.mode}, ${info.dolls.mode})`);
  check(info.cloth.height > 100 && info.dolls.height > 100, `${label}: the elements have a box (${info.cloth.height} px, ${info.dolls.height} px tall)`);
  if (path !== '/module.html' && path !== '/lib.html') check(info.global, `${label}: window.PhysicsElements holds the element classes`);
  for (const id of ['cloth', 'dolls']) check(await animates(tab, id), `${label}: #${id}'s canvas changes`);
  check(problems.length === 0, `${label}: no console errors or warnings${problems.length ? `:\n  ${problems.join('\n  ')}` : ''}`);
  await tab.screenshot({ path: resolve(artifacts, `pack-${browserName}-${path.slice(1, -5)}.png`) });
}

try {
  // Chromium, through playwright-core.
  const chromium = await launch();
  try {
    const tab = await chromium.newPage({ viewport: { width: 640, height: 1100 } });
    const problems = [];
    tab.on('console', (m) => ['error', 'warning'].includes(m.type()) && problems.push(`${m.type()}: ${m.text()}`));
    tab.on('pageerror', (e) => problems.push(`pageerror: ${e}`));
    tab.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
    for (const path of Object.keys(pages)) await checkPage('chromium', tab, problems, path);
  } finally {
    await chromium.close();
  }
  console.log(`(chromium done, ${elapsed()})`);

  // Firefox ESR, through puppeteer-core over WebDriver BiDi.
  const firefoxPath = process.env.FIREFOX_PATH ?? '/usr/bin/firefox-esr';
  if (!existsSync(firefoxPath)) {
    console.log(`SKIP firefox: ${firefoxPath} is not installed (apt-get install -y firefox-esr; or set FIREFOX_PATH)`);
  } else {
    const { default: puppeteer } = await import('puppeteer-core');
    const firefox = await puppeteer.launch({ browser: 'firefox', executablePath: firefoxPath, headless: true, defaultViewport: { width: 640, height: 1100 } });
    try {
      const tab = await firefox.newPage();
      const problems = [];
      tab.on('console', (m) => ['error', 'warn'].includes(m.type()) && problems.push(`${m.type()}: ${m.text()}`));
      tab.on('pageerror', (e) => problems.push(`pageerror: ${e}`));
      tab.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
      for (const path of Object.keys(pages)) await checkPage('firefox', tab, problems, path);
    } finally {
      await firefox.close();
    }
    console.log(`(firefox done, ${elapsed()})`);
  }
} finally {
  cdn.close();
  server.close();
  rmSync(work, { recursive: true, force: true });
}
console.log(`pack: ${check.failures.length ? `${check.failures.length} failed` : 'all passed'} in ${elapsed()}; screenshots in artifacts/`);
process.exit(check.failures.length ? 1 : 0);
