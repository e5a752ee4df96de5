// The rigid contact table keeps its capacity from step to step: it grows (by doubling) only while the number of
// contact points reaches a new high, and a settled pile steps without reallocating it.
import { expect } from 'chai';
import { World } from '../../../src/engine/index.js';
import { rigidContactsOf } from '../../../src/engine/inspect.js';

describe('rigid bodies: the contact table keeps its capacity', () => {
  it('grows only at a new high of contact points; a settled pile of 400 discs steps 200 times without reallocating it', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, bounds: { minX: 0, minY: -100, maxX: 20, maxY: 0 }, sleeping: false });
    for (let k = 0; k < 400; k++) world.addRigidBody({ x: 0.6 + (k % 16) * 1.2 + (Math.floor(k / 16) % 2) * 0.3, y: -1 - Math.floor(k / 16) * 1.2, radius: 0.5 });
    const table = rigidContactsOf(world);
    let high = 0;
    let growths = 0;
    let columns = table.a;
    for (let k = 0; k < 600; k++) {
      world.step();
      if (table.a !== columns) {
        growths++;
        // A reallocation only when this step's points no longer fit the old capacity.
        expect(table.count, `step ${k + 1}`).to.be.greaterThan(columns.length);
        expect(table.count).to.be.greaterThan(high);
        columns = table.a;
      }
      high = Math.max(high, table.count);
    }
    // 16 rows to start with, doubled to fit the pile's ~870 points: at most log2(capacity / 16) growths in all.
    expect(high).to.be.greaterThan(800);
    expect(growths).to.be.at.most(Math.log2(columns.length / 16));
    // Settled: the same arrays for 200 more steps, whatever the count does between steps.
    const settled = table.a;
    const nx = table.nx;
    for (let k = 0; k < 200; k++) world.step();
    expect(table.a).to.equal(settled);
    expect(table.nx).to.equal(nx);
  });
});
