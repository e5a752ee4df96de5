// One run of one engine on one scene, in a fresh process: node bench/peers/run-one.mjs <engine> <scene> [--steps 600]
// Times every step with performance.now(), measures quality at the start and the end, prints one JSON line.
import { ENGINES } from './engines/index.mjs';
import { SCENES } from './scenes.mjs';
import { quality } from './quality.mjs';

const [engineName, sceneId, ...rest] = process.argv.slice(2);
const stepsFlag = rest.indexOf('--steps');
const steps = stepsFlag >= 0 ? Number(rest[stepsFlag + 1]) : 600;
if (!ENGINES[engineName] || !SCENES[sceneId] || !(steps > 0)) {
  console.error(`usage: node bench/peers/run-one.mjs <${Object.keys(ENGINES).join('|')}> <${Object.keys(SCENES).join('|')}> [--steps N]`);
  process.exit(2);
}

/** The steps whose times count: 100..steps, or the second half of a short run. */
const timedFrom = (n) => Math.min(100, Math.floor(n / 2));

const scene = SCENES[sceneId];
const engine = await ENGINES[engineName].load();
const t0 = performance.now();
const sim = engine.build(scene);
const buildMs = performance.now() - t0;
const first = sim.measure();
const times = new Float64Array(steps);
for (let k = 0; k < steps; k++) {
  const t = performance.now();
  sim.step();
  times[k] = performance.now() - t;
}
const last = sim.measure();
const timed = Array.from(times.subarray(timedFrom(steps))).sort((a, b) => a - b);
const median = timed[Math.floor(timed.length / 2)];
const total = times.reduce((s, t) => s + t, 0);
process.stdout.write(
  JSON.stringify({ engine: engineName, scene: sceneId, version: engine.version, settings: engine.settings, steps, buildMs, median, meanAll: total / steps, quality: quality(scene, first, last) }) + '\n',
);
