import { JointKind, type Joints } from './joint-table.js';
import { MAX_TURN, spin, turnBySpin, type BodyRows } from './rows.js';

// Revolute joints' points and welds solved at once, exactly for the linearised problem, over each tree they form
// (Baraff 1996, "Linear-time dynamics using Lagrange multipliers"): the system of the bodies' moves Δq and the joints'
// multipliers Δλ,
//   Δq_b − W_b·Σ_j σ_jb·S_jbᵀ·Δλ_j = 0          (W = diag(1/m, 1/m, 1/I); S: the start levers, as in correctPoint)
//   Σ_b σ_jb·L_jb·Δq_b + α̃·Δλ_j = −c_j − α̃·λ_j  (L: the current levers; σ = +1 for side A, −1 for B)
// has the shape of the tree of bodies and joints, and block elimination from the leaves up and back down solves it in
// linear time with no fill. A joint has three rows, the point's two and the relative angle's (a weld's; a revolute
// joint's is empty). One Gauss–Seidel sweep leaves a chain's joints a residual close to the whole correction (its
// rate is about cos²(π/(n+1)) for n links), which the next substep takes out of the motion; among masses and levers
// far apart (a light part welded on long levers between heavy ones) the sweep's corrections overshoot.
//
// Immovable rows (the world, static, kinematic and sleeping bodies) are one node, so a chain pinned at both ends is a
// loop. A revolute joint that closes one (up to MAX_CLOSURES of them) is solved with the trees through its Schur
// complement (solveClosures); a weld that closes one is left to the sweep, as are the other kinds.

let stamp = new Int32Array(16);
let localOf = new Int32Array(16);
let stampNow = 0;

// Per local body (0: the immovable node).
let bodyRow = new Int32Array(16);
let uf = new Int32Array(16);
let adjStart = new Int32Array(17);
let adjCount = new Int32Array(16);
let adj = new Int32Array(32);
let visited = new Uint8Array(16);
let queue = new Int32Array(16);
let parentJoint = new Int32Array(16);
/** D (9), its inverse P (9), rhs (3), y = P·rhs (3), x (3). */
let bodyF = new Float64Array(16 * 27);
let startCos = new Float64Array(16);
let startSin = new Float64Array(16);
/** 1: the body's levers S are half-way between its start and current ones this substep (below a lopsided joint). */
let halfwayLevers = new Uint8Array(16);

// Per joint of the table: its local bodies (A, B).
let jA = new Int32Array(16);
let jB = new Int32Array(16);
let jTree = new Uint8Array(16);
let jVisited = new Uint8Array(16);

/** Whether joint i (a revolute joint's point, or a weld) was solved by the last solveJointTrees() that returned true. */
export function inJointTree(i: number): boolean {
  return jTree[i] === 1 || (jTree[i] === 2 && closuresSolved);
}

// The joints of the forest in BFS order (parents before children).
let order = new Int32Array(16);
let orderChild = new Int32Array(16);
let orderParent = new Int32Array(16);
/** Child's side sign σ_c, Dk⁻¹ (9), rhs (3), Q (9), parent levers l (2), s (2), Δλ (3), the angle row's weight w. */
let jointF = new Float64Array(16 * 30);

const JF = 30;
const BF = 27;

function ensure(rows: number, n: number): void {
  if (stamp.length < rows) {
    const size = Math.max(rows, stamp.length * 2);
    stamp = new Int32Array(size);
    localOf = new Int32Array(size);
    stampNow = 0;
  }
  const nb = 2 * n + 2;
  if (bodyRow.length < nb) {
    const size = Math.max(nb, bodyRow.length * 2);
    bodyRow = new Int32Array(size);
    uf = new Int32Array(size);
    adjStart = new Int32Array(size + 1);
    adjCount = new Int32Array(size);
    visited = new Uint8Array(size);
    queue = new Int32Array(size);
    parentJoint = new Int32Array(size);
    bodyF = new Float64Array(size * BF);
    startCos = new Float64Array(size);
    startSin = new Float64Array(size);
    halfwayLevers = new Uint8Array(size);
  }
  if (jA.length < n) {
    const size = Math.max(n, jA.length * 2);
    jA = new Int32Array(size);
    jB = new Int32Array(size);
    jTree = new Uint8Array(size);
    jVisited = new Uint8Array(size);
    order = new Int32Array(size);
    orderChild = new Int32Array(size);
    orderParent = new Int32Array(size);
    jointF = new Float64Array(size * JF);
    adj = new Int32Array(size * 2);
  }
}

function find(x: number): number {
  while (uf[x] !== x) {
    uf[x] = uf[uf[x]];
    x = uf[x];
  }
  return x;
}

/** Local id of row `row` (0: immovable). */
function localBody(r: BodyRows, row: number, nb: number[]): number {
  if (immovable(r, row)) return 0;
  if (stamp[row] === stampNow) return localOf[row];
  stamp[row] = stampNow;
  const id = nb[0]++;
  localOf[row] = id;
  bodyRow[id] = row;
  uf[id] = id;
  return id;
}

const counter = [0];

/**
 * The levers of joint i's side `side` (0: A, 1: B), local body `local`: current (from rc, rs) and, for a movable body,
 * at the substep's start.
 */
