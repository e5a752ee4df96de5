// Markup → engine. Every body and link element of the scene gets a numeric key; its description goes to the engine
// when the scene loads, and again when it changes (the element's own update) or comes and goes (a MutationObserver on
// the container). The markup is the source of truth: what the engine holds follows it. Not a controller: it has no
// lifecycle of its own, the session's start (observe, collect) and the scene's stop (reset) drive it.
import type { BodyDescription } from '../../engine/index.js';
import type { BodyStyle } from '../../render/renderer.js';
import type { KeyedBody, KeyedLink, LinkDescription } from '../../worker/protocol.js';
import { PhysicsBodyElement } from '../body-element.js';
import { nearestName } from '../../engine/validate.js';
import { Checker, describeElement, misspeltAttributes, type Problem } from '../checks.js';
import { PhysicsLinkElement } from '../link-element.js';
import type { SceneHost } from '../scene-host.js';
import type { ColourScheme } from './scheme.js';
import type { EngineCommands } from './session.js';

type Child = PhysicsBodyElement | PhysicsLinkElement;

/** The tags a scene simulates: its body elements, then its link elements. */
export const BODY_TAGS = ['physics-box', 'physics-circle', 'physics-polygon', 'physics-rope', 'physics-cloth', 'physics-softbody', 'physics-ragdoll'];
export const LINK_TAGS = ['physics-joint', 'physics-spring', 'physics-pin'];
const KNOWN_TAGS = [...BODY_TAGS, ...LINK_TAGS];

/**
 * Children that are not bodies or links and are not mistakes either: they hold no markup for the scene (templates,
 * scripts, styles), or they are what the page shows instead of the scene (`<noscript>`, an image, anything given a
 * `slot`).
 */
const NOT_A_MISTAKE = new Set(['template', 'script', 'style', 'noscript', 'img', 'picture', 'br']);

/**
 * Whether `el`, a child of the scene, is a paragraph a CMS or Markdown wrapped around the scene's lines (Markdown
 * ends raw HTML at a blank line and makes the lines after it a <p>; WordPress's automatic paragraphs add <p> and
 * <br>): a <p> holding body or link elements, or nothing but white space and <br>. Its body and link elements are the
 * scene's. A <p> of text is not one (reported as any other element).
 */
function isWrapper(el: Element): boolean {
  if (el.localName !== 'p' || el.hasAttribute('slot')) return false;
  for (const inner of Array.from(el.children)) if (KNOWN_TAGS.includes(inner.localName)) return true;
  return el.textContent!.trim() === '' && Array.from(el.children).every((inner) => inner.localName === 'br');
}

/** Whether `el` is in the scene's markup: a child of its container, or of a paragraph wrapped around its lines. */
export function inMarkup(el: Element, container: ParentNode & Node): boolean {
  const parent = el.parentElement;
  return el.parentNode === container || (parent !== null && parent.parentNode === container && isWrapper(parent));
}

/**
 * Other words for the known bodies and links, without the prefix: `<physics-ball>` means a circle, though its nearest
 * tag by spelling is `<physics-box>`.
 */
const SYNONYMS: Record<string, string> = {
  ball: 'physics-circle',
  disc: 'physics-circle',
  disk: 'physics-circle',
  rect: 'physics-box',
  rectangle: 'physics-box',
  square: 'physics-box',
  block: 'physics-box',
  crate: 'physics-box',
  triangle: 'physics-polygon',
  poly: 'physics-polygon',
  shape: 'physics-polygon',
  chain: 'physics-rope',
  string: 'physics-rope',
  sheet: 'physics-cloth',
  flag: 'physics-cloth',
  blob: 'physics-softbody',
  jelly: 'physics-softbody',
  figure: 'physics-ragdoll',
  hinge: 'physics-joint',
  link: 'physics-joint',
  constraint: 'physics-joint',
  anchor: 'physics-pin',
};

