// Soft bodies' material damping (the pressure model: AreaConstraints.damping, pipeline/spin.ts dampLoops): a pressure
// ring's deformation dies out, so it comes to rest where it lands, while it moves and turns as a whole as before.
import { expect } from 'chai';
import { World, buildBody, buildScene, catalogue, createSoftBody, type Handle, type SceneDescription } from '../../../src/engine/index.js';

const KERNELS = ['js', 'wasm'] as const;

/** Momentum, angular momentum about the centre of mass, and the kinetic energy of the motion apart from the rigid one. */
function motionOf(world: World, particles: readonly Handle[]): { px: number; py: number; L: number; deformation: number } {
  const rows = particles.map((p) => ({ m: world.getMass(p), q: world.getPosition(p), v: world.getVelocity(p) }));
  const m = rows.reduce((s, r) => s + r.m, 0);
  const c = rows.reduce((s, r) => ({ x: s.x + (r.m * r.q.x) / m, y: s.y + (r.m * r.q.y) / m }), { x: 0, y: 0 });
  const px = rows.reduce((s, r) => s + r.m * r.v.x, 0);
  const py = rows.reduce((s, r) => s + r.m * r.v.y, 0);
  let L = 0;
  let I = 0;
  for (const r of rows) {
    L += r.m * ((r.q.x - c.x) * (r.v.y - py / m) - (r.q.y - c.y) * (r.v.x - px / m));
    I += r.m * ((r.q.x - c.x) ** 2 + (r.q.y - c.y) ** 2);
  }
  const w = L / I;
  let deformation = 0;
  for (const r of rows) {
    const ux = r.v.x - px / m + w * (r.q.y - c.y);
    const uy = r.v.y - py / m - w * (r.q.x - c.x);
    deformation += 0.5 * r.m * (ux * ux + uy * uy);
  }
  return { px, py, L, deformation };
}

/** A world with gravity 10 (y down) and a static rigid floor whose top is at y = 0. */
function floorWorld(kernel: 'js' | 'wasm', sleeping = true): World {
  const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping });
  buildBody(world, { type: 'box', x: 0, y: 0.5, width: 400, height: 1, static: true });
  return world;
}

