// The solver kernels side by side (issue 16): median ms per step of the same scenes with new World({ kernel: 'js' })
// and { kernel: 'wasm' }, sleeping off, dt 1/60, default substeps and iterations. Runs alternate between the kernels
// so a burst of load from elsewhere on the machine lands on both; the load average is printed with the table. The
// table gives CPU time per step (process.cpuUsage: on a shared, loaded machine it counts only the time this process
// ran, where wall time also counts the time it waited for a core) and wall time beside it. With --fresh, each
// measurement runs in a process of its own (as bench/peers.mjs runs each engine) and its wall time is the median of
// the timed steps' times (as bench/peers.mjs reports them); in one process the rigid piles run slower (docs/engine.md).
//
//   node bench/kernel.mjs                       every scene, 5 runs
//   node bench/kernel.mjs --runs 3 --scenes cloth200,circles10k
//   node bench/kernel.mjs --runs 3 --scenes pyramid,boxes,circles   the rigid contact lanes (S1, S2, S3)
//   node bench/kernel.mjs --warm 100            warm-up steps for every scene (default: each scene's own, below)
//   node bench/kernel.mjs --fresh --runs 5 --scenes circles10k,cloth200   a fresh process a run, median step
//   node bench/kernel.mjs --sweep               also time the distance sweep alone (JS loop vs kernel, same arrays)
//   node bench/kernel.mjs --runs 3 --out bench/results/kernel.json   also write the table as JSON (the experiments
//                                               page, demo/report.html, draws it)
import { spawnSync } from 'node:child_process';
import { writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { cpus, loadavg } from 'node:os';
import { gzipSync } from 'node:zlib';
import { importTs } from '../scripts/build-engine-for-node.mjs';
import { benchWorld } from './scenes.mjs';

const arg = (name, fallback) => (process.argv.includes(name) ? process.argv[process.argv.indexOf(name) + 1] : fallback);
const runs = Number(arg('--runs', 5));
const fresh = process.argv.includes('--fresh');
const child = process.argv.includes('--child');
const median = (xs) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];
const engine = await importTs();
const { World, createCloth } = engine;

/** Scenes: how to build them and how many steps to warm up and to time. */
const SCENES = {
  cloth30: { title: 'S5 cloth 30×30 (catalogue)', warm: 60, timed: 300, make: (kernel) => benchWorld(engine, 'cloth', kernel) },
  // Rigid piles: the kernel's rigid contact lanes (single points for the circles, by manifold for the boxes).
  pyramid: { title: 'S1 pyramid, base 20 (catalogue)', warm: 60, timed: 300, make: (kernel) => benchWorld(engine, 'pyramid', kernel) },
  boxes: { title: 'S2 1000 boxes (catalogue)', warm: 300, timed: 100, make: (kernel) => benchWorld(engine, 'boxes', kernel) },
  circles: { title: 'S3 2000 circles (catalogue)', warm: 300, timed: 100, make: (kernel) => benchWorld(engine, 'circles', kernel) },
  chain: { title: 'S4 chain, 100 links (catalogue)', warm: 60, timed: 300, make: (kernel) => benchWorld(engine, 'chain', kernel) },
  cloth200: {
    title: '200×200 pinned cloth (bench/cloth.mjs layout)',
    // Built in its rest shape, it hangs still from the first step (largest speed 2e-4 after 10 steps, 1e-4 after 60),
    // but its tethers settle more slowly: taut at the end of a step 97 of 39,800 after one step, 6,400 after 10 (the old
    // warm-up), 10,000-11,000 from step 20 on. 60 steps time the settled cloth, with every phase's code optimised.
    warm: 60,
    timed: 40,
    make: (kernel) => benchWorld(engine, 'cloth200', kernel),
  },
  circles10k: {
    title: '10,000 circles r 0.5 dropped into a container 100 wide',
    // Two seconds first: after 30 steps no circle touches anything yet (the old warm-up of 30 timed the first
    // landings); from step 60 on the pile holds 27,000-29,000 contacts, and the window times a pile forming under the
    // rows still falling.
    warm: 120,
    timed: 30,
    make: (kernel) => benchWorld(engine, 'circles10k', kernel),
  },
};

/**
 * One scene and kernel measured: here, or with --fresh in a child process of its own (`--child <scene> <kernel>`
 * prints the result as JSON), as bench/peers.mjs runs each engine: a JS realm that ran other worlds is slower (see
 * docs/engine.md: the first detached buffer, other scenes' compiled code).
 */
