// @box2d/core (lusito's TypeScript port of Box2D v2.4): y up, metres. Step takes the iteration counts as
// arguments; we pass Box2D's recommended 8 velocity / 3 position iterations (its testbed's defaults).
import * as b2 from '@box2d/core';
import { DT, DENSITY, FRICTION, GRAVITY, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

const ITERATIONS = { velocityIterations: 8, positionIterations: 3 };

export async function load() {
  return {
    version: installedVersion('@box2d/core'),
    settings: `velocityIterations ${ITERATIONS.velocityIterations}, positionIterations ${ITERATIONS.positionIterations} (Box2D's recommended values, passed to Step); SetAllowSleeping(false)`,
    build,
  };
}

function build(scene) {
  const world = b2.b2World.Create({ x: 0, y: -GRAVITY });
  world.SetAllowSleeping(false);
  const ground = world.CreateBody();
  for (const s of scene.statics) ground.CreateFixture({ shape: new b2.b2PolygonShape().SetAsBox(s.w / 2, s.h / 2, { x: s.x, y: s.y }, 0), density: 0, friction: FRICTION });
  const dynamic = [];
  const add = (x, y, shape, noCollisions = false, pinned = false) => {
    const body = world.CreateBody({ type: pinned ? b2.b2BodyType.b2_staticBody : b2.b2BodyType.b2_dynamicBody, position: { x, y } });
    body.CreateFixture({ shape, density: DENSITY, friction: FRICTION, filter: noCollisions ? { groupIndex: -1 } : undefined });
    dynamic.push(body);
    return body;
  };
  for (const b of scene.boxes ?? []) add(b.x, b.y, new b2.b2PolygonShape().SetAsBox(b.w / 2, b.h / 2));
  for (const c of scene.circles ?? []) add(c.x, c.y, new b2.b2CircleShape(c.r));
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    let prev = ground;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      const link = add(c.x, c.y, new b2.b2PolygonShape().SetAsBox(length / 2, thickness / 2), true);
      const def = new b2.b2RevoluteJointDef();
      def.Initialize(prev, link, { x: k * length, y: 0 });
      world.CreateJoint(def);
      prev = link;
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => add(x, y, new b2.b2CircleShape(nodeRadius), true, pinned));
    for (const [a, b] of clothLinks(scene.cloth)) {
      if (b < columns) continue; // both pinned
      const def = new b2.b2DistanceJointDef();
      def.Initialize(dynamic[a], dynamic[b], dynamic[a].GetPosition(), dynamic[b].GetPosition());
      world.CreateJoint(def);
    }
  }
  return {
    step: () => world.Step(DT, ITERATIONS),
    measure: () =>
      measurePoses(dynamic, (body, out) => {
        const p = body.GetPosition();
        out[0] = p.x;
        out[1] = p.y;
        out[2] = body.GetAngle();
      }),
  };
}
