// The engine suite's second run in CI (scripts/test.sh, issue #16): every World that names no kernel runs the
// WebAssembly SIMD kernel. Loaded before the spec files with
//   npx mocha --require test/engine/kernel/wasm-default.setup.ts
// It sets the default kernel through the engine's API (setDefaultKernel) and fails the run if the kernel does not
// actually run (a silent fall-back to the JS solver would otherwise pass every test under JS a second time), or if a
// test leaves another default behind.
import { World, defaultKernel, setDefaultKernel } from '../../../src/engine/index.js';

setDefaultKernel('wasm');

function checkKernel(when: string): void {
  if (defaultKernel() !== 'wasm') throw new Error(`wasm-default run: the default kernel is '${defaultKernel()}' ${when}, not 'wasm'`);
  const diagnostics = new World().diagnostics();
  if (diagnostics.kernel !== 'wasm') {
    throw new Error(`wasm-default run: a World without a kernel option runs '${diagnostics.kernel}' ${when} (${diagnostics.reason || 'no reason given'}), not 'wasm'`);
  }
}

checkKernel('at setup');
console.log("engine suite: default kernel 'wasm' (the WebAssembly SIMD kernel runs every World that names no kernel)");

export const mochaHooks = {
  afterEach(): void {
    checkKernel('after this test');
  },
  afterAll(): void {
    checkKernel('at the end of the run');
  },
};
