import type { World } from '../world.js';
import { coordinate, integer, nonNegative, oneOf, positive } from '../validate.js';
import { BODY_OPTIONS, builderOptions, colliderOf, complianceOf, massEach, point, transactional, type BodyOptions, type Built } from './common.js';

export interface SoftBodyOptions extends BodyOptions {
  center: { x: number; y: number };
  radius: number;
  /** Particles on the ring. Default 16. */
  segments?: number;
  /** Total mass. Default the disc's area. */
  mass?: number;
  /**
   * 'pressure' (default): the ring's links plus an area constraint at `pressure` × the rest area.
   * 'springs': the ring's links plus damped springs from a centre particle (seed 2.4's mass–spring model).
   */
  model?: 'pressure' | 'springs';
  pressure?: number;
  /** Compliance of the ring's links. Default 0.0001 (a little give). */
  compliance?: number;
  /** Compliance of the area constraint. Default 0. */
  areaCompliance?: number;
  /** Springs model: Hooke constant of the spokes. Default 400. */
  stiffness?: number;
  /**
   * Springs model: the spokes' damping, default 2. Pressure model: the rate (per second) at which the ring's
   * deformation dies out, its material damping (AreaOptions.damping), default 5.
   */
  damping?: number;
}

const SOFT_BODY_OPTIONS = {
  ...BODY_OPTIONS, center: true, radius: true, segments: true, mass: true, model: true, pressure: true, compliance: true, areaCompliance: true, stiffness: true, damping: true,
} satisfies Record<keyof SoftBodyOptions, true>;

/** A deformable ring (seed 2.3/2.4). */
export function createSoftBody(world: World, o: SoftBodyOptions): Built {
  builderOptions(world, 'soft body', o, SOFT_BODY_OPTIONS);
  const c = point('center', o.center);
  const radius = coordinate('radius', positive('radius', o.radius));
  const segments = integer('segments', o.segments ?? 16, 3, 4096);
  const model = oneOf('model', o.model ?? 'pressure', ['pressure', 'springs'] as const);
  const each = o.static ? Infinity : massEach('mass', o.mass, segments, Math.PI * radius * radius, 'π · radius²');
  const compliance = complianceOf('compliance', o.compliance ?? 1e-4);
  const pressure = positive('pressure', o.pressure ?? 1);
  const areaCompliance = complianceOf('areaCompliance', o.areaCompliance);
  const stiffness = nonNegative('stiffness', o.stiffness ?? 400);
  const damping = nonNegative('damping', o.damping ?? (model === 'pressure' ? 5 : 2));
  return transactional(world, (particles, constraints) => {
    for (let k = 0; k < segments; k++) {
      // Counter-clockwise in a y-up frame, the orientation the area constraint measures as positive.
      const t = (2 * Math.PI * k) / segments;
      // Each ring particle collides as a circle half a chord wide, so the ring has no gaps.
      particles.push(world.addParticle({ x: c.x + radius * Math.cos(t), y: c.y + radius * Math.sin(t), mass: each, radius: radius * Math.sin(Math.PI / segments) }));
    }
    // The ring's links are solved every other one, then the rest, then (odd rings) the last, so that each link's
    // neighbours are both solved before it or both after it; they are listed in ring order all the same. Swept around
    // the ring in order, each link pulled along a direction the one before had just turned, and a ring under pressure
    // (its links taut) gained spin from nothing, the same way every substep: at pressure 1.2 it rolled 47 units along a
    // floor in 10 s under the JS solver (the kernel colours the links), and the order reversed rolled it the other way.
    const ring: number[] = [];
    const link = (k: number) => (ring[k] = world.addDistance(particles[k], particles[(k + 1) % segments], { compliance }));
    const paired = segments - (segments % 2);
    for (let k = 0; k < paired; k += 2) link(k);
    for (let k = 1; k < paired; k += 2) link(k);
    if (paired < segments) link(segments - 1);
    constraints.push(...ring);
    if (model === 'pressure') {
      constraints.push(world.addAreaConstraint(particles.slice(), { pressure, compliance: areaCompliance, damping }));
    } else {
      // Listed at once (after the ring, where addBody wants it), so a failed spring takes it back too.
      const hub = world.addParticle({ x: c.x, y: c.y, mass: each, radius: 0 });
      particles.push(hub);
      for (let k = 0; k < segments; k++) constraints.push(world.addSpring(hub, particles[k], { stiffness, damping }));
    }
    return world.addBody('soft', particles, constraints, colliderOf(o, 'particles', true));
  });
}
