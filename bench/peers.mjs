// Cross-engine benchmark (issue 4): S1–S5 in our engine and in matter-js, planck, p2-es, @box2d/core,
// box2d-wasm and Rapier (plain 0.21 and SIMD 0.19), each run in a fresh Node process.
//
//   npm run bench:peers                      full run (3 runs × 5 scenes × every engine × 600 steps), writes bench/results/peers.md
//   node bench/peers.mjs --scenes S1,S2 --engines ours,box2d-wasm --runs 1 --steps 300   a quick look (prints only)
//   ... --out FILE                           write the report to FILE (a partial run writes nothing unless asked)
//
// Runs go round-robin (run 1 of every scene and engine, then run 2, ...) so a burst of load on the shared machine
// lands on every engine instead of on one.
import { spawnSync } from 'node:child_process';
import { execFileSync } from 'node:child_process';
import { mkdirSync, rmSync, writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { fileURLToPath } from 'node:url';
import { ENGINES, PEERS, runs } from './peers/engines/index.mjs';
import { bundleOurs } from './peers/engines/ours.mjs';
import { SCENES, SCENE_IDS } from './peers/scenes.mjs';
import { report } from './peers/report.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const DEFAULTS = { scenes: SCENE_IDS, engines: Object.keys(ENGINES), runs: 3, steps: 600 };

function parseArgs(argv) {
  const o = { ...DEFAULTS, out: null };
  for (let k = 0; k < argv.length; k++) {
    const [flag, value] = [argv[k], argv[k + 1]];
    const list = () => value.split(',').map((s) => s.trim()).filter(Boolean);
    if (flag === '--scenes') (o.scenes = list()), k++;
    else if (flag === '--engines') (o.engines = list()), k++;
    else if (flag === '--runs') (o.runs = Number(value)), k++;
    else if (flag === '--steps') (o.steps = Number(value)), k++;
    else if (flag === '--out') (o.out = value), k++;
    else throw new Error(`unknown flag ${flag} (flags: --scenes S1,S2 --engines ours,box2d-wasm --runs 3 --steps 600 --out FILE)`);
  }
  for (const s of o.scenes) if (!SCENES[s]) throw new Error(`unknown scene ${s}; scenes: ${SCENE_IDS.join(', ')}`);
  for (const e of o.engines) if (!ENGINES[e]) throw new Error(`unknown engine ${e}; engines: ${Object.keys(ENGINES).join(', ')}`);
  if (!(o.runs >= 1) || !(o.steps >= 2)) throw new Error('--runs must be >= 1 and --steps >= 2');
  const full = o.scenes.length === SCENE_IDS.length && o.engines.length === DEFAULTS.engines.length && o.runs === DEFAULTS.runs && o.steps === DEFAULTS.steps;
  if (!o.out && full) o.out = 'bench/results/peers.md';
  return o;
}

const git = (...args) => {
  try {
    return execFileSync('git', args, { cwd: root, encoding: 'utf8' }).trim();
  } catch {
    return '?';
  }
};

const options = parseArgs(process.argv.slice(2));
const started = new Date();
const load = [loadavg()[0]];
const env = { ...process.env };
let bundle = null;
if (options.engines.some((e) => e.startsWith('ours'))) {
  bundle = await bundleOurs();
  env.PEERS_OURS_BUNDLE = bundle;
}
const source = { commit: git('rev-parse', '--short', 'HEAD'), dirty: git('status', '--porcelain', '--', 'src/engine') !== '' };

const results = [];
const total = options.runs * options.scenes.reduce((n, s) => n + options.engines.filter((e) => runs(e, s)).length, 0);
let done = 0;
for (let run = 1; run <= options.runs; run++) {
  for (const scene of options.scenes) {
    for (const engine of options.engines) {
      if (!runs(engine, scene)) continue;
      const child = spawnSync(process.execPath, [fileURLToPath(new URL('./peers/run-one.mjs', import.meta.url)), engine, scene, '--steps', String(options.steps)], {
        cwd: root,
        env,
        encoding: 'utf8',
        timeout: 10 * 60 * 1000,
        maxBuffer: 1 << 24,
      });
      done++;
      const line = child.stdout?.trim().split('\n').pop();
      let result;
      try {
        result = JSON.parse(line);
      } catch {
        result = { engine, scene, error: (child.error?.message ?? child.stderr?.trim().split('\n').slice(0, 3).join(' ') ?? 'no output') || `exit ${child.status}` };
      }
      result.run = run;
      results.push(result);
      load.push(loadavg()[0]);
      const what = result.error ? `FAILED: ${result.error}` : `${result.median.toFixed(3)} ms/step`;
      console.error(`[${done}/${total}] run ${run} ${scene} ${engine}: ${what}`);
    }
  }
}
if (bundle) rmSync(bundle, { force: true });

const text = report({
  options,
  results,
  started,
  finished: new Date(),
  node: process.version,
  cpu: `${cpus().length} × ${cpus()[0]?.model ?? '?'}`,
  load,
  source,
  peers: PEERS,
});
console.log(text);
if (options.out) {
  const file = root + options.out;
  mkdirSync(file.replace(/\/[^/]*$/, ''), { recursive: true });
  writeFileSync(file, text);
  console.error(`wrote ${options.out}`);
}
