// Bounces of particle frames: a box or polygon of model 'particles' is corner particles braced by sticks (seed 2.3).
// The velocity passes bounce the corner that touched alone; the sticks then share its new speed with the corners
// still falling, and a frame with e = 1 dropped from 2 rose to 0.03. After the passes, this phase solves the
// substep's bounces again with each frame that took part as one rigid body (its particles' mass, centre, inertia,
// momentum and angular momentum), so the impulse reaches the whole frame as it reaches a rigid box. With e = 0 the
// velocity passes stop the corner that touched alone, likewise: they note a frame's impacts (approach faster than
// BOUNCE_THRESHOLD) as bounces with target 0, and these stops take Coulomb's friction here too.
import { ParticleFlag, type ParticleStore } from '../particles.js';
import type { BodyRegistry } from '../body-registry.js';
import { grown } from '../table.js';
import { angularMomentum, centre } from './spin.js';

/** Gauss–Seidel passes over a substep's bounces (a box landing flat converges by 1/9 a pass). */
const PASSES = 8;

/** A frame's reals in FrameBounces.frame: mass, centre, inertia about it, velocity, angular velocity, angular momentum. */
const FRAME_FIELDS = 8;
const MASS = 0;
const CX = 1;
const CY = 2;
const INERTIA = 3;
const VX = 4;
const VY = 5;
const OMEGA = 6;
const SPIN = 7;

/**
 * The bounces the velocity passes applied in the current substep (particle contacts, the walls, rigid contacts), and
 * their stops (e = 0) of impacts on particle frames:
 * per bounce its two sides, the normal n from side 0 to side 1, and the target normal speed of side 1 relative to
 * side 0 along n. Side s of bounce k is at 2k + s: up to two rows p0, p1 (p1 = −1: one; p0 = −1: the world) with p1's
 * weight `alpha` on an edge, and the contact point's arm from a rigid row's centre (0 for a particle).
 */
export class FrameBounces {
  count = 0;
  p0 = new Int32Array(16);
  p1 = new Int32Array(16);
  alpha = new Float64Array(16);
  armX = new Float64Array(16);
  armY = new Float64Array(16);
  nx = new Float64Array(8);
  ny = new Float64Array(8);
  target = new Float64Array(8);
  /** The impulse this phase added (never below 0: it pushes only). */
  impulse = new Float64Array(8);
  /** Per bounce: its friction coefficient, and the friction impulse this phase added (Coulomb's: up to μ × impulse). */
  friction = new Float64Array(8);
  impulseT = new Float64Array(8);
  /** Per bounce: its sides' separation along n as the position pass left it, and the push that restores it. */
  separation = new Float64Array(8);
  shift = new Float64Array(8);

  /**
   * Per particle row: 1 when its body may be a frame (kind 'rigid', two rows or more, none a rigid row; rebuilt with
   * the topology). The velocity passes note stops (e = 0) only where a frame takes part; movability is judged here.
   */
  frameRow = new Uint8Array(16);
  /** Some body may be a frame: each substep then keeps where it integrated to (ParticleStore qx, qy). */
  anyFrame = false;

  /**
   * Per particle row: its frame's index in `frame` while the phase runs (−1: none; −2: a body that is no frame; −3: a
   * frame not loaded yet that bounces off a movable side). All −1 as the phase begins.
   */
  frameOf = new Int32Array(16);
  /** Per frame: its body slot, and its reals (FRAME_FIELDS each). */
  frameSlot = new Int32Array(4);
  frame = new Float64Array(4 * FRAME_FIELDS);
  frameCount = 0;

  /** A new bounce's index; the caller writes its columns (sides with setSide's layout; friction 0 unless it sets it). */
  add(): number {
    const k = this.count++;
    if (k >= this.nx.length) {
      for (const name of ['nx', 'ny', 'target', 'impulse', 'friction', 'impulseT', 'separation', 'shift'] as const) this[name] = grown(this[name], k + 1);
      for (const name of ['p0', 'p1'] as const) this[name] = grown(this[name], 2 * this.nx.length);
      for (const name of ['alpha', 'armX', 'armY'] as const) this[name] = grown(this[name], 2 * this.nx.length);
    }
    this.friction[k] = 0;
    return k;
  }
}