describe('soft bodies: the pressure model damps its deformation', () => {
  it("the catalogue's soft scene comes to rest: its three rings asleep within 20 s in their container, in both kernels", () => {
    // Undamped, the 20-link ring that rolls down the tilted box bounced between the slope and the ring at its foot as
    // an elastic body and rocked there for minutes (its centre at x −0.835, −0.694, −0.684, −0.436, −0.605, −0.565
    // every 10 s, up to 0.55 units/s after 20 s): never asleep. Now both pressure rings sleep at 17.4 s (9.1 s since the rolling
    // resistance, spin.ts ROLLING_RESISTANCE). The springs ring, hit by the falling 16-link ring at 1.07 s, rolled on over the open ground for 44 s and out of the gallery's
    // view; the scene's container now sends it back, and it sleeps at 20 s.
    for (const kernel of KERNELS) {
      const d: SceneDescription = catalogue.soft.make();
      d.world = { ...d.world, kernel };
      const { world, bodies } = buildScene(d);
      for (let k = 0; k < 1200; k++) world.step();
      const rings = d.bodies.flatMap((b, k) => (b.type === 'softbody' ? [k] : []));
      expect(rings).to.have.length(3);
      for (const [n, k] of rings.entries()) {
        const ring = bodies[k].body;
        const before = world.bodyCentroid(ring);
        for (let s = 0; s < 60; s++) world.step();
        const after = world.bodyCentroid(ring);
        expect(world.isAwake(ring), `${kernel}: ring ${n + 1} asleep at 20 s`).to.equal(false);
        expect(Math.hypot(after.x - before.x, after.y - before.y), `${kernel}: ring ${n + 1}'s centre over 1 s`).to.be.lessThan(0.01);
        expect(Math.abs(after.x), `${kernel}: ring ${n + 1} inside the container`).to.be.lessThan(8);
      }
    }
  });

  it('a pressure ring dropped on a floor comes to rest and sleeps, in both kernels', () => {
    // Undamped: asleep at 22.9 s, 26.3 s and 12.3 s, the 20-link ring not within 60 s; damped 5.5 s, 6.0 s, 5.5 s, 21.2 s;
    // with rolling resistance 5.2 s, 6.0 s, 5.5 s, 5.8 s.
    const drops: [segments: number, radius: number, height: number, within: number][] = [[16, 1, 3, 8], [16, 1, 5, 8], [12, 0.8, 4, 8], [20, 1.2, 3, 25]];
    for (const kernel of KERNELS) {
      for (const [segments, radius, height, within] of drops) {
        const world = floorWorld(kernel);
        const ring = createSoftBody(world, { center: { x: 0, y: -height }, radius, segments });
        for (let k = 0; k < within * 60 && world.isAwake(ring.body); k++) world.step();
        expect(world.isAwake(ring.body), `${kernel}, ${segments} links dropped from ${height}: asleep within ${within} s`).to.equal(false);
      }
    }
  });

  it('an inflated pressure ring dropped on a floor with friction stops rocking and sleeps, in both kernels', () => {
    // Inflated (pressure above 1) a ring is round and stiff and rests on the two particles of one side, over which it
    // rocked nearly as a rigid body, untouched by its damping: none of these slept within 60 s (16 links at 1.2 from 3
    // rocked at up to 0.31 units/s between 35 and 40 s, 0.18 between 55 and 60 s). With rolling resistance (spin.ts
    // ROLLING_RESISTANCE) they sleep after 9.4 s, 11.0 s, 9.6 s, 17.3 s, 11.7 s, 10.5 s and 14.9 s, both kernels.
    const drops: [segments: number, radius: number, height: number, pressure: number][] = [
      [16, 1, 3, 1.2], [16, 1, 5, 1.1], [12, 0.8, 4, 1.05], [12, 0.8, 2, 1.2], [20, 1.2, 6, 1.1], [20, 1.2, 3, 1.2], [16, 1, 6, 1.05],
    ];
    // Also onto the world's bounds (a page's floor): the first and fourth, asleep after 9.4 s and 17.5 s (not in 60 s).
    const runs = [...drops.map((d) => ({ d, bounds: false })), { d: drops[0], bounds: true }, { d: drops[3], bounds: true }];
    for (const kernel of KERNELS) {
      for (const { d: [segments, radius, height, pressure], bounds } of runs) {
        const world = bounds
          ? new World({ kernel, gravity: { x: 0, y: 10 }, bounds: { minX: -20, minY: -100, maxX: 20, maxY: 0 } })
          : floorWorld(kernel);
        const ring = createSoftBody(world, { center: { x: 0, y: -height }, radius, segments, pressure });
        const told = `${kernel}, ${segments} links at pressure ${pressure} dropped from ${height}${bounds ? ' onto the bounds' : ''}`;
        // The largest particle speed from 15 s to 20 s, and whether it sleeps by 20 s.
        let fastest = 0;
        for (let k = 1; k <= 1200; k++) {
          world.step();
          if (k <= 900) continue;
          for (const p of ring.particles) {
            const v = world.getVelocity(p);
            fastest = Math.max(fastest, Math.hypot(v.x, v.y));
          }
        }
        expect(fastest, `${told}: fastest particle after 15 s`).to.be.lessThan(0.2);
        expect(world.isAwake(ring.body), `${told}: asleep at 20 s`).to.equal(false);
      }
    }
  });

  it('an inflated pressure ring resting on a floor, set rocking, stops within seconds, in both kernels', () => {
    // 16 links at pressure 1.2 let down from 0.3 above the floor: asleep after 4.8 s (before the rolling resistance it
    // rocked on for a minute, never asleep). Set rocking about its contact at 0.24 units/s (its centre's speed), it is
    // at 0.05 units/s after 2 s and asleep after 2.6 s (before: on at 0.13–0.43 units/s every second).
    for (const kernel of KERNELS) {
      const world = floorWorld(kernel);
      const ring = createSoftBody(world, { center: { x: 0, y: -1.3 }, radius: 1, segments: 16, pressure: 1.2 });
      for (let k = 0; k < 480 && world.isAwake(ring.body); k++) world.step();
      expect(world.isAwake(ring.body), `${kernel}: asleep within 8 s`).to.equal(false);
      const c = world.bodyCentroid(ring.body);
      const w = 0.24 / -c.y;
      for (const p of ring.particles) {
        const q = world.getPosition(p);
        world.setVelocity(p, -w * q.y, w * (q.x - c.x));
      }
      for (let k = 0; k < 240 && world.isAwake(ring.body); k++) world.step();
      expect(world.isAwake(ring.body), `${kernel}: asleep within 4 s of being set rocking`).to.equal(false);
    }
  });

  it('a squeezed, spinning pressure ring in free flight stops wobbling and keeps its momentum and angular momentum', () => {
    // Undamped, 5.6% of the wobble's energy was left after 1 s; now 0.012%. The damping acts on the motion apart from the
    // ring's rigid one: momentum and angular momentum to 1e-12. damping 0 is the undamped ring.
    for (const kernel of KERNELS) {
      for (const damping of [5, 0]) {
        const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false });
        const ring = createSoftBody(world, { center: { x: 0, y: 0 }, radius: 1, segments: 16, damping });
        // Moving at (1, 0.5), turning at 2 rad/s and squeezed along x while stretched along y.
        for (const p of ring.particles) {
          const q = world.getPosition(p);
          world.setVelocity(p, 1 - 2 * q.y + 0.5 * q.x, 0.5 + 2 * q.x - 0.5 * q.y);
        }
        const start = motionOf(world, ring.particles);
        for (let k = 0; k < 60; k++) world.step();
        const end = motionOf(world, ring.particles);
        const told = `${kernel}, damping ${damping}`;
        expect(end.px, told).to.be.closeTo(start.px, 1e-12 * Math.abs(start.px));
        expect(end.py, told).to.be.closeTo(start.py, 1e-12 * Math.abs(start.py));
        expect(end.L, told).to.be.closeTo(start.L, 1e-12 * Math.abs(start.L));
        if (damping > 0) expect(end.deformation / start.deformation, told).to.be.lessThan(0.002);
        else expect(end.deformation / start.deformation, told).to.be.greaterThan(0.05);
      }
    }
  });

  it('a pressure ring rolling on a floor rolls on, slowed as by rolling resistance (its squeeze is damped)', () => {
    // Set rolling at 2 units/s: its mean speed in the fifth second 1.18 (undamped 1.69, about 0.06 units/s² of loss;
    // damped 0.17, a rolling resistance of about 0.017); with the rolling resistance of a ring that touches something
    // (spin.ts ROLLING_RESISTANCE, 0.01) 1.02, about 0.21 units/s².
    for (const kernel of KERNELS) {
      const world = floorWorld(kernel, false);
      const ring = createSoftBody(world, { center: { x: 0, y: -1.2 }, radius: 1, segments: 16 });
      for (let k = 0; k < 180; k++) world.step();
      const c = world.bodyCentroid(ring.body);
      const w = 2 / -c.y;
      for (const p of ring.particles) {
        const q = world.getPosition(p);
        world.setVelocity(p, 2 - w * (q.y - c.y), w * (q.x - c.x));
      }
      for (let k = 0; k < 240; k++) world.step();
      const before = world.bodyCentroid(ring.body).x;
      for (let k = 0; k < 60; k++) world.step();
      const speed = world.bodyCentroid(ring.body).x - before;
      expect(speed, kernel).to.be.within(1.0, 1.4);
    }
  });
});
