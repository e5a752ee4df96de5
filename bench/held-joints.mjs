// A light box held to the world by one joint (revolute, weld, prismatic), hit by a much heavier box, in our engine
// and in peers (docs/engine.md, Known limits, cites it). Run: node bench/held-joints.mjs [--json results.json] [--plain]
// (a line per engine, joint and case; --json also writes them to that file).
// Zero gravity, friction 0.6, restitution 0, sleeping off, 60 Hz, 120 steps, each engine's default iterations
// (as bench/peers/engines/*.mjs use them). Each engine also runs its variants (see `variants`) unless --plain.
import { readFileSync, writeFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { pathToFileURL } from 'node:url';
import { bundleOurs } from './peers/engines/ours.mjs';
import { installedVersion } from './peers/engines/version.mjs';
import { initRapier } from './peers/engines/rapier.mjs';

const require = createRequire(import.meta.url);
const DT = 1 / 60;
const STEPS = 120;
const FRICTION = 0.6;
const HALF = 0.3; // held box 0.6 × 0.6
const HELD_AREA = (2 * HALF) ** 2;
const ANGLE0 = 0.3;
const ANCHOR = { x: 0.1, y: -0.1 };
const AXIS = { x: 1, y: 0 };
const HAMMER_START = { x: -3, y: 0.1 };
const CASES = [
  [10, 20],
  [10, 40],
  [50, 40],
  [170, 276],
];
const JOINTS = ['revolute', 'weld', 'prismatic'];

// ---- engines: build(joint, R, v, { variant }) → { step(), held() → {x, y, angle, vx, vy}, hammer() → {x, y, vx, vy} } ----

async function loadOurs() {
  const engine = await import(pathToFileURL(await bundleOurs()).href);
  const probe = new engine.World();
  const box = (h) => [{ x: -h, y: -h }, { x: h, y: -h }, { x: h, y: h }, { x: -h, y: h }];
  return {
    name: 'ours',
    version: JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8')).version,
    settings: `substeps ${probe.substeps} (6 for rigid bodies) × ${probe.iterations} iteration (new World() defaults), js kernel`,
    // variant 'mirrored': the same numbers with y negated (our y points down, so this is the peers' layout seen in
    // our frame); results are mirrored back.
    variants: ['', 'mirrored'],
    build(joint, R, v, { variant = '' } = {}) {
      const m = variant === 'mirrored' ? -1 : 1;
      const anchor = { x: ANCHOR.x, y: m * ANCHOR.y };
      const axis = { x: AXIS.x, y: m * AXIS.y };
      const world = new engine.World({ sleeping: false, gravity: { x: 0, y: 0 } });
      const held = world.addRigidBody({ points: box(HALF), x: 0, y: 0, angle: m * ANGLE0, density: 1, friction: FRICTION, restitution: 0 });
      if (joint === 'revolute') world.addJoint({ type: 'revolute', a: held, anchor });
      if (joint === 'weld') world.addJoint({ type: 'weld', a: held, anchor });
      if (joint === 'prismatic') world.addJoint({ type: 'prismatic', a: held, anchor, axis, lower: -1, upper: 1 });
      const hammer = world.addRigidBody({ points: box(0.5), x: HAMMER_START.x, y: m * HAMMER_START.y, angle: 0, density: R * HELD_AREA, friction: FRICTION, restitution: 0 });
      world.setBodyVelocity(hammer, v, 0);
      const state = (h) => {
        const p = world.bodyPose(h);
        const u = world.bodyVelocity(h);
        return { x: p.x, y: m * p.y, angle: m * p.angle, vx: u.x, vy: m * u.y };
      };
      return { step: () => world.step(), held: () => state(held), hammer: () => state(hammer) };
    },
  };
}

const SIMD = WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));

