// A polygon: its outline's particles held rigid; its pose is the described origin, turning with its first edge.
import type { BodyDescriptor } from './descriptor.js';
import { RIGID } from './pose.js';

export const polygon: BodyDescriptor<'polygon'> = { model: 'particles', grip: 'soft', pose: RIGID };
