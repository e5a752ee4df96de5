// Binding the element layer's keys to engine objects: one record per described body and link, built into the world
// (or not, when its description is refused), rebuilt on edits, and the handle → key map that events, picking and
// grabs answer with.
import { World, buildBody, type BodyDescription, type Handle, type Vec2 } from '../../engine/index.js';
import { setRigidMaterial } from '../../engine/inspect.js';
import type { HostError, HostSnapshot, JointLink, KeyedBody, KeyedLink, LinkDescription, LinkEnd, TopologyLink } from '../protocol.js';
import { descriptorOf, type BodyDescriptor, type PoseBasis } from './bodies/index.js';
import { measurePose } from './bodies/pose.js';
import { rigidFacts, type RigidFacts } from './bodies/rigid.js';
import { errorOf } from './errors.js';
import type { HostSettings } from './settings.js';

export interface BodyRecord {
  key: number;
  desc: BodyDescription;
  /** Null while not built (refused description, or its world was replaced). */
  handle: Handle | null;
  /** What the host knows about its type (set when built). */
  descriptor: BodyDescriptor | null;
  /** Particle storage indices, as of the newest topology. */
  indices: Int32Array;
  /** Where a body built of particles has its pose. */
  basis: PoseBasis;
  /** Set when it is built as a rigid body (the engine's default model of boxes, polygons and circles). */
  rigid: RigidFacts | null;
}

export interface LinkRecord {
  key: number;
  desc: LinkDescription;
  handles: Handle[];
  /** Its ends as drawn (a rigid end's `body` is the body's key), null while not in force. */
  drawn: TopologyLink | null;
}

function bodyRecord(key: number, desc: BodyDescription): BodyRecord {
  return { key, desc, handle: null, descriptor: null, indices: new Int32Array(0), basis: [0, 0, 0, 0], rigid: null };
}

function linkRecord(key: number, desc: LinkDescription, handles: Handle[] = [], drawn: TopologyLink | null = null): LinkRecord {
  return { key, desc, handles, drawn };
}

/** Whether two descriptions differ only in the named fields. */
function sameExcept(a: object, b: object, ignore: string[]): boolean {
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  for (const k of keys) {
    if (ignore.includes(k)) continue;
    if (JSON.stringify((a as Record<string, unknown>)[k]) !== JSON.stringify((b as Record<string, unknown>)[k])) return false;
  }
  return true;
}

const STYLE = ['fill', 'stroke', 'id'];
const MATERIAL = [...STYLE, 'friction', 'restitution'];
/** What a rigid body that is not static takes without a rebuild: its velocities and its type. */
const MOTION = [...MATERIAL, 'vx', 'vy', 'angularVelocity', 'kinematic'];

type Motion = { friction?: number; restitution?: number; vx?: number; vy?: number; angularVelocity?: number; kinematic?: boolean; static?: boolean };

/** Joints whose ends are held together at one anchor (the rest join two anchors, or slide). */
const PIVOTS = new Set(['revolute', 'weld']);

/** One end of a link: what the engine joins (a rigid body, a particle, or the world when neither) and where. */
interface End {
  body?: Handle;
  particle?: Handle;
  at: Vec2;
  drawn: LinkEnd;
}

export class Bindings {
  /** The world everything is built in; load() and reset() replace it. */
  world: World;
  readonly bodies = new Map<number, BodyRecord>();
  readonly links = new Map<number, LinkRecord>();
  readonly #keys = new Map<Handle, number>();
  /** Handles of bodies removed or rebuilt since the last step, with their keys: that step's end events name them. */
  readonly #retired = new Map<Handle, number>();
  readonly #settings: HostSettings;
  readonly #changed: () => void;

  /** `changed` runs whenever what is built changes (the topology is stale). */
  constructor(settings: HostSettings, changed: () => void) {
    this.#settings = settings;
    this.#changed = changed;
    this.world = new World(settings.forWorld());
  }

