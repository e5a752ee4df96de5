import { buildScene, catalogue, World, type SceneName } from '../../../src/engine/index.js';

/** Builds a catalogue scene with optional world overrides. */
export function scene(name: SceneName, world: Record<string, unknown> = {}) {
  const description = catalogue[name].make();
  description.world = { ...description.world, ...world };
  return buildScene(description);
}

/**
 * Deepest penetration of any body vertex into another polygon body (its distance inside the outline), by brute
 * force over all pairs. Bodies are given by their particle index lists (convex outlines, counter-clockwise).
 */
export function deepestPenetration(world: World, outlines: Int32Array[]): number {
  const { x, y } = world.particles;
  // Bounds prefilter keeps this O(n²) in pairs but cheap per pair.
  const bounds = outlines.map((idx) => {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const i of idx) {
      minX = Math.min(minX, x[i]); maxX = Math.max(maxX, x[i]);
      minY = Math.min(minY, y[i]); maxY = Math.max(maxY, y[i]);
    }
    return [minX, minY, maxX, maxY];
  });
  let worst = 0;
  for (let a = 0; a < outlines.length; a++) {
    const A = outlines[a];
    for (let b = 0; b < outlines.length; b++) {
      if (a === b) continue;
      const [ax0, ay0, ax1, ay1] = bounds[a];
      const [bx0, by0, bx1, by1] = bounds[b];
      if (ax0 > bx1 || bx0 > ax1 || ay0 > by1 || by0 > ay1) continue;
      for (const v of outlines[b]) {
        let inside = Infinity;
        for (let k = 0; k < A.length; k++) {
          const i0 = A[k];
          const i1 = A[(k + 1) % A.length];
          const ex = x[i1] - x[i0];
          const ey = y[i1] - y[i0];
          // Distance inside the edge (positive inside a counter-clockwise outline).
          inside = Math.min(inside, -((x[v] - x[i0]) * ey - (y[v] - y[i0]) * ex) / Math.sqrt(ex * ex + ey * ey));
        }
        worst = Math.max(worst, inside);
      }
    }
  }
  return worst;
}

/** A small deterministic random generator (mulberry32). */
export function random(seed: number): () => number {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}
