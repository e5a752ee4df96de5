// The run-time parameters (HostParams) and the scene's world options: what a fresh world is made with (load, reset)
// and what a live setParams() changes in the current one.
import { KERNELS, defaultKernel, type KernelOptions, type World, type WorldOptions } from '../../engine/index.js';
import { oneOf } from '../../engine/validate.js';
import type { HostError, HostParams } from '../protocol.js';

const DEFAULT_PARAMS: HostParams = {
  gravity: { x: 0, y: 9.81 },
  timestep: 1 / 60,
  substeps: 'auto',
  iterations: 1,
  broadphase: 'grid',
  narrowphase: 'sat',
  debug: false,
  events: false,
  bounds: null,
  kernel: 'js',
};

export function copyParams(p: HostParams): HostParams {
  return { ...p, gravity: { ...p.gravity } };
}

export class HostSettings {
  /** The defaults; the kernel is the engine's default kernel in this realm when the host is made (setDefaultKernel). */
  params = copyParams({ ...DEFAULT_PARAMS, kernel: defaultKernel() });
  /** The scene's world options (HostScene.world), under the params. */
  worldOptions: WorldOptions = {};

  /** The options a fresh world is made with. */
  forWorld(): WorldOptions & KernelOptions {
    const p = this.params;
    return {
      ...this.worldOptions,
      gravity: { ...p.gravity },
      timestep: p.timestep,
      substeps: p.substeps,
      iterations: p.iterations,
      broadphase: p.broadphase,
      narrowphase: p.narrowphase,
      kernel: p.kernel,
    };
  }

  /** The world was made with another kernel than the params ask for (a fresh world would have the right one). */
  kernelDiffers(w: World): boolean {
    return w.diagnostics().requested !== this.params.kernel;
  }

  /** Applies to the params and the world what validates; returns one error per rejected field. */
  apply(w: World, params: Partial<HostParams>): HostError[] {
    const errors: HostError[] = [];
    const set = (field: keyof HostParams, apply: () => void) => {
      if (params[field] === undefined) return;
      try {
        apply();
      } catch (error) {
        errors.push({ key: -1, field, message: error instanceof Error ? error.message : String(error) });
      }
    };
    set('gravity', () => {
      w.setGravity(params.gravity!.x, params.gravity!.y);
      this.params.gravity = { x: params.gravity!.x, y: params.gravity!.y };
    });
    set('bounds', () => {
      const b = params.bounds;
      if (b && ![b.minX, b.minY, b.maxX, b.maxY].every(Number.isFinite)) throw new RangeError(`bounds must be finite numbers, got ${JSON.stringify(b)}`);
      w.bounds = b ? { minX: b.minX, minY: b.minY, maxX: b.maxX, maxY: b.maxY } : null;
      this.params.bounds = w.bounds && { ...w.bounds };
      // A rebuild (reset) makes its world from the scene's options: keep the new walls there too.
      this.worldOptions = { ...this.worldOptions, bounds: w.bounds && { ...w.bounds } };
    });
    // The world's own setters validate these.
    const copy = <K extends 'timestep' | 'substeps' | 'iterations' | 'broadphase' | 'narrowphase'>(field: K) =>
      set(field, () => {
        (w as Pick<World, K>)[field] = params[field] as unknown as World[K];
        (this.params as Pick<HostParams, K>)[field] = params[field]!;
      });
    copy('timestep');
    copy('substeps');
    copy('iterations');
    copy('broadphase');
    copy('narrowphase');
    // Set at construction only: the host remakes the world when it differs (kernelDiffers).
    set('kernel', () => {
      this.params.kernel = oneOf('kernel', params.kernel, KERNELS);
    });
    if (params.debug !== undefined) this.params.debug = Boolean(params.debug);
    if (params.events !== undefined) this.params.events = Boolean(params.events);
    return errors;
  }
}