  /** The key of the body with this handle, or -1. */
  keyOf(handle: Handle): number {
    return this.#keys.get(handle) ?? this.#retired.get(handle) ?? -1;
  }

  /** A step's events are read: the handles retired before it are named no more. */
  forgetRetired(): void {
    if (this.#retired.size > 0) this.#retired.clear();
  }

  /** Takes these descriptions instead of the current ones and builds them into a fresh world. */
  load(bodies: KeyedBody[], links: KeyedLink[]): HostError[] {
    this.bodies.clear();
    this.links.clear();
    for (const b of bodies) this.bodies.set(b.key, bodyRecord(b.key, b.desc));
    for (const l of links) this.links.set(l.key, linkRecord(l.key, l.desc));
    return this.rebuild();
  }

  /** A fresh world from the settings and the current descriptions (load and reset). */
  rebuild(): HostError[] {
    const errors: HostError[] = [];
    try {
      this.world = new World(this.#settings.forWorld());
    } catch (error) {
      errors.push(errorOf(-1, error));
      this.#settings.worldOptions = {};
      this.world = new World(this.#settings.forWorld());
    }
    this.#keys.clear();
    this.#retired.clear();
    for (const r of this.bodies.values()) {
      r.handle = null;
      const error = this.#build(r);
      if (error) errors.push(error);
    }
    for (const l of this.links.values()) {
      l.handles = [];
      const error = this.#link(l);
      if (error) errors.push(error);
    }
    // Events wanted: the new world tracks its pairs from its first step (its first read would take the pairs touching
    // then as already touching, and a pair a reset put in contact would never begin).
    if (this.#settings.params.events) void this.world.events;
    this.#changed();
    return errors;
  }

  addBody(body: KeyedBody): HostError | null {
    if (this.bodies.has(body.key)) return this.updateBody(body);
    const record = bodyRecord(body.key, body.desc);
    this.bodies.set(body.key, record);
    const error = this.#build(record);
    this.#relink(body.key);
    this.#changed();
    return error;
  }

  /**
   * A new description: a change of style costs nothing, of material a collider update, of a rigid body's velocities
   * or of its being kinematic a call on the body; of anything else a rebuild.
   */
  updateBody(body: KeyedBody): HostError | null {
    const record = this.bodies.get(body.key);
    if (!record) return this.addBody(body);
    const before = record.desc as Motion;
    const after = body.desc as Motion;
    record.desc = body.desc;
    if (record.handle !== null && sameExcept(before, after, record.rigid && !after.static ? MOTION : MATERIAL)) {
      try {
        this.#changeLive(record, before, after);
        return null;
      } catch (error) {
        return errorOf(body.key, error);
      }
    }
    this.#unbuild(record);
    const error = this.#build(record);
    this.#relink(body.key);
    this.#changed();
    return error;
  }

  /** Applies what changed of material and (rigid bodies) motion to the built body. */
  #changeLive(r: BodyRecord, before: Motion, after: Motion): void {
    const w = this.world;
    const h = r.handle!;
    if (before.friction !== after.friction || before.restitution !== after.restitution) {
      const friction = after.friction ?? 0.6;
      const restitution = after.restitution ?? 0;
      if (r.rigid) setRigidMaterial(w, h, friction, restitution);
      else w.setCollider(h, { friction, restitution });
      w.wake(h);
    }
    if (Boolean(before.kinematic) !== Boolean(after.kinematic)) w.setBodyType(h, after.kinematic ? 'kinematic' : 'dynamic');
    if (before.vx !== after.vx || before.vy !== after.vy) w.setBodyVelocity(h, after.vx ?? 0, after.vy ?? 0);
    if (before.angularVelocity !== after.angularVelocity) w.setBodyAngularVelocity(h, after.angularVelocity ?? 0);
  }

  removeBody(key: number): void {
    const record = this.bodies.get(key);
    if (!record) return;
    this.#unbuild(record);
    this.bodies.delete(key);
    this.#relink(key);
    this.#changed();
  }

  /** Adds the link, or replaces the one with its key. */
  addLink(link: KeyedLink): HostError | null {
    const old = this.links.get(link.key);
    if (old) this.#unlink(old);
    const record = linkRecord(link.key, link.desc);
    this.links.set(link.key, record);
    const error = this.#link(record);
    this.#changed();
    return error;
  }

  removeLink(key: number): void {
    const record = this.links.get(key);
    if (!record) return;
    this.#unlink(record);
    this.links.delete(key);
    this.#changed();
  }

  /** The built bodies in key order of arrival, their particle indices refreshed (the topology's order). */
  built(): BodyRecord[] {
    const out: BodyRecord[] = [];
    for (const r of this.bodies.values()) {
      if (r.handle === null) continue;
      r.indices = this.world.bodyParticleIndices(r.handle);
      out.push(r);
    }
    return out;
  }

  /** Links in force (both ends built). */
  activeLinks(): LinkRecord[] {
    return [...this.links.values()].filter((l) => l.drawn !== null);
  }

  /** The records as plain data (the world is snapshotted on its own). */
  snapshot(): Pick<HostSnapshot, 'bodies' | 'links'> {
    return {
      bodies: [...this.bodies.values()].map((r) => ({ key: r.key, desc: r.desc, handle: r.handle ?? -1, pose: r.basis.slice() })),
      links: [...this.links.values()].map((l) => ({ key: l.key, desc: l.desc, handles: l.handles.slice(), drawn: l.drawn })),
    };
  }

  /** Records from a snapshot, bound to the handles of the world restored from it. */
  restore(s: Pick<HostSnapshot, 'bodies' | 'links'>): void {
    this.bodies.clear();
    this.links.clear();
    this.#keys.clear();
    this.#retired.clear();
    for (const b of s.bodies) {
      const r = bodyRecord(b.key, b.desc);
      if (b.handle >= 0 && this.world.hasBody(b.handle)) {
        r.handle = b.handle;
        r.descriptor = descriptorOf(b.desc.type)!;
        r.basis = b.pose.slice() as PoseBasis;
        r.rigid = rigidFacts(this.world, b.handle, b.desc, r.descriptor);
        this.#keys.set(b.handle, b.key);
      }
      this.bodies.set(b.key, r);
    }
    for (const l of s.links) this.links.set(l.key, linkRecord(l.key, l.desc, l.handles.slice(), l.drawn));
    this.#changed();
  }

  /** Of the particles `idx`, the one nearest to (x, y). */
  nearest(idx: Int32Array, x: number, y: number): number {
    const p = this.world.particles;
    let best = idx[0];
    let bestD = Infinity;
    for (const i of idx) {
      const d = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
      if (d < bestD) [best, bestD] = [i, d];
    }
    return best;
  }

  #build(r: BodyRecord): HostError | null {
    try {
      const built = buildBody(this.world, r.desc);
      const descriptor = descriptorOf(r.desc.type)!;
      r.handle = built.body;
      r.descriptor = descriptor;
      this.#keys.set(built.body, r.key);
      r.rigid = rigidFacts(this.world, built.body, r.desc, descriptor);
      const idx = this.world.bodyParticleIndices(built.body);
      const { x, y } = this.world.particles;
      r.basis = measurePose(descriptor.pose, r.desc, idx, x, y);
      return null;
    } catch (error) {
      r.handle = null;
      r.rigid = null;
      return errorOf(r.key, error);
    }
  }

  #unbuild(r: BodyRecord): void {
    if (r.handle !== null && this.world.hasBody(r.handle)) this.world.removeBody(r.handle);
    if (r.handle !== null) {
      // The engine ends the body's touching pairs in the next step's events, under this handle.
      this.#retired.set(r.handle, r.key);
      this.#keys.delete(r.handle);
    }
    r.handle = null;
  }

  /** Re-creates the links that touch a body (after it was rebuilt, added or removed). */
  #relink(bodyKey: number): void {
    for (const l of this.links.values()) {
      if (l.desc.a !== bodyKey && (l.desc.type === 'pin' || l.desc.b !== bodyKey)) continue;
      this.#unlink(l);
      this.#link(l);
    }
  }

