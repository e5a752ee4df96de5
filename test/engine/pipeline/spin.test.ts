// Free spin (pipeline/spin.ts): a body built of particles keeps its angular momentum about its centre of mass through
// the steps nothing outside acts on it, and only through those.
import { expect } from 'chai';
import { World, buildBody, createRagdoll, type Handle, type KernelOptions } from '../../../src/engine/index.js';

/** Σ m r × (v − v̄) about the centre of mass of `particles`, and their kinetic energy about it. */
function spinOf(world: World, particles: readonly Handle[]): { L: number; energy: number } {
  const rows = particles.map((p) => ({ m: world.getMass(p), q: world.getPosition(p), v: world.getVelocity(p) }));
  const m = rows.reduce((s, r) => s + r.m, 0);
  const c = rows.reduce((s, r) => ({ x: s.x + (r.m * r.q.x) / m, y: s.y + (r.m * r.q.y) / m }), { x: 0, y: 0 });
  const v = rows.reduce((s, r) => ({ x: s.x + (r.m * r.v.x) / m, y: s.y + (r.m * r.v.y) / m }), { x: 0, y: 0 });
  let L = 0;
  let energy = 0;
  for (const r of rows) {
    const [rx, ry, vx, vy] = [r.q.x - c.x, r.q.y - c.y, r.v.x - v.x, r.v.y - v.y];
    L += r.m * (rx * vy - ry * vx);
    energy += 0.5 * r.m * (vx * vx + vy * vy);
  }
  return { L, energy };
}

/** A particle-frame box turned at `omega` rad/s about its centre (and moving at vx). */
function spunFrame(world: World, omega: number, x = 0, vx = 0): Handle[] {
  const built = buildBody(world, { type: 'box', x, y: 0, width: 2, height: 1, model: 'particles' });
  for (const p of built.particles) {
    const q = world.getPosition(p);
    world.setVelocity(p, vx - omega * q.y, omega * (q.x - x));
  }
  return built.particles;
}

for (const kernel of ['js', 'wasm'] as const) {
  describe(`free spin: bodies of particles keep their angular momentum in free flight (${kernel} kernel)`, () => {
    const options: KernelOptions = { kernel };

    it('a particle-frame box spun at 2, 5 and 10 rad/s keeps its spin and energy over 10 s, with or without gravity', () => {
      // Before: v = (x − x_prev)/h along the chord of each substep's turn kept 94%, 74% and 48% of the angular momentum
      // (88%, 55%, 23% of the energy) over these 10 s.
      for (const omega of [2, 5, 10]) {
        for (const gravity of [0, 10]) {
          const world = new World({ ...options, gravity: { x: 0, y: gravity }, sleeping: false });
          const particles = spunFrame(world, omega);
          const before = spinOf(world, particles);
          for (let k = 0; k < 600; k++) world.step();
          const after = spinOf(world, particles);
          const told = `${omega} rad/s, g ${gravity}`;
          expect(after.L / before.L, told).to.be.closeTo(1, 1e-9);
          expect(after.energy / before.energy, told).to.be.closeTo(1, 0.002);
        }
      }
    });

    it('a ragdoll thrown tumbling keeps its angular momentum about its centre of mass while it flies', () => {
      const world = new World({ ...options, gravity: { x: 0, y: 10 }, sleeping: false });
      const doll = createRagdoll(world, { x: 0, y: 0 });
      for (const p of doll.particles) {
        const q = world.getPosition(p);
        world.setVelocity(p, 3 - 4 * q.y, -8 + 4 * q.x);
      }
      const before = spinOf(world, doll.particles).L;
      let worst = 0;
      for (let k = 0; k < 120; k++) {
        world.step();
        worst = Math.max(worst, Math.abs(spinOf(world, doll.particles).L / before - 1));
      }
      expect(worst).to.be.lessThan(1e-9);
    });

    it('a pressure soft body spun at 3 rad/s keeps its angular momentum: its ring\'s damping slows its wobble, not its turn', () => {
      // dampLoops damps each particle's velocity about the ring's rigid motion (v̄ + ω × r); damping it about v̄ alone
      // braked the turn too, and nothing here spun a soft body.
      const world = new World({ ...options, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
      const ring = buildBody(world, { type: 'softbody', center: { x: 0, y: 0 }, radius: 1, segments: 16 }).particles;
      for (const p of ring) {
        const q = world.getPosition(p);
        world.setVelocity(p, -3 * q.y, 3 * q.x);
      }
      const before = spinOf(world, ring).L;
      expect(before).to.be.above(1);
      for (let k = 0; k < 120; k++) world.step();
      expect(spinOf(world, ring).L / before).to.be.closeTo(1, 1e-9);
    });

    it('the world damping takes its share of the spin, and nothing more', () => {
      const world = new World({ ...options, gravity: { x: 0, y: 0 }, sleeping: false, damping: 0.5, substeps: 10 });
      const particles = spunFrame(world, 5);
      const before = spinOf(world, particles).L;
      for (let k = 0; k < 60; k++) world.step();
      // Each substep keeps 1/(1 + h·damping) of every velocity.
      const h = 1 / 60 / 10;
      expect(spinOf(world, particles).L / before).to.be.closeTo((1 / (1 + h * 0.5)) ** 600, 1e-9);
    });

    it('a floor, a body it meets or a pin turn it as they must: its spin is not kept then', () => {
      // Against the bounds' floor with friction the frame stops turning on its own.
      const floor = new World({ ...options, gravity: { x: 0, y: 10 }, sleeping: false, bounds: { minX: -50, minY: -50, maxX: 50, maxY: 1.2 } });
      const onFloor = spunFrame(floor, 5);
      const Lf0 = spinOf(floor, onFloor).L;
      for (let k = 0; k < 300; k++) floor.step();
      expect(Math.abs(spinOf(floor, onFloor).L / Lf0)).to.be.lessThan(0.05);
      // Two frames meeting head-on, turning opposite ways: the hit changes each one's spin (kept through the steps of
      // the hit, it would stay as it was).
      const pair = new World({ ...options, gravity: { x: 0, y: 0 }, sleeping: false });
      const a = spunFrame(pair, 3, -3, 4);
      spunFrame(pair, -3, 3, -4);
      const La0 = spinOf(pair, a).L;
      let hit = false;
      for (let k = 0; k < 120; k++) {
        pair.step();
        if (Math.abs(spinOf(pair, a).L / La0 - 1) > 0.01) hit = true;
      }
      expect(hit, 'the hit changed the first frame’s own spin').to.equal(true);
      // A pin holds one corner: the frame swings about it, no longer about its centre.
      const pinned = new World({ ...options, gravity: { x: 0, y: 10 }, sleeping: false });
      const corners = spunFrame(pinned, 0);
      pinned.addPin(corners[0]);
      const Lp0 = spinOf(pinned, corners).L;
      for (let k = 0; k < 30; k++) pinned.step();
      expect(Math.abs(spinOf(pinned, corners).L - Lp0)).to.be.greaterThan(0.1);
    });
  });
}
