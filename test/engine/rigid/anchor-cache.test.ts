// The rigid contacts' friction anchors carried from one step to the next (RigidAnchorCache), against its definition
// with a plain Map by feature key: a new point gets the anchors its key's point left last step, if they are within
// reach, and no more overlap allowance than that point had left. Lists in the same order, reordered, with points
// dropped and new ones added, duplicate keys, and body slots past 32768 (whose keys wrap at 2^53). A round side's fresh
// anchor that is not replaced by a kept one is turned back by half the step's turn of its body (−ω·dt/2).
import { expect } from 'chai';
import { arcBeyond, RigidAnchorCache, RigidContacts, writeAnchorKey } from '../../../src/engine/rigid/contacts.js';
import type { BodyRows } from '../../../src/engine/rigid/rows.js';
import { random } from '../pipeline/scene-helpers.js';

interface Point {
  a: number; b: number; b2: number; feature: number; touched: number; slip: number; allowance: number;
  nx: number; ny: number; rAx: number; rAy: number; rBx: number; rBy: number; radA: number; radB: number;
}

function fill(table: RigidContacts, points: Point[]): void {
  table.count = 0;
  for (const q of points) {
    const f = table.next;
    f.fill(0);
    f[0] = q.nx;
    f[1] = q.ny;
    f[2] = q.rAx;
    f[3] = q.rAy;
    f[4] = q.rBx;
    f[5] = q.rBy;
    f[6] = q.radA;
    f[7] = q.radB;
    writeAnchorKey(f, q.a, q.b, q.feature);
    table.add(q.a, q.b, q.b2, q.a, q.b, 0);
    const i = table.count - 1;
    table.touched[i] = q.touched;
    table.slip[i] = q.slip;
    table.allowance[i] = q.allowance;
  }
}

/**
 * What the cache should restore, from its definition: last step's points (not on particle edges) as a list in their
 * order, each with its anchors if it acted; a fresh point takes the entry at the cursor when that has its key (the
 * cursor then moves past it), else the first entry of its key that holds anchors (a Map here).
 */
/** Point i's A anchor minus its B anchor along the tangent, a round side's along its arc (arcBeyond), levers only. */
function offsetAlongTangent(c: RigidContacts, rows: BodyRows, i: number, a: number[], b: number[]): number {
  const along = (p: number[], row: number): number => {
    const [x, y] = row < 0 ? p : [rows.rc[row] * p[0] - rows.rs[row] * p[1], rows.rs[row] * p[0] + rows.rc[row] * p[1]];
    return -x * c.ny[i] + y * c.nx[i];
  };
  const tA = along(a, c.a[i]);
  const tB = along(b, c.b[i]);
  return tA + arcBeyond(tA, c.radA[i]) - (c.b[i] < 0 ? tB : tB + arcBeyond(tB, c.radB[i]));
}

