// Our engine, built from the scene catalogue (y down) with sleeping off; measurements mirrored to y up.
// The parent bundles src/engine once (bundleOurs) so every child process runs the same snapshot of the source
// even while src/ is being edited; PEERS_OURS_BUNDLE names the bundle.
import { build as esbuild } from 'esbuild';
import { mkdirSync, readFileSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';
import { measurePoses } from '../scenes.mjs';

const root = fileURLToPath(new URL('../../../', import.meta.url));

/** Bundles src/engine/index.ts as scripts/build-engine-for-node.mjs does, to a file of our own. */
export async function bundleOurs() {
  const outdir = root + 'node_modules/.cache/physics-elements';
  mkdirSync(outdir, { recursive: true });
  const outfile = `${outdir}/bench-peers-engine-${process.pid}.mjs`;
  await esbuild({ entryPoints: [root + 'src/engine/index.ts'], bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error' });
  return outfile;
}

/**
 * options.tethers false: the chain and cloth without the builders' default tethers (S4/S5 only); options.kernel: the
 * solver kernel ('js', the default, or 'wasm': the WebAssembly SIMD kernel; see docs/engine.md).
 */
export async function load(options = {}) {
  const tethers = options.tethers ?? true;
  const kernel = options.kernel ?? 'js';
  const file = process.env.PEERS_OURS_BUNDLE ?? (await bundleOurs());
  const engine = await import(pathToFileURL(file).href);
  const probe = new engine.World();
  const { version } = JSON.parse(readFileSync(root + 'package.json', 'utf8'));
  return {
    version,
    settings: `substeps ${probe.substeps} (${AUTO_NOTE}) × ${probe.iterations} iteration (new World() defaults), sleeping off, the ${kernel} kernel; ${tethers ? "S4/S5 use the catalogue's rope/cloth with their default tethers" : 'S4/S5 with tethers: false (links and pin only)'}`,
    build: (scene) => build(engine, scene, tethers, kernel),
  };
}

const near = (a, b) => Math.abs(a - b) < 1e-9;

/** What 'auto' substeps gives (settings.ts AUTO_SUBSTEPS): the boxes and circles are rigid bodies, the chain and cloth particles. */
const AUTO_NOTE = 'auto: 6 for the rigid S1–S3, 10 for the particle S4/S5';

/** Throws unless the catalogue scene is the neutral scene mirrored in y (so every engine runs the same layout). */
function checkSameScene(description, scene) {
  const fail = (what) => {
    throw new Error(`catalogue scene '${scene.catalogue}' no longer matches bench/peers/scenes.mjs ${scene.id}: ${what}`);
  };
  const bodies = description.bodies;
  if (description.world?.gravity?.y !== 10 || description.world?.gravity?.x !== 0) fail('gravity');
  const sameBox = (d, s) => d.type === 'box' && near(d.x, s.x) && near(-d.y, s.y) && near(d.width, s.w) && near(d.height, s.h) && !d.angle;
  const statics = bodies.filter((d) => d.static);
  const dynamic = bodies.filter((d) => !d.static);
  if (statics.length !== scene.statics.length || statics.some((d, k) => !sameBox(d, scene.statics[k]))) fail('static bodies');
  if (scene.boxes && (dynamic.length !== scene.boxes.length || dynamic.some((d, k) => !sameBox(d, scene.boxes[k])))) fail('boxes');
  if (scene.circles) {
    const same = (d, s) => d.type === 'circle' && near(d.x, s.x) && near(-d.y, s.y) && near(d.radius, s.r);
    if (dynamic.length !== scene.circles.length || dynamic.some((d, k) => !same(d, scene.circles[k]))) fail('circles');
  }
  if (scene.chain) {
    const [d] = dynamic;
    const c = scene.chain;
    if (dynamic.length !== 1 || d.type !== 'rope' || d.segments !== c.links || d.from.x !== 0 || d.from.y !== 0 || !near(d.to.x, c.links * c.length) || d.to.y !== 0 || d.ropeLike !== false || d.pinStart === false || d.pinEnd) fail('chain');
  }
  if (scene.cloth) {
    const [d] = dynamic;
    const c = scene.cloth;
    if (dynamic.length !== 1 || d.type !== 'cloth' || d.columns !== c.columns || d.rows !== c.rows || d.spacing !== c.spacing || !near(d.origin.x, c.left) || !near(-d.origin.y, c.top) || (d.pins ?? 'top') !== 'top' || d.shear != null || d.bend != null) fail('cloth');
  }
}

function build(engine, scene, tethers, kernel) {
  const description = engine.catalogue[scene.catalogue].make();
  checkSameScene(description, scene);
  if (!tethers) for (const d of description.bodies) if (d.type === 'rope' || d.type === 'cloth') d.tethers = false;
  description.world = { ...description.world, sleeping: false, kernel };
  const { world, bodies } = engine.buildScene(description);
  const runs = world.diagnostics();
  if (runs.kernel !== kernel) throw new Error(`the ${kernel} kernel does not run: ${runs.reason}`);
  const dynamic = bodies.filter((_, k) => !description.bodies[k].static).map((b) => b.body);
  const particlesOf = (h) => world.bodyParticleIndices(h);
  return {
    step: () => world.step(),
    measure() {
      const { x, y } = world.particles;
      const m = {};
      if (scene.boxes) {
        // Rigid boxes by pose (y mirrored up, so angles turn the other way).
        return measurePoses(dynamic, (h, out) => {
          const p = world.bodyPose(h);
          out[0] = p.x;
          out[1] = -p.y;
          out[2] = -p.angle;
        });
      }
      if (scene.circles) {
        // A rigid disc's one particle is its centre.
        m.points = new Float64Array(dynamic.length * 2);
        dynamic.forEach((h, k) => {
          const i = particlesOf(h)[0];
          m.points[2 * k] = x[i];
          m.points[2 * k + 1] = -y[i];
        });
      } else {
        const idx = Array.from(particlesOf(dynamic[0]));
        m.points = new Float64Array(idx.length * 2);
        idx.forEach((i, k) => ((m.points[2 * k] = x[i]), (m.points[2 * k + 1] = -y[i])));
        if (scene.chain || scene.cloth) m.strain = world.maxStrain();
      }
      return m;
    },
  };
}
