// box2d-wasm (Box2D v2.4 compiled to WebAssembly): y up, metres. Its loader fetch()es the .wasm, which fails on
// a file path in Node, so we load the (UMD) build its entry would pick (SIMD when WebAssembly SIMD validates)
// and hand the bytes over as wasmBinary. Step takes 8 velocity / 3 position iterations, Box2D's recommended values.
import { readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { DT, DENSITY, FRICTION, GRAVITY, clothLinks, eachClothNode, linkCentre, measurePoses } from '../scenes.mjs';
import { installedVersion } from './version.mjs';

const VELOCITY_ITERATIONS = 8;
const POSITION_ITERATIONS = 3;
// The probe of box2d-wasm's own entry.js (from wasm-feature-detect).
const SIMD = WebAssembly.validate(new Uint8Array([0, 97, 115, 109, 1, 0, 0, 0, 1, 5, 1, 96, 0, 1, 123, 3, 2, 1, 0, 10, 10, 1, 8, 0, 65, 0, 253, 15, 253, 98, 11]));

export async function load() {
  const flavour = SIMD ? 'Box2D.simd' : 'Box2D';
  // The UMD build: the ES one refers to __dirname when it sees Node.
  const require = createRequire(import.meta.url);
  const factory = require(`box2d-wasm/dist/umd/${flavour}.js`);
  const Box2D = await factory({ wasmBinary: readFileSync(require.resolve(`box2d-wasm/dist/umd/${flavour}.wasm`)) });
  return {
    version: installedVersion('box2d-wasm') + (SIMD ? ' (SIMD build)' : ' (non-SIMD build)'),
    settings: `velocityIterations ${VELOCITY_ITERATIONS}, positionIterations ${POSITION_ITERATIONS} (Box2D's recommended values, passed to Step); SetAllowSleeping(false)`,
    build: (scene) => build(Box2D, scene),
  };
}

function build(B, scene) {
  const vec = (x, y) => new B.b2Vec2(x, y);
  const world = new B.b2World(vec(0, -GRAVITY));
  world.SetAllowSleeping(false);
  const fixtureDef = (shape, density, noCollisions) => {
    const def = new B.b2FixtureDef();
    def.set_shape(shape);
    def.set_density(density);
    def.set_friction(FRICTION);
    if (noCollisions) def.get_filter().set_groupIndex(-1);
    return def;
  };
  const boxShape = (hw, hh, x = 0, y = 0) => {
    const shape = new B.b2PolygonShape();
    shape.SetAsBox(hw, hh, vec(x, y), 0);
    return shape;
  };
  const circleShape = (r) => {
    const shape = new B.b2CircleShape();
    shape.set_m_radius(r);
    return shape;
  };
  const ground = world.CreateBody(new B.b2BodyDef());
  for (const s of scene.statics) ground.CreateFixture(fixtureDef(boxShape(s.w / 2, s.h / 2, s.x, s.y), 0, false));
  const dynamic = [];
  const add = (x, y, shape, noCollisions = false, pinned = false) => {
    const def = new B.b2BodyDef();
    def.set_type(pinned ? B.b2_staticBody : B.b2_dynamicBody);
    def.set_position(vec(x, y));
    const body = world.CreateBody(def);
    body.CreateFixture(fixtureDef(shape, DENSITY, noCollisions));
    dynamic.push(body);
    return body;
  };
  for (const b of scene.boxes ?? []) add(b.x, b.y, boxShape(b.w / 2, b.h / 2));
  for (const c of scene.circles ?? []) add(c.x, c.y, circleShape(c.r));
  if (scene.chain) {
    const { links, length, thickness } = scene.chain;
    let prev = ground;
    for (let k = 0; k < links; k++) {
      const c = linkCentre(scene.chain, k);
      const link = add(c.x, c.y, boxShape(length / 2, thickness / 2), true);
      const def = new B.b2RevoluteJointDef();
      def.Initialize(prev, link, vec(k * length, 0));
      world.CreateJoint(def);
      prev = link;
    }
  }
  if (scene.cloth) {
    const { columns, nodeRadius } = scene.cloth;
    eachClothNode(scene.cloth, (x, y, pinned) => add(x, y, circleShape(nodeRadius), true, pinned));
    for (const [a, b] of clothLinks(scene.cloth)) {
      if (b < columns) continue; // both pinned
      const def = new B.b2DistanceJointDef();
      def.Initialize(dynamic[a], dynamic[b], dynamic[a].GetPosition(), dynamic[b].GetPosition());
      world.CreateJoint(def);
    }
  }
  return {
    step: () => world.Step(DT, VELOCITY_ITERATIONS, POSITION_ITERATIONS),
    measure: () =>
      measurePoses(dynamic, (body, out) => {
        const p = body.GetPosition();
        out[0] = p.get_x();
        out[1] = p.get_y();
        out[2] = body.GetAngle();
      }),
  };
}
