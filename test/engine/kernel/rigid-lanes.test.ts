// The WebAssembly kernel's rigid contact lanes (wasm-kernel.ts beginRigid, solver.as rigidSweep / rigidVelocities and
// manifoldSweep / manifoldVelocities): a step whose rigid contacts are all single points (disc piles) sweeps them in
// coloured f64x2 packets of two points; a step with two-point manifolds (boxes, polygons on a face) sweeps every
// contact by manifold, two manifolds a packet; a step with restitution, a particle-built outline's edge point or a
// shock sweep runs the JS solver. Laid out one contact (manifold) a packet in list order (rigidSerial) the lanes give
// the JS solver's doubles exactly; coloured, they solve the same contacts in another Gauss–Seidel order, so a pile
// compares by quality (overlap, drift, height, nothing escaped), not by position.
import { expect } from 'chai';
import { buildScene, catalogue, createBox, World, type Handle, type KernelOptions, type SceneName, type WorldOptions } from '../../../src/engine/index.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import type { WasmKernel } from '../../../src/engine/kernel/wasm-kernel.js';
import { allFinite } from '../helpers.js';

function contextOf(world: World): StepContext {
  return (world as unknown as { ctx: StepContext }).ctx;
}

function kernelOf(world: World): WasmKernel {
  const kernel = contextOf(world).kernel;
  if (!kernel) throw new Error('no WebAssembly kernel');
  return kernel;
}

/** The catalogue's S3 pile (2,000 circles r 0.5 into a container), sleeping off. */
function pile(kernel: 'js' | 'wasm'): World {
  const d = catalogue.circles.make();
  const world: WorldOptions & KernelOptions = { ...d.world, sleeping: false, kernel };
  return buildScene({ ...d, world }).world;
}

/** A catalogue scene (sleeping off unless `sleeping`). */
function scene(name: SceneName, kernel: 'js' | 'wasm', sleeping = true): World {
  const d = catalogue[name].make();
  const world: WorldOptions & KernelOptions = { ...d.world, kernel, ...(sleeping ? {} : { sleeping: false }) };
  return buildScene({ ...d, world }).world;
}

/** Deepest rigid contact the narrow phase found this step (its depth at detection). */
function deepestContact(world: World): number {
  const c = contextOf(world).rigidContacts;
  let deepest = 0;
  for (let i = 0; i < c.count; i++) deepest = Math.max(deepest, c.depth[i]);
  return deepest;
}

/** Deepest overlap between two of the pile's discs (radius 0.5), as a fraction of the diameter. */
function deepestOverlap(world: World): number {
  const p = world.particles;
  const cells = new Map<number, number[]>();
  const key = (cx: number, cy: number) => cx * 100003 + cy;
  const discs: number[] = [];
  for (let i = 0; i < p.count; i++) if (p.alive[i] && p.invMass[i] > 0) discs.push(i);
  for (const i of discs) {
    const k = key(Math.floor(p.x[i]), Math.floor(p.y[i]));
    if (!cells.has(k)) cells.set(k, []);
    cells.get(k)!.push(i);
  }
  let deepest = 0;
  for (const i of discs) {
    const cx = Math.floor(p.x[i]);
    const cy = Math.floor(p.y[i]);
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (const j of cells.get(key(cx + dx, cy + dy)) ?? []) {
          if (j <= i) continue;
          deepest = Math.max(deepest, 1 - Math.hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]));
        }
      }
    }
  }
  return deepest;
}

/** Mean height (−y, y grows downwards) of the pile's discs, and how many left the container or are not finite. */
function heightAndEscaped(world: World, halfWidth = 20): { height: number; escaped: number } {
  const p = world.particles;
  let sum = 0;
  let n = 0;
  let escaped = 0;
  for (let i = 0; i < p.count; i++) {
    if (!p.alive[i] || p.invMass[i] === 0) continue;
    n++;
    sum += -p.y[i];
    if (!Number.isFinite(p.x[i]) || !Number.isFinite(p.y[i]) || p.y[i] > 0.01 || Math.abs(p.x[i]) > halfWidth) escaped++;
  }
  return { height: sum / n, escaped };
}

