// Property tests of issue 13 (fast-check, fixed seeds): sat, gjkEpa and polygonManifold over families of convex
// polygon pairs — random, regular, with 180° vertices, parallel faces, near contact, slivers, identical and nested —
// each as made, 1e6 from the origin and shrunk to 1e-6. On every pair:
//   - the yes/no answer is the exact one (orientation predicates in exact arithmetic), unless the pair is within
//     rounding of touching (then either answer is allowed);
//   - the depth is the brute-force least overlap over both shapes' edge normals, and so is the overlap along the
//     returned normal;
//   - every contact point ± depth/2 · normal lies on A's and on B's outline;
//   - listing either polygon from another vertex gives the same answer.
// Tolerance: 1e-9 of the pair's size + 64 ulps of its largest coordinate (outlineTolerance).
import { expect } from 'chai';
import fc from 'fast-check';
import { Manifold, Penetration, gjkEpa, polygonManifold, sat, type Shape } from '../../../src/engine/collision/index.js';
import { FAMILIES, PLACEMENTS, placed, show } from './families.js';
import {
  boundaryDistance, checkFeatures, coordinateMagnitude, edgeNormalOverlaps, exactOverlap, exactStats, outlineTolerance,
  overlapAlongLocal, pts, rotated, sizeOf,
} from './helpers.js';

/** Pairs per family and placement. */
const RUNS = 5000;
/** Environment variables (Node's, read without its types: the engine tests type-check against the DOM's). */
const env = (globalThis as unknown as { process?: { env: Record<string, string | undefined> } }).process?.env ?? {};
// Fixed so CI is deterministic; PROPERTY_SEED=n explores other pairs locally. A failure is reported as found (the
// message names both shapes): shrinking it can take many minutes on these 5,000-run properties; SHRINK=1 does it.
const SEED = Number(env.PROPERTY_SEED ?? 1300);

const pen = new Penetration();
const penR = new Penetration();
const epa = new Penetration();
const epaR = new Penetration();
const man = new Manifold();
const manR = new Manifold();

/** What the checks counted over a test (so that none passes by checking nothing). */
interface Tally {
  pairs: number;
  overlapping: number;
  undecided: number;
  twoPoints: number;
}

function fail(what: string, a: Shape, b: Shape): never {
  throw new Error(`${what}\n  A = ${show(a)}\n  B = ${show(b)}`);
}

/** A penetration (sat's or gjkEpa's) against the brute-force depth and the outlines. */
function checkPenetration(name: string, p: Penetration, a: Shape, b: Shape, depth: number, tol: number): void {
  const { normalX: nx, normalY: ny } = p;
  if (Math.abs(nx * nx + ny * ny - 1) > 1e-12) fail(`${name}: normal (${nx}, ${ny}) is not a unit vector`, a, b);
  if (Math.abs(p.depth - depth) > tol) fail(`${name}: depth ${p.depth}, least overlap over the edge normals ${depth} (tolerance ${tol})`, a, b);
  const along = overlapAlongLocal(a, b, nx, ny);
  if (Math.abs(along - depth) > tol) fail(`${name}: overlap along the normal ${along}, least overlap ${depth}`, a, b);
  const h = p.depth / 2;
  const onA = boundaryDistance(a, p.pointX + h * nx, p.pointY + h * ny);
  const onB = boundaryDistance(b, p.pointX - h * nx, p.pointY - h * ny);
  if (onA > tol || onB > tol) fail(`${name}: contact point (${p.pointX}, ${p.pointY}) ± depth/2·n is ${onA} off A's outline and ${onB} off B's (tolerance ${tol})`, a, b);
}

function checkManifold(m: Manifold, a: Shape, b: Shape, depth: number, tol: number): void {
  if (m.count < 1 || m.count > 2) fail(`manifold: ${m.count} points`, a, b);
  const { normalX: nx, normalY: ny } = m;
  if (Math.abs(nx * nx + ny * ny - 1) > 1e-12) fail(`manifold: normal (${nx}, ${ny}) is not a unit vector`, a, b);
  let deepest = -Infinity;
  for (let k = 0; k < m.count; k++) {
    deepest = Math.max(deepest, m.depth[k]);
    const h = m.depth[k] / 2;
    const onA = boundaryDistance(a, m.pointX[k] + h * nx, m.pointY[k] + h * ny);
    const onB = boundaryDistance(b, m.pointX[k] - h * nx, m.pointY[k] - h * ny);
    if (onA > tol || onB > tol) fail(`manifold: point ${k} (${m.pointX[k]}, ${m.pointY[k]}) depth ${m.depth[k]} is ${onA} off A's outline and ${onB} off B's (tolerance ${tol})`, a, b);
  }
  if (Math.abs(deepest - depth) > tol) fail(`manifold: deepest point ${deepest}, least overlap over the edge normals ${depth}`, a, b);
  const along = overlapAlongLocal(a, b, nx, ny);
  if (Math.abs(along - depth) > tol) fail(`manifold: overlap along the normal ${along}, least overlap ${depth}`, a, b);
  const features = checkFeatures(a, b, m, tol);
  if (features) fail(`manifold: ${features}`, a, b);
}

