// The engines of the benchmark. Each module exports load() → { version, settings, build(scene) → { step(), measure() } }
// (see ../quality.mjs for what measure() returns). Modules load lazily, so a run pays only for its own engine.
const lazy = (path, ...args) => ({ load: async () => (await import(path)).load(...args) });
/** An engine that runs only some scenes. */
const only = (scenes, engine) => ({ ...engine, scenes });

export const ENGINES = {
  ours: lazy('./ours.mjs'),
  // Our chain and cloth without tethers: what the links alone hold (peers have no tethers).
  'ours-no-tethers': only(['S4', 'S5'], lazy('./ours.mjs', { tethers: false })),
  // Our engine with the WebAssembly SIMD solver kernel (new World({ kernel: 'wasm' })).
  'ours-wasm': lazy('./ours.mjs', { kernel: 'wasm' }),
  'matter-js': lazy('./matter.mjs'),
  planck: lazy('./planck.mjs'),
  'p2-es': lazy('./p2.mjs'),
  '@box2d/core': lazy('./box2d-core.mjs'),
  'box2d-wasm': lazy('./box2d-wasm.mjs'),
  rapier2d: lazy('./rapier.mjs', '@dimforge/rapier2d-compat'),
  'rapier2d-simd': lazy('./rapier.mjs', '@dimforge/rapier2d-simd-compat'),
};

export const PEERS = Object.keys(ENGINES).filter((name) => !name.startsWith('ours'));

/** Whether an engine runs a scene. */
export const runs = (engine, scene) => !ENGINES[engine].scenes || ENGINES[engine].scenes.includes(scene);
