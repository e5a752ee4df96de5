// A soft body: a ring of particles; the 'springs' model adds a hub particle after the ring (createSoftBody), which
// is neither drawn nor part of the outline a press inside the ring grabs.
import type { BodyDescriptor, DescriptionOf } from './descriptor.js';
import { CENTROID } from './pose.js';

/** The ring's particles (all but the springs model's hub, the last one). */
function ring(d: DescriptionOf<'softbody'>, indices: Int32Array): Int32Array {
  return d.model === 'springs' ? indices.subarray(0, indices.length - 1) : indices;
}

export const softbody: BodyDescriptor<'softbody'> = {
  grip: 'firm',
  pose: CENTROID,
  describe(t, d, body) {
    t.ring = ring(d, body.indices).length;
    // The ring's particles collide as discs half a chord wide: drawn around them, the body rests on what it touches.
    t.radius = body.world.particles.radius[body.indices[0]];
  },
  outline: ring,
};