/**
 * What to tell the author of a child that is not a body or link: the known tag it is another word for (SYNONYMS), or
 * the known tag closest to it by edit distance (a `physics-*` tag always gets one; another tag only when it is close
 * to a known one without the prefix, as `<circle>` is to `<physics-circle>`), else that it is ignored. Exported for
 * tests.
 */
export function unknownChildMessage(tag: string): string {
  const prefixed = tag.startsWith('physics-');
  const name = prefixed ? tag : `physics-${tag}`;
  const synonym = SYNONYMS[name.slice('physics-'.length)];
  if (synonym !== undefined && customElements.get(tag) === undefined) return `unknown element, ignored: did you mean <${synonym}>?`;
  const { nearest: best, distance: bestDistance } = nearestName(name, KNOWN_TAGS);
  const close = prefixed || bestDistance <= Math.max(1, Math.floor(tag.length / 3));
  const list = (tags: string[]) => tags.map((t) => `<${t}>`).join(', ');
  const known = `bodies are ${list(BODY_TAGS)}; links are ${list(LINK_TAGS)}`;
  if (!close || customElements.get(tag) !== undefined) return `not a body or link element, so the scene ignores it (${known})`;
  // A far guess is still the nearest tag, but the whole list says more.
  return `unknown element, ignored: did you mean <${best}>?${bestDistance > 2 ? ` (${known})` : ''}`;
}

interface Entry {
  element: Child;
  kind: 'body' | 'link';
  /** JSON of the description last sent to the engine ('' = none). */
  sent: string;
}

export interface MarkupOptions {
  /** Where the body and link elements are: the scene, or a preset's hidden part of its shadow root. */
  container(): ParentNode & Node;
  /** The engine the changes go to (sent only while it has the scene loaded). */
  engine: EngineCommands & { readonly shown: { pose(key: number): [number, number, number] | null } | null };
  /** Where each element's problems go (the element is their source). */
  problems: { set(source: unknown, el: Element, problems: Problem[]): void; forget(source: unknown): void; resent(el: Element): void };
  /** How each body is drawn. */
  styles: { setStyle(key: number, style: BodyStyle): void; deleteStyle(key: number): void };
  /** The page's colour scheme, which the bodies' default colours follow (light when not given). */
  scheme?(): ColourScheme;
}

/** @internal */
export class MarkupSync implements SceneHost {
  private nextKey = 1;
  private keys = new WeakMap<Element, number>();
  private readonly entries = new Map<number, Entry>();
  /** Children that are neither bodies nor links, reported (each is its own source of problems). */
  private unknown = new Set<Element>();
  /** Body elements whose id an earlier one has (reported; links name the first), and where their problem is kept. */
  private duplicates = new Set<Element>();
  private readonly idSources = new WeakMap<Element, object>();
  private readonly observer = new MutationObserver((records) => this.mutated(records));

  constructor(private readonly options: MarkupOptions) {}

  /** Starts following the container's children (added, removed, ids changed) and attributes none of them reads. */
  observe(): void {
    this.observer.observe(this.options.container(), { childList: true, subtree: true, attributes: true });
  }

  /**
   * Children added or removed, or an id changed: the children again. An attribute the element does not read (a
   * misspelt `wdth`, set from script) changes nothing Lit sees: the element is checked again, so it is reported then,
   * not at the next change of a real attribute.
   */
  private mutated(records: MutationRecord[]): void {
    let children = false;
    const unread = new Set<Element>();
    for (const r of records) {
      if (r.type !== 'attributes' || r.attributeName === 'id') children = true;
      else if (misspelt(r.target as Element, r.attributeName!)) unread.add(r.target as Element);
    }
    if (children) this.sync();
    for (const el of unread) {
      if (this.keys.has(el)) this.childChanged(el);
      else if (el === this.options.container() && 'requestUpdate' in el) (el as unknown as { requestUpdate(): void }).requestUpdate();
    }
  }

