// The painters of src/render/bodies/ on a recording context: what each body type draws, batched by style.
import { expect } from '@open-wc/testing';
import { BODY_TYPES, RAGDOLL_BONES, RAGDOLL_JOINTS } from '../../src/engine/index.js';
import { PAINTERS, type BodyStyle, type Pen } from '../../src/render/bodies/index.js';
import type { Topology, TopologyBody } from '../../src/worker/protocol.js';

type Call = [string, ...number[]];

/** A 2D context that records path calls and the style set at each fill and stroke. */
function recorder() {
  const calls: Call[] = [];
  const paints: { op: 'fill' | 'stroke'; style: string; width: number }[] = [];
  const state = { fillStyle: '', strokeStyle: '', lineWidth: 0 };
  const ctx = {
    ...Object.fromEntries(['beginPath', 'moveTo', 'lineTo', 'arc', 'closePath'].map((name) => [name, (...args: number[]) => calls.push([name, ...args])])),
    fill: () => paints.push({ op: 'fill', style: state.fillStyle, width: state.lineWidth }),
    stroke: () => paints.push({ op: 'stroke', style: state.strokeStyle, width: state.lineWidth }),
  };
  for (const key of Object.keys(state) as (keyof typeof state)[]) {
    Object.defineProperty(ctx, key, { get: () => state[key], set: (v) => (state[key] = v as never) });
  }
  return { ctx: ctx as unknown as CanvasRenderingContext2D, calls, paints };
}

/**
 * Draws the topology's bodies k in one style with their type's painter; particle i is at (i, 10·i) pixels, body k's
 * pose at poses[3·k …] (world units, drawn at 20 pixels per unit, offset by (100, 200) pixels).
 */
function paint(topology: Topology, ks: number[], style: BodyStyle = { fill: '#f00', stroke: '#00f', lineWidth: 1.5 }, scale = 20, poses: number[] = []) {
  const r = recorder();
  const pen: Pen = { ctx: r.ctx, X: (i) => i, Y: (i) => 10 * i, scale, offsetX: 100, offsetY: 200, topology, poses: Float64Array.from(poses) };
  PAINTERS[topology.bodies[ks[0]].type].draw(pen, ks, style);
  return r;
}

const points = (calls: Call[], name: string) => calls.filter((c) => c[0] === name).map((c) => c[1]);

/**
 * The outlines among the path calls: each subpath (a moveTo and its lineTos) as its points [x, y], the closing ones
 * left out. An outline closes by going back to its first point and on to its second (a join there like the others;
 * closePath() is quadratic in Chromium); an outline that does not is an error here. Arcs are not outlines.
 */
function loops(calls: Call[]): number[][][] {
  const subpaths: number[][][] = [];
  for (const c of calls) {
    if (c[0] === 'moveTo') subpaths.push([[c[1], c[2]]]);
    else if (c[0] === 'lineTo') subpaths.at(-1)!.push([c[1], c[2]]);
  }
  return subpaths.map((p) => {
    const n = p.length - 2;
    expect(p.slice(n), `outline ${JSON.stringify(p)} back to its first point and on to its second`).to.deep.equal([p[0], p[1 % n]]);
    return p.slice(0, n);
  });
}