/** Vertex k of a shape listed from vertex `start`, as a point of the original list. */
const vertexOf = (s: Shape, k: number) => pts(s)[k];

/** sat and the manifold do not depend on where the lists start (bit for bit); gjkEpa within tolerance. */
function checkListStart(a: Shape, b: Shape, ra: number, rb: number, tol: number, epaDecided: boolean, tie: boolean): void {
  const a2 = rotated(a, ra % a.count);
  const b2 = rotated(b, rb % b.count);
  const where = `listed from vertices ${ra % a.count} and ${rb % b.count}`;
  const hit = sat(a, b, pen);
  if (sat(a2, b2, penR) !== hit) fail(`sat: hit ${hit}, ${!hit} ${where}`, a, b);
  if (hit) {
    const same = pen.normalX === penR.normalX && pen.normalY === penR.normalY && pen.depth === penR.depth && pen.pointX === penR.pointX && pen.pointY === penR.pointY;
    if (!same) fail(`sat: (${pen.normalX}, ${pen.normalY}) depth ${pen.depth} at (${pen.pointX}, ${pen.pointY}), but (${penR.normalX}, ${penR.normalY}) depth ${penR.depth} at (${penR.pointX}, ${penR.pointY}) ${where}`, a, b);
  }
  const m = polygonManifold(a, b, man);
  if (polygonManifold(a2, b2, manR) !== m) fail(`manifold: hit ${m}, ${!m} ${where}`, a, b);
  if (m) {
    if (man.count !== manR.count || man.normalX !== manR.normalX || man.normalY !== manR.normalY) {
      fail(`manifold: ${man.count} points along (${man.normalX}, ${man.normalY}), but ${manR.count} along (${manR.normalX}, ${manR.normalY}) ${where}`, a, b);
    }
    const shapes = [a, b];
    const shapesR = [a2, b2];
    for (let k = 0; k < man.count; k++) {
      const own = man.incident[k];
      const v = vertexOf(shapes[own], man.vertex[k]);
      const vR = vertexOf(shapesR[manR.incident[k]], manR.vertex[k]);
      const other = pts(shapes[1 - own]);
      const otherR = pts(shapesR[1 - manR.incident[k]]);
      const e0 = other[man.edge[k]];
      const e0R = otherR[manR.edge[k]];
      const e1 = other[(man.edge[k] + 1) % other.length];
      const e1R = otherR[(manR.edge[k] + 1) % otherR.length];
      const same = man.depth[k] === manR.depth[k] && man.pointX[k] === manR.pointX[k] && man.pointY[k] === manR.pointY[k] &&
        own === manR.incident[k] && v.x === vR.x && v.y === vR.y && man.alpha[k] === manR.alpha[k] &&
        e0.x === e0R.x && e0.y === e0R.y && e1.x === e1R.x && e1.y === e1R.y;
      if (!same) fail(`manifold: point ${k} differs ${where}: (${man.pointX[k]}, ${man.pointY[k]}) depth ${man.depth[k]} vertex (${v.x}, ${v.y}) edge (${e0.x}, ${e0.y})→(${e1.x}, ${e1.y}) α ${man.alpha[k]} / (${manR.pointX[k]}, ${manR.pointY[k]}) depth ${manR.depth[k]} vertex (${vR.x}, ${vR.y}) edge (${e0R.x}, ${e0R.y})→(${e1R.x}, ${e1R.y}) α ${manR.alpha[k]}`, a, b);
    }
  }
  // GJK + EPA walks A − B from the lists' first vertices, so it may decide a pair within rounding of touching
  // either way, and end on another face when several are least (a tie); otherwise the same face, and the same
  // contact point, to within tolerance.
  const e = gjkEpa(a, b, epa);
  const eR = gjkEpa(a2, b2, epaR);
  if (epaDecided && eR !== e) fail(`gjkEpa: hit ${e}, ${!e} ${where}`, a, b);
  if (e && eR) {
    if (Math.abs(epa.depth - epaR.depth) > tol) fail(`gjkEpa: depth ${epa.depth}, ${epaR.depth} ${where}`, a, b);
    const sameNormal = Math.abs(epa.normalX - epaR.normalX) <= 1e-9 && Math.abs(epa.normalY - epaR.normalY) <= 1e-9;
    if (!sameNormal && !tie) fail(`gjkEpa: normal (${epa.normalX}, ${epa.normalY}), (${epaR.normalX}, ${epaR.normalY}) ${where}, with one least face`, a, b);
    if (sameNormal && (Math.abs(epa.pointX - epaR.pointX) > tol || Math.abs(epa.pointY - epaR.pointY) > tol)) {
      fail(`gjkEpa: point (${epa.pointX}, ${epa.pointY}), (${epaR.pointX}, ${epaR.pointY}) ${where}`, a, b);
    }
  }
}