/** Side s of bounce k: one row (p1 = −1) or an edge (p1 with weight alpha), and an arm from a rigid row's centre. */
export function setSide(b: FrameBounces, k: number, s: 0 | 1, p0: number, p1: number): void {
  const j = 2 * k + s;
  b.p0[j] = p0;
  b.p1[j] = p1;
  b.alpha[j] = 0;
  b.armX[j] = 0;
  b.armY[j] = 0;
}

/** Velocity of side j's point (written to `sv`), its inverse mass along n, and impulses along n. */
const sv = new Float64Array(2);
/**
 * A result (a separation, an inverse mass) out of, and an impulse into, the helpers below: V8 boxes a double passed
 * to or returned from a call it does not inline.
 */
const io = new Float64Array(2);
/** The direction inverseMass() and push() act along: a bounce's normal, or its tangent (−ny, nx) for friction. */
const dir = new Float64Array(2);

/**
 * Solves the substep's bounces again with every particle frame in them as one rigid body, and clears the list. A
 * frame is a body of kind 'rigid' built of particles (none a rigid row), all of them movable.
 */
export function solveFrameBounces(b: FrameBounces, p: ParticleStore, bodies: BodyRegistry, h: number): void {
  if (b.count === 0) return;
  b.frameOf = grown(b.frameOf, p.count);
  b.frameOf.fill(-1);
  b.frameCount = 0;
  // The frames that bounce off a movable side, other than a frame that does not in turn: their rows −3 until loaded
  // (loadFrame). (Index −1, no row, reads undefined.)
  for (let again = true; again; ) {
    again = false;
    for (let j = 0, n = 2 * b.count; j < n; j++) {
      const q = b.p0[j];
      const o = b.p0[j ^ 1];
      const moves = b.frameRow[o] === 1 ? b.frameOf[o] === -3 : p.invMass[o] > 0 || p.invMass[b.p1[j ^ 1]] > 0;
      if (moves && b.frameRow[q] === 1 && p.invMass[q] > 0 && b.frameOf[q] === -1) {
        for (const r of bodies.particles[bodies.ownerOf(q)]) b.frameOf[r] = -3;
        again = true;
      }
    }
  }
  for (let j = 0, n = 2 * b.count; j < n; j++) {
    if (b.p0[j] >= 0) loadFrame(b, p, bodies, b.p0[j], h);
  }
  if (b.frameCount > 0) {
    // Each frame back on the shape it had at the substep's start (its centre and mean turn kept): the position pass
    // moved the corners that touched alone, and the sticks, in their one iteration, sprang that squeeze back out as
    // speed in the next substeps, against the other side. With e = 0 two frames parted at a quarter of their
    // approach; with e = 1 each bounce rose about 0.005 short.
    for (let k = 0; k < b.count; k++) {
      separationOf(b, p, k);
      b.separation[k] = io[0];
    }
    for (let f = 0; f < b.frameCount; f++) fitFrame(b, p, bodies.particles[b.frameSlot[f]], f * FRAME_FIELDS);
    // The velocity passes took each bounce's target from its corners' approach at the substep's start (their speed
    // over the substep before), and the frame's impulse acts at its point now, which the frame's turn has moved: a
    // corner below the centre of a frame spun at 12 rad/s approached at 6.41 there, not 6.61, and with e = 1 the
    // bounce gained 2.5%. Scaled by the frame's approach there over its corners' own (both as integrated, loadFrame;
    // a frame that met a movable side has its corners' speed after the velocity passes: mostly parting, left as is).
    for (let k = 0; k < b.count; k++) {
      dir[0] = b.nx[k];
      dir[1] = b.ny[k];
      relativeAlong(b, p, 2 * k, 2 * k + 1, 1);
      const own = io[0];
      relativeAlong(b, p, 2 * k, 2 * k + 1, 0);
      const now = io[0];
      if (own < 0 && b.target[k] > 0) b.target[k] *= now >= 0 ? 0 : now < own ? 1 : now / own;
    }
    b.impulse.fill(0, 0, b.count);
    b.impulseT.fill(0, 0, b.count);
    for (let pass = 0; pass < PASSES; pass++) for (let k = 0; k < b.count; k++) solveImpulse(b, p, k, 0);
    // Coulomb's friction on these impulses, toward no sliding, once they have settled: taken pass by pass with them,
    // a landing's two corners pushed the frame's turn back and forth and their friction with it (a flat landing with
    // e = 0.8 spun and landed crooked). The velocity passes gave the corners that touched theirs on their own
    // impulses only: a frame landing at 45° with μ = 0.5, e = 0 kept 0.82–0.99 of its slide where Coulomb leaves 0.5.
    for (let pass = 0; pass < PASSES; pass++) {
      for (let k = 0; k < b.count; k++) solveImpulse(b, p, k, 1);
      for (let k = 0; k < b.count; k++) solveImpulse(b, p, k, 0);
    }
    // The overlap the fit gave back (the squeeze was the position pass's push) is pushed out again by moving the
    // frames, as rigid bodies, after the velocities are taken: it adds no speed.
    b.shift.fill(0, 0, b.count);
    for (let pass = 0; pass < PASSES; pass++) {
      for (let k = 0; k < b.count; k++) {
        const j0 = 2 * k;
        const j1 = j0 + 1;
        const f0 = inFrame(b, j0);
        const f1 = inFrame(b, j1);
        if (!f0 && !f1) continue;
        separationOf(b, p, k);
        const error = io[0] - b.separation[k];
        dir[0] = b.nx[k];
        dir[1] = b.ny[k];
        let w = 0;
        if (f0) {
          inverseMass(b, p, j0);
          w += io[0];
        }
        if (f1) {
          inverseMass(b, p, j1);
          w += io[0];
        }
        if (w === 0) continue;
        const was = b.shift[k];
        const now = Math.max(0, was - error / w);
        if (now === was) continue;
        b.shift[k] = now;
        io[1] = now - was;
        if (f1) shiftFrame(b, p, bodies, j1);
        io[1] = was - now;
        if (f0) shiftFrame(b, p, bodies, j0);
      }
    }
    for (let f = 0; f < b.frameCount; f++) writeBack(b, p, bodies.particles[b.frameSlot[f]], f * FRAME_FIELDS);
  }
  b.count = 0;
}

