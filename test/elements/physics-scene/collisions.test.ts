// Collision events on their own: the engine is asked for events only while someone listens (or collision-events is
// set), and each engine event becomes physics-collision / physics-collision-end naming the two body elements.
import { expect } from '@open-wc/testing';
import type { PhysicsCollisionDetail } from '../../../src/index.js';
import { CollisionEventsController } from '../../../src/elements/physics-scene/collisions.js';
import type { Command, Engine } from '../../../src/elements/physics-scene/session.js';
import { FakeEngine, makeHost, type FakeHost } from './fakes.js';

function rig() {
  const host = makeHost();
  const sent: [Command, unknown[]][] = [];
  let always = false;
  const a = document.createElement('physics-box');
  const b = document.createElement('physics-circle');
  const port = { live: new FakeEngine() as Engine | null, send: (method: Command, ...args: unknown[]) => void sent.push([method, args]) };
  const collisions = new CollisionEventsController(host, {
    always: () => always,
    elementOf: (key) => (key === 1 ? a : key === 2 ? b : undefined),
    engine: port,
  });
  // The element's addEventListener and removeEventListener, as the scene passes them on.
  const add = (type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions) =>
    collisions.addListener(type, listener, options, (wrapper, o) => host.addEventListener(type, wrapper, o));
  const remove = (type: string, listener: EventListenerOrEventListenerObject, options?: boolean | EventListenerOptions) =>
    collisions.removeListener(type, listener, options, (wrapper, o) => host.removeEventListener(type, wrapper, o));
  return { host, sent, port, collisions, a, b, add, remove, setAlways: (on: boolean) => (always = on) };
}

describe('CollisionEventsController', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  it('asks the engine for events while a listener is registered, once per change', () => {
    const r = rig();
    host = r.host;
    const [f, g] = [() => {}, () => {}];
    expect(r.collisions.wanted).to.equal(false);
    r.add('physics-collision', f);
    r.add('physics-collision-end', g);
    expect(r.add('click', f), 'other types are left to the element').to.equal(false);
    expect(r.collisions.wanted).to.equal(true);
    r.remove('physics-collision', f);
    expect(r.sent).to.deep.equal([['setParams', [{ events: true }]]]);
    r.remove('physics-collision-end', g);
    // A listener removed twice does not go below none.
    r.remove('physics-collision-end', g);
    expect(r.sent).to.deep.equal([['setParams', [{ events: true }]], ['setParams', [{ events: false }]]]);
    expect(r.collisions.wanted).to.equal(false);
  });

  it('keeps the listeners as the DOM does: a stray remove, a second add, once, a signal, capture', () => {
    // Counting add and remove calls went wrong both ways: removing a listener never added stopped the events of one
    // still there; adding one twice, or a once listener, kept the engine collecting with nobody listening.
    const r = rig();
    host = r.host;
    const [f, g] = [() => {}, () => {}];
    r.add('physics-collision', f);
    r.remove('physics-collision', g);
    expect(r.collisions.wanted, 'removing a listener never added').to.equal(true);
    r.add('physics-collision', f);
    r.remove('physics-collision', f);
    expect(r.collisions.wanted, 'added twice (kept once), removed once').to.equal(false);
    // Capture flags tell listeners apart: a capture listener stays after the other is removed.
    r.add('physics-collision', f, true);
    r.add('physics-collision', f, { capture: false });
    r.remove('physics-collision', f);
    expect(r.collisions.wanted).to.equal(true);
    r.remove('physics-collision', f, { capture: true });
    expect(r.collisions.wanted).to.equal(false);
    // once: gone after its first call, which it gets with the event and the scene as `this`.
    const calls: [unknown, string][] = [];
    r.add('physics-collision', function (this: unknown, e: Event) { calls.push([this, e.type]); }, { once: true });
    expect(r.collisions.wanted).to.equal(true);
    r.host.dispatchEvent(new Event('physics-collision'));
    r.host.dispatchEvent(new Event('physics-collision'));
    expect(calls).to.deep.equal([[r.host, 'physics-collision']]);
    expect(r.collisions.wanted, 'a once listener after its call').to.equal(false);
    // A listener object's handleEvent is called; a signal's abort removes it; an aborted signal adds nothing.
    const handled: string[] = [];
    const controller = new AbortController();
    r.add('physics-collision-end', { handleEvent: (e: Event) => handled.push(e.type) }, { signal: controller.signal });
    r.host.dispatchEvent(new Event('physics-collision-end'));
    expect(handled).to.deep.equal(['physics-collision-end']);
    controller.abort();
    expect(r.collisions.wanted, 'after the signal aborted').to.equal(false);
    r.host.dispatchEvent(new Event('physics-collision-end'));
    expect(handled.length).to.equal(1);
    r.add('physics-collision', f, { signal: controller.signal });
    expect(r.collisions.wanted, 'added with an aborted signal').to.equal(false);
    expect(r.sent.map(([, [p]]) => (p as { events: boolean }).events)).to.deep.equal([true, false, true, false, true, false, true, false]);
  });

  it('collision-events wants them with no listener (seen after an update); nothing is sent with no live engine', () => {
    const r = rig();
    host = r.host;
    r.setAlways(true);
    r.host.update();
    expect(r.sent).to.deep.equal([['setParams', [{ events: true }]]]);
    r.setAlways(false);
    r.port.live = null;
    r.host.update();
    expect(r.sent.length).to.equal(1);
    expect(r.collisions.wanted).to.equal(false);
  });

  it('dispatches begin and end events naming the body elements, bubbling and composed; an end of a pair never begun is dropped', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    const seen: [string, PhysicsCollisionDetail, boolean, boolean][] = [];
    const record = (e: CustomEvent<PhysicsCollisionDetail>) => seen.push([e.type, e.detail, e.bubbles, e.composed]);
    document.addEventListener('physics-collision', record);
    document.addEventListener('physics-collision-end', record);
    try {
      // Begin (1, 2); end (2, 9), never begun; end (2, 1): the pair begun, named either way round; begin again.
      r.collisions.dispatch(new Float64Array([0, 1, 2, 0, -1, 0.02, 3.5, 1, 2, 9, 0, 0, 0, 0, 1, 2, 1, 0, 0, 0, 0, 0, 2, 1, 0, 1, 0.01, 0.25]), 4);
    } finally {
      document.removeEventListener('physics-collision', record);
      document.removeEventListener('physics-collision-end', record);
    }
    expect(seen).to.deep.equal([
      ['physics-collision', { a: r.a, b: r.b, normal: { x: 0, y: -1 }, depth: 0.02, speed: 3.5 }, true, true],
      ['physics-collision-end', { a: r.b, b: r.a, normal: { x: 0, y: 0 }, depth: 0, speed: 0 }, true, true],
      ['physics-collision', { a: r.b, b: r.a, normal: { x: 0, y: 1 }, depth: 0.01, speed: 0.25 }, true, true],
    ]);
  });
});
