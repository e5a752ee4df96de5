// The engine host: owns one World, builds it from keyed plain-data descriptions, applies live edits, runs its own
// fixed-step loop and publishes each new state as one frame. The same class runs inside the worker (behind comlink)
// and on the main thread (worker="none" or no Worker available), so both modes share every line of simulation code.
import { World, buildBody, type BodyDescription, type Handle, type WorldOptions } from '../engine/index.js';
import { handleSlot } from '../engine/handles.js';
import {
  EVENT, F, HEADER, MAX_CONTACTS, frameLength,
  type DebugFault, type Diagnostics, type EngineApi, type FramePatch, type HostError, type HostParams, type HostScene, type HostSnapshot, type KeyedBody,
  type KeyedLink, type LinkDescription, type Topology, type TopologyBody,
} from './protocol.js';
import type { Publisher } from './publishers.js';

export interface HostOutput {
  topology(topology: Topology): void;
  events(data: Float64Array, count: number): void;
}

interface BodyRecord {
  key: number;
  desc: BodyDescription;
  handle: Handle | null;
  indices: Int32Array;
  /** Pose bookkeeping: first edge's angle at build, offset from the particles' mean to the described origin. */
  edge0: number;
  dx: number;
  dy: number;
  angle0: number;
}

interface LinkRecord {
  key: number;
  desc: LinkDescription;
  handles: Handle[];
  /** Particle storage indices of the two ends (for drawing), -1 when inactive. */
  pa: number;
  pb: number;
}

const DEFAULT_PARAMS: HostParams = {
  gravity: { x: 0, y: 9.81 },
  timestep: 1 / 60,
  substeps: 10,
  iterations: 1,
  broadphase: 'grid',
  narrowphase: 'sat',
  debug: false,
  events: false,
  bounds: null,
};

/** "radius must be > 0, got -1" → "radius". */
function fieldOf(message: string): string {
  const m = /^([A-Za-z][\w.]*?)(?:\[\d+\])?(?:\.[xy])? must/.exec(message);
  return m ? m[1] : '';
}

function errorOf(key: number, error: unknown): HostError {
  const message = error instanceof Error ? error.message : String(error);
  return { key, field: fieldOf(message), message };
}

export function runningInWorker(): boolean {
  const scope = (globalThis as { WorkerGlobalScope?: { new (): unknown } }).WorkerGlobalScope;
  return typeof scope === 'function' && globalThis instanceof scope;
}

export class EngineHost implements EngineApi {
  private world: World;
  private worldOptions: WorldOptions = {};
  private params: HostParams = { ...DEFAULT_PARAMS, gravity: { ...DEFAULT_PARAMS.gravity } };
  private readonly bodies = new Map<number, BodyRecord>();
  private readonly links = new Map<number, LinkRecord>();
  private readonly keyOfHandle = new Map<Handle, number>();
  /** Bodies in topology order (the order of poses in a frame). */
  private order: BodyRecord[] = [];
  private topologyVersion = 0;
  private topologyDirty = true;
  private running = false;
  private timer: ReturnType<typeof setTimeout> | null = null;
  private lastTick = 0;
  private accumulator = 0;
  private seq = 0;
  private published = 0;
  private skipped = 0;
  private eventData = new Float64Array(EVENT * 64);
  private eventCount = 0;
  private eventsSent = 0;
  private disposed = false;
  /** A test fault armed for the next tick of the step loop. */
  private fault: DebugFault | null = null;

  constructor(
    private readonly publisher: Publisher,
    private readonly output: HostOutput,
  ) {
    this.world = new World(this.optionsForWorld());
  }

  // ---- scene -------------------------------------------------------------------------------------------------

  load(scene: HostScene): HostError[] {
    this.worldOptions = { ...(scene.world ?? {}) };
    const errors = this.applyParams(scene.params ?? {});
    this.bodies.clear();
    this.links.clear();
    for (const b of scene.bodies) this.bodies.set(b.key, this.emptyRecord(b.key, b.desc));
    for (const l of scene.links) this.links.set(l.key, { key: l.key, desc: l.desc, handles: [], pa: -1, pb: -1 });
    errors.push(...this.rebuild());
    if (scene.running) this.play();
    else this.publish();
    return errors;
  }

