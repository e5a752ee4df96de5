import { grown } from '../table.js';
import { ParticleFlag, type ParticleStore } from '../particles.js';
import type { ContactPairs } from './events.js';

/** A step's move (squared) at least this much larger than the step before's counts as growing (1% in speed). */
const GROWTH = 1.0201;
/** Steps in a row of growing motion that keep a body awake however slow it still is. */
const GROWING_STEPS = 10;

/**
 * Sleeping: bodies that have all moved slower than `speedThreshold` for `timeToSleep` seconds, together with every
 * body they touch or are constrained to (their island), stop being simulated. A sleeping body's particles park their
 * inverse mass, so they cost nothing and act as static to whatever touches them; touching an awake body wakes the
 * island again, and so does anything the user does to it. When every body sleeps, a step does no work at all.
 */
export class Sleep {
  enabled = true;
  speedThreshold = 0.05;
  timeToSleep = 0.5;

  /** Per body slot. */
  sleepTime = new Float64Array(16);
  /** The body's fastest point's squared move over the last step, and for how many steps in a row it grew. */
  lastMove = new Float64Array(16);
  growing = new Uint8Array(16);
  asleep = new Uint8Array(16);
  /** 1 for bodies that take part (live, with at least one movable particle when awake). */
  dynamic = new Uint8Array(16);
  private parent = new Int32Array(16);
  private islandMin = new Float64Array(16);
  /** Per particle: owning body slot (−1 for none) and inverse mass parked while asleep. */
  particleBody = new Int32Array(16);
  parkedInvMass = new Float64Array(16);
  /** A rigid body's inverse inertia, parked like its inverse mass. */
  parkedInvInertia = new Float64Array(16);
  /** Body pairs joined by constraints that span two bodies. */
  private linksA = new Int32Array(16);
  private linksB = new Int32Array(16);
  private linkCount = 0;
  awakeCount = 0;
  /** Bodies asleep now (0: the wake check before the solve has nothing to do). */
  asleepCount = 0;

  /** Rebuilds the particle → body map and the cross-body links (outside step(), when the topology changed). */
  rebuild(slots: number, particleCount: number, bodyParticles: (slot: number) => Int32Array | null): void {
    for (const name of ['sleepTime', 'lastMove', 'growing', 'asleep', 'dynamic', 'parent', 'islandMin'] as const) {
      (this as unknown as Record<string, Float64Array>)[name] = grown((this as unknown as Record<string, Float64Array>)[name], slots);
    }
    this.particleBody = grown(this.particleBody, particleCount);
    this.parkedInvMass = grown(this.parkedInvMass, particleCount);
    this.parkedInvInertia = grown(this.parkedInvInertia, particleCount);
    this.particleBody.fill(-1, 0, particleCount);
    for (let s = 0; s < slots; s++) {
      const idx = bodyParticles(s);
      if (idx) for (const i of idx) this.particleBody[i] = s;
    }
  }

  /** Body pairs joined by a constraint that spans two bodies (joints, springs between bodies). */
  setLinks(links: [number, number][]): void {
    this.linksA = grown(this.linksA, links.length);
    this.linksB = grown(this.linksB, links.length);
    this.linkCount = 0;
    for (const [a, b] of links) {
      this.linksA[this.linkCount] = a;
      this.linksB[this.linkCount++] = b;
    }
  }

  private find(s: number): number {
    const parent = this.parent;
    while (parent[s] !== s) {
      parent[s] = parent[parent[s]];
      s = parent[s];
    }
    return s;
  }

  private union(a: number, b: number): void {
    const ra = this.find(a);
    const rb = this.find(b);
    if (ra !== rb) this.parent[ra < rb ? rb : ra] = ra < rb ? ra : rb;
  }