const lev = new Float64Array(4);
function loadLevers(j: Joints, r: BodyRows, i: number, side: number, local: number): void {
  const row = side === 0 ? j.a[i] : j.b[i];
  const rx = side === 0 ? j.rAx[i] : j.rBx[i];
  const ry = side === 0 ? j.rAy[i] : j.rBy[i];
  const c = r.rc[row];
  const s = r.rs[row];
  lev[0] = c * rx - s * ry;
  lev[1] = s * rx + c * ry;
  if (local === 0) return;
  if (currentLevers) {
    lev[2] = lev[0];
    lev[3] = lev[1];
    return;
  }
  const ct = startCos[local];
  const st = startSin[local];
  lev[2] = ct * rx - st * ry;
  lev[3] = st * rx + ct * ry;
}

/**
 * Solves the revolute joints' points and the welds that form trees, once, before the sweep. False (nothing moved)
 * when no two joints share a body or a pivot came out singular.
 */
export function solveJointTrees(j: Joints, r: BodyRows, h: number): boolean {
  if (!forestValid(j, r)) buildForest(j, r);
  const m = forestJoints;
  const nb = forestBodies;
  closuresSolved = false;
  if (m < 2 && closureCount === 0) return false;
  injected = -1;
  currentLevers = false;
  halfwayLevers.fill(0, 0, nb);
  let solved = solveForest(j, r, h, m, nb);
  // Lopsided joints (LOPSIDED): solved again with their subtrees' levers half-way to now, then, if some joint is
  // still lopsided, with every body's current levers. A forest with loops takes every body's current levers at once:
  // the closing rows act through the whole forest, and mixed levers opened a sagging bridge's hinges under ten times
  // its weight twice as wide.
  const retries = closureCount > 0 ? 0 : HALFWAY_RETRIES;
  for (let retry = 0; !solved && lopsided && newlyHalfway && retry < retries; retry++) {
    // A joint's system D depends on its child's subtree alone.
    for (let k = 0; k < m; k++) if (halfwayLevers[orderParent[k]] === 1) halfwayLevers[orderChild[k]] = 1;
    solved = solveForest(j, r, h, m, nb);
  }
  if (!solved && lopsided) {
    currentLevers = true;
    solved = solveForest(j, r, h, m, nb);
  }
  if (solved) {
    if (closureCount > 0) closuresSolved = solveClosures(j, r, h, m, nb);
    applyForest(j, r, m, nb);
    // The solve is linear in the moves, the joints are not: a forest still open wider than STILL_OPEN (a whip, a heavy
    // load swinging) is solved again from where it got to (a Newton step), up to EXTRA_PASSES times. Not with loops:
    // there a second pass threw 2 of 60 random loops (5 links) about, one without bound.
    for (let pass = 0; closureCount === 0 && pass < EXTRA_PASSES && widestTreeGap(j, r, m) > STILL_OPEN; pass++) {
      if (!solveForest(j, r, h, m, nb)) break;
      applyForest(j, r, m, nb);
    }
  }
  currentLevers = false;
  return solved;
}

/**
 * Solving a loop-free forest again while a joint is open wider than STILL_OPEN: loads 100 to 2,000 times a plank's mass
 * swinging from chains of 10–30 planks gained up to 7% of their drop's energy with one pass, none with three; the
 * hinges' median over the swing went from 6·10⁻⁴ to 2·10⁻⁶. Chains of 10 links whipping take a second pass in 5% of
 * their substeps.
 */
const STILL_OPEN = 1e-5;
const EXTRA_PASSES = 2;

/** The widest of the forest's joint points now (A's anchor minus B's, current poses). */
function widestTreeGap(j: Joints, r: BodyRows, m: number): number {
  let widest = 0;
  for (let k = 0; k < m; k++) {
    const i = order[k];
    const a = j.a[i];
    const b = j.b[i];
    let ex = r.x[a] + r.rc[a] * j.rAx[i] - r.rs[a] * j.rAy[i];
    let ey = r.y[a] + r.rs[a] * j.rAx[i] + r.rc[a] * j.rAy[i];
    if (b < 0) {
      ex -= j.rBx[i];
      ey -= j.rBy[i];
    } else {
      ex -= r.x[b] + r.rc[b] * j.rBx[i] - r.rs[b] * j.rBy[i];
      ey -= r.y[b] + r.rs[b] * j.rBx[i] + r.rc[b] * j.rBy[i];
    }
    widest = Math.max(widest, ex * ex + ey * ey);
  }
  return Math.sqrt(widest);
}

/**
 * The tree's moves act through the start pose's levers S (SHAKE: a swinging chain keeps its energy) while its errors
 * are measured at the current levers L, so a joint's system D = α̃ + L·Q is not symmetric: its skew part grows with
 * the turn since the substep's start. Near a fold (a chain pulled straight between its anchor and a heavy load hinged
 * to it) D's symmetric part, the stiffness along the chain, shrinks to nearly nothing; the skew part then made D
 * indefinite and the solve threw the links about without bound (a load 100 to 900 times a plank's mass on a chain of
 * 10–30 planks blew up in 17 of 24 such scenes). Where a joint's point block has a symmetric part whose least
 * eigenvalue is not LOPSIDED times its skew part, the substep is solved again with levers half-way between the start
 * and current ones in that joint's child subtree (D depends on that subtree alone; its skew part, which grows with the
 * turn between S and L, about halves), up to HALFWAY_RETRIES times as more joints turn lopsided, then with every
 * body's current levers (S = L: D symmetric, a projection, which loses a little energy instead). Chains of equal links
 * whipping come down to 0.55 (40 links, unaffected) and 0.41 (50 links, whose whipping tail then loses 9.6% of the
 * drop energy in 10 s instead of 1.4%); the heavy loads' ratio falls through 0.5 steps before it turns negative.
 * Loads 50 to 150 times a chain of 20–30 planks (36 scenes, the chain level or tilted, planks 0.125 or 0.2 thick):
 * 16 ran away with the subtrees' current levers, 2 with half-way ones (4 with a third or 0.58 of the way from the
 * start, 7 with a quarter); with the joint's own two bodies' current levers the loads of 10–30 times blew up again,
 * and with every body's at once they gained up to 21% of their drop's energy.
 */
