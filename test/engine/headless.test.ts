// The engine stays headless and quiet: no DOM, worker or p5, and nothing in it prints except the kernel's one
// warning when WebAssembly cannot run (a debugging print left in the velocity pass once cost every manifold a global
// lookup).
import { expect } from 'chai';

/** node:fs, typed here: the test tsconfig has no Node types (the browser tests share it). */
interface Fs {
  readdirSync(path: string): string[];
  readFileSync(path: string, encoding: 'utf8'): string;
  statSync(path: string): { isDirectory(): boolean };
}
const fsModule = 'node:fs';
const { readdirSync, readFileSync, statSync } = (await import(fsModule)) as Fs;
const join = (dir: string, name: string): string => `${dir.replace(/\/$/, '')}/${name}`;

const root = new URL('../../src/engine/', import.meta.url).pathname;

function sources(dir: string): string[] {
  return readdirSync(dir).flatMap((name) => {
    const path = join(dir, name);
    return statSync(path).isDirectory() ? sources(path) : path.endsWith('.ts') ? [path] : [];
  });
}

/** The code of a file without its comments (block and line). */
function code(path: string): string {
  return readFileSync(path, 'utf8').replace(/\/\*[\s\S]*?\*\//g, '').replace(/^\s*\/\/.*$/gm, '');
}

describe('the engine is headless and quiet', () => {
  const files = sources(root);

  it('reads no DOM, window, document, worker or p5', () => {
    const found = files.filter((f) => /\b(document|window|HTMLElement|postMessage|importScripts)\b|from 'p5|from "p5/.test(code(f)));
    expect(found.map((f) => f.slice(root.length))).to.deep.equal([]);
  });

  it('prints nothing and reads no globals, but the kernel choice\'s one warning', () => {
    const found = files.flatMap((f) => code(f).split('\n').filter((l) => /console\.|globalThis/.test(l)).map((l) => `${f.slice(root.length)}: ${l.trim()}`));
    expect(found).to.have.length(1);
    expect(found[0]).to.match(/^kernel\/choice\.ts: console\.warn\(`physics-elements: the WebAssembly kernel cannot run/);
  });
});
