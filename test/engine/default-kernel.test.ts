// setDefaultKernel(): the kernel of every World whose options name none, in this realm. Each test puts back the
// default it found (the suite also runs with 'wasm' as the default: test/engine/kernel/wasm-default.setup.ts).
import { expect } from 'chai';
import { World, buildScene, createCloth, defaultKernel, setDefaultKernel, type KernelChoice } from '../../src/engine/index.js';
import { resetKernelModule } from '../../src/engine/kernel/choice.js';
import { CSP_REFUSAL, withWasmRefused } from './helpers.js';

describe('setDefaultKernel: the kernel of a World that names none', () => {
  let found: KernelChoice;
  beforeEach(() => (found = defaultKernel()));
  afterEach(() => {
    setDefaultKernel(found);
    resetKernelModule();
  });

  it("is 'js' where nothing set it: a fresh instance of the module chooses the JS solver for a World without the option", async () => {
    // The same module loaded again under another URL: its own default, untouched by this run's setDefaultKernel.
    const url = `${new URL('../../src/engine/kernel/choice.ts', import.meta.url).href}?fresh`;
    const fresh = (await import(url)) as typeof import('../../src/engine/kernel/choice.js');
    expect(fresh.defaultKernel()).to.equal('js');
    expect(fresh.chooseKernel().diagnostics).to.deep.equal({ kernel: 'js', requested: 'js', reason: '' });
    expect(fresh.chooseKernel(undefined).kernel).to.equal(null);
  });

  it('sets the kernel of every later World without the option, returns the one before, and an explicit kernel wins', () => {
    expect(setDefaultKernel('js')).to.equal(found);
    const before = new World();
    expect(before.diagnostics()).to.deep.equal({ kernel: 'js', requested: 'js', reason: '', rowsRepaired: 0 });
    expect(setDefaultKernel('wasm')).to.equal('js');
    expect(defaultKernel()).to.equal('wasm');
    expect(new World().diagnostics()).to.deep.equal({ kernel: 'wasm', requested: 'wasm', reason: '', rowsRepaired: 0 });
    expect(buildScene({ bodies: [{ type: 'box', x: 0, y: 0, width: 1, height: 1 }] }).world.diagnostics().kernel).to.equal('wasm');
    expect(new World({ kernel: 'js' }).diagnostics()).to.deep.equal({ kernel: 'js', requested: 'js', reason: '', rowsRepaired: 0 });
    // A World already made keeps its kernel.
    expect(before.diagnostics().kernel).to.equal('js');
    expect(setDefaultKernel('auto')).to.equal('wasm');
    expect(new World().diagnostics()).to.deep.equal({ kernel: 'wasm', requested: 'auto', reason: '', rowsRepaired: 0 });
  });

  it('a World made under the default steps exactly like one that names the same kernel', () => {
    const run = (world: World) => {
      createCloth(world, { origin: { x: 0, y: 0 }, columns: 10, rows: 8, spacing: 0.4, pins: 'top' });
      for (let k = 0; k < 60; k++) world.step();
      return world.stateHash();
    };
    for (const kernel of ['js', 'wasm'] as const) {
      setDefaultKernel(kernel);
      expect(run(new World({ gravity: { x: 2, y: 10 } })), kernel).to.equal(run(new World({ gravity: { x: 2, y: 10 }, kernel })));
    }
  });

  it('refuses anything but js, wasm or auto with a RangeError naming kernel and the value, and keeps the default', () => {
    setDefaultKernel('auto');
    for (const bad of ['simd', 'WASM', '', 3, null, undefined, {}]) {
      expect(() => setDefaultKernel(bad as unknown as KernelChoice)).to.throw(RangeError, /^kernel must be one of "js", "wasm", "auto", got /);
    }
    expect(() => setDefaultKernel('simd' as KernelChoice)).to.throw(RangeError, 'got "simd"');
    expect(defaultKernel()).to.equal('auto');
  });

  it("where WebAssembly is refused, a 'wasm' default runs JS with the reason and warns once", () => {
    withWasmRefused((warnings) => {
      setDefaultKernel('wasm');
      expect(new World().diagnostics()).to.deep.equal({ kernel: 'js', requested: 'wasm', reason: CSP_REFUSAL, rowsRepaired: 0 });
      expect(new World().diagnostics().kernel).to.equal('js');
      expect(warnings).to.have.length(1);
    });
  });
});
