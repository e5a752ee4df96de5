// Frame and topology encoding. A topology (which bodies, their particles and drawing facts, the links' ends) goes out
// when what is built changed; a frame (Float64Array, layout F/HEADER in protocol.ts) every time the state is published:
// header, particle positions, a pose per body and, in debug mode, bounding boxes and contacts.
import { handleSlot } from '../../engine/handles.js';
import { rigidContactsOf } from '../../engine/inspect.js';
import { F, HEADER, MAX_CONTACTS, POSE, frameLength, type LinkEnd, type TopologyBody } from '../protocol.js';
import type { Publisher } from '../publishers.js';
import type { BodyRecord, Bindings } from './bindings.js';
import { writePose } from './bodies/pose.js';
import { describeRigid, writeRigidBox, writeRigidPose } from './bodies/rigid.js';
import type { HostOutput } from './output.js';

export class FrameEncoder {
  /** Frames written, and frames skipped because the publisher had no free buffer. */
  published = 0;
  skipped = 0;
  /** Topologies sent. Frames carry it: a frame is drawn only with its own topology. */
  #version = 0;
  #stale = true;
  /** Bodies in topology order, the order of poses in a frame. */
  #order: BodyRecord[] = [];
  #seq = 0;

  readonly #bindings: Bindings;
  readonly #publisher: Publisher;
  readonly #output: Pick<HostOutput, 'topology'>;

  constructor(bindings: Bindings, publisher: Publisher, output: Pick<HostOutput, 'topology'>) {
    this.#bindings = bindings;
    this.#publisher = publisher;
    this.#output = output;
  }

  /** What is built changed: the next publish sends a new topology first. */
  invalidate(): void {
    this.#stale = true;
  }

  /** The version of the topology in force, or -1 while a change is not published yet. */
  get topology(): number {
    return this.#stale ? -1 : this.#version;
  }

  /** Bodies in the newest topology. */
  get bodyCount(): number {
    return this.#order.length;
  }

  /** Writes the current state as one frame (after a new topology, when stale); `eventsSent`: collision events sent so far. */
  publish(running: boolean, debug: boolean, eventsSent: number): void {
    if (this.#stale) this.#topologyNow();
    const w = this.#bindings.world;
    const p = w.particles;
    const n = p.count;
    const bodies = this.#order;
    const b = bodies.length;
    const c = debug ? Math.min(MAX_CONTACTS, w.contacts.count + rigidContactsOf(w).count) : 0;
    const f = this.#publisher.begin(frameLength(n, b, c, debug));
    if (!f) {
      this.skipped++;
      return;
    }
    f[F.seq] = ++this.#seq;
    f[F.topology] = this.#version;
    f[F.stepCount] = w.stepCount;
    f[F.time] = w.time;
    f[F.particles] = n;
    f[F.bodies] = b;
    f[F.contacts] = c;
    f[F.debug] = debug ? 1 : 0;
    f[F.cellSize] = debug ? w.gridCellSize : 0;
    f[F.running] = running ? 1 : 0;
    f[F.stamp] = performance.now();
    f[F.eventsSent] = eventsSent;
    const { x, y, angle } = p;
    let o = HEADER;
    for (let i = 0; i < n; i++) {
      f[o++] = x[i];
      f[o++] = y[i];
    }
    for (let k = 0; k < b; k++, o += POSE) {
      const r = bodies[k];
      if (r.rigid) writeRigidPose(f, o, r.indices[0], x, y, angle);
      else writePose(r.descriptor!.pose, f, o, r.indices, x, y, r.basis);
    }
    if (debug) this.#writeDebug(f, o, c);
    this.#publisher.commit();
    this.published++;
  }

  #topologyNow(): void {
    this.#stale = false;
    this.#version++;
    const w = this.#bindings.world;
    this.#order = this.#bindings.built();
    const bodies = this.#order.map((r): TopologyBody => {
      const t: TopologyBody = { key: r.key, type: r.desc.type, kind: w.bodyKindOf(r.handle!), indices: r.indices.slice() };
      r.descriptor!.describe?.(t, r.desc, { world: w, handle: r.handle!, indices: r.indices });
      if (r.rigid) describeRigid(t, r.rigid);
      return t;
    });
    // Link ends on rigid bodies name the body by its place in this topology.
    const place = new Map(this.#order.map((r, k) => [r.key, k]));
    const placed = (e: LinkEnd): LinkEnd => (e.body < 0 ? { ...e } : { ...e, body: place.get(e.body) ?? -1 });
    const links = this.#bindings.activeLinks().map((l) => ({ a: placed(l.drawn!.a), b: placed(l.drawn!.b), pivot: l.drawn!.pivot }));
    this.#output.topology({ version: this.#version, bodies, links });
  }

  /** Per body its bounding box, then the contacts (point and normal): of bodies of particles, then of rigid bodies. */
  #writeDebug(f: Float64Array, o: number, contacts: number): void {
    const w = this.#bindings.world;
    const { x, y, radius, angle } = w.particles;
    const col = w.colliders;
    for (let k = 0; k < this.#order.length; k++, o += 4) {
      const r = this.#order[k];
      if (r.rigid) {
        const i = r.indices[0];
        writeRigidBox(f, o, r.rigid, x[i], y[i], angle[i]);
        continue;
      }
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
      f[o] = x0;
      f[o + 1] = y0;
      f[o + 2] = x1;
      f[o + 3] = y1;
    }
    const ct = w.contacts;
    const particleContacts = Math.min(contacts, ct.count);
    for (let k = 0; k < particleContacts; k++) {
      const v = ct.v[k];
      f[o++] = x[v];
      f[o++] = y[v];
      f[o++] = ct.nx[k];
      f[o++] = ct.ny[k];
    }
    // A rigid contact's point on side A: a round side's nearest point along the normal, else its material point.
    const rc = rigidContactsOf(w);
    for (let k = 0; k < contacts - particleContacts; k++) {
      const a = rc.a[k];
      const nx = rc.nx[k];
      const ny = rc.ny[k];
      if (rc.radA[k] > 0) {
        f[o++] = x[a] + rc.radA[k] * nx;
        f[o++] = y[a] + rc.radA[k] * ny;
      } else {
        const c = Math.cos(angle[a]);
        const s = Math.sin(angle[a]);
        f[o++] = x[a] + c * rc.rAx[k] - s * rc.rAy[k];
        f[o++] = y[a] + s * rc.rAx[k] + c * rc.rAy[k];
      }
      f[o++] = nx;
      f[o++] = ny;
    }
  }
}
