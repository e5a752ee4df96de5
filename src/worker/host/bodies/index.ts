// The host's descriptor of every body type (the engine's BODY_TYPES): a new type is one module here and one in
// src/render/bodies/, and the compiler asks for both.
import type { BodyType } from '../../../engine/index.js';
import type { BodyDescriptor } from './descriptor.js';
import { box } from './box.js';
import { circle } from './circle.js';
import { cloth } from './cloth.js';
import { polygon } from './polygon.js';
import { ragdoll } from './ragdoll.js';
import { rope } from './rope.js';
import { softbody } from './softbody.js';

export type { BodyDescriptor, PoseBasis } from './descriptor.js';

const DESCRIPTORS: { readonly [T in BodyType]: BodyDescriptor<T> } = { box, circle, polygon, rope, cloth, softbody, ragdoll };

/** The descriptor of a body type, or undefined when `type` is none. */
export function descriptorOf(type: unknown): BodyDescriptor | undefined {
  return Object.hasOwn(DESCRIPTORS, type as PropertyKey) ? (DESCRIPTORS[type as BodyType] as BodyDescriptor) : undefined;
}
