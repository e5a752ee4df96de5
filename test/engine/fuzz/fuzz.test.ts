import { expect } from 'chai';
import { fuzzScene, violation } from './generator.js';

// The short batch CI runs; `node scripts/fuzz.mjs --scenes 100000` runs the long form. A seed that ever fails is
// added to REGRESSIONS with the date and what broke.
const BATCH = 40;
// Seeds that failed, each run under both solver kernels with the invariants checked after every step.
// 2026-12-02, 1826: a kicked ragdoll (≈250 units/s) drove a 0.06-mass rigid disc through the left wall of the
// bounds (x −62.4 at step 287, both kernels; the every-100-steps check caught it under the WebAssembly kernel only).
const REGRESSIONS: number[] = [1826];

describe('engine fuzzing', () => {
  for (const seed of REGRESSIONS) {
    for (const kernel of ['js', 'wasm'] as const) {
      it(`regression seed ${seed} (${kernel} kernel): a finite, bounded state after every one of 1000 steps`, () => {
        const a = fuzzScene(seed, kernel);
        expect(a.world.diagnostics().kernel).to.equal(kernel);
        for (let k = 1; k <= 1000; k++) {
          a.run(1);
          const problem = violation(a.world);
          expect(problem, `seed ${seed} (${kernel}), step ${k}`).to.equal(null);
        }
      });
    }
  }

  it(`${BATCH} random scenes × 1000 steps keep a finite, bounded state, and replay to the same hash`, () => {
    const seeds = Array.from({ length: BATCH }, (_, k) => 1000 + k);
    let steps = 0;
    for (const seed of seeds) {
      const a = fuzzScene(seed);
      for (let chunk = 0; chunk < 10; chunk++) {
        a.run(100);
        steps += 100;
        const problem = violation(a.world);
        expect(problem, `seed ${seed}, step ${(chunk + 1) * 100}`).to.equal(null);
      }
      const b = fuzzScene(seed);
      b.run(1000);
      expect(b.world.stateHash(), `seed ${seed} replay`).to.equal(a.world.stateHash());
    }
    expect(steps).to.equal(seeds.length * 1000);
  });
});
