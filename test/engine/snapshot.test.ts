import { expect } from 'chai';
import { World, buildScene, catalogue, createSoftBody, SCENE_NAMES, type WorldSnapshot } from '../../src/engine/index.js';
import { describedParts, FIELDS, TABLE_FIELDS, type FieldList } from '../../src/engine/snapshot.js';
import type { StepContext } from '../../src/engine/pipeline/context.js';

/** The world's context (private: this test is about what it holds). */
function contextOf(world: World): StepContext {
  return (world as unknown as { ctx: StepContext }).ctx;
}

/** Fields of `owner` in neither list, listed fields it does not have, and fields in both lists. */
function misfits(owner: object, list: FieldList): { unlisted: string[]; absent: string[]; twice: string[] } {
  const own = Object.keys(owner);
  const left = Object.keys(list.notSnapshotted);
  return {
    unlisted: own.filter((f) => !list.snapshotted.includes(f) && !left.includes(f)),
    absent: [...list.snapshotted, ...left].filter((f) => !own.includes(f)),
    twice: list.snapshotted.filter((f) => left.includes(f)),
  };
}

const NONE = { unlisted: [], absent: [], twice: [] };

describe('snapshot field lists', () => {
  // A busy world, so that lazily made fields exist too.
  const world = buildScene(catalogue.soft.make()).world;
  for (let k = 0; k < 3; k++) world.step();

  it("the World holds nothing but its context: a new field there is in neither list", () => {
    expect(misfits(world, FIELDS.world), 'World (put state in StepContext, then list it in snapshot.ts)').to.deep.equal(NONE);
    expect(misfits(new World(), FIELDS.world)).to.deep.equal(NONE);
  });

  it('every field of the context and of its parts is either snapshotted or left out with a reason, never both', () => {
    for (const w of [world, new World(), new World({ broadphase: 'brute' })]) {
      for (const [name, part] of describedParts(contextOf(w))) {
        expect(misfits(part, FIELDS[name]), `${name} (list the field in snapshot.ts FIELDS.${name})`).to.deep.equal(NONE);
      }
    }
    for (const list of Object.values(FIELDS)) for (const reason of Object.values(list.notSnapshotted) as string[]) expect(reason).to.have.length.above(5);
  });

  it("every field of every table is a column (all snapshotted) or listed", () => {
    const ctx = contextOf(world);
    const tables = [ctx.particles, ...ctx.constraints.tables];
    for (const table of tables) {
      const columns: readonly string[] = table.columns;
      const extra = { snapshotted: TABLE_FIELDS.snapshotted.filter((f) => f in table), notSnapshotted: TABLE_FIELDS.notSnapshotted };
      const { unlisted, twice } = misfits(table, { snapshotted: [...columns, ...extra.snapshotted], notSnapshotted: extra.notSnapshotted });
      expect({ unlisted, twice }, `${table.constructor.name} (add the field to its columns or to TABLE_FIELDS)`).to.deep.equal({ unlisted: [], twice: [] });
      for (const column of columns) expect(table, table.constructor.name).to.have.property(column);
    }
    for (const f of TABLE_FIELDS.snapshotted) expect(tables.some((t) => f in t), `TABLE_FIELDS names ${f}, which no table has`).to.equal(true);
  });

  it("a snapshot's keys are the context's snapshotted fields, and it survives structuredClone", () => {
    const snap = world.snapshot();
    expect(Object.keys(snap)).to.deep.equal([...FIELDS.context.snapshotted]);
    const copy = new World();
    copy.restore(structuredClone(snap));
    expect(copy.stateHash()).to.equal(world.stateHash());
  });
});

