// The gallery: a sidebar of stories (a menu button on phones), the live scene with stats under it (a toggle), a
// controls panel generated from each element's lit properties, and the markup snippet, kept in step with every edit:
// what Copy copies, the README's script line and the tag with its box reserved. Everything is built with the DOM
// API (createElement, setAttribute, textContent): no attribute value ever goes through innerHTML.
import { allStories, type Node, type Story } from './stories.js';

type SceneEl = HTMLElement & {
  ready: Promise<void>;
  mode: 'worker' | 'main' | null;
  transport: string | null;
  stepCount: number;
  renderedFrames: number;
  canvas: HTMLCanvasElement | null;
  diagnostics(): Promise<{ bodyCount: number; particleCount: number; linkCount: number; stepMs: number; transport: string; mode: string }>;
  drawHook: unknown;
};

// ---- main-thread time: every timer and animation-frame callback on this page is timed ---------------------------

const busy = { ms: 0 };
{
  const rawTimeout = window.setTimeout.bind(window);
  const rawRaf = window.requestAnimationFrame.bind(window);
  const timed = <A extends unknown[]>(fn: (...a: A) => void) => (...a: A) => {
    const t0 = performance.now();
    try {
      fn(...a);
    } finally {
      busy.ms += performance.now() - t0;
    }
  };
  window.setTimeout = ((fn: TimerHandler, ms?: number, ...rest: unknown[]) => (typeof fn === 'function' ? rawTimeout(timed(fn as (...a: unknown[]) => void), ms, ...rest) : rawTimeout(fn, ms, ...rest))) as typeof window.setTimeout;
  window.requestAnimationFrame = ((cb: FrameRequestCallback) => rawRaf(timed(cb))) as typeof window.requestAnimationFrame;
}

let longTasks = 0;
try {
  new PerformanceObserver((list) => (longTasks += list.getEntries().length)).observe({ type: 'longtask', buffered: false });
} catch {
  /* no long-task timing in this browser */
}

await import('../../src/index.js');

// ---- helpers ------------------------------------------------------------------------------------------------------

function el<K extends keyof HTMLElementTagNameMap>(tag: K, props: Partial<Record<string, string>> = {}, ...kids: (Node_ | string)[]): HTMLElementTagNameMap[K] {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(props)) if (v !== undefined) k === 'text' ? (e.textContent = v) : e.setAttribute(k, v);
  for (const kid of kids) e.append(kid);
  return e;
}
type Node_ = globalThis.Node;

