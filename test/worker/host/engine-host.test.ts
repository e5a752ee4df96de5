// The engine host without a worker (Node): a fake publisher and output, a fake clock for the loop. Scenes of every
// body type, live edits, steps, grabs, snapshots with a frame overlay, diagnostics, frame encoding and bad input.
import { expect } from 'chai';
import { BODY_TYPES, RAGDOLL_JOINTS, World, type BodyDescription, type WorldSnapshot } from '../../../src/engine/index.js';
import type { FramePatch, KeyedLink } from '../../../src/worker/protocol.js';
import { EVERY_TYPE, decode, makeHost } from './harness.js';

const clone = <T>(v: T): T => structuredClone(v);

/** The mean of the particles `indices` in a decoded frame. */
function mean(positions: [number, number][], indices: Int32Array): [number, number] {
  let x = 0;
  let y = 0;
  for (const i of indices) {
    x += positions[i][0];
    y += positions[i][1];
  }
  return [x / indices.length, y / indices.length];
}

describe('EngineHost (no worker)', () => {
  it('loads a scene of every body type; its topology tells the renderer what each needs to draw', () => {
    const h = makeHost();
    expect(h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: [] })).to.deep.equal([]);
    const t = h.topology;
    expect(t.version).to.equal(1);
    expect(new Set(t.bodies.map((b) => b.type))).to.deep.equal(new Set(BODY_TYPES));
    expect(t.bodies.map((b) => b.key)).to.deep.equal([0, 1, 2, 3, 4, 5, 6, 7]);
    expect(t.bodies.map((b) => b.indices.length)).to.deep.equal([4, 4, 1, 4, 13, 30, 13, RAGDOLL_JOINTS.length]);
    expect(t.bodies.map((b) => b.kind)).to.deep.equal(['rigid', 'rigid', 'particle', 'rigid', 'rope', 'cloth', 'soft', 'ragdoll']);
    // Every particle belongs to exactly one body.
    const all = t.bodies.flatMap((b) => Array.from(b.indices)).sort((a, b) => a - b);
    expect(all).to.deep.equal(Array.from({ length: 80 }, (_, i) => i));
    const [, , circle, , rope, cloth, soft, ragdoll] = t.bodies;
    expect(circle.radius).to.equal(0.5);
    expect(rope.radius).to.equal(0.05);
    expect([cloth.columns, cloth.rows, cloth.torn]).to.deep.equal([6, 5, undefined]);
    // The springs model's hub (its last particle) is not part of the ring.
    expect(soft.ring).to.equal(12);
    expect(ragdoll.radius).to.be.closeTo(0.075 * 1.5, 1e-12);
    const d = h.host.diagnostics();
    expect([d.bodyCount, d.particleCount, d.linkCount, d.stepCount, d.running, d.inWorker, d.transport]).to.deep.equal([8, 80, 0, 0, false, false, 'direct']);
    // A paused load publishes one frame of that topology.
    expect(h.publisher.frames.length).to.equal(1);
    expect(decode(h.frame).topology).to.equal(1);
  });

  it('a frame holds the world\'s particles (bit for bit) and each body\'s pose as its type reads it', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: [] });
    // At load, poses are the described ones: a box its centre and angle, a ragdoll its pelvis.
    const start = decode(h.frame);
    expect(start.poses[1][0]).to.be.closeTo(4, 1e-12);
    expect(start.poses[1][1]).to.be.closeTo(2, 1e-12);
    expect(start.poses[1][2]).to.be.closeTo(0.25, 1e-12);
    expect(start.poses[2]).to.deep.equal([7, 1, 0]);
    expect(start.poses[7][0]).to.be.closeTo(2, 1e-12);
    expect(start.poses[7][1]).to.be.closeTo(5, 1e-12);
    // The host's world, copied into a World of our own by the engine's snapshot, stepped as often: the same state, the
    // same numbers.
    const reference = new World();
    reference.restore(h.host.snapshot().world as WorldSnapshot);
    expect(h.host.step(40)).to.equal(40);
    for (let k = 0; k < 40; k++) reference.step();
    expect(h.host.stateHash()).to.equal(reference.stateHash());
    const f = decode(h.frame);
    expect([f.stepCount, f.time, f.running]).to.deep.equal([40, reference.time, false]);
    expect(f.positions.length).to.equal(reference.particles.count);
    f.positions.forEach(([x, y], i) => {
      expect(x).to.equal(reference.particles.x[i]);
      expect(y).to.equal(reference.particles.y[i]);
    });
    const t = h.topology.bodies;
    // Box: its centre and its first edge's turn since the build, added to the described angle.
    const b = t[1].indices;
    const [bx, by] = mean(f.positions, b);
    const edge = (q: [number, number][]) => Math.atan2(q[b[1]][1] - q[b[0]][1], q[b[1]][0] - q[b[0]][0]);
    expect(f.poses[1][0]).to.be.closeTo(bx, 1e-9);
    expect(f.poses[1][1]).to.be.closeTo(by, 1e-9);
    expect(f.poses[1][2]).to.be.closeTo(0.25 + edge(f.positions) - edge(start.positions), 1e-9);
    expect(f.poses[1][1]).to.be.greaterThan(2.1); // it fell
    // Circle: its particle. Rope, cloth, soft body: their particles' mean. Ragdoll: its pelvis.
    expect(f.poses[2].slice(0, 2)).to.deep.equal(f.positions[t[2].indices[0]]);
    for (const k of [4, 5, 6]) {
      const [mx, my] = mean(f.positions, t[k].indices);
      expect(f.poses[k][0]).to.be.closeTo(mx, 1e-9);
      expect(f.poses[k][1]).to.be.closeTo(my, 1e-9);
    }
    expect(f.poses[7].slice(0, 2)).to.deep.equal(f.positions[t[7].indices[RAGDOLL_JOINTS.indexOf('pelvis')]]);
  });

  it('step(n) takes n steps and publishes one frame; n is a count of at least 0', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(0, 3), links: [] });
    const counts: number[] = [];
    for (const n of [3, 0, -2, Number.NaN, 2.9, undefined]) counts.push(h.host.step(n));
    expect(counts).to.deep.equal([3, 3, 3, 3, 5, 6]);
    expect(h.publisher.frames.length).to.equal(1 + 6);
    expect(decode(h.frame).stepCount).to.equal(6);
  });

  it('adds, updates and removes bodies: a new topology for a change of shape, nothing for a change of style', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: [] });
    const ball: BodyDescription = { type: 'circle', x: 3, y: 3, radius: 0.3, restitution: 0.2 };
    expect(h.host.addBody({ key: 8, desc: ball })).to.equal(null);
    expect(h.topology.version).to.equal(2);
    expect(h.topology.bodies.map((b) => b.key)).to.deep.equal([0, 1, 2, 3, 4, 5, 6, 7, 8]);
    expect(decode(h.frame).poses[8]).to.deep.equal([3, 3, 0]);
    const frames = h.publisher.frames.length;
    // Style, then material: no rebuild, no new topology, no frame.
    expect(h.host.updateBody({ key: 8, desc: { ...ball, fill: '#f00' } })).to.equal(null);
    expect(h.host.updateBody({ key: 8, desc: { ...ball, fill: '#f00', restitution: 0.9 } })).to.equal(null);
    expect([h.topologies.length, h.publisher.frames.length]).to.deep.equal([2, frames]);
    // Shape: rebuilt.
    expect(h.host.updateBody({ key: 8, desc: { ...ball, radius: 0.7 } })).to.equal(null);
    expect(h.topology.bodies.find((b) => b.key === 8)!.radius).to.equal(0.7);
    expect(h.publisher.frames.length).to.equal(frames + 1);
    // Removing: gone from the topology; an unknown key changes nothing.
    h.host.removeBody(8);
    expect(h.topology.bodies.map((b) => b.key)).to.deep.equal([0, 1, 2, 3, 4, 5, 6, 7]);
    const topologies = h.topologies.length;
    h.host.removeBody(999);
    expect(h.topologies.length).to.equal(topologies);
    // Updating an unknown key adds it; adding a known key updates it.
    h.host.updateBody({ key: 9, desc: ball });
    h.host.addBody({ key: 9, desc: { ...ball, x: 5 } });
    const f = decode(h.frame);
    expect(h.topology.bodies.filter((b) => b.key === 9).length).to.equal(1);
    expect(f.poses[8]).to.deep.equal([5, 3, 0]);
    expect(h.host.diagnostics().bodyCount).to.equal(9);
  });

  it('links join the particles nearest their anchor, and follow their bodies through edits', () => {
    const h = makeHost();
    const links: KeyedLink[] = [
      { key: 100, desc: { type: 'joint', a: 1, b: 2 } },
      { key: 101, desc: { type: 'spring', a: 2, b: 0, stiffness: 20 } },
      { key: 102, desc: { type: 'pin', a: 1, x: 3.5, y: 1.5 } },
      { key: 103, desc: { type: 'pin', a: 4, x: 11, y: 1, particle: 3 } },
    ];
    expect(h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: clone(links) })).to.deep.equal([]);
    const pairs = (): number[][] => {
      const l = h.topology.links;
      return Array.from({ length: l.length / 2 }, (_, k) => [l[2 * k], l[2 * k + 1]]);
    };
    const t = h.topology.bodies;
    const f = decode(h.frame);
    const [joint, spring, pin, ropePin] = pairs();
    // The joint: the box's particle nearest the ball, and the ball.
    expect(Array.from(t[1].indices)).to.include(joint[0]);
    expect(joint[1]).to.equal(t[2].indices[0]);
    const d2 = (i: number, x: number, y: number) => (f.positions[i][0] - x) ** 2 + (f.positions[i][1] - y) ** 2;
    for (const i of t[1].indices) expect(d2(joint[0], 7, 1)).to.be.at.most(d2(i, 7, 1));
    expect(Array.from(t[0].indices)).to.include(spring[1]);
    // Pins hold one particle (the same index twice): nearest the anchor, or the one named.
    expect(pin[0]).to.equal(pin[1]);
    for (const i of t[1].indices) expect(d2(pin[0], 3.5, 1.5)).to.be.at.most(d2(i, 3.5, 1.5));
    expect(ropePin).to.deep.equal([t[4].indices[3], t[4].indices[3]]);
    expect(h.host.diagnostics().linkCount).to.equal(4);
    // Without the ball, its two links are out of force; with it back, in force again.
    h.host.removeBody(2);
    expect(pairs().length).to.equal(2);
    expect(h.host.diagnostics().linkCount).to.equal(2);
    h.host.addBody(clone(EVERY_TYPE[2]));
    expect(pairs().length).to.equal(4);
    h.host.removeLink(100);
    expect(pairs().length).to.equal(3);
    expect(h.host.diagnostics().linkCount).to.equal(3);
    // A link to a body that does not exist waits for it, quietly; a bad one names its field.
    expect(h.host.addLink({ key: 104, desc: { type: 'joint', a: 1, b: 77 } })).to.equal(null);
    expect(pairs().length).to.equal(3);
    const bad = h.host.updateLink({ key: 101, desc: { type: 'spring', a: 2, b: 0, stiffness: -1 } });
    expect(bad).to.include({ key: 101, field: 'stiffness' });
    expect(bad!.message).to.match(/stiffness/);
    expect(pairs().length).to.equal(2);
  });

  it('refuses bad descriptions with the key, the field and a message; the rest of the scene loads', () => {
    const h = makeHost();
    const errors = h.host.load({
      world: { damping: -1 },
      params: { timestep: -1, gravity: { x: 0, y: 3 }, bounds: { minX: 0, minY: 0, maxX: Number.NaN, maxY: 9 } },
      bodies: [
        { key: 1, desc: { type: 'circle', x: 1, y: 1, radius: -1 } },
        { key: 2, desc: { type: 'blob' } as unknown as BodyDescription },
        { key: 3, desc: { type: 'box', x: 2, y: 2, width: 1, height: 1 } },
        { key: 4, desc: null as unknown as BodyDescription },
        { key: 5, desc: { type: 'cloth', origin: { x: 0, y: 0 }, columns: 1, rows: 3, spacing: 0.2 } },
      ],
      links: [],
    });
    const brief = errors.map((e) => [e.key, e.field]);
    expect(brief).to.deep.equal([[-1, 'bounds'], [-1, 'timestep'], [-1, 'damping'], [1, 'radius'], [2, 'type'], [4, ''], [5, 'columns']]);
    for (const e of errors) expect(e.message).to.be.a('string').and.not.equal('');
    expect(errors[3].message).to.match(/radius must be > 0/);
    expect(errors[5].message).to.match(/must be an object/);
    // What validated is in force: gravity, the default timestep, the box.
    expect(h.host.snapshot().params).to.include({ timestep: 1 / 60 });
    expect(h.host.snapshot().params.gravity).to.deep.equal({ x: 0, y: 3 });
    expect(h.topology.bodies.map((b) => b.key)).to.deep.equal([3]);
    // Live: the same answers, and a bad edit takes the body out until it is fixed. NaN never gets in.
    expect(h.host.setParams({ substeps: 0, iterations: 2 })).to.include({ key: -1, field: 'substeps' });
    expect(h.host.snapshot().params).to.include({ substeps: 10, iterations: 2 });
    expect(h.host.updateBody({ key: 3, desc: { type: 'box', x: Number.NaN, y: 2, width: 1, height: 1 } })).to.include({ key: 3, field: 'x' });
    expect(h.topology.bodies.length).to.equal(0);
    expect(h.host.updateBody({ key: 3, desc: { type: 'box', x: 2, y: 2, width: 1, height: 1 } })).to.equal(null);
    expect(h.topology.bodies.length).to.equal(1);
    h.host.step(10);
    expect(decode(h.frame).positions.flat().every(Number.isFinite)).to.equal(true);
  });

  it('grabs hold what is under the point; a press inside a soft ring takes the ring; nothing there is null', () => {
    const h = makeHost();
    h.host.load({
      world: {},
      params: { gravity: { x: 0, y: 0 } },
      bodies: [
        { key: 1, desc: { type: 'box', x: 4, y: 2, width: 1, height: 1 } },
        { key: 2, desc: { type: 'softbody', center: { x: 10, y: 4 }, radius: 1.5, segments: 16 } },
        { key: 3, desc: { type: 'cloth', origin: { x: 1, y: 5 }, columns: 4, rows: 4, spacing: 0.3, pins: 'none' } },
      ],
      links: [],
    });
    const pose = (k: number) => decode(h.frame).poses[k];
    // The box, soft at the point: dragged 2 to the right.
    const g = h.host.grab(4, 2);
    expect(g).to.be.a('number');
    h.host.moveGrab(g!, 6, 2);
    h.host.step(120);
    expect(pose(0)[0]).to.be.closeTo(6, 0.05);
    h.host.release(g!);
    // The ring's centre is more than the pick radius away from every ring particle: still grabbed, by the ring.
    const ring = h.host.grab(10, 4);
    expect(ring).to.be.a('number');
    h.host.moveGrab(ring!, 10, 6);
    h.host.step(60);
    expect(pose(1)[1]).to.be.greaterThan(4.5);
    h.host.release(ring!);
    // A cloth particle, firmly.
    const c = h.host.grab(1.3, 5.3);
    expect(c).to.be.a('number');
    h.host.moveGrab(c!, 1.3, 7.3);
    h.host.step(30);
    const t = h.topology.bodies[2];
    const held = t.indices[5];
    expect(decode(h.frame).positions[held][1]).to.be.closeTo(7.3, 0.05);
    // Empty space and non-numbers: null.
    expect(h.host.grab(14, 1)).to.equal(null);
    expect(h.host.grab(Number.NaN, 1)).to.equal(null);
    // A stale handle (from before a reset) is ignored.
    h.host.reset();
    const hash = h.host.stateHash();
    for (const stale of [g!, ring!, c!]) {
      h.host.moveGrab(stale, 1, 1);
      h.host.release(stale);
    }
    expect(h.host.stateHash()).to.equal(hash);
  });

  it('moveGrab() and release() ignore a handle that names another constraint or nothing', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(1, 3), links: [{ key: 100, desc: { type: 'joint', a: 1, b: 2 } }] });
    const joint = h.host.snapshot().links[0].handles[0];
    for (const handle of [joint, 12345, -1]) {
      expect(() => h.host.moveGrab(handle, 1, 1)).to.not.throw();
      expect(() => h.host.release(handle)).to.not.throw();
    }
    expect(h.host.diagnostics().linkCount).to.equal(1);
    expect(h.host.snapshot().links[0].handles).to.deep.equal([joint]);
    h.host.step(1);
    expect(h.topology.links.length).to.equal(2);
  });

  it('applyImpulse and setVelocity move a body by its key; bodiesAt answers with keys', () => {
    const h = makeHost();
    h.host.load({ world: {}, params: { gravity: { x: 0, y: 0 } }, bodies: clone(EVERY_TYPE).slice(1, 3), links: [] });
    h.host.setVelocity(2, 3, 0);
    h.host.applyImpulse(1, 0, -2);
    h.host.applyImpulse(999, 1, 1);
    h.host.step(30);
    const f = decode(h.frame);
    expect(f.poses[1][0]).to.be.closeTo(7 + 3 * 0.5, 1e-6);
    expect(f.poses[0][1]).to.be.lessThan(2);
    expect(h.host.bodiesAt(f.poses[0][0], f.poses[0][1])).to.deep.equal([1]);
    expect(h.host.bodiesAt(20, 20)).to.deep.equal([]);
  });

  it('snapshot() → restore() puts everything back; with a frame of its topology, the frame\'s state on top', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: [{ key: 100, desc: { type: 'joint', a: 1, b: 2 } }] });
    h.host.step(20);
    const snap = h.host.snapshot();
    expect(snap.topology).to.equal(h.topology.version);
    h.host.step(30);
    const later = h.host.stateHash();
    expect(h.host.restore(snap)).to.equal(20);
    h.host.step(30);
    expect(h.host.stateHash()).to.equal(later);
    // A snapshot is plain data: a second host continues it the same way, and knows its bodies by key.
    const other = makeHost();
    expect(other.host.restore(clone(snap))).to.equal(20);
    other.host.step(30);
    expect(other.host.stateHash()).to.equal(later);
    const box = decode(other.frame).poses[1];
    expect(other.host.bodiesAt(box[0], box[1])).to.deep.equal([1]);
    expect(other.host.diagnostics()).to.include({ bodyCount: 8, linkCount: 1 });

    // The overlay: every movable particle where the frame drew it, 5 steps after the snapshot.
    h.host.restore(snap);
    const f = decode(h.frame);
    const moved = new Float64Array(f.positions.flat().map((v, i) => (i % 2 === 0 ? v + 0.1 : v)));
    const patch: FramePatch = { topology: snap.topology!, stepCount: 25, time: 25 / 60, positions: moved, velocities: new Float64Array(moved.length).fill(0.5) };
    expect(h.host.restore(snap, patch)).to.equal(25);
    const g = decode(h.frame);
    // Static and pinned particles stay: the floor's 4, the cloth's 2 corners, the rope's first.
    const world = new World();
    world.restore(snap.world as WorldSnapshot);
    const { invMass } = world.particles;
    let fixed = 0;
    g.positions.forEach(([x], i) => {
      if (invMass[i] === 0) fixed++;
      expect(x).to.be.closeTo(f.positions[i][0] + (invMass[i] === 0 ? 0 : 0.1), 1e-12);
    });
    expect(fixed).to.equal(4 + 2 + 1);
    expect([g.stepCount, g.time]).to.deep.equal([25, 25 / 60]);
    // Not over another topology, nor when older than the snapshot: the snapshot alone.
    for (const bad of [{ ...patch, topology: snap.topology! + 1 }, { ...patch, stepCount: 19 }, { ...patch, positions: moved.subarray(2) }]) {
      h.host.restore(snap, bad);
      expect(decode(h.frame).positions).to.deep.equal(f.positions);
    }
  });

  it('collision events carry body keys and go out once per frame, only while enabled', () => {
    const h = makeHost();
    const bodies = [clone(EVERY_TYPE[0]), { key: 2, desc: { type: 'circle', x: 5, y: 7.3, radius: 0.5 } as BodyDescription }];
    h.host.load({ world: {}, params: { events: true }, bodies, links: [] });
    h.host.step(60);
    const begins = h.events.filter((e) => e[0] === 0);
    expect(begins.length).to.equal(1);
    expect([begins[0][1], begins[0][2]].sort()).to.deep.equal([0, 2]);
    // A normal of unit length and a depth >= 0.
    expect(Math.hypot(begins[0][3], begins[0][4])).to.be.closeTo(1, 1e-9);
    expect(begins[0][5]).to.be.at.least(0);
    // Sixty steps, one batch: they went out with the frame.
    expect(h.eventBatches).to.equal(1);
    expect(h.host.diagnostics().eventsSent).to.equal(h.events.length);
    // Off: nothing is gathered or sent.
    h.host.setParams({ events: false });
    h.host.reset();
    const sent = h.events.length;
    h.host.step(60);
    expect(h.events.length).to.equal(sent);
    expect(h.host.diagnostics()).to.include({ events: false, eventsSent: sent });
  });

  it('debug frames carry each body\'s bounding box and the contacts', () => {
    const h = makeHost();
    const bodies = [clone(EVERY_TYPE[0]), clone(EVERY_TYPE[1]), { key: 2, desc: { type: 'circle', x: 7, y: 7.4, radius: 0.5 } as BodyDescription }];
    h.host.load({ world: {}, params: { debug: true }, bodies, links: [] });
    h.host.step(90);
    const f = decode(h.frame);
    expect(h.frame[8]).to.be.greaterThan(0); // F.cellSize
    expect(f.aabbs.length).to.equal(3);
    h.topology.bodies.forEach((b, k) => {
      const [x0, y0, x1, y1] = f.aabbs[k];
      for (const i of b.indices) {
        expect(f.positions[i][0]).to.be.within(x0, x1);
        expect(f.positions[i][1]).to.be.within(y0, y1);
      }
    });
    expect(f.contacts.length).to.be.greaterThan(0);
    for (const [, , nx, ny] of f.contacts) expect(Math.hypot(nx, ny)).to.be.closeTo(1, 1e-9);
    h.host.setParams({ debug: false });
    expect(decode(h.frame).aabbs).to.deep.equal([]);
  });

  it('a torn cloth\'s topology names its broken links until reset()', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: [{ key: 1, desc: { type: 'cloth', origin: { x: 2, y: 1 }, columns: 8, rows: 6, spacing: 0.4, pins: 'top', tear: 0.3 } }], links: [] });
    h.host.step(30);
    const g = h.host.grab(2.0, 3.0, 1e7)!;
    for (let k = 1; k <= 20 && h.host.diagnostics().brokenLinks === 0; k++) {
      h.host.moveGrab(g, 2.0 - 0.3 * k, 3.0 + 0.5 * k);
      h.host.step(3);
    }
    const broken = h.host.diagnostics().brokenLinks;
    expect(broken).to.be.greaterThan(0);
    const torn = h.topology.bodies[0].torn!;
    expect(torn).to.be.instanceOf(Uint8Array);
    let bits = 0;
    for (const v of torn) bits += (v & 1) + ((v >> 1) & 1);
    expect(bits).to.be.greaterThan(0).and.at.most(broken);
    h.host.reset();
    expect(h.topology.bodies[0].torn).to.equal(undefined);
    expect(h.host.diagnostics().brokenLinks).to.equal(0);
  });

  it('counts frames the publisher had no buffer for, and stops publishing once disposed', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(0, 2), links: [] });
    h.publisher.full = true;
    h.host.step(1);
    h.host.step(1);
    expect(h.host.diagnostics()).to.include({ published: 1, skipped: 2 });
    h.publisher.full = false;
    h.host.step(1);
    expect(h.host.diagnostics()).to.include({ published: 2, skipped: 2 });
    h.host.dispose();
    h.host.step(1);
    h.host.play();
    expect(h.publisher.frames.length).to.equal(2);
    expect(h.clock.pending).to.equal(0);
  });
});