  /**
   * After a step: update each body's still-time, wake sleeping bodies that an awake body touched, group bodies
   * into islands and put islands that have all been still long enough to sleep.
   */
  update(slots: number, alive: Uint8Array, bodyParticles: (slot: number) => Int32Array, p: ParticleStore, c: ContactPairs, r: ContactPairs, dt: number): void {
    if (!this.enabled) return;
    const { x, y, sx, sy, invMass, angle, sangle, radius, flags } = p;
    // Judged on the motion over the whole step: substep jitter that goes nowhere should not keep a body awake.
    const limit = this.speedThreshold * dt;
    const limit2 = limit * limit;
    for (let s = 0; s < slots; s++) {
      this.parent[s] = s;
      if (!alive[s] || this.asleep[s]) continue;
      const idx = bodyParticles(s);
      let fastest = 0;
      let movable = 0;
      for (let k = 0; k < idx.length; k++) {
        const i = idx[k];
        // A kinematic body counts as moving: it wakes what it touches and never sleeps while it moves.
        if (invMass[i] === 0 && !(flags[i] & ParticleFlag.Kinematic)) continue;
        movable = 1;
        const dx = x[i] - sx[i];
        const dy = y[i] - sy[i];
        // A turning rigid body moves its farthest point by angle × extent.
        const turn = (angle[i] - sangle[i]) * radius[i];
        const d2 = dx * dx + dy * dy + turn * turn;
        if (d2 > fastest) fastest = d2;
      }
      this.dynamic[s] = movable;
      // A body leaving an unstable balance (a box on its corner a hair off, a ball on a peak) speeds up step after
      // step from almost nothing: still slower than the threshold after timeToSleep, it fell asleep balanced.
      const grows = fastest > GROWTH * this.lastMove[s];
      this.lastMove[s] = fastest;
      this.growing[s] = grows ? Math.min(this.growing[s] + 1, GROWING_STEPS) : 0;
      this.sleepTime[s] = movable && fastest < limit2 && this.growing[s] < GROWING_STEPS ? this.sleepTime[s] + dt : 0;
    }
    // Contacts join islands; an awake body touching a sleeping one wakes it.
    this.joinTouching(c, bodyParticles, p);
    this.joinTouching(r, bodyParticles, p);
    for (let k = 0; k < this.linkCount; k++) {
      const a = this.linksA[k];
      const b = this.linksB[k];
      if (this.asleep[a] !== this.asleep[b]) {
        this.wakeBody(a, bodyParticles(a), p);
        this.wakeBody(b, bodyParticles(b), p);
      }
      this.union(a, b);
    }
    // An island sleeps when its least-still body has been still long enough.
    this.islandMin.fill(Infinity, 0, slots);
    for (let s = 0; s < slots; s++) {
      if (!alive[s] || !this.dynamic[s] || this.asleep[s]) continue;
      const r = this.find(s);
      if (this.sleepTime[s] < this.islandMin[r]) this.islandMin[r] = this.sleepTime[s];
    }
    this.awakeCount = 0;
    for (let s = 0; s < slots; s++) {
      if (!alive[s] || !this.dynamic[s] || this.asleep[s]) continue;
      if (this.islandMin[this.find(s)] >= this.timeToSleep) this.sleepBody(s, bodyParticles(s), p);
      else this.awakeCount++;
    }
  }

  /**
   * Before the solve: a sleeping body that a moving body may touch this step (any contact found, speculative ones
   * too), or that is joined to a body woken so, wakes now, and so on through what it touches in turn. Woken after the
   * step instead, it would meet the impact as a static body: a ball swung into a resting one would bounce back off
   * it and leave it still. "Moving" is an awake body that was not still over the last step (still-time 0).
   */
  wakeTouched(contacts: ContactPairs, rigidContacts: ContactPairs, bodyParticles: (slot: number) => Int32Array, p: ParticleStore): void {
    if (!this.enabled || this.asleepCount === 0) return;
    let woke = true;
    // Each pass wakes at least one body or ends: at most one pass per sleeping body, usually one or two in all.
    while (woke && this.asleepCount > 0) {
      woke = this.wakeAcross(contacts, bodyParticles, p) || this.wakeAcross(rigidContacts, bodyParticles, p);
      for (let k = 0; k < this.linkCount; k++) {
        const a = this.linksA[k];
        const b = this.linksB[k];
        if (this.asleep[a] !== this.asleep[b] && this.sleepTime[this.asleep[a] ? b : a] === 0) {
          this.wakeBody(this.asleep[a] ? a : b, bodyParticles(this.asleep[a] ? a : b), p);
          woke = true;
        }
      }
    }
  }

