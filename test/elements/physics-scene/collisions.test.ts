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
  return { host, sent, port, collisions, a, b, setAlways: (on: boolean) => (always = on) };
}

describe('CollisionEventsController', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  it('asks the engine for events while a listener is registered, once per change', () => {
    const r = rig();
    host = r.host;
    expect(r.collisions.wanted).to.equal(false);
    r.collisions.listened('physics-collision', 1);
    r.collisions.listened('physics-collision-end', 1);
    r.collisions.listened('click', 1);
    expect(r.collisions.wanted).to.equal(true);
    r.collisions.listened('physics-collision', -1);
    expect(r.sent).to.deep.equal([['setParams', [{ events: true }]]]);
    r.collisions.listened('physics-collision-end', -1);
    // More removals than additions (a listener removed twice) do not go below none.
    r.collisions.listened('physics-collision-end', -1);
    expect(r.sent).to.deep.equal([['setParams', [{ events: true }]], ['setParams', [{ events: false }]]]);
    expect(r.collisions.wanted).to.equal(false);
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
