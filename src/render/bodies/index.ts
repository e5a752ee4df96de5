// The painter of every body type (the engine's BODY_TYPES): a new type is one module here and one in
// src/worker/host/bodies/, and the compiler asks for both.
import type { BodyType } from '../../engine/index.js';
import type { BodyPainter } from './painter.js';
import { box } from './box.js';
import { circle } from './circle.js';
import { cloth } from './cloth.js';
import { polygon } from './polygon.js';
import { ragdoll } from './ragdoll.js';
import { rope } from './rope.js';
import { softbody } from './softbody.js';

export type { BodyPainter, BodyStyle, Pen } from './painter.js';

export const PAINTERS: { readonly [T in BodyType]: BodyPainter } = { box, circle, polygon, rope, cloth, softbody, ragdoll };