describe('solver kernel: rigid contacts in lanes', () => {
  it('one contact a packet in list order gives the JS solver\'s doubles exactly (S3 pile, 300 steps)', () => {
    const js = pile('js');
    const lanes = pile('wasm');
    kernelOf(lanes).rigidSerial = true;
    for (let k = 0; k < 300; k++) {
      js.step();
      lanes.step();
    }
    // Every step with contacts ran in the lanes (the pile has only single points between discs and walls).
    expect(kernelOf(lanes).rigidLaneSteps).to.be.greaterThan(250);
    expect(kernelOf(lanes).rigidJsSteps).to.equal(0);
    expect(lanes.stateHash()).to.equal(js.stateHash());
  });

  it('coloured, the S3 pile settles as under the JS solver: deepest overlap, height, none escaped (600 steps)', () => {
    const js = pile('js');
    const lanes = pile('wasm');
    for (let k = 0; k < 600; k++) {
      js.step();
      lanes.step();
    }
    expect(kernelOf(lanes).rigidJsSteps).to.equal(0);
    expect(allFinite(lanes)).to.equal(true);
    const [oJs, oLanes] = [deepestOverlap(js), deepestOverlap(lanes)];
    const [hJs, hLanes] = [heightAndEscaped(js), heightAndEscaped(lanes)];
    // Measured: deepest overlap 2.9% (JS) and 2.6% (lanes) of a diameter; mean heights within 0.1%.
    expect(oLanes, `deepest overlap, lanes (JS ${oJs})`).to.be.lessThan(Math.max(0.05, 1.5 * oJs));
    expect(Math.abs(hLanes.height - hJs.height) / hJs.height, `mean height ${hLanes.height} vs ${hJs.height}`).to.be.lessThan(0.02);
    expect(hLanes.escaped).to.equal(0);
    expect(hJs.escaped).to.equal(0);
  });

  it('a step where a disc with friction turns faster than FAST_TURN is the JS solver\'s (exact arcs), the same doubles; slower, the lanes take it again', () => {
    const make = (kernel: 'js' | 'wasm') => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel } as WorldOptions & KernelOptions);
      world.addRigidBody({ x: 0, y: 1, points: [{ x: -60, y: -0.5 }, { x: 60, y: -0.5 }, { x: 60, y: 0.5 }, { x: -60, y: 0.5 }], type: 'static' });
      // A marble of radius 0.1 rolling at 15 units/s: 2.5 rad a step.
      const marble = world.addRigidBody({ x: -50, y: 0.4, radius: 0.1, vx: 15, angularVelocity: 150, friction: 0.6 });
      world.addRigidBody({ x: 40, y: 0, radius: 0.5, friction: 0.6 });
      return { world, marble };
    };
    const js = make('js');
    const lanes = make('wasm');
    kernelOf(lanes.world).rigidSerial = true;
    for (let k = 0; k < 60; k++) {
      js.world.step();
      lanes.world.step();
    }
    expect(kernelOf(lanes.world).rigidJsSteps).to.equal(60);
    expect(kernelOf(lanes.world).rigidLaneSteps).to.equal(0);
    expect(lanes.world.stateHash()).to.equal(js.world.stateHash());
    // 0.7 rad a step: the lanes' series holds.
    for (const { world, marble } of [js, lanes]) {
      world.setBodyVelocity(marble, 4.2, 0);
      world.setBodyAngularVelocity(marble, 42);
    }
    for (let k = 0; k < 60; k++) {
      js.world.step();
      lanes.world.step();
    }
    expect(kernelOf(lanes.world).rigidLaneSteps).to.be.greaterThan(50);
    expect(lanes.world.stateHash()).to.equal(js.world.stateHash());
  });

  it('contacts that grow mid-run (discs added) lay out again, still the JS doubles one contact a packet', () => {
    const make = (kernel: 'js' | 'wasm') => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel } as WorldOptions);
      world.addRigidBody({ x: 0, y: 1, points: [{ x: -20, y: -0.5 }, { x: 20, y: -0.5 }, { x: 20, y: 0.5 }, { x: -20, y: 0.5 }], type: 'static' });
      return world;
    };
    const js = make('js');
    const lanes = make('wasm');
    kernelOf(lanes).rigidSerial = true;
    for (let wave = 0; wave < 6; wave++) {
      for (const world of [js, lanes]) {
        for (let k = 0; k < 40 * (wave + 1); k++) world.addRigidBody({ x: -15 + (k % 30) * 1.01 + (wave % 2) * 0.3, y: -2 - Math.floor(k / 30) * 1.05, radius: 0.5, friction: 0.4 });
      }
      for (let k = 0; k < 30; k++) {
        js.step();
        lanes.step();
      }
      expect(lanes.stateHash(), `wave ${wave}`).to.equal(js.stateHash());
    }
    expect(kernelOf(lanes).rigidLaneSteps).to.be.greaterThan(100);
  });

  it('one manifold a packet in list order gives the JS solver\'s doubles exactly (pyramid, boxes, stack: 300 steps)', () => {
    for (const name of ['pyramid', 'boxes', 'stack'] as const) {
      const js = scene(name, 'js');
      const lanes = scene(name, 'wasm');
      kernelOf(lanes).rigidSerial = true;
      for (let k = 0; k < 300; k++) {
        js.step();
        lanes.step();
      }
      // Every step with contacts ran in the lanes, laid out by manifold (boxes lie on faces: two-point manifolds).
      expect(kernelOf(lanes).manifoldSteps, name).to.be.greaterThan(30);
      expect(kernelOf(lanes).rigidJsSteps, name).to.equal(0);
      expect(lanes.stateHash(), name).to.equal(js.stateHash());
    }
  });

  it('discs, then boxes and triangles together (lone points beside manifolds), then discs among them, added in waves: still the JS doubles one manifold a packet', () => {
    const make = (kernel: 'js' | 'wasm') => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel } as WorldOptions);
      world.addRigidBody({ x: 0, y: 1, points: [{ x: -12, y: -0.5 }, { x: 12, y: -0.5 }, { x: 12, y: 0.5 }, { x: -12, y: 0.5 }], type: 'static' });
      // A kinematic paddle turning in the pile: contacts with a body that moves but is not moved.
      const paddle = world.addRigidBody({ x: 6, y: -1.5, points: [{ x: -1.5, y: -0.2 }, { x: 1.5, y: -0.2 }, { x: 1.5, y: 0.2 }, { x: -1.5, y: 0.2 }], type: 'kinematic' });
      world.setBodyAngularVelocity(paddle, 1);
      return world;
    };
    const js = make('js');
    const lanes = make('wasm');
    kernelOf(lanes).rigidSerial = true;
    const square = [{ x: -0.4, y: -0.4 }, { x: 0.4, y: -0.4 }, { x: 0.4, y: 0.4 }, { x: -0.4, y: 0.4 }];
    const triangle = [{ x: -0.45, y: 0.3 }, { x: 0.45, y: 0.3 }, { x: 0, y: -0.45 }];
    let jsSteps = 0;
    const discs: Handle[][] = [[], []];
    for (let wave = 0; wave < 6; wave++) {
      // The first wave's discs leave before the boxes come (discs among manifolds are the JS solver's, below).
      if (wave === 1) [js, lanes].forEach((world, w) => discs[w].forEach((h) => world.removeBody(h)));
      for (const [w, world] of [js, lanes].entries()) {
        for (let k = 0; k < 24; k++) {
          const x = -10 + (k % 12) * 1.7 + (wave % 2) * 0.4;
          const y = -3 - Math.floor(k / 12) * 1.3;
          // The first wave discs only (single-point packets), then boxes and triangles (laid out by manifold: the
          // packets grow); the last wave adds discs among them, which the manifold lanes leave to the JS solver (their
          // sweep has no rim arcs: wasm-kernel.ts lanesFit).
          if (wave === 0) discs[w].push(world.addRigidBody({ x, y, radius: 0.45, friction: 0.5 }));
          else if (wave === 5 && k % 3 === 0) world.addRigidBody({ x, y, radius: 0.45, friction: 0.5 });
          else if ((k + wave) % 3 === 0) world.addRigidBody({ x, y, points: triangle, angle: 0.3 * k, friction: 0.5 });
          else world.addRigidBody({ x, y, points: square, angle: 0.05 * k, friction: 0.6 });
        }
      }
      if (wave === 5) jsSteps = kernelOf(lanes).rigidJsSteps;
      for (let k = 0; k < 40; k++) {
        js.step();
        lanes.step();
      }
      expect(lanes.stateHash(), `wave ${wave}`).to.equal(js.stateHash());
      if (wave === 4) expect(kernelOf(lanes).rigidJsSteps, 'no step left to JS before the discs join the boxes').to.equal(0);
    }
    expect(kernelOf(lanes).manifoldSteps).to.be.greaterThan(100);
    expect(kernelOf(lanes).rigidLaneSteps - kernelOf(lanes).manifoldSteps, 'single-point steps').to.be.greaterThan(10);
    expect(kernelOf(lanes).rigidJsSteps - jsSteps, 'discs among manifolds: the JS solver').to.equal(40);
  });

  it('the step\'s end hands the JS phases what they read: touched, and a touched point\'s slip and allowance, as the JS solver leaves them (S3 pile, boxes)', () => {
    // endRigid copies back only these (the anchors, events and sleep read them; nothing reads λn, the impulses or gap
    // after the solver). One contact (manifold) a packet in list order, so the values are the JS solver's doubles.
    for (const name of ['circles', 'boxes'] as const) {
      const js = scene(name, 'js', false);
      const lanes = scene(name, 'wasm', false);
      kernelOf(lanes).rigidSerial = true;
      let touchedPoints = 0;
      let slipping = 0;
      for (let k = 0; k < 200; k++) {
        js.step();
        lanes.step();
        if (k % 20 !== 19) continue;
        const [a, b] = [contextOf(js).rigidContacts, contextOf(lanes).rigidContacts];
        expect(b.count, `${name} step ${k + 1}`).to.equal(a.count);
        for (let i = 0; i < a.count; i++) {
          expect(b.touched[i], `${name} step ${k + 1} point ${i}: touched`).to.equal(a.touched[i]);
          if (!a.touched[i]) continue;
          touchedPoints++;
          if (a.slip[i] !== 0) slipping++;
          expect(b.slip[i], `${name} step ${k + 1} point ${i}: slip`).to.equal(a.slip[i]);
          expect(b.allowance[i], `${name} step ${k + 1} point ${i}: allowance`).to.equal(a.allowance[i]);
        }
      }
      expect(kernelOf(lanes).rigidJsSteps, name).to.equal(0);
      // Enough of each to compare: thousands of touched points, some of them sliding.
      expect(touchedPoints, name).to.be.greaterThan(2000);
      expect(slipping, name).to.be.greaterThan(10);
    }
  });

  it('coloured, the base-20 pyramid stands for 10 s (top drift < 0.05 box) and a 20-box stack stays up', () => {
    const make = (kernel: 'js' | 'wasm') => {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 10 }, kernel } as WorldOptions);
      world.addRigidBody({ points: [{ x: -40, y: -0.5 }, { x: 40, y: -0.5 }, { x: 40, y: 0.5 }, { x: -40, y: 0.5 }], x: 0, y: 0.5, type: 'static' });
      const square = [{ x: -0.5, y: -0.5 }, { x: 0.5, y: -0.5 }, { x: 0.5, y: 0.5 }, { x: -0.5, y: 0.5 }];
      const stack = Array.from({ length: 20 }, (_, k) => world.addRigidBody({ points: square, x: -30, y: -(0.5 + k) }));
      const boxes = [];
      for (let row = 0; row < 20; row++) for (let k = 0; k < 20 - row; k++) boxes.push(world.addRigidBody({ points: square, x: k - (20 - row - 1) / 2, y: -(0.5 + row) }));
      return { world, stackTop: stack[19], top: boxes[boxes.length - 1] };
    };
    for (const kernel of ['wasm', 'js'] as const) {
      const { world, stackTop, top } = make(kernel);
      const t0 = world.bodyPose(top);
      for (let k = 0; k < 600; k++) world.step();
      if (kernel === 'wasm') {
        expect(kernelOf(world).manifoldSteps).to.equal(600);
        expect(kernelOf(world).rigidJsSteps).to.equal(0);
      }
      const s = world.bodyPose(stackTop);
      const p = world.bodyPose(top);
      // Measured: top drift 0.0085 both (sideways 4.8e-4 lanes, -8.3e-4 JS), stack top 0.015 both.
      expect(Math.hypot(s.x + 30, s.y + 19.5), `${kernel}: stack top`).to.be.lessThan(0.05);
      expect(Math.hypot(p.x - t0.x, p.y - t0.y), `${kernel}: pyramid top`).to.be.lessThan(0.05);
      expect(Math.abs(p.angle), kernel).to.be.lessThan(0.01);
    }
  });

  it('coloured, the S2 pile of 1,000 boxes settles as under the JS solver: deepest contact, height, none escaped (600 steps)', () => {
    const js = scene('boxes', 'js', false);
    const lanes = scene('boxes', 'wasm', false);
    let [deepJs, deepLanes] = [0, 0];
    for (let k = 0; k < 600; k++) {
      js.step();
      lanes.step();
      if (k >= 300) [deepJs, deepLanes] = [Math.max(deepJs, deepestContact(js)), Math.max(deepLanes, deepestContact(lanes))];
    }
    expect(kernelOf(lanes).rigidJsSteps).to.equal(0);
    expect(allFinite(lanes)).to.equal(true);
    const [hJs, hLanes] = [heightAndEscaped(js, 16), heightAndEscaped(lanes, 16)];
    // Measured: deepest contact over steps 300-600 JS 0.028, lanes 0.020 (of a unit box); mean heights 19.97 both.
    expect(deepLanes, `deepest contact, lanes (JS ${deepJs})`).to.be.lessThan(Math.max(0.05, 1.5 * deepJs));
    expect(Math.abs(hLanes.height - hJs.height) / hJs.height, `mean height ${hLanes.height} vs ${hJs.height}`).to.be.lessThan(0.02);
    expect(hLanes.escaped).to.equal(0);
    expect(hJs.escaped).to.equal(0);
  });

  it('steps with other contacts (bouncy discs and boxes: restitution) run the JS solver, bit for bit', () => {
    const bouncy = (kernel: 'js' | 'wasm') => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel } as WorldOptions);
      world.addRigidBody({ x: 0, y: 1, points: [{ x: -5, y: -0.5 }, { x: 5, y: -0.5 }, { x: 5, y: 0.5 }, { x: -5, y: 0.5 }], type: 'static' });
      for (let k = 0; k < 5; k++) world.addRigidBody({ x: -3 + k * 1.5, y: -3, radius: 0.5, restitution: 0.6 });
      for (let k = 0; k < 3; k++) world.addRigidBody({ x: -3 + k * 3, y: -6, points: [{ x: -0.5, y: -0.5 }, { x: 0.5, y: -0.5 }, { x: 0.5, y: 0.5 }, { x: -0.5, y: 0.5 }], restitution: 0.4 });
      return world;
    };
    const js = bouncy('js');
    const lanes = bouncy('wasm');
    for (let k = 0; k < 120; k++) {
      js.step();
      lanes.step();
    }
    expect(kernelOf(lanes).rigidLaneSteps).to.equal(0);
    expect(kernelOf(lanes).rigidJsSteps).to.be.greaterThan(20);
    expect(lanes.stateHash()).to.equal(js.stateHash());
  });

  it('a static rigid wall holds a light disc against a rigid hammer of 1-500× its mass at 100-500 units/s (the wall sweeps last)', () => {
    // wall-squeeze.test.ts's case under the lanes: contacts with a static body are coloured after the others.
    const r = 1.5;
    let laneSteps = 0;
    for (const ratio of [1, 3, 10, 30, 100, 500]) {
      for (const speed of [100, 250, 500]) {
        for (const gap of [0.5, 1.1, 2.5]) {
          const world = new World({ gravity: { x: 0, y: 0 }, bounds: { minX: -50, minY: -20, maxX: 40, maxY: 20 }, sleeping: false, kernel: 'wasm' } as WorldOptions);
          world.addRigidBody({ x: -0.5, y: 0, points: [{ x: -0.5, y: -10 }, { x: 0.5, y: -10 }, { x: 0.5, y: 10 }, { x: -0.5, y: 10 }], type: 'static' });
          const disc = world.addRigidBody({ x: r + gap, y: 0, radius: r, mass: 0.06 });
          // A round hammer: disc against disc and disc against wall are single points, so the lanes take every step.
          const hammer = world.addRigidBody({ x: r + gap + r + 2.5, y: 0, radius: 0.5, mass: 0.06 * ratio });
          world.applyBodyImpulse(hammer, -speed * 0.06 * ratio, 0);
          let deepest = Infinity;
          for (let k = 0; k < 60; k++) {
            world.step();
            deepest = Math.min(deepest, world.bodyPose(disc).x - r);
          }
          laneSteps += kernelOf(world).rigidLaneSteps;
          // Heavier hammers (30-500×) start the shock sweep (a stack of levels) at the hit: that step is the JS solver's.
          if (ratio < 30) expect(kernelOf(world).rigidJsSteps, `ratio ${ratio}, ${speed} u/s, gap ${gap}`).to.equal(0);
          expect(world.bodyPose(disc).x, `ratio ${ratio}, ${speed} u/s, gap ${gap}: ends on the near side`).to.be.greaterThan(r - 0.01);
          expect(deepest, `ratio ${ratio}, ${speed} u/s, gap ${gap}`).to.be.greaterThan(-0.01);
        }
      }
    }
    expect(laneSteps).to.be.greaterThan(27 * 20);
  });

  it('a box hammer (manifold pairs; 500× the disc: a shock sweep at the hit) and the wall still holds', () => {
    const r = 1.5;
    const world = new World({ gravity: { x: 0, y: 0 }, bounds: { minX: -50, minY: -20, maxX: 40, maxY: 20 }, sleeping: false, kernel: 'wasm' } as WorldOptions);
    world.addRigidBody({ x: -0.5, y: 0, points: [{ x: -0.5, y: -10 }, { x: 0.5, y: -10 }, { x: 0.5, y: 10 }, { x: -0.5, y: 10 }], type: 'static' });
    const disc = world.addRigidBody({ x: r + 0.5, y: 0, radius: r, mass: 0.06 });
    const hammer = createBox(world, { x: r + 0.5 + r + 2.5, y: 0, width: 1, height: 1, model: 'rigid', mass: 30 });
    world.applyBodyImpulse(hammer.body, -500 * 30, 0);
    let deepest = Infinity;
    for (let k = 0; k < 60; k++) {
      world.step();
      deepest = Math.min(deepest, world.bodyPose(disc).x - r);
    }
    expect(deepest).to.be.greaterThan(-0.01);
  });
});
