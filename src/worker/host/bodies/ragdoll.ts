// A ragdoll: a stick figure of RAGDOLL_JOINTS particles. Its pose is its pelvis, as in its markup; the topology gives
// the head's drawing radius.
import { RAGDOLL_HEIGHT, RAGDOLL_JOINTS } from '../../../engine/builders/ragdoll.js';
import type { BodyDescriptor } from './descriptor.js';

/** The head's drawing radius per unit of the figure's height. */
const HEAD_RADIUS = 0.075;

export const ragdoll: BodyDescriptor<'ragdoll'> = {
  grip: 'firm',
  pose: { anchor: RAGDOLL_JOINTS.indexOf('pelvis') },
  describe(t, d) {
    t.radius = HEAD_RADIUS * (d.height ?? RAGDOLL_HEIGHT);
  },
};
