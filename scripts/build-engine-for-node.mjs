// Bundles src/engine for Node with esbuild (no build step needed before a benchmark or a Node check).
import { build } from 'esbuild';
import { mkdirSync } from 'node:fs';
import { fileURLToPath, pathToFileURL } from 'node:url';

const root = fileURLToPath(new URL('..', import.meta.url));

/** Builds `entry` (a path under the repo) to node_modules/.cache and imports it. */
export async function importTs(entry = 'src/engine/index.ts') {
  const outdir = root + 'node_modules/.cache/physics-elements';
  mkdirSync(outdir, { recursive: true });
  const outfile = `${outdir}/${entry.replace(/[\/.]/g, '_')}.mjs`;
  await build({ entryPoints: [root + entry], bundle: true, format: 'esm', platform: 'neutral', target: 'es2022', outfile, logLevel: 'error' });
  return import(pathToFileURL(outfile).href + '?t=' + Date.now());
}
