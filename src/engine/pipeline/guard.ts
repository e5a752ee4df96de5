// The step's last phase: no row leaves a step with a non-finite value or a runaway speed. The solver's own guards
// (positive effective masses, the turn per substep, SHAKE_AGREEMENT in rigid/joints.ts) keep ordinary scenes far from
// this; what reaches it is a tangle the substeps cannot resolve (a light body between two rods through a dead point,
// loops of driven joints among masses 10⁶ apart), whose speeds grow step after step until they overflow to Infinity
// and then NaN, which would spread through every constraint and contact to the whole world.
import type { ParticleStore } from '../particles.js';
import { MAX_SPEED } from '../validate.js';
import type { StepContext } from './context.js';

/**
 * The speed (linear, or angular in rad/s) past which a row is a runaway: a thousand times what the API accepts
 * (MAX_SPEED), so a body that gravity or a push took a little past that limit keeps going.
 */
export const RUNAWAY_SPEED = 1000 * MAX_SPEED;

/**
 * Checks every row after the substeps: one whose position, angle or speeds are not finite, or whose linear or angular
 * speed is beyond RUNAWAY_SPEED (10¹²), goes back to where it started the step, at rest (a runaway's speed cut to the
 * bound would still let the solver throw it arbitrarily far each step). Returns the rows changed: 0 in every ordinary
 * step, whose cost is one sum over the speeds (40 µs for 40,000 rows).
 */
export function keepRowsFinite(ctx: StepContext): number {
  const p = ctx.particles;
  const { vx, vy, omega } = p;
  const n = p.count;
  // One sum over the speeds finds all of it: every integrator derives a row's velocities from where the substep left
  // it (v = (x − px)/h, ω = (θ − θ₀)/h), so a position or angle that is not finite leaves a speed that is not finite,
  // and a NaN or ±Infinity anywhere makes the sum NaN or past the bound. Without rigid bodies every ω is 0.
  let sum = 0;
  if (ctx.rigidCount > 0 || ctx.kinematicCount > 0) for (let i = 0; i < n; i++) sum += vx[i] * vx[i] + vy[i] * vy[i] + omega[i] * omega[i];
  else for (let i = 0; i < n; i++) sum += vx[i] * vx[i] + vy[i] * vy[i];
  if (sum <= RUNAWAY_SPEED * RUNAWAY_SPEED) return 0;
  let changed = 0;
  for (let i = 0; i < n; i++) if (repairRow(p, i)) changed++;
  ctx.rowsRepaired += changed;
  return changed;
}

/** Puts row i back where it started the step, at rest, if it needs it (see keepRowsFinite); false when it does not. */
function repairRow(p: ParticleStore, i: number): boolean {
  const speed = p.vx[i] * p.vx[i] + p.vy[i] * p.vy[i];
  const spin = p.omega[i] * p.omega[i];
  const finite = p.x[i] - p.x[i] === 0 && p.y[i] - p.y[i] === 0 && p.angle[i] - p.angle[i] === 0;
  if (finite && speed <= RUNAWAY_SPEED * RUNAWAY_SPEED && spin <= RUNAWAY_SPEED * RUNAWAY_SPEED) return false;
  // The step's start, finite since the previous step's guard (0 should it not be: nothing else is known).
  const x = Number.isFinite(p.sx[i]) ? p.sx[i] : 0;
  const y = Number.isFinite(p.sy[i]) ? p.sy[i] : 0;
  const a = Number.isFinite(p.sangle[i]) ? p.sangle[i] : 0;
  p.x[i] = p.px[i] = x;
  p.y[i] = p.py[i] = y;
  p.angle[i] = p.pangle[i] = p.qangle[i] = a;
  p.rc[i] = Math.cos(a);
  p.rs[i] = Math.sin(a);
  p.vx[i] = p.vy[i] = p.omega[i] = 0;
  return true;
}