const LOPSIDED = 0.5;
/** How many times a substep is solved again with more bodies' levers half-way before every body's are current. */
const HALFWAY_RETRIES = 3;
/** solveForest's levers S are the current ones (the last retry after a lopsided joint). */
let currentLevers = false;
/** The last solveForest() found a lopsided joint. */
let lopsided = false;
/** The last solveForest() marked a body's levers half-way that were not. */
let newlyHalfway = false;

/**
 * The forest buildForest() last built: the joint table it was built for (a weak reference: the arrays here are shared
 * by every world of the page or worker, and a world whose table this is not builds its own), its size, tree joints,
 * local bodies (with the immovable node).
 */
let forestOwner: WeakRef<Joints> | null = null;
let forestN = -1;
let forestJoints = 0;
let forestBodies = 0;
let cKind = new Uint8Array(16);
let cRowA = new Int32Array(16);
let cRowB = new Int32Array(16);

/** The kinds a tree may hold: revolute joints (their points) and welds (points and angles). */
function treeKind(kind: number): boolean {
  return (kind as JointKind) === JointKind.Revolute || (kind as JointKind) === JointKind.Weld;
}

function immovable(r: BodyRows, row: number): boolean {
  return row < 0 || (r.invMass[row] === 0 && r.invInertia[row] === 0);
}

/** Whether the joints, their bodies and which of those are immovable are as when the forest was built. */
function forestValid(j: Joints, r: BodyRows): boolean {
  const n = j.count;
  if (n !== forestN || forestOwner?.deref() !== j) return false;
  for (let i = 0; i < n; i++) {
    const a = j.a[i];
    const b = j.b[i];
    if (j.kind[i] !== cKind[i] || a !== cRowA[i] || b !== cRowB[i]) return false;
    if (!treeKind(j.kind[i])) continue;
    if ((jA[i] === 0) !== immovable(r, a) || (jB[i] === 0) !== immovable(r, b)) return false;
  }
  return true;
}

function buildForest(j: Joints, r: BodyRows): void {
  const n = j.count;
  ensure(r.count, n);
  if (cKind.length < n) {
    cKind = new Uint8Array(jA.length);
    cRowA = new Int32Array(jA.length);
    cRowB = new Int32Array(jA.length);
  }
  forestOwner = new WeakRef(j);
  forestN = n;
  forestJoints = 0;
  forestBodies = 0;
  closureCount = 0;
  stampNow++;
  if (stampNow > 0x3fffffff) {
    stamp.fill(0);
    stampNow = 1;
  }
  counter[0] = 1;
  uf[0] = 0;
  // Spanning forest over the revolute joints and welds (world node 0).
  let treeCount = 0;
  for (let i = 0; i < n; i++) {
    jTree[i] = 0;
    cKind[i] = j.kind[i];
    cRowA[i] = j.a[i];
    cRowB[i] = j.b[i];
    if (!treeKind(j.kind[i])) continue;
    const a = localBody(r, j.a[i], counter);
    const b = localBody(r, j.b[i], counter);
    jA[i] = a;
    jB[i] = b;
    if (a === b) continue;
    const ra = find(a);
    const rb = find(b);
    if (ra === rb) {
      // A revolute joint's point that closes a loop (a bridge hinged to the world at both ends): solved with the
      // trees' response (solveClosures) while there are few; a weld closing one is swept.
      if ((j.kind[i] as JointKind) === JointKind.Revolute && closureCount < MAX_CLOSURES) {
        closures[closureCount++] = i;
        jTree[i] = 2;
      }
      continue;
    }
    uf[ra] = rb;
    jTree[i] = 1;
    treeCount++;
  }
  const nb = counter[0];
  if (treeCount < 2 && closureCount === 0) return;
  // Adjacency (CSR) of the bodies to their tree joints.
  adjCount.fill(0, 0, nb);
  for (let i = 0; i < n; i++) {
    if (jTree[i] !== 1) continue;
    adjCount[jA[i]]++;
    adjCount[jB[i]]++;
  }
  adjStart[0] = 0;
  for (let k = 0; k < nb; k++) adjStart[k + 1] = adjStart[k] + adjCount[k];
  adjCount.fill(0, 0, nb);
  for (let i = 0; i < n; i++) {
    if (jTree[i] !== 1) continue;
    adj[adjStart[jA[i]] + adjCount[jA[i]]++] = i;
    adj[adjStart[jB[i]] + adjCount[jB[i]]++] = i;
    jVisited[i] = 0;
  }
  // Breadth first from the immovable node, then from each body not reached.
  visited.fill(0, 0, nb);
  let m = 0;
  for (let root = 0; root < nb; root++) {
    if (visited[root] === 1) continue;
    visited[root] = 1;
    parentJoint[root] = -1;
    let head = 0;
    let tail = 0;
    queue[tail++] = root;
    while (head < tail) {
      const p = queue[head++];
      for (let e = adjStart[p], end = adjStart[p + 1]; e < end; e++) {
        const i = adj[e];
        if (jVisited[i] === 1) continue;
        jVisited[i] = 1;
        const c = jA[i] === p ? jB[i] : jA[i];
        visited[c] = 1;
        parentJoint[c] = m;
        order[m] = i;
        orderChild[m] = c;
        orderParent[m] = p;
        m++;
        queue[tail++] = c;
      }
    }
  }
  forestJoints = m;
  forestBodies = nb;
}

