// Which solver kernel a World runs: the plain JavaScript loops (the reference, everywhere) or the WebAssembly SIMD
// kernel (wasm-kernel.ts) where the platform has WebAssembly with 128-bit SIMD and the page's Content-Security-Policy
// allows compiling it (script-src 'wasm-unsafe-eval'). The choice is made once, when the World is made.
import { oneOf } from '../validate.js';
import { KERNEL_WASM_OFFSET, KERNEL_WASM_TEXT } from './wasm-bytes.js';
import { WasmKernel } from './wasm-kernel.js';

export const KERNELS = ['js', 'wasm', 'auto'] as const;
/** The warning that 'wasm' falls back to JS has been given (in this page or worker). */
let warned = false;
/** 'js': the JavaScript solver; 'wasm': the WebAssembly SIMD kernel (JS, with one warning, where it cannot run);
 *  'auto': the WebAssembly kernel where it can run, silently JS elsewhere. */
export type KernelChoice = (typeof KERNELS)[number];

export interface KernelOptions {
  /** The solver kernel. Default: the realm's default kernel, 'js' unless setDefaultKernel() changed it (see KernelChoice). */
  kernel?: KernelChoice;
}

/** The kernel of a World whose options name none (this page, worker or Node process). */
let defaultChoice: KernelChoice = 'js';

/**
 * Sets the kernel a World runs when its options name none (`new World()`, `buildScene()` without `kernel`), in this
 * realm (page, worker or Node process), from the next World made on; Worlds already made keep theirs. The engine's
 * own default is 'js'. Returns the previous default. Throws a RangeError naming `kernel` and the value for anything
 * but 'js', 'wasm' or 'auto'.
 */
export function setDefaultKernel(kernel: KernelChoice): KernelChoice {
  const next = oneOf('kernel', kernel, KERNELS);
  const previous = defaultChoice;
  defaultChoice = next;
  return previous;
}

/** The kernel a World runs when its options name none: 'js' unless setDefaultKernel() changed it. */
export function defaultKernel(): KernelChoice {
  return defaultChoice;
}

/** What a World says about its kernel (World.diagnostics()). */
export interface KernelDiagnostics {
  /** The kernel that runs. */
  kernel: 'js' | 'wasm';
  /** The kernel asked for. */
  requested: KernelChoice;
  /** Why the WebAssembly kernel does not run ('' when it runs or was not asked for). */
  reason: string;
}

/** World.diagnostics(): the kernel, and how often the step's guard had to put a row right. */
export interface WorldDiagnostics extends KernelDiagnostics {
  /**
   * Rows (particles, rigid bodies) the step's last phase put back where they started the step, at rest, since the
   * world was made: rows left not finite or faster than 10¹². 0 unless the solver met a tangle it could not resolve
   * (pipeline/guard.ts).
   */
  rowsRepaired: number;
}

let compiled: WebAssembly.Module | string | undefined;

/** The kernel's module, compiled once per realm, or why it cannot be. */
function kernelModule(): WebAssembly.Module | string {
  if (compiled !== undefined) return compiled;
  if (typeof WebAssembly !== 'object') return (compiled = 'this platform has no WebAssembly');
  const bytes = kernelBytes(KERNEL_WASM_TEXT, KERNEL_WASM_OFFSET);
  if (!WebAssembly.validate(bytes)) return (compiled = 'this platform has no WebAssembly SIMD');
  try {
    compiled = new WebAssembly.Module(bytes);
  } catch (error) {
    // A page whose Content-Security-Policy lacks 'wasm-unsafe-eval' refuses to compile WebAssembly (a CompileError).
    compiled = `WebAssembly was refused (${(error as Error).message}); the page's Content-Security-Policy needs script-src 'wasm-unsafe-eval'`;
  }
  return compiled;
}

/**
 * The module's bytes from wasm-bytes.ts's text (scripts/build-wasm.mjs, encodeKernel): the alphabet is printable ASCII
 * but for ' " \\ and < (91 characters); its character 2 + v is v, its characters 0 and 1 start a pair: 89 + 91 k + the
 * next character's index; the byte is v less the offset, modulo 256.
 */
export function kernelBytes(text: string, offset: number): Uint8Array<ArrayBuffer> {
  const index = new Uint8Array(128);
  let size = 0;
  for (let c = 32; c < 127; c++) if (!`'"\\<`.includes(String.fromCharCode(c))) index[c] = size++;
  const bytes = new Uint8Array(text.length);
  let n = 0;
  for (let i = 0; i < text.length; i++) {
    const k = index[text.charCodeAt(i)];
    // A Uint8Array stores the value modulo 256.
    bytes[n++] = (k < 2 ? size - 2 + k * size + index[text.charCodeAt(++i)] : k - 2) - offset;
  }
  return bytes.subarray(0, n);
}

/** The kernel for `choice` (undefined: the default kernel; null kernel: the JS loops) and what to say about it.
 *  Throws a RangeError for a bad choice. */
export function chooseKernel(choice: unknown = defaultChoice): { kernel: WasmKernel | null; diagnostics: KernelDiagnostics } {
  const requested = oneOf('kernel', choice, KERNELS);
  if (requested === 'js') return { kernel: null, diagnostics: { kernel: 'js', requested, reason: '' } };
  const module = kernelModule();
  if (typeof module === 'string') {
    if (requested === 'wasm' && !warned) {
      // Once per page or worker: the reason does not change, and a scene rebuilds its world on every reset.
      warned = true;
      console.warn(`physics-elements: the WebAssembly kernel cannot run, using the JS solver: ${module}`);
    }
    return { kernel: null, diagnostics: { kernel: 'js', requested, reason: module } };
  }
  return { kernel: new WasmKernel(module), diagnostics: { kernel: 'wasm', requested, reason: '' } };
}

/** For tests: forget the compiled module (so a test can simulate a platform without it). The default kernel stays. */
export function resetKernelModule(value?: string): void {
  compiled = value;
  warned = false;
}
