// A pressure soft body's areaCompliance (src/engine/builders/softbody.ts → the area constraint, constraints/area.ts):
// XPBD's compliance α makes the area constraint C = A − A₀ a spring of energy C²/(2α). One ring particle is left free
// under gravity, every other pinned and the free particle's two ring links removed, so only the area constraint holds
// it. The area is then linear in its height y: ∂A/∂y = G = R·sin(2π/N) (half the chord between its two neighbours), and
// the particle is a mass m on a spring of stiffness G²/α under the load m·g:
//   equilibrium sag Δy = α·m·g / G², period T = 2π·√(m·α) / G.
// Let go at the rest area (Δy = 0) and undamped, it swings between 0 and 2·Δy about Δy, first back at 2·Δy at T/2.
// (XPBD keeps this equilibrium for any substep length: at rest, λ = −C/(w + α/h²) must cancel gravity's m·g·h².)
import { expect } from 'chai';
import { World, createSoftBody } from '../../../src/engine/index.js';

const N = 16;
const R = 1;
const MASS = 16;
const G_ACC = 10;
const STEPS = 600;
const DT = 1 / 60;
const KERNELS = ['js', 'wasm'] as const;

/** The free particle's sag below where it started, after each of STEPS steps. */
function sag(kernel: (typeof KERNELS)[number], areaCompliance: number | undefined, iterations = 1): number[] {
  const world = new World({ kernel, gravity: { x: 0, y: G_ACC }, sleeping: false, bounds: null, iterations });
  const options = { center: { x: 0, y: 0 }, radius: R, segments: N, mass: MASS, collide: false, damping: 0 };
  const soft = createSoftBody(world, areaCompliance === undefined ? options : { ...options, areaCompliance });
  const handles = world.bodyParticleHandles(soft.body);
  const indices = world.bodyParticleIndices(soft.body);
  // Particle N/4 is at angle π/2: the lowest (y grows downward here, along gravity).
  const k = N / 4;
  handles.forEach((h, i) => {
    if (i !== k) world.addPin(h);
  });
  let removed = 0;
  for (const c of world.bodyConstraintHandles(soft.body)) {
    if (world.constraintKindOf(c) !== 'distance') continue;
    if (world.distanceParticleIndices(c).includes(indices[k])) {
      world.removeConstraint(c);
      removed++;
    }
  }
  expect(removed).to.equal(2);
  const y0 = world.getPosition(handles[k]).y;
  expect(y0).to.be.closeTo(R, 1e-12);
  const out: number[] = [];
  for (let s = 0; s < STEPS; s++) {
    world.step();
    out.push(world.getPosition(handles[k]).y - y0);
  }
  return out;
}

describe('soft body: areaCompliance is the area constraint\'s compliance', () => {
  const G = R * Math.sin((2 * Math.PI) / N);
  const m = MASS / N;

  for (const kernel of KERNELS) {
    it(`no compliance (the default): the area holds the free particle where it is (${kernel})`, () => {
      for (const alpha of [undefined, 0]) {
        const ys = sag(kernel, alpha);
        expect(Math.max(...ys.map(Math.abs)), `areaCompliance ${alpha}`).to.be.below(1e-9);
      }
    });

    // XPBD's compliance is the material's, whatever the iterations: the multiplier λ a substep has accumulated enters
    // each further iteration (α·λ), so four iterations a substep sag as far as one.
    for (const iterations of [1, 4])
    it(`compliance α: the free particle swings about α·m·g/G² below, with period 2π·√(m·α)/G (${kernel}, ${iterations} iteration${iterations > 1 ? 's' : ''})`, () => {
      const mean: number[] = [];
      for (const alpha of [1e-3, 4e-3]) {
        const ys = sag(kernel, alpha, iterations);
        const expected = (alpha * m * G_ACC) / G ** 2; // 0.0683, 0.273
        const period = (2 * Math.PI * Math.sqrt(m * alpha)) / G; // 0.519 s, 1.038 s
        // 10 s is 19 and 9.6 periods: the mean is the equilibrium to within the part period left over.
        mean.push(ys.reduce((s, y) => s + y, 0) / ys.length);
        expect(mean[mean.length - 1], `α = ${alpha}: mean sag`).to.be.closeTo(expected, 0.02 * expected);
        // Its deepest (seen once a step: 0.2 rad of the swing at α = 10⁻³) twice the equilibrium's sag.
        const deepest = Math.max(...ys);
        expect(deepest, `α = ${alpha}: deepest sag`).to.be.closeTo(2 * expected, 0.05 * expected);
        expect(Math.min(...ys), `α = ${alpha}: back up to the start`).to.be.within(-0.001 * expected, 0.05 * expected);
        // The first time it is deepest: half a period after the start, to the step.
        expect((ys.indexOf(deepest) + 1) * DT, `α = ${alpha}: half a period`).to.be.closeTo(period / 2, DT);
      }
      // Four times the compliance, four times the sag.
      expect(mean[1] / mean[0]).to.be.closeTo(4, 0.08);
    });
  }
});
