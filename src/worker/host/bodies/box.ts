// A box: a rigid body (the engine's default) drawn from its pose and its outline; or (model 'particles') four
// particles held rigid, its pose the described centre, turning with its first edge.
import type { BodyDescriptor } from './descriptor.js';
import { RIGID } from './pose.js';

export const box: BodyDescriptor<'box'> = {
  grip: 'soft',
  pose: RIGID,
  rigidOutline({ width, height }) {
    const w = width / 2;
    const h = height / 2;
    return [{ x: -w, y: -h }, { x: w, y: -h }, { x: w, y: h }, { x: -w, y: h }];
  },
};
