// Micro-benchmark of the rigid contact solver's passes on a built scene: per substep, ns per contact point (the
// prepare pass only prepares edge points of particle frames; the position sweep computes the common points' levers).
//   node bench/rigid-solver.mjs [catalogue scene, default pyramid] [rounds, default 300]
import { build } from 'esbuild';
import { fileURLToPath } from 'node:url';
const root = fileURLToPath(new URL('..', import.meta.url));
import { pathToFileURL } from 'node:url';
const ENTRY = `
export { World, catalogue, buildScene } from './src/engine/index.ts';
export { prepareRigidContacts, solveRigidContacts, solveRigidContactVelocities } from './src/engine/rigid/contact-solver.ts';
export { syncRotation, integrateRotation, updateAngularVelocity } from './src/engine/rigid/rows.ts';
export { integrate, updateVelocities } from './src/engine/integrate.ts';
`;
const out = root + 'node_modules/.cache/physics-elements/rigid-solver-' + process.pid + '.mjs';
await build({ stdin: { contents: ENTRY, resolveDir: root, loader: 'ts' }, bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile: out, logLevel: 'error' });
const E = await import(pathToFileURL(out).href);
const scene = process.argv[2] ?? 'pyramid';
const d = E.catalogue[scene].make(); d.world = { ...d.world, sleeping: false };
const { world } = E.buildScene(d);
for (let k = 0; k < 150; k++) world.step();
const ctx = world.ctx;
const c = ctx.rigidContacts, p = ctx.particles;
const h = 1 / 600;
const sub = ctx.substepReals;
const T = { prep: [], pos: [], vel: [], rest: [] };
const ROUNDS = +(process.argv[3] ?? 300);
for (let r = 0; r < ROUNDS; r++) {
  // One step's detection (through world.step every 10 rounds keeps the state sane).
  if (r % 10 === 0) { world.step(); }
  let t0 = performance.now();
  E.integrate(p, h, 1, 'verlet');
  sub[0] = h; sub[1] = 1;
  E.integrateRotation(p, p.torque, ctx.rigidRows, ctx.rigidCount, sub);
  E.syncRotation(p, ctx.rigidRows, ctx.rigidCount);
  let t1 = performance.now();
  E.prepareRigidContacts(c, p);
  let t2 = performance.now();
  c.beginSubstep(4 * h);
  E.solveRigidContacts(c, p);
  let t3 = performance.now();
  E.updateVelocities(p, h, 'verlet');
  E.updateAngularVelocity(p, ctx.rigidRows, ctx.rigidCount, sub);
  let t4 = performance.now();
  E.solveRigidContactVelocities(c, p, h);
  let t5 = performance.now();
  T.rest.push(t1 - t0 + t4 - t3); T.prep.push(t2 - t1); T.pos.push(t3 - t2); T.vel.push(t5 - t4);
}
const med = (a) => a.slice(ROUNDS / 3).sort((x, y) => x - y)[a.length / 3 | 0];
const n = c.count;
console.log(`${scene}: ${n} points; ns/point: prepare ${(med(T.prep) * 1e6 / n).toFixed(1)}, position ${(med(T.pos) * 1e6 / n).toFixed(1)}, velocity ${(med(T.vel) * 1e6 / n).toFixed(1)}; other substep work ${(med(T.rest) * 1e3).toFixed(1)} µs; hash ${world.stateHash()}`);
import('node:fs').then(fs => fs.rmSync(out));
