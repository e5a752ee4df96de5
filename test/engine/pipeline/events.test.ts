// A begin event's depth (src/engine/pipeline/events.ts): the overlap of the pair's deepest contact when it was found,
// for every kind of contact. Bodies are put down already overlapping by a known amount, in a world without gravity
// and at rest, after the events were first read (so the overlap is new, not taken as already touching), and stepped
// once: the depth is then the geometric overlap, worked out here from the shapes (or, for rings of particles, by
// brute force over every pair of particles).
import { expect } from 'chai';
import { World, WORLD_BOUNDS, createBox, createCircle, createSoftBody, type Handle } from '../../../src/engine/index.js';

const KERNELS = ['js', 'wasm'] as const;
const MODELS = ['rigid', 'particles'] as const;
/** The bounds of the wall tests: the floor at y = 10, the left wall at x = −10. */
const BOUNDS = { minX: -10, minY: -10, maxX: 10, maxY: 10 };

/** A world at rest without gravity that already collects events (read once, with nothing in it). */
function quietWorld(kernel: (typeof KERNELS)[number], bounds: typeof BOUNDS | null = null): World {
  const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds });
  expect(world.events.count).to.equal(0);
  return world;
}

/** The one begin event of the next step: [body a, body b, depth]. */
function onlyBegin(world: World): [number, number, number] {
  world.step();
  const e = world.events;
  const begins: [number, number, number][] = [];
  for (let i = 0; i < e.count; i++) if (e.type[i] === 0) begins.push([e.bodyA[i], e.bodyB[i], e.depth[i]]);
  expect(begins.length, JSON.stringify(begins)).to.equal(1);
  return begins[0];
}

/** The pair's two bodies, in either order. */
function expectPair(begin: [number, number, number], a: Handle, b: Handle): void {
  expect([begin[0], begin[1]].sort()).to.deep.equal([a, b].sort());
}

// A unit box turned by θ (|θ| small) reaches sideways ½(cos θ + sin |θ|) from its centre at one corner of a side and
// ½(cos θ − sin |θ|) at the other.
const far = (theta: number) => 0.5 * (Math.cos(theta) + Math.sin(Math.abs(theta)));
const near = (theta: number) => 0.5 * (Math.cos(theta) - Math.sin(Math.abs(theta)));