/** At most this many loops' closing joints are solved with the trees' response (each costs two more tree solves). */
const MAX_CLOSURES = 8;
/** The revolute joints that close a loop through the forest (buildForest), and how many. */
const closures = new Int32Array(MAX_CLOSURES);
let closureCount = 0;
/** Whether the last solveJointTrees() solved the closing joints too (else the sweep takes them). */
let closuresSolved = false;
/** The closing joints' row whose response solveForest() computes (closure index × 2 + row), or −1: the step's own solve. */
let injected = -1;
/** solveForest's results, one after the other: the step's own, then each closing row's response (solveClosures). */
let responses = new Float64Array(64);
/** The closing rows' system (row by row) and right-hand side, then their multipliers. */
const schur = new Float64Array(4 * MAX_CLOSURES * MAX_CLOSURES + 4 * MAX_CLOSURES);

/** Adds sign·W·Sᵀ·e_row of joint i's side `side` (start levers) to local body `local`'s right-hand side. */
function injectRow(j: Joints, r: BodyRows, i: number, side: number, local: number, row: number, sign: number): void {
  if (local === 0) return;
  loadLevers(j, r, i, side, local);
  const o = local * BF;
  const wm = r.invMass[bodyRow[local]];
  const wi = r.invInertia[bodyRow[local]];
  if (row === 0) {
    bodyF[o + 18] += sign * wm;
    bodyF[o + 20] -= sign * wi * lev[3];
  } else {
    bodyF[o + 19] += sign * wm;
    bodyF[o + 20] += sign * wi * lev[2];
  }
}

/** Copies solveForest's moves and multipliers to (or, with back, from) solution `s` of `responses`. */
function keepSolution(s: number, nb: number, m: number, back: boolean): void {
  const base = s * (3 * nb + 2 * m);
  for (let k = 1; k < nb; k++) {
    for (let q = 0; q < 3; q++) {
      if (back) bodyF[k * BF + 24 + q] = responses[base + 3 * k + q];
      else responses[base + 3 * k + q] = bodyF[k * BF + 24 + q];
    }
  }
  for (let k = 0; k < m; k++) {
    for (let q = 0; q < 2; q++) {
      if (back) jointF[k * JF + 26 + q] = responses[base + 3 * nb + 2 * k + q];
      else responses[base + 3 * nb + 2 * k + q] = jointF[k * JF + 26 + q];
    }
  }
}

/**
 * Row `row` of closing joint i's linearised change of error (its current levers) under solution `s` of `responses`:
 * L_A·Δq_A − L_B·Δq_B.
 */
function closureChange(j: Joints, r: BodyRows, i: number, row: number, s: number, nb: number, m: number): number {
  const base = s * (3 * nb + 2 * m);
  let change = 0;
  for (let side = 0; side < 2; side++) {
    const local = side === 0 ? jA[i] : jB[i];
    if (local === 0) continue;
    loadLevers(j, r, i, side, local);
    const o = base + 3 * local;
    const d = row === 0 ? responses[o] - lev[1] * responses[o + 2] : responses[o + 1] + lev[0] * responses[o + 2];
    change += side === 0 ? d : -d;
  }
  return change;
}

/**
 * The joints that close loops through the trees (a bridge hinged to the world at both ends), solved with the trees:
 * the trees' solve is linear in the closing joints' multipliers Δλ_c (they act on their bodies as known forces), so
 * Δq = Δq₀ + Σ G_c·Δλ_c, G_c the trees' response to a unit multiplier on row c (one more tree solve each), and the
 * closing rows' system (their Schur complement) C·G·Δλ_c + α̃·Δλ_c = −e − α̃·λ − C·Δq₀ gives the multipliers. Swept
 * after the trees instead, a closing joint moved only its own two bodies, and under a load the bridge opened at its
 * last hinge. False (the sweep takes them, the trees' own solve stands) when a solve comes out singular.
 */
