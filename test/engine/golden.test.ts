import { expect } from 'chai';
import { buildScene, catalogue, type SceneName } from '../../src/engine/index.js';
import { busyWorld } from './helpers.js';

/**
 * Golden state hashes: stateHash() after 300 steps of catalogue scenes, as the engine computes them today.
 *
 * They change only deliberately. A refactoring must leave every one of them as it is (bit-identical results); a
 * change that is meant to alter the simulation (a new solver phase, a different default) updates the values here
 * and says in its commit message which ones changed and why. A value that changes by accident is a bug, even if
 * every other test still passes.
 *
 * They are the JS solver's hashes: every world here says `kernel: 'js'`, so they hold in the suite's second run too
 * (WebAssembly as the default kernel, scripts/test.sh). The WebAssembly kernel's own are in test/engine/kernel/.
 */
const GOLDEN: Partial<Record<SceneName, string>> = {
  pyramid: '3c05210083449d57',
  stack: '92bae300f49b6d38',
  chain: '3a2adb5b0e7fd6ab',
  cloth: '4a17b850c2e2c7fc',
  thrown: 'fed4f89683c07317',
  ragdolls: '942e35a91a558c8b',
  soft: '5f0559caf048f645',
};

/** The determinism test's busy world (cloth, rope, ragdoll, soft bodies, a box; bounds; sleeping off). */
const BUSY = 'bd72e34d7d5d8897';

const STEPS = 300;

describe('golden state hashes (change only deliberately, with the reason in the commit message)', () => {
  for (const [name, hash] of Object.entries(GOLDEN) as [SceneName, string][]) {
    it(`${name}: ${STEPS} steps give ${hash}`, () => {
      const scene = catalogue[name].make();
      const { world } = buildScene({ ...scene, world: { ...scene.world, kernel: 'js' } });
      expect(world.diagnostics().kernel).to.equal('js');
      for (let k = 0; k < STEPS; k++) world.step();
      expect(world.stateHash()).to.equal(hash);
    });
  }

  it(`the busy world: ${STEPS} steps give ${BUSY}`, () => {
    const world = busyWorld({ kernel: 'js' });
    expect(world.diagnostics().kernel).to.equal('js');
    for (let k = 0; k < STEPS; k++) world.step();
    expect(world.stateHash()).to.equal(BUSY);
  });
});
