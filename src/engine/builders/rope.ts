import type { World } from '../world.js';
import { coordinate, integer, nonNegative } from '../validate.js';
import { addTethers, BODY_OPTIONS, builderOptions, colliderOf, complianceOf, massEach, point, transactional, type BodyOptions, type Built } from './common.js';

export interface RopeOptions extends BodyOptions {
  from: { x: number; y: number };
  to: { x: number; y: number };
  /** Number of links (particles = segments + 1). Default 20. */
  segments?: number;
  /** Total mass. Default 1. */
  mass?: number;
  /** Link length as a multiple of the straight distance / segments. > 1 gives a rope that sags. Default 1. */
  slack?: number;
  /** Links are slack (only resist stretching, like a rope) instead of rigid sticks. Default true. */
  ropeLike?: boolean;
  pinStart?: boolean;
  pinEnd?: boolean;
  compliance?: number;
  radius?: number;
  /** Long-range tethers from each particle to the nearest pinned end (see addTethers). Default true. */
  tethers?: boolean;
}

const ROPE_OPTIONS = {
  ...BODY_OPTIONS, from: true, to: true, segments: true, mass: true, slack: true, ropeLike: true, pinStart: true, pinEnd: true, compliance: true, radius: true, tethers: true,
} satisfies Record<keyof RopeOptions, true>;

/** A rope or chain: a line of particles joined by distance links. */
export function createRope(world: World, o: RopeOptions): Built {
  builderOptions(world, 'rope', o, ROPE_OPTIONS);
  const from = point('from', o.from);
  const to = point('to', o.to);
  const segments = integer('segments', o.segments ?? 20, 1, 100000);
  const each = o.static ? Infinity : massEach('mass', o.mass, segments + 1, 1, '1');
  const slack = nonNegative('slack', o.slack ?? 1);
  const compliance = complianceOf('compliance', o.compliance);
  const radius = coordinate('radius', nonNegative('radius', o.radius ?? 0));
  const link = (Math.hypot(to.x - from.x, to.y - from.y) / segments) * slack;
  return transactional(world, (particles, constraints) => {
    for (let k = 0; k <= segments; k++) {
      const t = k / segments;
      particles.push(world.addParticle({ x: from.x + (to.x - from.x) * t, y: from.y + (to.y - from.y) * t, mass: each, radius }));
    }
    const ropeLike = o.ropeLike ?? true;
    for (let k = 0; k < segments; k++) {
      constraints.push(world.addDistance(particles[k], particles[k + 1], ropeLike ? { minLength: 0, maxLength: link, compliance } : { length: link, compliance }));
    }
    // A static rope is immovable already: no pins, no tethers.
    const pinned = o.static ? [] : [...(o.pinStart ?? true ? [0] : []), ...(o.pinEnd ? [segments] : [])];
    for (const k of pinned) constraints.push(world.addPin(particles[k]));
    if ((o.tethers ?? true) && compliance === 0) addTethers(world, particles, pinned, (a, b) => Math.abs(a - b) * link, constraints);
    // Collides (when asked) as circles of the particles' radius; off by default.
    return world.addBody('rope', particles, constraints, colliderOf(o, 'particles', false));
  });
}
