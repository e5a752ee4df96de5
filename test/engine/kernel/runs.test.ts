import { expect } from 'chai';
import fc from 'fast-check';
import { findRuns, MAX_LANES, RunKind, type RunLayout } from '../../../src/engine/kernel/runs.js';
import { createCloth, World } from '../../../src/engine/index.js';

interface Links {
  count: number;
  a: Int32Array;
  b: Int32Array;
  minLength: Float64Array;
  maxLength: Float64Array;
  compliance: Float64Array;
}

/** Links from a list of [a, b, kind] (kind: 0 stick, 1 slack, 2 compliant). */
function links(list: [number, number, number][]): Links {
  const count = list.length;
  const l: Links = { count, a: new Int32Array(count), b: new Int32Array(count), minLength: new Float64Array(count), maxLength: new Float64Array(count), compliance: new Float64Array(count) };
  list.forEach(([a, b, kind], i) => {
    l.a[i] = a;
    l.b[i] = b;
    l.minLength[i] = kind === 1 ? 0 : 1;
    l.maxLength[i] = 1;
    l.compliance[i] = kind === 2 ? 1e-3 : 0;
  });
  return l;
}

const runsOf = (l: Links): RunLayout => findRuns(l.count, l.a, l.b, l.minLength, l.maxLength, l.compliance);

/** Every property the kernel's sweep relies on (solver.as): see runs.ts. */
function checkLayout(l: Links, r: RunLayout): void {
  const seen = new Int32Array(l.count);
  for (const row of r.rows) if (row >= 0) seen[row]++;
  for (const row of r.leftover) seen[row]++;
  expect([...seen].every((s) => s === 1), 'every row once, in a run or left over').to.equal(true);
  let limitsSeen = false;
  for (let k = 0; k < r.lanes.length; k++) {
    const start = r.laneStart[k];
    const lanes = r.laneStart[k + 1] - start;
    expect(lanes % 2).to.equal(0);
    expect(r.lanes[k]).to.be.within(2, MAX_LANES);
    expect(lanes - r.lanes[k]).to.be.within(0, 1);
    // Rigid limits come after every other kind.
    if (r.kind[k] === RunKind.Limits) limitsSeen = true;
    else expect(limitsSeen, `chunk ${k}: a stick or compliant run after the limits`).to.equal(false);
    for (let j = 0; j < lanes; j++) {
      const row = r.rows[start + j];
      // The particles of lane j, from the chunk's record alone (what the kernel reads).
      const lo = r.interleaved[k] ? r.first[k] + 2 * j : r.first[k] + j;
      const hi = r.interleaved[k] ? lo + 1 : r.second[k] + j;
      if (j % 2 === 1) {
        // The two lanes of a pair (a padding lane's particles too: it reads and writes them back) share no particle.
        const other = [r.interleaved[k] ? lo - 2 : lo - 1, r.interleaved[k] ? lo - 1 : hi - 1];
        expect(other).to.not.include(lo);
        expect(other).to.not.include(hi);
      }
      if (j >= r.lanes[k]) {
        expect(row, 'padding lane').to.equal(-1);
        continue;
      }
      expect([Math.min(l.a[row], l.b[row]), Math.max(l.a[row], l.b[row])]).to.deep.equal([lo, hi]);
      const kind = l.compliance[row] !== 0 ? RunKind.Compliant : l.minLength[row] === l.maxLength[row] ? RunKind.Stick : RunKind.Limits;
      expect(kind).to.equal(r.kind[k]);
    }
  }
}

describe('solver kernel: runs of contiguous constraints', () => {
  it('random link sets: every row once, pairs of lanes share no particle, lanes match their record', () => {
    const lists = fc.array(fc.tuple(fc.nat(30), fc.integer({ min: 0, max: 4 }), fc.nat(2)), { maxLength: 300 });
    fc.assert(
      fc.property(lists, fc.boolean(), (raw, swap) => {
        // Small offsets make runs likely; a swapped pair (b < a) is the same link.
        const list = raw.map(([a, d, kind]): [number, number, number] => (swap && d % 2 ? [a + d, a, kind] : [a, a + d, kind]));
        const l = links(list);
        checkLayout(l, runsOf(l));
      }),
      { numRuns: 300 },
    );
  });

  it('a cloth with shear links and tethers is all runs: no link is left for the coloured packets', () => {
    const world = new World({ kernel: 'js' });
    createCloth(world, { origin: { x: 0, y: 0 }, columns: 30, rows: 20, spacing: 0.5, shear: 0 });
    const c = world.distances;
    const r = findRuns(c.count, c.a, c.b, c.minLength, c.maxLength, c.compliance);
    checkLayout({ count: c.count, a: c.a, b: c.b, minLength: c.minLength, maxLength: c.maxLength, compliance: c.compliance }, r);
    expect(r.leftover.length).to.equal(0);
    // Structural 2·30·20 − 30 − 20, shear 2·29·19, tethers 30·19.
    expect(r.rows.filter((row) => row >= 0).length).to.equal(1150 + 1102 + 570);
  });

  it('a chain is two interleaved runs (even and odd links); a fan from one particle is left over', () => {
    const chain = links(Array.from({ length: 9 }, (_, i): [number, number, number] => [i, i + 1, 0]));
    const r = runsOf(chain);
    expect([...r.interleaved]).to.deep.equal([1, 1]);
    expect([...r.lanes]).to.deep.equal([5, 4]);
    expect([...r.rows]).to.deep.equal([0, 2, 4, 6, 8, -1, 1, 3, 5, 7]);
    const fan = links(Array.from({ length: 6 }, (_, i): [number, number, number] => [0, 2 * i + 3, 0]));
    expect(runsOf(fan).leftover.length).to.equal(6);
  });
});