function checkPair(a: Shape, b: Shape, ra: number, rb: number, tally: Tally): void {
  tally.pairs++;
  const tol = outlineTolerance(a, b);
  // Pairs this close to touching may be called either way: rounding of the coordinates alone moves them that much.
  const band = 64 * Number.EPSILON * coordinateMagnitude(a, b) + 1e-12 * sizeOf(a, b);
  const exact = exactOverlap(a, b);
  const { depth, normals } = edgeNormalOverlaps(a, b);
  const decided = Math.abs(depth) > band;
  if (!decided) tally.undecided++;
  // The two oracles agree wherever rounding cannot decide.
  if (decided && depth > 0 !== exact) fail(`oracles disagree: exact ${exact}, brute-force least overlap ${depth}`, a, b);
  if (exact) tally.overlapping++;
  const s = sat(a, b, pen);
  const e = gjkEpa(a, b, epa);
  const m = polygonManifold(a, b, man);
  if (decided && (s !== exact || m !== exact)) fail(`overlap is ${exact} (exactly), but sat ${s}, manifold ${m}`, a, b);
  // GJK + EPA calls a depth within its convergence tolerance (1e-10 of the size, and rounding) touching.
  if (Math.abs(depth) > tol && e !== exact) fail(`overlap is ${exact} (exactly) by ${depth}, but gjkEpa ${e}`, a, b);
  if (s) checkPenetration('sat', pen, a, b, depth, tol);
  if (e) checkPenetration('gjkEpa', epa, a, b, depth, tol);
  if (m) {
    checkManifold(man, a, b, depth, tol);
    if (man.count === 2) tally.twoPoints++;
  }
  // Several least faces (a square in a square's middle): GJK + EPA may pick any of them.
  const least = normals.filter((n) => n[2] <= depth + tol);
  const tie = least.some((n) => Math.abs(n[0] - least[0][0]) > 1e-6 || Math.abs(n[1] - least[0][1]) > 1e-6);
  checkListStart(a, b, ra, rb, tol, Math.abs(depth) > tol, tie);
}

describe('collision properties (issue 13): sat, gjkEpa and polygonManifold on every convex input', () => {
  after(() => console.log(`  exact predicate: ${exactStats.calls} orientations, ${exactStats.exact} settled in exact arithmetic`));
  FAMILIES.forEach(([name, family], f) => {
    PLACEMENTS.forEach((placement, p) => {
      it(`${name}, ${placement === 'unit' ? 'size 1' : placement === 'far' ? 'offset 1e6' : 'scale 1e-6'}: exact yes/no, least-overlap depth and normal, points on both outlines, any starting vertex`, () => {
        const tally: Tally = { pairs: 0, overlapping: 0, undecided: 0, twoPoints: 0 };
        fc.assert(
          fc.property(placed(family, placement), ({ a, b, ra, rb }) => checkPair(a, b, ra, rb, tally)),
          { seed: SEED + 10 * f + p, numRuns: RUNS, endOnFailure: !env.SHRINK },
        );
        // Not vacuous: overlapping and separated pairs, two-point manifolds, and few pairs left undecided.
        expect(tally.overlapping, 'overlapping pairs').to.be.greaterThan(RUNS / 10);
        if (!name.startsWith('identical')) expect(tally.pairs - tally.overlapping, 'separated pairs').to.be.greaterThan(RUNS / 20);
        expect(tally.twoPoints, 'two-point manifolds').to.be.greaterThan(0);
        // (A gap of 1e-9 is below the rounding of coordinates near 1e6: those pairs check only that nothing breaks.)
        if (!(name.startsWith('near contact') && placement === 'far')) expect(tally.undecided, 'pairs within rounding of touching').to.be.lessThan(RUNS / 5);
      });
    });
  });
});
