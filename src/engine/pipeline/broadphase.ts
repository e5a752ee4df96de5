import { grown } from '../table.js';
import type { Colliders } from './colliders.js';

/** Candidate pairs of body slots whose AABBs overlap, each pair once, a < b not implied. */
export class PairList {
  a = new Int32Array(256);
  b = new Int32Array(256);
  count = 0;
  push(a: number, b: number): void {
    if (this.count === this.a.length) {
      this.a = grown(this.a, this.count + 1);
      this.b = grown(this.b, this.count + 1);
    }
    this.a[this.count] = a;
    this.b[this.count] = b;
    this.count++;
  }
}

export interface BroadPhase {
  readonly name: 'grid' | 'brute';
  /** Fills `out` with every pair of active colliders whose AABBs overlap and that `accept` lets through. */
  findPairs(c: Colliders, accept: (a: number, b: number) => boolean, out: PairList): void;
}

/** Per collider slot: the largest motion of its pairs' other bodies (partnerMotions). Grown, never shrunk. */
let partnerMotion = new Float64Array(64);

/**
 * For each active collider, the largest `motion` among the colliders it is paired with: how far a partner may push it
 * this step; with `above`, only motions above it count (0 where no partner moves more: growPushedBodies looks only at
 * fast partners, and skips the stores for the pairs of slow bodies). The array is shared (valid until the next call).
 */
export function partnerMotions(c: Colliders, pairs: PairList, motion: Float64Array, above = 0): Float64Array {
  if (partnerMotion.length < motion.length) partnerMotion = grown(partnerMotion, motion.length);
  const pushed = partnerMotion;
  for (let k = 0; k < c.activeCount; k++) pushed[c.active[k]] = 0;
  const pairA = pairs.a;
  const pairB = pairs.b;
  // Motions are ≥ 0 and pushed starts at 0, so above = 0 keeps every partner's largest motion.
  for (let k = 0, n = pairs.count; k < n; k++) {
    const a = pairA[k];
    const b = pairB[k];
    const ma = motion[a];
    const mb = motion[b];
    if (mb > above && mb > pushed[a]) pushed[a] = mb;
    if (ma > above && ma > pushed[b]) pushed[b] = ma;
  }
  return pushed;
}

/** Whether the AABBs of colliders a and b overlap. */
export function overlaps(c: Colliders, a: number, b: number): boolean {
  return c.minX[a] <= c.maxX[b] && c.minX[b] <= c.maxX[a] && c.minY[a] <= c.maxY[b] && c.minY[b] <= c.maxY[a];
}

/** Per active index: the cells its AABB spans, floor(minX / cell), floor(minY / cell), floor(maxX / cell), floor(maxY / cell) (scratch of findPairs). */
let cellSpans = new Float64Array(256);
/** One count per cell key: the broad phase's counting sort, when the keys in use span few cells (scratch). */
let cellCounts = new Uint32Array(1024);
/** Per collider slot: its AABB as minX, minY, maxX, maxY side by side (one cache line for the pair loop's test). */
let boxes = new Float64Array(256);

/** O(n²): every pair tested. The oracle for tests and the seed's comparison. */
export class BruteForceBroadPhase implements BroadPhase {
  readonly name = 'brute';
  findPairs(c: Colliders, accept: (a: number, b: number) => boolean, out: PairList): void {
    out.count = 0;
    for (let i = 0; i < c.activeCount; i++) {
      const a = c.active[i];
      for (let j = i + 1; j < c.activeCount; j++) {
        const b = c.active[j];
        if (overlaps(c, a, b) && accept(a, b)) out.push(a, b);
      }
    }
  }
}

/**
 * Uniform grid rebuilt every step (seed 5.2). Each AABB emits (cell key, body) for every cell it touches; the pairs
 * are sorted by key with an LSD radix sort and runs of equal keys give the candidates. Cell coordinates are taken
 * relative to the lowest cell in use, so the key ix·rows + iy is unique per cell for negative and very large
 * coordinates alike (the cell size grows if the scene would need more than 2³² cells). A pair is reported only from
 * the cell holding the lower-left corner of the two AABBs' overlap, so it is reported once without a hash set.
 * Bodies covering more than `maxCellsPerBody` cells (walls, floors) are tested against everything directly.
 */
