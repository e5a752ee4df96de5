import { Table } from './table.js';

/**
 * Particle state, one typed array per field. A rigid body is a particle too: the row of its centre of mass, with an
 * angle and an inverse moment of inertia (a plain particle has both 0, and every formula reduces to it). A particle's index is its handle's slot and never moves (constraints
 * and shapes refer to particles by index), so removed particles leave a hole: `alive` 0 and `invMass` 0, which
 * every loop already skips. Slots are reused by later particles.
 */
export class ParticleStore extends Table {
  readonly columns = ['x', 'y', 'px', 'py', 'vx', 'vy', 'qx', 'qy', 'ax', 'ay', 'sx', 'sy', 'fx', 'fy', 'invMass', 'radius', 'alive', 'flags',
    'angle', 'pangle', 'sangle', 'omega', 'rc', 'rs', 'qangle', 'torque', 'invInertia'] as const;
  /** Position now. */
  x = new Float64Array(16);
  y = new Float64Array(16);
  /** Position at the start of the current substep (Verlet's previous position). */
  px = new Float64Array(16);
  py = new Float64Array(16);
  /** Velocity over the last substep, (x − px) / h for position-based integrators. */
  vx = new Float64Array(16);
  vy = new Float64Array(16);
  /**
   * Position right after integration, before constraints: what the explicit Euler velocity update needs, and in a
   * world with particle frames their bounces (step.ts keeps it under every integrator then; frame-bounces.ts).
   */
  qx = new Float64Array(16);
  qy = new Float64Array(16);
  /** Acceleration this substep: gravity + user force / mass + spring forces / mass. */
  ax = new Float64Array(16);
  ay = new Float64Array(16);
  /** Position at the start of the step (sleeping judges motion over whole steps, not substep jitter). */
  sx = new Float64Array(16);
  sy = new Float64Array(16);
  /** Force accumulated by the user for the next step (cleared after it). */
  fx = new Float64Array(16);
  fy = new Float64Array(16);
  /** 1 / mass; 0 = immovable (pinned, static or removed). */
  invMass = new Float64Array(16);
  radius = new Float64Array(16);
  alive = new Uint8Array(16);
  /** Bit flags (see ParticleFlag). */
  flags = new Uint8Array(16);
  /** A rigid body's angle (radians), at the start of the substep and of the step, and its angular velocity. */
  angle = new Float64Array(16);
  pangle = new Float64Array(16);
  sangle = new Float64Array(16);
  omega = new Float64Array(16);
  /** cos and sin of the reference angle qangle (1 and 0 for a particle), brought up to the angle once a substep. */
  rc = new Float64Array(16);
  rs = new Float64Array(16);
  qangle = new Float64Array(16);
  /** Torque accumulated by the user for the next step (cleared after it). */
  torque = new Float64Array(16);
  /** 1 / moment of inertia about the centre of mass; 0 for particles and for static and kinematic bodies. */
  invInertia = new Float64Array(16);
}

export const enum ParticleFlag {
  /** Immovable by the user's choice (mass Infinity); keeps invMass 0 through pin/unpin. */
  Static = 1,
  /** Held by a rigid pin: invMass is 0 while the pin lives. */
  Pinned = 2,
  /** Collides with world bounds and (later) with shapes as a circle of its radius. */
  Collides = 4,
  /** The centre of mass of a rigid body: the bounds act on its shape, not on the row as a circle. */
  Rigid = 8,
  /** A rigid body moved by its prescribed velocity (inverse mass 0, but it moves). */
  Kinematic = 16,
}