function solveClosures(j: Joints, r: BodyRows, h: number, m: number, nb: number): boolean {
  const rows = 2 * closureCount;
  const size = (rows + 1) * (3 * nb + 2 * m);
  if (responses.length < size) responses = new Float64Array(Math.max(size, 2 * responses.length));
  keepSolution(0, nb, m, false);
  for (let q = 0; q < rows; q++) {
    injected = q;
    const solved = solveForest(j, r, h, m, nb);
    injected = -1;
    if (!solved) {
      keepSolution(0, nb, m, true);
      return false;
    }
    keepSolution(q + 1, nb, m, false);
  }
  const h2 = h * h;
  const rhs = rows * rows;
  for (let p = 0; p < rows; p++) {
    const i = closures[p >> 1];
    const row = p & 1;
    const alphaT = j.compliance[i] / h2;
    for (let q = 0; q < rows; q++) schur[p * rows + q] = closureChange(j, r, i, row, q + 1, nb, m) + (p === q ? alphaT : 0);
    // The error: A's anchor minus B's (B the world: its anchor is rB itself).
    const a = j.a[i];
    const b = j.b[i];
    loadLevers(j, r, i, 0, 0);
    let e = row === 0 ? r.x[a] + lev[0] : r.y[a] + lev[1];
    if (b < 0) e -= row === 0 ? j.rBx[i] : j.rBy[i];
    else {
      loadLevers(j, r, i, 1, 0);
      e -= row === 0 ? r.x[b] + lev[0] : r.y[b] + lev[1];
    }
    schur[rhs + p] = -e - alphaT * (row === 0 ? j.lambda[i] : j.lambdaY[i]) - closureChange(j, r, i, row, 0, nb, m);
  }
  if (!solveDense(rows)) {
    keepSolution(0, nb, m, true);
    return false;
  }
  // Δq = Δq₀ + f·Σ G_c·Δλ_c, and the trees' multipliers likewise; f keeps the closing part's turn of every body
  // within MAX_TURN, as withinTurn does for a swept joint: near a chain pulled straight between its ends the loop has
  // no finite answer, and the linearised one turns the links far (a straight bridge under a box three times its weight
  // opened gaps of 0.23 without it, 0.10 with it).
  const stride = 3 * nb + 2 * m;
  let turn = 0;
  for (let k = 1; k < nb; k++) {
    let t = 0;
    for (let c = 0; c < rows; c++) t += schur[rhs + c] * responses[(c + 1) * stride + 3 * k + 2];
    if (Math.abs(t) > turn) turn = Math.abs(t);
  }
  if (turn > MAX_TURN) for (let c = 0; c < rows; c++) schur[rhs + c] *= MAX_TURN / turn;
  for (let k = 1; k < nb; k++) {
    for (let q = 0; q < 3; q++) {
      let v = responses[3 * k + q];
      for (let c = 0; c < rows; c++) v += schur[rhs + c] * responses[(c + 1) * stride + 3 * k + q];
      bodyF[k * BF + 24 + q] = v;
    }
  }
  for (let k = 0; k < m; k++) {
    for (let q = 0; q < 2; q++) {
      let v = responses[3 * nb + 2 * k + q];
      for (let c = 0; c < rows; c++) v += schur[rhs + c] * responses[(c + 1) * stride + 3 * nb + 2 * k + q];
      jointF[k * JF + 26 + q] = v;
    }
  }
  for (let c = 0; c < closureCount; c++) {
    j.lambda[closures[c]] += schur[rhs + 2 * c];
    j.lambdaY[closures[c]] += schur[rhs + 2 * c + 1];
  }
  return true;
}

/** Solves schur's n×n system in place (Gaussian elimination, partial pivoting): x over the right-hand side. */
function solveDense(n: number): boolean {
  const rhs = n * n;
  let scale = 0;
  for (let p = 0; p < n; p++) scale = Math.max(scale, Math.abs(schur[p * n + p]));
  for (let col = 0; col < n; col++) {
    let pivot = col;
    for (let p = col + 1; p < n; p++) if (Math.abs(schur[p * n + col]) > Math.abs(schur[pivot * n + col])) pivot = p;
    if (!(Math.abs(schur[pivot * n + col]) > 1e-12 * scale)) return false;
    if (pivot !== col) {
      for (let q = 0; q < n; q++) {
        const t = schur[col * n + q];
        schur[col * n + q] = schur[pivot * n + q];
        schur[pivot * n + q] = t;
      }
      const t = schur[rhs + col];
      schur[rhs + col] = schur[rhs + pivot];
      schur[rhs + pivot] = t;
    }
    for (let p = col + 1; p < n; p++) {
      const f = schur[p * n + col] / schur[col * n + col];
      if (f === 0) continue;
      for (let q = col; q < n; q++) schur[p * n + q] -= f * schur[col * n + q];
      schur[rhs + p] -= f * schur[rhs + col];
    }
  }
  for (let p = n - 1; p >= 0; p--) {
    let v = schur[rhs + p];
    for (let q = p + 1; q < n; q++) v -= schur[p * n + q] * schur[rhs + q];
    schur[rhs + p] = v / schur[p * n + p];
  }
  return true;
}

/** The least |det| inverse3() inverts (a typed array, as dk: no double passed to a call). */
const minDet = new Float64Array(1);

/**
 * The inverse of the 3×3 matrix m[mo..mo+8] (row by row, by cofactors) into inv[io..io+8], and inv·v (v = rhs[ro..
 * ro+2]) into out[oo..oo+2]; false when |det| ≤ minDet[0].
 */
