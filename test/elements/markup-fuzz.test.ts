// Markup fuzzing: every attribute of every element, read from custom-elements.json (generated from the sources, so a
// new attribute is fuzzed without touching this file), set to hostile values, both before the element connects and
// on a live scene. For every value: an invalid one gives a `physics-error` naming the attribute and the
// value plus one console.warn saying the same; a valid one gives neither; nothing throws; the scene keeps stepping,
// another body keeps moving, the published frames hold no NaN or Infinity; no value ever becomes markup.
//
// What is invalid is derived from the manifest: the attribute's type (number, boolean, string; the default value's
// type when the manifest has none) and the range its description documents ("(> 0)", "whole number 1..12",
// "[0, 1]", "0 < s <= 1", "-1000..1000"), quoted options ("grid" or "brute"), "colour", "Id of". Where nothing
// is documented, a finite number may be refused or accepted ("either"), but the state must stay finite.
//
// Reproducible: every random choice comes from a seeded PRNG (SEED). A failing case prints its seed, tag, attribute
// and value; copy it into REGRESSIONS at the bottom, which runs those cases by name.
import { expect } from '@open-wc/testing';
import type { PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { F, frameLength } from '../../src/worker/protocol.js';
import { unmount } from './helpers.js';

const SEED = 0x5eed_0008;
/** Random extra values per attribute (on top of the fixed hostile list), in each of the two modes. */
const RANDOM_PER_ATTRIBUTE = 3;
/** Scene-level attributes need a scene per case before connecting: this many values per attribute, drawn by the PRNG. */
const PRECONNECT_SCENE_SAMPLE = 3;

/** mulberry32: small, fast, good enough for choosing test cases. */
function prng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const LONG_DIGITS = '7'.repeat(100_000);
const LONG_TEXT = 'ab<c>"\u202e'.repeat(20_000);
/** The fixed hostile values, each with a short name for messages. */
const HOSTILE: [name: string, value: string][] = [
  ['empty', ''],
  ['NaN', 'NaN'],
  ['Infinity', 'Infinity'],
  ['-Infinity', '-Infinity'],
  ['1e309', '1e309'],
  ['-1', '-1'],
  ['0', '0'],
  ['1e12', '1e12'],
  ['fullwidth 12', '１２'],
  ['arabic-indic 3', '٣'],
  ['emoji', '🧨💥'],
  ['img onerror', '<img src=x onerror=window.__pwned=1>'],
  ['javascript: url', 'javascript:alert(1)'],
  ['100k digits', LONG_DIGITS],
  ['100k text', LONG_TEXT],
  ['json breaker', '"}]);'],
  ['spaces', '   '],
];

/** A random value: numbers of every magnitude and sign, number-like text, junk unicode, short lists. */
function randomValue(rand: () => number): string {
  const pick = <T>(xs: T[]): T => xs[Math.floor(rand() * xs.length)];
  const num = () => {
    const sign = rand() < 0.3 ? -1 : 1;
    const x = sign * 10 ** (rand() * 10 - 4);
    return rand() < 0.5 ? String(Math.round(x)) : x.toPrecision(1 + Math.floor(rand() * 6));
  };
  switch (Math.floor(rand() * 6)) {
    case 0:
      return num();
    case 1:
      return `${num()} ${num()}`;
    case 2:
      return pick([' 3 ', '1e-400', '-0', '0x1f', '1_000', '.5', '5.', '+3', '1,5', '0.0001', '2e3', '１', '3px', 'null', 'undefined', 'true', '[]', '{}']);
    case 3: {
      let s = '';
      const n = 1 + Math.floor(rand() * 12);
      for (let k = 0; k < n; k++) s += String.fromCodePoint(pick([0x20, 0x30, 0x41, 0x3c, 0x22, 0x200b, 0x202e, 0x660, 0xff10, 0x1f600, 0xfffd]) + Math.floor(rand() * 10));
      return s;
    }
    case 4:
      return pick(['#abc', 'red', 'rgb(1 2 3)', 'none', 'transparent', 'currentColor', 'url(x)', 'expression(alert(1))', 'var(--x)', '#12345']);
    default:
      return Array.from({ length: 1 + Math.floor(rand() * 8) }, num).join(pick([' ', ',', ', ']));
  }
}

// ---- what the manifest says about each attribute ------------------------------------------------------------------

interface Attr {
  tag: string;
  name: string;
  field: string;
  kind: 'number' | 'boolean' | 'string' | 'unknown';
  description: string;
  min?: number;
  minExclusive?: boolean;
  max?: number;
  integer?: boolean;
  options?: string[];
}

interface Manifest {
  modules: { path: string; declarations?: { tagName?: string; attributes?: { name: string; fieldName?: string; type?: { text: string }; description?: string }[] }[] }[];
}

let manifestCache: Promise<Manifest> | null = null;
const manifest = () => (manifestCache ??= fetch('/custom-elements.json').then((r) => r.json() as Promise<Manifest>));

/** Attributes of every element in the manifest, with the ranges their descriptions document. */
async function attributes(): Promise<Map<string, Attr[]>> {
  const out = new Map<string, Attr[]>();
  for (const mod of (await manifest()).modules) {
    for (const d of mod.declarations ?? []) {
      if (!d.tagName) continue;
      const list: Attr[] = [];
      const fresh = document.createElement(d.tagName) as unknown as Record<string, unknown>;
      for (const a of d.attributes ?? []) {
        const field = a.fieldName ?? a.name;
        // A literal union ('view' | 'none') or a named type of attribute text (ClothPinsAttribute, the package's
        // *Attribute types) is a string in markup.
        const text = a.type?.text ?? typeof fresh[field];
        const named = /'[^']*'|\b[A-Z]\w*Attribute\b/.test(text);
        const kind = /\bboolean\b/.test(text) ? 'boolean' : /\bnumber\b/.test(text) ? 'number' : /\bstring\b/.test(text) || named ? 'string' : 'unknown';
        list.push({ tag: d.tagName, name: a.name, field, kind, description: a.description ?? '', ...rangeOf(a.description ?? '') });
      }
      out.set(d.tagName, list);
    }
  }
  return out;
}

