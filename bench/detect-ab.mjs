// Collision detection of rigid disc piles, A/B in one process (issue 16): the engine at git revision BASE (A) and the
// work tree (B) bundled apart with esbuild, the same scene built from each, stepped in alternating blocks (the order
// flips every round), CPU time (process.cpuUsage) per block; medians per side and of the per-round ratios B/A. The
// two worlds must stay equal (stateHash compared after each round): a change that moves the doubles is reported.
// Whole steps also print detection's share of the step (world.timings, wall clock). --mode broad / narrow time one
// phase of each side on the same world (A's, warmed), so on the same memory. Run under `node --single-threaded` (GC
// and compiler threads on the measured one) and compare with an A/A run: on a loaded machine ratios spread by ±10%.
// --profile adds a sampling CPU profile of the rounds: each side's detection functions, self time per step (the
// steady numbers in a step: detection's own data is cold there, unlike in --mode detect).
//
//   node bench/detect-ab.mjs --base HEAD                          whole steps, S3 and the 10,000-disc pile, both kernels
//   node bench/detect-ab.mjs --base HEAD --mode detect            detectCollisions alone, repeated on the warm state
//   node bench/detect-ab.mjs --base HEAD --mode broad             the broad phase alone (--mode narrow: the rigid narrow phase)
//   node bench/detect-ab.mjs --base HEAD --profile                whole steps, with each side's detection functions
//   node bench/detect-ab.mjs --base HEAD --b HEAD                 A/A: the noise of the comparison
//   node bench/detect-ab.mjs --base /tmp/copy                     A: a directory holding a copy of src/ (an experiment)
//   node bench/detect-ab.mjs --base HEAD --scenes circles10k --kernels wasm --rounds 15 --block 4
//
// Scenes: circles (S3, the catalogue's 2,000 discs, sleeping off as in bench/peers) warmed 300 steps, circles10k
// (bench/scenes.mjs) warmed 120 steps; each round times `--block` steps (or detections) per side.
import { build } from 'esbuild';
import { execFileSync } from 'node:child_process';
import { existsSync, mkdtempSync, rmSync } from 'node:fs';
import { Session } from 'node:inspector/promises';
import { loadavg, tmpdir } from 'node:os';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { benchWorld } from './scenes.mjs';

const root = fileURLToPath(new URL('..', import.meta.url));
const arg = (name, fallback) => (process.argv.includes(name) ? process.argv[process.argv.indexOf(name) + 1] : fallback);
const base = arg('--base', 'HEAD');
const mode = arg('--mode', 'step');
const scenes = arg('--scenes', 'circles,circles10k').split(',');
const kernels = arg('--kernels', 'js,wasm').split(',');
const rounds = Number(arg('--rounds', 15));
const block = Number(arg('--block', 5));

/** Bundles the engine (plus detectCollisions) from checkout `dir` to a file of its own and imports it. */
async function bundle(dir, name) {
  const outfile = `${root}node_modules/.cache/physics-elements/detect-ab-${name}.mjs`;
  await build({
    stdin: { contents: "export * from './src/engine/index.ts'; export { detectCollisions } from './src/engine/pipeline/collide.ts'; export { GridBroadPhase } from './src/engine/pipeline/broadphase.ts'; export { RigidNarrowPhase } from './src/engine/pipeline/rigid-narrowphase.ts';", resolveDir: dir, loader: 'ts' },
    bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error',
  });
  return import(pathToFileURL(outfile).href + '?t=' + Date.now());
}

/** The engine at git revision `rev` (its src/ unpacked to a temporary directory), bundled as `name`. */
async function bundleRevision(rev, name) {
  if (existsSync(rev)) return bundle(rev, name); // a checkout's directory (an experiment's copy of src/)
  const dir = mkdtempSync(`${tmpdir()}/detect-ab-`);
  execFileSync('sh', ['-c', `git -C "${root}" archive ${rev} src | tar -x -C "${dir}"`]);
  const engine = await bundle(dir, name);
  rmSync(dir, { recursive: true, force: true });
  return engine;
}
// --b REV: B is that revision instead of the work tree (--base HEAD --b HEAD: an A/A run, the noise).
const A = await bundleRevision(base, 'a');
const B = process.argv.includes('--b') ? await bundleRevision(arg('--b'), 'b') : await bundle(root, 'b');

const DETECTION = ['fastPartnerMotions', 'partnerMotions', 'detectCollisions', 'updateBoundingBoxes', 'findPairs', 'radixSort', 'growPushedBodies', 'run', 'discPairs', 'prefillDiscRows', 'circles', 'restore', 'wakeTouched', 'recordApproachSpeeds'];

async function startProfile() {
  const session = new Session();
  session.connect();
  await session.post('Profiler.enable');
  await session.post('Profiler.setSamplingInterval', { interval: 100 });
  await session.post('Profiler.start');
  return session;
}

