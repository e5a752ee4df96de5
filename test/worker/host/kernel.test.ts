// The host and the solver kernel: the `kernel` parameter (default: the engine's default kernel) makes the world with it, diagnostics() says which runs, a
// live change remakes the world in the same state, a bad value is a HostError naming the field, and a refused
// WebAssembly kernel ('auto', the pages' default) warns once and runs JS.
import { expect } from 'chai';
import { setDefaultKernel } from '../../../src/engine/index.js';
import { resetKernelModule } from '../../../src/engine/kernel/choice.js';
import type { KeyedBody } from '../../../src/worker/protocol.js';
import { CSP_REFUSAL, withWasmRefused } from '../../engine/helpers.js';
import { decode, makeHost } from './harness.js';

/** A pinned cloth and a slack rope: distance constraints, which the kernel solves. */
const BODIES: KeyedBody[] = [
  { key: 1, desc: { type: 'cloth', origin: { x: 1, y: 0.5 }, columns: 12, rows: 10, spacing: 0.3, pins: 'top' } },
  { key: 2, desc: { type: 'rope', from: { x: 8, y: 1 }, to: { x: 13, y: 1 }, segments: 20, slack: 1.2, pinEnd: true } },
];

function hostWith(kernel?: 'js' | 'wasm' | 'auto') {
  const h = makeHost();
  const errors = h.host.load({ world: {}, params: { gravity: { x: 2, y: 9.81 }, ...(kernel ? { kernel } : {}) }, bodies: BODIES, links: [] });
  expect(errors).to.deep.equal([]);
  return h;
}

function largestGap(a: [number, number][], b: [number, number][]): number {
  expect(a.length).to.equal(b.length);
  return Math.max(...a.map(([x, y], i) => Math.hypot(x - b[i][0], y - b[i][1])));
}

describe('EngineHost: the solver kernel', () => {
  afterEach(() => resetKernelModule());

  it("runs the engine's default kernel unless asked (JS, or what setDefaultKernel says when the host is made)", () => {
    const previous = setDefaultKernel('js'); // the engine's own default (the suite's second run sets 'wasm')
    try {
      const js = hostWith();
      expect(js.host.diagnostics()).to.include({ kernel: 'js', kernelRequested: 'js', kernelReason: '' });
      setDefaultKernel('wasm');
      expect(hostWith().host.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'wasm', kernelReason: '' });
      // A host keeps the kernel it was made with: a reset makes its world with the same one.
      js.host.reset();
      expect(js.host.diagnostics()).to.include({ kernel: 'js', kernelRequested: 'js' });
    } finally {
      setDefaultKernel(previous);
    }
  });

  it("with 'wasm' or 'auto' runs the WebAssembly kernel (in Node), near the JS one", () => {
    const js = hostWith('js');
    expect(js.host.diagnostics()).to.include({ kernel: 'js', kernelRequested: 'js', kernelReason: '', rowsRepaired: 0 });
    const wasm = hostWith('wasm');
    expect(wasm.host.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'wasm', kernelReason: '' });
    expect(hostWith('auto').host.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'auto' });
    js.host.step(120);
    wasm.host.step(120);
    const a = decode(js.frame).positions;
    const b = decode(wasm.frame).positions;
    expect(b.flat().every(Number.isFinite)).to.equal(true);
    expect(js.host.stateHash()).to.not.equal(wasm.host.stateHash()); // another order of the same sweep
    expect(largestGap(a, b)).to.be.below(0.06); // docs/engine.md: the equivalence bound in position
    // reset() makes the world again with the same kernel.
    wasm.host.reset();
    expect(wasm.host.diagnostics()).to.include({ kernel: 'wasm', stepCount: 0 });
  });

  it('a live change of kernel remakes the world in the same state (same step, same positions), then steps on', () => {
    const h = hostWith('js');
    h.host.step(40);
    const before = decode(h.frame);
    const hash = h.host.stateHash();
    expect(h.host.setParams({ kernel: 'wasm' })).to.equal(null);
    expect(h.host.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'wasm', stepCount: 40 });
    expect(h.host.stateHash()).to.equal(hash);
    expect(decode(h.frame).positions).to.deep.equal(before.positions);
    const reference = hostWith('js');
    reference.host.step(80);
    h.host.step(40);
    expect(largestGap(decode(h.frame).positions, decode(reference.frame).positions)).to.be.below(0.06);
    // Setting the same kernel again remakes nothing: the state is stepped on, not restored.
    const topologies = h.topologies.length;
    h.host.setParams({ kernel: 'wasm' });
    expect(h.topologies.length).to.equal(topologies);
  });

  it('refuses a kernel that is none with an error naming the field and the value; the world keeps its kernel', () => {
    const h = hostWith('wasm');
    const error = h.host.setParams({ kernel: 'fast' as 'js' });
    expect(error).to.deep.include({ key: -1, field: 'kernel' });
    expect(error!.message).to.contain('"fast"');
    expect(h.host.diagnostics()).to.include({ kernel: 'wasm', kernelRequested: 'wasm' });
    const loaded = makeHost().host.load({ world: {}, params: { kernel: 7 as unknown as 'js' }, bodies: BODIES, links: [] });
    expect(loaded.map((e) => e.field)).to.deep.equal(['kernel']);
  });

  it("where the page's policy refuses WebAssembly, 'auto' runs JS and warns once (per page or worker)", () => {
    // The realm's default kernel as in a page's worker, 'js' (the suite's second run sets 'wasm', and a refused
    // 'wasm' default warns once more, from the engine, when the host makes its first, empty world).
    const previous = setDefaultKernel('js');
    try {
      withWasmRefused((warnings) => {
        const a = hostWith('auto');
        const b = hostWith('auto');
        expect(a.host.diagnostics()).to.include({ kernel: 'js', kernelRequested: 'auto', kernelReason: CSP_REFUSAL });
        b.host.step(30);
        expect(decode(b.frame).positions.flat().every(Number.isFinite)).to.equal(true);
        expect(warnings).to.have.length(1);
        expect(warnings[0]).to.contain("'wasm-unsafe-eval'");
      });
    } finally {
      setDefaultKernel(previous);
    }
  });
});