/** Ranges are documented in parentheses ("(> 0)", "(whole number 1..12)"), as "in [0, 1]" or as "0 < s <= 1". */
function rangeOf(description: string): Partial<Attr> {
  const r: Partial<Attr> = {};
  const num = '(-?\\d+(?:\\.\\d+)?(?:e\\d+)?)';
  const inParens = [...description.matchAll(/\(([^)]*)\)/g)].map((m) => m[1]).join(' ; ');
  let m: RegExpMatchArray | null;
  if (/whole number/.test(description)) r.integer = true;
  if ((m = inParens.match(new RegExp(`${num} ?\\.\\. ?${num}`)))) [r.min, r.max] = [Number(m[1]), Number(m[2])];
  else if ((m = description.match(new RegExp(`\\[${num}, ?${num}\\]`)))) [r.min, r.max] = [Number(m[1]), Number(m[2])];
  else if ((m = description.match(new RegExp(`${num} < \\w+ <= ${num}`)))) [r.min, r.minExclusive, r.max] = [Number(m[1]), true, Number(m[2])];
  else if ((m = inParens.match(new RegExp(`>= ?${num}`)))) r.min = Number(m[1]);
  else if ((m = inParens.match(new RegExp(`> ?${num}`)))) [r.min, r.minExclusive] = [Number(m[1]), true];
  if (r.max === undefined && (m = inParens.match(new RegExp(`(?:at most|<=) ?${num}`)))) r.max = Number(m[1]);
  const quoted = [...description.matchAll(/"([a-z-]+)"/g)].map((q) => q[1]);
  if (quoted.length >= 2) r.options = quoted;
  return r;
}

type Verdict = 'invalid' | 'valid' | 'either';

/** Positions and angles: any finite number is fine (positions within ±1e9, as every coordinate). */
const UNBOUNDED = new Set(['x', 'y', 'x1', 'y1', 'x2', 'y2', 'angle']);
/** Positions, lengths and sizes in world units: documented (docs/embedding.md, Bad markup) as within ±1e9. */
const COORDINATES = new Set(['x', 'y', 'x1', 'y1', 'x2', 'y2', 'width', 'height', 'radius', 'spacing', 'length', 'lower']);

function listOfNumbers(value: string): number[] | null {
  const parts = value.trim().split(/[\s,]+/).filter(Boolean);
  const out = parts.map(Number);
  return out.length > 0 && out.every(Number.isFinite) ? out : null;
}

