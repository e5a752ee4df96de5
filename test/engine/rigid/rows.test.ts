// The rigid rows' integration (rigid/rows.ts) and the shock sweep's set-up (orderForShock): the rotation (rc, rs) a
// substep's turn brings up to the angle stays cos and sin of it at every spin rate (the series for turns up to
// SERIES_TURN, Math.cos/Math.sin beyond; one row in RESYNC_STEPS afresh a step), and the set-up finds a contact between
// masses 10× apart, and only then.
import { expect } from 'chai';
import { World } from '../../../src/engine/index.js';
import { ParticleStore } from '../../../src/engine/particles.js';
import { integrateRotation, resyncRotation, syncRotation, updateAngularVelocity, MAX_TURN, RESYNC_STEPS, SERIES_TURN } from '../../../src/engine/rigid/rows.js';
import { orderForShock } from '../../../src/engine/rigid/contact-solver.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import { box } from '../helpers.js';


const contextOf = (world: World): StepContext => (world as unknown as { ctx: StepContext }).ctx;

describe('rigid rows: integration of the rotation', () => {
  // One row per spin rate (rad/s): turns of 5.6e-5 to 0.5 rad a substep at h = 1/360, across the series' range (to
  // SERIES_TURN = 0.1 rad, 36 rad/s), the Math.cos/Math.sin range and the MAX_TURN cap (the last two).
  const RATES = [0.02, 0.2, 0.36, 1, 5, 21, 22, 35.9, 36.1, 60, 179, 200, -0.7, -15, -35.9, -400];
  const h = 1 / 360;

  function spinning(): { p: ParticleStore; rows: Int32Array } {
    const p = new ParticleStore();
    p.reserve(RATES.length);
    p.count = RATES.length;
    const rows = new Int32Array(RATES.length);
    RATES.forEach((w, k) => {
      rows[k] = k;
      p.omega[k] = w;
      p.invInertia[k] = 2;
      p.angle[k] = p.qangle[k] = 0.3 * k;
      p.rc[k] = Math.cos(0.3 * k);
      p.rs[k] = Math.sin(0.3 * k);
    });
    return { p, rows };
  }

  it('keeps (rc, rs) at cos and sin of the angle through 720 substeps without an exact sync, at every rate', () => {
    const { p, rows } = spinning();
    const step = new Float64Array([h, 1]);
    let worst = 0;
    for (let s = 0; s < 720; s++) {
      integrateRotation(p, p.torque, rows, rows.length, step);
      for (let k = 0; k < rows.length; k++) {
        expect(p.qangle[k]).to.equal(p.angle[k]);
        worst = Math.max(worst, Math.abs(p.rc[k] - Math.cos(p.angle[k])), Math.abs(p.rs[k] - Math.sin(p.angle[k])));
      }
    }
    // Two seconds of turns without an exact sync accumulate rounding only (one turn of 0.0997 by the series to d⁴ for
    // the cosine, as it was before the series went to d⁸, would be 2.7e-11 off).
    expect(worst).to.be.lessThan(1e-13);
    RATES.forEach((w, k) => {
      // Free spin: angle = start + 720·h·ω (ω capped at MAX_TURN/h).
      const turn = Math.sign(w) * Math.min(Math.abs(w) * h, MAX_TURN);
      expect(p.angle[k], `ω ${w}`).to.be.closeTo(0.3 * k + 720 * turn, 1e-9);
    });
  });

  it('follows corrections made between substeps (syncRotation), and ω = (θ − θ̄)/h after them', () => {
    const { p, rows } = spinning();
    const step = new Float64Array([h, 1]);
    for (let s = 0; s < 50; s++) {
      integrateRotation(p, p.torque, rows, rows.length, step);
      // A solver's correction: the angle moves, the rotation does not (yet).
      for (let k = 0; k < rows.length; k++) p.angle[k] += 1e-4 * ((k % 3) - 1);
      updateAngularVelocity(p, rows, rows.length, step);
      for (let k = 0; k < rows.length; k++) expect(p.omega[k]).to.be.closeTo((p.angle[k] - p.pangle[k]) / h, 1e-9);
    }
    syncRotation(p, rows, rows.length);
    for (let k = 0; k < rows.length; k++) {
      expect(p.rc[k], `row ${k}`).to.be.closeTo(Math.cos(p.angle[k]), 1e-14);
      expect(p.rs[k], `row ${k}`).to.be.closeTo(Math.sin(p.angle[k]), 1e-14);
    }
  });

  it('the series is exact to rounding at every turn up to SERIES_TURN (against Math.cos/Math.sin of the sum)', () => {
    const p = new ParticleStore();
    p.reserve(1);
    p.count = 1;
    const rows = new Int32Array([0]);
    let worst = 0;
    for (let k = 0; k <= 2000; k++) {
      // Turns from −SERIES_TURN to SERIES_TURN (both ends just inside), from 1,000 angles.
      const d = (k / 1000 - 1) * SERIES_TURN * (1 - 1e-12);
      const from = 0.37 * k;
      p.angle[0] = from + d;
      p.qangle[0] = from;
      p.rc[0] = Math.cos(from);
      p.rs[0] = Math.sin(from);
      syncRotation(p, rows, 1);
      worst = Math.max(worst, Math.abs(p.rc[0] - Math.cos(from + d)), Math.abs(p.rs[0] - Math.sin(from + d)));
    }
    // A few ulps of 1 (the sum from + d rounds too); the series to d⁴, as it was, is 2.8e-11 off at 0.1.
    expect(worst).to.be.lessThan(1e-15);
  });

  it('resyncs one row in RESYNC_STEPS a step from Math.cos/Math.sin, in turn, so every row within RESYNC_STEPS steps', () => {
    const n = 2 * RESYNC_STEPS + 10;
    const p = new ParticleStore();
    p.reserve(n);
    p.count = n;
    const rows = new Int32Array(n).map((_, k) => n - 1 - k);
    // Rotations off their angles by 1e-9, as rounding never gets; each resync puts one back exactly.
    for (let i = 0; i < n; i++) {
      p.angle[i] = p.qangle[i] = 0.1 * i;
      p.rc[i] = Math.cos(0.1 * i) + 1e-9;
      p.rs[i] = Math.sin(0.1 * i);
    }
    const exact = (i: number): boolean => p.rc[i] === Math.cos(p.angle[i]) && p.rs[i] === Math.sin(p.angle[i]);
    resyncRotation(p, rows, n, 7);
    expect(Array.from(rows).filter(exact)).to.deep.equal([rows[7], rows[7 + RESYNC_STEPS], rows[7 + 2 * RESYNC_STEPS]]);
    for (let step = 8; step < 7 + RESYNC_STEPS; step++) resyncRotation(p, rows, n, step);
    expect(Array.from(rows).every(exact)).to.equal(true);
  });

  it('a spinning disc in a world: its pose after each step has the rotation of its angle (to rounding since its last resync)', () => {
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    const discs = [0.5, 8, 30].map((w, k) => world.addRigidBody({ x: 3 * k, y: 0, radius: 0.5, angularVelocity: w }));
    const p = contextOf(world).particles;
    for (let s = 0; s < 120; s++) {
      world.step();
      discs.forEach((d, k) => {
        const i = contextOf(world).bodies.particles[contextOf(world).bodies.slotOf(d)][0];
        // At most RESYNC_STEPS steps of series turns since the last exact rotation (measured: 4.3e-15).
        expect(p.rc[i], `disc ${k}`).to.be.closeTo(Math.cos(p.angle[i]), 1e-13);
        expect(p.rs[i], `disc ${k}`).to.be.closeTo(Math.sin(p.angle[i]), 1e-13);
      });
    }
    expect(world.bodyPose(discs[1]).angle).to.be.closeTo(8 * 2, 1e-9);
  });
});

