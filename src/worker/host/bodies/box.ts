// A box: four particles held rigid; its pose is the described centre, turning with its first edge.
import type { BodyDescriptor } from './descriptor.js';
import { RIGID } from './pose.js';

export const box: BodyDescriptor<'box'> = { model: 'particles', grip: 'soft', pose: RIGID };