describe('body painters', () => {
  it('every body type has one', () => {
    expect(Object.keys(PAINTERS).sort()).to.deep.equal([...BODY_TYPES].sort());
  });

  it('shapes of one style are one path, one fill and one stroke: particle boxes and rings as loops, balls as discs', () => {
    const bodies: TopologyBody[] = [
      { key: 1, type: 'box', kind: 'rigid', indices: Int32Array.of(0, 1, 2, 3) },
      { key: 2, type: 'circle', kind: 'particle', indices: Int32Array.of(4), radius: 0.5 },
      // A springs-model soft body: 5 ring particles, then its hub (9), which is not on the outline.
      { key: 3, type: 'softbody', kind: 'soft', indices: Int32Array.of(5, 6, 7, 8, 9), ring: 4 },
      { key: 4, type: 'polygon', kind: 'rigid', indices: Int32Array.of(10, 11, 12) },
    ];
    expect(new Set([1, 2, 3].map((k) => PAINTERS[bodies[k].type].batch))).to.deep.equal(new Set([PAINTERS.box.batch]));
    const { calls, paints } = paint({ version: 1, bodies, links: [] }, [0, 1, 2, 3]);
    expect(calls.filter((c) => c[0] === 'beginPath').length).to.equal(1);
    expect(paints).to.deep.equal([{ op: 'fill', style: '#f00', width: 0 }, { op: 'stroke', style: '#00f', width: 1.5 }]);
    expect(points(calls, 'moveTo')).to.deep.equal([0, 4 + 10, 5, 10]);
    expect(loops(calls.filter((c) => c[0] !== 'arc' && !(c[0] === 'moveTo' && c[1] === 14))).map((l) => l.map(([x]) => x))).to.deep.equal([[0, 1, 2, 3], [5, 6, 7, 8], [10, 11, 12]]);
    expect(calls.filter((c) => c[0] === 'closePath').length).to.equal(0);
    // The ball: a disc of radius · scale around its particle.
    expect(calls.filter((c) => c[0] === 'arc')).to.deep.equal([['arc', 4, 40, 0.5 * 20, 0, Math.PI * 2]]);
  });

  it('a soft ring with a particle radius: its loop pushed out by the radius, away from its middle, either way round', () => {
    // Four particles on a 10-pixel square, their radius 0.1 units = 2 pixels at 20 pixels a unit.
    const square = [[0, 0], [10, 0], [10, 10], [0, 10]];
    for (const order of [[0, 1, 2, 3], [3, 2, 1, 0]]) {
      const r = recorder();
      const body: TopologyBody = { key: 1, type: 'softbody', kind: 'soft', indices: Int32Array.from(order), ring: 4, radius: 0.1 };
      const pen: Pen = { ctx: r.ctx, X: (i) => square[i][0], Y: (i) => square[i][1], scale: 20, offsetX: 0, offsetY: 0, topology: { version: 1, bodies: [body], links: [] }, poses: new Float64Array(0) };
      PAINTERS.softbody.draw(pen, [0], { fill: '#f00', stroke: null, lineWidth: 1 });
      const drawn = loops(r.calls)[0];
      expect(drawn.length).to.equal(4);
      drawn.forEach(([x, y], q) => {
        const [px, py] = square[order[q]];
        expect(Math.hypot(x - px, y - py), `corner ${order[q]} moved by the radius`).to.be.closeTo(2, 1e-9);
        expect(Math.hypot(x - 5, y - 5), `corner ${order[q]} away from the middle`).to.be.closeTo(Math.hypot(5, 5) + 2, 1e-9);
      });
    }
  });

  it('rigid bodies from their pose: an outline turned by the angle, a disc with a radius line that turns with it', () => {
    const bodies: TopologyBody[] = [
      { key: 1, type: 'box', kind: 'rigid', indices: Int32Array.of(0), rigid: true, outline: Float64Array.of(-1, -0.5, 1, -0.5, 1, 0.5, -1, 0.5), center: [0, 0] },
      { key: 2, type: 'circle', kind: 'rigid', indices: Int32Array.of(1), rigid: true, radius: 0.5, center: [0, 0] },
      // A concave polygon: drawn as its outline (an L), not as its convex parts.
      { key: 3, type: 'polygon', kind: 'rigid', indices: Int32Array.of(2), rigid: true, outline: Float64Array.of(0, 0, 2, 0, 2, 1, 1, 1, 1, 3, 0, 3), center: [0, 0] },
    ];
    // The box at (2, 3) turned a quarter turn; the ball at (5, 1) turned by pi; the L at (0, 0) unturned.
    const poses = [2, 3, Math.PI / 2, 5, 1, Math.PI, 0, 0, 0];
    const { calls, paints } = paint({ version: 1, bodies, links: [] }, [0, 1, 2], undefined, 20, poses);
    const px = (x: number, y: number) => [100 + 20 * x, 200 + 20 * y];
    const at = (c: Call) => [c[1], c[2]];
    const path = calls.slice(0, calls.findIndex((c, q) => q > 0 && c[0] === 'beginPath'));
    // The box's corners: (−1, −0.5) turned a quarter turn is (0.5, −1), about its centre.
    const outlines = loops(path.filter((c) => c[0] !== 'arc' && !(c[0] === 'moveTo' && c[1] === px(5, 1)[0] + 10)));
    expect(outlines.length).to.equal(2);
    const box = outlines[0];
    [[0.5, -1], [0.5, 1], [-0.5, 1], [-0.5, -1]].forEach(([u, v], q) => {
      expect(box[q][0]).to.be.closeTo(px(2 + u, 3 + v)[0], 1e-9);
      expect(box[q][1]).to.be.closeTo(px(2 + u, 3 + v)[1], 1e-9);
    });
    expect(path.filter((c) => c[0] === 'arc')).to.deep.equal([['arc', ...px(5, 1), 10, 0, Math.PI * 2]]);
    expect(outlines[1]).to.deep.equal([[0, 0], [2, 0], [2, 1], [1, 1], [1, 3], [0, 3]].map(([x, y]) => px(x, y)));
    // Fill and stroke of the shapes, then the radius lines in the stroke colour: from the centre along the angle.
    expect(paints).to.deep.equal([{ op: 'fill', style: '#f00', width: 0 }, { op: 'stroke', style: '#00f', width: 1.5 }, { op: 'stroke', style: '#00f', width: 1.5 }]);
    const spoke = calls.slice(calls.lastIndexOf(calls.filter((c) => c[0] === 'beginPath').at(-1)!));
    expect(spoke.map((c) => c[0])).to.deep.equal(['beginPath', 'moveTo', 'lineTo']);
    expect(at(spoke[1])).to.deep.equal(px(5, 1));
    expect(spoke[2][1]).to.be.closeTo(px(4.5, 1)[0], 1e-9);
    expect(spoke[2][2]).to.be.closeTo(px(4.5, 1)[1], 1e-9);
    // Without a stroke, the radius line is drawn darker than any fill.
    const plain = paint({ version: 1, bodies, links: [] }, [1], { fill: '#f00', stroke: null, lineWidth: 1.5 }, 20, poses);
    expect(plain.paints.map((p) => [p.op, p.style])).to.deep.equal([['fill', '#f00'], ['stroke', 'rgba(0, 0, 0, 0.45)']]);
    // A ball of particles has no turn to show: no radius line.
    const particleBall: TopologyBody = { key: 4, type: 'circle', kind: 'particle', indices: Int32Array.of(0), radius: 0.5 };
    expect(paint({ version: 1, bodies: [particleBall], links: [] }, [0]).paints.length).to.equal(2);
  });

  it('ropes are polylines as thick as their particles, at least the style\'s width', () => {
    const bodies: TopologyBody[] = [
      { key: 1, type: 'rope', kind: 'rope', indices: Int32Array.of(0, 1, 2), radius: 0.1 },
      { key: 2, type: 'rope', kind: 'rope', indices: Int32Array.of(3, 4), radius: 0 },
    ];
    const t = { version: 1, bodies, links: [] };
    const thick = paint(t, [0, 1]);
    expect(points(thick.calls, 'moveTo')).to.deep.equal([0, 3]);
    expect(points(thick.calls, 'lineTo')).to.deep.equal([1, 2, 4]);
    expect(thick.paints).to.deep.equal([{ op: 'stroke', style: '#00f', width: 2 * 0.1 * 20 }]);
    expect(paint(t, [1]).paints[0].width).to.equal(1.5);
  });

  it('ragdolls: the builder\'s bones as strokes, the head as a disc', () => {
    const indices = Int32Array.from({ length: RAGDOLL_JOINTS.length }, (_, i) => 20 + i);
    const bodies: TopologyBody[] = [{ key: 1, type: 'ragdoll', kind: 'ragdoll', indices, radius: 0.1 }];
    const { calls, paints } = paint({ version: 1, bodies, links: [] }, [0]);
    const segments = calls.filter((c) => c[0] === 'lineTo').map((c, q) => [points(calls, 'moveTo')[q] - 20, c[1] - 20]);
    expect(segments).to.deep.equal(RAGDOLL_BONES.map(([a, b]) => [a, b]));
    expect(calls.filter((c) => c[0] === 'arc')).to.deep.equal([['arc', 20, 200, 0.1 * 20, 0, Math.PI * 2]]);
    expect(paints.map((p) => [p.op, p.width])).to.deep.equal([['stroke', 2], ['fill', 2]]);
  });

  it('a ragdoll or rope drawn in one colour: the stroke\'s, else the fill\'s; nothing when both are "none"', () => {
    const indices = Int32Array.from({ length: RAGDOLL_JOINTS.length }, (_, i) => i);
    const doll = { version: 1, bodies: [{ key: 1, type: 'ragdoll', kind: 'ragdoll', indices, radius: 0.1 }] as TopologyBody[], links: [] };
    const rope = { version: 1, bodies: [{ key: 1, type: 'rope', kind: 'rope', indices: Int32Array.of(0, 1, 2), radius: 0 }] as TopologyBody[], links: [] };
    const styles = (t: Topology, fill: string | null, stroke: string | null) => paint(t, [0], { fill, stroke, lineWidth: 1.5 }).paints.map((p) => `${p.op} ${p.style}`);
    expect(styles(doll, null, '#00f')).to.deep.equal(['stroke #00f', 'fill #00f']);
    expect(styles(doll, '#f00', null)).to.deep.equal(['stroke #f00', 'fill #f00']);
    expect(styles(doll, '#f00', '#00f')).to.deep.equal(['stroke #00f', 'fill #f00']);
    expect(styles(rope, null, '#00f')).to.deep.equal(['stroke #00f']);
    expect(styles(rope, '#f00', null)).to.deep.equal(['stroke #f00']);
    // stroke="none" on a ragdoll (no fill by default) was drawn in #333, on a rope in #000.
    const none = paint(doll, [0], { fill: null, stroke: null, lineWidth: 1.5 });
    expect([none.paints, none.calls]).to.deep.equal([[], []]);
    const noRope = paint(rope, [0], { fill: null, stroke: null, lineWidth: 1.5 });
    expect([noRope.paints, noRope.calls]).to.deep.equal([[], []]);
  });

  it('a dense cloth draws every k-th grid line, through every k-th node and the last, so lines stay 6 px apart', () => {
    const n = 21;
    const body: TopologyBody = { key: 1, type: 'cloth', kind: 'cloth', indices: Int32Array.from({ length: n * n }, (_, i) => i), columns: n, rows: n };
    const strokeOf = (px: number) => {
      const r = recorder();
      const pen: Pen = { ctx: r.ctx, X: (i) => (i % n) * px, Y: (i) => Math.floor(i / n) * px, scale: 1, offsetX: 0, offsetY: 0, topology: { version: 1, bodies: [body], links: [] }, poses: new Float64Array(0) };
      PAINTERS.cloth.draw(pen, [0], { fill: null, stroke: '#00f', lineWidth: 1.5 });
      return r.calls;
    };
    // 6 px apart: every line, every node (21 rows and 21 columns of 20 segments).
    const sparse = strokeOf(6);
    expect(sparse.filter((c) => c[0] === 'moveTo').length).to.equal(2 * n);
    expect(sparse.filter((c) => c[0] === 'lineTo').length).to.equal(2 * n * (n - 1));
    // 2 px apart: every third line and node (0, 3, …, 18, and the last, 20): 8 rows and 8 columns of 7 segments.
    const dense = strokeOf(2);
    const starts = dense.filter((c) => c[0] === 'moveTo').map((c) => [c[1], c[2]]);
    expect(starts.slice(0, 8).map(([, y]) => y / 2)).to.deep.equal([0, 3, 6, 9, 12, 15, 18, 20]);
    expect(starts.slice(8).map(([x]) => x / 2)).to.deep.equal([0, 3, 6, 9, 12, 15, 18, 20]);
    const firstRow = dense.slice(2, 9).map((c) => c[1] / 2); // after beginPath and the row's moveTo
    expect(firstRow).to.deep.equal([3, 6, 9, 12, 15, 18, 20]);
    expect(dense.filter((c) => c[0] === 'lineTo').length).to.equal(16 * 7);
  });

  it('a torn cloth leaves out the cells and links that tore', () => {
    // 3 × 3 grid on particles 0…8; the link from node 0 to its right neighbour broke.
    const bodies: TopologyBody[] = [{ key: 1, type: 'cloth', kind: 'cloth', indices: Int32Array.from({ length: 9 }, (_, i) => i), columns: 3, rows: 3, torn: Uint8Array.of(1, 0, 0, 0, 0, 0, 0, 0, 0) }];
    const t = { version: 1, bodies, links: [] };
    const { calls, paints } = paint(t, [0]);
    expect(paints.map((p) => p.op)).to.deep.equal(['fill', 'stroke']);
    const fillPass = calls.slice(0, calls.findIndex((c, q) => q > 0 && c[0] === 'beginPath'));
    // Cells at nodes 1, 3 and 4; the one at node 0 touches the broken link.
    // Each row's run of whole cells one strip, along its top and back along its bottom; fill() closes them (no
    // closePath, which is quadratic in Chromium). Row 0: the cell at node 1 alone; row 1: the cells at 3 and 4.
    expect(fillPass.filter((c) => c[0] === 'closePath').length).to.equal(0);
    expect(points(fillPass, 'moveTo')).to.deep.equal([1, 3]);
    expect(points(fillPass, 'lineTo')).to.deep.equal([2, 5, 4, 4, 5, 8, 7, 6]);
    // Grid lines: the pen lifts over 0 → 1 (a moveTo to 1 instead of a lineTo).
    const strokePass = calls.slice(fillPass.length);
    expect(points(strokePass, 'moveTo')).to.deep.equal([0, 1, 3, 6, 0, 1, 2]);
    expect(points(strokePass, 'lineTo').length).to.equal(12 - 1);
    // Whole: four cells.
    const whole = paint({ ...t, bodies: [{ ...bodies[0], torn: undefined }] }, [0]);
    const wholeFill = whole.calls.slice(0, whole.calls.findIndex((c, q) => q > 0 && c[0] === 'beginPath'));
    expect(points(wholeFill, 'moveTo')).to.deep.equal([0, 3]);
    expect(points(wholeFill, 'lineTo')).to.deep.equal([1, 2, 5, 4, 3, 4, 5, 8, 7, 6]);
    // Node 4's links right (4 → 5) and down (4 → 7) broke: the bottom edge of the cell at node 1, the right edge of
    // the cell at 3, and two edges of the cell at 4. A cell is left out for a tear on any of its four edges: only
    // the cell at node 0 is filled. (The case above tears a top edge alone, which a test of torn[n] alone passes.)
    const inner = paint({ ...t, bodies: [{ ...bodies[0], torn: Uint8Array.of(0, 0, 0, 0, 3, 0, 0, 0, 0) }] }, [0]);
    const innerFill = inner.calls.slice(0, inner.calls.findIndex((c, q) => q > 0 && c[0] === 'beginPath'));
    expect(points(innerFill, 'moveTo')).to.deep.equal([0]);
    expect(points(innerFill, 'lineTo')).to.deep.equal([1, 4, 3]);
  });
});