async function loadBox2dWasm() {
  const flavour = SIMD ? 'Box2D.simd' : 'Box2D';
  const factory = require(`box2d-wasm/dist/umd/${flavour}.js`);
  const B = await factory({ wasmBinary: readFileSync(require.resolve(`box2d-wasm/dist/umd/${flavour}.wasm`)) });
  const vec = (x, y) => new B.b2Vec2(x, y);
  return {
    name: 'box2d-wasm',
    version: installedVersion('box2d-wasm') + (SIMD ? ' (SIMD build)' : ''),
    settings: 'Step(dt, 8, 3); SetAllowSleeping(false)',
    variants: ['', 'bullet'],
    build(joint, R, v, { variant = '' } = {}) {
      const bullet = variant.includes('bullet');
      const world = new B.b2World(vec(0, 0));
      world.SetAllowSleeping(false);
      const ground = world.CreateBody(new B.b2BodyDef());
      const add = (x, y, angle, h, density, isBullet) => {
        const def = new B.b2BodyDef();
        def.set_type(B.b2_dynamicBody);
        def.set_position(vec(x, y));
        def.set_angle(angle);
        def.set_bullet(isBullet);
        const body = world.CreateBody(def);
        const shape = new B.b2PolygonShape();
        shape.SetAsBox(h, h);
        const fd = new B.b2FixtureDef();
        fd.set_shape(shape);
        fd.set_density(density);
        fd.set_friction(FRICTION);
        fd.set_restitution(0);
        body.CreateFixture(fd);
        return body;
      };
      const held = add(0, 0, ANGLE0, HALF, 1, false);
      const a = vec(ANCHOR.x, ANCHOR.y);
      if (joint === 'revolute') {
        const def = new B.b2RevoluteJointDef();
        def.Initialize(ground, held, a);
        world.CreateJoint(def);
      } else if (joint === 'weld') {
        const def = new B.b2WeldJointDef();
        def.Initialize(ground, held, a);
        world.CreateJoint(def);
      } else {
        const def = new B.b2PrismaticJointDef();
        def.Initialize(ground, held, a, vec(AXIS.x, AXIS.y));
        def.set_enableLimit(true);
        def.set_lowerTranslation(-1);
        def.set_upperTranslation(1);
        world.CreateJoint(def);
      }
      const hammer = add(HAMMER_START.x, HAMMER_START.y, 0, 0.5, R * HELD_AREA, bullet);
      hammer.SetLinearVelocity(vec(v, 0));
      const state = (b) => {
        const p = b.GetPosition();
        const u = b.GetLinearVelocity();
        return { x: p.get_x(), y: p.get_y(), angle: b.GetAngle(), vx: u.get_x(), vy: u.get_y() };
      };
      return { step: () => world.Step(DT, 8, 3), held: () => state(held), hammer: () => state(hammer) };
    },
  };
}

async function loadBox2dCore() {
  const b2 = await import('@box2d/core');
  return {
    name: '@box2d/core',
    version: installedVersion('@box2d/core'),
    settings: 'Step(dt, {8, 3}); SetAllowSleeping(false)',
    variants: ['', 'bullet'],
    build(joint, R, v, { variant = '' } = {}) {
      const bullet = variant.includes('bullet');
      const world = b2.b2World.Create({ x: 0, y: 0 });
      world.SetAllowSleeping(false);
      const ground = world.CreateBody();
      const add = (x, y, angle, h, density, isBullet) => {
        const body = world.CreateBody({ type: b2.b2BodyType.b2_dynamicBody, position: { x, y }, angle, bullet: isBullet });
        body.CreateFixture({ shape: new b2.b2PolygonShape().SetAsBox(h, h), density, friction: FRICTION, restitution: 0 });
        return body;
      };
      const held = add(0, 0, ANGLE0, HALF, 1, false);
      if (joint === 'revolute') {
        const def = new b2.b2RevoluteJointDef();
        def.Initialize(ground, held, ANCHOR);
        world.CreateJoint(def);
      } else if (joint === 'weld') {
        const def = new b2.b2WeldJointDef();
        def.Initialize(ground, held, ANCHOR);
        world.CreateJoint(def);
      } else {
        const def = new b2.b2PrismaticJointDef();
        def.Initialize(ground, held, ANCHOR, AXIS);
        def.enableLimit = true;
        def.lowerTranslation = -1;
        def.upperTranslation = 1;
        world.CreateJoint(def);
      }
      const hammer = add(HAMMER_START.x, HAMMER_START.y, 0, 0.5, R * HELD_AREA, bullet);
      hammer.SetLinearVelocity({ x: v, y: 0 });
      const state = (b) => {
        const p = b.GetPosition();
        const u = b.GetLinearVelocity();
        return { x: p.x, y: p.y, angle: b.GetAngle(), vx: u.x, vy: u.y };
      };
      return { step: () => world.Step(DT, { velocityIterations: 8, positionIterations: 3 }), held: () => state(held), hammer: () => state(hammer) };
    },
  };
}

