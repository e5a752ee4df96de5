// The engine's caps per scene (200,000 particles, 1,000,000 constraints, 100,000 bodies) reached from markup: the body
// that would pass them is refused with a physics-error naming the limit, and the rest of the scene keeps running.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

describe('<physics-scene> limits', () => {
  let scene: PhysicsSceneElement | null = null;
  const warn = console.warn;
  afterEach(() => {
    console.warn = warn;
    unmount(scene);
  });

  it('a 600 × 400 cloth (240,000 particles) is refused with the particle limit named; the box beside it falls', async () => {
    const warnings: string[] = [];
    console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
    const errors: PhysicsErrorDetail[] = [];
    scene = await mount(
      'width="16" height="10" gravity="0 10"',
      `<physics-box id="box" x="3" y="1" width="1" height="1"></physics-box>
       <physics-cloth id="huge" x="6" y="1" columns="600" rows="400" spacing="0.01"></physics-cloth>`,
      { before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)) },
    );
    await waitFor(() => errors.length > 0, 'a physics-error for the cloth');
    const [error] = errors;
    expect(error.element.id).to.equal('huge');
    expect(error.message).to.match(/too many particles: the limit is 200000/);
    expect(warnings.some((w) => /too many particles/.test(w))).to.equal(true);
    const d = await scene.diagnostics();
    expect(d.bodyCount).to.equal(1);
    // The box is a rigid body: one particle, its centre of mass.
    expect(d.particleCount).to.equal(1);
    const box = scene.querySelector<PhysicsBoxElement>('#box')!;
    const y0 = box.y;
    const steps = scene.stepCount;
    await waitFor(() => box.y > y0 + 1 && scene!.stepCount > steps + 20, 'the box to fall while the scene steps');
  });
});
