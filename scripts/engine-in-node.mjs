// The headless engine must import and run in plain Node 20 (no DOM, no p5, no lit): build it, run a cloth, and
// check the state stays finite and the run is reproducible.
import { importTs } from './build-engine-for-node.mjs';

const { World, createCloth, buildScene, catalogue } = await importTs();
function run() {
  // A cloth and a colliding scene (ragdolls on steps): constraints, contacts and sleeping all run in plain Node.
  const { world } = buildScene(catalogue.ragdolls.make());
  createCloth(world, { origin: { x: 20, y: -20 }, columns: 20, rows: 20, spacing: 0.1, pins: 'corners' });
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
console.log(`engine-in-node: ok (ragdolls on steps + 20x20 cloth, 300 steps, ${a.contacts.count} contacts, hash ${a.stateHash()}, strain ${(a.maxStrain() * 100).toFixed(3)}%)`);