function inverse3(m: Float64Array, mo: number, inv: Float64Array, io: number, rhs: Float64Array, ro: number, out: Float64Array, oo: number): boolean {
  const d0 = m[mo], d1 = m[mo + 1], d2 = m[mo + 2];
  const d3 = m[mo + 3], d4 = m[mo + 4], d5 = m[mo + 5];
  const d6 = m[mo + 6], d7 = m[mo + 7], d8 = m[mo + 8];
  const c0 = d4 * d8 - d5 * d7;
  const c1 = d5 * d6 - d3 * d8;
  const c2 = d3 * d7 - d4 * d6;
  const det = d0 * c0 + d1 * c1 + d2 * c2;
  if (!(Math.abs(det) > minDet[0])) return false;
  const id = 1 / det;
  const p0 = c0 * id, p1 = (d2 * d7 - d1 * d8) * id, p2 = (d1 * d5 - d2 * d4) * id;
  const p3 = c1 * id, p4 = (d0 * d8 - d2 * d6) * id, p5 = (d2 * d3 - d0 * d5) * id;
  const p6 = c2 * id, p7 = (d1 * d6 - d0 * d7) * id, p8 = (d0 * d4 - d1 * d3) * id;
  inv[io] = p0; inv[io + 1] = p1; inv[io + 2] = p2;
  inv[io + 3] = p3; inv[io + 4] = p4; inv[io + 5] = p5;
  inv[io + 6] = p6; inv[io + 7] = p7; inv[io + 8] = p8;
  const r0 = rhs[ro], r1 = rhs[ro + 1], r2 = rhs[ro + 2];
  out[oo] = p0 * r0 + p1 * r1 + p2 * r2;
  out[oo + 1] = p3 * r0 + p4 * r1 + p5 * r2;
  out[oo + 2] = p6 * r0 + p7 * r1 + p8 * r2;
  return true;
}

/** The body at bodyF[o]: P = D⁻¹ (its 3×3 block) into its fields 9–17, and y = P·rhs into 21–23; false when D is singular. */
function invertBody(o: number): boolean {
  minDet[0] = 1e-12;
  return inverse3(bodyF, o, bodyF, o + 9, bodyF, o + 18, bodyF, o + 21);
}

/**
 * Dk⁻¹ of the joint at jointF[f] (fields 1–9) from its 3×3 D (dk), and z = Dk⁻¹·e (e in its fields 10–12); false
 * when D is singular. A revolute joint's D (w = 0) is block-diagonal, its angle row the identity: only its point's
 * 2×2 block is inverted.
 */
const z = new Float64Array(3);
/** D of the joint being solved, row by row (a typed array: V8 boxes doubles passed to a call it does not inline). */
const dk = new Float64Array(9);
function invertJoint(f: number, w: number): boolean {
  const d0 = dk[0], d1 = dk[1], d3 = dk[3], d4 = dk[4];
  const point = Math.abs(d0) + Math.abs(d4);
  if (w === 1) {
    minDet[0] = 1e-14 * point * point * Math.abs(dk[8]);
    return inverse3(dk, 0, jointF, f + 1, jointF, f + 10, z, 0);
  }
  const det = d0 * d4 - d1 * d3;
  if (!(Math.abs(det) > 1e-14 * point * point)) return false;
  const id = 1 / det;
  const p0 = d4 * id, p1 = -d1 * id, p3 = -d3 * id, p4 = d0 * id;
  jointF[f + 1] = p0; jointF[f + 2] = p1; jointF[f + 3] = 0;
  jointF[f + 4] = p3; jointF[f + 5] = p4; jointF[f + 6] = 0;
  jointF[f + 7] = 0; jointF[f + 8] = 0; jointF[f + 9] = 1;
  const e0 = jointF[f + 10], e1 = jointF[f + 11];
  z[0] = p0 * e0 + p1 * e1;
  z[1] = p3 * e0 + p4 * e1;
  z[2] = 0;
  return true;
}

