// Binding the element layer's keys to engine objects: one record per described body and link, built into the world
// (or not, when its description is refused), rebuilt on edits, and the handle → key map that events, picking and
// grabs answer with.
import { World, buildBody, type BodyDescription, type Handle } from '../../engine/index.js';
import type { HostError, HostSnapshot, KeyedBody, KeyedLink, LinkDescription } from '../protocol.js';
import { descriptorOf, type BodyDescriptor, type PoseBasis } from './bodies/index.js';
import { measurePose } from './bodies/pose.js';
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
  basis: PoseBasis;
}

export interface LinkRecord {
  key: number;
  desc: LinkDescription;
  handles: Handle[];
  /** Particle storage indices of the two ends (for drawing), -1 when inactive. */
  pa: number;
  pb: number;
}

function bodyRecord(key: number, desc: BodyDescription): BodyRecord {
  return { key, desc, handle: null, descriptor: null, indices: new Int32Array(0), basis: [0, 0, 0, 0] };
}

function linkRecord(key: number, desc: LinkDescription, handles: Handle[] = [], pa = -1, pb = -1): LinkRecord {
  return { key, desc, handles, pa, pb };
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

export class Bindings {
  /** The world everything is built in; load() and reset() replace it. */
  world: World;
  readonly bodies = new Map<number, BodyRecord>();
  readonly links = new Map<number, LinkRecord>();
  readonly #keys = new Map<Handle, number>();
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
    return this.#keys.get(handle) ?? -1;
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

  /** A new description: a change of style costs nothing, of material a collider update, of anything else a rebuild. */
  updateBody(body: KeyedBody): HostError | null {
    const record = this.bodies.get(body.key);
    if (!record) return this.addBody(body);
    const before = record.desc as { friction?: number; restitution?: number };
    const after = body.desc as { friction?: number; restitution?: number };
    record.desc = body.desc;
    if (record.handle !== null && sameExcept(before, after, MATERIAL) && (before.friction !== after.friction || before.restitution !== after.restitution)) {
      try {
        this.world.setCollider(record.handle, { friction: after.friction ?? 0.6, restitution: after.restitution ?? 0 });
        this.world.wake(record.handle);
        return null;
      } catch (error) {
        return errorOf(body.key, error);
      }
    }
    if (record.handle !== null && sameExcept(before, after, STYLE)) return null;
    this.#unbuild(record);
    const error = this.#build(record);
    this.#relink(body.key);
    this.#changed();
    return error;
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
    return [...this.links.values()].filter((l) => l.pa >= 0);
  }

  /** The records as plain data (the world is snapshotted on its own). */
  snapshot(): Pick<HostSnapshot, 'bodies' | 'links'> {
    return {
      bodies: [...this.bodies.values()].map((r) => ({ key: r.key, desc: r.desc, handle: r.handle ?? -1, pose: r.basis.slice() })),
      links: [...this.links.values()].map((l) => ({ key: l.key, desc: l.desc, handles: l.handles.slice(), pa: l.pa, pb: l.pb })),
    };
  }

  /** Records from a snapshot, bound to the handles of the world restored from it. */
  restore(s: Pick<HostSnapshot, 'bodies' | 'links'>): void {
    this.bodies.clear();
    this.links.clear();
    this.#keys.clear();
    for (const b of s.bodies) {
      const r = bodyRecord(b.key, b.desc);
      if (b.handle >= 0 && this.world.hasBody(b.handle)) {
        r.handle = b.handle;
        r.descriptor = descriptorOf(b.desc.type)!;
        r.basis = b.pose.slice() as PoseBasis;
        this.#keys.set(b.handle, b.key);
      }
      this.bodies.set(b.key, r);
    }
    for (const l of s.links) this.links.set(l.key, linkRecord(l.key, l.desc, l.handles.slice(), l.pa, l.pb));
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
      const descriptor = descriptorOf(r.desc?.type);
      const model = descriptor?.model;
      const built = buildBody(this.world, model ? ({ model, ...r.desc } as BodyDescription) : r.desc);
      r.handle = built.body;
      r.descriptor = descriptor!;
      this.#keys.set(built.body, r.key);
      const { x, y } = this.world.particles;
      r.basis = measurePose(r.descriptor.pose, r.desc, this.world.bodyParticleIndices(built.body), x, y);
      return null;
    } catch (error) {
      r.handle = null;
      return errorOf(r.key, error);
    }
  }

  #unbuild(r: BodyRecord): void {
    if (r.handle !== null && this.world.hasBody(r.handle)) this.world.removeBody(r.handle);
    if (r.handle !== null) this.#keys.delete(r.handle);
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
    l.pa = l.pb = -1;
  }

  /** Joins the link's ends (when both bodies are built): each at its body's particle nearest the anchor. */
  #link(l: LinkRecord): HostError | null {
    const d = l.desc;
    const a = this.bodies.get(d.a);
    if (!a || a.handle === null) return null;
    try {
      const w = this.world;
      if (d.type === 'pin') {
        const idx = w.bodyParticleIndices(a.handle);
        const i = d.particle !== undefined ? idx[Math.max(0, Math.min(idx.length - 1, d.particle))] : this.nearest(idx, d.x, d.y);
        l.handles = [w.addPin(w.particleHandle(i), { x: d.x, y: d.y, compliance: d.compliance })];
        l.pa = l.pb = i;
        return null;
      }
      const b = this.bodies.get(d.b);
      if (!b || b.handle === null) return null;
      const ia = w.bodyParticleIndices(a.handle);
      const ib = w.bodyParticleIndices(b.handle);
      let pa: number;
      let pb: number;
      if (d.x !== undefined && d.y !== undefined) {
        pa = this.nearest(ia, d.x, d.y);
        pb = this.nearest(ib, d.x, d.y);
      } else {
        const cb = w.bodyCentroid(b.handle);
        pa = this.nearest(ia, cb.x, cb.y);
        pb = this.nearest(ib, w.particles.x[pa], w.particles.y[pa]);
      }
      const ha = w.particleHandle(pa);
      const hb = w.particleHandle(pb);
      l.handles = [
        d.type === 'joint'
          ? w.addDistance(ha, hb, { length: d.length, compliance: d.compliance })
          : w.addSpring(ha, hb, { stiffness: d.stiffness, damping: d.damping, length: d.length }),
      ];
      l.pa = pa;
      l.pb = pb;
      return null;
    } catch (error) {
      l.handles = [];
      return errorOf(l.key, error);
    }
  }
}
