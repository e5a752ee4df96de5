// Revolute joints and welds solved over the trees they form (rigid/joint-tree.ts), on random trees of 2 to 12 bodies: boxes
// and discs whose masses span 10⁴, each hinged to the world or to a body within 3 units of its anchor, the anchor at
// the body's centre of mass, half its size or twice its size off it, a fifth of the joints soft. After every step the
// state is finite; at the end every rigid hinge holds its anchors together and no energy has appeared. Swept joint by
// joint, as before the tree solve, 19 of these 60 trees failed (hinges apart, energy gained, or blown up); limits,
// motors and loops (which the sweep keeps) are in physics.test.ts.
import { expect } from 'chai';
import { World, type Handle, type Vec2 } from '../../../src/engine/index.js';
import { rng } from '../collision/helpers.js';
import { box, rigidEnergy } from '../helpers.js';


interface Hinge {
  a: Handle;
  b: Handle | null;
  /** Each side's anchor in its body's frame (B's in the world's when b is null). */
  la: Vec2;
  lb: Vec2;
  soft: boolean;
  /** A weld's relative angle (A's minus B's) as made; null for a revolute joint. */
  weld: number | null;
}

/** A point given in a body's frame (the world's for null), in the world's. */
function worldPoint(world: World, h: Handle | null, local: Vec2): Vec2 {
  if (h === null) return local;
  const p = world.bodyPose(h);
  const c = Math.cos(p.angle);
  const s = Math.sin(p.angle);
  return { x: p.x + c * local.x - s * local.y, y: p.y + s * local.x + c * local.y };
}

/** A point given in the world, in a body's frame. */
function localPoint(world: World, h: Handle, point: Vec2): Vec2 {
  const p = world.bodyPose(h);
  const c = Math.cos(p.angle);
  const s = Math.sin(p.angle);
  const dx = point.x - p.x;
  const dy = point.y - p.y;
  return { x: c * dx + s * dy, y: -s * dx + c * dy };
}

/**
 * Steps `scenes` random trees (see the file's head; with `welds`, a third of the joints welds) 300 steps each in both
 * kernels and checks them; returns the joints made.
 */
function randomTrees(scenes: number, seed: number, welds: boolean): number {
  let joints = 0;
  for (let scene = 0; scene < scenes; scene++) {
    const rnd = rng(seed + scene);
    const kernel = scene % 2 ? 'wasm' : 'js';
    const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false });
    const bodies: Handle[] = [];
    const hinges: Hinge[] = [];
    const count = 2 + Math.floor(rnd() * 11);
    for (let k = 0; k < count; k++) {
      const size = 0.1 + rnd() * 2;
      const x = (rnd() * 2 - 1) * 4;
      const y = (rnd() * 2 - 1) * 4;
      const density = 10 ** (rnd() * 4 - 2) / (size * size);
      const body = world.addRigidBody({
        ...(rnd() < 0.4 ? { radius: size / 2 } : { points: box(size / 2, size / (2 + rnd() * 6)) }),
        x, y, angle: rnd() * 6, density, collide: false,
      });
      const reach = [0, size / 2, 2 * size][Math.floor(rnd() * 3)];
      const anchor = { x: x + (rnd() * 2 - 1) * reach, y: y + (rnd() * 2 - 1) * reach };
      const near = bodies.filter((h) => {
        const p = world.bodyPose(h);
        return Math.hypot(p.x - anchor.x, p.y - anchor.y) < 3;
      });
      const b = k === 0 || rnd() < 0.15 || near.length === 0 ? null : near[Math.floor(rnd() * near.length)];
      const soft = rnd() < 0.2;
      const type = welds && rnd() < 1 / 3 ? 'weld' : 'revolute';
      world.addJoint({ type, a: body, b, anchor, ...(soft ? { compliance: 10 ** (-6 + rnd() * 4) } : {}) });
      const relative = world.bodyPose(body).angle - (b === null ? 0 : world.bodyPose(b).angle);
      hinges.push({ a: body, b, la: localPoint(world, body, anchor), lb: b === null ? anchor : localPoint(world, b, anchor), soft, weld: type === 'weld' ? relative : null });
      bodies.push(body);
    }
    joints += hinges.length;
    const energy = (): number => rigidEnergy(world, bodies, 10);
    // The scene's energy scale: its mass falling 10 units.
    const scale = bodies.reduce((s, h) => s + world.bodyMassInfo(h).mass, 0) * 10 * 10;
    world.step();
    const start = energy();
    for (let s = 0; s < 300; s++) {
      world.step();
      for (const h of bodies) {
        const p = world.bodyPose(h);
        const v = world.bodyVelocity(h);
        const finite = [p.x, p.y, p.angle, v.x, v.y, world.bodyAngularVelocity(h)].every(Number.isFinite);
        expect(finite, `scene ${scene} (${kernel}), step ${s}: finite`).to.equal(true);
      }
    }
    // Rigid joints hold their anchors together (relative to the levers they hang on), welds their angle too; soft
    // ones may stretch.
    for (const hinge of hinges) {
      if (hinge.soft) continue;
      const pa = worldPoint(world, hinge.a, hinge.la);
      const pb = worldPoint(world, hinge.b, hinge.lb);
      const lever = 1 + Math.hypot(hinge.la.x, hinge.la.y) + Math.hypot(hinge.lb.x, hinge.lb.y);
      expect(Math.hypot(pa.x - pb.x, pa.y - pb.y) / lever, `scene ${scene} (${kernel}): hinge gap`).to.be.below(0.02);
      if (hinge.weld === null) continue;
      const relative = world.bodyPose(hinge.a).angle - (hinge.b === null ? 0 : world.bodyPose(hinge.b).angle);
      expect(Math.abs(relative - hinge.weld), `scene ${scene} (${kernel}): weld angle`).to.be.below(0.02);
    }
    expect((energy() - start) / scale, `scene ${scene} (${kernel}): energy gained`).to.be.below(0.01);
  }
  return joints;
}