export class GridBroadPhase implements BroadPhase {
  readonly name = 'grid';
  /** Cell size; 0 = automatic (twice the median AABB extent of the dynamic bodies). */
  cellSize = 0;
  maxCellsPerBody = 64;
  /** The cell size used in the last findPairs (for debug drawing). */
  lastCellSize = 1;
  lastOriginX = 0;
  lastOriginY = 0;

  private keys = new Uint32Array(1024);
  private values = new Uint32Array(1024);
  private keysTmp = new Uint32Array(1024);
  private valuesTmp = new Uint32Array(1024);
  private large = new Int32Array(16);
  private extents = new Float64Array(16);
  private readonly counts = new Uint32Array(256);

  findPairs(c: Colliders, accept: (a: number, b: number) => boolean, out: PairList): void {
    out.count = 0;
    const n = c.activeCount;
    if (n < 2) return;
    const cell = this.chooseCellSize(c);
    const inv = 1 / cell;
    if (cellSpans.length < 4 * n) cellSpans = new Float64Array(4 * c.active.length);
    const span = cellSpans;
    // Each body's cell span (floors kept for the emission below), and the cell range in use.
    let loX = Infinity;
    let loY = Infinity;
    let hiX = -Infinity;
    let hiY = -Infinity;
    for (let i = 0; i < n; i++) {
      const s = c.active[i];
      const x0 = Math.floor(c.minX[s] * inv);
      const y0 = Math.floor(c.minY[s] * inv);
      const x1 = Math.floor(c.maxX[s] * inv);
      const y1 = Math.floor(c.maxY[s] * inv);
      span[4 * i] = x0;
      span[4 * i + 1] = y0;
      span[4 * i + 2] = x1;
      span[4 * i + 3] = y1;
      if (x0 < loX) loX = x0;
      if (y0 < loY) loY = y0;
      if (x1 > hiX) hiX = x1;
      if (y1 > hiY) hiY = y1;
    }
    const rows = hiY - loY + 1;
    const cellsInUse = (hiX - loX + 1) * rows;
    if (!Number.isFinite(cellsInUse)) {
      // A box reaching to infinity (a body given a speed past any limit): no grid spans it; every pair is tested.
      bruteForce.findPairs(c, accept, out);
      return;
    }
    if (cellsInUse > 0xffffffff) {
      // Sparse scene over a huge extent: coarser cells keep keys unique in 32 bits.
      const saved = this.cellSize;
      this.cellSize = cell * 2;
      this.findPairs(c, accept, out);
      this.cellSize = saved;
      return;
    }
    this.lastCellSize = cell;
    this.lastOriginX = loX * cell;
    this.lastOriginY = loY * cell;

    // Few cells for the bodies (a pile in a container): the entries are counted per cell as they are made and placed
    // in one pass (a counting sort); otherwise sorted by LSD radix. Both are stable: the same order.
    const counting = cellsInUse < 4 * n + 1024;
    if (counting) {
      if (cellCounts.length <= cellsInUse) cellCounts = new Uint32Array(Math.max(cellsInUse + 1, 2 * cellCounts.length));
      cellCounts.fill(0, 0, cellsInUse);
    }
    const counts = cellCounts;
    let m = 0;
    let largeCount = 0;
    this.large = grown(this.large, n);
    if (boxes.length < 4 * c.minX.length) boxes = new Float64Array(4 * c.minX.length);
    const box = boxes;
    for (let i = 0; i < n; i++) {
      const s = c.active[i];
      const x0 = span[4 * i] - loX;
      const y0 = span[4 * i + 1] - loY;
      const x1 = span[4 * i + 2] - loX;
      const y1 = span[4 * i + 3] - loY;
      const cells = (x1 - x0 + 1) * (y1 - y0 + 1);
      // Not a number of cells (a box that is NaN, which no step should make): with the large ones, where every
      // comparison with it fails, so it pairs with nothing instead of sizing the arrays.
      if (!(cells <= this.maxCellsPerBody)) {
        this.large[largeCount++] = s;
        continue;
      }
      box[4 * s] = c.minX[s];
      box[4 * s + 1] = c.minY[s];
      box[4 * s + 2] = c.maxX[s];
      box[4 * s + 3] = c.maxY[s];
      this.reserve(m + cells);
      const keys = this.keys;
      const values = this.values;
      // Each entry carries the body's slot and two bits: whether the body's lower-left corner cell is this cell's
      // column (1) and row (2). A pair is reported only from the cell holding the lower-left corner of the two boxes'
      // overlap: floor(max(minX_a, minX_b) / cell) is the larger of the two corner cells (floor and a rounded product
      // are monotonic), so with both bodies in this cell, the pair belongs to it when one of them has the column bit
      // and one the row bit.
      for (let x = x0; x <= x1; x++) {
        const inX = x === x0 ? 1 : 0;
        for (let y = y0; y <= y1; y++) {
          const key = x * rows + y;
          keys[m] = key;
          values[m] = s * 4 + inX + (y === y0 ? 2 : 0);
          m++;
          if (counting) counts[key]++;
        }
      }
    }
    let values: Uint32Array;
    if (counting) {
      let sum = 0;
      for (let k = 0; k < cellsInUse; k++) {
        const count = counts[k];
        counts[k] = sum;
        sum += count;
      }
      const keys = this.keys;
      const from = this.values;
      values = this.valuesTmp;
      for (let i = 0; i < m; i++) values[counts[keys[i]]++] = from[i];
      // counts[k] is now the end of cell k's entries.
      for (let k = 0, start = 0; k < cellsInUse; k++) {
        const end = counts[k];
        if (end - start > 1) cellPairs(values, start, end, box, accept, out);
        start = end;
      }
    } else {
      this.radixSort(m);
      const keys = this.keys;
      values = this.values;
      for (let start = 0; start < m; ) {
        const key = keys[start];
        let end = start + 1;
        while (end < m && keys[end] === key) end++;
        if (end - start > 1) cellPairs(values, start, end, box, accept, out);
        start = end;
      }
    }
    // Large bodies against everything (large–large pairs once). The overlap is tested first, on the packed boxes
    // (each wall of a pile meets most bodies only there), and only a body that overlaps is looked up in the list of
    // large ones: the same tests, in an order that leaves the same pairs in the same order.
    for (let k = 0; k < largeCount; k++) {
      const s = this.large[k];
      box[4 * s] = c.minX[s];
      box[4 * s + 1] = c.minY[s];
      box[4 * s + 2] = c.maxX[s];
      box[4 * s + 3] = c.maxY[s];
    }
    const active = c.active;
    for (let k = 0; k < largeCount; k++) {
      const a = this.large[k];
      const aMinX = box[4 * a];
      const aMinY = box[4 * a + 1];
      const aMaxX = box[4 * a + 2];
      const aMaxY = box[4 * a + 3];
      for (let i = 0; i < n; i++) {
        const b = active[i];
        const q = 4 * b;
        if (!(aMinX <= box[q + 2] && box[q] <= aMaxX && aMinY <= box[q + 3] && box[q + 1] <= aMaxY)) continue;
        if (b === a) continue;
        if (b < a && this.isLarge(b, largeCount)) continue;
        if (accept(a, b)) out.push(a, b);
      }
    }
  }