  #unlink(l: LinkRecord): void {
    for (const h of l.handles) if (this.world.hasConstraint(h)) this.world.removeConstraint(h);
    l.handles = [];
    l.drawn = null;
  }

  /** Makes the link in the world once the bodies it names are built (a joint without `b` holds to the world). */
  #link(l: LinkRecord): HostError | null {
    const d = l.desc;
    const a = this.bodies.get(d.a);
    if (!a || a.handle === null) return null;
    const b = d.type === 'pin' || d.b === undefined ? null : this.bodies.get(d.b);
    if (b === undefined || b?.handle === null) return null;
    try {
      if (d.type === 'pin') this.#pin(l, d, a);
      else if (d.type === 'spring' && !a.rigid && !b!.rigid) this.#particleSpring(l, d, a, b!);
      else this.#joint(l, d.type === 'spring' ? { ...d, type: 'joint', joint: 'spring' } : d, a, b);
      return null;
    } catch (error) {
      this.#unlink(l);
      return errorOf(l.key, error);
    }
  }

  /** A pin: a rigid body by a revolute joint to the world at the point; otherwise its particle held there. */
  #pin(l: LinkRecord, d: Extract<LinkDescription, { type: 'pin' }>, a: BodyRecord): void {
    const w = this.world;
    const at = { x: d.x, y: d.y };
    const world: LinkEnd = { body: -1, particle: -1, x: d.x, y: d.y };
    if (a.rigid && d.particle === undefined) {
      l.handles = [w.addJoint({ type: 'revolute', a: a.handle!, anchor: at, compliance: d.compliance })];
      l.drawn = { a: this.#end(a, at, at).drawn, b: world, pivot: true };
      return;
    }
    const idx = w.bodyParticleIndices(a.handle!);
    // A rigid body has one row (its centre: particle 0); a body of particles is pinned by the one named.
    if ((d.particle ?? 0) >= idx.length) throw new RangeError(`particle must be less than the body's particle count (${idx.length}), got ${d.particle}`);
    const i = a.rigid ? idx[0] : d.particle !== undefined ? idx[d.particle] : this.nearest(idx, d.x, d.y);
    try {
      l.handles = [w.addPin(w.particleHandle(i), { x: d.x, y: d.y, compliance: d.compliance })];
    } catch (error) {
      // The engine names its own particle index; the page knows the body's, and which attribute chose it.
      if (!(error instanceof RangeError && error.message.includes('already rigidly pinned'))) throw error;
      const chosen = d.particle !== undefined ? `got ${d.particle}` : `x, y pick the nearest, particle ${idx.indexOf(i)}`;
      throw new RangeError(`${d.particle !== undefined ? 'particle' : 'x'} must choose a particle that is not rigidly pinned already (by another pin or the body's own pins), ${chosen}`);
    }
    l.drawn = { a: { body: -1, particle: i, x: 0, y: 0 }, b: world, pivot: true };
  }

  /** <physics-spring> between bodies of particles: an explicit Hooke force between their particles. */
  #particleSpring(l: LinkRecord, d: Extract<LinkDescription, { type: 'spring' }>, a: BodyRecord, b: BodyRecord): void {
    const [A, B] = this.#ends(d, a, b, false);
    l.handles = [this.world.addSpring(A.particle!, B.particle!, { stiffness: d.stiffness, damping: d.damping, length: d.length })];
    l.drawn = { a: A.drawn, b: B.drawn, pivot: false };
  }

  /**
   * An engine joint (World.addJoint) between the ends. A distance limited on one side only is free on the other (at
   * least `lower`; at most `upper`, a rope); a spring of stiffness 0 pulls with no force (drawn, nothing made).
   */
  #joint(l: LinkRecord, d: JointLink, a: BodyRecord, b: BodyRecord | null): void {
    const type = d.joint ?? 'distance';
    const single = type === 'revolute' || type === 'weld' || type === 'prismatic';
    const [A, B, anchor] = this.#ends(d, a, b, single);
    const together = A.at.x === B.at.x && A.at.y === B.at.y;
    l.drawn = { a: A.drawn, b: B.drawn, pivot: PIVOTS.has(type) || (type === 'distance' && together) };
    if (type === 'spring' && d.stiffness === 0) return;
    const limited = type === 'distance' || type === 'prismatic';
    const oneSided = type === 'distance' && (d.lower === undefined) !== (d.upper === undefined);
    l.handles = [
      this.world.addJoint({
        type,
        a: A.body,
        particleA: A.particle,
        b: B.body ?? null,
        particleB: B.particle,
        anchor: single ? anchor : undefined,
        anchorA: single ? undefined : A.at,
        anchorB: single ? undefined : B.at,
        axis: d.axis,
        lowerAngle: d.lowerAngle,
        upperAngle: d.upperAngle,
        motorSpeed: d.motorSpeed,
        maxMotorTorque: d.maxMotorTorque,
        lower: !limited ? undefined : oneSided ? (d.lower ?? 0) : d.lower,
        upper: !limited ? undefined : oneSided ? (d.upper ?? Infinity) : d.upper,
        length: d.length,
        stiffness: d.stiffness,
        damping: d.damping,
        compliance: d.compliance,
        collideConnected: d.collideConnected,
      }),
    ];
  }

  /**
   * Where a link's ends are, and the one anchor of a joint that has one (`single`: revolute, weld, prismatic). With
   * anchors (x, y for both ends; x1, y1 and x2, y2 for each), a rigid body at the anchor itself, a body of particles at
   * its particle nearest to it, the world at the anchor. Without, a rigid body at its centre of mass and a body of
   * particles at its particle nearest to the other end (the two bodies' nearest particles), the world where a's end
   * is; a single anchor is then where a's end is.
   */
  #ends(d: JointLink | Extract<LinkDescription, { type: 'spring' }>, a: BodyRecord, b: BodyRecord | null, single: boolean): [End, End, Vec2] {
    const anchor = d.x !== undefined && d.y !== undefined ? { x: d.x, y: d.y } : null;
    const j = d as JointLink;
    const first = j.x1 !== undefined && j.y1 !== undefined ? { x: j.x1, y: j.y1 } : anchor;
    const second = j.x2 !== undefined && j.y2 !== undefined ? { x: j.x2, y: j.y2 } : anchor;
    const A = this.#end(a, single ? anchor : first, this.world.bodyCentroid((b ?? a).handle!));
    const at = single ? (anchor ?? A.at) : A.at;
    const B = this.#end(b, single ? at : second, A.at);
    return [A, B, at];
  }

  /** The end on body r (null: the world) at `anchor`, or without one toward the point `toward`. */
  #end(r: BodyRecord | null, anchor: Vec2 | null, toward: Vec2): End {
    const w = this.world;
    const p = w.particles;
    if (!r) {
      const at = anchor ?? toward;
      return { at, drawn: { body: -1, particle: -1, x: at.x, y: at.y } };
    }
    const idx = w.bodyParticleIndices(r.handle!);
    if (r.rigid) {
      const i = idx[0];
      const at = anchor ?? { x: p.x[i], y: p.y[i] };
      // The anchor in the body's frame: about its centre of mass, turned back by its angle.
      const c = Math.cos(p.angle[i]);
      const s = Math.sin(p.angle[i]);
      const dx = at.x - p.x[i];
      const dy = at.y - p.y[i];
      return { body: r.handle!, at, drawn: { body: r.key, particle: -1, x: c * dx + s * dy, y: -s * dx + c * dy } };
    }
    const near = anchor ?? toward;
    const i = this.nearest(idx, near.x, near.y);
    return { particle: w.particleHandle(i), at: { x: p.x[i], y: p.y[i] }, drawn: { body: -1, particle: i, x: 0, y: 0 } };
  }
}
