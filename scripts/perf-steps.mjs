// Step timings of our engine on the benchmark scenes, for before/after comparisons on a shared, loaded machine.
//
//   node scripts/perf-steps.mjs                         S1 S2 S3 five: median ms/step, this checkout
//   node scripts/perf-steps.mjs --ab REV                the same, interleaved with git revision REV (e.g. HEAD):
//                                                       fresh processes alternating A (REV) and B (the work tree),
//                                                       --rounds N times; prints each side's median of medians
//   node scripts/perf-steps.mjs --scenes S1 --steps 50 --warm 0 --quiet    for callgrind (instruction counts: run
//                                                       N + W steps and W steps, subtract)
//
//   node scripts/perf-steps.mjs --ab HEAD --scenes circles10k --kernel wasm --steps 30 --warm 120
//                                                       bench/kernel.mjs's large scenes, on one kernel
//
// Scenes: S1 pyramid, S2 1000 boxes, S3 2000 circles, S4 chain, S5 cloth (the catalogue's, sleeping off, as in
// bench/peers), `five`: a 5-body world (ground, three boxes, a disc) that measures the fixed cost of a step, and
// bench/scenes.mjs's circles10k and cloth200. `--kernel js|wasm` picks the solver kernel (default: the World's).
// Timed steps: `--steps` after `--warm` (default 300 after 100, as bench/peers times steps 100..600).
import { build } from 'esbuild';
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, rmSync } from 'node:fs';
import { loadavg, tmpdir } from 'node:os';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { benchWorld } from '../bench/scenes.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const CATALOGUE = { S1: 'pyramid', S2: 'boxes', S3: 'circles', S4: 'chain', S5: 'cloth' };
const LARGE = ['circles10k', 'cloth200'];

function parseArgs(argv) {
  const o = { scenes: ['S1', 'S2', 'S3', 'five'], steps: 300, warm: 100, ab: null, rounds: 5, bundle: null, quiet: false, kernel: undefined };
  for (let k = 0; k < argv.length; k++) {
    const [flag, value] = [argv[k], argv[k + 1]];
    if (flag === '--scenes') (o.scenes = value.split(',')), k++;
    else if (flag === '--steps') (o.steps = Number(value)), k++;
    else if (flag === '--warm') (o.warm = Number(value)), k++;
    else if (flag === '--ab') (o.ab = value), k++;
    else if (flag === '--rounds') (o.rounds = Number(value)), k++;
    else if (flag === '--bundle') (o.bundle = value), k++;
    else if (flag === '--kernel') (o.kernel = value), k++;
    else if (flag === '--quiet') o.quiet = true;
    else throw new Error(`unknown flag ${flag}`);
  }
  for (const s of o.scenes) if (s !== 'five' && !CATALOGUE[s] && !LARGE.includes(s)) throw new Error(`unknown scene ${s}: S1..S5, five, ${LARGE}`);
  return o;
}

/** Bundles src/engine/index.ts under `dir` (a checkout) to a file of its own. */
async function bundle(dir, name) {
  const outdir = root + 'node_modules/.cache/physics-elements';
  mkdirSync(outdir, { recursive: true });
  const outfile = `${outdir}/perf-${name}-${process.pid}.mjs`;
  await build({ entryPoints: [dir + '/src/engine/index.ts'], bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error' });
  return outfile;
}

function makeWorld(engine, scene, kernel) {
  if (LARGE.includes(scene)) return benchWorld(engine, scene, kernel);
  if (scene === 'five') {
    const world = new engine.World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel });
    const { buildBody } = engine;
    buildBody(world, { type: 'box', x: 0, y: 0.5, width: 20, height: 1, static: true });
    buildBody(world, { type: 'box', x: -2, y: -0.5, width: 1, height: 1 });
    buildBody(world, { type: 'box', x: -2, y: -1.5, width: 1, height: 1 });
    buildBody(world, { type: 'box', x: 2, y: -3, width: 1.5, height: 0.5, angle: 0.3 });
    buildBody(world, { type: 'circle', x: 0, y: -2, radius: 0.5 });
    return world;
  }
  const description = engine.catalogue[CATALOGUE[scene]].make();
  description.world = { ...description.world, sleeping: false, kernel };
  return engine.buildScene(description).world;
}

/** In this process: median ms/step of each scene. */
async function measure(file, o) {
  const engine = await import(pathToFileURL(file).href);
  const out = {};
  for (const scene of o.scenes) {
    const world = makeWorld(engine, scene, o.kernel);
    for (let k = 0; k < o.warm; k++) world.step();
    const times = new Float64Array(o.steps);
    for (let k = 0; k < o.steps; k++) {
      const t = performance.now();
      world.step();
      times[k] = performance.now() - t;
    }
    times.sort();
    out[scene] = { median: times[o.steps >> 1], hash: world.stateHash() };
  }
  return out;
}

const median = (a) => [...a].sort((x, y) => x - y)[a.length >> 1];
const o = parseArgs(process.argv.slice(2));

if (o.bundle) {
  // A child: measure one bundle, print one JSON line.
  const r = await measure(o.bundle, o);
  process.stdout.write(JSON.stringify(r) + '\n');
} else if (!o.ab) {
  const file = await bundle(root, 'work');
  const r = await measure(file, o);
  rmSync(file);
  if (!o.quiet) for (const [s, v] of Object.entries(r)) console.log(`${s.padEnd(5)} ${v.median.toFixed(4)} ms/step  hash ${v.hash}`);
} else {
  const dir = mkdtempSync(tmpdir() + '/perf-ab-');
  execFileSync('sh', ['-c', `git -C "${root}" archive ${o.ab} src/engine | tar -x -C "${dir}"`]);
  const files = { A: await bundle(dir, 'A'), B: await bundle(root, 'B') };
  const runs = { A: [], B: [] };
  const args = (f) => [fileURLToPath(import.meta.url), '--bundle', f, '--scenes', o.scenes.join(','), '--steps', String(o.steps), '--warm', String(o.warm), ...(o.kernel ? ['--kernel', o.kernel] : [])];
  const loads = [];
  for (let r = 0; r < o.rounds; r++) {
    for (const side of r % 2 === 0 ? ['A', 'B'] : ['B', 'A']) {
      const child = spawnSync(process.execPath, args(files[side]), { encoding: 'utf8' });
      if (child.status !== 0) throw new Error(child.stderr);
      runs[side].push(JSON.parse(child.stdout.trim().split('\n').pop()));
    }
    loads.push(loadavg()[0]);
  }
  console.log(`A = ${o.ab}, B = work tree; ${o.rounds} rounds, load ${Math.min(...loads).toFixed(1)}–${Math.max(...loads).toFixed(1)}`);
  for (const s of o.scenes) {
    const a = median(runs.A.map((x) => x[s].median));
    const b = median(runs.B.map((x) => x[s].median));
    const same = runs.A[0][s].hash === runs.B[0][s].hash ? 'same hash' : 'hash differs';
    console.log(`${s.padEnd(5)} A ${a.toFixed(4)}  B ${b.toFixed(4)}  B/A ${(b / a).toFixed(3)}  (${same})`);
  }
  rmSync(dir, { recursive: true });
  rmSync(files.A);
  rmSync(files.B);
}