/** What the documentation says about `value` for `attr`. */
function verdict(attr: Attr, value: string): Verdict {
  if (attr.kind === 'boolean') return 'valid';
  const d = attr.description;
  // An attribute a body type reports whatever its value ("(a rope, cloth or ragdoll reports it", on density).
  const reporters = d.match(/\(an? ([a-z,\s]+) reports it/)?.[1].split(/,\s*|\s+or\s+/) ?? [];
  if (reporters.some((r) => attr.tag === `physics-${r}`)) return 'invalid';
  if (attr.kind === 'number') {
    if (value.trim() === '') return 'invalid';
    // A number that also takes a word its description quotes (substeps: "auto").
    if (/^[a-z-]+$/.test(value) && d.includes(`"${value}"`)) return 'valid';
    const n = Number(value);
    if (!Number.isFinite(n)) return 'invalid';
    const documented = attr.min !== undefined || attr.max !== undefined || attr.integer;
    if (attr.min !== undefined && (attr.minExclusive ? !(n > attr.min) : n < attr.min)) return 'invalid';
    if (attr.max !== undefined && n > attr.max) return 'invalid';
    if (attr.integer && !Number.isInteger(n)) return 'invalid';
    if (COORDINATES.has(attr.name) && Math.abs(n) > 1e9) return 'invalid';
    // Documented on both sides, or unbounded by nature: a valid number must be taken without complaint.
    if ((attr.min !== undefined && attr.max !== undefined) || UNBOUNDED.has(attr.name)) return 'valid';
    // One side documented: a moderate value on the allowed side must be taken, unless the bound depends on the scene.
    return documented && Math.abs(n) <= 1e6 && !/less than the/.test(d) ? 'valid' : 'either';
  }
  if (attr.kind !== 'string') return 'either';
  const v = value.trim();
  if (/colou?r/i.test(d)) {
    if (v === '') return 'either';
    if (v === 'none') return 'valid';
    return CSS.supports('color', v) ? 'valid' : 'invalid';
  }
  if (/^Id of/i.test(d)) return 'invalid'; // no body has a hostile id
  if (/^Gravity/.test(d)) return listOfNumbers(v)?.length === 2 ? 'valid' : 'invalid';
  if (/^Outline/.test(d)) return 'invalid'; // no hostile value is a polygon
  if (/column indices/.test(d)) {
    if (v === '') return 'either';
    if (attr.options?.includes(v)) return 'valid';
    const list = listOfNumbers(v);
    return list && list.every((c) => Number.isInteger(c) && c >= 0 && c <= 4) ? 'valid' : list && list.some((c) => !Number.isInteger(c) || c < 0 || c > 1e6) ? 'invalid' : 'either';
  }
  if (attr.options) {
    if (v === '') return 'either';
    return attr.options.includes(value) ? 'valid' : 'invalid';
  }
  return 'either';
}

// ---- scenes ----------------------------------------------------------------------------------------------------

const SCENE_TAGS = new Set(['physics-scene', 'cloth-sim', 'ragdoll-sim']);
/**
 * Attributes the fixture needs on each target (a fuzzed one is put back to this value after its case). The scenes are
 * paused: every step is one the checks take, so how far the probe moves does not depend on the machine's speed (a
 * running scene's own steps between the kick and the reading could swing it back to where it was).
 */
const BASE: Record<string, Record<string, string>> = {
  'physics-scene': { width: '16', height: '9', paused: '' },
  'cloth-sim': { columns: '6', rows: '5', paused: '' },
  'ragdoll-sim': { count: '2', paused: '' },
  'physics-box': { x: '12', y: '4' },
  'physics-circle': { x: '12', y: '4' },
  'physics-polygon': { x: '12', y: '4', points: '0,0 1,0 0,1' },
  'physics-rope': { x1: '10', y1: '1', x2: '13', y2: '1', segments: '6' },
  'physics-cloth': { x: '10', y: '1', columns: '4', rows: '3' },
  'physics-softbody': { x: '12', y: '4', radius: '0.8', segments: '8' },
  'physics-ragdoll': { x: '12', y: '4' },
  'physics-joint': { a: 'A', b: 'B' },
  'physics-spring': { a: 'A', b: 'B' },
  'physics-pin': { body: 'A', x: '6', y: '2' },
};
/** The bodies every <physics-scene> fixture holds: a floor, the probe (kept moving), and A and B for the links. */
const FIXTURE = `<physics-box id="floor" static x="8" y="8.6" width="16" height="0.8"></physics-box>
  <physics-circle id="probe" x="2" y="3" radius="0.3"></physics-circle>
  <physics-box id="A" x="6" y="3" width="1" height="1"></physics-box>
  <physics-box id="B" x="9" y="3" width="1" height="1"></physics-box>`;

interface Recorder {
  errors: PhysicsErrorDetail[];
  warnings: string[];
  uncaught: string[];
  stop(): void;
}

function record(): Recorder {
  const r: Recorder = { errors: [], warnings: [], uncaught: [], stop: () => {} };
  const warn = console.warn;
  console.warn = (...args: unknown[]) => void r.warnings.push(args.map(String).join(' '));
  const onError = (e: Event) => r.errors.push((e as CustomEvent<PhysicsErrorDetail>).detail);
  const onUncaught = (e: ErrorEvent) => r.uncaught.push(String(e.error ?? e.message));
  const onRejection = (e: PromiseRejectionEvent) => r.uncaught.push(`unhandled rejection: ${String(e.reason)}`);
  document.addEventListener('physics-error', onError, true);
  window.addEventListener('error', onUncaught);
  window.addEventListener('unhandledrejection', onRejection);
  r.stop = () => {
    console.warn = warn;
    document.removeEventListener('physics-error', onError, true);
    window.removeEventListener('error', onUncaught);
    window.removeEventListener('unhandledrejection', onRejection);
  };
  return r;
}

function frameOf(scene: PhysicsSceneElement): Float64Array | null {
  const client = scene.client;
  if (!client) return null;
  client.poll();
  return client.frames.received > 0 ? client.frames.curr : null;
}

/** Index and value of the first non-finite number of the newest published frame, or null when all are finite. */
function nonFinite(scene: PhysicsSceneElement): string | null {
  const f = frameOf(scene);
  if (!f) return 'no frame';
  const n = frameLength(f[F.particles], f[F.bodies], f[F.contacts], f[F.debug] !== 0);
  for (let i = 0; i < n; i++) if (!Number.isFinite(f[i])) return `frame[${i}] = ${f[i]} (of ${n})`;
  return null;
}

/** The body kept moving during the fuzz: the probe ball, or the preset's cloth / first ragdoll. */
function probeOf(scene: PhysicsSceneElement): (Element & { x: number; y: number; setVelocity(vx: number, vy: number): void }) | null {
  return (scene.querySelector('#probe') ?? scene.shadowRoot?.querySelector('physics-cloth, physics-ragdoll')) as never;
}

/** Every element of the document and of every shadow root below it. */
function* allElements(root: Document | ShadowRoot | Element = document): Generator<Element> {
  for (const el of Array.from(root.querySelectorAll('*'))) {
    yield el;
    if (el.shadowRoot) yield* allElements(el.shadowRoot);
  }
}

/** The test page's own scripts, counted before any fuzzing. */
const pageScripts = document.querySelectorAll('script').length;

function assertNoMarkup(where: string): void {
  expect((window as { __pwned?: unknown }).__pwned, `${where}: window.__pwned`).to.equal(undefined);
  expect([...allElements()].filter((el) => el.localName === 'script').length, `${where}: scripts in the page`).to.equal(pageScripts);
  for (const el of allElements()) {
    if (el.localName === 'img' || el.localName === 'iframe' || el.localName === 'object' || el.localName === 'embed') throw new Error(`${where}: a <${el.localName}> appeared in the document`);
    for (const a of Array.from(el.attributes)) if (/^on/i.test(a.name)) throw new Error(`${where}: <${el.localName}> got an ${a.name} attribute`);
  }
}

interface Case {
  attr: Attr;
  name: string;
  value: string;
}

const label = (c: Case) => `seed ${SEED.toString(16)} <${c.attr.tag}> ${c.attr.name}=${c.name.length > 40 ? c.name.slice(0, 40) + '…' : JSON.stringify(c.name)}`;

const CONTROL = /[\p{Cc}\p{Cf}\u2028\u2029]/u;

/** How a warning shows `name="value"`: whole when short and plain, else (escaped and cut) its plain beginning. */
function shownAs(name: string, value: string): string {
  if (value.length <= 100 && !CONTROL.test(value)) return `${name}="${value}"`;
  const plain = value.slice(0, 20);
  const cut = plain.search(CONTROL);
  return `${name}="${cut < 0 ? plain : plain.slice(0, cut)}`;
}

/** Checks the physics-error events and warnings one case produced. */
function checkReports(c: Case, target: Element, errors: PhysicsErrorDetail[], warnings: string[]): void {
  const v = verdict(c.attr, c.value);
  const mine = errors.filter((e) => e.element === target);
  const named = mine.filter((e) => e.attribute === c.attr.name && e.value === c.value);
  const where = label(c);
  if (v === 'invalid') expect(named.length, `${where}: a physics-error naming the attribute and value (got ${JSON.stringify(mine.map((e) => [e.attribute, e.message]))})`).to.be.greaterThan(0);
  if (v === 'valid') expect(mine.map((e) => `${e.attribute}: ${e.message}`), `${where}: a valid value must not be refused`).to.deep.equal([]);
  // Every report of this case is about this attribute and value, and each has its console warning.
  for (const e of mine) {
    expect([e.attribute, e.value === c.value], `${where}: unexpected report ${e.attribute}="${e.value.slice(0, 60)}": ${e.message}`).to.deep.equal([c.attr.name, true]);
    expect(warnings.some((w) => w.includes(`<${c.attr.tag}`) && w.includes(shownAs(c.attr.name, c.value))), `${where}: a console.warn naming it`).to.equal(true);
  }
  // Messages stay short and plain whatever the value: no control or bidi characters, no 100k-character lines.
  for (const w of warnings) {
    expect(w.length, `${where}: warning length`).to.be.below(1000);
    expect(/[\p{Cc}\p{Cf}]/u.test(w), `${where}: control characters in a warning`).to.equal(false);
  }
}

/**
 * The probe's live pose. step() resolves once the page has the frame of its last step with that frame's topology, so
 * the pose of a body rebuilt just before is there at once; on a loaded machine this waits (never steps) for it, so
 * every case takes the same steps and the whole run is the same simulation however fast the machine is.
 */
async function livePose(scene: PhysicsSceneElement, probe: Element): Promise<[number, number, number] | null> {
  const until = performance.now() + 15000;
  for (;;) {
    const pose = scene.poseOf(probe);
    if (pose || performance.now() > until) return pose;
    await new Promise((r) => setTimeout(r, 10));
  }
}

/** Steps the scene, kicks the probe once, and checks that it moved and the frame is finite. */
async function checkAlive(scene: PhysicsSceneElement, where: string, c?: Case, live = false): Promise<void> {
  const count = scene.stepCount;
  const probe = probeOf(scene);
  // One step first: the newest frame then shows every change sent so far (a frame from before a rebuild would do).
  await scene.step(1);
  const before = probe && (await livePose(scene, probe));
  probe?.setVelocity(1.5, -4);
  const stepped = await scene.step(3);
  expect(stepped, `${where}: the step counter advances`).to.be.greaterThan(count);
  // step() waits up to 2 s for its frame; on a loaded machine it may need longer.
  const until = performance.now() + 15000;
  while ((frameOf(scene)?.[F.stepCount] ?? -1) < stepped && performance.now() < until) await new Promise((r) => setTimeout(r, 10));
  expect(frameOf(scene)?.[F.stepCount], `${where}: the frame of step ${stepped} reaches the page`).to.be.at.least(stepped);
  expect(nonFinite(scene), `${where}: the published frame is finite`).to.equal(null);
  if (probe) {
    expect(before, `${where}: the probe body is simulated`).to.not.equal(null);
    const after = await livePose(scene, probe);
    expect(after, `${where}: the probe body is still simulated`).to.not.equal(null);
    const moved = Math.hypot(after![0] - before![0], after![1] - before![1]);
    expect(moved, `${where}: the probe body moves when kicked`).to.be.greaterThan(1e-4);
  }
}

/** Mounts a scene of `tag` built with DOM calls (so hostile attributes can be set before it connects). */
async function mountScene(tag: string, setup: (scene: PhysicsSceneElement) => void = () => {}): Promise<PhysicsSceneElement> {
  const box = document.createElement('div');
  box.style.cssText = 'width: 320px; height: 200px; position: relative;';
  const scene = document.createElement(tag) as PhysicsSceneElement;
  scene.style.cssText = 'width: 100%; height: 100%';
  for (const [k, v] of Object.entries(BASE[tag] ?? {})) scene.setAttribute(k, v);
  // Fixed test markup only.
  if (tag === 'physics-scene') scene.innerHTML = FIXTURE;
  setup(scene);
  box.append(scene);
  document.body.append(box);
  await scene.ready;
  return scene;
}

/** A target element with its base attributes; with `own`, a link gets bodies of its own (ids "A-own", "B-own"). */
function makeTarget(tag: string, scene: Element, own?: number): HTMLElement {
  const el = document.createElement(tag);
  for (const [k, v] of Object.entries(BASE[tag] ?? {})) el.setAttribute(k, own !== undefined && (v === 'A' || v === 'B') ? `${v}-${own}` : v);
  if (own !== undefined && (el.hasAttribute('a') || el.hasAttribute('body'))) {
    for (const name of ['A', 'B']) {
      const box = document.createElement('physics-box');
      box.id = `${name}-${own}`;
      box.setAttribute('x', String(1 + (own % 14) + (name === 'B' ? 0.5 : 0)));
      box.setAttribute('y', String(1 + Math.floor(own / 14)));
      box.setAttribute('width', '0.3');
      box.setAttribute('height', '0.3');
      scene.append(box);
    }
    if (el.hasAttribute('body')) el.setAttribute('x', String(1 + (own % 14)));
  }
  return el;
}

function restore(el: Element, attr: string, tag: string): void {
  const base = BASE[tag]?.[attr];
  if (base === undefined) el.removeAttribute(attr);
  else el.setAttribute(attr, base);
}

/** The cases of one element: every fixed hostile value, plus random ones from the PRNG, for every attribute. */
function casesOf(attrs: Attr[], rand: () => number): Case[] {
  const out: Case[] = [];
  for (const attr of attrs) {
    for (const [name, value] of HOSTILE) out.push({ attr, name, value });
    for (let k = 0; k < RANDOM_PER_ATTRIBUTE; k++) {
      const value = randomValue(rand);
      out.push({ attr, name: value, value });
    }
  }
  return out;
}

/** Waits until the scene and every element in it (light and shadow DOM) have finished updating. */
async function settle(scene: PhysicsSceneElement): Promise<void> {
  for (let round = 0; round < 3; round++) {
    const els: Element[] = [scene, ...allElements(scene), ...(scene.shadowRoot ? allElements(scene.shadowRoot) : [])];
    await Promise.all(els.map((el) => (el as unknown as { updateComplete?: Promise<unknown> }).updateComplete));
  }
}

/** Live: one loaded scene; each case sets the attribute, checks, and puts the base value back. */
async function fuzzLive(tag: string, cases: Case[]): Promise<number> {
  const rec = record();
  let scene: PhysicsSceneElement | null = null;
  let n = 0;
  try {
    scene = await mountScene(SCENE_TAGS.has(tag) ? tag : 'physics-scene', (s) => {
      if (!SCENE_TAGS.has(tag)) {
        const t = makeTarget(tag, s);
        t.id = 'target';
        s.append(t);
      }
    });
    const target = SCENE_TAGS.has(tag) ? scene : scene.querySelector('#target')!;
    await checkAlive(scene, `<${tag}> live fixture`);
    expect(rec.errors.map((e) => `${e.attribute}: ${e.message}`), `<${tag}> fixture reports nothing`).to.deep.equal([]);
    for (const c of cases) {
      n++;
      const where = `${label(c)} (live)`;
      // The fixture's bodies start each case afresh (rebuilt at rest where the markup puts them): a valid but absurd
      // earlier value leaves them where it put them and moving as it made them move. A soft body of radius 1e12 may
      // have jammed the probe between the floor and the bottom wall, where no kick moves it; a pin at x = 1e12 set A
      // spinning at thousands of radians per second (joints before e71531c), and A, free once the next case dropped
      // the pin, smashed the freshly rebuilt probe into the floor there.
      for (const id of ['probe', 'A', 'B']) scene.querySelector(`#${id}`)?.setAttribute('y', String(3 + (n % 2) * 1e-3));
      rec.errors.length = 0;
      rec.warnings.length = 0;
      target.setAttribute(c.attr.name, c.value);
      await settle(scene);
      await checkAlive(scene, where, c, true);
      checkReports(c, target, rec.errors, rec.warnings);
      expect(rec.uncaught, `${where}: uncaught errors`).to.deep.equal([]);
      expect((window as { __pwned?: unknown }).__pwned, `${where}: window.__pwned`).to.equal(undefined);
      // Putting the value back is quiet and clears the error box.
      rec.errors.length = 0;
      restore(target, c.attr.name, tag);
      await settle(scene);
      // A restarted engine (the worker attribute changed) must be ready, and the preset's first calls answered,
      // before the next case restarts it again (the known issue above).
      if (c.attr.name === 'worker') await scene.step(1);
      expect(rec.errors.map((e) => `${e.attribute}="${e.value.slice(0, 40)}": ${e.message}`), `${where}: putting it back reports nothing`).to.deep.equal([]);
    }
    await checkAlive(scene, `<${tag}> after the live fuzz`);
    const box = scene.shadowRoot!.querySelector<HTMLElement>('.error')!;
    expect(box.hidden, `<${tag}>: the error box is empty once every value is put back (${box.textContent?.slice(0, 200)})`).to.equal(true);
    expect(box.children.length, 'the error box holds text only').to.equal(0);
    assertNoMarkup(`<${tag}> live`);
    return n;
  } finally {
    rec.stop();
    unmount(scene);
  }
}

/** Before connecting, children: one scene per attribute holding one target per value. */
async function fuzzChildBeforeConnect(tag: string, all: Case[]): Promise<number> {
  let n = 0;
  for (const attr of new Set(all.map((c) => c.attr))) {
    const cases = all.filter((c) => c.attr === attr);
    const rec = record();
    let scene: PhysicsSceneElement | null = null;
    try {
      const targets: Element[] = [];
      scene = await mountScene('physics-scene', (s) => {
        for (const c of cases) {
          const t = makeTarget(tag, s, targets.length);
          t.setAttribute(attr.name, c.value);
          targets.push(t);
          s.append(t);
        }
      });
      await checkAlive(scene, `<${tag}> ${attr.name}: scene with every value set before connecting`);
      cases.forEach((c, k) => checkReports(c, targets[k], rec.errors, rec.warnings));
      n += cases.length;
      expect(rec.uncaught, `<${tag}> ${attr.name} before connecting: uncaught errors`).to.deep.equal([]);
      expect(rec.warnings.length, `<${tag}> ${attr.name}: one warning per physics-error`).to.equal(rec.errors.length);
      assertNoMarkup(`<${tag}> ${attr.name} before connecting`);
    } finally {
      rec.stop();
      unmount(scene);
    }
  }
  return n;
}

/** Before connecting, scenes: a scene per case, PRECONNECT_SCENE_SAMPLE values per attribute drawn by the PRNG. */
/** Before connecting, scenes: a scene of its own per case. */
async function fuzzSceneBeforeConnect(tag: string, cases: Case[]): Promise<number> {
  let n = 0;
  for (const c of cases) {
    const rec = record();
    let scene: PhysicsSceneElement | null = null;
    const where = `${label(c)} (before connecting)`;
    try {
      scene = await mountScene(tag, (s) => s.setAttribute(c.attr.name, c.value));
      await settle(scene);
      await checkAlive(scene, where, c);
      checkReports(c, scene, rec.errors, rec.warnings);
      expect(rec.uncaught, `${where}: uncaught errors`).to.deep.equal([]);
      assertNoMarkup(where);
      n++;
    } finally {
      rec.stop();
      unmount(scene);
    }
  }
  return n;
}

/** PRECONNECT_SCENE_SAMPLE cases per attribute, drawn by the PRNG. */
function sample(cases: Case[], rand: () => number): Case[] {
  const out: Case[] = [];
  for (const attr of new Set(cases.map((c) => c.attr))) {
    const mine = cases.filter((c) => c.attr === attr);
    for (let k = 0; k < PRECONNECT_SCENE_SAMPLE && mine.length > 0; k++) out.push(mine.splice(Math.floor(rand() * mine.length), 1)[0]);
  }
  return out;
}

describe('markup fuzz', function () {
  this.timeout(180_000);
  let attrs: Map<string, Attr[]>;
  before(async () => {
    attrs = await attributes();
  });
  afterEach(() => {
    delete (window as { __pwned?: unknown }).__pwned;
  });

  it('the manifest lists every element with its attributes, and the derived rules make sense', () => {
    const tags = [...attrs.keys()].sort();
    expect(tags).to.include.members(['physics-scene', 'physics-box', 'physics-circle', 'physics-polygon', 'physics-rope', 'physics-cloth', 'physics-softbody', 'physics-ragdoll', 'physics-joint', 'physics-spring', 'physics-pin', 'cloth-sim', 'ragdoll-sim']);
    const find = (tag: string, name: string) => attrs.get(tag)!.find((a) => a.name === name)!;
    expect(find('physics-box', 'width')).to.deep.include({ kind: 'number', min: 0, minExclusive: true });
    expect(find('ragdoll-sim', 'count')).to.deep.include({ kind: 'number', min: 1, max: 12, integer: true });
    expect(find('physics-rope', 'pin').options).to.deep.equal(['start', 'end', 'both', 'none']);
    expect(find('physics-scene', 'timestep').kind).to.equal('number');
    expect(find('physics-scene', 'substeps')).to.deep.include({ kind: 'number', min: 1, max: 1000, integer: true });
    expect(['auto', '3', '0', '2.5', 'autos', '-1'].map((v) => verdict(find('physics-scene', 'substeps'), v))).to.deep.equal(['valid', 'valid', 'invalid', 'invalid', 'invalid', 'invalid']);
    expect(find('physics-box', 'static').kind).to.equal('boolean');
    expect(verdict(find('physics-box', 'width'), '0')).to.equal('invalid');
    expect(verdict(find('physics-box', 'x'), '-1')).to.equal('valid');
    expect(verdict(find('physics-box', 'fill'), 'none')).to.equal('valid');
    expect(verdict(find('physics-box', 'fill'), '<img>')).to.equal('invalid');
    expect(verdict(find('physics-box', 'density'), '2')).to.equal('valid');
    expect(verdict(find('physics-cloth', 'density'), '2')).to.equal('invalid');
    for (const list of attrs.values()) for (const a of list) expect(a.kind, `<${a.tag}> ${a.name} has a type`).to.not.equal('unknown');
  });

  it('no attribute can reach HTML: no innerHTML, unsafeHTML or the like in the element and renderer sources', async () => {
    const paths = (await manifest()).modules.map((m) => m.path);
    expect(paths.length).to.be.greaterThan(10);
    for (const path of paths) {
      const text = await (await fetch(`/${path}`, { headers: { accept: 'text/plain' } })).text();
      expect(text.length, path).to.be.greaterThan(0);
      const hit = text.match(/\.innerHTML\s*=|\.outerHTML\s*=|insertAdjacentHTML|unsafeHTML|unsafeSVG|document\.write|createContextualFragment|parseFromString/);
      expect(hit?.[0] ?? null, `${path} writes markup`).to.equal(null);
    }
  });

  for (const tag of ['physics-box', 'physics-circle', 'physics-polygon', 'physics-rope', 'physics-cloth', 'physics-softbody', 'physics-ragdoll', 'physics-joint', 'physics-spring', 'physics-pin']) {
    it(`<${tag}>: every attribute, hostile values before connecting and live`, async () => {
      const list = attrs.get(tag)!;
      const cases = casesOf(list, prng(SEED ^ hash(tag)));
      expect(await fuzzChildBeforeConnect(tag, cases)).to.equal(list.length * (HOSTILE.length + RANDOM_PER_ATTRIBUTE));
      expect(await fuzzLive(tag, cases)).to.equal(cases.length);
    });
  }

  for (const tag of ['physics-scene', 'cloth-sim', 'ragdoll-sim']) {
    it(`<${tag}>: every attribute, hostile values live, and a sample before connecting`, async () => {
      const list = attrs.get(tag)!;
      const rand = prng(SEED ^ hash(tag));
      const cases = casesOf(list, rand);
      expect(await fuzzLive(tag, cases)).to.equal(list.length * (HOSTILE.length + RANDOM_PER_ATTRIBUTE));
      expect(await fuzzSceneBeforeConnect(tag, sample(cases, rand))).to.equal(list.length * PRECONNECT_SCENE_SAMPLE);
    });
  }

  // Cases the fuzz found (seed 5eed0008), by name, fixed in the element code; each runs before connecting and live.
  const REGRESSIONS: [tag: string, attribute: string, value: string, what: string][] = [
    ['physics-box', 'x', 'NaN', 'x set live while the body sits at its declared x was ignored (Lit compared the live pose with the old value)'],
    ['physics-box', 'angle', '', 'an empty angle set live while the body is unrotated was ignored'],
    ['physics-rope', 'x1', '', 'an empty number attribute was taken as 0 without a report'],
    ['physics-box', 'friction', ' ', 'a blank friction became 0 instead of the default 0.6, silently'],
    ['cloth-sim', 'wind', '', 'an empty wind was ignored live (Number("") is 0, the default: no change)'],
    ['physics-rope', 'x', 'NaN', 'x, y and angle of a rope were not checked at all'],
    ['physics-cloth', 'angle', 'Infinity', 'angle of a cloth was not checked at all'],
    ['physics-rope', 'slack', '0', 'slack 0 was accepted (links of length 0)'],
    ['cloth-sim', 'spacing', '1e12', 'a cloth 1e13 units wide was accepted and froze against the walls'],
    ['physics-joint', 'a', LONG_DIGITS, 'the message repeated the 100k-character id: a 100k-character warning'],
    ['physics-scene', 'width', LONG_TEXT, '140k characters with U+202E in the error box took 4 s of layout'],
  ];
  for (const [tag, attribute, value, what] of REGRESSIONS) {
    it(`regression (seed ${SEED.toString(16)}): <${tag}> ${attribute}="${value.length > 20 ? `${value.slice(0, 12)}… (${value.length} characters)` : value}": ${what}`, async () => {
      const attr = attrs.get(tag)!.find((a) => a.name === attribute)!;
      const c: Case = { attr, name: value, value };
      expect(verdict(attr, value), 'the value is invalid by the documentation').to.equal('invalid');
      if (SCENE_TAGS.has(tag)) expect(await fuzzSceneBeforeConnect(tag, [c])).to.equal(1);
      else expect(await fuzzChildBeforeConnect(tag, [c])).to.equal(1);
      expect(await fuzzLive(tag, [c])).to.equal(1);
    });
  }
});

function hash(s: string): number {
  let h = 0;
  for (let k = 0; k < s.length; k++) h = (Math.imul(h, 31) + s.charCodeAt(k)) | 0;
  return h;
}