function inFrame(b: FrameBounces, j: number): boolean {
  return b.p0[j] >= 0 && b.frameOf[b.p0[j]] >= 0;
}

/**
 * Row i's body as a rigid frame: its mass, centre, inertia and rigid motion (momentum, angular momentum). A frame whose
 * bounces meet only immovable sides (the world, static bodies) or frames like it bounces from its motion as integrated
 * (qx − px over h), before any contact: the velocity passes and the pushes out of the overlap had given each point
 * that touched an impulse of its own, which the impulses here, pushing only, can add to but not take back (a spun
 * frame landing on two points of an edge kept the one's and gained 5%; thrown at 45° onto a rigid floor it kept up to
 * 0.74 of its slide for μ = 0.5). Against any other movable side those impulses keep the momentum (rows −3). (A body
 * resting on it, with no bounce, loses its push on it for the substep: about its weight × h of momentum.)
 */
function loadFrame(b: FrameBounces, p: ParticleStore, bodies: BodyRegistry, i: number, h: number): void {
  // (−1 and −3: not loaded yet.)
  if (b.frameOf[i] > -1 || b.frameOf[i] === -2 || p.flags[i] & ParticleFlag.Rigid) return;
  const slot = bodies.ownerOf(i);
  if (slot < 0) return;
  const rows = bodies.particles[slot];
  const { vx, vy, invMass } = p;
  let movable = bodies.kind[slot] === 'rigid' && rows.length >= 2;
  let held = true;
  for (const r of rows) {
    if (invMass[r] === 0 || p.flags[r] & ParticleFlag.Rigid) movable = false;
    if (b.frameOf[r] === -3) held = false;
  }
  if (!movable) {
    for (const r of rows) b.frameOf[r] = -2;
    return;
  }
  const f = b.frameCount++;
  if (f === b.frameSlot.length) {
    b.frameSlot = grown(b.frameSlot, f + 1);
    b.frame = grown(b.frame, b.frameSlot.length * FRAME_FIELDS);
  }
  b.frameSlot[f] = slot;
  for (const r of rows) {
    if (held) {
      vx[r] = (p.qx[r] - p.px[r]) / h;
      vy[r] = (p.qy[r] - p.py[r]) / h;
    }
    b.frameOf[r] = f;
  }
  const spin = angularMomentum(p, rows);
  const inertia = centre[2];
  const o = f * FRAME_FIELDS;
  b.frame[o + MASS] = centre[5];
  b.frame[o + CX] = centre[0];
  b.frame[o + CY] = centre[1];
  b.frame[o + INERTIA] = inertia;
  b.frame[o + VX] = centre[3];
  b.frame[o + VY] = centre[4];
  b.frame[o + OMEGA] = inertia > 0 ? spin / inertia : 0;
  b.frame[o + SPIN] = spin;
}

