// The step loop's step(n) (src/worker/host/loop.ts) against a world that only counts its steps: n is clamped to
// [0, MAX_STEPS = 100000] and floored, anything not a number is 0, and every step is followed by afterStep.
import { expect } from 'chai';
import type { World } from '../../../src/engine/index.js';
import { StepLoop } from '../../../src/worker/host/loop.js';
import { FakeClock } from './harness.js';

const MAX_STEPS = 100000;

/** A loop over a world that counts step() calls (and refuses to go past MAX_STEPS + 1, so a missing clamp fails fast). */
function counting() {
  const counts = { steps: 0, after: 0, published: 0 };
  const world = {
    step() {
      if (++counts.steps > MAX_STEPS + 1) throw new Error(`stepped past ${MAX_STEPS}`);
    },
  } as unknown as World;
  const loop = new StepLoop(
    {
      world: () => world,
      afterStep: () => counts.after++,
      stepped: () => counts.published++,
    },
    new FakeClock(),
  );
  return { loop, counts };
}

/** How many steps one step(n) call takes. */
function stepsFor(n: unknown): number {
  const { loop, counts } = counting();
  loop.step(n as number);
  // Each step is read after (collision events, broken links) before the next; step(n) itself publishes nothing.
  expect(counts.after, `afterStep calls for ${String(n)}`).to.equal(counts.steps);
  expect(counts.published).to.equal(0);
  return counts.steps;
}

describe('StepLoop.step(n)', () => {
  it('takes n steps, n floored; a negative count is 0', () => {
    expect(stepsFor(0)).to.equal(0);
    expect(stepsFor(1)).to.equal(1);
    expect(stepsFor(7)).to.equal(7);
    expect(stepsFor(2.9)).to.equal(2);
    expect(stepsFor(0.5)).to.equal(0);
    expect(stepsFor(-3)).to.equal(0);
    expect(stepsFor(-Infinity)).to.equal(0);
  });

  it(`takes at most ${MAX_STEPS} steps however large n is`, () => {
    expect(stepsFor(MAX_STEPS - 1)).to.equal(MAX_STEPS - 1);
    expect(stepsFor(MAX_STEPS)).to.equal(MAX_STEPS);
    expect(stepsFor(MAX_STEPS + 1)).to.equal(MAX_STEPS);
    expect(stepsFor(1e9)).to.equal(MAX_STEPS);
    expect(stepsFor(Number.MAX_VALUE)).to.equal(MAX_STEPS);
    expect(stepsFor(Infinity)).to.equal(MAX_STEPS);
  });

  it('anything not a number takes no step', () => {
    for (const n of [NaN, undefined, null, 'many', {}, [1, 2], () => 5]) expect(stepsFor(n), String(n)).to.equal(0);
  });
});
