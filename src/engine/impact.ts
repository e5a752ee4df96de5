// Bounces: the speed a contact hit with, from what a substep stores, shared by the rigid contacts and the walls.

/** Approach speeds below this (units/s) do not bounce: a resting contact's jitter would otherwise hop. */
export const BOUNCE_THRESHOLD = 0.5;

/** impact()'s arguments and results: [v, a, gap, half] in, [hit speed, lift] out in the first two. */
export const hit = new Float64Array(4);

/**
 * The normal speed at the moment of a hit into hit[0] (negative: approaching), and into hit[1] the lift a bounce
 * adds to −e × it, given in `hit`: v, the normal speed stored before the fall (under position Verlet the mean over the
 * substep before); a, the normal acceleration (gravity); the gap the sides closed from then to the hit; and half, h/2
 * under position Verlet (0 for the Euler integrators, whose stored speed is the one at the substep's end). Gravity
 * adds a·h/2 up to the substep's end and √(2·a·gap) over the gap; the bounce's stored speed, −e × the hit's speed −
 * a·h/2, leaves the contact at e times it. Without them a bounce left at −e × the stored speed: g·h slower than the
 * hit, and the fall through the gap lost (a ball with e = 1 dropped from 2 rose to 1.964, then 1.847 at the seventh
 * bounce). Doubles through an array: V8 boxes a double passed to or from a call it does not inline.
 */
export function impact(): void {
  const v = hit[0];
  const a = hit[1];
  if (a === 0) {
    hit[1] = 0;
    return;
  }
  const gap = hit[2];
  const half = hit[3];
  const u = v + a * half;
  const u2 = u * u - 2 * a * (gap > 0 ? gap : 0);
  hit[0] = u >= 0 ? u : u2 > 0 ? -Math.sqrt(u2) : 0;
  hit[1] = -a * half;
}

/**
 * impact() of v and a in hit[0], hit[1] for a contact found overlapping by overlap[i] after a substep's predicted move:
 * the gap it closed in that substep is the overlap less the move, (v + a·h)·h toward it (none when it does not
 * overlap). `motion` is the step's [gx, gy, h, half] (StepContext.substepMotion).
 */
export function impactInSubstep(overlap: Float64Array, i: number, motion: Float64Array): void {
  const o = overlap[i];
  const h = motion[2];
  hit[2] = o > 0 ? -o - (hit[0] + hit[1] * h) * h : 0;
  hit[3] = motion[3];
  impact();
}
