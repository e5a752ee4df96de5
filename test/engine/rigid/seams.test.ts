// Seams between static polygons (rigid/seams.ts): a face is internal exactly when other static parts cover it along
// its whole length from the other side. Checked against a brute-force oracle (points just outside the face, sampled
// along it, each inside some other static part) on random tilings, turned and moved, with flush tiles, bricks whose
// joints are covered by two neighbours, tiles one step taller and tiles a hair apart; and found again when a static
// body moves.
import { expect } from 'chai';
import { World, type Handle, type Vec2 } from '../../../src/engine/index.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import { rng } from '../collision/helpers.js';

const contextOf = (world: World): StepContext => (world as unknown as { ctx: StepContext }).ctx;

const rect = (w: number, h: number): Vec2[] => [
  { x: -w / 2, y: -h / 2 },
  { x: w / 2, y: -h / 2 },
  { x: w / 2, y: h / 2 },
  { x: -w / 2, y: h / 2 },
];

interface Face {
  part: number;
  vertex: number;
}

/** Every face of every static part, with its world vertices, after one step. */
function staticFaces(world: World): { faces: Face[]; ctx: StepContext } {
  world.step();
  const ctx = contextOf(world);
  const s = ctx.rigidShapes;
  const faces: Face[] = [];
  for (let q = 0; q < s.polygonCount; q++) {
    const slot = s.polygons[q];
    for (let p = s.partStart[slot]; p < s.partStart[slot] + s.partCount[slot]; p++) {
      for (let v = s.partVertexStart[p]; v < s.partVertexStart[p] + s.partVertexCount[p]; v++) faces.push({ part: p, vertex: v });
    }
  }
  return { faces, ctx };
}

/** Whether (x, y) is inside part p (within 1e-9 of its outline counts). */
function inside(ctx: StepContext, p: number, x: number, y: number): boolean {
  const s = ctx.rigidShapes;
  for (let v = s.partVertexStart[p]; v < s.partVertexStart[p] + s.partVertexCount[p]; v++) {
    if ((x - s.wx[v]) * s.wnx[v] + (y - s.wy[v]) * s.wny[v] > 1e-9) return false;
  }
  return true;
}

/** The oracle's count: of 41 points 10⁻⁴ outside the face, along it, how many are inside some other part. */
function coveredPoints(ctx: StepContext, f: Face): number {
  const s = ctx.rigidShapes;
  const start = s.partVertexStart[f.part];
  const next = f.vertex + 1 === start + s.partVertexCount[f.part] ? start : f.vertex + 1;
  let count = 0;
  for (let k = 0; k <= 40; k++) {
    const t = 0.001 + (0.998 * k) / 40;
    const x = s.wx[f.vertex] + t * (s.wx[next] - s.wx[f.vertex]) + 1e-4 * s.wnx[f.vertex];
    const y = s.wy[f.vertex] + t * (s.wy[next] - s.wy[f.vertex]) + 1e-4 * s.wny[f.vertex];
    for (let p = 0; p < s.partsUsed; p++) {
      if (p !== f.part && inside(ctx, p, x, y)) {
        count++;
        break;
      }
    }
  }
  return count;
}

