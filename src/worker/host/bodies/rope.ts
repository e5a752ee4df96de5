// A rope: a line of particles, drawn as thick as its particles' radius.
import type { BodyDescriptor } from './descriptor.js';
import { CENTROID } from './pose.js';

export const rope: BodyDescriptor<'rope'> = {
  grip: 'firm',
  pose: CENTROID,
  describe(t, d) {
    t.radius = d.radius ?? 0;
  },
};