/** The numbers: up the forest, the roots, down, then the moves. */
function solveForest(j: Joints, r: BodyRows, h: number, m: number, nb: number): boolean {
  lopsided = false;
  newlyHalfway = false;
  // Bodies start at D = I, rhs = 0; cos and sin of their angles at the substep's start (half-way to now, for the
  // bodies below a lopsided joint).
  for (let k = 1; k < nb; k++) {
    const o = k * BF;
    const row = bodyRow[k];
    const t = halfwayLevers[k] === 1 ? 0.5 * (r.pangle[row] + r.angle[row]) : r.pangle[row];
    startCos[k] = Math.cos(t);
    startSin[k] = Math.sin(t);
    for (let q = 0; q < 9; q++) bodyF[o + q] = 0;
    bodyF[o] = bodyF[o + 4] = bodyF[o + 8] = 1;
    bodyF[o + 18] = bodyF[o + 19] = bodyF[o + 20] = 0;
  }
  // The response to a unit multiplier on one row of a loop's closing joint: W·S_Aᵀ·e on its side A, −W·S_Bᵀ·e on B.
  if (injected >= 0) {
    const i = closures[injected >> 1];
    injectRow(j, r, i, 0, jA[i], injected & 1, 1);
    injectRow(j, r, i, 1, jB[i], injected & 1, -1);
  }
  // Homogeneous (a response): no joint's error or multiplier enters the right-hand side.
  const own = injected < 0 ? 1 : 0;
  const h2 = h * h;
  // Up: each joint, children first. A joint's rows: the point (x, y) and, for a weld (w = 1), the relative angle; a
  // revolute joint's angle row is empty (w = 0: no Jacobian, D's diagonal 1, no error), so its multiplier stays 0.
  for (let k = m - 1; k >= 0; k--) {
    const i = order[k];
    const c = orderChild[k];
    const p = orderParent[k];
    const cRow = bodyRow[c];
    const sideC = jA[i] === c ? 0 : 1;
    const sigC = sideC === 0 ? 1 : -1;
    const w = (j.kind[i] as JointKind) === JointKind.Weld ? 1 : 0;
    const o = c * BF;
    // P = D_c⁻¹, y = P·rhs_c.
    if (!invertBody(o)) return false;
    const p0 = bodyF[o + 9], p1 = bodyF[o + 10], p2 = bodyF[o + 11];
    const p3 = bodyF[o + 12], p4 = bodyF[o + 13], p5 = bodyF[o + 14];
    const p6 = bodyF[o + 15], p7 = bodyF[o + 16], p8 = bodyF[o + 17];
    const y0 = bodyF[o + 21], y1 = bodyF[o + 22], y2 = bodyF[o + 23];
    // Q = P·W_c·S_cᵀ (3×3).
    loadLevers(j, r, i, sideC, c);
    const lx = lev[0], ly = lev[1], sx = lev[2], sy = lev[3];
    const wm = r.invMass[cRow];
    const wi = r.invInertia[cRow];
    const q00 = p0 * wm - p2 * wi * sy, q01 = p1 * wm + p2 * wi * sx;
    const q10 = p3 * wm - p5 * wi * sy, q11 = p4 * wm + p5 * wi * sx;
    const q20 = p6 * wm - p8 * wi * sy, q21 = p7 * wm + p8 * wi * sx;
    // The angle row's column (a weld's only).
    const q02 = w === 1 ? p2 * wi : 0, q12 = w === 1 ? p5 * wi : 0, q22 = w === 1 ? p8 * wi : 0;
    const f = k * JF;
    jointF[f] = sigC;
    jointF[f + 13] = q00; jointF[f + 14] = q01; jointF[f + 15] = q02;
    jointF[f + 16] = q10; jointF[f + 17] = q11; jointF[f + 18] = q12;
    jointF[f + 19] = q20; jointF[f + 20] = q21; jointF[f + 21] = q22;
    jointF[f + 29] = w;
    // D_k = α̃ (on the point's rows) + L_c·Q; rhs_k = −c − α̃λ − σ_c·L_c·y.
    const alphaT = j.compliance[i] / h2;
    dk[0] = alphaT + q00 - ly * q20;
    dk[1] = q01 - ly * q21;
    dk[2] = q02 - ly * q22;
    dk[3] = q10 + lx * q20;
    dk[4] = alphaT + q11 + lx * q21;
    dk[5] = q12 + lx * q22;
    dk[6] = w * q20;
    dk[7] = w * q21;
    dk[8] = w === 1 ? q22 : 1;
    // Parent side's levers, and the error: A's anchor minus B's (current poses).
    let plx = 0, ply = 0, psx = 0, psy = 0;
    if (p !== 0) {
      loadLevers(j, r, i, 1 - sideC, p);
      plx = lev[0]; ply = lev[1]; psx = lev[2]; psy = lev[3];
    }
    const rowA = j.a[i];
    const rowB = j.b[i];
    let ex: number;
    let ey: number;
    if (sideC === 0) {
      ex = r.x[rowA] + lx;
      ey = r.y[rowA] + ly;
      if (rowB < 0) {
        ex -= j.rBx[i];
        ey -= j.rBy[i];
      } else {
        if (p === 0) {
          loadLevers(j, r, i, 1, 0);
          plx = lev[0];
          ply = lev[1];
        }
        ex -= r.x[rowB] + plx;
        ey -= r.y[rowB] + ply;
      }
    } else {
      if (p === 0) {
        loadLevers(j, r, i, 0, 0);
        plx = lev[0];
        ply = lev[1];
      }
      ex = r.x[rowA] + plx - (r.x[rowB] + lx);
      ey = r.y[rowA] + ply - (r.y[rowB] + ly);
    }
    jointF[f + 10] = own * (-ex - alphaT * j.lambda[i]) - sigC * (y0 - ly * y2);
    jointF[f + 11] = own * (-ey - alphaT * j.lambdaY[i]) - sigC * (y1 + lx * y2);
    jointF[f + 12] = w === 1 ? -own * (r.angle[rowA] - (rowB < 0 ? 0 : r.angle[rowB]) - j.refAngle[i]) - sigC * y2 : 0;
    // The point block's symmetric part's least eigenvalue against its skew part (see LOPSIDED).
    if (!currentLevers) {
      const mean = 0.5 * (dk[0] + dk[4]);
      const spread = Math.sqrt(0.25 * (dk[0] - dk[4]) * (dk[0] - dk[4]) + 0.25 * (dk[1] + dk[3]) * (dk[1] + dk[3]));
      if (!(mean - spread > LOPSIDED * 0.5 * Math.abs(dk[1] - dk[3]))) {
        lopsided = true;
        if (halfwayLevers[c] === 0) newlyHalfway = true;
        halfwayLevers[c] = 1;
      }
    }
    if (!invertJoint(f, w)) return false;
    jointF[f + 22] = plx; jointF[f + 23] = ply;
    jointF[f + 24] = psx; jointF[f + 25] = psy;
    if (p === 0) continue;
    // Into the parent: D_p += W_p·S_pᵀ·Dk⁻¹·L_p, rhs_p += σ_p·W_p·S_pᵀ·Dk⁻¹·rhs_k (σ_p = −σ_c).
    const pRow = bodyRow[p];
    const pm = r.invMass[pRow];
    const pi = r.invInertia[pRow];
    const i00 = jointF[f + 1], i01 = jointF[f + 2], i02 = jointF[f + 3];
    const i10 = jointF[f + 4], i11 = jointF[f + 5], i12 = jointF[f + 6];
    const i20 = jointF[f + 7], i21 = jointF[f + 8], i22 = jointF[f + 9];
    // R = Dk⁻¹·L_p (3×3; its first two columns are Dk⁻¹'s), and D_p += W_p·S_pᵀ·R: the angle row's terms for a weld.
    let R02 = -ply * i00 + plx * i01;
    let R12 = -ply * i10 + plx * i11;
    const op = p * BF;
    const sigP = -sigC;
    if (w === 1) {
      R02 += i02;
      R12 += i12;
      const R22 = -ply * i20 + plx * i21 + i22;
      bodyF[op + 6] += pi * i20;
      bodyF[op + 7] += pi * i21;
      bodyF[op + 8] += pi * R22;
      bodyF[op + 20] += sigP * pi * z[2];
    }
    bodyF[op] += pm * i00; bodyF[op + 1] += pm * i01; bodyF[op + 2] += pm * R02;
    bodyF[op + 3] += pm * i10; bodyF[op + 4] += pm * i11; bodyF[op + 5] += pm * R12;
    bodyF[op + 6] += pi * (-psy * i00 + psx * i10);
    bodyF[op + 7] += pi * (-psy * i01 + psx * i11);
    bodyF[op + 8] += pi * (-psy * R02 + psx * R12);
    bodyF[op + 18] += sigP * pm * z[0];
    bodyF[op + 19] += sigP * pm * z[1];
    bodyF[op + 20] += sigP * pi * (-psy * z[0] + psx * z[1]);
  }
  if (lopsided) return false;
  // Roots: x = D⁻¹·rhs.
  for (let c = 1; c < nb; c++) {
    if (parentJoint[c] !== -1) continue;
    const o = c * BF;
    if (!invertBody(o)) return false;
    bodyF[o + 24] = bodyF[o + 21];
    bodyF[o + 25] = bodyF[o + 22];
    bodyF[o + 26] = bodyF[o + 23];
  }
  // Down: each joint's Δλ from its parent's move, then its child's move.
  for (let k = 0; k < m; k++) {
    const f = k * JF;
    const p = orderParent[k];
    const w = jointF[f + 29];
    let e0 = jointF[f + 10];
    let e1 = jointF[f + 11];
    let e2 = jointF[f + 12];
    if (p !== 0) {
      const op = p * BF;
      const x0 = bodyF[op + 24], x1 = bodyF[op + 25], x2 = bodyF[op + 26];
      const sigP = -jointF[f];
      e0 -= sigP * (x0 - jointF[f + 23] * x2);
      e1 -= sigP * (x1 + jointF[f + 22] * x2);
      e2 -= sigP * w * x2;
    }
    const l0 = jointF[f + 1] * e0 + jointF[f + 2] * e1 + jointF[f + 3] * e2;
    const l1 = jointF[f + 4] * e0 + jointF[f + 5] * e1 + jointF[f + 6] * e2;
    const l2 = jointF[f + 7] * e0 + jointF[f + 8] * e1 + jointF[f + 9] * e2;
    jointF[f + 26] = l0;
    jointF[f + 27] = l1;
    jointF[f + 28] = l2;
    const oc = orderChild[k] * BF;
    const sigC = jointF[f];
    bodyF[oc + 24] = bodyF[oc + 21] + sigC * (jointF[f + 13] * l0 + jointF[f + 14] * l1 + jointF[f + 15] * l2);
    bodyF[oc + 25] = bodyF[oc + 22] + sigC * (jointF[f + 16] * l0 + jointF[f + 17] * l1 + jointF[f + 18] * l2);
    bodyF[oc + 26] = bodyF[oc + 23] + sigC * (jointF[f + 19] * l0 + jointF[f + 20] * l1 + jointF[f + 21] * l2);
  }
  return true;
}

