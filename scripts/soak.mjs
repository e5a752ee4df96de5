// Soak: a busy scene (ragdolls on steps, soft bodies, boxes, a rope and a cloth; sleeping off; a kick every second)
// run for many steps, sampling the heap (after a forced GC) and the step time. Fails if the heap grows by more than
// 2 MB after warm-up; step times are printed, not judged.
// Usage: node --expose-gc scripts/soak.mjs [--steps 1000000] [--samples 20]
import { importTs } from './build-engine-for-node.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const steps = arg('steps', 1_000_000);
const samples = arg('samples', 20);
if (typeof globalThis.gc !== 'function') {
  console.error('run with node --expose-gc');
  process.exit(2);
}
const { buildScene, catalogue, createCloth, createRope, buildBody } = await importTs();
const description = catalogue.ragdolls.make();
description.world.sleeping = false;
const { world, bodies } = buildScene(description);
for (const d of catalogue.soft.make().bodies.slice(1)) bodies.push(buildBody(world, { ...d, ...(d.center ? { center: { x: d.center.x + 14, y: d.center.y - 10 } } : { x: d.x + 14, y: d.y - 10 }) }));
createCloth(world, { origin: { x: -20, y: -15 }, columns: 12, rows: 12, spacing: 0.25, pins: 'corners', collide: true, radius: 0.05 });
createRope(world, { from: { x: 20, y: -15 }, to: { x: 26, y: -15 }, segments: 20, collide: true, radius: 0.08 });
const dynamic = bodies.filter((b) => world.bodyKindOf(b.body) !== 'rigid' || world.getMass(b.particles[0]) < Infinity);

const heap = () => {
  globalThis.gc();
  return process.memoryUsage().heapUsed;
};
const every = Math.max(1, Math.floor(steps / samples));
const rows = [];
let kick = 0;
let t0 = performance.now();
let baseline = 0;
for (let k = 1; k <= steps; k++) {
  if (k % 60 === 0) {
    const b = dynamic[kick++ % dynamic.length].body;
    const c = world.bodyCentroid(b);
    world.applyBodyImpulse(b, c.x > 0 ? -20 : 20, -30);
  }
  world.step();
  if (k % every === 0) {
    const ms = (performance.now() - t0) / every;
    const used = heap();
    if (rows.length === 1) baseline = used; // after one sample of warm-up
    rows.push({ step: k, ms, used, contacts: world.contacts.count });
    console.log(`step ${k}: ${ms.toFixed(3)} ms/step, heap ${(used / 1e6).toFixed(2)} MB, ${world.contacts.count} contacts`);
    t0 = performance.now();
  }
}
const finite = Array.from(world.particles.x.subarray(0, world.particles.count)).every(Number.isFinite);
const growth = rows.length > 1 ? rows[rows.length - 1].used - baseline : 0;
const times = rows.slice(1).map((r) => r.ms).sort((a, b) => a - b);
console.log(`soak: ${steps} steps, heap after warm-up ${(baseline / 1e6).toFixed(2)} MB → ${(rows[rows.length - 1].used / 1e6).toFixed(2)} MB (${(growth / 1e6).toFixed(2)} MB), step time median ${times[Math.floor(times.length / 2)]?.toFixed(3)} ms (min ${times[0]?.toFixed(3)}, max ${times[times.length - 1]?.toFixed(3)}), state finite: ${finite}`);
process.exit(finite && growth < 2e6 ? 0 : 1);
