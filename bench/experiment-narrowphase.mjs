// Seed experiment 1 (chapter 6): SAT vs GJK + EPA narrow phase, with and without the grid broad phase, for 2 to
// 10,000 moving convex polygons of 3–8 vertices. Prints a table and writes bench/results/experiment1.json.
// Usage: node bench/experiment-narrowphase.mjs [--runs 3] [--max 10000]
// A throwaway warm-up pass (every configuration, small sizes) runs first so the JIT is warm before anything is
// timed; each configuration is then measured `runs` times (different seeds; 5 × runs up to 200 objects, whose steps
// take microseconds) and the medians are kept.
import { writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { importTs } from '../scripts/build-engine-for-node.mjs';

const arg = (name, fallback) => {
  const i = process.argv.indexOf(`--${name}`);
  return i > 0 ? Number(process.argv[i + 1]) : fallback;
};
const runs = arg('runs', 3);
const max = arg('max', 10000);
const { World, createPolygon } = await importTs();

function rng(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/**
 * n convex polygons of 3–8 vertices (radius 0.5, vertex angles evenly spread with jitter, mass 1) on a jittered grid
 * covering about 15% of a square box, moving at up to 5 units/s in random directions, no gravity.
 */
function build(n, narrowphase, broadphase, seed) {
  const rnd = rng(seed);
  const side = Math.sqrt((n * Math.PI * 0.25) / 0.15);
  const world = new World({ gravity: { x: 0, y: 0 }, narrowphase, broadphase, sleeping: false, bounds: { minX: 0, minY: 0, maxX: side, maxY: side } });
  const columns = Math.ceil(Math.sqrt(n));
  const cell = side / columns;
  for (let k = 0; k < n; k++) {
    const count = 3 + Math.floor(rnd() * 6);
    const turn = rnd() * 2 * Math.PI;
    const points = Array.from({ length: count }, (_, j) => {
      const t = turn + ((j + 0.3 * (rnd() - 0.5)) * 2 * Math.PI) / count;
      return { x: 0.5 * Math.cos(t), y: 0.5 * Math.sin(t) };
    });
    const x = ((k % columns) + 0.5) * cell + (rnd() - 0.5) * (cell - 1.1);
    const y = (Math.floor(k / columns) + 0.5) * cell + (rnd() - 0.5) * (cell - 1.1);
    const body = createPolygon(world, { points, x, y, mass: 1, friction: 0.3 });
    world.applyBodyImpulse(body.body, (rnd() * 2 - 1) * 5, (rnd() * 2 - 1) * 5);
  }
  return world;
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const sizes = [2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000, 10000].filter((n) => n <= max);
const configs = [];
for (const narrowphase of ['sat', 'gjk']) for (const broadphase of ['grid', 'brute']) configs.push({ narrowphase, broadphase });

/** One measured run: per-step averages over `steps` steps after 20 unmeasured ones. */
function measure(n, narrowphase, broadphase, seed) {
  const world = build(n, narrowphase, broadphase, seed);
  world.measureTimings = true;
  for (let k = 0; k < 20; k++) world.step();
  const steps = n >= 2000 ? 20 : 60;
  let detect = 0;
  let tests = 0;
  let hits = 0;
  let pairs = 0;
  const t0 = performance.now();
  for (let k = 0; k < steps; k++) {
    world.step();
    detect += world.timings.detect;
    tests += world.narrowPhase.tests;
    pairs += world.pairs.count;
    // A pair "hits" when it produced a contact that acted (the polygons really touched).
    const c = world.contacts;
    for (let i = 0; i < c.count; i++) if (c.touched[i]) hits++;
  }
  return { ms: (performance.now() - t0) / steps, detect: detect / steps, tests: tests / steps, hits: hits / steps, pairs: pairs / steps };
}

// Warm-up: every configuration once at small and middle sizes, results thrown away.
const loadBefore = loadavg();
const tWarm = performance.now();
for (const n of [2, 10, 50, 100, 200]) for (const { narrowphase, broadphase } of configs) measure(n, narrowphase, broadphase, 99);
console.log(`warm-up pass: ${((performance.now() - tWarm) / 1000).toFixed(1)} s (discarded)`);

const rows = [];
console.log('| objects | narrow phase | broad phase | ms/step | detection ms/step | narrow-phase tests/step | contacts/step | hit rate |');
console.log('|---|---|---|---|---|---|---|---|');
for (const n of sizes) {
  for (const { narrowphase, broadphase } of configs) {
    if (broadphase === 'brute' && n > 2000) continue; // 25 M pair tests a step: not worth the wait
    const results = [];
    // Small worlds step in microseconds: 5× as many runs (seeds) so their medians are not one noisy sample.
    const count = n <= 200 ? runs * 5 : runs;
    for (let run = 0; run < count; run++) results.push(measure(n, narrowphase, broadphase, 1 + run));
    const pick = (key) => median(results.map((r) => r[key]));
    const row = { objects: n, narrowphase, broadphase, msPerStep: pick('ms'), detectMsPerStep: pick('detect'), testsPerStep: pick('tests'), contactsPerStep: pick('hits'), pairsPerStep: pick('pairs'), runsMs: results.map((r) => r.ms) };
    row.hitRate = row.testsPerStep ? row.contactsPerStep / row.testsPerStep : 0;
    rows.push(row);
    console.log(`| ${n} | ${narrowphase} | ${broadphase} | ${row.msPerStep.toFixed(3)} | ${row.detectMsPerStep.toFixed(3)} | ${row.testsPerStep.toFixed(0)} | ${row.contactsPerStep.toFixed(0)} | ${(row.hitRate * 100).toFixed(1)}% |`);
  }
}
// The seed's claim: up to 65% less time with the grid at 100 objects.
const at100 = (np, bp) => rows.find((r) => r.objects === 100 && r.narrowphase === np && r.broadphase === bp)?.detectMsPerStep;
const gain = (np) => (at100(np, 'brute') && at100(np, 'grid') ? 1 - at100(np, 'grid') / at100(np, 'brute') : null);
const total100 = (np, bp) => rows.find((r) => r.objects === 100 && r.narrowphase === np && r.broadphase === bp)?.msPerStep;
const totalGain = (np) => (total100(np, 'brute') && total100(np, 'grid') ? 1 - total100(np, 'grid') / total100(np, 'brute') : null);
const summary = { date: new Date().toISOString(), node: process.version, runs, max, warmup: true, statistic: 'median', smallSizeRuns: runs * 5, cpus: cpus().length, loadavgBefore: loadBefore, loadavgAfter: loadavg(), command: `node bench/experiment-narrowphase.mjs ${process.argv.slice(2).join(' ')}`.trim(), gridGainAt100: { sat: gain('sat'), gjk: gain('gjk') }, gridGainAt100Total: { sat: totalGain('sat'), gjk: totalGain('gjk') } };
console.log(`grid vs brute force at 100 objects: ${(summary.gridGainAt100.sat * 100).toFixed(0)}% less detection time with SAT, ${(summary.gridGainAt100.gjk * 100).toFixed(0)}% with GJK + EPA (the seed reports up to 65%)`);
writeFileSync(new URL('./results/experiment1.json', import.meta.url), JSON.stringify({ summary, rows }, null, 2));