/**
 * The hinge points of `planks` chords of length 1 on a circular arc sagging below the x axis between its ends, which
 * are 0.9·planks apart (the first at the origin).
 */
function sagging(planks: number): Vec2[] {
  let lo = 0.5;
  let hi = 1e6;
  for (let it = 0; it < 200; it++) {
    const r = (lo + hi) / 2;
    const half = planks * Math.asin(1 / (2 * r));
    if (half > Math.PI / 2 || r * Math.sin(half) < 0.45 * planks) lo = r;
    else hi = r;
  }
  const half = planks * Math.asin(1 / (2 * lo));
  return Array.from({ length: planks + 1 }, (_, k): Vec2 => {
    const t = -half + (2 * half * k) / planks;
    return { x: lo * (Math.sin(t) + Math.sin(half)), y: lo * (Math.cos(t) - Math.cos(half)) };
  });
}

/** Bars hinged end to end along `points`, the first to the world at points[0] and, when `closed`, the last at the end. */
interface BarChain {
  bodies: Handle[];
  points: Vec2[];
  /** Each bar's half length (its hinges at ∓half along its x axis). */
  halves: number[];
  closed: boolean;
}

/**
 * A bar from each point to the next, `halfThickness` thick each side: length 1 (planks) or, without `length`, the
 * distance between its points; density 1 or `density()` bar by bar.
 */
function barChain(world: World, points: Vec2[], o: { closed: boolean; halfThickness: number; length?: number; density?: () => number; collide?: boolean }): BarChain {
  const bodies: Handle[] = [];
  const halves: number[] = [];
  for (let k = 0; k + 1 < points.length; k++) {
    const [p, q] = [points[k], points[k + 1]];
    halves.push((o.length ?? Math.hypot(q.x - p.x, q.y - p.y)) / 2);
    bodies.push(world.addRigidBody({
      points: box(halves[k], o.halfThickness), x: (p.x + q.x) / 2, y: (p.y + q.y) / 2, angle: Math.atan2(q.y - p.y, q.x - p.x),
      ...(o.density ? { density: o.density() } : {}), ...(o.collide === false ? { collide: false } : {}),
    }));
    world.addJoint({ type: 'revolute', a: bodies[k], b: k === 0 ? null : bodies[k - 1], anchor: p });
  }
  if (o.closed) world.addJoint({ type: 'revolute', a: bodies[bodies.length - 1], b: null, anchor: points[points.length - 1] });
  return { bodies, points, halves, closed: o.closed };
}

/**
 * Planks of length 1 hinged along `points` (the first to the world), and a 1 × 1 box `times` the chain's mass hinged
 * 1.5 below its middle hinge; the energy scale is the load's drop by half the chain's length.
 */