  addBody(body: KeyedBody): HostError | null {
    if (this.bodies.has(body.key)) return this.updateBody(body);
    const record = this.emptyRecord(body.key, body.desc);
    this.bodies.set(body.key, record);
    const error = this.build(record);
    this.relink(body.key);
    this.changed();
    return error;
  }

  updateBody(body: KeyedBody): HostError | null {
    const record = this.bodies.get(body.key);
    if (!record) return this.addBody(body);
    const before = record.desc;
    record.desc = body.desc;
    if (record.handle !== null && this.onlyMaterialChanged(before, body.desc)) {
      try {
        const d = body.desc as { friction?: number; restitution?: number };
        this.world.setCollider(record.handle, { friction: d.friction ?? 0.6, restitution: d.restitution ?? 0 });
        this.world.wake(record.handle);
        return null;
      } catch (error) {
        return errorOf(body.key, error);
      }
    }
    if (record.handle !== null && this.onlyStyleChanged(before, body.desc)) return null;
    this.unbuild(record);
    const error = this.build(record);
    this.relink(body.key);
    this.changed();
    return error;
  }

  removeBody(key: number): void {
    const record = this.bodies.get(key);
    if (!record) return;
    this.unbuild(record);
    this.bodies.delete(key);
    this.relink(key);
    this.changed();
  }

  addLink(link: KeyedLink): HostError | null {
    const old = this.links.get(link.key);
    if (old) this.unlink(old);
    const record: LinkRecord = { key: link.key, desc: link.desc, handles: [], pa: -1, pb: -1 };
    this.links.set(link.key, record);
    const error = this.link(record);
    this.changed();
    return error;
  }

  updateLink(link: KeyedLink): HostError | null {
    return this.addLink(link);
  }

  removeLink(key: number): void {
    const record = this.links.get(key);
    if (!record) return;
    this.unlink(record);
    this.links.delete(key);
    this.changed();
  }

  setParams(params: Partial<HostParams>): HostError | null {
    const errors = this.applyParams(params);
    this.publish();
    return errors[0] ?? null;
  }

  // ---- time --------------------------------------------------------------------------------------------------

  play(): void {
    if (this.running || this.disposed) return;
    this.running = true;
    this.lastTick = performance.now();
    this.accumulator = 0;
    this.schedule(0);
    this.publish();
  }

  pause(): void {
    this.running = false;
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = null;
    this.publish();
  }

  step(n = 1): number {
    const count = Math.max(0, Math.min(100000, Math.floor(Number(n) || 0)));
    for (let k = 0; k < count; k++) this.stepOnce();
    this.flushEvents();
    this.publish();
    return this.world.stepCount;
  }

  reset(): void {
    this.rebuild();
    this.accumulator = 0;
    this.publish();
  }

  private schedule(ms: number): void {
    if (this.timer !== null) clearTimeout(this.timer);
    this.timer = setTimeout(this.tick, Math.max(0, ms));
  }

  /** The fixed-step loop: as many steps as real time allows (at most 5), then one published frame. */
  private readonly tick = (): void => {
    this.timer = null;
    if (!this.running || this.disposed) return;
    if (this.fault === 'throw') {
      // Uncaught on purpose: the loop stops here and the page sees the worker's error event.
      this.fault = null;
      throw new Error('debug fault: the step loop threw');
    }
    const now = performance.now();
    const elapsed = Math.min(0.25, (now - this.lastTick) / 1000);
    this.lastTick = now;
    const dt = this.world.timestep;
    this.accumulator += elapsed;
    let taken = 0;
    while (this.accumulator >= dt && taken < 5) {
      this.stepOnce();
      this.accumulator -= dt;
      taken++;
    }
    if (this.accumulator >= dt) this.accumulator %= dt;
    if (taken > 0) {
      this.flushEvents();
      this.publish();
    }
    this.schedule((dt - this.accumulator) * 1000);
  };

  private stepOnce(): void {
    this.world.step();
    if (this.params.events) this.collectEvents();
    // A torn cloth is drawn without its broken links: the topology says which.
    if (this.world.breaks.count > 0) this.topologyDirty = true;
  }

  // ---- interaction -------------------------------------------------------------------------------------------

