// planck.js (Box2D v2 in JavaScript): y up, metres. world.step(dt) uses the world's default iterations.
import * as planck from 'planck';
import { DT, DENSITY, FRICTION, GRAVITY, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

export async function load() {
  const version = installedVersion('planck');
  const probe = new planck.World();
  return {
    version,
    settings: `velocityIterations ${probe.m_velocityIterations}, positionIterations ${probe.m_positionIterations} (world defaults); allowSleep false`,
    build,
  };
}

function build(scene) {
  const world = new planck.World({ gravity: planck.Vec2(0, -GRAVITY), allowSleep: false });
  const fixture = { density: DENSITY, friction: FRICTION };
  const noCollisions = { ...fixture, filterGroupIndex: -1 };
  const ground = world.createBody();
  for (const s of scene.statics) ground.createFixture(planck.Box(s.w / 2, s.h / 2, planck.Vec2(s.x, s.y), 0), fixture);
  const dynamic = [];
  const add = (x, y, shape, def, type = 'dynamic') => {
    const body = world.createBody({ type, position: planck.Vec2(x, y) });
    body.createFixture(shape, def);
    dynamic.push(body);
    return body;
  };
  for (const b of scene.boxes ?? []) add(b.x, b.y, planck.Box(b.w / 2, b.h / 2), fixture);
  for (const c of scene.circles ?? []) add(c.x, c.y, planck.Circle(c.r), fixture);
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    let prev = ground;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      const link = add(c.x, c.y, planck.Box(length / 2, thickness / 2), noCollisions);
      world.createJoint(planck.RevoluteJoint({ collideConnected: false }, prev, link, planck.Vec2(k * length, 0)));
      prev = link;
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => add(x, y, planck.Circle(nodeRadius), noCollisions, pinned ? 'static' : 'dynamic'));
    for (const [a, b] of clothLinks(scene.cloth)) {
      if (b < columns) continue; // both pinned
      const A = dynamic[a];
      const B = dynamic[b];
      world.createJoint(planck.DistanceJoint({}, A, B, A.getPosition(), B.getPosition()));
    }
  }
  return {
    step: () => world.step(DT),
    measure: () =>
      measurePoses(dynamic, (body, out) => {
        const p = body.getPosition();
        out[0] = p.x;
        out[1] = p.y;
        out[2] = body.getAngle();
      }),
  };
}
