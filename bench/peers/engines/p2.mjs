// p2-es: y up, metres, masses given explicitly (area × density). Body damping (default 0.1) is set to 0 like the
// others'; sleeping is off by default (World.NO_SLEEPING); friction through the default contact material.
import * as p2 from 'p2-es';
import { DT, DENSITY, FRICTION, GRAVITY, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

export async function load() {
  const probe = new p2.World();
  return {
    version: installedVersion('p2-es'),
    settings: `GSSolver ${probe.solver.iterations} iterations (tolerance ${probe.solver.tolerance}), ${probe.broadphase.constructor.name}; sleepMode NO_SLEEPING; damping 0`,
    build,
  };
}

function build(scene) {
  const world = new p2.World({ gravity: [0, -GRAVITY] });
  world.sleepMode = p2.World.NO_SLEEPING;
  world.defaultContactMaterial.friction = FRICTION;
  const ground = new p2.Body({ type: p2.Body.STATIC });
  for (const s of scene.statics) ground.addShape(new p2.Box({ width: s.w, height: s.h }), [s.x, s.y]);
  world.addBody(ground);
  const dynamic = [];
  const add = (x, y, shape, mass, pinned = false) => {
    const body = new p2.Body({ mass: pinned ? 0 : mass, type: pinned ? p2.Body.STATIC : p2.Body.DYNAMIC, position: [x, y], damping: 0, angularDamping: 0 });
    body.addShape(shape);
    world.addBody(body);
    dynamic.push(body);
    return body;
  };
  for (const b of scene.boxes ?? []) add(b.x, b.y, new p2.Box({ width: b.w, height: b.h }), b.w * b.h * DENSITY);
  for (const c of scene.circles ?? []) add(c.x, c.y, new p2.Circle({ radius: c.r }), Math.PI * c.r * c.r * DENSITY);
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    let prev = ground;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      const link = add(c.x, c.y, new p2.Box({ width: length, height: thickness, collisionMask: 0 }), length * thickness * DENSITY);
      world.addConstraint(new p2.RevoluteConstraint(prev, link, { worldPivot: [k * length, 0], collideConnected: false }));
      prev = link;
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => add(x, y, new p2.Circle({ radius: nodeRadius, collisionMask: 0 }), Math.PI * nodeRadius ** 2 * DENSITY, pinned));
    for (const [a, b] of clothLinks(scene.cloth)) {
      if (b >= columns) world.addConstraint(new p2.DistanceConstraint(dynamic[a], dynamic[b], { collideConnected: false }));
    }
  }
  return {
    step: () => world.step(DT),
    measure: () =>
      measurePoses(dynamic, (body, out) => {
        out[0] = body.position[0];
        out[1] = body.position[1];
        out[2] = body.angle;
      }),
  };
}