function loadedChain(world: World, points: Vec2[], times: number, halfThickness: number, collide: boolean): { chain: BarChain; all: Handle[]; scale: number } {
  const chain = barChain(world, points, { closed: false, halfThickness, length: 1, collide });
  const planks = chain.bodies.length;
  const mass = chain.bodies.reduce((sum, b) => sum + world.bodyMassInfo(b).mass, 0);
  const middle = points[planks >> 1];
  const load = world.addRigidBody({ points: box(0.5, 0.5), x: middle.x, y: middle.y + 1.5, density: times * mass, collide: false });
  world.addJoint({ type: 'revolute', a: load, b: chain.bodies[planks >> 1], anchor: middle });
  return { chain, all: [...chain.bodies, load], scale: (times * mass * 10 * planks) / 2 };
}

/** The widest of a chain's hinges now: between its bars, at its first anchor and (closed) its last. */
function widestHinge(world: World, chain: BarChain): number {
  const { bodies, points, halves } = chain;
  const n = bodies.length;
  let gap = 0;
  for (let k = 0; k <= (chain.closed ? n : n - 1); k++) {
    const a = k === 0 ? points[0] : worldPoint(world, bodies[k - 1], { x: halves[k - 1], y: 0 });
    const b = k === n ? points[n] : worldPoint(world, bodies[k], { x: -halves[k], y: 0 });
    gap = Math.max(gap, Math.hypot(a.x - b.x, a.y - b.y));
  }
  return gap;
}

