// Free spin: a body built of particles (a particle frame, a ragdoll, a soft body, a free rope or cloth) keeps its
// angular momentum about its centre of mass through a step in which nothing outside it acts on it.
//
// Why: position Verlet takes a particle's velocity from its move, v = (x − x_prev)/h, and a link that pulls a turning
// particle back onto its circle shortens that move: the chord of the turn, not its arc. Each substep the body keeps
// 1/√(1 + (ωh)²) of its angular momentum, so a box of particles spun at 5 rad/s kept 74% of it (55% of its energy)
// over 10 s of free flight, at 10 rad/s 48% (23%), where a rigid body keeps all of it. The links' own corrections
// are internal (rotation-invariant constraints: distances, angles, areas, springs), so nothing outside turned it:
// what the step lost is the velocities' error, and it is put back as a turn of the whole body, δω = ΔL / I.
//
// Only while nothing outside acts: no contact of any kind found this step (speculative ones too), no wall touched, no
// force applied, no pin, grab, joint or link to anything else, no kinematic or immovable particle, awake. Gravity and
// the world's damping act alike on every particle: the first turns nothing about the centre of mass, the second
// scales the target by what it takes in the step.
//
// The same fit of a rigid motion (the centre's velocity and ω = L / I) damps the area loops' deformation (dampLoops).
import { ParticleFlag, type ParticleStore } from '../particles.js';
import { grown } from '../table.js';
import type { StepContext } from './context.js';
import { eachLinkedPair } from './linked.js';

export class FreeSpin {
  /** Per body slot: 1 when only its own links act on its particles (rebuilt with the topology). */
  closed = new Uint8Array(16);
  /** Any closed body: 0 skips both passes. */
  closedCount = 0;
  /** Per body slot, this step: its angular momentum about its centre of mass when the step began (NaN: not kept). */
  start = new Float64Array(16);
  /** Per particle, within dampLoops: 1 while it touches something outside its body this step (0 between steps). */
  touching = new Uint8Array(16);
}

/** Which bodies only their own links act on (after bodies or constraints changed: topology.ts). */
export function rebuildFreeSpin(ctx: StepContext): void {
  const { ids, kind, particles: members } = ctx.bodies;
  const spin = ctx.freeSpin;
  const high = ids.high;
  spin.closed = grown(spin.closed, high);
  spin.start = grown(spin.start, high);
  spin.touching = grown(spin.touching, ctx.particles.count);
  const closed = spin.closed;
  for (let s = 0; s < high; s++) {
    // A rigid body turns by its own angular velocity; a lone particle has no turn.
    closed[s] = ids.alive[s] && kind[s] !== 'particle' && !ctx.rigidShapes.source(s) && members[s].length > 1 ? 1 : 0;
  }
  const owner = ctx.sleep.particleBody;
  // A constraint between particles of different bodies, or of a body and a free particle or the world (j < 0), opens both.
  const open = (i: number, j: number): void => {
    const a = owner[i];
    const b = j >= 0 ? owner[j] : -1;
    if (a === b) return;
    if (a >= 0) closed[a] = 0;
    if (b >= 0) closed[b] = 0;
  };
  eachLinkedPair(ctx, open);
  const { joints: j, pins } = ctx.constraints;
  for (let r = 0; r < j.count; r++) open(j.a[r], j.b[r]);
  for (let r = 0; r < pins.count; r++) open(pins.p[r], -1);
  let count = 0;
  for (let s = 0; s < high; s++) count += closed[s];
  spin.closedCount = count;
}

/**
 * After detection: each closed body that nothing outside can reach this step (no contact found, no grab, no force, all
 * its particles movable and awake) notes its angular momentum; every other body is marked not kept (NaN).
 */
export function recordFreeSpin(ctx: StepContext): void {
  const spin = ctx.freeSpin;
  if (spin.closedCount === 0) return;
  const { start, closed } = spin;
  const high = ctx.bodies.ids.high;
  for (let s = 0; s < high; s++) start[s] = closed[s] === 1 ? 0 : NaN;
  reached(ctx.contacts.bodyA, ctx.contacts.bodyB, ctx.contacts.count, start);
  reached(ctx.rigidContacts.bodyA, ctx.rigidContacts.bodyB, ctx.rigidContacts.count, start);
  const owner = ctx.sleep.particleBody;
  const grabs = ctx.constraints.grabs;
  for (let r = 0; r < grabs.count; r++) {
    held(owner, grabs.p0[r], start);
    held(owner, grabs.p1[r], start);
    held(owner, grabs.p2[r], start);
  }
  const p = ctx.particles;
  const { invMass, flags, fx, fy } = p;
  for (let s = 0; s < high; s++) {
    if (start[s] !== 0) continue;
    const idx = ctx.bodies.particles[s];
    let outside = false;
    for (let k = 0; k < idx.length; k++) {
      const i = idx[k];
      if (invMass[i] === 0 || flags[i] & ParticleFlag.Kinematic || fx[i] !== 0 || fy[i] !== 0) {
        outside = true;
        break;
      }
    }
    start[s] = outside ? NaN : angularMomentum(ctx.particles, idx);
  }
}