  private isLarge(slot: number, count: number): boolean {
    for (let k = 0; k < count; k++) if (this.large[k] === slot) return true;
    return false;
  }

  /**
   * The cell size chosen automatically at the first step after the bodies changed (0: not chosen yet). Part of the
   * state: chosen again from other positions, it would find the same pairs in another order.
   */
  autoCellSize = 0;

  /** The bodies changed: choose the automatic cell size again at the next step. */
  invalidateCellSize(): void {
    this.autoCellSize = 0;
  }

  private chooseCellSize(c: Colliders): number {
    if (this.cellSize > 0) return this.cellSize;
    if (this.autoCellSize === 0) this.autoCellSize = this.medianCellSize(c);
    return this.autoCellSize;
  }

  private medianCellSize(c: Colliders): number {
    const n = c.activeCount;
    this.extents = grown(this.extents, n);
    let m = 0;
    for (let i = 0; i < n; i++) {
      const s = c.active[i];
      if (c.isStatic[s]) continue;
      this.extents[m++] = Math.max(c.maxX[s] - c.minX[s], c.maxY[s] - c.minY[s]);
    }
    if (m === 0) return 1;
    const sorted = this.extents.subarray(0, m).sort();
    const median = sorted[m >> 1];
    return median > 0 ? 2 * median : 1;
  }

