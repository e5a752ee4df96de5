// matter-js: pixels and y down, so 1 m = 100 px (its default gravity, 1 × scale 0.001 px/ms², is then 10 m/s²)
// and y is mirrored. Density 1 kg/m² = 1e-4 per px². frictionAir (default 0.01) is set to 0 like the others'
// damping. Sleeping is off by default in matter-js.
import Matter from 'matter-js';
import { DT, FRICTION, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

const PX = 100;
const DENSITY = 1 / (PX * PX);
const { Engine, Bodies, Composite, Constraint } = Matter;

export async function load() {
  const version = installedVersion('matter-js');
  const probe = Engine.create();
  return {
    version,
    settings: `positionIterations ${probe.positionIterations}, velocityIterations ${probe.velocityIterations}, constraintIterations ${probe.constraintIterations}; enableSleeping false; frictionAir 0`,
    build,
  };
}

function build(scene) {
  const engine = Engine.create({ enableSleeping: false });
  const common = { friction: FRICTION, frictionAir: 0, density: DENSITY };
  const noCollisions = { group: -1 };
  const statics = scene.statics.map((s) => Bodies.rectangle(s.x * PX, -s.y * PX, s.w * PX, s.h * PX, { ...common, isStatic: true }));
  let dynamic = [];
  const constraints = [];
  if (scene.boxes) dynamic = scene.boxes.map((b) => Bodies.rectangle(b.x * PX, -b.y * PX, b.w * PX, b.h * PX, common));
  if (scene.circles) dynamic = scene.circles.map((c) => Bodies.circle(c.x * PX, -c.y * PX, c.r * PX, common));
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    const half = (length / 2) * PX;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      dynamic.push(Bodies.rectangle(c.x * PX, -c.y * PX, length * PX, thickness * PX, { ...common, collisionFilter: noCollisions }));
    }
    constraints.push(Constraint.create({ pointA: { x: 0, y: 0 }, bodyB: dynamic[0], pointB: { x: -half, y: 0 }, length: 0, stiffness: 1 }));
    for (let k = 1; k < links; k++) {
      constraints.push(Constraint.create({ bodyA: dynamic[k - 1], pointA: { x: half, y: 0 }, bodyB: dynamic[k], pointB: { x: -half, y: 0 }, length: 0, stiffness: 1 }));
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => dynamic.push(Bodies.circle(x * PX, -y * PX, nodeRadius * PX, { ...common, isStatic: pinned, collisionFilter: noCollisions })));
    for (const [a, b] of clothLinks(scene.cloth)) if (b >= columns) constraints.push(Constraint.create({ bodyA: dynamic[a], bodyB: dynamic[b], stiffness: 1 }));
  }
  Composite.add(engine.world, [...statics, ...dynamic, ...constraints]);
  const deltaMs = DT * 1000;
  return {
    step: () => Engine.update(engine, deltaMs),
    measure: () =>
      measurePoses(dynamic, (b, out) => {
        out[0] = b.position.x / PX;
        out[1] = -b.position.y / PX;
        out[2] = -b.angle;
      }),
  };
}