function oracle(old: RigidContacts, rows: BodyRows, fresh: RigidContacts, reach: number, dt: number): { rA: number[][]; rB: number[][]; allowance: number[] } {
  const list: { key: number; held: boolean; rA: number[]; rB: number[]; allow: number }[] = [];
  const firstHeld = new Map<number, number>();
  for (let i = 0; i < old.count; i++) {
    if (old.b2[i] >= 0) continue;
    const key = old.feature[i];
    if (!old.touched[i]) {
      list.push({ key, held: false, rA: [], rB: [], allow: 0 });
      continue;
    }
    const tx = -old.ny[i] * old.slip[i];
    const ty = old.nx[i] * old.slip[i];
    let bx = old.rBx[i];
    let by = old.rBy[i];
    const ib = old.b[i];
    if (ib < 0) {
      bx += tx;
      by += ty;
    } else if (old.slip[i] !== 0) {
      bx += rows.rc[ib] * tx + rows.rs[ib] * ty;
      by += -rows.rs[ib] * tx + rows.rc[ib] * ty;
    }
    if (!firstHeld.has(key)) firstHeld.set(key, list.length);
    list.push({ key, held: true, rA: [old.rAx[i], old.rAy[i]], rB: [bx, by], allow: old.allowance[i] });
  }
  const rA: number[][] = [];
  const rB: number[][] = [];
  const allowance: number[] = [];
  let cursor = 0;
  const turned = (x: number, y: number, row: number): number[] => {
    const t = -0.5 * rows.omega[row] * dt;
    return [Math.cos(t) * x - Math.sin(t) * y, Math.sin(t) * x + Math.cos(t) * y];
  };
  for (let i = 0; i < fresh.count; i++) {
    if (fresh.b2[i] >= 0) {
      rA.push([fresh.rAx[i], fresh.rAy[i]]);
      rB.push([fresh.rBx[i], fresh.rBy[i]]);
      allowance.push(fresh.allowance[i]);
      continue;
    }
    let a = [fresh.rAx[i], fresh.rAy[i]];
    let b = [fresh.rBx[i], fresh.rBy[i]];
    let kept = false;
    let allow = fresh.allowance[i];
    const key = fresh.feature[i];
    const k = fresh.b2[i] >= 0 ? -1 : cursor < list.length && list[cursor].key === key ? cursor : (firstHeld.get(key) ?? -1);
    if (k >= 0) {
      cursor = k + 1;
      const h = list[k];
      if (h.held) {
        allow = Math.min(allow, h.allow);
        // Measured from the fresh anchors turned back by half the step's turn, to first order.
        const tA = fresh.radA[i] > 0 ? -0.5 * rows.omega[fresh.a[i]] * dt : 0;
        const tB = fresh.radB[i] > 0 && fresh.b[i] >= 0 ? -0.5 * rows.omega[fresh.b[i]] * dt : 0;
        const da = (h.rA[0] - (a[0] - tA * a[1])) ** 2 + (h.rA[1] - (a[1] + tA * a[0])) ** 2;
        const db = (h.rB[0] - (b[0] - tB * b[1])) ** 2 + (h.rB[1] - (b[1] + tB * b[0])) ** 2;
        if (da <= reach * reach && db <= reach * reach) {
          a = h.rA;
          b = h.rB;
          kept = true;
        }
      }
    }
    // Not kept from last step: a round side's fresh anchor turned back by half its body's turn in the step, and the
    // anchors shifted along the tangent (the side that is not round, else both by half) so that the point's offset
    // as friction measures it (a rim along its arc) is what the narrow phase found.
    const roundA = fresh.radA[i] > 0;
    const roundB = fresh.radB[i] > 0 && fresh.b[i] >= 0;
    if (!kept && (roundA || roundB)) {
      const found = offsetAlongTangent(fresh, rows, i, a, b);
      if (roundA) a = turned(a[0], a[1], fresh.a[i]);
      if (roundB) b = turned(b[0], b[1], fresh.b[i]);
      const moved = offsetAlongTangent(fresh, rows, i, a, b) - found;
      const shift = (p: number[], row: number, d: number): number[] => {
        const t = [-fresh.ny[i] * d, fresh.nx[i] * d];
        if (row < 0) return [p[0] + t[0], p[1] + t[1]];
        return [p[0] + rows.rc[row] * t[0] + rows.rs[row] * t[1], p[1] - rows.rs[row] * t[0] + rows.rc[row] * t[1]];
      };
      if (!roundB) b = shift(b, fresh.b[i], moved);
      else if (!roundA) a = shift(a, fresh.a[i], -moved);
      else {
        a = shift(a, fresh.a[i], -0.5 * moved);
        b = shift(b, fresh.b[i], 0.5 * moved);
      }
    }
    rA.push(a);
    rB.push(b);
    allowance.push(allow);
  }
  return { rA, rB, allowance };
}

