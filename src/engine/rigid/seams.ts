// Seams between static polygons. A floor built of flush pieces (tiles, or a concave ground's convex parts) has faces
// inside the solid: the side of the second piece, covered by the first piece's side. A box sliding over the join sinks
// into the first piece by the contact slop, so its front corner meets that covered face as it comes near, and the
// separating axis takes it (the "ghost edge"): the box was stopped, tipped or thrown over at the join. Such a face is
// marked internal here. In collide.ts, collidePolygons then answers from the other axes when the one it would take
// belongs to, or faces, an internal face; collidePolygonCircle leaves a circle past a seam to the neighbouring piece.

import { INTERNAL_FACE } from './collide.js';
import { BodyType, type RigidShapes } from './shapes.js';

/** Faces this close to each other (relative to 1 + their length) count as the same line, and as covering it. */
const SEAM_TOLERANCE = 1e-6;

/**
 * Marks each face of a static polygon part (`shapes.internal`, per vertex: the face from it to the next) that is
 * covered along its whole length by faces of other static parts lying on it, facing the other way; and each part
 * that has such a face (`shapes.partInternal`). Only parts of bodies that `collideAlike` (body slots) cover each other:
 * a neighbour that collides with other bodies, or with none, leaves the face a real boundary for some. From the world
 * vertices: call after updateWorld() when static bodies changed. Pairs of parts whose boxes are apart are skipped; the
 * rest is quadratic in the static parts near each other.
 */
export function findInternalFaces(shapes: RigidShapes, collideAlike: (a: number, b: number) => boolean): void {
  const { wx, wy, wnx, wny } = shapes;
  shapes.internal.fill(0);
  shapes.partInternal.fill(0);
  const parts: number[] = [];
  const bodyOf: number[] = [];
  for (let q = 0; q < shapes.polygonCount; q++) {
    const s = shapes.polygons[q];
    if (shapes.type[s] !== BodyType.Static) continue;
    for (let p = shapes.partStart[s], end = p + shapes.partCount[s]; p < end; p++) {
      parts.push(p);
      bodyOf.push(s);
    }
  }
  const n = parts.length;
  if (n < 2) return;
  // Each part's box and its tolerance (relative to 1 + its size: no face of it has a larger one).
  const box = new Float64Array(5 * n);
  let widest = 0;
  for (let i = 0; i < n; i++) {
    const v0 = shapes.partVertexStart[parts[i]];
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (let v = v0, end = v0 + shapes.partVertexCount[parts[i]]; v < end; v++) {
      if (wx[v] < x0) x0 = wx[v];
      if (wx[v] > x1) x1 = wx[v];
      if (wy[v] < y0) y0 = wy[v];
      if (wy[v] > y1) y1 = wy[v];
    }
    const tol = SEAM_TOLERANCE * (1 + Math.max(x1 - x0, y1 - y0));
    box.set([x0, y0, x1, y1, tol], 5 * i);
    if (tol > widest) widest = tol;
  }
  // Parts whose boxes meet and that collide alike, by a sweep along x (a tile map is thousands of parts).
  const order = Array.from({ length: n }, (_, i) => i).sort((i, j) => box[5 * i] - box[5 * j]);
  const near: number[][] = Array.from({ length: n }, () => []);
  for (let a = 0; a < n; a++) {
    const i = order[a];
    for (let b = a + 1; b < n; b++) {
      const j = order[b];
      if (box[5 * j] > box[5 * i + 2] + 2 * widest) break;
      const tol = box[5 * i + 4] + box[5 * j + 4];
      if (box[5 * j] > box[5 * i + 2] + tol || box[5 * i + 1] > box[5 * j + 3] + tol || box[5 * j + 1] > box[5 * i + 3] + tol) continue;
      if (!collideAlike(bodyOf[i], bodyOf[j])) continue;
      near[i].push(j);
      near[j].push(i);
    }
  }
  // Per face of each part: the intervals (along its tangent) that its neighbours' opposite faces on its line cover.
  const cover: number[] = [];
  for (let i = 0; i < n; i++) {
    if (near[i].length === 0) continue;
    const p = parts[i];
    const v0 = shapes.partVertexStart[p];
    const count = shapes.partVertexCount[p];
    for (let k = 0; k < count; k++) {
      const a = v0 + k;
      const b = v0 + (k + 1 === count ? 0 : k + 1);
      const [nx, ny] = [wnx[a], wny[a]];
      const lo = wx[a] * -ny + wy[a] * nx;
      const hi = wx[b] * -ny + wy[b] * nx;
      const tol = SEAM_TOLERANCE * (1 + (hi - lo));
      cover.length = 0;
      for (const j of near[i]) {
        const u0 = shapes.partVertexStart[parts[j]];
        const m = shapes.partVertexCount[parts[j]];
        for (let h = 0; h < m; h++) {
          const c = u0 + h;
          const d = u0 + (h + 1 === m ? 0 : h + 1);
          // Opposite normals, and both of the other face's ends on this face's line.
          if (nx * wnx[c] + ny * wny[c] > -1 + SEAM_TOLERANCE) continue;
          if (Math.abs((wx[c] - wx[a]) * nx + (wy[c] - wy[a]) * ny) > tol || Math.abs((wx[d] - wx[a]) * nx + (wy[d] - wy[a]) * ny) > tol) continue;
          // It runs the other way along the line: from its end d to its start c.
          cover.push(wx[d] * -ny + wy[d] * nx, wx[c] * -ny + wy[c] * nx);
        }
      }
      if (covers(cover, lo, hi, tol)) {
        shapes.internal[a] |= INTERNAL_FACE;
        shapes.partInternal[p] = 1;
      }
    }
  }
}

/** Whether the union of the intervals (flat: start, end, …) covers [lo, hi] (within tol). */
function covers(intervals: number[], lo: number, hi: number, tol: number): boolean {
  let reached = lo;
  // Few intervals (a face's neighbours): extend the reach by any that starts within it until none does.
  for (let grew = true; grew && reached < hi - tol; ) {
    grew = false;
    for (let k = 0; k < intervals.length; k += 2) {
      if (intervals[k] <= reached + tol && intervals[k + 1] > reached + tol) {
        reached = intervals[k + 1];
        grew = true;
      }
    }
  }
  return reached >= hi - tol;
}