  /** The scene stopped: no observing, no keys; the children are no longer this scene's. */
  reset(): void {
    this.observer.disconnect();
    for (const key of [...this.entries.keys()]) this.forget(key);
    for (const el of this.unknown) this.options.problems.forget(el);
    this.unknown.clear();
    this.keys = new WeakMap();
  }

  /**
   * The page's colour scheme changed: every body's style again (its default colours may differ; its problems were
   * reported when it was described).
   */
  restyle(): void {
    for (const [key, entry] of this.entries) {
      if (entry.kind === 'body') this.options.styles.setStyle(key, (entry.element as PhysicsBodyElement).styleOf(new Checker(entry.element), this.scheme()));
    }
  }

  private scheme(): ColourScheme {
    return this.options.scheme?.() ?? 'light';
  }

  keyOf(el: Element): number | undefined {
    return this.keys.get(el);
  }

  elementOf(key: number): Child | undefined {
    return this.entries.get(key)?.element;
  }

  /**
   * Every child described, for a (re)load. A restart keeps the keys of children it knows (the snapshot names them),
   * forgets removed ones and adopts new ones.
   */
  collect(): { bodies: KeyedBody[]; links: KeyedLink[] } {
    const children = this.children();
    this.prune(children, false);
    const bodies: KeyedBody[] = [];
    const links: KeyedLink[] = [];
    for (const el of children) if (el instanceof PhysicsBodyElement) {
      const key = this.keys.get(el) ?? this.adopt(el);
      const desc = this.describeBody(key);
      if (desc) bodies.push({ key, desc });
    }
    for (const el of children) if (el instanceof PhysicsLinkElement) {
      const key = this.keys.get(el) ?? this.adopt(el);
      const desc = this.describeLink(key);
      if (desc) links.push({ key, desc });
    }
    this.checkIds();
    return { bodies, links };
  }

  /**
   * Why `snapshot` is not a state of this scene as its markup is now (the same bodies and links by key, with the same
   * descriptions unless `descriptions` is false), or null when it is. Another scene's snapshot, or one taken before the markup changed, would leave
   * the simulation out of step with the page: bodies drawn with other elements' colours, poses read off other bodies.
   */
  mismatch(snapshot: { bodies: readonly { key: number; desc: unknown }[]; links: readonly { key: number; desc: unknown }[] }, descriptions = true): string | null {
    const here = new Map<number, string>();
    for (const [key, entry] of this.entries) if (entry.sent) here.set(key, entry.sent);
    const there = [...snapshot.bodies, ...snapshot.links];
    const differ = there.filter(({ key, desc }) => !here.has(key) || (descriptions && here.get(key) !== JSON.stringify(desc))).length;
    if (differ === 0 && there.length === here.size) return null;
    return (
      `restore() takes a snapshot of this scene with its markup as it is now: this one holds ${there.length} bodies and links, ` +
      `${differ} of them not as the markup describes them (${here.size} here); it is another scene's, or was taken before the markup changed`
    );
  }

  /** The child list changed: new children added, gone ones removed, links resolved again. */
  sync(): void {
    const { engine } = this.options;
    if (!engine.live) return;
    const children = this.children();
    this.prune(children, true);
    for (const el of children) {
      if (this.keys.has(el) || !(el instanceof PhysicsBodyElement)) continue;
      const key = this.adopt(el);
      const desc = this.describeBody(key);
      if (desc) engine.send('addBody', { key, desc });
    }
    for (const el of children) if (!this.keys.has(el) && el instanceof PhysicsLinkElement) this.adopt(el);
    this.checkIds();
    this.refreshLinks();
  }

  /**
   * Reports each body element whose id an earlier one of the scene has (links name the earlier one, and would quietly
   * move to this one once the first left), and takes back the reports of ids no longer shared.
   */
  private checkIds(): void {
    const first = new Map<string, Element>();
    const shared = new Set<Element>();
    for (const entry of this.entries.values()) {
      const el = entry.element;
      if (entry.kind !== 'body' || !el.id) continue;
      const earlier = first.get(el.id);
      if (!earlier) {
        first.set(el.id, el);
        continue;
      }
      shared.add(el);
      if (!this.duplicates.has(el)) this.options.problems.set(this.idSource(el), el, [{ attribute: 'id', value: el.id, message: `is also the id of an earlier ${describeElement(earlier)} in this scene: links name that one` }]);
    }
    for (const el of this.duplicates) if (!shared.has(el)) this.options.problems.forget(this.idSource(el));
    this.duplicates = shared;
  }