/** Marks not kept (NaN) the body that particle i (−1: none) belongs to. */
function held(owner: Int32Array, i: number, start: Float64Array): void {
  if (i >= 0 && owner[i] >= 0) start[owner[i]] = NaN;
}

/** Marks not kept (NaN) each body a contact joins to anything but itself. */
function reached(bodyA: Int32Array, bodyB: Int32Array, count: number, start: Float64Array): void {
  for (let c = 0; c < count; c++) {
    const a = bodyA[c];
    const b = bodyB[c];
    if (a === b) continue;
    if (a >= 0) start[a] = NaN;
    if (b >= 0) start[b] = NaN;
  }
}

/** Scratch of angularMomentum(): the body's centre of mass (x, y), its moment of inertia about it, its velocity (x, y), its mass. */
export const centre = new Float64Array(6);

/**
 * L = Σ m (r × (v − v̄)) about the centre of mass of the particles idx[from..to) (all movable); fills `centre`. Free
 * spin, the area loops' damping and the particle frames' bounces (frame-bounces.ts) take a body's rigid motion here.
 */
export function angularMomentum(p: ParticleStore, idx: Int32Array, from = 0, to = idx.length): number {
  const { x, y, vx, vy, invMass } = p;
  let m = 0;
  let cx = 0;
  let cy = 0;
  let cvx = 0;
  let cvy = 0;
  for (let k = from; k < to; k++) {
    const i = idx[k];
    const mi = 1 / invMass[i];
    m += mi;
    cx += mi * x[i];
    cy += mi * y[i];
    cvx += mi * vx[i];
    cvy += mi * vy[i];
  }
  cx /= m;
  cy /= m;
  cvx /= m;
  cvy /= m;
  let L = 0;
  let I = 0;
  for (let k = from; k < to; k++) {
    const i = idx[k];
    const mi = 1 / invMass[i];
    const rx = x[i] - cx;
    const ry = y[i] - cy;
    L += mi * (rx * (vy[i] - cvy) - ry * (vx[i] - cvx));
    I += mi * (rx * rx + ry * ry);
  }
  centre[0] = cx;
  centre[1] = cy;
  centre[2] = I;
  centre[3] = cvx;
  centre[4] = cvy;
  centre[5] = m;
  return L;
}

/**
 * After the substeps: each body kept this step (no wall touched either) turns by δω = (L₀·dampⁿ − L) / I, its angular
 * momentum back to what it began the step with, less the world's damping over the `substeps` (factor `damp` each).
 */
export function keepFreeSpin(ctx: StepContext, substeps: number, damp: number): void {
  const spin = ctx.freeSpin;
  if (spin.closedCount === 0) return;
  const { start } = spin;
  // (stepWall has room for every particle only in a world with bounds.)
  const walls = ctx.settings.bounds ? ctx.wallHits.stepWall : null;
  const scale = damp === 1 ? 1 : damp ** substeps;
  for (let s = 0, high = ctx.bodies.ids.high; s < high; s++) {
    const L0 = start[s];
    if (L0 !== L0) continue;
    const idx = ctx.bodies.particles[s];
    let walled = false;
    if (walls) for (let k = 0; k < idx.length; k++) if (walls[idx[k]] !== 0) walled = true;
    if (walled) continue;
    const L = angularMomentum(ctx.particles, idx);
    const I = centre[2];
    const dw = (L0 * scale - L) / I;
    // A body of coincident particles (I = 0) has no turn to mend; a non-finite row is keepRowsFinite's.
    if (!(I > 0) || !Number.isFinite(dw)) continue;
    turn[2] = dw;
    addTurn(ctx.particles, idx, 0, idx.length);
  }
}

/**
 * Rolling resistance of a pressure ring on what it rests on: its rigid turn slows by at most this × |g| / r (r its
 * radius of gyration) a second while any of its particles touches something outside its body or a wall, as a Coulomb rolling
 * resistance torque c·N·R slows a wheel (N its weight; a ball's c is about 0.001–0.02).
 */
export const ROLLING_RESISTANCE = 0.01;

/**
 * The area loops' material damping, once a step of `dt`: each particle's velocity apart from its loop's rigid motion
 * (the centre's velocity v̄ and the turn ω = L / I) is scaled by 1 / (1 + c·dt), c the row's `damping` (per second),
 * as Müller et al. (2007, §3.5) damp a body's velocities; momentum and angular momentum are kept. Without it a pressure
 * ring (its links stiff springs, its area exact) gave back nearly all the energy of its squeeze: it bounced on between
 * what it leant on and rocked on its flattened contact patch for minutes.
 *
 * A damped loop that touches something outside its body (or a wall of the world's bounds) also meets rolling
 * resistance (ROLLING_RESISTANCE): its turn ω is brought toward 0 by at most ROLLING_RESISTANCE·|g|/r·dt, the change
 * spread as a rigid turn about its centre (its momentum kept: friction at the contact shares the loss between turn and
 * roll). Why: an inflated ring (pressure above 1) is round and stiff, and rests on the two particles of one of its
 * sides, a polygon on its edge; it rocked over them (each swing lifting one a few millimetres, gravity and the links'
 * stretch bringing it back) nearly as a rigid body, which the damping above leaves alone, and each landing of a
 * 16-gon's corner takes only about 5% of the swing's energy: one of 16 links at pressure 1.2 dropped from 3 still
 * rocked at 0.3 units/s after 40 s, and rings at 1.05–1.2 did not sleep within a minute. A real ball loses that
 * motion in its flattened contact patch (hysteresis), which this stands for. It is rate-independent, as a rolling
 * resistance is: those rings now sleep after 9–18 s, while one rolling at 2 units/s loses about 0.04 units/s² more.
 */
