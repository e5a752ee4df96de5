import { buildScene, catalogue, World, type BodyDescription, type Handle, type SceneName, type Vec2 } from '../../../src/engine/index.js';

/** Builds a catalogue scene with optional world overrides; `description` is what it was built from. */
export function scene(name: SceneName, world: Record<string, unknown> = {}) {
  const description = catalogue[name].make();
  description.world = { ...description.world, ...world };
  return { ...buildScene(description), description };
}

/**
 * A box's outline in world coordinates, counter-clockwise in the engine's y-down frame as the particle frames are:
 * from its rigid pose and its described size, or from its corner particles when it is a frame of particles.
 */
export function boxOutline(world: World, body: Handle, d: BodyDescription): Vec2[] {
  if (d.type !== 'box') throw new TypeError(`boxOutline takes boxes, got ${d.type}`);
  const idx = world.bodyParticleIndices(body);
  const { x, y } = world.particles;
  if (idx.length === 4) return [...idx].map((i) => ({ x: x[i], y: y[i] }));
  const pose = world.bodyPose(body);
  const [c, s] = [Math.cos(pose.angle), Math.sin(pose.angle)];
  const [w, h] = [d.width / 2, d.height / 2];
  return [[-w, -h], [w, -h], [w, h], [-w, h]].map(([lx, ly]) => ({ x: pose.x + lx * c - ly * s, y: pose.y + lx * s + ly * c }));
}

/**
 * Deepest penetration of any body vertex into another convex outline (its distance inside the outline), by brute
 * force over all pairs. Outlines are world-space vertex lists in the frames' winding (boxOutline).
 */
export function deepestPenetration(outlines: Vec2[][]): number {
  // Bounds prefilter keeps this O(n²) in pairs but cheap per pair.
  const bounds = outlines.map((points) => {
    let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
    for (const p of points) {
      minX = Math.min(minX, p.x); maxX = Math.max(maxX, p.x);
      minY = Math.min(minY, p.y); maxY = Math.max(maxY, p.y);
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
          const p0 = A[k];
          const p1 = A[(k + 1) % A.length];
          const ex = p1.x - p0.x;
          const ey = p1.y - p0.y;
          // Distance inside the edge (positive inside a counter-clockwise outline).
          inside = Math.min(inside, -((v.x - p0.x) * ey - (v.y - p0.y) * ex) / Math.sqrt(ex * ex + ey * ey));
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
