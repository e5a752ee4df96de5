import { expect } from 'chai';
import fc from 'fast-check';
import { colourRows } from '../../../src/engine/kernel/colour.js';

/** Random constraint graphs: `count` links between `particles` particles (a ≠ b), some immovable, some slack. */
const graphs = fc
  .record({ particles: fc.integer({ min: 2, max: 60 }), count: fc.integer({ min: 0, max: 400 }), seed: fc.integer(), lanes: fc.constantFrom(2, 4) })
  .map(({ particles, count, seed, lanes }) => {
    let s = seed >>> 0 || 1;
    const next = () => ((s = (s * 1103515245 + 12345) >>> 0) % 1_000_003) / 1_000_003;
    const a = new Int32Array(count);
    const b = new Int32Array(count);
    const slack = new Uint8Array(count);
    for (let i = 0; i < count; i++) {
      a[i] = Math.floor(next() * particles);
      b[i] = (a[i] + 1 + Math.floor(next() * (particles - 1))) % particles;
      slack[i] = next() < 0.3 ? 1 : 0;
    }
    const invMass = Float64Array.from({ length: particles }, () => (next() < 0.15 ? 0 : 1));
    return { a, b, slack, invMass, count, lanes };
  });

describe('solver kernel: graph colouring', () => {
  it('lists every row once, in packets whose lanes share no movable particle (so they can be solved at once)', () => {
    fc.assert(
      fc.property(graphs, ({ a, b, slack, invMass, count, lanes }) => {
        const order = colourRows(count, a, b, slack, invMass, lanes);
        expect(order.length % lanes).to.equal(0);
        const rows = [...order].filter((r) => r >= 0).sort((x, y) => x - y);
        expect(rows).to.deep.equal(Array.from({ length: count }, (_, i) => i));
        for (let p = 0; p < order.length; p += lanes) {
          const movable = [...order.subarray(p, p + lanes)].filter((r) => r >= 0).flatMap((r) => [a[r], b[r]]).filter((i) => invMass[i] !== 0);
          expect(new Set(movable).size, `packet at ${p}`).to.equal(movable.length);
        }
      }),
      { numRuns: 300 },
    );
  });

  it('a hub with more than 64 links to movable particles sends the rest to the serial tail, one row per packet', () => {
    const count = 100;
    const a = new Int32Array(count); // every link from particle 0
    const b = Int32Array.from({ length: count }, (_, i) => i + 1);
    const order = colourRows(count, a, b, new Uint8Array(count), new Float64Array(count + 1).fill(1));
    const tail = order.subarray(64 * 2);
    expect([...tail].filter((r) => r >= 0)).to.have.length(count - 64);
    for (let p = 0; p < tail.length; p += 2) expect(tail[p + 1]).to.equal(-1);
  });

  it('an immovable hub (a pinned particle with tethers) shares one colour among all its links', () => {
    const count = 100;
    const a = new Int32Array(count);
    const b = Int32Array.from({ length: count }, (_, i) => i + 1);
    const invMass = new Float64Array(count + 1).fill(1);
    invMass[0] = 0;
    const order = colourRows(count, a, b, new Uint8Array(count), invMass);
    expect(order.length).to.equal(count);
    expect([...order]).to.deep.equal(Array.from({ length: count }, (_, i) => i));
  });
});