/** Self time per call of each side's detection functions (ms per step or call), from the profile of the rounds. */
async function printProfile(session, calls) {
  const { profile } = await session.post('Profiler.stop');
  session.disconnect();
  const nodes = new Map(profile.nodes.map((n) => [n.id, n.callFrame]));
  const self = [new Map(), new Map()];
  profile.samples.forEach((id, k) => {
    const frame = nodes.get(id);
    const side = frame.url.includes('detect-ab-a.mjs') ? 0 : frame.url.includes('detect-ab-b.mjs') ? 1 : -1;
    if (side >= 0 && DETECTION.includes(frame.functionName)) self[side].set(frame.functionName, (self[side].get(frame.functionName) ?? 0) + profile.timeDeltas[k] / 1000);
  });
  const names = [...new Set([...self[0].keys(), ...self[1].keys()])];
  const sum = (m) => [...m.values()].reduce((a, b) => a + b, 0);
  for (const f of names) console.log(`    ${f.padEnd(22)} A ${((self[0].get(f) ?? 0) / calls).toFixed(3)}  B ${((self[1].get(f) ?? 0) / calls).toFixed(3)} ms`);
  console.log(`    ${'detection (profiled)'.padEnd(22)} A ${(sum(self[0]) / calls).toFixed(3)}  B ${(sum(self[1]) / calls).toFixed(3)} ms`);
}

const median = (v) => [...v].sort((a, b) => a - b)[v.length >> 1];
const cpu = () => {
  const u = process.cpuUsage();
  return (u.user + u.system) / 1000;
};

console.log(`detect-ab: A = ${base}, B = ${arg('--b', 'work tree')}; mode ${mode}, ${rounds} rounds x ${block}; load ${loadavg().map((l) => l.toFixed(1)).join(' ')}`);
for (const scene of scenes) {
  for (const kernel of kernels) {
    // broad, narrow: one world (A's), each side's broad or narrow phase run on its state (the same memory).
    const parts = mode === 'broad' || mode === 'narrow';
    const worlds = parts ? [benchWorld(A, scene, kernel)] : [benchWorld(A, scene, kernel), benchWorld(B, scene, kernel)];
    if (parts) worlds.push(worlds[0]);
    const components = [A, B].map((E) => (mode === 'broad' ? new E.GridBroadPhase() : new E.RigidNarrowPhase()));
    const warm = scene === 'circles' ? 300 : 120;
    for (const w of new Set(worlds)) for (let k = 0; k < warm; k++) w.step();
    let same = worlds[0].stateHash() === worlds[1].stateHash();
    const times = [[], []];
    const detectWall = [0, 0];
    const stepWall = [0, 0];
    if (mode === 'step') for (const w of worlds) w.measureTimings = true;
    const ratios = [];
    // --profile: a CPU profile of the rounds, self time split by bundle (each side's functions live in its own file).
    const session = process.argv.includes('--profile') ? await startProfile() : null;
    for (let r = 0; r < rounds; r++) {
      const t = [0, 0];
      for (const side of r % 2 ? [1, 0] : [0, 1]) {
        const w = worlds[side];
        const detect = side ? B.detectCollisions : A.detectCollisions;
        const ctx = w.ctx;
        // The narrow phase reads scratch its own side's detection writes (the disc records): one untimed detection.
        if (mode === 'narrow') detect(ctx, w.settings.timestep);
        const t0 = cpu();
        if (mode === 'detect') for (let k = 0; k < block; k++) detect(ctx, w.settings.timestep);
        else if (mode === 'broad') for (let k = 0; k < block; k++) components[side].findPairs(ctx.colliders, ctx.acceptPair, ctx.pairs);
        else if (mode === 'narrow') for (let k = 0; k < block; k++) components[side].run(ctx.pairs, ctx.colliders, ctx.rigidShapes, ctx.particles, ctx.motion, ctx.settings.contactSlop, ctx.rigidContacts);
        else {
          // Detection's share of the step: world.timings.detect (wall clock: detectCollisions, with the step's
          // start positions and the kernel's step start) over the step's wall clock.
          const w0 = performance.now();
          for (let k = 0; k < block; k++) {
            w.step();
            detectWall[side] += w.timings.detect;
          }
          stepWall[side] += performance.now() - w0;
        }
        t[side] = (cpu() - t0) / block;
        times[side].push(t[side]);
      }
      ratios.push(t[1] / t[0]);
      if (mode === 'step' && worlds[0].stateHash() !== worlds[1].stateHash()) same = false;
    }
    const name = scene === 'circles' ? 'S3 circles' : '10k circles';
    if (session) await printProfile(session, rounds * block);
    console.log(`${name.padEnd(12)} ${kernel.padEnd(4)} A ${median(times[0]).toFixed(3)} ms  B ${median(times[1]).toFixed(3)} ms  B/A ${median(ratios).toFixed(3)}  (ratios ${Math.min(...ratios).toFixed(2)}-${Math.max(...ratios).toFixed(2)})  ${same ? 'same state' : 'STATES DIFFER'}${mode === 'step' ? `  detection ${((100 * detectWall[0]) / stepWall[0]).toFixed(0)}% / ${((100 * detectWall[1]) / stepWall[1]).toFixed(0)}% of the step` : ''}`);
  }
}
