// Collision events: the engine collects contacts that begin and end only while someone listens on the scene (or
// `collision-events` asks for them), and each one reaches the page as `physics-collision` / `physics-collision-end`
// naming the two body elements.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { EVENT } from '../../worker/protocol.js';
import { firePhysicsEvent } from './events.js';
import type { EngineCommands } from './session.js';

const COLLISION_EVENTS = new Set(['physics-collision', 'physics-collision-end']);

export interface CollisionOptions {
  /** Events wanted even with no listener on the scene (the `collision-events` attribute). */
  always(): boolean;
  /** The body element of an engine key. */
  elementOf(key: number): Element | undefined;
  engine: EngineCommands;
}

/** @internal */
export class CollisionEventsController implements ReactiveController {
  /**
   * The scene's own listeners of the collision events, as the DOM keeps them: one per listener, type and capture flag.
   * Each is registered through a wrapper of ours, so that a `once` listener's call and a `signal`'s abort, which the
   * DOM removes without a removeEventListener call, are seen too. Counting the calls instead went wrong both ways:
   * removing a listener never added stopped the events of one still there, and adding one twice (the DOM keeps one)
   * or a `once` one kept the engine collecting with nobody listening.
   */
  private readonly registered = new Map<EventListenerOrEventListenerObject, Map<string, EventListener>>();
  private listeners = 0;
  /** Whether the engine was last told to collect events. */
  private on = false;
  /**
   * The pairs touching, as the page was told (by their keys, "lo hi"), with their elements: an end names the elements
   * its begin named, also once a body element has left the scene (the engine ends a removed body's pairs a step
   * later, when its key names no element any more).
   */
  private readonly touching = new Map<string, [Element | null, Element | null]>();

  constructor(
    private readonly host: ReactiveControllerHost & EventTarget,
    private readonly options: CollisionOptions,
  ) {
    host.addController(this);
  }

  /** `collision-events` may have changed. */
  hostUpdated(): void {
    this.refresh();
  }

  /** Whether the engine should collect events now. */
  get wanted(): boolean {
    return this.options.always() || this.listeners > 0;
  }

  /**
   * addEventListener on the scene: a collision event's listener is registered here, through `add` (the element's own
   * addEventListener), and true returned; any other type is left to the caller (false).
   */
  addListener(type: string, listener: EventListenerOrEventListenerObject, options: boolean | AddEventListenerOptions | undefined, add: (wrapper: EventListener, options: boolean | AddEventListenerOptions | undefined) => void): boolean {
    if (!COLLISION_EVENTS.has(type)) return false;
    const key = `${type} ${capture(options)}`;
    const signal = typeof options === 'object' ? options.signal : undefined;
    let byKey = this.registered.get(listener);
    // The DOM adds nothing for a listener it holds already, or with a signal aborted before.
    if (byKey?.has(key) || signal?.aborted) return true;
    const wrapper = function (this: unknown, event: Event): void {
      if (typeof options === 'object' && options.once) forget();
      if (typeof listener === 'function') listener.call(this, event);
      else listener.handleEvent(event);
    };
    const forget = (): void => {
      if (this.registered.get(listener)?.get(key) !== wrapper) return;
      this.registered.get(listener)!.delete(key);
      this.listeners--;
      this.refresh();
    };
    if (!byKey) this.registered.set(listener, (byKey = new Map()));
    byKey.set(key, wrapper);
    this.listeners++;
    signal?.addEventListener('abort', forget, { once: true });
    add(wrapper, options);
    this.refresh();
    return true;
  }

  /** removeEventListener on the scene: as addListener, through `remove`. */
  removeListener(type: string, listener: EventListenerOrEventListenerObject, options: boolean | EventListenerOptions | undefined, remove: (wrapper: EventListener, options: boolean | EventListenerOptions | undefined) => void): boolean {
    if (!COLLISION_EVENTS.has(type)) return false;
    const key = `${type} ${capture(options)}`;
    const wrapper = this.registered.get(listener)?.get(key);
    if (!wrapper) return true;
    this.registered.get(listener)!.delete(key);
    this.listeners--;
    remove(wrapper, options);
    this.refresh();
    return true;
  }

  /** Tells the engine when whether events are wanted changed. */
  refresh(): void {
    const on = this.wanted;
    if (on === this.on) return;
    this.on = on;
    if (this.options.engine.live) this.options.engine.send('setParams', { events: on });
  }

  /** Events from the engine: [type (0 begin, 1 end), key a, key b, normal x, normal y, depth, speed] each. */
  readonly dispatch = (data: Float64Array, count: number): void => {
    for (let k = 0; k < count; k++) {
      const o = k * EVENT;
      const ka = data[o + 1];
      const kb = data[o + 2];
      const pair = ka < kb ? `${ka} ${kb}` : `${kb} ${ka}`;
      const begin = data[o] === 0;
      const told = this.touching.get(pair);
      // Begins and ends alternate per pair, as the page was told: a world that starts its pairs afresh (a kernel
      // change) begins pairs told already, and an end can come for a pair the page never heard begin (events asked
      // for while it touched).
      if (begin === (told !== undefined)) continue;
      let a: Element | null;
      let b: Element | null;
      if (begin) {
        a = this.options.elementOf(ka) ?? null;
        b = this.options.elementOf(kb) ?? null;
        this.touching.set(pair, ka < kb ? [a, b] : [b, a]);
      } else {
        a = ka < kb ? told![0] : told![1];
        b = ka < kb ? told![1] : told![0];
        this.touching.delete(pair);
      }
      firePhysicsEvent(this.host, begin ? 'physics-collision' : 'physics-collision-end', { a, b, normal: { x: data[o + 3], y: data[o + 4] }, depth: data[o + 5], speed: data[o + 6] });
    }
  };

  /**
   * The engine starts its pairs afresh (a reset, a restore, a restart): every pair the page was told is touching ends
   * now, and those still touching begin again with the next events.
   */
  endAll(): void {
    const pairs = [...this.touching.values()];
    this.touching.clear();
    for (const [a, b] of pairs) firePhysicsEvent(this.host, 'physics-collision-end', { a, b, normal: { x: 0, y: 0 }, depth: 0, speed: 0 });
  }

}

/** The capture flag of addEventListener's or removeEventListener's options (the DOM tells listeners apart by it). */
function capture(options: boolean | EventListenerOptions | undefined): boolean {
  return typeof options === 'boolean' ? options : !!options?.capture;
}
