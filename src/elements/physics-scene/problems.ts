// What is wrong with a scene, told three ways: a `physics-error` event on the element at fault, one console warning
// naming the element, attribute and value, and the visible error box (every current markup problem and the latest
// engine failures). Markup problems are reported once each while they last; a fixed one leaves the box. So does an
// element's description the engine refused, once the element sends another.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { HostError } from '../../worker/protocol.js';
import { describeElement, displayValue, shownValue, type Problem } from '../checks.js';
import { firePhysicsEvent } from './events.js';

/** Engine description fields → the attribute that sets them, where the names differ. */
const ENGINE_FIELDS: Record<string, string> = { from: 'x1', to: 'x2', origin: 'x', center: 'x', structural: 'compliance', jointCompliance: 'joint-compliance' };

/** Engine failures kept in the error box (the latest ones). */
const FAILURES_SHOWN = 5;

export interface ProblemsOptions {
  /** The error box, once rendered. */
  box(): HTMLElement | null;
  /** The body or link element of an engine key. */
  elementOf(key: number): Element | undefined;
}

/** One line of the error box and of the console. */
function problemText(el: Element, attribute: string, value: string, message: string): string {
  return `${describeElement(el)}${attribute ? ` ${attribute}="${displayValue(value)}"` : ''}: ${message}`;
}

/** @internal */
export class ProblemsController implements ReactiveController {
  /** Per source (an element's attributes, the scene's, a preset's): the problems reported (ids) and their lines. */
  private readonly sources = new Map<unknown, { reported: Set<string>; lines: string[] }>();
  private failures: string[] = [];
  /** Per element: the lines of the engine's refusals of its description (until it sends another one). */
  private readonly refusals = new Map<Element, string[]>();
  private shown: string[] = [];

  constructor(
    private readonly host: ReactiveControllerHost & Element,
    private readonly options: ProblemsOptions,
  ) {
    host.addController(this);
  }

  /** The error box's lines: markup problems, then the latest engine failures. */
  get lines(): readonly string[] {
    return this.shown;
  }

  /**
   * The current problems of one source (`el` is the element they are about). New ones are reported; ones gone leave
   * the error box; ones still there are not reported again.
   */
  set(source: unknown, el: Element, problems: Problem[]): void {
    const entry = this.sources.get(source) ?? { reported: new Set<string>(), lines: [] };
    this.sources.set(source, entry);
    const now = new Set<string>();
    entry.lines = [];
    for (const p of problems) {
      const id = `${p.attribute}\u0000${p.value}\u0000${p.message}`;
      now.add(id);
      entry.lines.push(problemText(el, p.attribute, p.value, p.message));
      if (!entry.reported.has(id)) this.report(el, p.attribute, p.value, p.message, false);
    }
    entry.reported = now;
    this.refresh();
  }

  /** A source is gone (an element removed from the scene): its problems leave the box, and would be reported anew. */
  forget(source: unknown): void {
    const refused = source instanceof Element && this.refusals.delete(source);
    if (this.sources.delete(source) || refused) this.refresh();
  }

  /** The element sent the engine a new description: the engine's refusals of the old one leave the box. */
  resent(el: Element): void {
    if (this.refusals.delete(el)) this.refresh();
  }

  /** A console warning naming the element, the attribute and the value, and a `physics-error` event; `keep`: in the box too. */
  report(el: Element, attribute: string, value: string, message: string, keep = true): void {
    const text = problemText(el, attribute, value, message);
    console.warn(text);
    firePhysicsEvent(el.isConnected ? el : this.host, 'physics-error', { element: el, attribute, value, message });
    if (keep) {
      this.failures = [...this.failures.slice(1 - FAILURES_SHOWN), text];
      this.refresh();
    }
  }

  /** The engine refused an element's description: reported on that element, naming the attribute behind the field. */
  refused(e: HostError): void {
    const el = this.options.elementOf(e.key) ?? this.host;
    const attribute = ENGINE_FIELDS[e.field] ?? e.field;
    const value = attribute ? shownValue(el, attribute) : '';
    // A refused call (an impulse past the speed limit) is reported on its body, and shown as the scene's failures are.
    if (el === this.host || e.call) {
      this.report(el, attribute, value, e.message);
      return;
    }
    // Shown while the element's description stays the refused one (resent() and forget() take it out).
    this.report(el, attribute, value, e.message, false);
    const line = problemText(el, attribute, value, e.message);
    const lines = this.refusals.get(el) ?? [];
    if (!lines.includes(line)) this.refusals.set(el, [...lines, line]);
    this.refresh();
  }

  /** The scene stopped: the box empties. What was reported stays reported (sources that remain are not reported again). */
  clear(): void {
    this.failures = [];
    this.refusals.clear();
    for (const entry of this.sources.values()) entry.lines = [];
    this.refresh();
  }

  hostUpdated(): void {
    this.show();
  }

  private refresh(): void {
    const lines = [...[...this.sources.values()].flatMap((s) => s.lines), ...[...this.refusals.values()].flat(), ...this.failures];
    if (lines.join('\n') === this.shown.join('\n')) return;
    this.shown = lines;
    this.show();
  }

  /** Written straight into the DOM: problems are found during updates, too late to render them in the same one. */
  private show(): void {
    const box = this.options.box();
    if (!box) return;
    const text = this.shown.join('\n');
    if (box.textContent !== text) box.textContent = text;
    box.hidden = this.shown.length === 0;
  }
}