describe('snapshot and restore', () => {
  for (const name of SCENE_NAMES) {
    it(`${name}: restoring mid-run, into the same or a fresh world, reproduces the run`, () => {
      const { world } = buildScene(catalogue[name].make());
      for (let k = 0; k < 60; k++) world.step();
      const snap = structuredClone(world.snapshot());
      for (let k = 0; k < 30; k++) world.step();
      const expected = world.stateHash();
      world.restore(snap);
      for (let k = 0; k < 30; k++) world.step();
      expect(world.stateHash(), 'same world').to.equal(expected);
      const fresh = new World({ broadphase: 'brute', sleeping: false });
      fresh.restore(snap);
      for (let k = 0; k < 30; k++) fresh.step();
      expect(fresh.stateHash(), 'fresh world').to.equal(expected);
    });
  }

  it('a restored soft body is still picked by its inside (its ring length is state)', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const soft = createSoftBody(world, { center: { x: 0, y: 0 }, radius: 1, segments: 12, model: 'springs' }).body;
    expect(world.bodiesAtPoint(0.3, 0.2)).to.deep.equal([soft]);
    const copy = new World();
    copy.restore(world.snapshot());
    expect(copy.bodiesAtPoint(0.3, 0.2)).to.deep.equal([soft]);
  });

  it('restore() refuses what is not a snapshot, naming what is wrong, and leaves the world as it was', () => {
    const { world } = buildScene(catalogue.stack.make());
    for (let k = 0; k < 10; k++) world.step();
    const before = world.stateHash();
    const bad: unknown[] = [null, 42, 'snapshot', {}, { ...world.snapshot(), bodies: undefined }];
    for (const s of bad) expect(() => world.restore(s as WorldSnapshot), String(s)).to.throw(TypeError, /snapshot/);
    const { stepCount: _, ...noSteps } = world.snapshot();
    expect(() => world.restore(noSteps as WorldSnapshot)).to.throw(TypeError, /stepCount/);
    // JSON turns the typed arrays into plain objects: refused by name, not by a failing array method inside.
    expect(() => world.restore(JSON.parse(JSON.stringify(world.snapshot())) as WorldSnapshot)).to.throw(TypeError, /JSON.stringify.*structuredClone/);
    expect(world.stateHash()).to.equal(before);
    world.restore(structuredClone(world.snapshot()));
    expect(world.stateHash()).to.equal(before);
    const settings = { ...world.snapshot().settings, timestep: -1 };
    expect(() => world.restore({ ...world.snapshot(), settings })).to.throw(RangeError, /timestep/);
  });

  it('restore() refuses NaN or ±Infinity in a constraint or a collider, naming the column and row; open limits may be ±Infinity', () => {
    const world = new World();
    const p = world.addParticle({ x: 0, y: 0 });
    const q = world.addParticle({ x: 1, y: 0 });
    world.addPin(p, { compliance: 0.001 });
    world.addSpring(p, q, { length: 1, stiffness: 10 });
    const a = world.addRigidBody({ x: 3, y: 0, radius: 0.5 });
    world.addJoint({ type: 'revolute', a });
    for (let k = 0; k < 5; k++) world.step();
    const before = world.stateHash();
    const damaged = (edit: (s: WorldSnapshot) => void) => {
      const s = structuredClone(world.snapshot());
      edit(s);
      return s;
    };
    const column = (s: WorldSnapshot, kind: number, k: number) => s.constraints.tables[kind].columns[k] as Float64Array;
    // Pins (table 2): tx is column 1; springs (table 3): restLength is column 2; colliders' friction.
    expect(() => world.restore(damaged((s) => (column(s, 2, 1)[0] = NaN)))).to.throw(RangeError, /pin constraints\.tx\[0\].*NaN/);
    expect(() => world.restore(damaged((s) => (column(s, 3, 2)[0] = Infinity)))).to.throw(RangeError, /spring constraints\.restLength\[0\] must be a finite number/);
    expect(() => world.restore(damaged((s) => ((s.colliders.friction as Float64Array)[0] = NaN)))).to.throw(RangeError, /colliders\.friction\[0\]/);
    expect(world.stateHash()).to.equal(before);
    // A part that is not what snapshot() makes is named as such, not as the field read inside that failed.
    for (const edit of [(s: WorldSnapshot) => ((s as unknown as { constraints: unknown }).constraints = 5), (s: WorldSnapshot) => ((s as unknown as { anchors: unknown }).anchors = [])]) {
      expect(() => world.restore(damaged(edit))).to.throw(TypeError, /^snapshot is not one World\.snapshot\(\) made/);
    }
    expect(world.stateHash()).to.equal(before);
    // The revolute joint's open limits are ±Infinity: restored as they were.
    world.restore(structuredClone(world.snapshot()));
    expect(world.stateHash()).to.equal(before);
  });

  it('a refused restore() keeps the collision events going: the resting pairs do not begin again', () => {
    const { world } = buildScene({ ...catalogue.stack.make(), world: { ...catalogue.stack.make().world, sleeping: false } });
    for (let k = 0; k < 60; k++) world.step();
    const begins = (): number => {
      const e = world.events;
      let n = 0;
      for (let i = 0; i < e.count; i++) if (e.type[i] === 0) n++;
      return n;
    };
    begins();
    world.step();
    expect(begins(), 'a resting stack, events read from here on').to.equal(0);
    expect(() => world.restore(JSON.parse(JSON.stringify(world.snapshot())) as WorldSnapshot)).to.throw(TypeError);
    world.step();
    expect(begins(), 'the step after a refused restore').to.equal(0);
    // A restore that succeeds starts afresh: the touching pairs begin again.
    world.restore(world.snapshot());
    world.step();
    expect(begins()).to.be.greaterThan(5);
  });
});
