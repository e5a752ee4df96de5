// A cloth: a grid of columns × rows particles, row-major. The topology gives the grid and, once it tears, which of
// its links broke, so the renderer leaves those cells and links undrawn.
import type { BodyDescriptor, BuiltBody } from './descriptor.js';
import { CENTROID } from './pose.js';

/** Broken links as bits per grid node (see TopologyBody.torn), or undefined while the cloth is whole. */
function tornLinks({ world: w, handle, indices }: BuiltBody, columns: number): Uint8Array | undefined {
  let torn: Uint8Array | undefined;
  let gridOf: Map<number, number> | undefined;
  for (const h of w.bodyConstraintHandles(handle)) {
    if (w.constraintKindOf(h) !== 'distance' || !w.isBroken(h)) continue;
    gridOf ??= new Map(Array.from(indices, (slot, n) => [slot, n]));
    torn ??= new Uint8Array(indices.length);
    const [i, j] = w.distanceParticleIndices(h);
    const a = gridOf.get(i) ?? -1;
    const b = gridOf.get(j) ?? -1;
    const lo = Math.min(a, b);
    if (lo < 0) continue;
    if (Math.abs(a - b) === 1) torn[lo] |= 1;
    else if (Math.abs(a - b) === columns) torn[lo] |= 2;
  }
  return torn;
}

export const cloth: BodyDescriptor<'cloth'> = {
  grip: 'firm',
  pose: CENTROID,
  describe(t, d, body) {
    t.columns = d.columns;
    t.rows = d.rows;
    t.torn = tornLinks(body, d.columns);
  },
};