function measure(scene, kernel) {
  if (fresh && !child) {
    const name = Object.keys(SCENES).find((n) => SCENES[n] === scene);
    const warm = process.argv.includes('--warm') ? ['--warm', arg('--warm')] : [];
    const run = spawnSync(process.execPath, [fileURLToPath(import.meta.url), '--child', name, kernel, '--fresh', ...warm], { encoding: 'utf8', maxBuffer: 1 << 24 });
    if (run.status !== 0) throw new Error(`${name} ${kernel}: ${run.stderr}`);
    return JSON.parse(run.stdout.trim().split('\n').pop());
  }
  const world = scene.make(kernel);
  if (world.diagnostics().kernel !== kernel) throw new Error(`asked for ${kernel}, runs ${world.diagnostics().kernel}: ${world.diagnostics().reason}`);
  for (let k = 0, n = Number(arg('--warm', scene.warm)); k < n; k++) world.step();
  const t0 = performance.now();
  const cpu0 = process.cpuUsage();
  const steps = [];
  for (let k = 0; k < scene.timed; k++) {
    const t = performance.now();
    world.step();
    steps.push(performance.now() - t);
  }
  const cpu = process.cpuUsage(cpu0);
  const wall = fresh ? median(steps) : (performance.now() - t0) / scene.timed;
  // Steps (warm-up included) whose rigid contacts the kernel's lanes took, and those left to the JS solver.
  const k = world.ctx.kernel;
  const lanes = k ? { lanes: k.rigidLaneSteps, js: k.rigidJsSteps } : null;
  return { ms: (cpu.user + cpu.system) / 1000 / scene.timed, wall, strain: world.maxStrain(), particles: world.particleCount, links: world.distances.count, lanes };
}

if (child) {
  console.log(JSON.stringify(measure(SCENES[process.argv[process.argv.indexOf('--child') + 1]], process.argv[process.argv.indexOf('--child') + 2])));
  process.exit(0);
}
const names = arg('--scenes', Object.keys(SCENES).join(',')).split(',');
const wasmBytes = (await import('../scripts/build-wasm.mjs')).readKernelBytes();
const load = [loadavg()[0]];
console.log(`solver kernels: ${runs} runs alternating${fresh ? ', each in a fresh process (wall: median step)' : ''}, sleeping off, substeps ${new World().substeps} × iterations ${new World().iterations}, Node ${process.version}`);
console.log('| scene | particles | links | js CPU ms/step | wasm CPU ms/step | wasm/js | wall js | wall wasm | max strain js | wasm |');
console.log('|---|---|---|---|---|---|---|---|---|---|');
const rows = [];
for (const name of names) {
  const scene = SCENES[name];
  if (!scene) throw new Error(`unknown scene ${name}; scenes: ${Object.keys(SCENES).join(', ')}`);
  const results = { js: [], wasm: [] };
  for (let r = 0; r < runs; r++) for (const kernel of r % 2 ? ['wasm', 'js'] : ['js', 'wasm']) results[kernel].push(measure(scene, kernel));
  const [js, wasm] = [results.js, results.wasm].map((rs) => median(rs.map((r) => r.ms)));
  const [wallJs, wallWasm] = [results.js, results.wasm].map((rs) => median(rs.map((r) => r.wall)));
  const [r] = results.js;
  const strain = (rs) => `${(median(rs.map((x) => x.strain)) * 100).toFixed(3)}%`;
  console.log(`| ${scene.title} | ${r.particles} | ${r.links} | ${js.toFixed(3)} | ${wasm.toFixed(3)} | ${(wasm / js).toFixed(2)} | ${wallJs.toFixed(3)} | ${wallWasm.toFixed(3)} | ${strain(results.js)} | ${strain(results.wasm)} |`);
  const lanes = results.wasm[0].lanes;
  if (lanes && lanes.lanes + lanes.js > 0) console.log(`|  (wasm: rigid contacts in the kernel's lanes ${lanes.lanes} steps, JS solver ${lanes.js} steps, first run) |`);
  rows.push({ scene: name, title: scene.title, particles: r.particles, links: r.links, jsMs: js, wasmMs: wasm, wallJsMs: wallJs, wallWasmMs: wallWasm, strainJs: strain(results.js), strainWasm: strain(results.wasm) });
  load.push(loadavg()[0]);
}
console.log(`\nload average (1 min) during the runs: ${load.map((l) => l.toFixed(1)).join(' → ')} on ${cpus().length} cores`);
console.log(`kernel: ${wasmBytes.length} bytes of WebAssembly, ${gzipSync(wasmBytes).length} gzip`);
const out = arg('--out', null);
if (out) {
  const summary = { date: new Date().toISOString(), runs, fresh, node: process.version, cpus: cpus().length, load, wasmBytes: wasmBytes.length, wasmGzip: gzipSync(wasmBytes).length };
  writeFileSync(new URL(`../${out}`, import.meta.url), `${JSON.stringify({ summary, rows }, null, 2)}\n`);
  console.log(`wrote ${out}`);
}