/**
 * The most a forest's solve may turn a body in one substep: a larger turn is a Newton step taken too far (the solve is
 * linear in the turns), and every move and multiplier is scaled down by the same factor, the next passes and
 * substeps finishing the step. Taken whole, after a hard hit had opened a chain, the linear answer turned bodies by
 * radians at once and each correction overshot the last: of 300 random hits by boxes 1–200 times heavier on two
 * bodies hinged together (one of them to the world half the time), 16 threw them at 10³–10¹² units/s, and with a weld
 * instead 22. Scaled down to 1 rad: 1 and 0 (to 0.5 rad, MAX_TURN, 2 and 0, but 5 of the 36 heavy loads on chains of
 * joint-tree.test.ts ran away instead of 3; to 1 rad, 2).
 */
const TREE_MAX_TURN = 1;

/** The multipliers and moves solveForest (and solveClosures) found (scaled to TREE_MAX_TURN): added to the joints and the rows. */
function applyForest(j: Joints, r: BodyRows, m: number, nb: number): void {
  let widest = 0;
  for (let c = 1; c < nb; c++) if (visited[c] !== 0) widest = Math.max(widest, Math.abs(bodyF[c * BF + 26]));
  const f = widest > TREE_MAX_TURN ? TREE_MAX_TURN / widest : 1;
  for (let k = 0; k < m; k++) {
    const i = order[k];
    j.lambda[i] += f * jointF[k * JF + 26];
    j.lambdaY[i] += f * jointF[k * JF + 27];
  }
  for (let c = 1; c < nb; c++) {
    if (visited[c] === 0) continue;
    const o = c * BF;
    const row = bodyRow[c];
    r.x[row] += f * bodyF[o + 24];
    r.y[row] += f * bodyF[o + 25];
    const t = f * bodyF[o + 26];
    if (t !== 0) {
      spin[0] = t;
      turnBySpin(r, row);
    }
  }
}
