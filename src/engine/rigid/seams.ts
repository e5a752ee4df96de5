// Seams between static polygons. A floor built of flush pieces (tiles, or a concave ground's convex parts) has faces
// inside the solid: the side of the second piece, covered by the first piece's side. A box sliding over the join sinks
// into the first piece by the contact slop, so its front corner meets that covered face as it comes near, and the
// separating axis takes it (the "ghost edge"): the box was stopped, tipped or thrown over at the join. Such a face is
// marked internal here; collidePolygons (collide.ts) then answers from the other axes when the one it would take
// belongs to, or faces, an internal face.

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
  if (parts.length < 2) return;
  const boxes = parts.map((p) => {
    const v0 = shapes.partVertexStart[p];
    const v1 = v0 + shapes.partVertexCount[p];
    let [x0, y0, x1, y1] = [Infinity, Infinity, -Infinity, -Infinity];
    for (let v = v0; v < v1; v++) [x0, y0, x1, y1] = [Math.min(x0, wx[v]), Math.min(y0, wy[v]), Math.max(x1, wx[v]), Math.max(y1, wy[v])];
    return [x0, y0, x1, y1];
  });
  // Per face of each part: the intervals (along its tangent) that other parts' opposite faces on its line cover.
  for (let i = 0; i < parts.length; i++) {
    const p = parts[i];
    const v0 = shapes.partVertexStart[p];
    const n = shapes.partVertexCount[p];
    for (let k = 0; k < n; k++) {
      const a = v0 + k;
      const b = v0 + (k + 1 === n ? 0 : k + 1);
      const tx = -wny[a];
      const ty = wnx[a];
      const lo = wx[a] * tx + wy[a] * ty;
      const hi = wx[b] * tx + wy[b] * ty;
      const tol = SEAM_TOLERANCE * (1 + (hi - lo));
      const cover: [number, number][] = [];
      for (let j = 0; j < parts.length; j++) {
        if (j === i || !boxesMeet(boxes[i], boxes[j], tol) || !collideAlike(bodyOf[i], bodyOf[j])) continue;
        const u0 = shapes.partVertexStart[parts[j]];
        const m = shapes.partVertexCount[parts[j]];
        for (let h = 0; h < m; h++) {
          const c = u0 + h;
          const d = u0 + (h + 1 === m ? 0 : h + 1);
          // Opposite normals, and both of the other face's ends on this face's line.
          if (wnx[a] * wnx[c] + wny[a] * wny[c] > -1 + SEAM_TOLERANCE) continue;
          const off = (x: number, y: number) => Math.abs((x - wx[a]) * wnx[a] + (y - wy[a]) * wny[a]);
          if (off(wx[c], wy[c]) > tol || off(wx[d], wy[d]) > tol) continue;
          // It runs the other way along the line: from its end d to its start c.
          cover.push([wx[d] * tx + wy[d] * ty, wx[c] * tx + wy[c] * ty]);
        }
      }
      if (covers(cover, lo, hi, tol)) {
        shapes.internal[a] = 1;
        shapes.partInternal[p] = 1;
      }
    }
  }
}

function boxesMeet(a: number[], b: number[], tol: number): boolean {
  return a[0] <= b[2] + tol && b[0] <= a[2] + tol && a[1] <= b[3] + tol && b[1] <= a[3] + tol;
}

/** Whether the union of the intervals covers [lo, hi] (within tol). */
function covers(intervals: [number, number][], lo: number, hi: number, tol: number): boolean {
  intervals.sort((u, v) => u[0] - v[0]);
  let reached = lo;
  for (const [s, e] of intervals) {
    if (s > reached + tol) break;
    if (e > reached) reached = e;
  }
  return reached >= hi - tol;
}