async function loadPlanck() {
  const planck = await import('planck');
  const probe = new planck.World();
  return {
    name: 'planck',
    version: installedVersion('planck'),
    settings: `world defaults (velocityIterations ${probe.m_velocityIterations}, positionIterations ${probe.m_positionIterations}); allowSleep false`,
    // 'maxTranslation 10': Box2D v2 caps a body's travel at maxTranslation (2) a step, 120 units/s at 60 Hz; planck
    // lets it be raised (box2d-wasm and @box2d/core do not), so the 276 units/s hammer keeps its speed.
    variants: ['', 'bullet', 'maxTranslation 10', 'bullet, maxTranslation 10'],
    build(joint, R, v, { variant = '' } = {}) {
      const bullet = variant.includes('bullet');
      const cap = variant.includes('maxTranslation') ? 10 : 2;
      planck.Settings.maxTranslation = cap;
      const world = new planck.World({ gravity: planck.Vec2(0, 0), allowSleep: false });
      const ground = world.createBody();
      const add = (x, y, angle, h, density, isBullet) => {
        const body = world.createBody({ type: 'dynamic', position: planck.Vec2(x, y), angle, bullet: isBullet });
        body.createFixture(planck.Box(h, h), { density, friction: FRICTION, restitution: 0 });
        return body;
      };
      const held = add(0, 0, ANGLE0, HALF, 1, false);
      const a = planck.Vec2(ANCHOR.x, ANCHOR.y);
      if (joint === 'revolute') world.createJoint(planck.RevoluteJoint({}, ground, held, a));
      else if (joint === 'weld') world.createJoint(planck.WeldJoint({}, ground, held, a));
      else world.createJoint(planck.PrismaticJoint({ enableLimit: true, lowerTranslation: -1, upperTranslation: 1 }, ground, held, a, planck.Vec2(AXIS.x, AXIS.y)));
      const hammer = add(HAMMER_START.x, HAMMER_START.y, 0, 0.5, R * HELD_AREA, bullet);
      hammer.setLinearVelocity(planck.Vec2(v, 0));
      const state = (b) => {
        const p = b.getPosition();
        const u = b.getLinearVelocity();
        return { x: p.x, y: p.y, angle: b.getAngle(), vx: u.x, vy: u.y };
      };
      return { step: () => world.step(DT), held: () => state(held), hammer: () => state(hammer) };
    },
  };
}