  private reserve(n: number): void {
    if (n <= this.keys.length) return;
    this.keys = grown(this.keys, n);
    this.values = grown(this.values, n);
    this.keysTmp = grown(this.keysTmp, n);
    this.valuesTmp = grown(this.valuesTmp, n);
  }

  /** LSD radix sort of (key, value) by key, 8 bits a pass; passes whose byte is zero for all keys are skipped. */
  private radixSort(n: number): void {
    let keys = this.keys;
    let values = this.values;
    let keysTmp = this.keysTmp;
    let valuesTmp = this.valuesTmp;
    const counts = this.counts;
    let maxKey = 0;
    for (let i = 0; i < n; i++) if (keys[i] > maxKey) maxKey = keys[i];
    for (let shift = 0; shift < 32; shift += 8) {
      if (maxKey >>> shift === 0) break;
      counts.fill(0);
      for (let i = 0; i < n; i++) counts[(keys[i] >>> shift) & 255]++;
      let sum = 0;
      for (let b = 0; b < 256; b++) {
        const c = counts[b];
        counts[b] = sum;
        sum += c;
      }
      for (let i = 0; i < n; i++) {
        const d = counts[(keys[i] >>> shift) & 255]++;
        keysTmp[d] = keys[i];
        valuesTmp[d] = values[i];
      }
      [keys, keysTmp] = [keysTmp, keys];
      [values, valuesTmp] = [valuesTmp, values];
    }
    this.keys = keys;
    this.values = values;
    this.keysTmp = keysTmp;
    this.valuesTmp = valuesTmp;
  }
}

/**
 * The pairs of one cell's entries [start, end) (slot · 4 + corner bits, in active order) whose boxes overlap and that
 * belong to this cell (one entry with the column bit, one with the row bit), in entry order.
 */
function cellPairs(values: Uint32Array, start: number, end: number, box: Float64Array, accept: (a: number, b: number) => boolean, out: PairList): void {
  for (let i = start; i < end - 1; i++) {
    const va = values[i];
    const a = va >>> 2;
    const aBits = va & 3;
    const aMinX = box[4 * a];
    const aMinY = box[4 * a + 1];
    const aMaxX = box[4 * a + 2];
    const aMaxY = box[4 * a + 3];
    for (let j = i + 1; j < end; j++) {
      const vb = values[j];
      if (((aBits | vb) & 3) !== 3) continue;
      const q = 4 * (vb >>> 2);
      if (aMinX <= box[q + 2] && box[q] <= aMaxX && aMinY <= box[q + 3] && box[q + 1] <= aMaxY && accept(a, vb >>> 2)) out.push(a, vb >>> 2);
    }
  }
}

const bruteForce = new BruteForceBroadPhase();

export function makeBroadPhase(kind: 'grid' | 'brute', cellSize: number): BroadPhase {
  if (kind === 'brute') return new BruteForceBroadPhase();
  const grid = new GridBroadPhase();
  grid.cellSize = cellSize;
  return grid;
}
