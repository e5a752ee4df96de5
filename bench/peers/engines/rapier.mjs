// Rapier 2D through its -compat packages (wasm inlined): @dimforge/rapier2d-compat (plain build, 0.21) or
// @dimforge/rapier2d-simd-compat (SIMD build, newest 0.19). y up, metres, bodies with setCanSleep(false),
// impulse joints, the world's default integration parameters. Rapier has no rigid distance joint in 2D, so the
// cloth uses rope joints (a maximum distance: resist stretching only), the nearest it offers.
import { DT, DENSITY, FRICTION, GRAVITY, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

// Membership 1, filter 0: interacts with nothing.
const NO_COLLISIONS = 0x0001_0000;

/**
 * The Rapier module of `pkg`, initialised, and its world's default solver parameters ("numSolverIterations 4, …")
 * for the report. Shared with bench/held-joints.mjs.
 */
export async function initRapier(pkg) {
  const { default: R } = await import(pkg);
  // init() of 0.21 logs a deprecation note about its parameters on some versions: silence that one call.
  const warn = console.warn;
  console.warn = () => {};
  try {
    await R.init();
  } finally {
    console.warn = warn;
  }
  const p = new R.World({ x: 0, y: 0 }).integrationParameters;
  const params = ['numSolverIterations', 'numInternalPgsIterations', 'numAdditionalFrictionIterations']
    .filter((name) => typeof p[name] === 'number')
    .map((name) => `${name} ${p[name]}`);
  return { R, params };
}

export async function load(pkg) {
  const { R, params } = await initRapier(pkg);
  return {
    version: installedVersion(pkg),
    settings: `${params.join(', ')} (world defaults); setCanSleep(false) on every body${pkg.includes('simd') ? '; SIMD build' : ''}`,
    build: (scene) => build(R, scene),
  };
}

function build(R, scene) {
  const world = new R.World({ x: 0, y: -GRAVITY });
  world.timestep = DT;
  const ground = world.createRigidBody(R.RigidBodyDesc.fixed());
  const collider = (desc, noCollisions = false) => {
    desc.setDensity(DENSITY).setFriction(FRICTION);
    if (noCollisions) desc.setCollisionGroups(NO_COLLISIONS);
    return desc;
  };
  for (const s of scene.statics) world.createCollider(collider(R.ColliderDesc.cuboid(s.w / 2, s.h / 2).setTranslation(s.x, s.y)), ground);
  const dynamic = [];
  const add = (x, y, shape, noCollisions = false, pinned = false) => {
    const body = world.createRigidBody((pinned ? R.RigidBodyDesc.fixed() : R.RigidBodyDesc.dynamic()).setTranslation(x, y).setCanSleep(false));
    world.createCollider(collider(shape, noCollisions), body);
    dynamic.push(body);
    return body;
  };
  for (const b of scene.boxes ?? []) add(b.x, b.y, R.ColliderDesc.cuboid(b.w / 2, b.h / 2));
  for (const c of scene.circles ?? []) add(c.x, c.y, R.ColliderDesc.ball(c.r));
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    let prev = ground;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      const link = add(c.x, c.y, R.ColliderDesc.cuboid(length / 2, thickness / 2), true);
      const anchorOnPrev = k === 0 ? { x: 0, y: 0 } : { x: length / 2, y: 0 };
      world.createImpulseJoint(R.JointData.revolute(anchorOnPrev, { x: -length / 2, y: 0 }), prev, link, true);
      prev = link;
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius, spacing } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => add(x, y, R.ColliderDesc.ball(nodeRadius), true, pinned));
    for (const [a, b] of clothLinks(scene.cloth)) {
      if (b >= columns) world.createImpulseJoint(R.JointData.rope(spacing, { x: 0, y: 0 }, { x: 0, y: 0 }), dynamic[a], dynamic[b], true);
    }
  }
  return {
    step: () => world.step(),
    measure: () =>
      measurePoses(dynamic, (body, out) => {
        const t = body.translation();
        out[0] = t.x;
        out[1] = t.y;
        out[2] = body.rotation();
      }),
  };
}
