// Same-process A/B of the rigid contact lanes: the engine bundled from two source trees (esbuild), a world from each
// built alike, stepped alternately in blocks (A B B A …) from the same state, CPU time (process.cpuUsage) per block.
// Prints each side's median ms a step and the median of the per-round ratios B/A (an A/A run shows the noise).
//
//   node bench/ab-rigid-lanes.mjs --a /tmp/before --b . --scene circles --warm 300 --rounds 30 --block 5
//   scenes: circles (S3, catalogue), circles10k (bench/scenes.mjs), pyramid, boxes; --kernel wasm|js
import { build } from 'esbuild';
import { mkdirSync } from 'node:fs';
import { resolve } from 'node:path';
import { loadavg } from 'node:os';
import { pathToFileURL } from 'node:url';
import { benchWorld } from './scenes.mjs';

const arg = (name, fallback) => (process.argv.includes(name) ? process.argv[process.argv.indexOf(name) + 1] : fallback);
const roots = { A: resolve(arg('--a', '.')), B: resolve(arg('--b', '.')) };
const sceneName = arg('--scene', 'circles');
const kernel = arg('--kernel', 'wasm');
const warm = Number(arg('--warm', sceneName === 'circles10k' ? 120 : 300));
const rounds = Number(arg('--rounds', 30));
const block = Number(arg('--block', 5));

async function bundle(root, tag) {
  const outdir = '/tmp/ab-rigid-lanes';
  mkdirSync(outdir, { recursive: true });
  const outfile = `${outdir}/${tag}-${process.pid}.mjs`;
  await build({ entryPoints: [root + '/src/engine/index.ts'], bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error' });
  return import(pathToFileURL(outfile).href);
}

const engines = { A: await bundle(roots.A, 'A'), B: await bundle(roots.B, 'B') };
const worlds = { A: benchWorld(engines.A, sceneName, kernel), B: benchWorld(engines.B, sceneName, kernel) };
for (const side of ['A', 'B']) {
  if (worlds[side].diagnostics().kernel !== kernel) throw new Error(`${side}: kernel ${worlds[side].diagnostics().kernel}`);
  for (let k = 0; k < warm; k++) worlds[side].step();
}
const times = { A: [], B: [] };
const ratios = [];
function timeBlock(side) {
  const w = worlds[side];
  const c0 = process.cpuUsage();
  for (let k = 0; k < block; k++) w.step();
  const c1 = process.cpuUsage(c0);
  return (c1.user + c1.system) / 1000 / block;
}
for (let r = 0; r < rounds; r++) {
  const order = r % 2 ? ['B', 'A'] : ['A', 'B'];
  const t = {};
  for (const side of order) t[side] = timeBlock(side);
  times.A.push(t.A);
  times.B.push(t.B);
  ratios.push(t.B / t.A);
}
const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
const same = worlds.A.stateHash() === worlds.B.stateHash();
console.log(
  `${sceneName} kernel ${kernel}, steps ${warm}-${warm + rounds * block}, ${rounds} rounds x ${block} steps, load ${loadavg()[0].toFixed(2)}: ` +
    `A ${median(times.A).toFixed(3)} ms, B ${median(times.B).toFixed(3)} ms a step (CPU medians), B/A ${median(ratios).toFixed(3)} (median of rounds); same hash: ${same}`,
);
