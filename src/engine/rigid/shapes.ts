import { grown } from '../table.js';
import type { BodyRows } from './rows.js';
import type { PolygonRef } from './collide.js';

/** A rigid body's collision shape. */
export const enum RigidShapeKind {
  None = 0,
  /** Convex parts (one for a convex outline; a concave outline's decomposition). */
  Polygon = 1,
  /** A disc of `radius` about the centre of mass. */
  Circle = 2,
}

/** How a rigid body moves. */
export const enum BodyType {
  Dynamic = 0,
  Static = 1,
  /** Moved by its velocity and angular velocity alone; pushes what it touches, nothing pushes it. */
  Kinematic = 2,
}
export const BODY_TYPES = ['dynamic', 'static', 'kinematic'] as const;
export type BodyTypeName = (typeof BODY_TYPES)[number];

/** What a rigid body is made of, in its own frame with the centre of mass at the origin. */
export interface RigidShapeSource {
  kind: RigidShapeKind;
  /** Convex parts, counter-clockwise, each a flat list x0, y0, x1, y1, … (Polygon). */
  parts: Float64Array[];
  radius: number;
  /** The centre of mass in the body's own coordinates (where its points were given): pose = centre − R·centroid. */
  centroidX: number;
  centroidY: number;
  /** Mass and moment of inertia about the centre of mass (what a dynamic body moves with). */
  mass: number;
  inertia: number;
  /** Farthest point of the shape from the centre of mass. */
  extent: number;
}

/**
 * Rigid shapes per body slot: vertices and outward unit normals in the body's frame (centre of mass at the origin),
 * and the same in world coordinates for the current step, written once a step by updateWorld(). Parts of all bodies
 * share one vertex pool, packed by rebuild() whenever bodies are added or removed (never inside step()).
 */
export class RigidShapes {
  kind = new Uint8Array(16);
  /** BodyType per slot. */
  type = new Uint8Array(16);
  /** The body's row in the particle store (its centre of mass). */
  row = new Int32Array(16);
  radius = new Float64Array(16);
  partStart = new Int32Array(16);
  partCount = new Int32Array(16);
  /** Per part: its vertices [start, start + count) in the pool. */
  partVertexStart = new Int32Array(16);
  partVertexCount = new Int32Array(16);
  partsUsed = 0;
  /** Vertex pool: body frame, then world (this step). */
  lx = new Float64Array(64);
  ly = new Float64Array(64);
  lnx = new Float64Array(64);
  lny = new Float64Array(64);
  wx = new Float64Array(64);
  wy = new Float64Array(64);
  wnx = new Float64Array(64);
  wny = new Float64Array(64);
  verticesUsed = 0;
  /**
   * Per vertex of a static part: INTERNAL_FACE when the face from it to the next is covered by other static parts (a
   * seam inside a floor of flush pieces: rigid/seams.ts); per part: 1 when it has such a face. Found again when
   * `staticsMoved`.
   */
  internal = new Uint8Array(64);
  partInternal = new Uint8Array(16);
  /** Static polygons were added, removed or moved since their seams were found. */
  staticsMoved = true;
  /** Dense list of the slots holding a polygon (for updateWorld). */
  polygons = new Int32Array(16);
  polygonCount = 0;
  private sources: (RigidShapeSource | undefined)[] = [];
  private rows: number[] = [];

  /** Gives body `slot` (row `row`) its shape; takes effect at the next rebuild(). */
  set(slot: number, row: number, source: RigidShapeSource, type: BodyType): void {
    this.sources[slot] = source;
    this.rows[slot] = row;
    this.type = grown(this.type, slot + 1);
    this.row = grown(this.row, slot + 1);
    this.type[slot] = type;
    this.row[slot] = row;
  }

  clear(slot: number): void {
    this.sources[slot] = undefined;
  }

  source(slot: number): RigidShapeSource | undefined {
    return this.sources[slot];
  }

  /** Packs every live shape into the pools (after bodies changed). */
  rebuild(slots: number): void {
    for (const name of ['kind', 'type', 'row', 'radius', 'partStart', 'partCount', 'polygons'] as const) {
      (this as unknown as Record<string, Float64Array>)[name] = grown((this as unknown as Record<string, Float64Array>)[name], slots);
    }
    this.partsUsed = 0;
    this.verticesUsed = 0;
    this.polygonCount = 0;
    this.staticsMoved = true;
    for (let s = 0; s < slots; s++) {
      const src = this.sources[s];
      this.kind[s] = src ? src.kind : RigidShapeKind.None;
      this.partCount[s] = 0;
      if (!src) continue;
      this.row[s] = this.rows[s];
      this.radius[s] = src.radius;
      if (src.kind !== RigidShapeKind.Polygon) continue;
      this.polygons[this.polygonCount++] = s;
      this.partStart[s] = this.partsUsed;
      this.partCount[s] = src.parts.length;
      for (const part of src.parts) this.addPart(part);
    }
  }

