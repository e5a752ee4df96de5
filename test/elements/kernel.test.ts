// The scene's kernel attribute: "auto" by default (the WebAssembly kernel in this chromium, in the worker and on the
// main thread alike), "js" and "wasm" on request, a live change keeping the state, and a bad value reported like any
// bad attribute (physics-error and one console warning naming it) with the default in its place.
import { expect } from '@open-wc/testing';
import type { PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

const CLOTH = '<physics-cloth x="2" y="1" columns="10" rows="8" spacing="0.4" pins="top"></physics-cloth>';

describe('<physics-scene kernel>', () => {
  let scene: PhysicsSceneElement | null = null;
  const warn = console.warn;
  afterEach(() => {
    console.warn = warn;
    unmount(scene);
  });

  for (const worker of ['auto', 'none']) {
    it(`runs the WebAssembly kernel by default, JS with kernel="js" (worker="${worker}")`, async () => {
      scene = await mount(`paused worker="${worker}"`, CLOTH);
      expect(await scene.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'auto', kernelReason: '', mode: worker === 'auto' ? 'worker' : 'main' });
      unmount(scene);
      scene = await mount(`paused worker="${worker}" kernel="js"`, CLOTH);
      expect(await scene.diagnostics()).to.include({ kernel: 'js', kernelRequested: 'js' });
    });
  }

  it('a live change of kernel keeps the state: same step count, same state hash', async () => {
    scene = await mount('paused kernel="js"', CLOTH);
    await scene.step(30);
    const hash = await scene.stateHash();
    scene.kernel = 'wasm';
    await waitFor(async () => (await scene!.diagnostics()).kernel === 'wasm', 'the WebAssembly kernel');
    expect(await scene.diagnostics()).to.include({ kernelRequested: 'wasm', stepCount: 30 });
    expect(await scene.stateHash()).to.equal(hash);
    await scene.step(30);
    expect((await scene.diagnostics()).stepCount).to.equal(60);
  });

  it('kernel="simd": a physics-error and one warning naming the attribute and the value; the default runs', async () => {
    const warnings: string[] = [];
    console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
    const errors: PhysicsErrorDetail[] = [];
    scene = await mount('paused kernel="simd"', CLOTH, {
      before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    });
    expect(errors.map((e) => [e.attribute, e.value])).to.deep.equal([['kernel', 'simd']]);
    expect(errors[0].message).to.contain('auto, wasm, js');
    expect(warnings.filter((w) => w.includes('kernel="simd"'))).to.have.length(1);
    expect(await scene.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'auto' });
  });
});
