// The headless engine must import and run in plain Node 20 (no DOM, no p5, no lit): build it, run a cloth, and
// check the state stays finite and the run is reproducible.
import { importTs } from './build-engine-for-node.mjs';

const { World, createCloth } = await importTs();
function run() {
  const world = new World({ gravity: { x: 0, y: 10 } });
  createCloth(world, { origin: { x: 0, y: 0 }, columns: 20, rows: 20, spacing: 0.1, pins: 'corners' });
  for (let k = 0; k < 300; k++) world.step();
  return world;
}
const a = run();
const b = run();
const finite = Array.from(a.particles.x.subarray(0, a.particles.count)).every(Number.isFinite);
if (!finite || a.stateHash() !== b.stateHash() || typeof globalThis.document !== 'undefined') {
  console.error('engine-in-node: FAILED', { finite, hashA: a.stateHash(), hashB: b.stateHash() });
  process.exit(1);
}
console.log(`engine-in-node: ok (20x20 cloth, 300 steps, hash ${a.stateHash()}, strain ${(a.maxStrain() * 100).toFixed(3)}%)`);