/** Escapes an attribute value for the markup snippet (shown as text, but copied as markup). */
export const escapeAttr = (v: string) => v.replace(/&/g, '&amp;').replace(/"/g, '&quot;').replace(/</g, '&lt;').replace(/>/g, '&gt;');

function markup(node: Node, indent = ''): string {
  const attrs = Object.entries(node.attrs)
    .map(([k, v]) => (v === true ? ` ${k}` : ` ${k}="${escapeAttr(v)}"`))
    .join('');
  const kids = node.children ?? [];
  if (!kids.length) return `${indent}<${node.tag}${attrs}></${node.tag}>`;
  return `${indent}<${node.tag}${attrs}>\n${kids.map((c) => markup(c, indent + '  ')).join('\n')}\n${indent}</${node.tag}>`;
}

function build(node: Node): HTMLElement {
  const e = document.createElement(node.tag);
  for (const [k, v] of Object.entries(node.attrs)) e.setAttribute(k, v === true ? '' : v);
  for (const c of node.children ?? []) e.append(build(c));
  return e;
}

const clone = (node: Node): Node => ({ tag: node.tag, attrs: { ...node.attrs }, children: node.children?.map(clone) });

const ENUMS: Record<string, string[]> = {
  broadphase: ['grid', 'brute'],
  narrowphase: ['sat', 'gjk'],
  worker: ['auto', 'none'],
  bounds: ['view', 'none'],
  'draw-mode': ['over', 'replace'],
  model: ['rigid', 'particles'],
  // Keyed by tag and attribute where one element's values differ from the others'.
  'physics-softbody model': ['pressure', 'springs'],
  pin: ['start', 'end', 'both', 'none'],
};

interface PropInfo {
  attr: string;
  kind: 'number' | 'boolean' | 'string';
}

/** The attributes an element class declares, from lit's elementProperties. */
function propsOf(tag: string): PropInfo[] {
  const ctor = customElements.get(tag) as (CustomElementConstructor & { elementProperties?: Map<string, { attribute?: string | boolean; type?: unknown }> }) | undefined;
  if (!ctor?.elementProperties) return [];
  const out: PropInfo[] = [];
  for (const [name, opts] of ctor.elementProperties) {
    if (opts.attribute === false) continue;
    const attr = typeof opts.attribute === 'string' ? opts.attribute : String(name).toLowerCase();
    out.push({ attr, kind: opts.type === Number ? 'number' : opts.type === Boolean ? 'boolean' : 'string' });
  }
  return out;
}

// ---- the page -----------------------------------------------------------------------------------------------------

const stories = allStories();
const nav = document.getElementById('stories')!;
const title = document.getElementById('story-title')!;
const description = document.getElementById('story-description')!;
const stage = document.getElementById('stage')!;
const controls = document.getElementById('controls')!;
const snippet = document.getElementById('snippet')!;
const stats = document.getElementById('stats')!;
const toggles = document.getElementById('toggles')!;
const copyButton = document.getElementById('copy') as HTMLButtonElement;
const navEl = nav.closest('nav')!;
const navToggle = document.getElementById('nav-toggle') as HTMLButtonElement;

/** The README's script line (scripts/check-gallery.mjs checks they are the same). */
export const SCRIPT_LINE = '<script defer src="https://cdn.jsdelivr.net/npm/physics-elements@0.1.0/dist/physics-elements.iife.js"></script>';

// Phones: the story list opens from a button and closes when a story is chosen.
const setNavOpen = (open: boolean) => {
  navEl.classList.toggle('open', open);
  navToggle.setAttribute('aria-expanded', String(open));
};
navToggle.addEventListener('click', () => setNavOpen(!navEl.classList.contains('open')));
nav.addEventListener('click', (e) => (e.target as Element).closest('a') && setNavOpen(false));
document.addEventListener('keydown', (e) => {
  if (e.key !== 'Escape' || !navEl.classList.contains('open')) return;
  setNavOpen(false);
  navToggle.focus();
});

let groupEl: HTMLElement | null = null;
let lastGroup = '';
for (const s of stories) {
  if (s.group !== lastGroup) {
    lastGroup = s.group;
    groupEl = el('ul');
    nav.append(el('h3', { text: s.group }), groupEl);
  }
  const a = el('a', { href: `#${s.id}`, text: s.title, 'data-story': s.id });
  groupEl!.append(el('li', {}, a));
}

interface Current {
  story: Story;
  data: Node;
  scene: SceneEl;
  featured: HTMLElement | null;
  featuredData: Node | null;
}
let current: Current | null = null;

/**
 * The snippet a page pastes: the script line, then the scene's tag with its box reserved before the script runs
 * (display:block and the aspect ratio of its view, which is the element's own sizing once defined: no layout shift)
 * and a line of fallback text, which the box shows until the scene starts and keeps if the script cannot load (a
 * blank box said nothing to a reader).
 */
function refreshSnippet(): void {
  if (!current) return;
  const { scene, data, story } = current;
  const [w, h] = [Number((scene as unknown as { width: unknown }).width), Number((scene as unknown as { height: unknown }).height)];
  const valid = Number.isFinite(w) && w > 0 && Number.isFinite(h) && h > 0;
  if (valid) stage.style.setProperty('--view-ratio', String(w / h));
  const reserved = valid && data.attrs.style === undefined;
  const root = reserved ? { ...data, attrs: { ...data.attrs, style: `display:block;aspect-ratio:${w}/${h}` } } : data;
  const tag = markup(root);
  // The opening tag ends at its first ">": attribute values are escaped (escapeAttr).
  const open = tag.indexOf('>') + 1;
  const rest = tag.slice(open);
  const fallback = `<p slot="fallback">${escapeAttr(story.title)}: an interactive physics animation.</p>`;
  snippet.textContent = `${SCRIPT_LINE}\n${tag.slice(0, open)}\n  ${fallback}${rest.startsWith('\n') ? rest : `\n${rest}`}`;
}

function setAttr(target: HTMLElement, data: Node, attr: string, value: string | true | null): void {
  if (value === null) {
    target.removeAttribute(attr);
    delete data.attrs[attr];
  } else {
    target.setAttribute(attr, value === true ? '' : value);
    data.attrs[attr] = value;
  }
  refreshSnippet();
  syncToggles();
  writeHash();
}

function controlFor(target: HTMLElement, data: Node, p: PropInfo): HTMLElement {
  const id = `c-${data.tag}-${p.attr}`;
  const label = el('label', { for: id, text: p.attr });
  let input: HTMLInputElement | HTMLSelectElement;
  const value = data.attrs[p.attr];
  if (p.kind === 'boolean') {
    input = el('input', { id, type: 'checkbox' });
    input.checked = value !== undefined;
    input.addEventListener('change', () => setAttr(target, data, p.attr, (input as HTMLInputElement).checked ? true : null));
  } else if (ENUMS[`${data.tag} ${p.attr}`] ?? ENUMS[p.attr]) {
    input = el('select', { id });
    input.append(el('option', { value: '', text: '(default)' }));
    for (const o of ENUMS[`${data.tag} ${p.attr}`] ?? ENUMS[p.attr]) input.append(el('option', { value: o, text: o }));
    input.value = typeof value === 'string' ? value : '';
    input.addEventListener('change', () => setAttr(target, data, p.attr, input.value === '' ? null : input.value));
  } else {
    input = el('input', { id, type: p.kind === 'number' ? 'number' : 'text', step: 'any', placeholder: 'default' });
    input.value = typeof value === 'string' ? value : '';
    // Applied when the value is committed (Enter, leaving the field, a spinner click), not at every keystroke: a
    // half-typed "0 -" is not reported as an error on the way to "0 -3".
    input.addEventListener('change', () => setAttr(target, data, p.attr, input.value === '' ? null : input.value));
  }
  input.dataset.attr = p.attr;
  return el('div', { class: `control ${p.kind}` }, label, input);
}

function renderControls(): void {
  controls.replaceChildren();
  if (!current) return;
  const sections: [HTMLElement, Node][] = [[current.scene, current.data]];
  if (current.featured && current.featuredData) sections.push([current.featured, current.featuredData]);
  for (const [target, data] of sections) {
    const box = el('fieldset', {}, el('legend', { text: `<${data.tag}${data.attrs.id ? ` id="${data.attrs.id}"` : ''}>` }));
    for (const p of propsOf(data.tag)) box.append(controlFor(target, data, p));
    controls.append(box);
  }
}

// Toolbar toggles: attributes of the scene element, shared with the controls panel.
const TOGGLES: { attr: string; on: string; off: string | null; label: string }[] = [
  { attr: 'worker', on: 'none', off: null, label: 'main thread (worker="none")' },
  { attr: 'broadphase', on: 'brute', off: null, label: 'brute-force broad phase' },
  { attr: 'narrowphase', on: 'gjk', off: null, label: 'GJK + EPA narrow phase' },
  { attr: 'debug', on: '', off: null, label: 'debug drawing' },
];
const toggleInputs = TOGGLES.map((t) => {
  const input = el('input', { type: 'checkbox', id: `t-${t.attr}`, 'data-toggle': t.attr });
  input.addEventListener('change', () => {
    if (!current) return;
    setAttr(current.scene, current.data, t.attr, input.checked ? (t.on === '' ? true : t.on) : t.off);
    renderControls();
  });
  toggles.append(el('label', { class: 'toggle' }, input, ` ${t.label}`));
  return { t, input };
});

// The stats (fps, physics and main-thread time) go under the scene, only when asked for: measuring costs steps.
const statsToggle = el('input', { type: 'checkbox', id: 't-stats' });
statsToggle.addEventListener('change', () => {
  stats.hidden = !statsToggle.checked;
  resetStats();
});
toggles.append(el('label', { class: 'toggle' }, statsToggle, ' stats'));

function syncToggles(): void {
  for (const { t, input } of toggleInputs) {
    const v = current?.data.attrs[t.attr];
    input.checked = t.on === '' ? v !== undefined : v === t.on;
  }
}

function writeHash(): void {
  if (!current) return;
  const base = current.story.root.attrs;
  const params = new URLSearchParams();
  for (const t of TOGGLES) {
    const now = current.data.attrs[t.attr];
    if (now !== base[t.attr]) params.set(t.attr, now === undefined ? '' : now === true ? '1' : now);
  }
  const q = params.toString();
  history.replaceState(null, '', `#${current.story.id}${q ? `?${q}` : ''}`);
}

function show(id: string, query: URLSearchParams): void {
  const story = stories.find((s) => s.id === id) ?? stories[0];
  const data = clone(story.root);
  for (const t of TOGGLES) {
    if (!query.has(t.attr)) continue;
    const v = query.get(t.attr)!;
    if (v === '') delete data.attrs[t.attr];
    else data.attrs[t.attr] = t.on === '' ? true : v;
  }
  const scene = build(data) as SceneEl;
  const featuredData = story.featured !== undefined ? (data.children?.[story.featured] ?? null) : null;
  const featured = story.featured !== undefined ? (scene.children[story.featured] as HTMLElement) : null;
  current = { story, data, scene, featured, featuredData };
  pausedWatch.disconnect();
  pausedWatch.observe(scene, { attributes: true, attributeFilter: ['paused'] });
  stage.replaceChildren(scene);
  title.textContent = story.title;
  description.replaceChildren(...withCode(story.description));
  for (const a of nav.querySelectorAll('a')) a.classList.toggle('active', a.dataset.story === story.id);
  document.title = `${story.title} · physics-elements gallery`;
  renderControls();
  refreshSnippet();
  syncToggles();
  writeHash();
  resetStats();
  if (story.onReady) scene.ready?.then(() => current?.scene === scene && story.onReady!(scene));
}

/** A description's text with its `backticked` spans as <code> (built as nodes: nothing goes through innerHTML). */
function withCode(text: string): (string | HTMLElement)[] {
  return text.split('`').map((part, k) => (k % 2 === 1 ? el('code', { text: part }) : part));
}

/**
 * The scene pauses itself too (Space, the reduced-motion preference, its play control): the panel's `paused` box
 * shows the state the scene is in. The snippet keeps the markup as written (a reader's pause is not the page's).
 */
const pausedWatch = new MutationObserver(() => {
  if (!current) return;
  const box = controls.querySelector<HTMLInputElement>(`#c-${current.data.tag}-paused`);
  if (box) box.checked = current.scene.hasAttribute('paused');
});

function fromHash(): void {
  const raw = decodeURIComponent(location.hash.slice(1));
  const [id, q = ''] = raw.split('?');
  if (current && current.story.id === id) return;
  show(id, new URLSearchParams(q));
  // A story chosen while the page was scrolled down (on a phone, from the menu) starts at its title.
  window.scrollTo(0, 0);
}
window.addEventListener('hashchange', fromHash);

copyButton.addEventListener('click', async () => {
  const text = snippet.textContent ?? '';
  try {
    await navigator.clipboard.writeText(text);
    copyButton.textContent = 'Copied';
  } catch {
    // No clipboard API (a page not served over https or from localhost, as `npm start`'s network address is on a
    // phone): the snippet selected and copied the old way, or left selected for the reader to copy.
    const range = document.createRange();
    range.selectNodeContents(snippet);
    getSelection()?.removeAllRanges();
    getSelection()?.addRange(range);
    copyButton.textContent = document.execCommand('copy') ? 'Copied' : 'Selected: copy it';
  }
  setTimeout(() => (copyButton.textContent = 'Copy'), 1500);
});

// ---- stats --------------------------------------------------------------------------------------------------

let frames = 0;
let windowStart = performance.now();
let busyStart = busy.ms;
let stepStart = 0;
let stepMs = NaN;
let counts = { bodies: 0, particles: 0 };
let longStart = 0;
function resetStats(): void {
  frames = 0;
  windowStart = performance.now();
  busyStart = busy.ms;
  stepStart = current?.scene.stepCount ?? 0;
  stepMs = NaN;
  longStart = longTasks;
  counts = { bodies: 0, particles: 0 };
}

const count = () => {
  frames++;
  requestAnimationFrame(count);
};
requestAnimationFrame(count);

setInterval(async () => {
  const c = current;
  if (!c || stats.hidden) return;
  const now = performance.now();
  const dt = now - windowStart;
  const fps = (frames * 1000) / dt;
  const mainMs = frames ? (busy.ms - busyStart) / frames : NaN;
  const steps = c.scene.stepCount - stepStart;
  const lt = longTasks - longStart;
  frames = 0;
  windowStart = now;
  busyStart = busy.ms;
  stepStart = c.scene.stepCount;
  longStart = longTasks;
  try {
    const d = await Promise.race([c.scene.diagnostics(), new Promise<null>((r) => setTimeout(() => r(null), 500))]);
    // The engine's own time per step (its loop's average): measuring it takes no extra steps.
    if (d) {
      counts = { bodies: d.bodyCount, particles: d.particleCount };
      stepMs = d.stepMs;
    }
  } catch {
    /* the scene is restarting */
  }
  const f = (v: number, digits = 1) => (Number.isFinite(v) ? v.toFixed(digits) : '–');
  const lines = [
    `${f(fps, 0)} fps · ${f((steps * 1000) / dt, 0)} steps/s`,
    `physics ${f(stepMs, 2)} ms/step`,
    `main thread ${f(mainMs, 2)} ms/frame`,
    `${counts.bodies} bodies · ${counts.particles} particles`,
    `${c.scene.mode ?? '…'} · ${c.scene.transport ?? '…'}${lt ? ` · ${lt} long tasks` : ''}`,
  ];
  stats.textContent = lines.join('\n');
}, 1000);

fromHash();
