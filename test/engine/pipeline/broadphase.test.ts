import { expect } from 'chai';
import { BruteForceBroadPhase, GridBroadPhase, PairList } from '../../../src/engine/pipeline/broadphase.js';
import { Colliders } from '../../../src/engine/pipeline/colliders.js';
import { random } from './scene-helpers.js';

/** Colliders holding n random AABBs: centres spread over ±extent, sizes from tiny to large, some huge bodies. */
function randomColliders(n: number, extent: number, rnd: () => number): Colliders {
  const c = new Colliders();
  c.ensureBodies(n);
  c.active = new Int32Array(n);
  for (let s = 0; s < n; s++) {
    const size = rnd() < 0.05 ? extent * rnd() : 10 ** (rnd() * 4 - 3); // 1e-3 .. 10, a few huge
    const cx = (rnd() * 2 - 1) * extent;
    const cy = (rnd() * 2 - 1) * extent;
    const w = size * (0.2 + rnd());
    const h = size * (0.2 + rnd());
    c.minX[s] = cx - w;
    c.maxX[s] = cx + w;
    c.minY[s] = cy - h;
    c.maxY[s] = cy + h;
    c.isStatic[s] = rnd() < 0.1 ? 1 : 0;
    c.active[c.activeCount++] = s;
  }
  return c;
}

function pairSet(list: PairList): { keys: Set<string>; duplicates: number } {
  const keys = new Set<string>();
  let duplicates = 0;
  for (let k = 0; k < list.count; k++) {
    const a = Math.min(list.a[k], list.b[k]);
    const b = Math.max(list.a[k], list.b[k]);
    const key = `${a}:${b}`;
    if (keys.has(key)) duplicates++;
    keys.add(key);
  }
  return { keys, duplicates };
}

describe('pipeline: broad phase', () => {
  it('the grid finds exactly the pairs brute force finds, each once, on 200 random scenes', () => {
    const rnd = random(42);
    const accept = () => true;
    let totalPairs = 0;
    for (let scene = 0; scene < 200; scene++) {
      const extent = [1, 100, 1e4, 1e6][scene % 4];
      const n = 20 + Math.floor(rnd() * 300);
      const c = randomColliders(n, extent * (scene % 8 < 4 ? 1 : 0.01), rnd);
      // Shift half the scenes far into negative coordinates.
      if (scene % 2) for (let s = 0; s < n; s++) {
        c.minX[s] -= 3e6;
        c.maxX[s] -= 3e6;
        c.minY[s] -= 5e5;
        c.maxY[s] -= 5e5;
      }
      const grid = new GridBroadPhase();
      grid.cellSize = scene % 3 === 0 ? 0 : 10 ** (rnd() * 4 - 2);
      const gridPairs = new PairList();
      const brutePairs = new PairList();
      grid.findPairs(c, accept, gridPairs);
      new BruteForceBroadPhase().findPairs(c, accept, brutePairs);
      const g = pairSet(gridPairs);
      const b = pairSet(brutePairs);
      expect(g.duplicates, `scene ${scene}: duplicates`).to.equal(0);
      expect(g.keys.size, `scene ${scene}: pair count`).to.equal(b.keys.size);
      for (const key of b.keys) expect(g.keys.has(key), `scene ${scene}: missing ${key}`).to.equal(true);
      totalPairs += b.keys.size;
    }
    expect(totalPairs).to.be.above(1000); // the scenes really overlap
  });

  it('lists the grid pairs cell by cell (the cell of the overlap\'s lower-left corner), lower slot first within a cell, large bodies last', () => {
    // The order is part of the result (the solver sweeps contacts in it): a pile in a small grid (keys sorted by
    // counting) and scenes spread over many cells (sorted byte by byte) must give the same order, checked here from
    // its definition against brute force.
    const rnd = random(11);
    let checked = 0;
    for (let scene = 0; scene < 60; scene++) {
      const n = 30 + Math.floor(rnd() * 400);
      const c = randomColliders(n, [3, 30, 1e3, 1e6][scene % 4], rnd);
      const grid = new GridBroadPhase();
      grid.cellSize = scene % 2 ? 0 : 0.05 + rnd() * 3;
      const out = new PairList();
      grid.findPairs(c, () => true, out);
      const cell = grid.lastCellSize;
      const inv = 1 / cell;
      const loX = Math.round(grid.lastOriginX / cell);
      const loY = Math.round(grid.lastOriginY / cell);
      let hiY = -Infinity;
      for (let s = 0; s < n; s++) hiY = Math.max(hiY, Math.floor(c.maxY[s] * inv));
      const rows = hiY - loY + 1;
      const large = (s: number) =>
        (Math.floor(c.maxX[s] * inv) - Math.floor(c.minX[s] * inv) + 1) * (Math.floor(c.maxY[s] * inv) - Math.floor(c.minY[s] * inv) + 1) > grid.maxCellsPerBody;
      const brute = new PairList();
      new BruteForceBroadPhase().findPairs(c, () => true, brute);
      const expected: [number, number, number][] = [];
      for (let k = 0; k < brute.count; k++) {
        const a = brute.a[k];
        const b = brute.b[k];
        if (large(a) || large(b)) continue;
        const key = (Math.floor(Math.max(c.minX[a], c.minX[b]) * inv) - loX) * rows + (Math.floor(Math.max(c.minY[a], c.minY[b]) * inv) - loY);
        expected.push([key, a, b]);
      }
      expected.sort((p, q) => p[0] - q[0] || p[1] - q[1] || p[2] - q[2]);
      expect(out.count, `scene ${scene}`).to.be.at.least(expected.length);
      for (let k = 0; k < expected.length; k++) {
        expect([out.a[k], out.b[k]], `scene ${scene}, pair ${k}`).to.deep.equal([expected[k][1], expected[k][2]]);
      }
      for (let k = expected.length; k < out.count; k++) expect(large(out.a[k]) || large(out.b[k]), `scene ${scene}, pair ${k}`).to.equal(true);
      checked += expected.length;
    }
    expect(checked).to.be.above(2000);
  });

  it('filters pairs through the accept callback', () => {
    const rnd = random(7);
    const c = randomColliders(200, 5, rnd);
    const out = new PairList();
    new GridBroadPhase().findPairs(c, (a, b) => (a + b) % 2 === 0, out);
    expect(out.count).to.be.above(0);
    for (let k = 0; k < out.count; k++) expect((out.a[k] + out.b[k]) % 2).to.equal(0);
  });
});
