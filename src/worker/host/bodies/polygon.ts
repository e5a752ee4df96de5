// A polygon: a rigid body (the engine's default) drawn from its pose and its outline as described (a concave one as
// its outline, not its convex parts); or (model 'particles') its outline's particles held rigid, its pose the
// described origin, turning with its first edge.
import type { BodyDescriptor } from './descriptor.js';
import { RIGID } from './pose.js';

export const polygon: BodyDescriptor<'polygon'> = { grip: 'soft', pose: RIGID, rigidOutline: (d) => d.points };