describe('rigid seams: internal faces of static polygons', () => {
  it('random tilings (grids, bricks, steps, hairline gaps; turned and moved): internal exactly where the oracle finds the face covered', () => {
    const r = rng(20261204);
    let internal = 0;
    let outer = 0;
    let partial = 0;
    for (let trial = 0; trial < 60; trial++) {
      const world = new World({ gravity: { x: 0, y: 0 }, kernel: 'js' });
      const turn = r() * 2 * Math.PI;
      const [ox, oy] = [(r() - 0.5) * 200, (r() - 0.5) * 200];
      const place = (cx: number, cy: number, w: number, h: number) => {
        const [c, s] = [Math.cos(turn), Math.sin(turn)];
        world.addRigidBody({ points: rect(w, h), x: ox + c * cx - s * cy, y: oy + s * cx + c * cy, angle: turn, type: 'static' });
      };
      const rows = 2 + Math.floor(r() * 4);
      const bricks = trial % 2 === 1;
      const widths = Array.from({ length: 3 + Math.floor(r() * 4) }, () => 0.5 + r() * 2);
      let y = 0;
      for (let j = 0; j < rows; j++) {
        const h = 0.4 + r() * 1.5;
        // Bricks: each row cut at its own places, so a row's top is covered by several tiles of the next.
        const cuts = bricks ? Array.from({ length: 3 + Math.floor(r() * 4) }, () => 0.5 + r() * 2) : widths;
        let x = 0;
        let raised = false;
        for (const w of cuts) {
          const roll = r();
          // Most tiles flush; some missing, some a step taller, some shrunk by a hair (not flush any more).
          if (roll < 0.15) {
            x += w;
            continue;
          }
          const taller = roll < 0.25 ? 0.3 : 0;
          raised ||= taller > 0;
          const hair = roll > 0.9 ? 1e-3 : 0;
          place(x + w / 2, y + (h + taller) / 2, w - hair, h + taller - hair);
          x += w;
        }
        // Above a row with a taller tile the next starts above it (no two tiles overlap), so none of its faces is flush.
        y += h + (raised ? 0.3 : r() < 0.2 ? 0.5 : 0);
      }
      const { faces, ctx } = staticFaces(world);
      for (const f of faces) {
        const points = coveredPoints(ctx, f);
        const expected = points === 41;
        if (points > 0 && points < 41) partial++;
        expect(ctx.rigidShapes.internal[f.vertex], `trial ${trial}, part ${f.part}, vertex ${f.vertex}`).to.equal(expected ? 1 : 0);
        if (expected) internal++;
        else outer++;
      }
      // Parts flagged when (and only when) they have an internal face.
      for (let p = 0; p < ctx.rigidShapes.partsUsed; p++) {
        const any = faces.some((f) => f.part === p && ctx.rigidShapes.internal[f.vertex] === 1);
        expect(ctx.rigidShapes.partInternal[p], `trial ${trial}, part ${p}`).to.equal(any ? 1 : 0);
      }
    }
    console.log(`      seams: ${internal} internal faces, ${outer} not (${partial} of them partly covered)`);
    expect(internal).to.be.greaterThan(500);
    expect(partial).to.be.greaterThan(100);
  });

  it('two flush floor pieces: the two faces at the join; one step taller: only the lower one; a hair apart, colliding otherwise or jointed apart from a body: none; found again when a piece moves', () => {
    // A disc far off keeps the world stepping (a world of static bodies alone does no work).
    const world = new World({ gravity: { x: 0, y: 0 }, kernel: 'js', sleeping: false });
    world.addRigidBody({ radius: 0.5, x: 0, y: -50 });
    const left = world.addRigidBody({ points: rect(20, 1), x: -10, y: 0.5, type: 'static' });
    const right: Handle = world.addRigidBody({ points: rect(20, 1), x: 10, y: 0.5, type: 'static' });
    const marked = () => {
      const { faces, ctx } = staticFaces(world);
      const s = ctx.rigidShapes;
      return faces.filter((f) => s.internal[f.vertex] === 1).map((f) => `${f.part}: normal ${Math.round(s.wnx[f.vertex])},${Math.round(s.wny[f.vertex])}`);
    };
    expect(marked()).to.have.members(['0: normal 1,0', '1: normal -1,0']);
    world.setBodyPose(right, 10.001, 0.5, 0);
    expect(marked()).to.deep.equal([]);
    world.setBodyPose(right, 10, 0.5, 0);
    expect(marked()).to.have.members(['0: normal 1,0', '1: normal -1,0']);
    // A neighbour that collides with nothing, or with other bodies, hides nothing: for some body the face is a wall.
    world.setCollider(right, { shape: 'none' });
    expect(marked()).to.deep.equal([]);
    world.setCollider(right, { shape: 'polygon', mask: 2 });
    expect(marked()).to.deep.equal([]);
    world.setCollider(right, { mask: 0xffffffff });
    expect(marked()).to.have.members(['0: normal 1,0', '1: normal -1,0']);
    // A piece jointed to a body that it must not collide with hides nothing: that body moves inside it, up to the seam.
    const disc = world.addRigidBody({ radius: 0.5, x: -2, y: -3 });
    const hinge = world.addJoint({ type: 'revolute', a: disc, b: left, anchor: { x: -2, y: -3 } });
    expect(marked()).to.deep.equal([]);
    world.removeConstraint(hinge);
    expect(marked()).to.have.members(['0: normal 1,0', '1: normal -1,0']);
    // Jointed with collideConnected, it collides with that body as with any other: the seam is back.
    world.addJoint({ type: 'revolute', a: disc, b: left, anchor: { x: -2, y: -3 }, collideConnected: true });
    expect(marked()).to.have.members(['0: normal 1,0', '1: normal -1,0']);
    // The right piece 0.5 taller (same bottom): its side stands above the left piece, a real wall.
    world.removeBody(right);
    world.addRigidBody({ points: rect(20, 1.5), x: 10, y: 0.25, type: 'static' });
    expect(marked()).to.deep.equal(['0: normal 1,0']);
    // Dynamic bodies have no seams.
    world.setBodyType(left, 'dynamic');
    expect(marked()).to.deep.equal([]);
  });
});