if (process.argv.includes('--sweep')) {
  // The distance sweep alone, on the same arrays: the JS loop (distance.ts) against the kernel's coloured packets.
  const { solveDistances } = await importTs('src/engine/constraints/distance.ts');
  for (const size of [30, 200]) {
    const world = new World({ gravity: { x: 0, y: 10 }, kernel: 'wasm' });
    createCloth(world, { origin: { x: 0, y: 0 }, columns: size, rows: size, spacing: 0.5, shear: 0 });
    world.step();
    const ctx = world.ctx;
    const h2 = world.substepDt ** 2;
    const reps = size > 100 ? 10 : 200;
    const js = [];
    const wasm = [];
    for (let r = 0; r < 11; r++) {
      let t = performance.now();
      for (let k = 0; k < reps; k++) solveDistances(ctx.constraints.distances, ctx.particles, h2);
      js.push((performance.now() - t) / reps);
      t = performance.now();
      for (let k = 0; k < reps; k++) ctx.kernel.solveDistances(h2);
      wasm.push((performance.now() - t) / reps);
    }
    console.log(`sweep ${size}×${size} (${ctx.constraints.distances.count} links): js ${median(js).toFixed(4)} ms, wasm ${median(wasm).toFixed(4)} ms, ratio ${(median(wasm) / median(js)).toFixed(2)}`);
  }
}

if (process.argv.includes('--f32')) {
  // The f32x4 experiment (src/engine/kernel/experiment-f32.as, not shipped): the same sweep in four f32 lanes over
  // float32 copies of x, y and inverse masses, with and without the f64 → f32 → f64 copies an f32 kernel on the
  // engine's f64 state would pay per iteration.
  const { compileKernel } = await import('../scripts/build-wasm.mjs');
  const { colourRows } = await importTs('src/engine/kernel/colour.ts');
  const { bytes } = await compileKernel(new URL('../src/engine/kernel/experiment-f32.as', import.meta.url).pathname);
  for (const size of [30, 200]) {
    const world = new World({ gravity: { x: 0, y: 10 }, kernel: 'wasm' });
    createCloth(world, { origin: { x: 0, y: 0 }, columns: size, rows: size, spacing: 0.5, shear: 0 });
    world.step();
    const { particles: p, constraints, kernel } = world.ctx;
    const c = constraints.distances;
    const slack = Uint8Array.from(c.minLength.subarray(0, c.count), (lo, row) => (lo === c.maxLength[row] ? 0 : 1));
    const rows = colourRows(c.count, c.a, c.b, slack, p.invMass, 4);
    const n = p.x.length;
    const packets = rows.length / 4;
    const bytesNeeded = 3 * n * 4 + packets * 96 + 2 * n * 8 + 64;
    const memory = new WebAssembly.Memory({ initial: Math.ceil(bytesNeeded / 65536) + 1 });
    const { exports } = new WebAssembly.Instance(new WebAssembly.Module(bytes), { env: { memory } });
    const [X, Y, W, P, X64] = [0, n * 4, 2 * n * 4, 3 * n * 4, 3 * n * 4 + packets * 96];
    const f32 = new Float32Array(memory.buffer);
    const i32 = new Int32Array(memory.buffer);
    f32.set(p.x, X / 4);
    f32.set(p.y, Y / 4);
    f32.set(p.invMass, W / 4);
    new Float64Array(memory.buffer, X64, n).set(p.x);
    for (let lane = 0; lane < rows.length; lane++) {
      const row = rows[lane];
      const base = (P >> 2) + (lane >> 2) * 24;
      const l = lane & 3;
      i32[base + l] = row < 0 ? 0 : c.a[row] * 4;
      i32[base + 4 + l] = row < 0 ? 0 : c.b[row] * 4;
      f32[base + 8 + l] = row < 0 ? 0 : c.minLength[row];
      f32[base + 12 + l] = row < 0 ? Infinity : c.maxLength[row];
      f32[base + 16 + l] = row < 0 ? 0 : c.compliance[row];
    }
    const h2 = world.substepDt ** 2;
    const reps = size > 100 ? 10 : 200;
    const t = { f64x2: [], f32x4: [], f32x4copies: [] };
    for (let r = 0; r < 11; r++) {
      let t0 = performance.now();
      for (let k = 0; k < reps; k++) kernel.solveDistances(h2);
      t.f64x2.push((performance.now() - t0) / reps);
      t0 = performance.now();
      for (let k = 0; k < reps; k++) exports.solveDistances32(X, Y, W, P, packets, h2);
      t.f32x4.push((performance.now() - t0) / reps);
      t0 = performance.now();
      for (let k = 0; k < reps; k++) {
        // x and y down to f32 and back up (measured on one f64 column twice each way).
        for (let m = 0; m < 2; m++) exports.demote(X64, X, n);
        exports.solveDistances32(X, Y, W, P, packets, h2);
        for (let m = 0; m < 2; m++) exports.promote(X, X64, n);
      }
      t.f32x4copies.push((performance.now() - t0) / reps);
    }
    console.log(`sweep ${size}×${size}: f64x2 (shipped) ${median(t.f64x2).toFixed(4)} ms, f32x4 ${median(t.f32x4).toFixed(4)} ms, f32x4 with the copies ${median(t.f32x4copies).toFixed(4)} ms`);
  }
}
