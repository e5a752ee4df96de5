import type { Column } from './table.js';

/**
 * FNV-1a over the raw bits of the first `count` entries of each column, plus a few integers. Two 32-bit lanes
 * with different offsets give a 64-bit hex digest; equal state gives an equal digest on every platform
 * (typed arrays are little-endian everywhere JS runs in practice, and the bits are what is hashed).
 */
export function hashColumns(columns: Column[], count: number, extra: number[] = []): string {
  let h1 = 0x811c9dc5;
  let h2 = 0x01000193 ^ 0x5bd1e995;
  const mix = (word: number) => {
    h1 = Math.imul(h1 ^ word, 0x01000193);
    h2 = Math.imul(h2 ^ word, 0x01000193) ^ (h2 >>> 15);
  };
  for (const col of columns) {
    const bytesPer = col.BYTES_PER_ELEMENT;
    const byteLength = count * bytesPer;
    const words = new Uint32Array(col.buffer, col.byteOffset, Math.floor(byteLength / 4));
    for (let k = 0; k < words.length; k++) mix(words[k]);
    const bytes = new Uint8Array(col.buffer, col.byteOffset + words.length * 4, byteLength - words.length * 4);
    for (let k = 0; k < bytes.length; k++) mix(bytes[k]);
  }
  for (const e of extra) mix(e >>> 0);
  return (h1 >>> 0).toString(16).padStart(8, '0') + (h2 >>> 0).toString(16).padStart(8, '0');
}
