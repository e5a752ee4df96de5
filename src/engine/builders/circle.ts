import type { World } from '../world.js';
import { finite, positive } from '../validate.js';
import { colliderOf, transactional, type BodyOptions, type Built } from './common.js';

export interface CircleOptions extends BodyOptions {
  x: number;
  y: number;
  radius: number;
  /** Default: the disc's area (density 1). */
  mass?: number;
  vx?: number;
  vy?: number;
}

/** A ball: one particle colliding as a circle of its radius. */
export function createCircle(world: World, o: CircleOptions): Built {
  const radius = positive('radius', o?.radius);
  const mass = o.static ? Infinity : positive('mass', o.mass ?? Math.PI * radius * radius);
  const x = finite('x', o.x);
  const y = finite('y', o.y);
  return transactional(world, (particles) => {
    particles.push(world.addParticle({ x, y, radius, mass, vx: o.vx ?? 0, vy: o.vy ?? 0 }));
    return world.addBody('particle', particles, [], colliderOf(o, 'particles', true));
  });
}