  private addPart(flat: Float64Array): void {
    const n = flat.length / 2;
    const p = this.partsUsed++;
    this.partVertexStart = grown(this.partVertexStart, p + 1);
    this.partVertexCount = grown(this.partVertexCount, p + 1);
    this.partInternal = grown(this.partInternal, p + 1);
    const start = this.verticesUsed;
    this.partVertexStart[p] = start;
    this.partVertexCount[p] = n;
    for (const name of ['lx', 'ly', 'lnx', 'lny', 'wx', 'wy', 'wnx', 'wny'] as const) this[name] = grown(this[name], start + n);
    this.internal = grown(this.internal, start + n);
    for (let k = 0; k < n; k++) {
      const k2 = k + 1 === n ? 0 : k + 1;
      const ex = flat[2 * k2] - flat[2 * k];
      const ey = flat[2 * k2 + 1] - flat[2 * k + 1];
      const len = Math.sqrt(ex * ex + ey * ey);
      this.lx[start + k] = flat[2 * k];
      this.ly[start + k] = flat[2 * k + 1];
      this.lnx[start + k] = ey / len;
      this.lny[start + k] = -ex / len;
    }
    this.verticesUsed += n;
  }

  /** World vertices and normals of every polygon from the bodies' poses (once a step, before collision detection). */
  updateWorld(r: BodyRows): void {
    const { x, y, rc, rs } = r;
    const { lx, ly, lnx, lny, wx, wy, wnx, wny } = this;
    for (let q = 0; q < this.polygonCount; q++) {
      const s = this.polygons[q];
      const i = this.row[s];
      const c = rc[i];
      const sn = rs[i];
      const ox = x[i];
      const oy = y[i];
      const p0 = this.partStart[s];
      const p1 = p0 + this.partCount[s];
      const v0 = this.partVertexStart[p0];
      const v1 = this.partVertexStart[p1 - 1] + this.partVertexCount[p1 - 1];
      // A static body moved (setBodyPose): its seams are found again.
      if (this.type[s] === BodyType.Static && (wx[v0] !== ox + c * lx[v0] - sn * ly[v0] || wy[v0] !== oy + sn * lx[v0] + c * ly[v0] || wnx[v0] !== c * lnx[v0] - sn * lny[v0])) this.staticsMoved = true;
      for (let v = v0; v < v1; v++) {
        wx[v] = ox + c * lx[v] - sn * ly[v];
        wy[v] = oy + sn * lx[v] + c * ly[v];
        wnx[v] = c * lnx[v] - sn * lny[v];
        wny[v] = sn * lnx[v] + c * lny[v];
      }
    }
  }

  snapshot(slots: number): RigidShapesSnapshot {
    return { sources: this.sources.slice(0, slots), rows: this.rows.slice(0, slots), type: this.type.slice(0, slots) };
  }

  restore(s: RigidShapesSnapshot): void {
    this.sources = s.sources.slice();
    this.rows = s.rows.slice();
    this.type = grown(new Uint8Array(16), s.type.length);
    this.type.set(s.type);
    this.row = grown(this.row, s.rows.length);
    s.rows.forEach((r, k) => (this.row[k] = r ?? 0));
  }

  /** Points `view` at part p's world vertices. */
  viewPart(p: number, view: PolygonRef): void {
    view.x = this.wx;
    view.y = this.wy;
    view.nx = this.wnx;
    view.ny = this.wny;
    view.start = this.partVertexStart[p];
    view.count = this.partVertexCount[p];
    view.internal = this.partInternal[p] === 1 ? this.internal : null;
  }
}

export interface RigidShapesSnapshot {
  sources: (RigidShapeSource | undefined)[];
  rows: number[];
  type: Uint8Array;
}

/**
 * A rigid outline ready for RigidShapes: counter-clockwise, without repeated or collinear (180°) vertices, which
 * would give zero-length edges and duplicate normals. `tolerance` is relative to the outline's size.
 */
export function cleanOutline(xs: number[], ys: number[], tolerance = 1e-9): { xs: number[]; ys: number[] } {
  let size = 0;
  for (let k = 0; k < xs.length; k++) size = Math.max(size, Math.abs(xs[k] - xs[0]), Math.abs(ys[k] - ys[0]));
  const eps = tolerance * size;
  let px = xs.slice();
  let py = ys.slice();
  let area = 0;
  for (let k = 0; k < px.length; k++) {
    const k2 = (k + 1) % px.length;
    area += (px[k] - px[0]) * (py[k2] - py[0]) - (px[k2] - px[0]) * (py[k] - py[0]);
  }
  if (area < 0) {
    px = px.reverse();
    py = py.reverse();
  }
  // Drop a vertex while it repeats its predecessor or lies on the line through its neighbours.
  let changed = true;
  while (changed && px.length > 3) {
    changed = false;
    for (let k = 0; k < px.length && px.length > 3; k++) {
      const n = px.length;
      const a = (k + n - 1) % n;
      const c = (k + 1) % n;
      const ex = px[c] - px[a];
      const ey = py[c] - py[a];
      const len = Math.sqrt(ex * ex + ey * ey);
      const off = len === 0 ? 0 : Math.abs((px[k] - px[a]) * ey - (py[k] - py[a]) * ex) / len;
      const repeat = Math.abs(px[k] - px[a]) <= eps && Math.abs(py[k] - py[a]) <= eps;
      if (repeat || off <= eps) {
        px.splice(k, 1);
        py.splice(k, 1);
        changed = true;
        k--;
      }
    }
  }
  return { xs: px, ys: py };
}
