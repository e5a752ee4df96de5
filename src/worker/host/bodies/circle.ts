// A ball: one particle colliding as a circle, drawn with its radius.
import type { BodyDescriptor } from './descriptor.js';
import { DISC } from './pose.js';

export const circle: BodyDescriptor<'circle'> = {
  model: 'particles',
  grip: 'firm',
  pose: DISC,
  describe(t, d) {
    t.radius = d.radius;
  },
};
