import { expect } from 'chai';
import { kernelBytes } from '../../../src/engine/kernel/choice.js';
import { KERNEL_WASM_OFFSET, KERNEL_WASM_TEXT } from '../../../src/engine/kernel/wasm-bytes.js';

// The module travels as text (scripts/build-wasm.mjs encodeKernel, choice.ts kernelBytes): one or two printable
// characters a byte, none of ' " \ <.
describe('solver kernel: the module as text', () => {
  // The encoding as documented, written again here (scripts/build-wasm.mjs has its own).
  const alphabet = [...Array(95)].map((_, i) => String.fromCharCode(32 + i)).filter((ch) => !`'"\\<`.includes(ch));
  const encodeKernel = (bytes: Uint8Array, offset: number): string =>
    [...bytes]
      .map((b) => (b + offset) % 256)
      .map((v) => (v < 89 ? alphabet[2 + v] : alphabet[Math.floor((v - 89) / 91)] + alphabet[(v - 89) % 91]))
      .join('');

  it('decodes every byte value under every offset to itself', () => {
    expect(alphabet.length).to.equal(91);
    const bytes = Uint8Array.from({ length: 512 }, (_, i) => (i * 37 + (i >> 8)) & 255);
    for (let offset = 0; offset < 256; offset++) {
      const text: string = encodeKernel(bytes, offset);
      expect(text).to.match(/^[ -~]*$/);
      expect(text).not.to.match(/['"\\<]/);
      expect([...kernelBytes(text, offset)]).to.deep.equal([...bytes], `offset ${offset}`);
    }
  });

  it('the shipped text is a WebAssembly module (magic, version 1) that validates with SIMD', () => {
    expect(KERNEL_WASM_TEXT).not.to.match(/['"\\<]/);
    const bytes = kernelBytes(KERNEL_WASM_TEXT, KERNEL_WASM_OFFSET);
    expect([...bytes.subarray(0, 8)]).to.deep.equal([0, 0x61, 0x73, 0x6d, 1, 0, 0, 0]);
    expect(WebAssembly.validate(bytes)).to.equal(true);
    // Under 1.2 characters a byte (base64 took 1.33).
    expect(KERNEL_WASM_TEXT.length / bytes.length).to.be.below(1.2);
  });
});
