import { expect } from 'chai';
import { World, createBox, createCircle } from '../../../src/engine/index.js';
import { scene } from './scene-helpers.js';

describe('pipeline: motion', () => {
  it('a 100-link chain and a 30×30 cloth keep link strain < 0.5% after 10 s', () => {
    for (const name of ['chain', 'cloth'] as const) {
      const { world } = scene(name, { sleeping: false });
      let worst = 0;
      for (let k = 0; k < 600; k++) {
        world.step();
        if (k >= 540) worst = Math.max(worst, world.maxStrain());
      }
      console.log(`${name}, 10 s: max strain ${(worst * 100).toFixed(4)}%`);
      expect(worst).to.be.below(0.005);
    }
  });

  it('a unit box thrown at 300 units/s never passes a static wall 0.1 thick', () => {
    for (const speed of [300, 150, 600]) {
      const { world, byId } = scene('thrown', { sleeping: false });
      const bullet = byId.get('bullet')!;
      for (const p of world.bodyParticleHandles(bullet)) world.setVelocity(p, speed, 0);
      let furthest = -Infinity;
      for (let k = 0; k < 120; k++) {
        world.step();
        for (const i of world.bodyParticleIndices(bullet)) furthest = Math.max(furthest, world.particles.x[i]);
      }
      // The wall's near face is at x = 9.95.
      expect(furthest, `at ${speed} units/s`).to.be.below(9.95 + 0.02);
    }
  });

  it('two discs thrown at each other at 300 units/s, 0.1 off head-on, glance off each other: neither passes through the other', () => {
    for (const speed of [300, 60, 20]) {
      const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
      // 10 units a step each at 300 units/s: far more than the gap of 2 and the discs' size.
      const a = createCircle(world, { x: -1.5, y: 0, radius: 0.5, vx: speed });
      const b = createCircle(world, { x: 1.5, y: 0.1, radius: 0.5, vx: -speed });
      let closest = Infinity;
      for (let k = 0; k < 60; k++) {
        world.step();
        const pa = world.bodyCentroid(a.body);
        const pb = world.bodyCentroid(b.body);
        // They roll off each other (the hit is 5.7° off head-on) and may end past each other in x, but only around:
        // never in x past each other while their paths still overlap in y.
        if (pa.x >= pb.x) expect(Math.abs(pb.y - pa.y), `at ${speed} units/s, step ${k}`).to.be.above(0.99);
        closest = Math.min(closest, Math.hypot(pb.x - pa.x, pb.y - pa.y));
      }
      // Touching is 1 apart; the overlap at the hit stays within a hundredth of a diameter.
      expect(closest, `at ${speed} units/s`).to.be.above(0.99);
    }
  });

  it('friction: a box on a 20° slope stays with μ = 0.6 and slides with μ = 0.1 as Coulomb says', () => {
    const angle20 = (20 * Math.PI) / 180;
    const slide = (mu: number) => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
      const angle = (20 * Math.PI) / 180;
      createBox(world, { x: 0, y: 0, width: 40, height: 1, angle, static: true, friction: mu });
      // Resting on the slope's top face: half a unit box plus half the slope's thickness along the normal.
      const nx = Math.sin(angle);
      const ny = -Math.cos(angle);
      const box = createBox(world, { x: nx * 1.0, y: ny * 1.0, width: 1, height: 1, angle, friction: mu });
      for (let k = 0; k < 30; k++) world.step();
      const start = world.bodyCentroid(box.body);
      for (let k = 0; k < 120; k++) world.step();
      const end = world.bodyCentroid(box.body);
      return Math.hypot(end.x - start.x, end.y - start.y);
    };
    const stuck = slide(0.6);
    const sliding = slide(0.1);
    // Sliding: a = g (sin 20° − μ cos 20°); after the first 0.5 s it moves v0·t + ½·a·t² over the next 2 s.
    const a = 10 * (Math.sin(angle20) - 0.1 * Math.cos(angle20));
    const expected = a * 0.5 * 2 + 0.5 * a * 2 * 2;
    console.log(`slope 20°: moved ${stuck.toFixed(4)} with μ 0.6, ${sliding.toFixed(3)} with μ 0.1 (analytic ${expected.toFixed(3)})`);
    expect(stuck).to.be.below(0.01);
    expect(sliding).to.be.closeTo(expected, 0.03 * expected);
  });

  it("particle balls bounce off the world's bounds and a particle floor: e = 1 keeps its height over 5 bounces, e = 0.8 each within 1% of e²ᵏ·h, e = 0 stays down (both kernels)", () => {
    // The walls only pushed particles back (Jakobsen's projection): every particle landed dead, whatever its
    // restitution. A rigid ball bounced (its walls are rigid contacts): the two agree now. On a floor of particles
    // the bounce left at −e × the speed at the step's start, before the fall to the floor: 1.252 for 1.28.
    const h = 2;
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of ['bounds', 'particles'] as const)
        for (const [e, bounces, tolerance] of [[1, 5, 1e-3], [0.8, 3, 1e-2], [0, 0, 0]] as const) {
          const world = new World({ kernel, sleeping: false, bounds: floor === 'bounds' ? { minX: -10, maxX: 10, minY: -20, maxY: 0 } : null });
          if (floor === 'particles') createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, model: 'particles', restitution: e });
          const ball = createCircle(world, { x: 0, y: -h - 0.5, radius: 0.5, restitution: e, model: 'particles' });
          const i = ball.particles[0];
          const p = world.particles;
          const peaks: number[] = [];
          let top = Infinity;
          let falling = true;
          for (let n = 0; n < 60 * 12 && peaks.length <= bounces; n++) {
            world.step();
            if (!falling) top = Math.min(top, p.y[i]);
            if (falling && p.vy[i] < -0.1) falling = false;
            else if (!falling && p.vy[i] >= 0) {
              peaks.push(-(top + 0.5));
              top = Infinity;
              falling = true;
            }
          }
          const at = `${kernel}, ${floor}, e ${e}`;
          if (e === 0) expect(peaks.length === 0 || peaks[0] < 0.01, `${at}: ${peaks[0]}`).to.equal(true);
          for (let k = 1; k <= bounces; k++) expect(peaks[k - 1], `${at}, bounce ${k}`).to.be.closeTo(h * e ** (2 * k), tolerance * h * e ** (2 * k));
        }
  });

  it("particle frames bounce as one body: a box of model 'particles' dropped flat with e = 1 keeps its height within 0.1% over 3 bounces and with e = 0.5 each within 0.5% of e²ᵏ·h, on the bounds, a rigid floor and a particle floor (both kernels)", () => {
    // The corners that touched bounced alone and the sticks shared their speed with the corners still falling:
    // dropped from 2, the frame rose 0.033 whatever its restitution. Solved again as one body it rose about 0.005
    // short a bounce (the frame, squeezed by the overlap's push, sprang back in its one iteration): e = 1 0.2%, 0.3%,
    // 0.5% short, e = 0.5 1.0%, 2.5%. Put back on its shape after the bounce: 0.01%, 0.01%, 0.00% and 0.05%, 0.16%.
    const h = 2;
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of ['bounds', 'rigid', 'particles'] as const)
        for (const [e, bounces, tolerance] of [[1, 3, 1e-3], [0.5, 2, 5e-3]] as const) {
          const world = new World({ kernel, sleeping: false, bounds: floor === 'bounds' ? { minX: -10, maxX: 10, minY: -20, maxY: 0 } : null });
          if (floor !== 'bounds') createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, model: floor, restitution: 0, friction: 0 });
          const box = createBox(world, { x: 0, y: -h - 0.5, width: 1, height: 1, restitution: e, friction: 0, model: 'particles' });
          const peaks: number[] = [];
          let last = world.bodyCentroid(box.body).y;
          let rising = false;
          for (let n = 0; n < 60 * 8 && peaks.length < bounces; n++) {
            world.step();
            const y = world.bodyCentroid(box.body).y;
            if (y < last) rising = true;
            else if (rising) {
              peaks.push(-(last + 0.5));
              rising = false;
            }
            last = y;
          }
          const at = `${kernel}, ${floor} floor, e ${e}`;
          expect(peaks.length, at).to.equal(bounces);
          for (let k = 1; k <= bounces; k++) expect(peaks[k - 1], `${at}, bounce ${k}`).to.be.closeTo(h * e ** (2 * k), tolerance * h * e ** (2 * k));
        }
  });

  it("a particle ball thrown at 45° onto the bounds, a rigid and a particle floor leaves with Coulomb's sideways speed, max(0, 1 − μ(1 + e))·v, wherever in a step it lands", () => {
    // Friction acted on the push out of the overlap only: with a bounce on the bounds the ball kept 7.3–12.6 of its
    // 14.1 sideways (μ 0.5, e 1: 0), and on a particle floor all of it, bounce or not.
    for (const floor of ['bounds', 'rigid', 'particles'] as const)
      for (const [e, mu] of [[1, 0.5], [1, 0.2], [0.5, 0.5], [0, 0.5]] as const)
        for (const late of [0, 0.02, 0.05, 0.08]) {
          const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false, boundsFriction: mu, bounds: floor === 'bounds' ? { minX: -50, maxX: 50, minY: -50, maxY: 0 } : null });
          if (floor !== 'bounds') createBox(world, { x: 0, y: 0.5, width: 100, height: 1, static: true, model: floor, friction: mu, restitution: 0 });
          const v = 10 / Math.SQRT2;
          const ball = createCircle(world, { x: 0, y: -2 - late, radius: 0.5, vx: v, vy: v, restitution: e, friction: mu, model: 'particles' });
          for (let n = 0; n < 30; n++) world.step();
          const i = world.bodyParticleIndices(ball.body)[0];
          const at = `${floor}, e ${e}, μ ${mu}, ${late} later`;
          expect(world.particles.vx[i], at).to.be.closeTo(Math.max(0, 1 - mu * (1 + e)) * v, 0.01 * v);
          expect(world.particles.vy[i], at).to.be.closeTo(-e * v, 0.01 * v);
        }
  });

  it("the same throw onto the bounds' left and right walls: Coulomb's speed along the wall, max(0, 1 − μ(1 + e))·v, and −e·v off it", () => {
    // Only floors were thrown at: the walls' friction (the push out of a side overlap and the bounce's) had no test.
    for (const side of [1, -1])
      for (const [e, mu] of [[1, 0.5], [1, 0.2], [0.5, 0.5], [0, 0.5]] as const)
        for (const late of [0, 0.02, 0.05, 0.08]) {
          const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false, boundsFriction: mu, bounds: side > 0 ? { minX: -50, maxX: 0, minY: -50, maxY: 50 } : { minX: 0, maxX: 50, minY: -50, maxY: 50 } });
          const v = 10 / Math.SQRT2;
          const ball = createCircle(world, { x: -side * (2 + late), y: 0, radius: 0.5, vx: side * v, vy: v, restitution: e, friction: mu, model: 'particles' });
          for (let n = 0; n < 30; n++) world.step();
          const i = world.bodyParticleIndices(ball.body)[0];
          const at = `${side > 0 ? 'right' : 'left'} wall, e ${e}, μ ${mu}, ${late} later`;
          expect(world.particles.vy[i], at).to.be.closeTo(Math.max(0, 1 - mu * (1 + e)) * v, 0.01 * v);
          expect(world.particles.vx[i], at).to.be.closeTo(-side * e * v, 0.01 * v);
        }
  });

  it('particle balls meeting at a glance bounce or stop along their line of centres at the touch: the energy kept at e = 1, the textbook speeds and directions at e = 1, 0.5 and 0', () => {
    // The bounce took the approach along the line of centres found a step earlier, and acted along the one of the
    // overlap: a glancing elastic hit gained up to 26% of its energy at 60 units/s, 10% at 20.
    const kinetic = (world: World) => {
      const p = world.particles;
      let sum = 0;
      for (let i = 0; i < p.count; i++) if (p.invMass[i] > 0) sum += (0.5 * (p.vx[i] ** 2 + p.vy[i] ** 2)) / p.invMass[i];
      return sum;
    };
    for (const v of [5, 20, 60])
      for (const heavy of [1, 10])
        for (let late = 0; late < 8; late++) {
          const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
          createCircle(world, { x: -3 - (late * v) / 480, y: 0.6, radius: 0.5, mass: 1, vx: v, restitution: 1, friction: 0, model: 'particles' });
          createCircle(world, { x: 0, y: 0, radius: 0.5, mass: heavy, restitution: 1, friction: 0, model: 'particles' });
          const before = kinetic(world);
          for (let n = 0; n < Math.ceil(360 / v) + 30; n++) world.step();
          expect(kinetic(world) / before, `${v} units/s, mass ${heavy}, ${late}/8 of a step later`).to.be.closeTo(1, 1e-3);
        }
    // Equal masses, 0.6 of a diameter off centre: they touch along a line 36.87° from the path. With e = 0 the stop
    // acted along the overlap's line of centres, up to 1.8° and 2.4% off at 60 units/s (0.3° at 5).
    for (const [e, speedA, speedB] of [[1, 0.6, 0.8], [0.5, Math.hypot(0.6, 0.2), 0.6], [0, Math.hypot(0.6, 0.4), 0.4]] as const)
      for (const v of [5, 20, 60])
        for (const late of [0, 3, 6]) {
          const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
          const a = createCircle(world, { x: -3 - (late * v) / 480, y: -0.6, radius: 0.5, mass: 1, vx: v, restitution: e, friction: 0, model: 'particles' });
          const b = createCircle(world, { x: 0, y: 0, radius: 0.5, mass: 1, restitution: e, friction: 0, model: 'particles' });
          for (let n = 0; n < 60; n++) world.step();
          const at = `e ${e}, ${v} units/s, ${late}/8 of a step later`;
          const va = world.getVelocity(a.particles[0]);
          const vb = world.getVelocity(b.particles[0]);
          expect(Math.hypot(va.x, va.y), `${at}: A`).to.be.closeTo(speedA * v, 1e-3 * v);
          expect(Math.hypot(vb.x, vb.y), `${at}: B`).to.be.closeTo(speedB * v, 1e-3 * v);
          expect((Math.atan2(vb.y, vb.x) * 180) / Math.PI, `${at}: B's direction`).to.be.closeTo((Math.asin(0.6) * 180) / Math.PI, 0.05);
        }
    // The same stop with friction: Coulomb's on the normal impulse (0.4·v a unit mass) along the touch's tangent, up
    // to what stops the slide (0.3·v): B leaves at 0.4·v along the line of centres and min(μ·0.4, 0.3)·v across it.
    for (const mu of [0.2, 0.5, 1])
      for (const v of [5, 60])
        for (const late of [0, 3, 6]) {
          const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
          createCircle(world, { x: -3 - (late * v) / 480, y: -0.6, radius: 0.5, mass: 1, vx: v, restitution: 0, friction: mu, model: 'particles' });
          const b = createCircle(world, { x: 0, y: 0, radius: 0.5, mass: 1, restitution: 0, friction: mu, model: 'particles' });
          for (let n = 0; n < 60; n++) world.step();
          const vb = world.getVelocity(b.particles[0]);
          const at = `μ ${mu}, ${v} units/s, ${late}/8 of a step later`;
          expect(vb.x * 0.8 + vb.y * 0.6, `${at}: B along the line of centres`).to.be.closeTo(0.4 * v, 1e-3 * v);
          expect(vb.x * 0.6 - vb.y * 0.8, `${at}: B across it`).to.be.closeTo(Math.min(mu * 0.4, 0.3) * v, 1e-3 * v);
        }
  });

  it("a Newton's cradle of particle balls passes the hit down the row: without gravity exactly, hung on strings the last rises as the rigid cradle's does", () => {
    // Without gravity, five balls 1.001 apart, the first at 3 units/s: one ball moves at a time, at 3.
    const free = new World({ gravity: { x: 0, y: 0 }, bounds: null, sleeping: false });
    const row = Array.from({ length: 5 }, (_, k) => createCircle(free, { x: k * 1.001, y: 0, radius: 0.5, restitution: 1, friction: 0, model: 'particles', vx: k === 0 ? 3 : 0 }).particles[0]);
    for (let k = 0; k < 60; k++) free.step();
    expect(row.map((p) => Math.round(free.getVelocity(p).x * 1e6) / 1e6 + 0)).to.deep.equal([0, 0, 0, 0, 3]);
    // Hung by 4-long links from pins, the first released from 35°, 45° or 55°. Before, a pair at rest at the step's
    // start took no bounce when a partner's hit reached it within the step (and one that bounced was pulled back when
    // its overlap acted again): the row swung on together and the last ball rose 7–14% of the drop.
    for (const degrees of [35, 45, 55]) {
      const world = new World({ gravity: { x: 0, y: 9.81 }, bounds: null, sleeping: false });
      const release = (degrees * Math.PI) / 180;
      const balls = Array.from({ length: 5 }, (_, k) => {
        const pivotX = 6 + k * 1.001;
        const [x, y] = k === 0 ? [pivotX - 4 * Math.sin(release), 1 + 4 * Math.cos(release)] : [pivotX, 5];
        const ball = createCircle(world, { x, y, radius: 0.5, restitution: 1, friction: 0, model: 'particles' }).particles[0];
        const pivot = world.addParticle({ x: pivotX, y: 1 });
        world.addPin(pivot);
        world.addDistance(pivot, ball, { length: 4 });
        return ball;
      });
      const drop = 4 - 4 * Math.cos(release);
      let rise = 0;
      for (let k = 0; k < 200; k++) {
        world.step();
        rise = Math.max(rise, 5 - world.getPosition(balls[4]).y);
      }
      expect(rise / drop, `${degrees}°`).to.be.greaterThan(0.7);
    }
  });

  it('an elastic particle frame that hits a body at rest without gravity keeps momentum and energy: head-on it stops and the other leaves at its speed', () => {
    // The sticks spread the touching corners' bounce over the frame after the fact: 44% of the energy was lost.
    for (const other of ['rigid disc', 'particle ball', 'particle frame', 'rigid box'] as const)
      for (const offset of [0, 0.3]) {
        const world = new World({ sleeping: false, gravity: { x: 0, y: 0 }, bounds: null });
        const frame = createBox(world, { x: 0, y: 0, width: 1, height: 1, restitution: 1, friction: 0, model: 'particles', vx: 5 });
        const o = { x: 3, y: offset, restitution: 1, friction: 0, mass: 1 };
        const hit =
          other === 'rigid disc' || other === 'particle ball'
            ? createCircle(world, { ...o, radius: 0.5, model: other === 'rigid disc' ? 'rigid' : 'particles' })
            : createBox(world, { ...o, width: 1, height: 1, model: other === 'rigid box' ? 'rigid' : 'particles' });
        for (let n = 0; n < 60; n++) world.step();
        let px = 0;
        let py = 0;
        let energy = 0;
        const p = world.particles;
        for (const i of [...world.bodyParticleIndices(frame.body), ...world.bodyParticleIndices(hit.body)]) {
          const m = 1 / p.invMass[i];
          px += m * p.vx[i];
          py += m * p.vy[i];
          energy += 0.5 * m * (p.vx[i] ** 2 + p.vy[i] ** 2) + (p.invInertia[i] > 0 ? (0.5 * p.omega[i] ** 2) / p.invInertia[i] : 0);
        }
        const at = `${other}, ${offset} off centre`;
        expect(px, at).to.be.closeTo(5, 1e-9);
        expect(py, at).to.be.closeTo(0, 1e-9);
        expect(energy, at).to.be.closeTo(12.5, offset === 0 ? 1e-3 : 0.1);
        if (offset === 0) {
          const v = world.particles.vx;
          for (const i of world.bodyParticleIndices(frame.body)) expect(v[i], `${at}: the frame stops`).to.be.closeTo(0, 0.01);
          for (const i of world.bodyParticleIndices(hit.body)) expect(v[i], `${at}: the other leaves`).to.be.closeTo(5, 0.01);
        }
      }
  });

  it('a particle frame with e = 0 stops as one body without gravity: against a frame (equal and unequal masses), a rigid disc, a static rigid or particle wall and the bounds, momentum kept (both kernels)', () => {
    // Only the corners that touched were stopped, and the sticks, in their one iteration, sprang the frame's squeeze
    // back out against the other side: two frames parted at a quarter of their approach (1.875 and 3.125 where 2.5
    // and 2.5) at 1, 5 and 20 units/s, an eighth at 60, and a frame left a wall at a quarter of its speed.
    const mean = (world: World, body: number) => {
      const p = world.particles;
      let m = 0;
      let px = 0;
      for (const i of world.bodyParticleIndices(body)) {
        m += 1 / p.invMass[i];
        px += p.vx[i] / p.invMass[i];
      }
      return px / m;
    };
    for (const kernel of ['js', 'wasm'] as const)
      for (const v of [1, 5, 20, 60]) {
        const steps = 60 + Math.ceil(240 / v);
        const at = `${kernel}, ${v} units/s`;
        for (const heavy of [1, 3]) {
          const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
          const a = createBox(world, { x: -3, y: 0, width: 1, height: 1, model: 'particles', mass: 1, friction: 0, vx: v });
          const b = createBox(world, { x: 0, y: 0, width: 1, height: 1, model: 'particles', mass: heavy, friction: 0 });
          for (let n = 0; n < steps; n++) world.step();
          const va = mean(world, a.body);
          const vb = mean(world, b.body);
          expect(va + heavy * vb, `${at}, frame of ${heavy}: momentum`).to.be.closeTo(v, 1e-9 * v);
          expect(va, `${at}, frame of ${heavy}: the frame`).to.be.closeTo(v / (1 + heavy), 0.01 * v);
          expect(vb, `${at}, frame of ${heavy}: the other`).to.be.closeTo(v / (1 + heavy), 0.01 * v);
        }
        {
          // A rigid disc of mass 3 into a frame of mass 1: both go on at 3/4 of its speed.
          const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
          const disc = createCircle(world, { x: -3, y: 0, radius: 0.5, mass: 3, friction: 0, vx: v });
          const frame = createBox(world, { x: 0, y: 0, width: 1, height: 1, model: 'particles', mass: 1, friction: 0 });
          for (let n = 0; n < steps; n++) world.step();
          const vd = world.getVelocity(disc.particles[0]).x;
          const vf = mean(world, frame.body);
          expect(3 * vd + vf, `${at}, disc: momentum`).to.be.closeTo(3 * v, 1e-9 * v);
          expect(vd, `${at}: the disc`).to.be.closeTo(0.75 * v, 0.01 * v);
          expect(vf, `${at}: the frame the disc hit`).to.be.closeTo(0.75 * v, 0.01 * v);
        }
        for (const wall of ['rigid', 'particles', 'bounds'] as const) {
          const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: wall === 'bounds' ? { minX: -10, maxX: 0.5, minY: -10, maxY: 10 } : null });
          if (wall !== 'bounds') createBox(world, { x: 1, y: 0, width: 1, height: 4, static: true, model: wall, friction: 0 });
          const frame = createBox(world, { x: -3, y: 0, width: 1, height: 1, model: 'particles', mass: 1, friction: 0, vx: v });
          for (let n = 0; n < steps; n++) world.step();
          expect(mean(world, frame.body), `${at}, ${wall} wall`).to.be.closeTo(0, 0.01 * v);
        }
      }
  });

  it('a particle frame with e = 0 landing flat stays down: dropped to hit at 5 units/s on the bounds, a rigid and a particle floor, it rises less than 1 mm (both kernels)', () => {
    // Its sticks sprang the squeeze of the landing back out: it hopped 7.6 cm on the bounds and 2.6 cm on a floor.
    const g = 9.81;
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of ['bounds', 'rigid', 'particles'] as const) {
        const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: g }, bounds: floor === 'bounds' ? { minX: -10, maxX: 10, minY: -20, maxY: 0 } : null });
        if (floor !== 'bounds') createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, model: floor, restitution: 0 });
        const box = createBox(world, { x: 0, y: -0.5 - 25 / (2 * g), width: 1, height: 1, model: 'particles', restitution: 0 });
        const p = world.particles;
        let landed = false;
        let hop = 0;
        for (let n = 0; n < 120; n++) {
          world.step();
          let low = -Infinity;
          for (const i of world.bodyParticleIndices(box.body)) low = Math.max(low, p.y[i]);
          if (low > -2e-3) landed = true;
          if (landed) hop = Math.max(hop, -(world.bodyCentroid(box.body).y + 0.5));
        }
        expect(landed, `${kernel}, ${floor}: landed`).to.equal(true);
        expect(hop, `${kernel}, ${floor}: hop`).to.be.below(1e-3);
      }
  });

  it("a particle frame with e = 0 thrown at 45° onto the bounds, a rigid or a particle floor stops along the normal and leaves with Coulomb's sideways speed, (1 − μ)·v (both kernels)", () => {
    // The corners that touched took friction on their own impulses and the rest of the frame came on: it rebounded
    // at 0.17–0.42 of its speed and kept 0.29–0.35 of its slide for μ = 0.5. On a rigid floor the frame-bounce pass
    // added its friction to the impulses the rigid velocity pass had given the edge's two points, without friction
    // of their own: it kept 0.53–0.74 of its slide for μ = 0.5, 0.81–0.90 for μ = 0.2.
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of ['bounds', 'rigid', 'particles'] as const)
        for (const mu of [0.5, 0.2])
          for (const late of [0, 0.02, 0.05]) {
            const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, boundsFriction: mu, bounds: floor === 'bounds' ? { minX: -50, maxX: 50, minY: -50, maxY: 0 } : null });
            if (floor !== 'bounds') createBox(world, { x: 0, y: 0.5, width: 100, height: 1, static: true, model: floor, friction: mu, restitution: 0 });
            const v = 10 / Math.SQRT2;
            const box = createBox(world, { x: 0, y: -2 - late, width: 1, height: 1, vx: v, vy: v, restitution: 0, friction: mu, model: 'particles' });
            for (let n = 0; n < 30; n++) world.step();
            const at = `${kernel}, ${floor}, μ ${mu}, ${late} later`;
            for (const i of world.bodyParticleIndices(box.body)) {
              expect(world.particles.vx[i], at).to.be.closeTo((1 - mu) * v, 0.01 * v);
              expect(world.particles.vy[i], at).to.be.closeTo(0, 0.01 * v);
            }
          }
  });

  it("the bounds' side walls and corners bounce a particle ball without gravity at its speed (e = 1) or e times it", () => {
    for (const e of [1, 0.5]) {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 0 }, bounds: { minX: -5, maxX: 5, minY: -5, maxY: 5 } });
      // Aimed at the corner (4.5, 4.5): it meets both walls at once.
      const ball = createCircle(world, { x: 0, y: 0, radius: 0.5, vx: 9, vy: 9, restitution: e, model: 'particles' });
      const i = ball.particles[0];
      for (let n = 0; n < 45; n++) world.step();
      const p = world.particles;
      expect(p.vx[i], `e ${e}`).to.be.closeTo(-9 * e, 1e-9);
      expect(p.vy[i], `e ${e}`).to.be.closeTo(-9 * e, 1e-9);
    }
  });

  it('restitution: a ball with e = 0.8 dropped from 5 bounces back to about e²·5', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, restitution: 0.8 });
    const ball = createCircle(world, { x: 0, y: -5.5, radius: 0.5, restitution: 0.8 });
    let bounced = false;
    let apex = Infinity;
    let prevY = world.bodyCentroid(ball.body).y;
    for (let k = 0; k < 240; k++) {
      world.step();
      const y = world.bodyCentroid(ball.body).y;
      if (!bounced && y < prevY) bounced = true;
      if (bounced) apex = Math.min(apex, y);
      prevY = y;
    }
    const height = -apex - 0.5;
    console.log(`restitution 0.8 from 5: bounced to ${height.toFixed(3)} (e²·5 = 3.2)`);
    expect(height).to.be.closeTo(3.2, 0.35);
  });
});
