// Cloth benchmark (issue 2): median ms per step of a 30×30 and a 100×100 cloth, structural + shear links, top row
// pinned, dt 1/60, default substeps/iterations. Each run builds a fresh world, warms up 100 steps and times 500.
// Usage: npm run bench:cloth [-- --runs 5]
import { importTs } from '../scripts/build-engine-for-node.mjs';

const runs = Number(process.argv[process.argv.indexOf('--runs') + 1]) || 5;
const { World, createCloth } = await importTs();

function measure(size) {
  const world = new World({ gravity: { x: 0, y: 10 } });
  createCloth(world, { origin: { x: 0, y: 0 }, columns: size, rows: size, spacing: 0.5, shear: 0 });
  for (let k = 0; k < 100; k++) world.step();
  const t0 = performance.now();
  for (let k = 0; k < 500; k++) world.step();
  const ms = (performance.now() - t0) / 500;
  return { ms, strain: world.maxStrain(), links: world.distances.count, particles: world.particleCount };
}

const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
console.log(`cloth benchmark: ${runs} runs, substeps ${new World().substeps}, iterations ${new World().iterations}, Node ${process.version}`);
console.log('| cloth | particles | constraints | median ms/step | min | max | max strain |');
console.log('|---|---|---|---|---|---|---|');
for (const size of [30, 100]) {
  const results = Array.from({ length: runs }, () => measure(size));
  const ms = results.map((r) => r.ms);
  const r = results[0];
  console.log(`| ${size}×${size} | ${r.particles} | ${r.links} | ${median(ms).toFixed(3)} | ${Math.min(...ms).toFixed(3)} | ${Math.max(...ms).toFixed(3)} | ${(r.strain * 100).toFixed(3)}% |`);
}
