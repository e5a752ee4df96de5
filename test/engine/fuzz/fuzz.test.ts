import { expect } from 'chai';
import { fuzzScene, violation } from './generator.js';

// The short batch CI runs; `node scripts/fuzz.mjs --scenes 100000` runs the long form. A seed that ever fails is
// added to REGRESSIONS with the date and what broke.
const BATCH = 40;
const REGRESSIONS: number[] = [];

describe('engine fuzzing', () => {
  it(`${BATCH} random scenes × 1000 steps keep a finite, bounded state, and replay to the same hash`, () => {
    const seeds = [...REGRESSIONS, ...Array.from({ length: BATCH }, (_, k) => 1000 + k)];
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