  /**
   * Grabs what is under the point. Rigid shapes are held softly at the point (the engine scales the pull by the
   * body's mass). Particles of cloth, ropes, ragdolls, soft rings and balls are held firmly: a soft pull on one light
   * particle loses to the rigid links of the rest of its body (the engine caps the drag speed, so nothing is flung).
   * A press inside a soft ring takes its nearest ring particle.
   */
  grab(x: number, y: number, stiffness?: number): number | null {
    try {
      const w = this.world;
      const rigid = w.bodiesAtPoint(x, y).some((h) => {
        const type = this.bodies.get(this.keyOfHandle.get(h) ?? -1)?.desc.type;
        return type === 'box' || type === 'polygon';
      });
      if (rigid) return w.grab(x, y, stiffness === undefined ? {} : { stiffness });
      const firm = { stiffness: stiffness ?? PARTICLE_GRAB_STIFFNESS };
      const g = w.grab(x, y, firm);
      if (g !== null) return g;
      const { x: px, y: py } = w.particles;
      for (const r of this.order) {
        if (r.desc.type !== 'softbody' || r.handle === null) continue;
        const ring = r.desc.model === 'springs' ? r.indices.subarray(0, r.indices.length - 1) : r.indices;
        if (!insideLoop(ring, px, py, x, y)) continue;
        const i = this.nearest(ring, x, y);
        const held = w.grab(px[i], py[i], firm);
        if (held !== null) {
          w.moveGrab(held, x, y);
          return held;
        }
      }
      return null;
    } catch {
      return null;
    }
  }

  moveGrab(grab: number, x: number, y: number): void {
    if (this.world.hasConstraint(grab)) this.world.moveGrab(grab, x, y);
  }

  release(grab: number): void {
    if (this.world.hasConstraint(grab)) this.world.release(grab);
  }

  applyImpulse(key: number, ix: number, iy: number): void {
    const r = this.bodies.get(key);
    if (!r || r.handle === null) return;
    this.world.wake(r.handle);
    this.world.applyBodyImpulse(r.handle, ix, iy);
  }

  setVelocity(key: number, vx: number, vy: number): void {
    const r = this.bodies.get(key);
    if (!r || r.handle === null) return;
    for (const h of this.world.bodyParticleHandles(r.handle)) this.world.setVelocity(h, vx, vy);
  }

  bodiesAt(x: number, y: number): number[] {
    return this.world.bodiesAtPoint(x, y).map((h) => this.keyOfHandle.get(h) ?? -1);
  }

  // ---- state -------------------------------------------------------------------------------------------------

  snapshot(): HostSnapshot {
    return {
      world: this.world.snapshot(),
      bodies: [...this.bodies.values()].map((r) => ({ key: r.key, desc: r.desc, handle: r.handle ?? -1, pose: [r.edge0, r.dx, r.dy, r.angle0] })),
      links: [...this.links.values()].map((l) => ({ key: l.key, desc: l.desc, handles: l.handles.slice(), pa: l.pa, pb: l.pb })),
      params: { ...this.params, gravity: { ...this.params.gravity } },
      topology: this.topologyDirty ? -1 : this.topologyVersion,
    };
  }

  restore(s: HostSnapshot, frame?: FramePatch | null): number {
    this.params = { ...s.params, gravity: { ...s.params.gravity } };
    this.world.restore(s.world as Parameters<World['restore']>[0]);
    this.bodies.clear();
    this.links.clear();
    for (const b of s.bodies) {
      const r = this.emptyRecord(b.key, b.desc);
      if (b.handle >= 0 && this.world.hasBody(b.handle)) {
        r.handle = b.handle;
        [r.edge0, r.dx, r.dy, r.angle0] = b.pose;
      }
      this.bodies.set(b.key, r);
    }
    for (const l of s.links) {
      this.links.set(l.key, { key: l.key, desc: l.desc, handles: l.handles.slice(), pa: l.pa, pb: l.pb });
    }
    if (frame) this.overlay(s, frame);
    this.changed();
    return this.world.stepCount;
  }

