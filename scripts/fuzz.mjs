// Long-form engine fuzzing: node scripts/fuzz.mjs [--scenes 100000] [--from 1000] [--steps 1000] [--kernel js|wasm|both]
// Each scene runs its steps, checking every 100 steps that the state is finite and bounded; every 10th scene is also
// replayed and compared by hash. With --kernel both (the default) every scene runs under each solver kernel (the JS
// loops and the WebAssembly SIMD kernel), each checked and replayed on its own (each kernel is deterministic; the two
// are not bit-identical to each other). Prints failing seeds (add them to REGRESSIONS in test/engine/fuzz/fuzz.test.ts).
import { build } from 'esbuild';
import { mkdirSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? process.argv[i + 1] : fallback;
};
const scenes = Number(arg('scenes', 1000));
const from = Number(arg('from', 1000));
const steps = Number(arg('steps', 1000));
const kernels = { js: ['js'], wasm: ['wasm'], both: ['js', 'wasm'] }[arg('kernel', 'both')];
if (!kernels) throw new RangeError(`--kernel must be js, wasm or both, got ${arg('kernel')}`);

const { fuzzScene, violation, setKernel } = await generatorWithKernel();
const failures = [];
const t0 = performance.now();
for (let seed = from; seed < from + scenes; seed++) {
  for (const kernel of kernels) {
    const problem = fuzz(seed, kernel);
    if (!problem) continue;
    failures.push({ seed, kernel, problem });
    // Say a failure as soon as it is found: a long run may be stopped before the end.
    console.log(`seed ${seed} (${kernel}): ${problem}`);
  }
  if ((seed - from + 1) % 100 === 0) console.log(`${seed - from + 1} scenes, ${failures.length} failing, ${((performance.now() - t0) / 1000).toFixed(0)} s`);
}
if (failures.length) console.log(`failing seeds: ${failures.map((f) => `${f.seed} (${f.kernel})`).join(' ')}`);
console.log(`fuzz: ${scenes} scenes × ${steps} steps × kernels ${kernels.join(', ')}, ${failures.length} failing`);
process.exit(failures.length ? 1 : 0);

/** Runs scene `seed` under kernel `wanted`: the first broken invariant, a replay that differs, or null. */
function fuzz(seed, wanted) {
  setKernel(wanted);
  try {
    const a = fuzzScene(seed);
    const { kernel, reason } = a.world.diagnostics();
    if (kernel !== wanted) return `the ${wanted} kernel does not run: ${reason}`;
    for (let done = 0; done < steps; done += 100) {
      a.run(Math.min(100, steps - done));
      const problem = violation(a.world);
      if (problem) return problem;
    }
    if (seed % 10 === 0) {
      const b = fuzzScene(seed);
      b.run(steps);
      if (b.world.stateHash() !== a.world.stateHash()) return 'replay gave a different hash';
    }
    return null;
  } catch (error) {
    return `threw ${error}`;
  }
}

/**
 * The scene generator (test/engine/fuzz/generator.ts) bundled with an engine whose World is made with the kernel last
 * given to setKernel() unless its options name one: the generator's scenes stay as they are, under either kernel.
 */
async function generatorWithKernel() {
  const root = fileURLToPath(new URL('..', import.meta.url));
  const engine = `${root}src/engine/index.ts`;
  const outfile = `${root}node_modules/.cache/physics-elements/fuzz-kernels.mjs`;
  mkdirSync(`${root}node_modules/.cache/physics-elements`, { recursive: true });
  const shim = `export * from ${JSON.stringify(engine)};
import { World as EngineWorld } from ${JSON.stringify(engine)};
let kernel = 'js';
export function setKernel(k) { kernel = k; }
export class World extends EngineWorld { constructor(options = {}) { super({ kernel, ...options }); } }`;
  await build({
    stdin: { contents: `export * from ${JSON.stringify(`${root}test/engine/fuzz/generator.ts`)}; export { setKernel } from 'kernel-shim';`, resolveDir: root, loader: 'ts' },
    bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error',
    plugins: [{
      name: 'kernel-shim',
      setup(b) {
        // The generator's engine import, and ours, go to the shim; the shim's own import goes to the engine.
        b.onResolve({ filter: /^kernel-shim$|src\/engine\/index\.js$/ }, () => ({ path: 'kernel-shim', namespace: 'shim' }));
        b.onLoad({ filter: /.*/, namespace: 'shim' }, () => ({ contents: shim, resolveDir: root, loader: 'js' }));
      },
    }],
  });
  return import(`${pathToFileURL(outfile).href}?t=${Date.now()}`);
}
