// The constraints: one dense table per kind (rows packed, swap-removed) and, per handle slot, which table and which
// row hold the constraint. The World checks the arguments; this module keeps the tables and the handles in step.
import { handleSlot, HandleRegistry, type Handle, type RegistrySnapshot } from './handles.js';
import { ParticleFlag, type ParticleStore } from './particles.js';
import { grown, type Column, type Table } from './table.js';
import { DistanceConstraints } from './constraints/distance.js';
import { AngleConstraints } from './constraints/angle.js';
import { PinConstraints } from './constraints/pin.js';
import { AreaConstraints } from './constraints/area.js';
import { Springs } from './constraints/spring.js';
import { GrabConstraints } from './constraints/grab.js';
import { Joints } from './rigid/joint-table.js';
import { CONSTRAINT_KINDS, type ConstraintKind } from './options.js';

/** A constraint's table, as an index into the registry's `tables` (and into CONSTRAINT_KINDS). */
export const enum Kind {
  Distance,
  Angle,
  Pin,
  Spring,
  Area,
  Grab,
  Joint,
}

type ConstraintTable = Table & { slot: Int32Array };

export class ConstraintRegistry {
  readonly distances = new DistanceConstraints();
  readonly angles = new AngleConstraints();
  readonly pins = new PinConstraints();
  readonly springs = new Springs();
  readonly areas = new AreaConstraints();
  readonly grabs = new GrabConstraints();
  readonly joints = new Joints();
  /** Indexed by Kind. */
  readonly tables: readonly ConstraintTable[] = [this.distances, this.angles, this.pins, this.springs, this.areas, this.grabs, this.joints];
  readonly ids = new HandleRegistry('constraint', 'constraints');
  /** Per handle slot: the Kind of its table and its row there. */
  kind = new Uint8Array(64);
  row = new Int32Array(64);

  /** Live constraints of every kind. */
  get count(): number {
    let n = 0;
    for (const t of this.tables) n += t.count;
    return n;
  }

  /** Adds a row holding `values` to `table` under a new handle (the handle first: at the limit nothing changes). */
  add<T extends ConstraintTable>(table: T, values: Partial<Record<T['columns'][number], number>>): Handle {
    const handle = this.ids.allocate();
    const slot = handleSlot(handle);
    if (slot >= this.kind.length) {
      this.kind = grown(this.kind, this.kind.length * 2);
      this.row = grown(this.row, this.row.length * 2);
    }
    const row = table.pushValues(values);
    this.kind[slot] = this.tables.indexOf(table);
    this.row[slot] = row;
    table.slot[row] = slot;
    return handle;
  }

  /** The row of a live constraint of `kind`; a TypeError/RangeError naming `what` otherwise. */
  rowOf(handle: Handle, kind: Kind, what: string): number {
    const slot = this.ids.slotOf(handle, what);
    if (this.kind[slot] !== kind) throw new RangeError(`constraint ${handle} is not a ${what}`);
    return this.row[slot];
  }

  kindOf(handle: Handle): ConstraintKind {
    return CONSTRAINT_KINDS[this.kind[this.ids.slotOf(handle, 'constraint')]];
  }

  /** Removes a live constraint; a rigid pin gives its particle its mass back. */
  remove(handle: Handle, particles: ParticleStore): void {
    const slot = handleSlot(handle);
    const kind = this.kind[slot] as Kind;
    const row = this.row[slot];
    const pins = this.pins;
    if (kind === Kind.Pin && pins.compliance[row] === 0) {
      particles.invMass[pins.p[row]] = pins.savedInvMass[row];
      particles.flags[pins.p[row]] &= ~ParticleFlag.Pinned;
    }
    const table = this.tables[kind];
    if (table.swapRemove(row) !== row) this.row[table.slot[row]] = row;
    if (kind === Kind.Area) this.areas.compactPool();
    this.ids.release(handle);
  }

  /** Handles of the live constraints that act on particle `i`, in slot order. */
  using(i: number): Handle[] {
    const found: Handle[] = [];
    for (let slot = 0; slot < this.ids.high; slot++) {
      if (this.ids.alive[slot] && this.uses(this.kind[slot] as Kind, this.row[slot], i)) found.push(this.ids.handleOf(slot));
    }
    return found;
  }

  private uses(kind: Kind, row: number, i: number): boolean {
    switch (kind) {
      case Kind.Distance:
        return this.distances.a[row] === i || this.distances.b[row] === i;
      case Kind.Angle:
        return this.angles.a[row] === i || this.angles.b[row] === i || this.angles.c[row] === i;
      case Kind.Pin:
        return this.pins.p[row] === i;
      case Kind.Spring:
        return this.springs.a[row] === i || this.springs.b[row] === i;
      case Kind.Area: {
        const t = this.areas;
        for (let k = 0; k < t.length[row]; k++) if (t.pool[t.start[row] + k] === i) return true;
        return false;
      }
      case Kind.Grab:
        return this.grabs.p0[row] === i || this.grabs.p1[row] === i || this.grabs.p2[row] === i;
      case Kind.Joint:
        return this.joints.a[row] === i || this.joints.b[row] === i;
    }
  }

  /** The inverse mass a rigid pin parked for particle i (0 when none holds it). */
  pinnedInvMass(i: number): number {
    const pins = this.pins;
    for (let r = 0; r < pins.count; r++) if (pins.p[r] === i && pins.compliance[r] === 0) return pins.savedInvMass[r];
    return 0;
  }

  snapshot(): ConstraintsSnapshot {
    return {
      ids: this.ids.snapshot(),
      kind: this.kind.slice(),
      row: this.row.slice(),
      tables: this.tables.map((t) => ({ count: t.count, columns: t.snapshot() })),
      areaPool: this.areas.pool.slice(0, this.areas.poolUsed),
    };
  }

  restore(s: ConstraintsSnapshot): void {
    this.ids.restore(s.ids);
    this.kind = s.kind.slice();
    this.row = s.row.slice();
    this.tables.forEach((t, k) => t.restore(s.tables[k].columns, s.tables[k].count));
    this.areas.pool = new Int32Array(Math.max(64, s.areaPool.length));
    this.areas.pool.set(s.areaPool);
    this.areas.poolUsed = s.areaPool.length;
  }
}

export interface ConstraintsSnapshot {
  ids: RegistrySnapshot;
  kind: Uint8Array;
  row: Int32Array;
  tables: { count: number; columns: Column[] }[];
  areaPool: Int32Array;
}
