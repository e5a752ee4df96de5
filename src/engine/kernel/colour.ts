// Graph colouring of the distance constraints: constraints of one colour share no particle, so a batch of them can be
// solved lane-parallel (SIMD) and the sweep is still Gauss–Seidel across batches. Greedy, in row order, at most 64
// colours (two 32-bit masks per particle); a constraint that finds no free colour goes to a serial tail, one per
// packet. An immovable particle (inverse mass 0) is never written (its correction is 0·s), so it may appear in any
// number of lanes of a batch: the cloth's tethers to its pinned row would otherwise need a colour per tether. The
// colouring holds while those particles stay immovable: pins and static particles change only with the topology,
// and then the kernel colours again.
// Runs only when the constraints' structure changes (it allocates).

/**
 * The coloured order: rows by colour, each colour padded with -1 to a multiple of `lanes`, then the serial tail (each
 * row followed by lanes − 1 times -1); `lanes` consecutive entries form a packet. `slack`[row] is 1 for a link whose
 * limits differ (see visitOrder). `subset`: colour only these rows (the others are solved elsewhere: runs.ts).
 */
export function colourRows(count: number, a: Int32Array, b: Int32Array, slack: Uint8Array, invMass: Float64Array, lanes = 2, subset?: Int32Array): Int32Array {
  // Masks of the colours each movable particle takes part in; an immovable one's stay 0 and are never set.
  const low = new Uint32Array(invMass.length);
  const high = new Uint32Array(invMass.length);
  const colourOf = new Int8Array(count);
  const sizes = new Int32Array(64);
  let tail = 0;
  for (const i of visitOrder(count, slack, subset)) {
    const ia = a[i];
    const ib = b[i];
    const c = lowestFree(low[ia] | low[ib], high[ia] | high[ib]);
    colourOf[i] = c;
    if (c < 0) {
      tail++;
      continue;
    }
    sizes[c]++;
    if (invMass[ia] !== 0) take(low, high, ia, c);
    if (invMass[ib] !== 0) take(low, high, ib, c);
  }
  // Where each colour's batch starts (batches padded to whole packets), and the tail after them.
  const start = new Int32Array(65);
  for (let c = 0; c < 64; c++) start[c + 1] = start[c] + Math.ceil(sizes[c] / lanes) * lanes;
  const order = new Int32Array(start[64] + lanes * tail).fill(-1);
  const next = start.slice(0, 64);
  let t = start[64];
  for (const i of visitOrder(count, slack, subset)) {
    const c = colourOf[i];
    if (c < 0) {
      order[t] = i;
      t += lanes;
    } else order[next[c]++] = i;
  }
  return order;
}

/** Sticks first, then slack links (min < max), each in row order: within a colour the two kinds then fill packets of
 *  their own, and a packet of slack links within their limits is skipped whole. */
function visitOrder(count: number, slack: Uint8Array, subset?: Int32Array): Int32Array {
  const rows = subset ?? Int32Array.from({ length: count }, (_, i) => i);
  const order = new Int32Array(rows.length);
  let k = 0;
  for (const kind of [0, 1]) for (const i of rows) if (slack[i] === kind) order[k++] = i;
  return order;
}

function take(low: Uint32Array, high: Uint32Array, i: number, c: number): void {
  if (c < 32) low[i] |= 1 << c;
  else high[i] |= 1 << (c - 32);
}

/** The lowest colour set in neither mask, or -1 when all 64 are taken. */
function lowestFree(low: number, high: number): number {
  if (~low !== 0) return 31 - Math.clz32(~low & (low + 1));
  if (~high !== 0) return 32 + 31 - Math.clz32(~high & (high + 1));
  return -1;
}
