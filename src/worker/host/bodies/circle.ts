// A ball: a rigid disc (the engine's default), drawn from its pose with its radius; or (model 'particles') one
// particle colliding as a circle.
import type { BodyDescriptor } from './descriptor.js';
import { DISC } from './pose.js';

export const circle: BodyDescriptor<'circle'> = {
  grip: 'firm',
  pose: DISC,
  describe(t, d) {
    t.radius = d.radius;
  },
};
