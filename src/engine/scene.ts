// Scenes as plain data: what the worker loads, what <physics-scene> markup turns into, and what the catalogue of
// named scenes produces for tests, benchmarks and the demo. buildScene() turns a description into bodies.
import { World, type Handle, type WorldOptions } from './world.js';
import type { KernelOptions } from './kernel/choice.js';
import { createBox, createPolygon, type BoxOptions, type PolygonOptions } from './builders/rigid.js';
import { createCircle, type CircleOptions } from './builders/circle.js';
import { createRope, type RopeOptions } from './builders/rope.js';
import { createCloth, type ClothOptions } from './builders/cloth.js';
import { createSoftBody, type SoftBodyOptions } from './builders/softbody.js';
import { createRagdoll, type RagdollOptions } from './builders/ragdoll.js';
import type { Built } from './builders/common.js';
import { describeValue } from './validate.js';

/** Fields every body description may carry besides its builder's options. */
interface Described {
  /** Names the body for joints, events and updates. */
  id?: string;
  /** Drawing style, used by the renderer (CSS colours). */
  fill?: string;
  stroke?: string;
}

export type BodyDescription =
  | ({ type: 'box' } & BoxOptions & Described)
  | ({ type: 'circle' } & CircleOptions & Described)
  | ({ type: 'polygon' } & PolygonOptions & Described)
  | ({ type: 'rope' } & RopeOptions & Described)
  | ({ type: 'cloth' } & ClothOptions & Described)
  | ({ type: 'softbody' } & SoftBodyOptions & Described)
  | ({ type: 'ragdoll' } & RagdollOptions & Described);

export type BodyType = BodyDescription['type'];
export const BODY_TYPES: readonly BodyType[] = ['box', 'circle', 'polygon', 'rope', 'cloth', 'softbody', 'ragdoll'];

export interface SceneDescription {
  /** The world's options, the solver kernel among them (`kernel`: when left out, the default set by setDefaultKernel(), 'js' unless changed). */
  world?: WorldOptions & KernelOptions;
  bodies: BodyDescription[];
}

/** Adds one described body to the world. */
export function buildBody(world: World, d: BodyDescription): Built {
  if (!(world instanceof World)) throw new TypeError(`buildBody needs a World first, got ${describeValue(world)}`);
  if (d == null || typeof d !== 'object') throw new TypeError(`a body description must be an object, got ${describeValue(d)}`);
  // The builder gets the description without the fields every description may carry (it refuses names it does not take).
  const { type, id: _id, fill: _fill, stroke: _stroke, ...options } = d;
  switch (type) {
    case 'box':
      return createBox(world, options as BoxOptions);
    case 'circle':
      return createCircle(world, options as CircleOptions);
    case 'polygon':
      return createPolygon(world, options as PolygonOptions);
    case 'rope':
      return createRope(world, options as RopeOptions);
    case 'cloth':
      return createCloth(world, options as ClothOptions);
    case 'softbody':
      return createSoftBody(world, options as SoftBodyOptions);
    case 'ragdoll':
      return createRagdoll(world, options as RagdollOptions);
    default:
      throw new RangeError(`type must be one of ${BODY_TYPES.join(', ')}, got ${describeValue(type)}`);
  }
}

/** A new world holding the scene. Returns the world and the bodies in description order. */
export function buildScene(description: SceneDescription): { world: World; bodies: Built[]; byId: Map<string, Handle> } {
  if (description == null || typeof description !== 'object') throw new TypeError(`a scene description must be an object {world?, bodies}, got ${describeValue(description)}`);
  if (!Array.isArray(description.bodies)) throw new TypeError(`a scene description's bodies must be a list, got ${describeValue(description.bodies)}`);
  const world = new World(description.world);
  const bodies = description.bodies.map((d) => buildBody(world, d));
  const byId = new Map<string, Handle>();
  description.bodies.forEach((d, k) => d.id && byId.set(d.id, bodies[k].body));
  return { world, bodies, byId };
}
