import { World, type KernelOptions, type Vec2, createBox, createCloth, createRagdoll, createRope, createSoftBody, type Handle } from '../../src/engine/index.js';
import { resetKernelModule } from '../../src/engine/kernel/choice.js';

/**
 * Kinetic + gravitational potential energy of every movable particle. The velocity of a position-based step is the
 * mean over the last substep, i.e. the velocity half a substep ago, so the potential is taken at the midpoint of
 * that substep too: both terms then describe the same instant.
 */
export function totalEnergy(world: World): number {
  const p = world.particles;
  let e = 0;
  for (let i = 0; i < p.count; i++) {
    if (!p.alive[i] || p.invMass[i] === 0) continue;
    const m = 1 / p.invMass[i];
    e += 0.5 * m * (p.vx[i] ** 2 + p.vy[i] ** 2) - m * (world.gravity.x * (p.x[i] + p.px[i]) + world.gravity.y * (p.y[i] + p.py[i])) / 2;
  }
  return e;
}

/** A box's outline, its centre at the origin: half-width hw, half-height hh. */
export const box = (hw: number, hh: number): Vec2[] => [
  { x: -hw, y: -hh },
  { x: hw, y: -hh },
  { x: hw, y: hh },
  { x: -hw, y: hh },
];

/** Kinetic (linear and angular) + gravitational potential energy of rigid bodies, gravity g along +y. */
export function rigidEnergy(world: World, bodies: Handle[], g: number): number {
  return bodies.reduce((e, h) => {
    const m = world.bodyMassInfo(h);
    const v = world.bodyVelocity(h);
    const w = world.bodyAngularVelocity(h);
    return e + 0.5 * m.mass * (v.x * v.x + v.y * v.y) + 0.5 * m.inertia * w * w - m.mass * g * world.bodyPose(h).y;
  }, 0);
}

export function allFinite(world: World): boolean {
  const p = world.particles;
  for (const col of [p.x, p.y, p.px, p.py, p.vx, p.vy]) {
    for (let i = 0; i < p.count; i++) if (!Number.isFinite(col[i])) return false;
  }
  return true;
}

export function distance(world: World, a: Handle, b: Handle): number {
  const pa = world.getPosition(a);
  const pb = world.getPosition(b);
  return Math.sqrt((pa.x - pb.x) ** 2 + (pa.y - pb.y) ** 2);
}

/** A world with one of everything (cloth, rope, ragdoll, two soft bodies, a box) in bounds, sleeping off; the
 *  default kernel unless `options` names one. */
export function busyWorld(options: KernelOptions = {}): World {
  const world = new World({ gravity: { x: 0.5, y: 10 }, sleeping: false, bounds: { minX: -20, minY: -20, maxX: 20, maxY: 10 }, ...options });
  createCloth(world, { origin: { x: -5, y: -10 }, columns: 12, rows: 10, spacing: 0.4, pins: 'corners', shear: 1e-4, bend: 1e-3 });
  createRope(world, { from: { x: 8, y: -10 }, to: { x: 15, y: -10 }, segments: 20 });
  createRagdoll(world, { x: -12, y: 0 });
  createSoftBody(world, { center: { x: 0, y: 5 }, radius: 1.5 });
  createSoftBody(world, { center: { x: 5, y: 5 }, radius: 1, model: 'springs' });
  createBox(world, { x: 12, y: 5, width: 2, height: 1, angle: 0.4 });
  return world;
}

/** What chooseKernel reports when a page's Content-Security-Policy refuses to compile WebAssembly. */
export const CSP_REFUSAL = "WebAssembly was refused (CompileError); the page's Content-Security-Policy needs script-src 'wasm-unsafe-eval'";

/**
 * Runs `body` as in a page whose policy refuses WebAssembly (resetKernelModule(CSP_REFUSAL): the caller's afterEach
 * resets the module) with console.warn recording into the array `body` gets; console.warn is restored after.
 */
export function withWasmRefused(body: (warnings: string[]) => void): void {
  const warnings: string[] = [];
  const warn = console.warn;
  console.warn = (message: string) => warnings.push(message);
  try {
    resetKernelModule(CSP_REFUSAL);
    body(warnings);
  } finally {
    console.warn = warn;
  }
}