describe('rigid contacts: the shock sweep set-up (orderForShock)', () => {
  /** A light box on the ground and a box `ratio` times its mass on it (or beside it, `apart`), one step. */
  function pile(ratio: number, apart = false): StepContext {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel: 'js' });
    world.addRigidBody({ points: box(10, 0.5), x: 0, y: 0.5, type: 'static' });
    world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -0.5, mass: 1 });
    world.addRigidBody({ points: box(0.5, 0.5), x: apart ? 3 : 0, y: apart ? -0.5 : -1.5, mass: ratio });
    world.step();
    return contextOf(world);
  }

  it('orders the manifolds for the shock sweep when a contact joins masses 10x apart or more', () => {
    for (const ratio of [10.5, 100, 1 / 50]) {
      const ctx = pile(ratio);
      orderForShock(ctx.rigidContacts, ctx.particles);
      // Two levels above the ground: the lower box's manifold with the ground and the upper box's with it.
      expect(ctx.rigidContacts.shockCount, `ratio ${ratio}`).to.equal(2);
    }
  });

  it('leaves it off when the masses in contact are alike, even when other bodies differ 10x', () => {
    for (const [ratio, apart] of [[1, false], [9.5, false], [0.2, false], [100, true], [1 / 100, true]] as const) {
      const ctx = pile(ratio, apart);
      orderForShock(ctx.rigidContacts, ctx.particles);
      expect(ctx.rigidContacts.shockCount, `ratio ${ratio}${apart ? ', apart' : ''}`).to.equal(0);
      expect(ctx.rigidContacts.shockReady).to.equal(true);
      expect(ctx.rigidContacts.edgePoints).to.equal(0);
    }
  });
});