  /**
   * After a worker restart: the snapshot holds the full state (constraints, contacts, sleep) as of up to a second
   * ago; the page's newest frame holds where every particle was drawn last. Moving the particles there (velocities
   * from the two newest frames, else the snapshot's) resumes from what the user saw instead of jumping back. Only
   * when the frame has the snapshot's topology (same particles in the same slots) and is not older than it.
   */
  private overlay(s: HostSnapshot, f: FramePatch): void {
    const w = this.world;
    const p = w.particles;
    const n = p.count;
    if (s.topology === undefined || s.topology < 0 || f.topology !== s.topology || f.positions.length !== 2 * n) return;
    if (f.stepCount < w.stepCount || (f.velocities && f.velocities.length !== 2 * n)) return;
    for (let i = 0; i < n; i++) {
      if (!p.alive[i] || p.invMass[i] === 0) continue;
      const x = f.positions[2 * i];
      const y = f.positions[2 * i + 1];
      if (!Number.isFinite(x) || !Number.isFinite(y)) continue;
      p.x[i] = p.px[i] = p.qx[i] = p.sx[i] = x;
      p.y[i] = p.py[i] = p.qy[i] = p.sy[i] = y;
      if (f.velocities && Number.isFinite(f.velocities[2 * i]) && Number.isFinite(f.velocities[2 * i + 1])) {
        p.vx[i] = f.velocities[2 * i];
        p.vy[i] = f.velocities[2 * i + 1];
      }
    }
    w.stepCount = f.stepCount;
    w.time = f.time;
    // Bodies asleep in the snapshot may have been moving in the frame.
    w.wakeAll();
  }

  /** @internal Test hook: 'throw' arms the step loop to throw on its next tick; 'hang' blocks this thread (20 s at most). */
  debugFault(fault: DebugFault): void {
    if (fault === 'throw') this.fault = 'throw';
    else if (fault === 'hang') {
      // After this call has answered: the next call gets no answer.
      setTimeout(() => {
        const until = performance.now() + 20000;
        while (performance.now() < until) {
          // busy: nothing else runs in this worker meanwhile
        }
      }, 0);
    }
  }

  stateHash(): string {
    return this.world.stateHash();
  }

  diagnostics(): Diagnostics {
    return {
      inWorker: runningInWorker(),
      transport: this.publisher.transport,
      crossOriginIsolated: Boolean((globalThis as { crossOriginIsolated?: boolean }).crossOriginIsolated),
      running: this.running,
      stepCount: this.world.stepCount,
      particleCount: this.world.particleCount,
      bodyCount: this.order.length,
      linkCount: [...this.links.values()].filter((l) => l.handles.length > 0).length,
      brokenLinks: this.world.brokenLinkCount,
      published: this.published,
      skipped: this.skipped,
      buffersAllocated: this.publisher.allocated,
      events: this.params.events,
      eventsSent: this.eventsSent,
    };
  }

  dispose(): void {
    this.disposed = true;
    this.pause();
    this.publisher.dispose();
  }

  // ---- building ----------------------------------------------------------------------------------------------

  private optionsForWorld(): WorldOptions {
    const p = this.params;
    return {
      ...this.worldOptions,
      gravity: { ...p.gravity },
      timestep: p.timestep,
      substeps: p.substeps,
      iterations: p.iterations,
      broadphase: p.broadphase,
      narrowphase: p.narrowphase,
    };
  }

  /** Applies what validates; returns one error per rejected field. */
  private applyParams(params: Partial<HostParams>): HostError[] {
    const errors: HostError[] = [];
    const w = this.world;
    const set = (field: keyof HostParams, apply: () => void) => {
      if (params[field] === undefined) return;
      try {
        apply();
      } catch (error) {
        errors.push({ key: -1, field, message: error instanceof Error ? error.message : String(error) });
      }
    };
    set('gravity', () => {
      w.setGravity(params.gravity!.x, params.gravity!.y);
      this.params.gravity = { x: params.gravity!.x, y: params.gravity!.y };
    });
    set('bounds', () => {
      const b = params.bounds;
      if (b && ![b.minX, b.minY, b.maxX, b.maxY].every(Number.isFinite)) throw new RangeError(`bounds must be finite numbers, got ${JSON.stringify(b)}`);
      w.bounds = b ? { minX: b.minX, minY: b.minY, maxX: b.maxX, maxY: b.maxY } : null;
      this.params.bounds = w.bounds && { ...w.bounds };
      // A rebuild (reset) makes its world from the scene's options: keep the new walls there too.
      this.worldOptions = { ...this.worldOptions, bounds: w.bounds && { ...w.bounds } };
    });
    set('timestep', () => {
      w.timestep = params.timestep!;
      this.params.timestep = params.timestep!;
    });
    set('substeps', () => {
      w.substeps = params.substeps!;
      this.params.substeps = params.substeps!;
    });
    set('iterations', () => {
      w.iterations = params.iterations!;
      this.params.iterations = params.iterations!;
    });
    set('broadphase', () => {
      w.broadphase = params.broadphase!;
      this.params.broadphase = params.broadphase!;
    });
    set('narrowphase', () => {
      w.narrowphase = params.narrowphase!;
      this.params.narrowphase = params.narrowphase!;
    });
    if (params.debug !== undefined) this.params.debug = Boolean(params.debug);
    if (params.events !== undefined) {
      this.params.events = Boolean(params.events);
      if (!this.params.events) this.eventCount = 0;
    }
    return errors;
  }