export function dampLoops(ctx: StepContext, dt: number): void {
  const loops = ctx.constraints.areas;
  const { pool, start, damping } = loops;
  const { x, y, vx, vy, invMass } = ctx.particles;
  const touching = markTouching(ctx, 1);
  // (stepWall has room for every particle only in a world with bounds.)
  const walls = ctx.settings.bounds ? ctx.wallHits.stepWall : null;
  const g = ctx.settings.gravity;
  const load = ROLLING_RESISTANCE * Math.sqrt(g.x * g.x + g.y * g.y);
  for (let r = 0; r < loops.count; r++) {
    const from = start[r];
    const to = from + loops.length[r];
    // A loop with an immovable or sleeping particle (inverse mass 0) has no rigid motion of its own.
    let free = damping[r] > 0;
    let rests = false;
    for (let k = from; k < to; k++) {
      if (invMass[pool[k]] === 0) free = false;
      if (touching[pool[k]] !== 0 || (walls !== null && walls[pool[k]] !== 0)) rests = true;
    }
    if (!free) continue;
    turn[0] = angularMomentum(ctx.particles, pool, from, to) / centre[2];
    // Coincident particles (I = 0) have no turn; a non-finite row is keepRowsFinite's.
    if (!Number.isFinite(turn[0])) continue;
    if (rests && load > 0) {
      turn[1] = (load / Math.sqrt(centre[2] / centre[5])) * dt;
      resistTurn(ctx.particles, pool, from, to);
    }
    const w = turn[0];
    const keep = 1 / (1 + damping[r] * dt);
    for (let k = from; k < to; k++) {
      const i = pool[k];
      const ux = centre[3] - w * (y[i] - centre[1]);
      const uy = centre[4] + w * (x[i] - centre[0]);
      vx[i] = ux + (vx[i] - ux) * keep;
      vy[i] = uy + (vy[i] - uy) * keep;
    }
  }
  markTouching(ctx, 0);
}

/**
 * Scratch of keepFreeSpin and dampLoops (V8 boxes a double passed to or returned from a call it does not inline): a
 * loop's turn ω, the most rolling resistance takes from it this step, and the turn addTurn adds.
 */
const turn = new Float64Array(3);

/** Adds the turn turn[2] (rad/s) about `centre` to the velocities of particles idx[from..to): a rigid turn. */
function addTurn(p: ParticleStore, idx: Int32Array, from: number, to: number): void {
  const { x, y, vx, vy } = p;
  const dw = turn[2];
  const cx = centre[0];
  const cy = centre[1];
  for (let k = from; k < to; k++) {
    const i = idx[k];
    vx[i] -= dw * (y[i] - cy);
    vy[i] += dw * (x[i] - cx);
  }
}

/** Brings turn[0] toward 0 by at most turn[1], as a rigid turn of the loop's particles idx[from..to) about `centre`. */
function resistTurn(p: ParticleStore, idx: Int32Array, from: number, to: number): void {
  const most = turn[1];
  turn[2] = Math.max(-most, Math.min(most, -turn[0]));
  addTurn(p, idx, from, to);
  turn[0] += turn[2];
}

/**
 * Sets (on = 1) or clears (0) FreeSpin.touching for every particle in a contact that acted this step between two
 * bodies (or a body and a free particle or the world): particle contacts, both sides; rigid contacts, the particle side.
 */
function markTouching(ctx: StepContext, on: 0 | 1): Uint8Array {
  const spin = ctx.freeSpin;
  // (Particles added since the topology was rebuilt; rebuildFreeSpin grows it otherwise.)
  if (spin.touching.length < ctx.particles.count) spin.touching = grown(spin.touching, ctx.particles.count);
  const t = spin.touching;
  const c = ctx.contacts;
  for (let k = 0; k < c.count; k++) {
    if (c.touched[k] === 0 || c.bodyA[k] === c.bodyB[k]) continue;
    t[c.v[k]] = on;
    if (c.e0[k] >= 0) t[c.e0[k]] = on;
    if (c.e1[k] >= 0) t[c.e1[k]] = on;
  }
  const rc = ctx.rigidContacts;
  for (let k = 0; k < rc.count; k++) {
    if (rc.touched[k] === 0 || rc.bodyA[k] === rc.bodyB[k]) continue;
    if (rc.b[k] >= 0) t[rc.b[k]] = on;
    if (rc.b2[k] >= 0) t[rc.b2[k]] = on;
  }
  return t;
}
