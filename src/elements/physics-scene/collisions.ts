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

  /** A listener of `type` was added (+1) or removed (−1) on the scene. */
  listened(type: string, delta: 1 | -1): void {
    if (!COLLISION_EVENTS.has(type) || (delta < 0 && this.listeners === 0)) return;
    this.listeners += delta;
    this.refresh();
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