  private wakeAcross(c: ContactPairs, bodyParticles: (slot: number) => Int32Array, p: ParticleStore): boolean {
    let woke = false;
    for (let i = 0; i < c.count; i++) {
      const a = c.bodyA[i];
      const b = c.bodyB[i];
      if (a < 0 || b < 0 || this.asleep[a] === this.asleep[b]) continue;
      const sleeper = this.asleep[a] ? a : b;
      const mover = sleeper === a ? b : a;
      if (!this.dynamic[mover] || this.sleepTime[mover] !== 0) continue;
      this.wakeBody(sleeper, bodyParticles(sleeper), p);
      woke = true;
    }
    return woke;
  }

  private joinTouching(c: ContactPairs, bodyParticles: (slot: number) => Int32Array, p: ParticleStore): void {
    for (let i = 0; i < c.count; i++) {
      if (!c.touched[i]) continue;
      const a = c.bodyA[i];
      const b = c.bodyB[i];
      if (a < 0 || b < 0) continue;
      if (this.asleep[a] && !this.asleep[b] && this.dynamic[b]) this.wakeBody(a, bodyParticles(a), p);
      if (this.asleep[b] && !this.asleep[a] && this.dynamic[a]) this.wakeBody(b, bodyParticles(b), p);
      if (this.dynamic[a] && this.dynamic[b]) this.union(a, b);
    }
  }

  private sleepBody(s: number, idx: Int32Array, p: ParticleStore): void {
    this.asleep[s] = 1;
    this.asleepCount++;
    for (let k = 0; k < idx.length; k++) {
      const i = idx[k];
      // A kinematic body keeps moving: it does not sleep (its island's other bodies do).
      if (p.flags[i] & ParticleFlag.Kinematic) continue;
      this.parkedInvMass[i] = p.invMass[i];
      this.parkedInvInertia[i] = p.invInertia[i];
      p.invMass[i] = 0;
      p.invInertia[i] = 0;
      p.vx[i] = p.vy[i] = p.omega[i] = 0;
      p.px[i] = p.x[i];
      p.py[i] = p.y[i];
      p.pangle[i] = p.angle[i];
    }
  }

  wakeBody(s: number, idx: Int32Array, p: ParticleStore): void {
    this.sleepTime[s] = 0;
    if (!this.asleep[s]) return;
    this.asleep[s] = 0;
    this.asleepCount--;
    this.awakeCount++;
    for (let k = 0; k < idx.length; k++) {
      const i = idx[k];
      if (p.flags[i] & ParticleFlag.Kinematic) continue;
      p.invMass[i] = this.parkedInvMass[i];
      p.invInertia[i] = this.parkedInvInertia[i];
    }
  }

  snapshot(slots: number, particles: number): Float64Array[] {
    return [this.sleepTime.slice(0, slots), Float64Array.from(this.asleep.subarray(0, slots)), this.parkedInvMass.slice(0, particles), Float64Array.of(this.awakeCount), this.parkedInvInertia.slice(0, particles)];
  }

  restore(s: Float64Array[]): void {
    this.sleepTime = grown(new Float64Array(16), s[0].length);
    this.sleepTime.set(s[0]);
    this.asleep = grown(new Uint8Array(16), s[1].length);
    this.asleep.set(s[1]);
    this.asleepCount = this.asleep.reduce((n, v) => n + v, 0);
    this.parkedInvMass = grown(new Float64Array(16), s[2].length);
    this.parkedInvMass.set(s[2]);
    this.awakeCount = s[3][0];
    this.parkedInvInertia = grown(new Float64Array(16), s[2].length);
    if (s[4]) this.parkedInvInertia.set(s[4]);
  }

  /** Inverse mass a particle has when awake (its parked value while its body sleeps). */
  awakeInvMass(i: number, p: ParticleStore): number {
    const s = this.particleBody[i];
    return s >= 0 && this.asleep[s] ? this.parkedInvMass[i] : p.invMass[i];
  }

  /** Inverse moment of inertia a rigid body's row has when awake (its parked value while the body sleeps). */
  awakeInvInertia(i: number, p: ParticleStore): number {
    const s = this.particleBody[i];
    return s >= 0 && this.asleep[s] ? this.parkedInvInertia[i] : p.invInertia[i];
  }
}
