import type { World } from '../world.js';
import { coordinate, positive } from '../validate.js';
import { builderOptions, colliderOf, massEach, transactional, type Built } from './common.js';
import { createRigid, modelOf, RIGID_OPTIONS, type RigidOptions } from './rigid.js';

export interface CircleOptions extends RigidOptions {
  x: number;
  y: number;
  radius: number;
  /** Initial angle, radians (a rigid disc turns, and is drawn with a mark that shows it). Default 0. */
  angle?: number;
  /** Default: the disc's area (density 1). */
  mass?: number;
}

const CIRCLE_OPTIONS = { ...RIGID_OPTIONS, x: true, y: true, radius: true, angle: true, mass: true } satisfies Record<keyof CircleOptions, true>;

/** A ball: a rigid disc that spins and rolls, or (model 'particles') one particle colliding as a circle. */
export function createCircle(world: World, o: CircleOptions): Built {
  builderOptions(world, 'circle', o, CIRCLE_OPTIONS);
  const radius = coordinate('radius', positive('radius', o.radius));
  if (modelOf(o) === 'rigid') return createRigid(world, { ...o, x: coordinate('x', o.x), y: coordinate('y', o.y) }, undefined, radius);
  const mass = o.static ? Infinity : massEach('mass', o.mass, 1, Math.PI * radius * radius, 'π · radius²');
  const x = coordinate('x', o.x);
  const y = coordinate('y', o.y);
  return transactional(world, (particles) => {
    particles.push(world.addParticle({ x, y, radius, mass, vx: o.vx ?? 0, vy: o.vy ?? 0 }));
    return world.addBody('particle', particles, [], colliderOf(o, 'particles', true));
  });
}
