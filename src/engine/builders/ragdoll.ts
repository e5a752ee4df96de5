import type { Handle, World } from '../world.js';
import { coordinate, describeValue, positive } from '../validate.js';
import { BODY_OPTIONS, builderOptions, colliderOf, complianceOf, massEach, transactional, type BodyOptions, type Built } from './common.js';

export interface RagdollOptions extends BodyOptions {
  /** Pelvis position. */
  x: number;
  y: number;
  /** Height of the figure from feet to top of the head. Default 1.8. */
  height?: number;
  /** Total mass. Default 70. */
  mass?: number;
  /** Compliance of the joint limits (0 = hard stops). Default 0. */
  jointCompliance?: number;
}

/** The figure's height when none is given. */
export const RAGDOLL_HEIGHT = 1.8;

/** Joint names in particle order. */
export const RAGDOLL_JOINTS = ['head', 'neck', 'pelvis', 'elbowL', 'handL', 'elbowR', 'handR', 'kneeL', 'footL', 'kneeR', 'footR'] as const;

// Rest pose in units of height, y downward, pelvis at the origin.
const POSE: [number, number][] = [
  [0, -0.5], // head
  [0, -0.36], // neck
  [0, 0], // pelvis
  [-0.1, -0.2], // elbowL
  [-0.14, -0.04], // handL
  [0.1, -0.2], // elbowR
  [0.14, -0.04], // handR
  [-0.06, 0.24], // kneeL
  [-0.07, 0.5], // footL
  [0.06, 0.24], // kneeR
  [0.07, 0.5], // footR
];

/** Bones as pairs of indices into RAGDOLL_JOINTS (for drawing). */
export const RAGDOLL_BONES: readonly (readonly [number, number])[] = [
  [0, 1], [1, 2], [1, 3], [3, 4], [1, 5], [5, 6], [2, 7], [7, 8], [2, 9], [9, 10],
];

/** Joint limits as [a, vertex, c, range below rest, range above rest] in radians, relative to the rest pose. */
const LIMITS: [number, number, number, number, number][] = [
  [2, 1, 0, 0.5, 0.5], // neck: head nods ±0.5 about straight
  [2, 1, 3, 2.6, 0.6], // shoulder L
  [2, 1, 5, 0.6, 2.6], // shoulder R
  [1, 3, 4, 0, 2.4], // elbow L bends one way only
  [1, 5, 6, 2.4, 0], // elbow R, mirrored
  [1, 2, 7, 1.6, 0.5], // hip L
  [1, 2, 9, 0.5, 1.6], // hip R
  [2, 7, 8, 2.3, 0], // knee L bends one way only
  [2, 9, 10, 0, 2.3], // knee R, mirrored
];

const RAGDOLL_OPTIONS = { ...BODY_OPTIONS, x: true, y: true, height: true, mass: true, jointCompliance: true } satisfies Record<keyof RagdollOptions, true>;

/**
 * A stick-figure ragdoll (seed 2.6): 11 particles, 10 bones as sticks, joints as shared particles and angle limits
 * at the neck, shoulders, elbows, hips and knees.
 */
export function createRagdoll(world: World, o: RagdollOptions): Built {
  builderOptions(world, 'ragdoll', o, RAGDOLL_OPTIONS);
  const x = coordinate('x', o.x);
  const y = coordinate('y', o.y);
  const height = coordinate('height', positive('height', o.height ?? RAGDOLL_HEIGHT));
  const each = o.static ? Infinity : massEach('mass', o.mass, POSE.length, 70, '70');
  const compliance = complianceOf('jointCompliance', o.jointCompliance);
  return transactional(world, (particles, constraints) => {
    for (const [px, py] of POSE) particles.push(world.addParticle({ x: x + px * height, y: y + py * height, mass: each, radius: 0.04 * height }));
    for (const [a, b] of RAGDOLL_BONES) constraints.push(world.addDistance(particles[a], particles[b]));
    for (const [a, v, c, below, above] of LIMITS) {
      const rest = world.angleAt(particles[a], particles[v], particles[c]);
      constraints.push(world.addAngleLimit(particles[a], particles[v], particles[c], { min: rest - below, max: rest + above, compliance }));
    }
    return world.addBody('ragdoll', particles, constraints, colliderOf(o, 'particles', true));
  });
}

export type RagdollParticles = Record<(typeof RAGDOLL_JOINTS)[number], Handle>;

/** The ragdoll's particles by joint name. */
export function ragdollJoints(built: Built): RagdollParticles {
  if (built?.particles?.length !== RAGDOLL_JOINTS.length) throw new TypeError(`ragdollJoints takes what createRagdoll() returned, got ${describeValue(built)}`);
  return Object.fromEntries(RAGDOLL_JOINTS.map((name, k) => [name, built.particles[k]])) as RagdollParticles;
}