describe('EngineHost step loop (fake clock)', () => {
  function running() {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(0, 3), links: [], running: true });
    return h;
  }

  it('steps as time passes, one frame per tick that stepped, and stops on pause()', () => {
    const h = running();
    expect(h.host.diagnostics().running).to.equal(true);
    expect(decode(h.frame).running).to.equal(true);
    const frames = h.publisher.frames.length;
    h.clock.advance(1000 / 60 * 6 + 1);
    expect(h.host.diagnostics().stepCount).to.equal(6);
    expect(h.publisher.frames.length - frames).to.equal(6);
    h.clock.advance(1000);
    expect(h.host.diagnostics().stepCount).to.equal(66);
    h.host.pause();
    expect(h.clock.pending).to.equal(0);
    expect(decode(h.frame).running).to.equal(false);
    h.clock.advance(1000);
    expect(h.host.diagnostics()).to.include({ stepCount: 66, running: false });
    // play() twice: one loop.
    h.host.play();
    h.host.play();
    expect(h.clock.pending).to.equal(1);
  });

  it('after a stall it catches up by at most the world\'s maxCatchUpSteps, in one frame', () => {
    const h = makeHost();
    h.host.load({ world: { maxCatchUpSteps: 3 }, bodies: clone(EVERY_TYPE).slice(0, 3), links: [], running: true });
    h.clock.advance(100);
    const steps = h.host.diagnostics().stepCount;
    const frames = h.publisher.frames.length;
    // A 2 s stall: the due tick runs once, late.
    (h.clock as unknown as { time: number }).time += 2000;
    h.clock.advance(0);
    expect(h.host.diagnostics().stepCount - steps).to.equal(3);
    expect(h.publisher.frames.length - frames).to.equal(1);
  });

  it('debugFault("throw") makes the next tick throw, and the loop stops there', () => {
    const h = running();
    h.clock.advance(50);
    h.host.debugFault('throw');
    expect(() => h.clock.advance(50)).to.throw('debug fault: the step loop threw');
    const steps = h.host.diagnostics().stepCount;
    expect(h.clock.pending).to.equal(0);
    h.clock.advance(500);
    expect(h.host.diagnostics().stepCount).to.equal(steps);
  });
});
