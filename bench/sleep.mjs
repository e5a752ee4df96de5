// Sleeping benchmark (issue 4): how long a scene takes to fall asleep, and what a step of the settled scene costs
// against an awake step of the same scene (sleeping turned off after settling). Usage: node bench/sleep.mjs
import { importTs } from '../scripts/build-engine-for-node.mjs';

const { buildScene, catalogue } = await importTs();
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const timeSteps = (world, n) => {
  const t = performance.now();
  for (let k = 0; k < n; k++) world.step();
  return (performance.now() - t) / n;
};

console.log('| scene | asleep after | settled ms/step | awake ms/step | ratio |');
console.log('|---|---|---|---|---|');
for (const name of ['stack', 'pyramid', 'soft', 'ragdolls']) {
  const rows = [];
  for (let run = 0; run < 3; run++) {
    const { world } = buildScene(catalogue[name].make());
    let asleepAt = -1;
    for (let k = 0; k < 1800 && asleepAt < 0; k++) {
      world.step();
      if (world.settled) asleepAt = k + 1;
    }
    const settled = timeSteps(world, 1000);
    world.sleeping = false;
    timeSteps(world, 30);
    const awake = timeSteps(world, 200);
    rows.push({ asleepAt, settled, awake });
  }
  const at = rows[0].asleepAt;
  const settled = median(rows.map((r) => r.settled));
  const awake = median(rows.map((r) => r.awake));
  console.log(`| ${name} | ${at < 0 ? 'not within 30 s' : (at / 60).toFixed(2) + ' s'} | ${settled.toFixed(5)} | ${awake.toFixed(3)} | ${((settled / awake) * 100).toFixed(3)}% |`);
}