/**
 * The frame's particles onto the shape they had at the substep's start (px, py), turned by the mean turn since
 * (the best fit by mass) about the centre they have now; its inertia for that shape, and its angular velocity for
 * the angular momentum it had.
 */
function fitFrame(b: FrameBounces, p: ParticleStore, rows: Int32Array, o: number): void {
  const { x, y, px, py, invMass } = p;
  const m = b.frame[o + MASS];
  const cx = b.frame[o + CX];
  const cy = b.frame[o + CY];
  let qx = 0;
  let qy = 0;
  for (const r of rows) {
    const mr = 1 / invMass[r];
    qx += mr * px[r];
    qy += mr * py[r];
  }
  qx /= m;
  qy /= m;
  let dot = 0;
  let cross = 0;
  for (const r of rows) {
    const mr = 1 / invMass[r];
    const ax = px[r] - qx;
    const ay = py[r] - qy;
    const bx = x[r] - cx;
    const by = y[r] - cy;
    dot += mr * (ax * bx + ay * by);
    cross += mr * (ax * by - ay * bx);
  }
  const len = Math.sqrt(dot * dot + cross * cross);
  if (!(len > 0)) return;
  const c = dot / len;
  const s = cross / len;
  let inertia = 0;
  for (const r of rows) {
    const ax = px[r] - qx;
    const ay = py[r] - qy;
    x[r] = cx + c * ax - s * ay;
    y[r] = cy + s * ax + c * ay;
    inertia += (ax * ax + ay * ay) / invMass[r];
  }
  b.frame[o + INERTIA] = inertia;
  b.frame[o + OMEGA] = inertia > 0 ? b.frame[o + SPIN] / inertia : 0;
}

/**
 * Bounce k's impulse along n (t 0: its sides' normal speed brought to its target; it only pushes), or its friction along
 * (−ny, nx) (t 1: their sliding stopped, within μ × its impulse along n).
 */
function solveImpulse(b: FrameBounces, p: ParticleStore, k: number, t: 0 | 1): void {
  const j0 = 2 * k;
  const j1 = j0 + 1;
  const mu = b.friction[k];
  if ((t && !(mu > 0)) || (!inFrame(b, j0) && !inFrame(b, j1))) return;
  dir[0] = t ? -b.ny[k] : b.nx[k];
  dir[1] = t ? b.nx[k] : b.ny[k];
  relativeAlong(b, p, j0, j1);
  const w = io[1];
  if (w === 0) return;
  const sum = t ? b.impulseT : b.impulse;
  const limit = mu * b.impulse[k];
  const was = sum[k];
  const now = was + ((t ? 0 : b.target[k]) - io[0]) / w;
  sum[k] = t ? (now > limit ? limit : now < -limit ? -limit : now) : now > 0 ? now : 0;
  io[1] = sum[k] - was;
  exchange(b, p, j0, j1);
}