describe('rigid bodies: friction anchors from step to step', () => {
  it('restores what a map by feature key gives, for lists kept, reordered, thinned and grown (200 cases)', () => {
    const rnd = random(5);
    const rows = { rc: new Float64Array(90000), rs: new Float64Array(90000), omega: new Float64Array(90000) } as unknown as BodyRows;
    for (let r = 0; r < 90000; r++) {
      const t = rnd() * 6.3;
      rows.rc[r] = Math.cos(t);
      rows.rs[r] = Math.sin(t);
    }
    // Spins up to 12 rad/s, and a few past the series' range (a turn of 0.1 rad or more in a step of 1/60 s).
    for (let r = 0; r < rows.omega.length; r++) rows.omega[r] = rnd() < 0.02 ? (rnd() - 0.5) * 40 : (rnd() - 0.5) * 24;
    const dt = 1 / 60;
    const cache = new RigidAnchorCache();
    const old = new RigidContacts();
    const fresh = new RigidContacts();
    let restored = 0;
    let kept = 0;
    for (let trial = 0; trial < 200; trial++) {
      const far = trial % 5 === 4; // body slots past 32768: keys past 2^53 wrap
      const bodies = 3 + Math.floor(rnd() * 40);
      const slot = () => (far ? 40000 + Math.floor(rnd() * bodies) * 977 : Math.floor(rnd() * bodies));
      const n = Math.floor(rnd() * 300);
      const before: Point[] = [];
      for (let k = 0; k < n; k++) {
        const t = rnd() * 6.3;
        before.push({
          a: slot(), b: rnd() < 0.2 ? -1 : Math.floor(rnd() * 64), b2: rnd() < 0.05 ? 3 : -1, feature: Math.floor(rnd() * 6),
          touched: rnd() < 0.8 ? 1 : 0, slip: rnd() < 0.5 ? 0 : rnd() * 0.02 - 0.01, allowance: rnd() * 0.01,
          nx: Math.cos(t), ny: Math.sin(t), rAx: rnd() - 0.5, rAy: rnd() - 0.5, rBx: rnd() - 0.5, rBy: rnd() - 0.5,
          radA: rnd() < 0.3 ? 0.5 : 0, radB: rnd() < 0.2 ? 0.25 : 0,
        });
      }
      fill(old, before);
      cache.store(old, rows);
      // Next step: mostly the same points nudged, some dropped, some new, sometimes in another order.
      const after: Point[] = [];
      for (const q of before) {
        if (rnd() < 0.15) continue;
        after.push({ ...q, rAx: q.rAx + (rnd() - 0.5) * 0.04, rBy: q.rBy + (rnd() - 0.5) * 0.04, allowance: rnd() * 0.01 });
        if (rnd() < 0.1) after.push({ ...q, a: slot(), feature: Math.floor(rnd() * 6) });
      }
      if (trial % 3 === 1) after.sort(() => rnd() - 0.5);
      if (trial % 3 === 2) for (let k = 0; k + 1 < after.length; k += 7) [after[k], after[k + 1]] = [after[k + 1], after[k]];
      fill(fresh, after);
      const reach = 0.02;
      const want = oracle(old, rows, fresh, reach, dt);
      cache.restore(fresh, reach, rows, dt);
      for (let i = 0; i < fresh.count; i++) {
        // The cache turns a round side's lever by the rotation series of rows.ts below 0.1 rad (exact to rounding).
        const got = [fresh.rAx[i], fresh.rAy[i], fresh.rBx[i], fresh.rBy[i]];
        const wanted = [...want.rA[i], ...want.rB[i]];
        got.forEach((v, q) => expect(v, `trial ${trial}, point ${i}`).to.be.closeTo(wanted[q], 1e-12));
        expect(fresh.allowance[i], `trial ${trial}, point ${i}`).to.equal(want.allowance[i]);
        if (want.rA[i][0] !== after[i].rAx) restored++;
        else kept++;
      }
    }
    expect(restored).to.be.above(5000);
    expect(kept).to.be.above(1000);
  });
});
