// Same-process A/B of the rigid friction anchors (RigidAnchorCache.store and .restore) timed inside real steps: the
// engine bundled from two source trees (esbuild), a world from each built alike and stepped alternately from the same
// state, the two methods wrapped on each world's cache (performance.now around each call); medians over the steps.
// Timed in place because the lists' first touch of the step (cold caches) and the cursor's misses are what they cost.
//
//   node bench/ab-rigid-anchors.mjs --a /tmp/before --b . --scene circles10k     (scenes: circles = S3, circles10k)
import { build } from 'esbuild';
import { mkdirSync } from 'node:fs';
import { pathToFileURL } from 'node:url';
import { benchWorld } from './scenes.mjs';
const arg = (n, f) => (process.argv.includes(n) ? process.argv[process.argv.indexOf(n) + 1] : f);
const dirs = [arg('--a', '.'), arg('--b', '.')];
const scene = arg('--scene', 'circles');
const kernel = arg('--kernel', 'wasm');
const warm = Number(arg('--warm', scene === 'circles10k' ? 120 : 300));
const steps = Number(arg('--steps', scene === 'circles10k' ? 60 : 200));
const engines = [];
for (const [k, d] of dirs.entries()) {
  mkdirSync('/tmp/ab-rigid-anchors', { recursive: true });
  const outfile = `/tmp/ab-rigid-anchors/${k ? 'B' : 'A'}-${process.pid}.mjs`;
  await build({ entryPoints: [d + '/src/engine/index.ts'], bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error' });
  engines.push(await import(pathToFileURL(outfile).href));
}
const worlds = engines.map((e) => benchWorld(e, scene, kernel));
const acc = worlds.map(() => ({ store: 0, restore: 0 }));
worlds.forEach((w, k) => {
  const cache = w.ctx.rigidAnchors;
  for (const name of ['store', 'restore']) {
    const f = cache[name].bind(cache);
    cache[name] = (a, b) => { const t0 = performance.now(); f(a, b); acc[k][name] += performance.now() - t0; };
  }
});
for (const w of worlds) for (let k = 0; k < warm; k++) w.step();
const per = worlds.map(() => ({ store: [], restore: [], step: [] }));
for (let s = 0; s < steps; s++) {
  for (const k of s % 2 ? [1, 0] : [0, 1]) {
    acc[k].store = acc[k].restore = 0;
    const t0 = performance.now();
    worlds[k].step();
    per[k].step.push(performance.now() - t0);
    per[k].store.push(acc[k].store);
    per[k].restore.push(acc[k].restore);
  }
}
const med = (a) => { const s = [...a].sort((x, y) => x - y); return s[s.length >> 1]; };
for (const [k, r] of per.entries()) console.log(`${dirs[k]} ${scene} ${kernel}: step ${med(r.step).toFixed(3)} ms, store ${(1000 * med(r.store)).toFixed(1)} us, restore ${(1000 * med(r.restore)).toFixed(1)} us`);
console.log(`B/A store ${(med(per[1].store) / med(per[0].store)).toFixed(3)}, restore ${(med(per[1].restore) / med(per[0].restore)).toFixed(3)}; hashes ${worlds.map((w) => w.stateHash()).join(' ')}`);
