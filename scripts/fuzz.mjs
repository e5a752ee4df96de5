// Long-form engine fuzzing: node scripts/fuzz.mjs [--scenes 100000] [--from 1000] [--steps 1000]
// Each scene runs its steps, checking every 100 steps that the state is finite and bounded; every 10th scene is also
// replayed and compared by hash. Prints failing seeds (add them to REGRESSIONS in test/engine/fuzz/fuzz.test.ts).
import { importTs } from './build-engine-for-node.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const scenes = arg('scenes', 1000);
const from = arg('from', 1000);
const steps = arg('steps', 1000);
const { fuzzScene, violation } = await importTs('test/engine/fuzz/generator.ts');
const failures = [];
const t0 = performance.now();
for (let seed = from; seed < from + scenes; seed++) {
  try {
    const a = fuzzScene(seed);
    let problem = null;
    for (let done = 0; done < steps && !problem; done += 100) {
      a.run(Math.min(100, steps - done));
      problem = violation(a.world);
    }
    if (!problem && seed % 10 === 0) {
      const b = fuzzScene(seed);
      b.run(steps);
      if (b.world.stateHash() !== a.world.stateHash()) problem = 'replay gave a different hash';
    }
    if (problem) failures.push({ seed, problem });
  } catch (error) {
    failures.push({ seed, problem: `threw ${error}` });
  }
  // Say a failure as soon as it is found: a long run may be stopped before the end.
  if (failures.length && failures[failures.length - 1].seed === seed) console.log(`seed ${seed}: ${failures[failures.length - 1].problem}`);
  if ((seed - from + 1) % 100 === 0) console.log(`${seed - from + 1} scenes, ${failures.length} failing, ${((performance.now() - t0) / 1000).toFixed(0)} s`);
}
if (failures.length) console.log(`failing seeds: ${failures.map((f) => f.seed).join(' ')}`);
console.log(`fuzz: ${scenes} scenes × ${steps} steps, ${failures.length} failing`);
process.exit(failures.length ? 1 : 0);
