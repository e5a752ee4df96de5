// Spinning bodies under the rigid contact lanes (kernel 'wasm', one contact a packet in list order: rigidSerial, which
// gives the JS solver's doubles): every case of a rigid body's angular integration (rows.ts integrateRotation and
// updateAngularVelocity) keeps the JS doubles bit for bit: a turn under 1e-3 a substep (the rotation's series), a larger
// one (Math.cos/Math.sin), the MAX_TURN clamp, torque, damping, and a kinematic row (inverse inertia 0: ω undamped).
// Whatever part of the integration the kernel does while the lanes hold a step's contacts (positions and velocities
// since f08da2b; the angles measured there, docs/engine.md) must pass it: it compares the body columns after every
// step, so any bit the kernel computes differently fails it (checked with the angles in the kernel: a changed series
// threshold, torque term order, ω rounding or clamp each fails within the first 66 steps).
import { expect } from 'chai';
import { World, type Handle, type KernelOptions, type WorldOptions } from '../../../src/engine/index.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import type { WasmKernel } from '../../../src/engine/kernel/wasm-kernel.js';

const COLUMNS = ['x', 'y', 'vx', 'vy', 'angle', 'pangle', 'omega', 'rc', 'rs', 'qangle'] as const;
/** Substep length: 1/60 s in 4 substeps. */
const H = 1 / 240;

function contextOf(world: World): StepContext {
  return (world as unknown as { ctx: StepContext }).ctx;
}

/**
 * A floor and two walls, and 60 discs: a row resting on the floor (contacts from the first step, so the lanes run
 * from it) and more above, spun slowly (ω·h under 1e-3), fast (0.125 rad a substep: cos/sin) or far too fast for the
 * clamp (500 rad/s: 2 rad a substep), a kinematic disc turning among them; damping 0.5.
 */
function spinningPile(kernel: 'js' | 'wasm'): { world: World; discs: Handle[] } {
  const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, substeps: 4, damping: 0.5, kernel } as WorldOptions & KernelOptions);
  world.addRigidBody({ x: 0, y: 1, points: [{ x: -8, y: -0.5 }, { x: 8, y: -0.5 }, { x: 8, y: 0.5 }, { x: -8, y: 0.5 }], type: 'static' });
  for (const side of [-1, 1]) world.addRigidBody({ x: side * 7.5, y: -5, points: [{ x: -0.5, y: -6 }, { x: 0.5, y: -6 }, { x: 0.5, y: 6 }, { x: -0.5, y: 6 }], type: 'static' });
  const spins = [0.05, 30, -0.2, 500, -30, 0.1];
  const discs: Handle[] = [];
  for (let k = 0; k < 60; k++) {
    const row = Math.floor(k / 12);
    // The discs spun or torqued past FAST_TURN a step are frictionless: a round side with friction turning that fast
    // makes its step's arcs exact (contacts.ts arcBeyond), which the lanes leave to the JS solver.
    const fast = spins[k % 6] === 500 || k === 4 || k % 7 === 3;
    discs[k] = world.addRigidBody({ x: -6 + (k % 12) * 1.05 + (row % 2) * 0.3, y: -row * 1.1, radius: 0.5, friction: fast ? 0 : 0.5, angle: 0.1 * k, angularVelocity: spins[k % 6] });
  }
  world.addRigidBody({ x: 0, y: -7, radius: 0.5, type: 'kinematic', angularVelocity: 3 });
  return { world, discs };
}

/** Rows and column of the first bit that differs between the two worlds' body columns, or null. */
function firstDifference(a: World, b: World): string | null {
  const pa = a.particles;
  const pb = b.particles;
  for (const name of COLUMNS) {
    const bitsA = new BigInt64Array(pa[name].buffer, pa[name].byteOffset, pa.count);
    const bitsB = new BigInt64Array(pb[name].buffer, pb[name].byteOffset, pb.count);
    for (let i = 0; i < pa.count; i++) if (bitsA[i] !== bitsB[i]) return `${name}[${i}]: ${pa[name][i]} (js) vs ${pb[name][i]} (wasm)`;
  }
  return null;
}

describe('solver kernel: spinning bodies while the rigid lanes hold the contacts', () => {
  it('gives rows.ts integrateRotation\'s and updateAngularVelocity\'s doubles bit for bit: series, cos/sin, clamp, torque, damping, kinematic (200 steps)', () => {
    const { world: js, discs } = spinningPile('js');
    const { world: wasm } = spinningPile('wasm');
    const kernel = contextOf(wasm).kernel as WasmKernel;
    kernel.rigidSerial = true;
    let series = 0;
    let far = 0;
    for (let step = 0; step < 200; step++) {
      // Torques of both signs and many magnitudes on some discs (discs 3, 10, 17, …), and one far beyond the clamp
      // on disc 4 (ω·h would grow by about 170 rad a substep): the clamp acts in every substep, the kernel's too.
      for (const world of [js, wasm]) {
        for (let k = 3; k < discs.length; k += 7) world.applyBodyTorque(discs[k], Math.sin(step * 0.7 + k) * (11.3 + step * 0.37));
        world.applyBodyTorque(discs[4], step % 2 ? 4e6 : -4e6);
      }
      js.step();
      wasm.step();
      expect(firstDifference(js, wasm), `step ${step + 1}`).to.equal(null);
      const p = js.particles;
      const rows = contextOf(js).rigidRows;
      for (let k = 0; k < contextOf(js).rigidCount; k++) {
        const turn = Math.abs(p.omega[rows[k]]) * H;
        if (turn > 0 && turn < 1e-3) series++;
        else if (turn >= 1e-3) far++;
      }
      // The torqued disc turned about MAX_TURN (0.5 rad) a substep, give or take what its contacts turned it (about
      // 170 rad unclamped).
      const fastest = Math.max(...Array.from(p.omega.subarray(0, p.count), Math.abs)) * H;
      expect(fastest, `step ${step + 1}`).to.be.within(0.3, 0.6);
    }
    // Every step had contacts and swept them in the lanes (the kernel integrated from each step's second substep on);
    // both cases of the turn occurred many times.
    expect(kernel.rigidLaneSteps).to.equal(200);
    expect(kernel.rigidJsSteps).to.equal(0);
    expect(series, 'rows turning under 1e-3 a substep').to.be.greaterThan(500);
    expect(far, 'rows turning further').to.be.greaterThan(500);
  });
});