async function loadRapier(pkg) {
  const { R: RA, params } = await initRapier(pkg);
  return {
    name: pkg.includes('simd') ? 'rapier2d-simd' : 'rapier2d',
    version: installedVersion(pkg),
    settings: `${params.join(', ')} (world defaults); impulse joints; setCanSleep(false)`,
    variants: ['', 'ccd'],
    build(joint, R, v, { variant = '' } = {}) {
      const world = new RA.World({ x: 0, y: 0 });
      world.timestep = DT;
      const ground = world.createRigidBody(RA.RigidBodyDesc.fixed());
      // The held box is a body at angle 0 carrying its collider turned ANGLE0 (the same box): Rapier's JS
      // prismatic joint takes one axis for both bodies' frames and locks their relative angle at 0, so a body
      // turned at the start would be snapped to the ground's angle. Its angle is reported + ANGLE0.
      const add = (x, y, colliderAngle, h, density, ccd) => {
        const body = world.createRigidBody(RA.RigidBodyDesc.dynamic().setTranslation(x, y).setCanSleep(false).setCcdEnabled(ccd));
        world.createCollider(RA.ColliderDesc.cuboid(h, h).setRotation(colliderAngle).setDensity(density).setFriction(FRICTION).setRestitution(0), body);
        return body;
      };
      const held = add(0, 0, ANGLE0, HALF, 1, false);
      let data;
      if (joint === 'revolute') data = RA.JointData.revolute(ANCHOR, ANCHOR);
      else if (joint === 'weld') data = RA.JointData.fixed(ANCHOR, 0, ANCHOR, 0);
      else {
        data = RA.JointData.prismatic(ANCHOR, ANCHOR, AXIS);
        data.limitsEnabled = true;
        data.limits = [-1, 1];
      }
      world.createImpulseJoint(data, ground, held, true);
      const hammer = add(HAMMER_START.x, HAMMER_START.y, 0, 0.5, R * HELD_AREA, variant === 'ccd');
      hammer.setLinvel({ x: v, y: 0 }, true);
      const state = (b) => {
        const t = b.translation();
        const u = b.linvel();
        return { x: t.x, y: t.y, angle: b.rotation(), vx: u.x, vy: u.y };
      };
      return { step: () => world.step(), held: () => (({ angle, ...rest }) => ({ ...rest, angle: angle + ANGLE0 }))(state(held)), hammer: () => state(hammer) };
    },
  };
}

// ---- the run ----

const cs = Math.cos(ANGLE0);
const sn = Math.sin(ANGLE0);
const LOCAL = { x: cs * ANCHOR.x + sn * ANCHOR.y, y: -sn * ANCHOR.x + cs * ANCHOR.y };

/** How deep two boxes (centre, angle, half-size) overlap: the least overlap over their four face normals (0 if apart). */
function overlap(a, ha, b, hb) {
  const corners = (p, h) => [[-h, -h], [h, -h], [h, h], [-h, h]].map(([x, y]) => [p.x + Math.cos(p.angle) * x - Math.sin(p.angle) * y, p.y + Math.sin(p.angle) * x + Math.cos(p.angle) * y]);
  const ca = corners(a, ha);
  const cb = corners(b, hb);
  let least = Infinity;
  for (const p of [a, b])
    for (const t of [p.angle, p.angle + Math.PI / 2]) {
      const n = [Math.cos(t), Math.sin(t)];
      const proj = (cs) => cs.map(([x, y]) => x * n[0] + y * n[1]);
      const pa = proj(ca);
      const pb = proj(cb);
      least = Math.min(least, Math.min(Math.max(...pa), Math.max(...pb)) - Math.max(Math.min(...pa), Math.min(...pb)));
    }
  return Math.max(0, least);
}