  /** The source an element's duplicate-id problem is kept under (apart from its attributes' problems). */
  private idSource(el: Element): object {
    let source = this.idSources.get(el);
    if (!source) this.idSources.set(el, (source = {}));
    return source;
  }

  // ---- SceneHost: what the children call ---------------------------------------------------------------------

  childChanged(child: Element): void {
    const { engine } = this.options;
    if (!engine.live) return;
    const key = this.keys.get(child);
    if (key === undefined) {
      this.sync();
      return;
    }
    const entry = this.entries.get(key)!;
    if (entry.kind === 'body') {
      const before = entry.sent;
      const desc = this.describeBody(key);
      if (entry.sent !== before) {
        this.options.problems.resent(child);
        if (desc) engine.send('updateBody', { key, desc });
        else engine.send('removeBody', key);
      }
    }
    this.refreshLinks();
  }

  /** The host of a child added since the observer last ran (a command right after it was added), or null. */
  hostOf(child: Element): SceneHost | null {
    this.flush(child);
    return this.keys.has(child) ? this : null;
  }

  poseOf(child: Element): [number, number, number] | null {
    const key = this.keys.get(child);
    const shown = this.options.engine.shown;
    return key === undefined || !shown ? null : shown.pose(key);
  }

  applyImpulse(child: Element, ix: number, iy: number): void {
    const key = this.flush(child);
    if (key !== undefined && Number.isFinite(ix) && Number.isFinite(iy)) this.options.engine.send('applyImpulse', key, ix, iy);
  }

  setVelocity(child: Element, vx: number, vy: number): void {
    const key = this.flush(child);
    if (key !== undefined && Number.isFinite(vx) && Number.isFinite(vy)) this.options.engine.send('setVelocity', key, vx, vy);
  }

  // ---- internals ---------------------------------------------------------------------------------------------

  /**
   * Before a command about `child`: the markup changes made so far go to the engine first, so the command acts on the
   * body they build, not on the one they replace. Children added or removed since the observer last ran (its records
   * come in a microtask) are synced now, and the child's own attribute changes, which Lit renders in a microtask,
   * are described now (its update then finds nothing new to send). Returns the child's key.
   */
  private flush(child: Element): number | undefined {
    if (this.options.engine.live) {
      if (this.observer.takeRecords().length > 0 || (!this.keys.has(child) && inMarkup(child, this.options.container()))) this.sync();
      if (this.keys.has(child) && (child as Element & { isUpdatePending?: boolean }).isUpdatePending) this.childChanged(child);
    }
    return this.keys.get(child);
  }

  /**
   * The body and link elements of the container, also those in a paragraph wrapped around its lines (isWrapper); the
   * other elements are reported (once each) instead.
   */
  private children(): Child[] {
    const out: Child[] = [];
    const unknown = new Set<Element>();
    const take = (el: Element) => {
      if (el instanceof PhysicsBodyElement || el instanceof PhysicsLinkElement) out.push(el);
      // A known tag not upgraded yet (its module loads later) is not a mistake.
      else if (!NOT_A_MISTAKE.has(el.localName) && !el.hasAttribute('slot') && !(KNOWN_TAGS.includes(el.localName) && !customElements.get(el.localName))) unknown.add(el);
    };
    for (const el of Array.from(this.options.container().children)) {
      if (isWrapper(el)) for (const inner of Array.from(el.children)) take(inner);
      else take(el);
    }
    for (const el of this.unknown) if (!unknown.has(el)) this.options.problems.forget(el);
    for (const el of unknown) {
      if (!this.unknown.has(el)) this.options.problems.set(el, el, [{ attribute: '', value: el.localName, message: unknownChildMessage(el.localName) }]);
    }
    this.unknown = unknown;
    return out;
  }

