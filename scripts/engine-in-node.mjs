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

// step() must not allocate (the worker would pause for garbage collection): sample the heap allocations of 200
// steps of each catalogue scene after a warm-up, counting objects already collected too. A double returned from or
// passed to a call V8 does not inline is boxed, which in the narrow phase came to 100-200 KB per step.
const { Session } = await import('node:inspector/promises');
const session = new Session();
session.connect();
const ALLOWED_KB_PER_STEP = 24;
const rates = [];
for (const name of Object.keys(catalogue)) {
  const { world } = buildScene(catalogue[name].make());
  for (let k = 0; k < 300; k++) world.step();
  // The lesser of two windows of 200 steps: V8 recompiles code that a scene's first sleeps or wakes deoptimise, and
  // until then it boxes doubles (the soft scene's rings fall asleep about then: 1.5-18.5 KB a step in one window).
  // A step that allocates does so in both.
  let kb = Infinity;
  for (let w = 0; w < 2; w++) {
    await session.post('HeapProfiler.startSampling', { samplingInterval: 1024, includeObjectsCollectedByMinorGC: true, includeObjectsCollectedByMajorGC: true });
    for (let k = 0; k < 200; k++) world.step();
    const { profile } = await session.post('HeapProfiler.stopSampling');
    let bytes = 0;
    const walk = (node) => {
      bytes += node.selfSize;
      node.children.forEach(walk);
    };
    walk(profile.head);
    kb = Math.min(kb, bytes / 1024 / 200);
  }
  rates.push([name, kb]);
}
session.disconnect();
const heavy = rates.filter(([, kb]) => kb > ALLOWED_KB_PER_STEP);
const summary = rates.map(([name, kb]) => `${name} ${kb.toFixed(1)}`).join(', ');
if (heavy.length) {
  console.error(`engine-in-node: step() allocates more than ${ALLOWED_KB_PER_STEP} KB per step: ${summary}`);
  process.exit(1);
}
console.log(`engine-in-node: allocation per step (KB, sampled): ${summary}`);