function run(engine, joint, R, v, opts) {
  const sim = engine.build(joint, R, v, opts);
  const m = { gap: 0, disp: 0, turn: 0, past: 0, off: 0, speed: 0, overlap: 0, blowup: false, firstContact: null };
  const check0 = sim.held();
  if (Math.hypot(check0.x, check0.y) > 1e-6 || Math.abs(check0.angle - ANGLE0) > 1e-6) throw new Error(`${engine.name}: held box not at its start`);
  for (let k = 0; k < STEPS; k++) {
    sim.step();
    const h = sim.held();
    if (![h.x, h.y, h.angle, h.vx, h.vy].every(Number.isFinite)) {
      m.blowup = true;
      break;
    }
    const c = Math.cos(h.angle);
    const s = Math.sin(h.angle);
    m.gap = Math.max(m.gap, Math.hypot(h.x + c * LOCAL.x - s * LOCAL.y - ANCHOR.x, h.y + s * LOCAL.x + c * LOCAL.y - ANCHOR.y));
    m.disp = Math.max(m.disp, Math.hypot(h.x, h.y));
    m.turn = Math.max(m.turn, Math.abs(h.angle - ANGLE0));
    const along = h.x * AXIS.x + h.y * AXIS.y;
    m.past = Math.max(m.past, along - 1, -1 - along);
    m.off = Math.max(m.off, Math.abs(-h.x * AXIS.y + h.y * AXIS.x));
    m.speed = Math.max(m.speed, Math.hypot(h.vx, h.vy));
    if (m.firstContact === null && Math.hypot(h.vx, h.vy) > 1e-6) m.firstContact = k + 1;
    const hm = sim.hammer();
    m.overlap = Math.max(m.overlap, overlap(h, HALF, hm, 0.5));
  }
  const hm = sim.hammer();
  const h = sim.held();
  m.hammerVx = hm.vx;
  m.hammerX = hm.x;
  m.heldEnd = { x: h.x, y: h.y, angle: h.angle };
  // What the hammer did: its centre ended past the held box's, after overlapping it by at least half its width at the
  // end of some step ('through': it passed through the box) or not ('past': it knocked the box aside and went by);
  // 'missed' (never touched it: tunnelled in one step); else back (vx < −5% of v), on (> 5% of v) or stopped.
  const beyond = hm.x > h.x;
  m.hammer = m.firstContact === null && m.overlap === 0 ? 'missed' : beyond && m.overlap >= HALF ? 'through' : beyond ? 'past' : hm.vx < -0.05 * v ? 'back' : hm.vx > 0.05 * v ? 'on' : 'stopped';
  return m;
}

const args = process.argv.slice(2);
const jsonOut = args.includes('--json') ? args[args.indexOf('--json') + 1] : null;
const withVariants = !args.includes('--plain');

const engines = [];
for (const [name, load] of [
  ['ours', loadOurs],
  ['box2d-wasm', loadBox2dWasm],
  ['@box2d/core', loadBox2dCore],
  ['planck', loadPlanck],
  ['rapier2d-simd', () => loadRapier('@dimforge/rapier2d-simd-compat')],
]) {
  try {
    engines.push(await load());
  } catch (e) {
    console.error(`${name}: cannot load: ${e.message}`);
  }
}

const results = [];
const f = (x) => (x === undefined ? '-' : x.toFixed(3));
// Sanity: the hammer at rest: every joint must keep the box where it is.
for (const joint of JOINTS)
  for (const engine of engines) {
    const m = run(engine, joint, 10, 0, { variant: '' });
    const moved = Math.max(m.gap, m.disp, joint === 'revolute' ? 0 : m.turn, m.speed);
    if (moved > 1e-4) console.error(`SANITY ${joint} ${engine.name}: the box moves with nothing hitting it (${moved})`);
  }
for (const joint of JOINTS)
  for (const engine of engines)
    for (const variant of withVariants ? engine.variants : [''])
      for (const [R, v] of CASES) {
        let m;
        try {
          m = run(engine, joint, R, v, { variant });
        } catch (e) {
          m = { error: e.message };
        }
        const name = engine.name + (variant ? ` (${variant})` : '');
        results.push({ joint, engine: name, variant, R, v, ...m });
        console.log(`${joint.padEnd(9)} ${name.padEnd(40)} R ${String(R).padStart(3)} v ${String(v).padStart(3)}  gap ${f(m.gap)} disp ${f(m.disp)} turn ${f(m.turn)} past ${f(m.past)} off ${f(m.off)} speed ${f(m.speed)} overlap ${f(m.overlap)} hammer vx ${f(m.hammerVx)} x ${f(m.hammerX)} ${m.hammer ?? m.error}${m.blowup ? ' BLOWUP' : ''} contact@${m.firstContact}`);
      }
if (jsonOut) writeFileSync(jsonOut, JSON.stringify({ engines: engines.map(({ name, version, settings }) => ({ name, version, settings })), results }, null, 1));