  /** A fresh world from the current options and descriptions (load and reset). */
  private rebuild(): HostError[] {
    const errors: HostError[] = [];
    try {
      this.world = new World(this.optionsForWorld());
    } catch (error) {
      errors.push(errorOf(-1, error));
      this.worldOptions = {};
      this.world = new World(this.optionsForWorld());
    }
    this.keyOfHandle.clear();
    for (const r of this.bodies.values()) {
      r.handle = null;
      const error = this.build(r);
      if (error) errors.push(error);
    }
    for (const l of this.links.values()) {
      l.handles = [];
      const error = this.link(l);
      if (error) errors.push(error);
    }
    this.eventCount = 0;
    this.topologyDirty = true;
    return errors;
  }

  private emptyRecord(key: number, desc: BodyDescription): BodyRecord {
    return { key, desc, handle: null, indices: new Int32Array(0), edge0: 0, dx: 0, dy: 0, angle0: 0 };
  }

  private build(r: BodyRecord): HostError | null {
    try {
      const built = buildBody(this.world, r.desc);
      r.handle = built.body;
      this.keyOfHandle.set(built.body, r.key);
      const idx = this.world.bodyParticleIndices(built.body);
      const { x, y } = this.world.particles;
      let mx = 0;
      let my = 0;
      for (const i of idx) {
        mx += x[i];
        my += y[i];
      }
      mx /= idx.length;
      my /= idx.length;
      const d = r.desc as { x?: number; y?: number; angle?: number };
      const ox = typeof d.x === 'number' && (r.desc.type === 'box' || r.desc.type === 'polygon' || r.desc.type === 'circle') ? d.x : mx;
      const oy = typeof d.y === 'number' && (r.desc.type === 'box' || r.desc.type === 'polygon' || r.desc.type === 'circle') ? d.y : my;
      r.dx = ox - mx;
      r.dy = oy - my;
      r.edge0 = idx.length >= 2 ? Math.atan2(y[idx[1]] - y[idx[0]], x[idx[1]] - x[idx[0]]) : 0;
      r.angle0 = typeof d.angle === 'number' ? d.angle : 0;
      return null;
    } catch (error) {
      r.handle = null;
      return errorOf(r.key, error);
    }
  }

  private unbuild(r: BodyRecord): void {
    if (r.handle !== null && this.world.hasBody(r.handle)) this.world.removeBody(r.handle);
    if (r.handle !== null) this.keyOfHandle.delete(r.handle);
    r.handle = null;
  }

  private onlyStyleChanged(a: BodyDescription, b: BodyDescription): boolean {
    return sameExcept(a, b, ['fill', 'stroke', 'id']);
  }

  private onlyMaterialChanged(a: BodyDescription, b: BodyDescription): boolean {
    const ma = a as { friction?: number; restitution?: number };
    const mb = b as { friction?: number; restitution?: number };
    return sameExcept(a, b, ['fill', 'stroke', 'id', 'friction', 'restitution']) && (ma.friction !== mb.friction || ma.restitution !== mb.restitution);
  }

  /** Re-creates the links that touch a body (after it was rebuilt, added or removed). */
  private relink(bodyKey: number): void {
    for (const l of this.links.values()) {
      if (l.desc.a !== bodyKey && (l.desc.type === 'pin' || l.desc.b !== bodyKey)) continue;
      this.unlink(l);
      this.link(l);
    }
  }

  private unlink(l: LinkRecord): void {
    for (const h of l.handles) if (this.world.hasConstraint(h)) this.world.removeConstraint(h);
    l.handles = [];
    l.pa = l.pb = -1;
  }

