// The bodies: per handle slot its kind, its member particles (storage indices), the constraints it owns and its
// collider's convex parts. A body groups what the builders made; removing it removes its particles and constraints.
import { handleSlot, HandleRegistry, type Handle, type RegistrySnapshot } from './handles.js';
import { grown } from './table.js';
import type { ParticleStore } from './particles.js';
import type { Springs } from './constraints/spring.js';
import type { BodyKind, Vec2 } from './options.js';

export class BodyRegistry {
  readonly ids = new HandleRegistry('body', 'bodies', 'bodies');
  kind: BodyKind[] = [];
  particles: Int32Array[] = [];
  constraints: Handle[][] = [];
  /** Convex parts as indices into the body's particle list (undefined: the whole outline is one part). */
  parts: (number[][] | undefined)[] = [];
  /** Per particle slot: 1 + the slot of the body that holds it, 0 for none (a particle is in one body at most). */
  private owner = new Int32Array(64);

  /** The slot of the live body holding particle slot `i`, or -1. */
  ownerOf(i: number): number {
    return i < this.owner.length ? this.owner[i] - 1 : -1;
  }

  /** A new body of checked particle slots and constraint handles; returns its handle. */
  add(kind: BodyKind, particles: Int32Array, constraints: readonly Handle[]): Handle {
    const handle = this.ids.allocate();
    const slot = handleSlot(handle);
    this.kind[slot] = kind;
    this.particles[slot] = particles;
    this.constraints[slot] = constraints.slice();
    this.own(particles, slot + 1);
    return handle;
  }

  /** Forgets a live body (its particles and constraints are removed by the caller). */
  remove(handle: Handle): void {
    const slot = handleSlot(handle);
    this.own(this.particles[slot], 0);
    this.particles[slot] = new Int32Array(0);
    this.constraints[slot] = [];
    this.parts[slot] = undefined;
    this.ids.release(handle);
  }

  /** The slot of a live body handle; a TypeError/RangeError naming `what` otherwise. */
  slotOf(handle: unknown, what = 'body'): number {
    return this.ids.slotOf(handle, what);
  }

  /** The body's particles' collision parts as particle storage indices (the whole outline when it has no parts). */
  partIndices(slot: number): Int32Array[] {
    const particles = this.particles[slot];
    const parts = this.parts[slot];
    return parts ? parts.map((part) => Int32Array.from(part, (k) => particles[k])) : [particles];
  }

  snapshot(): BodiesSnapshot {
    return {
      ids: this.ids.snapshot(),
      kind: this.kind.slice(),
      particles: this.particles.map((a) => a.slice()),
      constraints: this.constraints.map((a) => a.slice()),
      parts: this.parts.map((parts) => parts?.map((part) => part.slice())),
    };
  }

  restore(s: BodiesSnapshot): void {
    this.ids.restore(s.ids);
    this.kind = s.kind.slice();
    this.particles = s.particles.map((a) => a.slice());
    this.constraints = s.constraints.map((a) => a.slice());
    this.parts = s.parts.map((parts) => parts?.map((part) => part.slice()));
    this.owner.fill(0);
    for (let b = 0; b < this.ids.high; b++) if (this.ids.alive[b] === 1) this.own(this.particles[b], b + 1);
  }

  private own(particles: Int32Array, value: number): void {
    let high = 0;
    for (const i of particles) if (i >= high) high = i + 1;
    if (high > this.owner.length) this.owner = grown(this.owner, high);
    for (const i of particles) this.owner[i] = value;
  }
}

export interface BodiesSnapshot {
  ids: RegistrySnapshot;
  kind: BodyKind[];
  particles: Int32Array[];
  constraints: Handle[][];
  parts: (number[][] | undefined)[];
}

/**
 * How many of a soft body's first particles form its closed outline, which it is picked and queried by (the
 * 'springs' model's last particle is the hub, held by springs, not part of the ring).
 */
export function softRingLength(particles: Int32Array, springs: Springs): number {
  const hub = particles[particles.length - 1];
  for (let r = 0; r < springs.count; r++) if (springs.a[r] === hub || springs.b[r] === hub) return particles.length - 1;
  return particles.length;
}

/** Mean position of the particles. */
export function centroid(p: ParticleStore, particles: Int32Array): Vec2 {
  let sx = 0;
  let sy = 0;
  for (const i of particles) {
    sx += p.x[i];
    sy += p.y[i];
  }
  return { x: sx / particles.length, y: sy / particles.length };
}

/** The mass of the movable particles among `particles` (0 when none moves). */
export function bodyMass(p: ParticleStore, particles: Int32Array): number {
  let mass = 0;
  for (const i of particles) if (p.invMass[i] > 0) mass += 1 / p.invMass[i];
  return mass;
}

/** Changes the velocity of the movable particles by impulse / (their total mass). */
export function applyImpulseByMass(p: ParticleStore, particles: Int32Array, jx: number, jy: number): void {
  const mass = bodyMass(p, particles);
  if (mass === 0) return;
  for (const i of particles) {
    if (p.invMass[i] === 0) continue;
    p.vx[i] += jx / mass;
    p.vy[i] += jy / mass;
  }
}
