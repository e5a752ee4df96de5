// The host's collision event queue (src/worker/host/events.ts): what a step's events become, that each goes out once
// (a flush empties the queue, sent or not; clear() drops it), and, through the EngineHost, that a frame carries only
// the events of the steps since the frame before.
import { expect } from 'chai';
import type { BodyDescription, World } from '../../../src/engine/index.js';
import { EventQueue } from '../../../src/worker/host/events.js';
import type { Bindings } from '../../../src/worker/host/bindings.js';
import { EVENT } from '../../../src/worker/protocol.js';
import { makeHost } from './harness.js';

/** A world whose last step left `rows` (type, handle a, handle b, nx, ny, depth, speed each). */
function worldWith(rows: number[][]): World {
  const column = (k: number) => Float64Array.from(rows, (r) => r[k]);
  const events = { count: rows.length, type: Uint8Array.from(rows, (r) => r[0]), bodyA: column(1), bodyB: column(2), normalX: column(3), normalY: column(4), depth: column(5), speed: column(6) };
  return { events } as unknown as World;
}

/** Keys are handles + 100 (the bounds' −1 too, as the real bindings map what they do not know). */
const bindings = { keyOf: (h: number) => h + 100 } as unknown as Bindings;

/** An output that keeps each batch as rows of EVENT numbers. */
function recorder() {
  const batches: number[][][] = [];
  return {
    batches,
    events(data: Float64Array, count: number) {
      expect(data.length).to.equal(count * EVENT);
      batches.push(Array.from({ length: count }, (_, k) => Array.from(data.subarray(k * EVENT, (k + 1) * EVENT))));
    },
  };
}

describe('EventQueue', () => {
  const A = [0, 1, 2, 0, -1, 0.25, 3.5];
  const B = [1, 4, -1, 0, 0, 0, 0];
  const C = [0, 7, 8, 0.6, 0.8, 0, 1.25];

  it('gathers the events of each step (handles as keys) and sends them in one batch; the next flush sends only newer ones', () => {
    const q = new EventQueue();
    const out = recorder();
    q.collect(worldWith([A, B]), bindings);
    q.collect(worldWith([C]), bindings);
    q.flush(true, out);
    expect(out.batches).to.deep.equal([[[0, 101, 102, 0, -1, 0.25, 3.5], [1, 104, 99, 0, 0, 0, 0], [0, 107, 108, 0.6, 0.8, 0, 1.25]]]);
    expect(q.sent).to.equal(3);
    // Nothing new: no batch at all.
    q.flush(true, out);
    expect(out.batches.length).to.equal(1);
    // One new step's events: that batch holds them alone.
    q.collect(worldWith([B]), bindings);
    q.flush(true, out);
    expect(out.batches.slice(1)).to.deep.equal([[[1, 104, 99, 0, 0, 0, 0]]]);
    expect(q.sent).to.equal(4);
    // A step without events adds nothing.
    q.collect(worldWith([]), bindings);
    q.flush(true, out);
    expect(out.batches.length).to.equal(2);
  });

  it('a flush while nobody listens drops the gathered events: they are not sent later', () => {
    const q = new EventQueue();
    const out = recorder();
    q.collect(worldWith([A, C]), bindings);
    q.flush(false, out);
    expect(out.batches).to.deep.equal([]);
    expect(q.sent).to.equal(0);
    q.collect(worldWith([B]), bindings);
    q.flush(true, out);
    expect(out.batches).to.deep.equal([[[1, 104, 99, 0, 0, 0, 0]]]);
    expect(q.sent).to.equal(1);
  });

  it('clear() drops what was gathered', () => {
    const q = new EventQueue();
    const out = recorder();
    q.collect(worldWith([A, B, C]), bindings);
    q.clear();
    q.flush(true, out);
    expect(out.batches).to.deep.equal([]);
    q.collect(worldWith([C]), bindings);
    q.flush(true, out);
    expect(out.batches).to.deep.equal([[[0, 107, 108, 0.6, 0.8, 0, 1.25]]]);
  });

  it('grows past its first room (64 events) and keeps every event in order', () => {
    const q = new EventQueue();
    const out = recorder();
    const rows = Array.from({ length: 150 }, (_, k) => [k % 2, k, k + 1, 0, 1, k / 1000, k / 10]);
    for (let k = 0; k < 150; k += 50) q.collect(worldWith(rows.slice(k, k + 50)), bindings);
    q.flush(true, out);
    expect(out.batches.length).to.equal(1);
    expect(out.batches[0]).to.deep.equal(rows.map((r) => [r[0], r[1] + 100, r[2] + 100, ...r.slice(3)]));
  });
});

describe('EngineHost: each collision event goes out once', () => {
  it('a ball that lands, is thrown up and lands again: each frame carries only its own steps\' begins and ends', () => {
    const h = makeHost();
    // A ball 0.2 above a static floor (g = 9.81): it lands after √(2·0.2/9.81) = 0.20 s, step 13 of 60 per second.
    const bodies: { key: number; desc: BodyDescription }[] = [
      { key: 0, desc: { type: 'box', x: 8, y: 8.5, width: 16, height: 1, static: true } },
      { key: 2, desc: { type: 'circle', x: 5, y: 7.3, radius: 0.5 } },
    ];
    h.host.load({ world: { sleeping: false }, params: { events: true }, bodies, links: [] });
    const kinds = (from: number) => h.events.slice(from).map((e) => [e[0], ...[e[1], e[2]].sort()]);
    h.host.step(30);
    expect(kinds(0), 'the landing').to.deep.equal([[0, 0, 2]]);
    expect(h.eventBatches).to.equal(1);
    // At rest on the floor, further frames carry nothing (the landing is not sent again).
    for (let k = 0; k < 5; k++) h.host.step(6);
    expect(h.events.length).to.equal(1);
    expect(h.eventBatches).to.equal(1);
    // Thrown up at 6 units/s: it leaves the floor in the first step (an end) and lands again after 2·6/9.81 = 1.22 s.
    h.host.setVelocity(2, 0, -6);
    h.host.step(1);
    expect(kinds(1), 'the throw').to.deep.equal([[1, 0, 2]]);
    h.host.step(90);
    expect(kinds(2), 'the second landing').to.deep.equal([[0, 0, 2]]);
    expect(h.eventBatches).to.equal(3);
    expect(h.host.diagnostics().eventsSent).to.equal(3);
  });
});