describe('rigid joints: revolute and weld trees solved at once', () => {
  it('60 random trees (masses 10⁴ apart, anchors off the centres, soft joints) stay finite, joined and without energy from nowhere, in both kernels', () => {
    expect(randomTrees(60, 4242, false)).to.be.above(300);
  });

  it('a load 100 to 2,000 times a plank\'s mass, hinged to the middle of a chain of 10–30 planks, swings without blowing up or gaining energy (32 scenes)', () => {
    // Planks 1 × 0.125 hinged end to end and to the world at one end, laid level or on a sagging arc, colliding with
    // one another or not; a box of 10 or 30 times the chain's mass (and 100 times a chain of 10 or 20) hinged 1.5
    // below the middle hinge. As the load swings it pulls the chain above it straight (a fold): before the tree solve
    // stepped aside there (joint-tree.ts, LOPSIDED), 17 of the 24 lighter scenes blew up, planks flung at 10¹¹ units/s.
    // With one tree pass a substep (no EXTRA_PASSES) the loads gained up to 7% of their drop's energy (21% while the
    // lopsided retry took every body's levers), planks whipped at up to 79 units/s, the hinges' median over the last
    // 5 s reached 6·10⁻⁴, and 100 times a chain of 20 blew up. What is left: 100 times a chain of 30 still blows up.
    const seen = { rise: 0, speed: 0, gap: 0 };
    for (const planks of [10, 20, 30])
      for (const times of planks < 30 ? [10, 30, 100] : [10, 30])
        for (const arc of [false, true])
          for (const collide of [false, true]) {
            const label = `${planks} planks, a load ${times}× the chain, ${arc ? 'on an arc' : 'level'}, ${collide ? '' : 'not '}colliding`;
            const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
            const points = arc ? sagging(planks) : Array.from({ length: planks + 1 }, (_, k): Vec2 => ({ x: k, y: 0 }));
            const { chain: chainOfPlanks, all, scale } = loadedChain(world, points, times, 0.0625, collide);
            const bodies = chainOfPlanks.bodies;
            const start = rigidEnergy(world, all, 10);
            let rise = 0;
            let speed = 0;
            // The widest hinge every step of the last 5 s: it opens for a step or two as the free planks whip (up to
            // 0.06 under loads of 10 and 30 times the chain), so its median is what says the chain holds (at most 4·10⁻⁶).
            const gaps: number[] = [];
            for (let s = 1; s <= 600; s++) {
              world.step();
              if (s > 300) gaps.push(widestHinge(world, chainOfPlanks));
              if (s % 5 !== 0) continue;
              rise = Math.max(rise, (rigidEnergy(world, all, 10) - start) / scale);
              for (const b of bodies) speed = Math.max(speed, Math.hypot(world.bodyVelocity(b).x, world.bodyVelocity(b).y));
            }
            const gap = gaps.sort((a, b) => a - b)[gaps.length >> 1];
            expect(speed, `${label}: fastest plank`).to.be.below(100);
            expect(rise, `${label}: energy gained over the load's drop`).to.be.below(0.01);
            expect(gap, `${label}: the widest hinge's median over the last 5 s`).to.be.below(1e-4);
            seen.rise = Math.max(seen.rise, rise);
            seen.speed = Math.max(seen.speed, speed);
            seen.gap = Math.max(seen.gap, gap);
          }
    console.log(`      worst: energy gained ${seen.rise.toFixed(3)} of the drop, plank ${seen.speed.toFixed(1)} units/s, widest hinge's median ${seen.gap.toExponential(1)}`);
  });

  it('loads 50 to 150 times a chain of 20–30 planks (1,000 to 4,500 times a plank) mostly swing without running away (36 scenes)', () => {
    // Beyond the test above: chains level or tilted by 0.3 rad, planks 0.125 or 0.2 thick, not colliding. Below a
    // lopsided joint the retry moves bodies along levers half-way between the substep's start and now (joint-tree.ts,
    // LOPSIDED): 2 of these 36 run away (a plank past 150 units/s or a quarter of the drop's energy gained; 3 before a
    // forest's turns were capped at TREE_MAX_TURN, 5 with the cap at 0.5 rad); along the current levers 17 did. Which ones is chaotic: the planks laid at angle 0.3 instead of atan2 of their ends (the
    // last bits of a double) gave 2 and 16, a quarter of the way to now 7. What is left: engine.md's known limits.
    let runaways = 0;
    for (const planks of [20, 25, 30])
      for (const times of [50, 100, 150])
        for (const tilt of [0, 0.3])
          for (const halfThickness of [0.0625, 0.1]) {
            const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
            const points = Array.from({ length: planks + 1 }, (_, k): Vec2 => ({ x: k * Math.cos(tilt), y: k * Math.sin(tilt) }));
            const { chain, all, scale } = loadedChain(world, points, times, halfThickness, false);
            const bodies = chain.bodies;
            const start = rigidEnergy(world, all, 10);
            let ranAway = false;
            for (let s = 1; s <= 600 && !ranAway; s++) {
              world.step();
              if (s % 5 !== 0) continue;
              ranAway = !((rigidEnergy(world, all, 10) - start) / scale < 0.25) || bodies.some((b) => !(Math.hypot(world.bodyVelocity(b).x, world.bodyVelocity(b).y) < 150));
            }
            if (ranAway) runaways++;
          }
    console.log(`      ${runaways} of 36 ran away`);
    expect(runaways).to.be.at.most(3);
  });

  it('a sagging bridge of 30 planks hinged to the world at both ends holds its hinges with the loop solved with the tree', () => {
    // On a circular arc whose ends are 27 apart, a box of 0 to 30 times the bridge's mass hung by a hinge 1.5 below its
    // middle hinge. Its last hinge closes a loop through the world: swept after the tree, it opened gaps of 0.0026,
    // 0.031, 0.085, 0.22 and 0.33 (and tore under the 30 times before the lopsided retry); solved with the tree
    // (solveClosures), the first three hold to rounding.
    const limits = { 0: 1e-8, 1: 1e-4, 3: 1e-4, 10: 0.02, 30: 0.4 };
    for (const times of [0, 1, 3, 10, 30] as const) {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
      const points = sagging(30);
      const bridge = barChain(world, points, { closed: true, halfThickness: 0.0625, length: 1 });
      const planks = bridge.bodies;
      if (times > 0) {
        const mass = planks.reduce((sum, b) => sum + world.bodyMassInfo(b).mass, 0);
        const load = world.addRigidBody({ points: box(0.5, 0.5), x: points[15].x, y: points[15].y + 1.5, density: times * mass, collide: false });
        world.addJoint({ type: 'revolute', a: load, b: planks[15], anchor: points[15] });
      }
      let gap = 0;
      for (let s = 1; s <= 600; s++) {
        world.step();
        gap = Math.max(gap, widestHinge(world, bridge));
      }
      console.log(`      load ${times}×: widest hinge ${gap.toExponential(1)}`);
      expect(gap, `load ${times}× the bridge: widest hinge`).to.be.below(limits[times]);
    }
  });

  it('a bridge of 30 planks hinged to the world at both ends holds a box 1, 3 and 10 times its weight dropped on it, in both kernels', () => {
    // Laid straight from (0, 0) to (30, 0): once loaded, a loop through the world with no answer (a straight chain
    // cannot sag), which the tree and its closing hinge solve within MAX_TURN a substep; where the box lands is
    // chaotic, so the kernels' contacts (the same formulas, other rounding) end far apart. Measured 0.086, 0.14–0.18 and
    // 0.43–0.65 wide at most, planks up to 114 units/s. Swept after the tree, the last hinge opened gaps of 0.12, 0.23 and
    // 0.39; before the lopsided retry the box of 3 tore the bridge apart (gaps of 9), as did the box of 10 (29).
    const limits = { 1: 0.15, 3: 0.3, 10: 1 };
    for (const kernel of ['js', 'wasm'] as const)
      for (const times of [1, 3, 10] as const) {
        const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false });
        const bridge = barChain(world, Array.from({ length: 31 }, (_, k): Vec2 => ({ x: k, y: 0 })), { closed: true, halfThickness: 0.0625, length: 1 });
        const planks = bridge.bodies;
        const mass = planks.reduce((sum, b) => sum + world.bodyMassInfo(b).mass, 0);
        world.addRigidBody({ points: box(0.5, 0.5), x: 15, y: -3, density: times * mass });
        let gap = 0;
        let speed = 0;
        for (let s = 1; s <= 600; s++) {
          world.step();
          gap = Math.max(gap, widestHinge(world, bridge));
          for (const p of planks) speed = Math.max(speed, Math.hypot(world.bodyVelocity(p).x, world.bodyVelocity(p).y));
        }
        console.log(`      ${kernel}, box ${times}×: widest hinge ${gap.toFixed(3)}, fastest plank ${speed.toFixed(1)}`);
        expect(gap, `${kernel}, box ${times}× the bridge: widest hinge`).to.be.below(limits[times]);
        expect(speed, `${kernel}, box ${times}× the bridge: fastest plank`).to.be.below(200);
      }
  });

  it('60 random loops: 2–9 links hinged end to end between two world anchors (masses 30 times apart) hold their hinges', () => {
    // Each link a bar 0.1 thick between two hinge points of a random zigzag from (0, 0) to (x, 0), its density
    // 10^±1.5. With the closing hinge swept after the tree, loop 0 opened 0.18 (and in a like set the median loop
    // 0.0093, the 90th percentile 0.16, 2 of 60 blew up); solved with the tree the median loop holds to 1.6·10⁻⁵, the
    // 90th percentile 6.3·10⁻⁴. What is left: loop 39 (5 links) opens 0.017 and gains a fifth of the energy scale for
    // a while, and masses 10⁴ apart still blow up 3 loops in 60 at 6 substeps (engine.md, known limits).
    const rnd = rng(4242);
    const gaps: number[] = [];
    let rise = 0;
    for (let scene = 0; scene < 60; scene++) {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
      const links = 2 + Math.floor(rnd() * 8);
      const points: Vec2[] = [{ x: 0, y: 0 }];
      for (let k = 1; k < links; k++) points.push({ x: points[k - 1].x + 0.5 + rnd() * 1.5, y: (rnd() * 2 - 0.5) * 1.5 });
      points.push({ x: points[links - 1].x + 0.5 + rnd() * 1.5, y: 0 });
      const loop = barChain(world, points, { closed: true, halfThickness: 0.05, density: () => 10 ** (3 * rnd() - 1.5), collide: false });
      const bodies = loop.bodies;
      const start = rigidEnergy(world, bodies, 10);
      // The energy scale: every link dropped by the span's length.
      const scale = bodies.reduce((sum, b) => sum + world.bodyMassInfo(b).mass, 0) * 10 * points[links].x;
      let gap = 0;
      let loopRise = 0;
      for (let s = 1; s <= 600; s++) {
        world.step();
        gap = Math.max(gap, widestHinge(world, loop));
        if (s % 10 === 0) loopRise = Math.max(loopRise, (rigidEnergy(world, bodies, 10) - start) / scale);
      }
      expect(gap, `loop ${scene} (${links} links): widest hinge`).to.be.below(0.05);
      gaps.push(gap);
      rise = Math.max(rise, loopRise);
      expect(loopRise, `loop ${scene} (${links} links): energy gained over the scale`).to.be.below(0.25);
    }
    gaps.sort((a, b) => a - b);
    console.log(`      widest hinge: median ${gaps[30].toExponential(1)}, 90th percentile ${gaps[54].toExponential(1)}, most ${gaps[59].toExponential(1)}; energy gained at most ${rise.toExponential(1)} of the scale`);
    expect(gaps[30], 'the median loop\'s widest hinge').to.be.below(2e-3);
    expect(gaps[54], 'the 90th percentile').to.be.below(2e-3);
  });

  it('60 random trees of revolute joints and welds hold the same way', () => {
    // Welds swept joint by joint (before they joined the trees), 13 of these 60 failed: joints apart or energy gained.
    expect(randomTrees(60, 9000, true)).to.be.above(300);
  });
});
