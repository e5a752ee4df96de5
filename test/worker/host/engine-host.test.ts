// The engine host without a worker (Node): a fake publisher and output, a fake clock for the loop. Scenes of every
// body type, live edits, steps, grabs, snapshots with a frame overlay, diagnostics, frame encoding and bad input.
import { expect } from 'chai';
import { BODY_TYPES, RAGDOLL_JOINTS, World, type BodyDescription, type WorldSnapshot } from '../../../src/engine/index.js';
import { AUTO_SUBSTEPS } from '../../../src/engine/settings.js';
import type { FramePatch, KeyedLink } from '../../../src/worker/protocol.js';
import { EngineHost } from '../../../src/worker/engine-host.js';
import { TransferPublisher } from '../../../src/worker/publishers.js';
import { EVERY_TYPE, FakeClock, decode, makeHost } from './harness.js';

const clone = <T>(v: T): T => structuredClone(v);

/** Each number within `tolerance` of the expected one. */
function near(actual: ArrayLike<number>, expected: number[], tolerance = 1e-12): void {
  expect(actual.length).to.equal(expected.length);
  expected.forEach((v, k) => expect(actual[k], `[${k}]`).to.be.closeTo(v, tolerance));
}

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
    // Boxes, balls and polygons are rigid bodies: one particle each, their centre of mass.
    expect(t.bodies.map((b) => b.indices.length)).to.deep.equal([1, 1, 1, 1, 13, 30, 13, RAGDOLL_JOINTS.length]);
    expect(t.bodies.map((b) => b.kind)).to.deep.equal(['rigid', 'rigid', 'rigid', 'rigid', 'rope', 'cloth', 'soft', 'ragdoll']);
    expect(t.bodies.map((b) => b.rigid ?? false)).to.deep.equal([true, true, true, true, false, false, false, false]);
    // Every particle belongs to exactly one body.
    const all = t.bodies.flatMap((b) => Array.from(b.indices)).sort((a, b) => a - b);
    expect(all).to.deep.equal(Array.from({ length: 71 }, (_, i) => i));
    const [floor, box, circle, polygon, rope, cloth, soft, ragdoll] = t.bodies;
    // Rigid shapes: an outline about the centre of mass (here the origin), or a disc's radius.
    near(floor.outline!, [-8, -0.5, 8, -0.5, 8, 0.5, -8, 0.5]);
    near(box.outline!, [-0.5, -0.5, 0.5, -0.5, 0.5, 0.5, -0.5, 0.5]);
    near(polygon.outline!, [-1, -0.5, 1, -0.5, 1, 0.5, -1, 0.5]);
    for (const b of [floor, box, circle, polygon]) near(b.center!, [0, 0]);
    expect([circle.radius, circle.outline]).to.deep.equal([0.5, undefined]);
    expect(rope.radius).to.equal(0.05);
    expect([cloth.columns, cloth.rows, cloth.torn]).to.deep.equal([6, 5, undefined]);
    // The springs model's hub (its last particle) is not part of the ring.
    expect(soft.ring).to.equal(12);
    expect(ragdoll.radius).to.be.closeTo(0.075 * 1.5, 1e-12);
    const d = h.host.diagnostics();
    expect([d.bodyCount, d.particleCount, d.linkCount, d.stepCount, d.running, d.inWorker, d.transport]).to.deep.equal([8, 71, 0, 0, false, false, 'direct']);
    // A paused load publishes one frame of that topology.
    expect(h.publisher.frames.length).to.equal(1);
    expect(decode(h.frame).topology).to.equal(1);
  });

  it('a frame holds the world\'s particles (bit for bit) and each body\'s pose as its type reads it', () => {
    const h = makeHost();
    // Besides every type, a box of the particle model (a frame of four particles).
    const frameBox = { key: 8, desc: { type: 'box', model: 'particles', x: 6, y: 5, width: 1, height: 1, angle: 0.25 } as BodyDescription };
    h.host.load({ world: {}, bodies: [...clone(EVERY_TYPE), frameBox], links: [] });
    // At load, poses are the described ones: a rigid box its centre and angle, a ragdoll its pelvis.
    const start = decode(h.frame);
    expect(start.poses[1]).to.deep.equal([4, 2, 0.25]);
    expect(start.poses[2]).to.deep.equal([7, 1, 0]);
    near(start.poses[8], [6, 5, 0.25]);
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
    // Rigid bodies (box, ball, polygon): their centre of mass and their angle, as the engine holds them.
    for (const k of [1, 2, 3]) {
      const i = t[k].indices[0];
      expect(f.poses[k]).to.deep.equal([reference.particles.x[i], reference.particles.y[i], reference.particles.angle[i]]);
    }
    expect(f.poses[1][1]).to.be.greaterThan(2.1); // it fell
    // The particle box: its centre and its first edge's turn since the build, added to the described angle.
    const b = t[8].indices;
    const [bx, by] = mean(f.positions, b);
    const edge = (q: [number, number][]) => Math.atan2(q[b[1]][1] - q[b[0]][1], q[b[1]][0] - q[b[0]][0]);
    near(f.poses[8], [bx, by, 0.25 + edge(f.positions) - edge(start.positions)], 1e-9);
    // Rope, cloth, soft body: their particles' mean. Ragdoll: its pelvis.
    for (const k of [4, 5, 6]) near(f.poses[k].slice(0, 2), mean(f.positions, t[k].indices), 1e-9);
    expect(f.poses[7].slice(0, 2)).to.deep.equal(f.positions[t[7].indices[RAGDOLL_JOINTS.indexOf('pelvis')]]);
  });

  it('a rigid polygon described off its centre: the frame poses its centre of mass, the topology says where that is', () => {
    const h = makeHost();
    // An L: its centre of mass is not its origin, nor the mean of its points.
    const points = [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 3 }, { x: 0, y: 3 }];
    h.host.load({ world: {}, params: { gravity: { x: 0, y: 0 } }, bodies: [{ key: 1, desc: { type: 'polygon', x: 5, y: 4, angle: 0.5, points } }], links: [] });
    const body = h.topology.bodies[0];
    // Area 4: the 2×1 foot (centre 1, 0.5) and the 1×2 leg (centre 0.5, 2), each half of it.
    near(body.center!, [0.75, 1.25]);
    // The outline is the one described (a concave one too, not its convex parts), about the centre of mass.
    near(body.outline!, points.flatMap((q) => [q.x - 0.75, q.y - 1.25]));
    const [x, y, angle] = decode(h.frame).poses[0];
    const c = Math.cos(0.5);
    const s = Math.sin(0.5);
    near([x, y, angle], [5 + c * 0.75 - s * 1.25, 4 + s * 0.75 + c * 1.25, 0.5]);
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

  it('links: a rigid body held at the anchor (or its centre), a body of particles at its nearest particle; they follow edits', () => {
    const h = makeHost();
    const links: KeyedLink[] = [
      { key: 100, desc: { type: 'joint', a: 1, b: 2 } },
      { key: 101, desc: { type: 'spring', a: 2, b: 0, stiffness: 20 } },
      { key: 102, desc: { type: 'pin', a: 1, x: 3.5, y: 1.5 } },
      { key: 103, desc: { type: 'pin', a: 4, x: 11, y: 1, particle: 3 } },
      { key: 104, desc: { type: 'joint', a: 4, b: 5, x: 2, y: 1 } },
      { key: 105, desc: { type: 'spring', a: 4, b: 6, stiffness: 5 } },
    ];
    expect(h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: clone(links) })).to.deep.equal([]);
    const t = h.topology.bodies;
    const f = decode(h.frame);
    const [joint, spring, pin, ropePin, ropeCloth, ropeSoft] = h.topology.links;
    const centre = (body: number) => ({ body, particle: -1, x: 0, y: 0 });
    const particle = (i: number) => ({ body: -1, particle: i, x: 0, y: 0 });
    // Without an anchor, rigid bodies are joined at their centres: the joint (a stick, the default type) and the spring.
    expect(joint).to.deep.equal({ a: centre(1), b: centre(2), pivot: false });
    expect(spring).to.deep.equal({ a: centre(2), b: centre(0), pivot: false });
    // A rigid body pinned at a point: that point of it (in its own frame, turned back by its angle 0.25) on the world's.
    const [dx, dy] = [3.5 - 4, 1.5 - 2];
    expect(pin.a.body).to.equal(1);
    near([pin.a.x, pin.a.y], [Math.cos(0.25) * dx + Math.sin(0.25) * dy, -Math.sin(0.25) * dx + Math.cos(0.25) * dy]);
    expect([pin.b, pin.pivot]).to.deep.equal([{ body: -1, particle: -1, x: 3.5, y: 1.5 }, true]);
    // Bodies of particles: the particle named, or the one nearest the anchor, or nearest the other end.
    expect(ropePin).to.deep.equal({ a: particle(t[4].indices[3]), b: { body: -1, particle: -1, x: 11, y: 1 }, pivot: true });
    const d2 = (i: number, x: number, y: number) => (f.positions[i][0] - x) ** 2 + (f.positions[i][1] - y) ** 2;
    for (const i of t[4].indices) expect(d2(ropeCloth.a.particle, 2, 1)).to.be.at.most(d2(i, 2, 1));
    for (const i of t[5].indices) expect(d2(ropeCloth.b.particle, 2, 1)).to.be.at.most(d2(i, 2, 1));
    expect(Array.from(t[5].indices)).to.include(ropeCloth.b.particle);
    // Between particles a spring is a spring force; everything else an engine joint, or a pin.
    const world = new World();
    world.restore(h.host.snapshot().world as WorldSnapshot);
    const kinds = h.host.snapshot().links.map((l) => l.handles.map((c) => world.constraintKindOf(c)));
    expect(kinds).to.deep.equal([['joint'], ['joint'], ['joint'], ['pin'], ['joint'], ['spring']]);
    expect(ropeSoft.a.particle).to.be.at.least(0);
    expect(h.host.diagnostics().linkCount).to.equal(6);
    // Without the ball, its two links are out of force; with it back, in force again.
    h.host.removeBody(2);
    expect(h.topology.links.length).to.equal(4);
    expect(h.host.diagnostics().linkCount).to.equal(4);
    h.host.addBody(clone(EVERY_TYPE[2]));
    expect(h.topology.links.length).to.equal(6);
    // Ends on rigid bodies name the body by its place in the topology, which the re-added ball changed.
    expect(h.topology.links.find((l) => l.a.body === 1 && l.b.body >= 0)!.b.body).to.equal(h.topology.bodies.findIndex((b) => b.key === 2));
    h.host.removeLink(100);
    expect(h.topology.links.length).to.equal(5);
    expect(h.host.diagnostics().linkCount).to.equal(5);
    // A link to a body that does not exist waits for it, quietly; a bad one names its field.
    expect(h.host.addLink({ key: 106, desc: { type: 'joint', a: 1, b: 77 } })).to.equal(null);
    expect(h.topology.links.length).to.equal(5);
    const bad = h.host.updateLink({ key: 101, desc: { type: 'spring', a: 2, b: 0, stiffness: -1 } });
    expect(bad).to.include({ key: 101, field: 'stiffness' });
    expect(bad!.message).to.match(/stiffness/);
    expect(h.topology.links.length).to.equal(4);
    const badJoint = h.host.addLink({ key: 107, desc: { type: 'joint', joint: 'revolute', a: 1, lowerAngle: 1, upperAngle: 0 } });
    expect(badJoint).to.include({ key: 107 });
    expect(badJoint!.message).to.match(/lowerAngle/);
  });

  it("substeps: 'auto' unless a count is given; the engine's count by what moves, and a count wins", () => {
    const rigid = () => clone(EVERY_TYPE.slice(0, 4));
    const cloth = clone(EVERY_TYPE[5]);
    const h = makeHost();
    h.host.load({ world: {}, bodies: rigid(), links: [] });
    expect(h.host.snapshot().params.substeps).to.equal('auto');
    expect(h.host.diagnostics().substepCount).to.equal(AUTO_SUBSTEPS.rigid);
    // The steps taken are the ones said: the same state as a host told the count, not as one told 10.
    const told = (substeps: number) => {
      const o = makeHost();
      o.host.load({ world: {}, params: { substeps }, bodies: rigid(), links: [] });
      expect(o.host.diagnostics().substepCount).to.equal(substeps);
      o.host.step(30);
      return o.host.stateHash();
    };
    h.host.step(30);
    expect(h.host.stateHash()).to.equal(told(AUTO_SUBSTEPS.rigid));
    expect(h.host.stateHash()).to.not.equal(told(AUTO_SUBSTEPS.particles));
    // A cloth moves: particles' count. Taken out: the rigid count again.
    expect(h.host.addBody(cloth)).to.equal(null);
    expect(h.host.diagnostics().substepCount).to.equal(AUTO_SUBSTEPS.particles);
    expect(h.host.setParams({ substeps: 3 })).to.equal(null);
    expect([h.host.snapshot().params.substeps, h.host.diagnostics().substepCount]).to.deep.equal([3, 3]);
    // A bad count is refused and the last good value stays.
    for (const bad of [0, 2.5, 1001, 'x']) {
      const error = h.host.setParams({ substeps: bad as number });
      expect([error?.key, error?.field]).to.deep.equal([-1, 'substeps']);
      expect(error!.message).to.match(/substeps/);
      expect(h.host.snapshot().params.substeps).to.equal(3);
    }
    expect(h.host.setParams({ substeps: 'auto' })).to.equal(null);
    expect(h.host.diagnostics().substepCount).to.equal(AUTO_SUBSTEPS.particles);
    h.host.removeBody(cloth.key);
    expect(h.host.diagnostics().substepCount).to.equal(AUTO_SUBSTEPS.rigid);
    // A rebuild keeps the choice.
    h.host.setParams({ substeps: 4 });
    h.host.reset();
    expect(h.host.diagnostics().substepCount).to.equal(4);
  });

  it('the params a scene is loaded or set with are the world\'s, in the world built then and in every one rebuilt (a reset, a kernel switch)', () => {
    // The host keeps its own copy of the params (snapshot().params, which the test above reads); the world is built
    // from forWorld(). A timestep, iterations or phases left out of it ran the world at the defaults while the host
    // said otherwise: nothing here looked at the world itself.
    for (const when of ['load', 'reset', 'kernel switch', 'set, then reset'] as const) {
      const h = makeHost();
      const params = { timestep: 1 / 30, iterations: 3, broadphase: 'brute', narrowphase: 'gjk', bounds: { minX: -10, minY: -10, maxX: 10, maxY: 3.5 } } as const;
      h.host.load({ world: { sleeping: false }, params: when === 'set, then reset' ? {} : params, bodies: [{ key: 1, desc: { type: 'circle', x: 0, y: 0, radius: 0.5 } }], links: [] });
      if (when === 'set, then reset') expect(h.host.setParams(params)).to.equal(null);
      if (when === 'reset' || when === 'set, then reset') h.host.reset();
      if (when === 'kernel switch') h.host.setParams({ kernel: h.host.diagnostics().kernelRequested === 'wasm' ? 'js' : 'wasm' });
      const settings = (h.host.snapshot().world as unknown as { settings: Record<string, unknown> }).settings;
      expect([settings.timestep, settings.iterations, settings.broadphase, settings.narrowphase], when).to.deep.equal([1 / 30, 3, 'brute', 'gjk']);
      expect(settings.bounds, when).to.deep.equal(params.bounds);
      expect(h.host.snapshot().params, when).to.deep.include({ timestep: 1 / 30, iterations: 3, broadphase: 'brute', narrowphase: 'gjk', bounds: params.bounds });
      // 15 steps of 1/30 s: ½·9.81·0.5² = 1.22625 fallen (1/60 s steps would give a quarter of it).
      h.host.step(15);
      expect(decode(h.frame).poses[0][1], when).to.be.closeTo(0.5 * 9.81 * 0.25, 1e-9);
      // Then it lands on the bounds' floor at 3.5, its centre at 3.
      h.host.step(60);
      expect(decode(h.frame).poses[0][1], when).to.be.closeTo(3, 0.01);
    }
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
    expect(h.host.snapshot().params).to.include({ substeps: 'auto', iterations: 2 });
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
    // The rigid box, held softly at the pressed point (0.3, 0.2 from its centre) and dragged 2 to the right: that
    // point of it follows the pointer while the box swings about it.
    const g = h.host.grab(4.3, 2.2);
    expect(g).to.be.a('number');
    for (let k = 1; k <= 40; k++) {
      h.host.moveGrab(g!, 4.3 + 0.05 * k, 2.2);
      h.host.step(2);
    }
    let farthest = 0;
    for (let k = 0; k < 60; k++) {
      h.host.step(1);
      const [x, y, a] = pose(0);
      const held = [x + Math.cos(a) * 0.3 - Math.sin(a) * 0.2, y + Math.sin(a) * 0.3 + Math.cos(a) * 0.2];
      farthest = Math.max(farthest, Math.hypot(held[0] - 6.3, held[1] - 2.2));
    }
    expect(farthest).to.be.below(0.05);
    expect(Math.abs(pose(0)[2])).to.be.greaterThan(0.1);
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

  it('a press takes a rigid body or a box or polygon of particles softly, anything else firmly, each at the stiffness given if one is', () => {
    // Dragged at 3 units/s, the held point trails the pointer by 3 × 2ζ/ω = 3 × 0.0358 × √(2000 / k) at stiffness k
    // (the engine's grab, test/engine/grab.test.ts): 0.107 at the engine's default 2000, 0.0048 at the host's firm 1e6.
    // Nothing else here told the two grips apart, nor checked that the stiffness passed was used.
    const trail = (desc: BodyDescription, stiffness: number | undefined): number => {
      const h = makeHost();
      h.host.load({ world: { gravity: { x: 0, y: 0 }, bounds: null, sleeping: false }, bodies: [{ key: 1, desc }], links: [] });
      const g = h.host.grab(0, 0, stiffness)!;
      expect(g).to.be.a('number');
      for (let k = 1; k <= 30; k++) {
        h.host.moveGrab(g, (3 * k) / 60, 0);
        h.host.step(1);
      }
      const idx = h.topology.bodies[0].indices;
      const positions = decode(h.frame).positions;
      // The box's middle (where it was pressed), or the cloth's corner particle (at the press).
      const x = desc.type === 'box' ? idx.reduce((sum, i) => sum + positions[i][0], 0) / idx.length : positions[idx[0]][0];
      return 1.5 - x;
    };
    const expected = (k: number) => 3 * 0.0358 * Math.sqrt(2000 / k);
    const box: BodyDescription = { type: 'box', model: 'particles', x: 0, y: 0, width: 1, height: 1 };
    const cloth: BodyDescription = { type: 'cloth', origin: { x: 0, y: 0 }, columns: 4, rows: 4, spacing: 0.3, pins: 'none' };
    for (const [stiffness, k] of [[undefined, 2000], [8000, 8000], [1e6, 1e6]] as const) expect(trail(box, stiffness), `box, stiffness ${stiffness}`).to.be.closeTo(expected(k), 0.03 * expected(k));
    // The cloth follows a little behind its held corner (it stretches): 6 % more at 2000.
    for (const [stiffness, k] of [[undefined, 1e6], [2000, 2000], [8000, 8000]] as const) expect(trail(cloth, stiffness), `cloth, stiffness ${stiffness}`).to.be.closeTo(expected(k), 0.08 * expected(k));
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
    expect(h.topology.links.length).to.equal(1);
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
    // The params come back with it (the host's record of them, which a rebuilt world is made from).
    other.host.setParams({ gravity: { x: 1, y: 2 }, iterations: 4 });
    other.host.restore(clone(snap));
    expect(other.host.snapshot().params).to.deep.equal(snap.params);

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
    // The rigid floor's centre, the cloth's 2 corners, the rope's first.
    expect(fixed).to.equal(1 + 2 + 1);
    // And moving at the frame's velocities (0.5, 0.5); the fixed ones still.
    const overlaid = new World();
    overlaid.restore(h.host.snapshot().world as WorldSnapshot);
    for (let i = 0; i < g.positions.length; i++) {
      const v = invMass[i] === 0 ? [0, 0] : [0.5, 0.5];
      expect([overlaid.particles.vx[i], overlaid.particles.vy[i]], `particle ${i}'s velocity`).to.deep.equal(v);
    }
    expect([g.stepCount, g.time]).to.deep.equal([25, 25 / 60]);
    // Not over another topology, nor when older than the snapshot: the snapshot alone.
    for (const bad of [{ ...patch, topology: snap.topology! + 1 }, { ...patch, stepCount: 19 }, { ...patch, positions: moved.subarray(2) }]) {
      h.host.restore(snap, bad);
      expect(decode(h.frame).positions).to.deep.equal(f.positions);
    }
  });

  it('the frame overlay also turns rigid bodies to the frame\'s angles and spins them at its angular velocities', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE), links: [] });
    h.host.step(10);
    const snap = h.host.snapshot();
    const f = decode(h.frame);
    // As drawn 5 steps later: the box (body 1) turned to 1.2 rad and spinning at 3 rad/s, the ball at -2 rad/s.
    const poses = new Float64Array(f.poses.flat());
    poses[3 * 1 + 2] = 1.2;
    // The static floor (body 0) drawn turned: a static body is not the frame's to turn.
    poses[3 * 0 + 2] = 0.7;
    const spins = new Float64Array(8);
    spins[1] = 3;
    spins[2] = -2;
    const positions = new Float64Array(f.positions.flat());
    const patch: FramePatch = { topology: snap.topology!, stepCount: 15, time: 15 / 60, positions, velocities: null, poses, spins };
    h.host.restore(snap, patch);
    expect(decode(h.frame).poses[1][2]).to.equal(1.2);
    const world = new World();
    world.restore(h.host.snapshot().world as WorldSnapshot);
    const handle = (key: number) => h.host.snapshot().bodies.find((b) => b.key === key)!.handle;
    expect(world.bodyPose(handle(1)).angle).to.equal(1.2);
    expect(world.bodyAngularVelocity(handle(1))).to.equal(3);
    expect(world.bodyAngularVelocity(handle(2))).to.equal(-2);
    // The static floor keeps its angle; the box keeps turning from where the frame had it.
    expect(world.bodyPose(handle(0)).angle).to.equal(0);
    expect(decode(h.frame).poses[0][2]).to.equal(0);
    // Turned in full (its cosine and sine too, which its shape is placed by): a point 0.45, 0.45 from its centre in
    // its own frame, turned by 1.2, is in it (turned by -1.2 instead, that point is 0.64 out along its x).
    const [bx, by] = decode(h.frame).poses[1];
    const [c, sn] = [Math.cos(1.2), Math.sin(1.2)];
    expect(h.host.bodiesAt(bx + 0.45 * c - 0.45 * sn, by + 0.45 * sn + 0.45 * c)).to.deep.equal([1]);
    // And 0.6 along its turned x axis is outside it (a cosine left at 1 stretches it over that point).
    expect(h.host.bodiesAt(bx + 0.6 * c, by + 0.6 * sn)).to.deep.equal([]);
    h.host.step(1);
    expect(decode(h.frame).poses[1][2]).to.be.closeTo(1.2 + 3 / 60, 0.01);
  });

  it('collision events carry body keys and go out once per frame, only while enabled', () => {
    const h = makeHost();
    const bodies = [clone(EVERY_TYPE[0]), { key: 2, desc: { type: 'circle', x: 5, y: 7.3, radius: 0.5 } as BodyDescription }];
    h.host.load({ world: {}, params: { events: true }, bodies, links: [] });
    h.host.step(60);
    const begins = h.events.filter((e) => e[0] === 0);
    expect(begins.length).to.equal(1);
    expect([begins[0][1], begins[0][2]].sort()).to.deep.equal([0, 2]);
    // The normal, vertical; depth 0 (the contact is found before they touch) and the speed they met at: the ball's
    // bottom fell 0.2 (from 7.8 to the floor's top at 8) under g = 9.81, √(2·9.81·0.2).
    expect(Math.abs(begins[0][4])).to.be.closeTo(1, 1e-9);
    expect(begins[0][3]).to.be.closeTo(0, 1e-9);
    expect(begins[0][5]).to.equal(0);
    expect(begins[0][6]).to.be.closeTo(Math.sqrt(2 * 9.81 * 0.2), 2e-3 * Math.sqrt(2 * 9.81 * 0.2));
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

  it('debug frames carry each body\'s bounding box and the contacts, of rigid bodies and of bodies of particles', () => {
    const h = makeHost();
    const bodies = [
      clone(EVERY_TYPE[0]),
      clone(EVERY_TYPE[1]),
      { key: 2, desc: { type: 'circle', x: 7, y: 7.4, radius: 0.5 } as BodyDescription },
      { key: 3, desc: { type: 'box', model: 'particles', x: 10, y: 7.4, width: 1, height: 1 } as BodyDescription },
    ];
    // Awake, so every resting body keeps its contacts.
    h.host.load({ world: { sleeping: false }, params: { debug: true }, bodies, links: [] });
    h.host.step(89);
    // F.cellSize: the grid's cell in the last step, as a world in the same state says (> 0 held for any number).
    const reference = new World();
    reference.restore(h.host.snapshot().world as WorldSnapshot);
    reference.step();
    h.host.step(1);
    expect(reference.gridCellSize).to.be.above(0.1);
    expect(h.frame[8]).to.equal(reference.gridCellSize);
    const f = decode(h.frame);
    expect(f.aabbs.length).to.equal(4);
    h.topology.bodies.forEach((b, k) => {
      const [x0, y0, x1, y1] = f.aabbs[k];
      for (const i of b.indices) {
        expect(f.positions[i][0]).to.be.within(x0, x1);
        expect(f.positions[i][1]).to.be.within(y0, y1);
      }
    });
    // A rigid body's box is its turned outline's (or its disc's): the ball rests on the floor (top at y = 8).
    const ball = f.poses[2];
    near(f.aabbs[2], [ball[0] - 0.5, ball[1] - 0.5, ball[0] + 0.5, ball[1] + 0.5]);
    expect(f.aabbs[2][3]).to.be.closeTo(8, 0.03);
    const [bx, by, ba] = f.poses[1];
    const corners = [[-0.5, -0.5], [0.5, -0.5], [0.5, 0.5], [-0.5, 0.5]].map(([u, v]) => [bx + Math.cos(ba) * u - Math.sin(ba) * v, by + Math.sin(ba) * u + Math.cos(ba) * v]);
    near(f.aabbs[1], [Math.min(...corners.map((c) => c[0])), Math.min(...corners.map((c) => c[1])), Math.max(...corners.map((c) => c[0])), Math.max(...corners.map((c) => c[1]))]);
    // Contacts of all three resting bodies, on the floor's top, normals vertical.
    expect(f.contacts.length).to.be.at.least(3);
    for (const [x, y, nx, ny] of f.contacts) {
      expect(Math.hypot(nx, ny)).to.be.closeTo(1, 1e-9);
      // Up, out of the floor (y grows downward), for particle and rigid contacts alike.
      expect(ny).to.be.closeTo(-1, 1e-3);
      expect(y).to.be.closeTo(8, 0.05);
      expect(x).to.be.within(1, 12);
    }
    for (const x of [bx, ball[0], f.poses[3][0]]) expect(f.contacts.some((c) => Math.abs(c[0] - x) <= 0.75)).to.equal(true);
    // The tilted box touches at its lowest corner: a contact point there (placed by its turned lever arm).
    const lowest = corners.reduce((p, q) => (q[1] > p[1] ? q : p));
    expect(Math.abs(ba), 'the box still tilted').to.be.above(0.05);
    expect(Math.min(...f.contacts.map((c) => Math.hypot(c[0] - lowest[0], c[1] - lowest[1]))), 'a contact at the lowest corner').to.be.below(0.01);
    h.host.setParams({ debug: false });
    expect(decode(h.frame).aabbs).to.deep.equal([]);
  });

  it('a rigid body\'s velocity, angular velocity and being kinematic change live, without a rebuild', () => {
    const h = makeHost();
    const box: BodyDescription = { type: 'box', x: 4, y: 2, width: 1, height: 1 };
    h.host.load({ world: {}, params: { gravity: { x: 0, y: 0 } }, bodies: [{ key: 1, desc: box }], links: [] });
    const topologies = h.topologies.length;
    const pose = () => decode(h.frame).poses[0];
    expect(h.host.updateBody({ key: 1, desc: { ...box, vx: 3, vy: -1, angularVelocity: 2 } })).to.equal(null);
    h.host.step(30);
    near(pose(), [4 + 1.5, 2 - 0.5, 1], 1e-9);
    // Kinematic: it keeps moving by its velocities; another box does not stop it.
    expect(h.host.updateBody({ key: 1, desc: { ...box, vx: 3, vy: -1, angularVelocity: 2, kinematic: true } })).to.equal(null);
    h.host.addBody({ key: 2, desc: { type: 'box', x: 7.5, y: 1, width: 1, height: 1, mass: 100 } });
    h.host.step(60);
    near(pose(), [5.5 + 3, 1.5 - 1, 3], 1e-6);
    // Back to dynamic, at rest: it stays put.
    expect(h.host.updateBody({ key: 1, desc: { ...box, vx: 0, vy: 0, angularVelocity: 0 } })).to.equal(null);
    const before = pose();
    h.host.step(30);
    near(pose(), before, 1e-9);
    // One new topology (the added box), no rebuild of the first: it is where it went, not where it was described.
    expect(h.topologies.length).to.equal(topologies + 1);
    // A static body is rebuilt instead (static and kinematic do not mix: the engine names the field).
    const error = h.host.updateBody({ key: 1, desc: { ...box, static: true, kinematic: true } });
    expect(error).to.include({ key: 1 });
    expect(error!.message).to.match(/static or kinematic/);
  });

  it('a body of particles takes its described velocity and angular velocity too', () => {
    const h = makeHost();
    h.host.load({
      world: {},
      params: { gravity: { x: 0, y: 0 } },
      bodies: [{ key: 1, desc: { type: 'box', model: 'particles', x: 4, y: 2, width: 1, height: 1, vx: 2, angularVelocity: 1 } }],
      links: [],
    });
    h.host.step(30);
    const [x, y, angle] = decode(h.frame).poses[0];
    expect(x).to.be.closeTo(5, 1e-3);
    expect(y).to.be.closeTo(2, 1e-3);
    expect(angle).to.be.closeTo(0.5, 0.02);
  });

  it('joints from descriptions hold: revolute, weld, prismatic, distance and spring, to bodies or the world', () => {
    const h = makeHost();
    const box = (x: number, y: number): BodyDescription => ({ type: 'box', x, y, width: 0.6, height: 0.4 });
    h.host.load({
      world: {},
      params: { gravity: { x: 0, y: 9.81 } },
      bodies: [
        { key: 1, desc: box(2, 3) },
        { key: 2, desc: box(7.5, 1) },
        { key: 3, desc: box(8.5, 1) },
        { key: 4, desc: box(12, 2) },
        { key: 5, desc: box(15, 4) },
        { key: 6, desc: { type: 'rope', from: { x: 18, y: 1 }, to: { x: 18, y: 3 }, segments: 8 } },
        { key: 7, desc: box(18, 3.5) },
      ],
      links: [
        // A pendulum: the box on a hinge to the world 2 above its centre.
        { key: 10, desc: { type: 'joint', joint: 'revolute', a: 1, x: 2, y: 1 } },
        // Two boxes welded together, hanging from the world by the first one's hinge.
        { key: 11, desc: { type: 'joint', joint: 'revolute', a: 2, x: 7, y: 1 } },
        { key: 12, desc: { type: 'joint', joint: 'weld', a: 2, b: 3, x: 8, y: 1 } },
        // A box on a vertical rail, stopped 1 below where it starts.
        { key: 13, desc: { type: 'joint', joint: 'prismatic', a: 4, axis: { x: 0, y: 1 }, lower: -1, upper: 1 } },
        // A box on a spring from the world point 2 above it: it settles where k·stretch = m·g.
        { key: 14, desc: { type: 'joint', joint: 'spring', a: 5, x1: 15, y1: 4, x2: 15, y2: 2, stiffness: 20, damping: 2 } },
        // A box tied to the end of a rope: the rope's particle nearest the anchor, at a fixed distance.
        { key: 15, desc: { type: 'joint', joint: 'distance', a: 7, b: 6, x1: 18, y1: 3.3, x2: 18, y2: 3 } },
      ],
    });
    const t = h.topology;
    const handles = h.host.snapshot().bodies;
    const pose = (key: number) => {
      const world = new World();
      world.restore(h.host.snapshot().world as WorldSnapshot);
      return world.bodyPose(handles.find((b) => b.key === key)!.handle);
    };
    // Local points of bodies: where (u, v) of body `key` is now.
    const at = (key: number, u: number, v: number) => {
      const p = pose(key);
      return [p.x + Math.cos(p.angle) * u - Math.sin(p.angle) * v, p.y + Math.sin(p.angle) * u + Math.cos(p.angle) * v];
    };
    const weldStart = [pose(3).x - pose(2).x, pose(3).y - pose(2).y];
    // Give the pendulum a push, so it swings.
    h.host.setVelocity(1, 4, 0);
    for (let k = 0; k < 120; k++) {
      h.host.step(1);
      const pivot = at(1, 0, -2);
      expect(Math.hypot(pivot[0] - 2, pivot[1] - 1), 'revolute').to.be.below(1e-3);
    }
    expect(Math.abs(pose(1).angle)).to.be.greaterThan(0.3);
    // The welded pair turned together, rigidly.
    expect(pose(3).angle).to.be.closeTo(pose(2).angle, 1e-3);
    expect(Math.abs(pose(2).angle)).to.be.greaterThan(0.3);
    const [c, s] = [Math.cos(pose(2).angle), Math.sin(pose(2).angle)];
    near([pose(3).x - pose(2).x, pose(3).y - pose(2).y], [c * weldStart[0] - s * weldStart[1], s * weldStart[0] + c * weldStart[1]], 1e-3);
    // The rail: straight down, not turned, stopped at its limit.
    near([pose(4).x, pose(4).y, pose(4).angle], [12, 3, 0], 1e-3);
    // The spring: k·stretch = m·g with m = 0.24 (density 1), rest length 2.
    h.host.step(600);
    expect(pose(5).y - 2).to.be.closeTo(2 + (0.24 * 9.81) / 20, 0.01);
    // The rope's end particle stays 0.3 from the box's top point.
    const ropeEnd = decode(h.frame).positions[t.bodies[5].indices[8]];
    const top = at(7, 0, -0.2);
    expect(Math.hypot(ropeEnd[0] - top[0], ropeEnd[1] - top[1])).to.be.closeTo(0.3, 1e-3);
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

  it('with transferred buffers all lent out, the skipped frame is written as soon as the page hands one back', () => {
    // The page holds the four buffers (markup edits published them) and has not handed any back yet.
    const posted: ArrayBuffer[] = [];
    const publisher = new TransferPublisher((buffer) => posted.push(buffer));
    const host = new EngineHost(publisher, { topology: () => {}, events: () => {} }, new FakeClock());
    host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(0, 2), links: [] });
    for (let k = 0; k < 3; k++) host.step(1);
    expect(posted.length).to.equal(4);
    host.step(10);
    expect(host.diagnostics()).to.include({ skipped: 1, stepCount: 13 });
    expect(decode(new Float64Array(posted.at(-1)!)).stepCount).to.equal(3);
    // A paused scene publishes nothing more by itself: the returned buffer carries the state after the ten steps.
    publisher.recycle(posted[0]);
    expect(posted.length).to.equal(5);
    expect(decode(new Float64Array(posted.at(-1)!)).stepCount).to.equal(13);
    // Only once: a buffer back with nothing skipped writes nothing.
    publisher.recycle(posted[1]);
    expect(posted.length).to.equal(5);
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

  it('diagnostics().stepMs: the time the loop\'s ticks spend per step, NaN before it stepped; step(n) is not counted', () => {
    const h = makeHost();
    h.host.load({ world: {}, bodies: clone(EVERY_TYPE).slice(0, 3), links: [] });
    h.host.step(5);
    expect(h.host.diagnostics().stepMs).to.be.NaN;
    // Each reading of the clock lets 3 ms pass: a tick reads it before and after its steps.
    h.clock.readCost = 3;
    h.host.play();
    h.clock.advance(500);
    const { stepMs, stepCount } = h.host.diagnostics();
    expect(stepCount).to.be.greaterThan(5 + 10);
    // 3 ms over the 1 or 2 steps of a tick.
    expect(stepMs).to.be.within(1.5, 3);
    h.host.pause();
    h.host.step(20);
    expect(h.host.diagnostics().stepMs).to.equal(stepMs);
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
