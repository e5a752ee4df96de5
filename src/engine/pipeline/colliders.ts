import { grown } from '../table.js';
import type { ColliderOptions, ResolvedCollider } from '../options.js';

/** How a body collides. */
export const enum ColliderKind {
  None = 0,
  /** Convex parts whose vertices are the body's particles (a rigid frame's outline, or a concave outline's pieces). */
  Polygon = 1,
  /** Every particle is a circle of its own radius (soft rings, ragdolls, ropes and cloth that collide, balls). */
  Particles = 2,
  /** A rigid body's shape (polygon parts or a disc) in its own frame, posed by its row (rigid/shapes.ts). */
  Rigid = 3,
}

/**
 * Collision data per body slot (indexed like the world's body registry), plus the convex parts of polygon bodies.
 * Part vertices are particle indices, so a part always collides with the particles' current positions.
 */
export class Colliders {
  kind = new Uint8Array(16);
  friction = new Float64Array(16);
  restitution = new Float64Array(16);
  category = new Uint32Array(16);
  mask = new Uint32Array(16);
  group = new Int32Array(16);
  partStart = new Int32Array(16);
  partCount = new Int32Array(16);
  /** For soft rings: how many of the body's first particles form its closed outline (0 otherwise). */
  ringLength = new Int32Array(16);
  /** 1 when every particle of the body is immovable. */
  isStatic = new Uint8Array(16);
  /** The body's AABB this step (enlarged by its motion), and its particles' index list. */
  minX = new Float64Array(16);
  minY = new Float64Array(16);
  maxX = new Float64Array(16);
  maxY = new Float64Array(16);
  particles: Int32Array[] = [];

  /** Parts: [start, start + count) in `vertices`. */
  partVertexStart = new Int32Array(16);
  partVertexCount = new Int32Array(16);
  partBody = new Int32Array(16);
  partsUsed = 0;
  vertices = new Int32Array(64);
  verticesUsed = 0;

  /** Dense list of the body slots that collide, in slot order (rebuilt when bodies change). */
  active = new Int32Array(16);
  activeCount = 0;

  ensureBodies(slots: number): void {
    for (const name of ['kind', 'friction', 'restitution', 'category', 'mask', 'group', 'partStart', 'partCount', 'isStatic', 'ringLength', 'minX', 'minY', 'maxX', 'maxY'] as const) {
      (this as unknown as Record<string, Float64Array>)[name] = grown((this as unknown as Record<string, Float64Array>)[name], slots);
    }
  }

  /** Sets a body's collider from checked options (its parts are rebuilt with the others by rebuild()). */
  write(slot: number, o: ResolvedCollider, ringLength: number): void {
    this.ensureBodies(slot + 1);
    this.kind[slot] = o.shape === 'polygon' ? ColliderKind.Polygon : o.shape === 'particles' ? ColliderKind.Particles : ColliderKind.None;
    this.friction[slot] = o.friction;
    this.restitution[slot] = o.restitution;
    this.category[slot] = o.category;
    this.mask[slot] = o.mask;
    this.group[slot] = o.group;
    this.ringLength[slot] = ringLength;
  }

  /** A body's collider as options (`parts` as the body keeps them). */
  optionsOf(slot: number, parts: number[][] | undefined): ColliderOptions {
    const kind = this.kind[slot];
    return {
      shape: kind === ColliderKind.Polygon ? 'polygon' : kind === ColliderKind.Particles ? 'particles' : 'none',
      parts,
      friction: this.friction[slot],
      restitution: this.restitution[slot],
      category: this.category[slot],
      mask: this.mask[slot],
      group: this.group[slot],
    };
  }

  addPart(body: number, vertexIndices: ArrayLike<number>): void {
    const p = this.partsUsed++;
    this.partVertexStart = grown(this.partVertexStart, p + 1);
    this.partVertexCount = grown(this.partVertexCount, p + 1);
    this.partBody = grown(this.partBody, p + 1);
    this.vertices = grown(this.vertices, this.verticesUsed + vertexIndices.length);
    this.partVertexStart[p] = this.verticesUsed;
    this.partVertexCount[p] = vertexIndices.length;
    this.partBody[p] = body;
    for (let k = 0; k < vertexIndices.length; k++) this.vertices[this.verticesUsed++] = vertexIndices[k];
  }

  /** Rebuilds parts and the active list from scratch (bodies were added or removed; not called inside step()). */
  rebuild(slots: number, describe: (slot: number) => PartSource | null): void {
    this.ensureBodies(slots);
    this.partsUsed = 0;
    this.verticesUsed = 0;
    this.activeCount = 0;
    this.active = grown(this.active, slots);
    for (let slot = 0; slot < slots; slot++) {
      const source = describe(slot);
      if (!source || this.kind[slot] === ColliderKind.None) {
        this.partCount[slot] = 0;
        continue;
      }
      this.partStart[slot] = this.partsUsed;
      for (const part of source.parts) this.addPart(slot, part);
      this.partCount[slot] = source.parts.length;
      this.particles[slot] = source.particles;
      this.active[this.activeCount++] = slot;
    }
  }
}

export interface PartSource {
  particles: Int32Array;
  parts: Int32Array[];
}