/**
 * Along `dir` at a bounce's sides j0, j1: side 1's speed less side 0's into io[0], their inverse masses' sum into io[1]
 * (`own` 1: a frame's point at its particles' own speed).
 */
function relativeAlong(b: FrameBounces, p: ParticleStore, j0: number, j1: number, own: 0 | 1 = 0): void {
  const dx = dir[0];
  const dy = dir[1];
  sideVelocity(b, p, j1, own);
  let v = sv[0] * dx + sv[1] * dy;
  sideVelocity(b, p, j0, own);
  v -= sv[0] * dx + sv[1] * dy;
  inverseMass(b, p, j0);
  let w = io[0];
  inverseMass(b, p, j1);
  w += io[0];
  io[0] = v;
  io[1] = w;
}

/** The impulse io[1] along `dir` between a bounce's sides: side 1 pushed forward, side 0 back. */
function exchange(b: FrameBounces, p: ParticleStore, j0: number, j1: number): void {
  const change = io[1];
  push(b, p, j1);
  io[1] = -change;
  push(b, p, j0);
}

/** Bounce k's separation along n into io[0]: side 1's point less side 0's (the world's counts as 0: only changes are read). */
function separationOf(b: FrameBounces, p: ParticleStore, k: number): void {
  const nx = b.nx[k];
  const ny = b.ny[k];
  let s = 0;
  if (b.p0[2 * k + 1] >= 0) {
    pointOf(b, p, 2 * k + 1);
    s += sv[0] * nx + sv[1] * ny;
  }
  if (b.p0[2 * k] >= 0) {
    pointOf(b, p, 2 * k);
    s -= sv[0] * nx + sv[1] * ny;
  }
  io[0] = s;
}

/** Side j's frame moved as a rigid body by a positional push io[1] along n at its point (its centre and turn). */
function shiftFrame(b: FrameBounces, p: ParticleStore, bodies: BodyRegistry, j: number): void {
  const P = io[1];
  const nx = b.nx[j >> 1];
  const ny = b.ny[j >> 1];
  const f = b.frameOf[b.p0[j]];
  const o = f * FRAME_FIELDS;
  pointOf(b, p, j);
  const cx = b.frame[o + CX];
  const cy = b.frame[o + CY];
  const rn = (sv[0] - cx) * ny - (sv[1] - cy) * nx;
  const im = 1 / b.frame[o + MASS];
  const dx = im * P * nx;
  const dy = im * P * ny;
  const turn = (rn * P) / b.frame[o + INERTIA];
  const c = Math.cos(turn);
  const s = Math.sin(turn);
  const { x, y } = p;
  for (const r of bodies.particles[b.frameSlot[f]]) {
    const rx = x[r] - cx;
    const ry = y[r] - cy;
    x[r] = cx + dx + c * rx - s * ry;
    y[r] = cy + dy + s * rx + c * ry;
  }
  b.frame[o + CX] = cx + dx;
  b.frame[o + CY] = cy + dy;
}

/** Side j's contact point: its edge point, or its row plus the arm. */
function pointOf(b: FrameBounces, p: ParticleStore, j: number): void {
  const q0 = b.p0[j];
  const q1 = b.p1[j];
  if (q1 >= 0) {
    const a = b.alpha[j];
    sv[0] = (1 - a) * p.x[q0] + a * p.x[q1];
    sv[1] = (1 - a) * p.y[q0] + a * p.y[q1];
  } else {
    sv[0] = p.x[q0] + b.armX[j];
    sv[1] = p.y[q0] + b.armY[j];
  }
}