  private adopt(el: Child): number {
    const key = this.nextKey++;
    this.keys.set(el, key);
    this.entries.set(key, { element: el, kind: el instanceof PhysicsBodyElement ? 'body' : 'link', sent: '' });
    el._scene = this;
    return key;
  }

  private forget(key: number): void {
    const entry = this.entries.get(key)!;
    entry.element._scene = null;
    this.entries.delete(key);
    this.keys.delete(entry.element);
    this.options.problems.forget(entry.element);
    if (this.duplicates.delete(entry.element)) this.options.problems.forget(this.idSource(entry.element));
  }

  /** Forgets the children no longer in the container (and, with `tellEngine`, removes them from the engine). */
  private prune(children: Child[], tellEngine: boolean): void {
    const present = new Set<Element>(children);
    for (const [key, entry] of [...this.entries]) {
      if (present.has(entry.element)) continue;
      if (tellEngine) this.options.engine.send(entry.kind === 'body' ? 'removeBody' : 'removeLink', key);
      if (entry.kind === 'body') this.options.styles.deleteStyle(key);
      this.forget(key);
    }
  }

  private describeBody(key: number): BodyDescription | null {
    const entry = this.entries.get(key)!;
    const el = entry.element as PhysicsBodyElement;
    const { desc, problems } = el.describe();
    const check = new Checker(el);
    const style = el.styleOf(check, this.scheme());
    this.options.problems.set(el, el, [...problems, ...check.problems, ...misspeltAttributes(el)]);
    this.options.styles.setStyle(key, style);
    entry.sent = desc ? JSON.stringify(desc) : '';
    return desc;
  }

  private describeLink(key: number): LinkDescription | null {
    const entry = this.entries.get(key)!;
    const el = entry.element as PhysicsLinkElement;
    const { desc, problems } = el.describe((id) => this.resolve(id));
    this.options.problems.set(el, el, [...problems, ...misspeltAttributes(el)]);
    entry.sent = desc ? JSON.stringify(desc) : '';
    return desc;
  }

  /**
   * Whether `sent` (a call's first argument: a keyed description, or anything else) is what the element of its key
   * sent last. The engine answers in order, but a refusal of an older description can arrive after the element sent a
   * newer one.
   */
  isLatest(sent: unknown): boolean {
    if (sent === null || typeof sent !== 'object' || !('desc' in sent) || !('key' in sent)) return true;
    const entry = this.entries.get((sent as KeyedBody).key);
    return entry !== undefined && entry.sent === JSON.stringify((sent as KeyedBody).desc);
  }

  /** The key of the body element with this id, or null. */
  private resolve(id: string): number | null {
    for (const [key, entry] of this.entries) if (entry.kind === 'body' && entry.element.id === id) return key;
    return null;
  }

  /** Describes every link again (ids may now name other bodies) and sends the ones that changed. */
  private refreshLinks(): void {
    const { engine } = this.options;
    for (const [key, entry] of this.entries) {
      if (entry.kind !== 'link') continue;
      const before = entry.sent;
      const desc = this.describeLink(key);
      if (entry.sent === before) continue;
      this.options.problems.resent(entry.element);
      if (desc) engine.send('updateLink', { key, desc });
      else engine.send('removeLink', key);
    }
  }
}

/**
 * Whether a custom element has attribute `name` now and reports it as misspelt. Only those are checked again: the
 * scene's own class, style and aria attributes, or a page's, change nothing and must not make it update.
 */
function misspelt(el: Element, name: string): boolean {
  const observed = (el.constructor as { observedAttributes?: readonly string[] }).observedAttributes;
  if (observed === undefined || observed.includes(name)) return false;
  return !el.hasAttribute(name) || misspeltAttributes(el).some((p) => p.attribute === name);
}