  private link(l: LinkRecord): HostError | null {
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

  private nearest(idx: Int32Array, x: number, y: number): number {
    const p = this.world.particles;
    let best = idx[0];
    let bestD = Infinity;
    for (const i of idx) {
      const d = (p.x[i] - x) ** 2 + (p.y[i] - y) ** 2;
      if (d < bestD) [best, bestD] = [i, d];
    }
    return best;
  }

  private changed(): void {
    this.topologyDirty = true;
    this.publish();
  }

  // ---- publishing --------------------------------------------------------------------------------------------

  private sendTopology(): void {
    this.topologyDirty = false;
    this.topologyVersion++;
    this.order = [];
    const bodies: TopologyBody[] = [];
    for (const r of this.bodies.values()) {
      if (r.handle === null) continue;
      r.indices = this.world.bodyParticleIndices(r.handle);
      this.order.push(r);
      const d = r.desc;
      const t: TopologyBody = { key: r.key, type: d.type, kind: this.world.bodyKindOf(r.handle), indices: r.indices.slice() };
      if (d.type === 'cloth') [t.columns, t.rows, t.torn] = [d.columns, d.rows, this.tornLinks(r, d.columns)];
      if (d.type === 'circle') t.radius = d.radius;
      if (d.type === 'rope') t.radius = d.radius ?? 0;
      if (d.type === 'ragdoll') t.radius = 0.075 * (d.height ?? 1.8);
      if (d.type === 'softbody') t.ring = d.model === 'springs' ? r.indices.length - 1 : r.indices.length;
      bodies.push(t);
    }
    const active = [...this.links.values()].filter((l) => l.pa >= 0);
    const links = new Float64Array(active.length * 2);
    active.forEach((l, k) => {
      links[2 * k] = l.pa;
      links[2 * k + 1] = l.pb;
    });
    this.output.topology({ version: this.topologyVersion, bodies, links });
  }

  /** A cloth's broken links as bits per grid node (see TopologyBody.torn), or undefined when it is whole. */
  private tornLinks(r: BodyRecord, columns: number): Uint8Array | undefined {
    const w = this.world;
    let torn: Uint8Array | undefined;
    let gridOf: Map<number, number> | undefined;
    for (const h of w.bodyConstraintHandles(r.handle!)) {
      if (w.constraintKindOf(h) !== 'distance' || !w.isBroken(h)) continue;
      gridOf ??= new Map(Array.from(r.indices, (slot, n) => [slot, n]));
      torn ??= new Uint8Array(r.indices.length);
      const [i, j] = w.distanceParticleIndices(h);
      const a = gridOf.get(i) ?? -1;
      const b = gridOf.get(j) ?? -1;
      const lo = Math.min(a, b);
      if (lo < 0) continue;
      if (Math.abs(a - b) === 1) torn[lo] |= 1;
      else if (Math.abs(a - b) === columns) torn[lo] |= 2;
    }
    return torn;
  }

  private collectEvents(): void {
    const e = this.world.events;
    if (e.count === 0) return;
    const need = (this.eventCount + e.count) * EVENT;
    if (need > this.eventData.length) {
      const grown = new Float64Array(Math.max(need, this.eventData.length * 2));
      grown.set(this.eventData);
      this.eventData = grown;
    }
    let o = this.eventCount * EVENT;
    for (let k = 0; k < e.count; k++) {
      this.eventData[o++] = e.type[k];
      this.eventData[o++] = this.keyOfHandle.get(e.bodyA[k]) ?? -1;
      this.eventData[o++] = this.keyOfHandle.get(e.bodyB[k]) ?? -1;
      this.eventData[o++] = e.normalX[k];
      this.eventData[o++] = e.normalY[k];
      this.eventData[o++] = e.depth[k];
    }
    this.eventCount += e.count;
  }

  /** Events cross the boundary once per published frame, and only while someone listens. */
  private flushEvents(): void {
    if (this.eventCount === 0) return;
    if (this.params.events) {
      this.output.events(this.eventData.slice(0, this.eventCount * EVENT), this.eventCount);
      this.eventsSent += this.eventCount;
    }
    this.eventCount = 0;
  }

  private publish(): void {
    if (this.disposed) return;
    if (this.topologyDirty) this.sendTopology();
    const w = this.world;
    const p = w.particles;
    const n = p.count;
    const bodies = this.order;
    const b = bodies.length;
    const debug = this.params.debug;
    const c = debug ? Math.min(MAX_CONTACTS, w.contacts.count) : 0;
    const f = this.publisher.begin(frameLength(n, b, c, debug));
    if (!f) {
      this.skipped++;
      return;
    }
    f[F.seq] = ++this.seq;
    f[F.topology] = this.topologyVersion;
    f[F.stepCount] = w.stepCount;
    f[F.time] = w.time;
    f[F.particles] = n;
    f[F.bodies] = b;
    f[F.contacts] = c;
    f[F.debug] = debug ? 1 : 0;
    f[F.cellSize] = debug ? w.gridCellSize : 0;
    f[F.running] = this.running ? 1 : 0;
    f[F.stamp] = performance.now();
    const { x, y } = p;
    let o = HEADER;
    for (let i = 0; i < n; i++) {
      f[o++] = x[i];
      f[o++] = y[i];
    }
    for (let k = 0; k < b; k++) {
      const r = bodies[k];
      const idx = r.indices;
      let mx = 0;
      let my = 0;
      for (let q = 0; q < idx.length; q++) {
        mx += x[idx[q]];
        my += y[idx[q]];
      }
      mx /= idx.length;
      my /= idx.length;
      if (r.desc.type === 'ragdoll' && idx.length > 2) {
        // A ragdoll's position is its pelvis (particle 2), as in its markup.
        mx = x[idx[2]];
        my = y[idx[2]];
      }
      const theta = idx.length >= 2 && (r.desc.type === 'box' || r.desc.type === 'polygon')
        ? Math.atan2(y[idx[1]] - y[idx[0]], x[idx[1]] - x[idx[0]]) - r.edge0
        : 0;
      const cos = Math.cos(theta);
      const sin = Math.sin(theta);
      f[o++] = mx + r.dx * cos - r.dy * sin;
      f[o++] = my + r.dx * sin + r.dy * cos;
      f[o++] = r.angle0 + theta;
    }
    if (debug) {
      const col = w.colliders;
      const radius = p.radius;
      for (let k = 0; k < b; k++) {
        const r = bodies[k];
        // The particles' box; the collider's box (grown by this step's motion) when it is current, i.e. holds it.
        let x0 = Infinity;
        let y0 = Infinity;
        let x1 = -Infinity;
        let y1 = -Infinity;
        for (let q = 0; q < r.indices.length; q++) {
          const i = r.indices[q];
          if (x[i] - radius[i] < x0) x0 = x[i] - radius[i];
          if (y[i] - radius[i] < y0) y0 = y[i] - radius[i];
          if (x[i] + radius[i] > x1) x1 = x[i] + radius[i];
          if (y[i] + radius[i] > y1) y1 = y[i] + radius[i];
        }
        const slot = handleSlot(r.handle!);
        if (col.kind[slot] !== 0 && col.minX[slot] <= x0 && col.minY[slot] <= y0 && col.maxX[slot] >= x1 && col.maxY[slot] >= y1) {
          x0 = col.minX[slot];
          y0 = col.minY[slot];
          x1 = col.maxX[slot];
          y1 = col.maxY[slot];
        }
        f[o++] = x0;
        f[o++] = y0;
        f[o++] = x1;
        f[o++] = y1;
      }
      const ct = w.contacts;
      for (let k = 0; k < c; k++) {
        const v = ct.v[k];
        f[o++] = x[v];
        f[o++] = y[v];
        f[o++] = ct.nx[k];
        f[o++] = ct.ny[k];
      }
    }
    this.publisher.commit();
    this.published++;
  }
}

/** Pull of a grab on loose particles, per unit mass (1/s²): firm enough to beat the rigid links of a cloth. */
const PARTICLE_GRAB_STIFFNESS = 1e6;

/** Even–odd test of (x, y) against the closed loop of particles. */
function insideLoop(loop: Int32Array, px: Float64Array, py: Float64Array, x: number, y: number): boolean {
  let inside = false;
  for (let k = 0, j = loop.length - 1; k < loop.length; j = k++) {
    const a = loop[k];
    const b = loop[j];
    if (py[a] > y !== py[b] > y && x < ((px[b] - px[a]) * (y - py[a])) / (py[b] - py[a]) + px[a]) inside = !inside;
  }
  return inside;
}

function sameExcept(a: object, b: object, ignore: string[]): boolean {
  const keys = new Set([...Object.keys(a), ...Object.keys(b)]);
  for (const k of keys) {
    if (ignore.includes(k)) continue;
    if (JSON.stringify((a as Record<string, unknown>)[k]) !== JSON.stringify((b as Record<string, unknown>)[k])) return false;
  }
  return true;
}