describe('collision events: a begin event\'s depth is the overlap found', () => {
  for (const kernel of KERNELS)
    for (const ma of MODELS)
      for (const mb of MODELS)
        it(`two unit boxes (${ma}, ${mb}; ${kernel}): the deepest corner's overlap, whichever corner is first`, () => {
          for (const theta of [0.1, -0.1]) {
            // B's centre 0.9 right of A's, turned: both its left corners inside A, 0.147 and 0.048 deep.
            const world = quietWorld(kernel);
            const a = createBox(world, { x: 0, y: 0, width: 1, height: 1, model: ma }).body;
            const b = createBox(world, { x: 0.9, y: 0, width: 1, height: 1, angle: theta, model: mb }).body;
            const begin = onlyBegin(world);
            expectPair(begin, a, b);
            expect(near(theta) - 0.4, 'the shallower corner overlaps too').to.be.greaterThan(0.04);
            expect(begin[2], `θ = ${theta}`).to.be.closeTo(far(theta) - 0.4, 1e-9);
          }
          // B 0.95 right, turned 0.1: one corner in, 0.097 deep (the other 0.002 short).
          const world = quietWorld(kernel);
          const a = createBox(world, { x: 0, y: 0, width: 1, height: 1, model: ma }).body;
          const b = createBox(world, { x: 0.95, y: 0, width: 1, height: 1, angle: 0.1, model: mb }).body;
          const begin = onlyBegin(world);
          expectPair(begin, a, b);
          expect(begin[2]).to.be.closeTo(far(0.1) - 0.45, 1e-9);
        });

  for (const kernel of KERNELS)
    it(`two rigid discs (${kernel}): the sum of the radii less the distance of the centres`, () => {
      for (const [r1, r2, d] of [[0.5, 0.5, 0.9], [0.3, 0.7, 0.75], [1, 0.25, 1.2]]) {
        const world = quietWorld(kernel);
        const a = createCircle(world, { x: 0, y: 0, radius: r1 }).body;
        const b = createCircle(world, { x: d * 0.6, y: d * 0.8, radius: r2 }).body;
        const begin = onlyBegin(world);
        expectPair(begin, a, b);
        expect(begin[2], `${r1} + ${r2} − ${d}`).to.be.closeTo(r1 + r2 - d, 1e-9);
      }
    });

  /** The deepest overlap of any particle of ring a with any of ring b (each a disc of its radius): brute force. */
  function ringOverlap(world: World, a: Handle, b: Handle): number {
    const p = world.particles;
    let deepest = -Infinity;
    for (const i of world.bodyParticleIndices(a))
      for (const j of world.bodyParticleIndices(b)) deepest = Math.max(deepest, p.radius[i] + p.radius[j] - Math.hypot(p.x[i] - p.x[j], p.y[i] - p.y[j]));
    return deepest;
  }

  for (const kernel of KERNELS)
    it(`two soft rings, particles against particles (${kernel}): the deepest overlap of two of their particles`, () => {
      for (const [gap, turn] of [[1.9, 0], [1.7, 0.1], [1.85, 0.3]]) {
        const world = quietWorld(kernel);
        const a = createSoftBody(world, { center: { x: 0, y: 0 }, radius: 1, segments: 16 }).body;
        const b = createSoftBody(world, { center: { x: gap * Math.cos(turn), y: gap * Math.sin(turn) }, radius: 1, segments: 16 }).body;
        const expected = ringOverlap(world, a, b);
        const begin = onlyBegin(world);
        expectPair(begin, a, b);
        // (1.9 apart: the particles at ±22.5° meet 0.338 deep; the ones facing each other only 0.290.)
        expect(begin[2], `${gap} apart`).to.be.closeTo(expected, 1e-9);
      }
    });

  for (const kernel of KERNELS)
    it(`a soft ring's particles in a box (${kernel}): the deepest particle's radius past the box's side`, () => {
      for (const model of MODELS) {
        // A ring of radius 1 (particles of radius sin(π/16) = 0.195) whose rightmost particle is 0.1 inside the box's
        // left side, plus its radius: 0.295 deep.
        const world = quietWorld(kernel);
        const box = createBox(world, { x: 1.5, y: 0, width: 1, height: 1, model }).body;
        const ring = createSoftBody(world, { center: { x: 0.1, y: 0 }, radius: 1, segments: 16 }).body;
        const begin = onlyBegin(world);
        expectPair(begin, box, ring);
        expect(begin[2], model).to.be.closeTo(0.1 + Math.sin(Math.PI / 16), 1e-9);
      }
    });

  for (const kernel of KERNELS)
    for (const model of MODELS)
      it(`a body sunk into the world's bounds (${model}; ${kernel}): how far its deepest point is past the wall`, () => {
        // A level unit box 0.1 into the floor (y = 10) and into the left wall (x = −10).
        for (const [x, y] of [[0, 9.6], [-9.6, 0]]) {
          const world = quietWorld(kernel, BOUNDS);
          const box = createBox(world, { x, y, width: 1, height: 1, model }).body;
          const begin = onlyBegin(world);
          expect([begin[0], begin[1]]).to.deep.equal([box, WORLD_BOUNDS]);
          expect(begin[2], `at (${x}, ${y})`).to.be.closeTo(0.1, 1e-9);
        }
        // Turned 0.1 and 0.45 above the floor: one corner in, 0.097 deep.
        const world = quietWorld(kernel, BOUNDS);
        const box = createBox(world, { x: 0, y: 9.55, width: 1, height: 1, angle: 0.1, model }).body;
        const begin = onlyBegin(world);
        expect([begin[0], begin[1]]).to.deep.equal([box, WORLD_BOUNDS]);
        expect(begin[2]).to.be.closeTo(far(0.1) - 0.45, 1e-9);
        // Turned ±0.1 and 0.4 above the floor: both bottom corners in, the deeper 0.147, whichever of them comes
        // first among the body's particles.
        for (const theta of [0.1, -0.1]) {
          const w = quietWorld(kernel, BOUNDS);
          const b = createBox(w, { x: 0, y: 9.6, width: 1, height: 1, angle: theta, model }).body;
          const e = onlyBegin(w);
          expect([e[0], e[1]]).to.deep.equal([b, WORLD_BOUNDS]);
          expect(e[2], `θ = ${theta}`).to.be.closeTo(far(theta) - 0.4, 1e-9);
        }
        // A rigid disc or a particle ring: its lowest point past the floor.
        const discs = quietWorld(kernel, BOUNDS);
        const disc = (model === 'rigid' ? createCircle(discs, { x: 0, y: 9.35, radius: 0.75 }) : createSoftBody(discs, { center: { x: 0, y: 9.35 }, radius: 0.75, segments: 16 })).body;
        const landed = onlyBegin(discs);
        expect([landed[0], landed[1]]).to.deep.equal([disc, WORLD_BOUNDS]);
        // The ring's lowest particle sits at the radius (0.75 below the centre) and reaches its own radius further.
        const reach = model === 'rigid' ? 0.75 : 0.75 + 0.75 * Math.sin(Math.PI / 16);
        expect(landed[2]).to.be.closeTo(9.35 + reach - 10, 1e-9);
      });
});
