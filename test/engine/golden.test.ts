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
 */
const GOLDEN: Partial<Record<SceneName, string>> = {
  pyramid: '6b066118714d388d',
  stack: 'a780cda0cbd720e1',
  chain: 'a841c3fb5345fbe8',
  cloth: '4df439d08758041b',
  thrown: 'b04bcc188fb7acea',
  ragdolls: 'd967f5be9302e581',
  soft: 'b7d2a653e46afbb3',
};

/** The determinism test's busy world (cloth, rope, ragdoll, soft bodies, a box; bounds; sleeping off). */
const BUSY = 'a3249b56f7e2ea49';

const STEPS = 300;

describe('golden state hashes (change only deliberately, with the reason in the commit message)', () => {
  for (const [name, hash] of Object.entries(GOLDEN) as [SceneName, string][]) {
    it(`${name}: ${STEPS} steps give ${hash}`, () => {
      const { world } = buildScene(catalogue[name].make());
      for (let k = 0; k < STEPS; k++) world.step();
      expect(world.stateHash()).to.equal(hash);
    });
  }

  it(`the busy world: ${STEPS} steps give ${BUSY}`, () => {
    const world = busyWorld();
    for (let k = 0; k < STEPS; k++) world.step();
    expect(world.stateHash()).to.equal(BUSY);
  });
});
