// Runs of distance constraints for the kernel's contiguous sweep (solver.as): constraints whose particles step by one
// row from one to the next, found in any table order, with no knowledge of what built them. A cloth's vertical links
// (r·C + c, (r+1)·C + c), its diagonals and a pinned row's tethers (c, r·C + c) are "parallel" runs (lanes a + k,
// b + k with b − a ≥ 2, so two consecutive lanes share no particle); a row's or a chain's links (i, i + 1) are two
// "interleaved" runs, the even and the odd ones (lanes a + 2k, a + 2k + 1). A run is cut into chunks of at most
// MAX_LANES lanes, and the chunks are ordered by the highest particle they start on: the sweep then moves through the
// particle columns as a wavefront (rows r and r + 1 of a cloth, with every kind of link between them, while they are in
// cache) instead of once per family of links. Rigid limits (tethers, slack links) come after every stick and compliant
// link, in their own wavefront: interleaved with the sticks, a tether clamping a particle mid-sweep makes a rigid cloth
// unstable (measured: a 40×40 rigid cloth with shear links reaches 25–130% strain in three steps; with the tethers last,
// 0.002%, as in table order). Whatever forms no run of two lanes is left for the coloured packets.
// Runs only when the constraints' structure changes (it allocates).

/** How a run's lanes are solved: rigid sticks (one length), rigid limits (slack links, tethers), compliant links. */
export const enum RunKind {
  Stick = 0,
  Limits = 1,
  Compliant = 2,
}

/** Lanes per chunk at most (even: only a run's last chunk may end with a padding lane). */
export const MAX_LANES = 64;

export interface RunLayout {
  /** Per chunk: its first lane's lower and higher particle, its lane count, whether interleaved, its kind. */
  first: Int32Array;
  second: Int32Array;
  lanes: Int32Array;
  interleaved: Uint8Array;
  kind: Uint8Array;
  /** Where each chunk's lanes start in `rows` (each chunk padded to an even number of lanes). */
  laneStart: Int32Array;
  /** The distance row each lane solves, in sweep order; -1 for a padding lane. */
  rows: Int32Array;
  /** Rows in no run (for the coloured packets), in row order. */
  leftover: Int32Array;
}

/** The kind of distance row `i` (see RunKind). */
export function kindOf(minLength: Float64Array, maxLength: Float64Array, compliance: Float64Array, i: number): RunKind {
  if (compliance[i] !== 0) return RunKind.Compliant;
  return minLength[i] === maxLength[i] ? RunKind.Stick : RunKind.Limits;
}

/** Finds the runs among `count` distance rows (particles a, b; kinds from the limits and compliance). */
export function findRuns(count: number, a: Int32Array, b: Int32Array, minLength: Float64Array, maxLength: Float64Array, compliance: Float64Array): RunLayout {
  const lo = new Int32Array(count);
  const hi = new Int32Array(count);
  // Sort key: (b − a, kind, parity of a for neighbour links, a), exact in a double for up to 2^24 particles.
  const key = new Float64Array(count);
  for (let i = 0; i < count; i++) {
    lo[i] = Math.min(a[i], b[i]);
    hi[i] = Math.max(a[i], b[i]);
    const d = hi[i] - lo[i];
    const group = (d * 3 + kindOf(minLength, maxLength, compliance, i)) * 2 + (d === 1 ? lo[i] & 1 : 0);
    key[i] = group * 16777216 + lo[i];
  }
  const order = new Int32Array(count);
  for (let i = 0; i < count; i++) order[i] = i;
  order.sort((i, j) => key[i] - key[j] || i - j);

  // Maximal runs in the sorted order, cut into chunks.
  const chunks: number[] = []; // start index into `order`, lane count, repeated
  const leftover: number[] = [];
  for (let s = 0; s < count; ) {
    const r0 = order[s];
    const d = hi[r0] - lo[r0];
    const group = Math.floor(key[r0] / 16777216);
    const step = d === 1 ? 2 : 1;
    let e = s + 1;
    if (d > 0) while (e < count && Math.floor(key[order[e]] / 16777216) === group && lo[order[e]] === lo[order[e - 1]] + step) e++;
    if (e - s === 1) leftover.push(r0);
    else for (let c = s; c < e; c += MAX_LANES) chunks.push(c, Math.min(MAX_LANES, e - c));
    s = e;
  }

  // Chunks by the highest particle of their first lane (stable: ties keep the sorted order).
  const n = chunks.length / 2;
  const byStart = Array.from({ length: n }, (_, k) => k);
  const late = (k: number): number => (kindOf(minLength, maxLength, compliance, order[chunks[2 * k]]) === RunKind.Limits ? 1 : 0);
  byStart.sort((p, q) => late(p) - late(q) || hi[order[chunks[2 * p]]] - hi[order[chunks[2 * q]]] || p - q);
  const layout: RunLayout = {
    first: new Int32Array(n),
    second: new Int32Array(n),
    lanes: new Int32Array(n),
    interleaved: new Uint8Array(n),
    kind: new Uint8Array(n),
    laneStart: new Int32Array(n + 1),
    rows: new Int32Array(0),
    leftover: Int32Array.from(leftover.sort((p, q) => p - q)),
  };
  let laneTotal = 0;
  byStart.forEach((k, m) => {
    const start = chunks[2 * k];
    const lanes = chunks[2 * k + 1];
    const r0 = order[start];
    layout.first[m] = lo[r0];
    layout.second[m] = hi[r0];
    layout.lanes[m] = lanes;
    layout.interleaved[m] = hi[r0] - lo[r0] === 1 ? 1 : 0;
    layout.kind[m] = kindOf(minLength, maxLength, compliance, r0);
    layout.laneStart[m] = laneTotal;
    laneTotal += lanes + (lanes & 1);
  });
  layout.laneStart[n] = laneTotal;
  const rows = new Int32Array(laneTotal).fill(-1);
  byStart.forEach((k, m) => {
    const start = chunks[2 * k];
    for (let l = 0; l < chunks[2 * k + 1]; l++) rows[layout.laneStart[m] + l] = order[start + l];
  });
  layout.rows = rows;
  return layout;
}