function sideVelocity(b: FrameBounces, p: ParticleStore, j: number, own: 0 | 1): void {
  const q0 = b.p0[j];
  if (q0 < 0) {
    sv[0] = 0;
    sv[1] = 0;
    return;
  }
  const f = b.frameOf[q0];
  if (f >= 0 && own === 0) {
    const o = f * FRAME_FIELDS;
    pointOf(b, p, j);
    const w = b.frame[o + OMEGA];
    const rx = sv[0] - b.frame[o + CX];
    const ry = sv[1] - b.frame[o + CY];
    sv[0] = b.frame[o + VX] - w * ry;
    sv[1] = b.frame[o + VY] + w * rx;
    return;
  }
  const q1 = b.p1[j];
  if (q1 >= 0) {
    const a = b.alpha[j];
    sv[0] = (1 - a) * p.vx[q0] + a * p.vx[q1];
    sv[1] = (1 - a) * p.vy[q0] + a * p.vy[q1];
  } else {
    const w = p.omega[q0];
    sv[0] = p.vx[q0] - w * b.armY[j];
    sv[1] = p.vy[q0] + w * b.armX[j];
  }
}

/** Side j's inverse mass along `dir`, at its point, into io[0]. */
function inverseMass(b: FrameBounces, p: ParticleStore, j: number): void {
  const nx = dir[0];
  const ny = dir[1];
  const q0 = b.p0[j];
  if (q0 < 0) {
    io[0] = 0;
    return;
  }
  const f = b.frameOf[q0];
  if (f >= 0) {
    const o = f * FRAME_FIELDS;
    pointOf(b, p, j);
    const rn = (sv[0] - b.frame[o + CX]) * ny - (sv[1] - b.frame[o + CY]) * nx;
    io[0] = 1 / b.frame[o + MASS] + (rn * rn) / b.frame[o + INERTIA];
    return;
  }
  const q1 = b.p1[j];
  if (q1 >= 0) {
    const a = b.alpha[j];
    io[0] = (1 - a) * (1 - a) * p.invMass[q0] + a * a * p.invMass[q1];
    return;
  }
  const rn = b.armX[j] * ny - b.armY[j] * nx;
  io[0] = p.invMass[q0] + p.invInertia[q0] * rn * rn;
}

/** Impulse io[1] along `dir` on side j. */
function push(b: FrameBounces, p: ParticleStore, j: number): void {
  const P = io[1];
  const nx = dir[0];
  const ny = dir[1];
  const q0 = b.p0[j];
  if (q0 < 0 || P === 0) return;
  const f = b.frameOf[q0];
  if (f >= 0) {
    const o = f * FRAME_FIELDS;
    pointOf(b, p, j);
    const rn = (sv[0] - b.frame[o + CX]) * ny - (sv[1] - b.frame[o + CY]) * nx;
    const im = 1 / b.frame[o + MASS];
    b.frame[o + VX] += im * P * nx;
    b.frame[o + VY] += im * P * ny;
    b.frame[o + OMEGA] += (rn * P) / b.frame[o + INERTIA];
    return;
  }
  const q1 = b.p1[j];
  if (q1 >= 0) {
    const a = b.alpha[j];
    p.vx[q0] += (1 - a) * p.invMass[q0] * P * nx;
    p.vy[q0] += (1 - a) * p.invMass[q0] * P * ny;
    p.vx[q1] += a * p.invMass[q1] * P * nx;
    p.vy[q1] += a * p.invMass[q1] * P * ny;
  } else {
    p.vx[q0] += p.invMass[q0] * P * nx;
    p.vy[q0] += p.invMass[q0] * P * ny;
    p.omega[q0] += p.invInertia[q0] * (b.armX[j] * ny - b.armY[j] * nx) * P;
  }
}

/** The frame's particles move with its rigid motion. */
function writeBack(b: FrameBounces, p: ParticleStore, rows: Int32Array, o: number): void {
  const cx = b.frame[o + CX];
  const cy = b.frame[o + CY];
  const w = b.frame[o + OMEGA];
  for (const r of rows) {
    p.vx[r] = b.frame[o + VX] - w * (p.y[r] - cy);
    p.vy[r] = b.frame[o + VY] + w * (p.x[r] - cx);
  }
}
