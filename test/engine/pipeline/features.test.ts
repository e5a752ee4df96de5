import { expect } from 'chai';
import { World, WORLD_BOUNDS, createBox, createCircle, createCloth, createPolygon, createSoftBody, buildScene, catalogue, type BoxOptions } from '../../../src/engine/index.js';
import { scene } from './scene-helpers.js';

describe('pipeline: narrow phase modes', () => {
  it('GJK + EPA and SAT give the same settled pyramid', () => {
    const tops = (['sat', 'gjk'] as const).map((narrowphase) => {
      const { world, bodies } = scene('pyramid', { narrowphase, sleeping: false });
      for (let k = 0; k < 300; k++) world.step();
      return world.bodyCentroid(bodies[bodies.length - 1].body);
    });
    expect(tops[0].y).to.be.closeTo(-19.5, 0.05);
    expect(tops[1].x).to.be.closeTo(tops[0].x, 0.01);
    expect(tops[1].y).to.be.closeTo(tops[0].y, 0.01);
  });
});

describe('pipeline: filtering', () => {
  const dropOnto = (ground: Partial<BoxOptions>, box: Partial<BoxOptions>) => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    createBox(world, { x: 0, y: 0.5, width: 10, height: 1, static: true, ...ground });
    const b = createBox(world, { x: 0, y: -1, width: 1, height: 1, ...box });
    for (let k = 0; k < 60; k++) world.step();
    return world.bodyCentroid(b.body).y;
  };
  it('category and mask decide who collides', () => {
    expect(dropOnto({ category: 2 }, { mask: 2 })).to.be.closeTo(-0.5, 0.01); // lands
    expect(dropOnto({ category: 2 }, { mask: 4 })).to.be.above(1); // falls through
    expect(dropOnto({ mask: 4 }, { category: 1 })).to.be.above(1); // both sides must agree
  });
  it('a shared negative group never collides, a shared positive group always does', () => {
    expect(dropOnto({ group: -3 }, { group: -3 })).to.be.above(1);
    expect(dropOnto({ group: 3, category: 2 }, { group: 3, mask: 4 })).to.be.closeTo(-0.5, 0.01);
  });
});

describe('pipeline: events', () => {
  it('begin when a box lands (with the normal and the two bodies), end when it is thrown off', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    const ground = createBox(world, { x: 0, y: 0.5, width: 10, height: 1, static: true });
    const box = createBox(world, { x: 0, y: -2, width: 1, height: 1 });
    const seen: { type: number; a: number; b: number; nx: number; ny: number; step: number }[] = [];
    const collect = (step: number) => {
      const e = world.events;
      for (let i = 0; i < e.count; i++) seen.push({ type: e.type[i], a: e.bodyA[i], b: e.bodyB[i], nx: e.normalX[i], ny: e.normalY[i], step });
    };
    for (let k = 0; k < 60; k++) {
      world.step();
      collect(k);
    }
    // Begin and end alternate (a landing may hop a little before it rests), starting with a begin.
    seen.forEach((e, k) => expect(e.type, `event ${k}`).to.equal(k % 2));
    expect(seen[seen.length - 1].type).to.equal(0); // it ends up resting on the ground
    expect([seen[0].a, seen[0].b].sort()).to.deep.equal([ground.body, box.body].sort());
    // Free fall of 1.5 units takes √(2·1.5/10) ≈ 0.548 s ≈ step 32.
    expect(seen[0].step).to.be.within(30, 34);
    // The normal points from A to B, i.e. along the ground's up normal when A is the ground.
    expect(Math.abs(seen[0].ny)).to.be.closeTo(1, 1e-6);
    const landed = seen.length;
    world.applyBodyImpulse(box.body, 0, -8);
    for (let k = 60; k < 90; k++) {
      world.step();
      collect(k);
    }
    expect(seen.length).to.equal(landed + 1);
    expect(seen[landed].type).to.equal(1);
    expect(seen[landed].step).to.equal(60);
  });

  for (const model of ['rigid', 'particles'] as const)
  it(`a body (${model}) landing on the world's bounds begins a pair with WORLD_BOUNDS (normal from the body into the floor), thrown off it ends; a particle of no body makes none`, () => {
    // Particles met the bounds without contacts: a particle ball or a frame landing on the view's floor fired nothing.
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false, bounds: { minX: -5, minY: -20, maxX: 5, maxY: 0 } });
    const box = createBox(world, { x: 0, y: -2, width: 1, height: 1, model });
    world.addParticle({ x: 3, y: -1, mass: 1 });
    const seen: number[][] = [];
    const collect = (step: number) => {
      const e = world.events;
      for (let i = 0; i < e.count; i++) seen.push([e.type[i], e.bodyA[i], e.bodyB[i], e.normalX[i], e.normalY[i], step]);
    };
    for (let k = 0; k < 60; k++) {
      world.step();
      collect(k);
    }
    expect(seen.length, JSON.stringify(seen)).to.be.greaterThan(0);
    const [type, a, b, nx, ny, step] = seen[0];
    expect([type, a, b]).to.deep.equal([0, box.body, WORLD_BOUNDS]);
    expect([nx, ny]).to.deep.equal([0, 1]);
    // Free fall of 1.5 units: ≈ step 32.
    expect(step).to.be.within(30, 34);
    const landed = seen.length;
    world.applyBodyImpulse(box.body, 0, -8);
    for (let k = 60; k < 70; k++) {
      world.step();
      collect(k);
    }
    expect(seen.slice(landed).map((e) => e.slice(0, 3))).to.deep.equal([[1, box.body, WORLD_BOUNDS]]);
  });

  it('a begin event carries the speed the bodies met at: √(2gh) for a drop from h onto the bounds, a rigid or a particle floor, a thrown speed without gravity, 0 for end events (both kernels)', () => {
    // depth is usually 0 (contacts are found before bodies touch): a page that plays a sound had nothing to scale it by.
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of ['bounds', 'rigid', 'particles'] as const)
        for (const model of ['rigid', 'particles'] as const)
          for (const drop of [0.5, 2, 6]) {
            const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false, bounds: floor === 'bounds' ? { minX: -10, maxX: 10, minY: -20, maxY: 0 } : null });
            if (floor !== 'bounds') createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, model: floor });
            createCircle(world, { x: 0, y: -drop - 0.5, radius: 0.5, model });
            let speed = NaN;
            let depth = NaN;
            for (let k = 0; k < 120 && speed !== speed; k++) {
              world.step();
              const e = world.events;
              for (let i = 0; i < e.count; i++) if (e.type[i] === 0) [speed, depth] = [e.speed[i], e.depth[i]];
            }
            expect(speed, `${kernel}, ${floor} floor, ${model} ball from ${drop}`).to.be.closeTo(Math.sqrt(20 * drop), 2e-3 * Math.sqrt(20 * drop));
            // The overlap when they met: none (contacts are found before touching: their gap, up to 0.1 here, is not
            // a depth), or a particle's sink into the bounds in its last substep (measured 0.0009 to 0.0013 × speed).
            if (floor === 'bounds' && model === 'particles') expect(depth, `${kernel}, ${model} ball from ${drop}: depth`).to.be.within(0, 0.002 * speed);
            else expect(depth, `${kernel}, ${floor} floor, ${model} ball from ${drop}: depth`).to.equal(0);
          }
    const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
    createCircle(world, { x: 0, y: 0, radius: 0.5, mass: 1 });
    createBox(world, { x: -3, y: 0, width: 1, height: 1, vx: 7, angularVelocity: 0 });
    const seen: number[][] = [];
    for (let k = 0; k < 60; k++) {
      world.step();
      const e = world.events;
      for (let i = 0; i < e.count; i++) seen.push([e.type[i], e.speed[i]]);
    }
    expect(seen[0][0]).to.equal(0);
    expect(seen[0][1]).to.be.closeTo(7, 1e-9);
    const ends = seen.filter(([type]) => type === 1);
    expect(ends.length).to.be.greaterThan(0);
    for (const [, speed] of ends) expect(speed).to.equal(0);
  });

  it('a begin event\'s speed counts spin: a rod spinning in place meets a block at ω times its corner\'s reach (either body first); a body thrown at a side wall meets it at its speed, normal into the wall', () => {
    // The drops and the throw above move without turning: leaving out ω × r (of body a or b) passed them. Both
    // kernels: the WebAssembly one's rigid lanes gave the contact table no normal levers back, and reported 0.
    for (const kernel of ['js', 'wasm'] as const)
    for (const order of ['rod first', 'rod last'])
    for (const along of ['x', 'y']) {
      const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
      const omega = 3;
      // A 2 × 0.2 rod about the origin turning at 3 rad/s; blocks whose faces at y = ±0.3 its corners (±1, ±0.1)
      // reach (along x), or at x = ∓0.3 for its corners (∓0.1, ±1) (along y: the same hit turned a quarter).
      const rod = () => createBox(world, { x: 0, y: 0, width: along === 'x' ? 2 : 0.2, height: along === 'x' ? 0.2 : 2, angularVelocity: omega }).body;
      const first = order === 'rod first' ? rod() : -1;
      for (const s of [1, -1]) {
        if (along === 'x') createBox(world, { x: s, y: 0.55 * s, width: 0.4, height: 0.5, static: true });
        else createBox(world, { x: -0.55 * s, y: s, width: 0.5, height: 0.4, static: true });
      }
      const spinning = first >= 0 ? first : rod();
      const speeds: number[] = [];
      for (let k = 0; k < 30 && speeds.length === 0; k++) {
        world.step();
        const e = world.events;
        for (let i = 0; i < e.count; i++) if (e.type[i] === 0) speeds.push(e.speed[i]);
      }
      // The corner (1, 0.1) turned by θ meets y = 0.3 where sin θ + 0.1 cos θ = 0.3; its speed across the face is
      // ω times its x there, cos θ − 0.1 sin θ.
      const theta = Math.asin(0.3 / Math.hypot(1, 0.1)) - Math.atan2(0.1, 1);
      const expected = omega * (Math.cos(theta) - 0.1 * Math.sin(theta));
      const at = `${kernel}, ${order}, along ${along}`;
      expect(speeds, at).to.have.length(2);
      for (const v of speeds) expect(v, at).to.be.closeTo(expected, 0.02 * expected);
      expect(world.bodyPose(spinning).angle, at).to.be.closeTo(theta, 0.05);
    }
    // A lone point (the rod's face on a static disc: the kernel's single-point lanes): the same speed in both kernels,
    // about ω times the distance along the rod to where its face meets the disc (0.96: 2.88 measured).
    const lone = (kernel: 'js' | 'wasm') => {
      const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
      createBox(world, { x: 0, y: 0, width: 2, height: 0.2, angularVelocity: 3 });
      createCircle(world, { x: 0.9, y: 0.6, radius: 0.2, static: true });
      for (let k = 0; k < 30; k++) {
        world.step();
        const e = world.events;
        for (let i = 0; i < e.count; i++) if (e.type[i] === 0) return e.speed[i];
      }
      return NaN;
    };
    const js = lone('js');
    expect(js).to.be.within(2.7, 3);
    expect(lone('wasm')).to.equal(js);
    for (const model of ['rigid', 'particles'] as const)
    for (const [side, vx] of [['right', 6], ['left', -4]] as const) {
      const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false, bounds: { minX: -5, minY: -5, maxX: 5, maxY: 5 } });
      const ball = createCircle(world, { x: 0, y: 0, radius: 0.5, vx, model });
      let begin: number[] | null = null;
      for (let k = 0; k < 120 && !begin; k++) {
        world.step();
        const e = world.events;
        for (let i = 0; i < e.count; i++) if (e.type[i] === 0) begin = [e.bodyA[i], e.bodyB[i], e.normalX[i], e.normalY[i], e.speed[i]];
      }
      expect(begin, `${model} ${side}`).to.not.equal(null);
      expect(begin!.slice(0, 4), `${model} ${side}`).to.deep.equal([ball.body, WORLD_BOUNDS, Math.sign(vx), 0]);
      expect(begin![4], `${model} ${side}`).to.be.closeTo(Math.abs(vx), 1e-9);
    }
  });

  it('a body asleep on the floor goes on touching it: another body thrown off ends only its own pair, and the sleeper nudged begins nothing anew', () => {
    for (const model of ['rigid', 'particles'] as const) {
      const world = new World({ gravity: { x: 0, y: 10 } });
      const ground = createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true, model });
      const ball = createCircle(world, { x: -2, y: -1.5, radius: 0.5, model });
      const crate = createBox(world, { x: 2, y: -1.5, width: 1, height: 1, model });
      const log: string[] = [];
      const name = (h: number) => (h === ground.body ? 'ground' : h === ball.body ? 'ball' : 'crate');
      world.events;
      for (let k = 0; k < 400; k++) {
        if (k === 200) {
          expect([world.isAwake(ball.body), world.isAwake(crate.body)], `${model}: both asleep first`).to.deep.equal([false, false]);
          world.applyBodyImpulse(crate.body, 0, -3);
        }
        if (k === 300) world.applyBodyImpulse(ball.body, 0.01, 0);
        world.step();
        const e = world.events;
        for (let i = 0; i < e.count; i++) log.push(`${e.type[i] === 0 ? 'begin' : 'end'} ${[name(e.bodyA[i]), name(e.bodyB[i])].sort().join('-')}`);
      }
      // (The ball's pair ended at the throw, and began again at the nudge.)
      expect(log.filter((l) => l.includes('ball')), model).to.deep.equal(['begin ball-ground']);
      expect(log.filter((l) => l.includes('crate')).slice(0, 3), model).to.deep.equal(['begin crate-ground', 'end crate-ground', 'begin crate-ground']);
    }
  });

  it('cost nothing until read: no tracking before the first read; from it on, a landing begins and a throw ends', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    createBox(world, { x: 0, y: 0.5, width: 10, height: 1, static: true });
    const resting = createBox(world, { x: -3, y: -0.5, width: 1, height: 1 });
    const falling = createBox(world, { x: 3, y: -2, width: 1, height: 1 });
    const tracker = (world as unknown as { ctx: { eventTracker: { active: boolean } } }).ctx.eventTracker;
    for (let k = 0; k < 10; k++) world.step();
    expect(tracker.active, 'tracking before anyone read the events').to.equal(false);
    // The first read starts tracking; the box already resting then is not reported as a new contact.
    expect(world.events.count).to.equal(0);
    expect(tracker.active).to.equal(true);
    const begins: number[] = [];
    const ends: number[] = [];
    for (let k = 0; k < 50; k++) {
      if (k === 40) world.applyBodyImpulse(resting.body, 0, -8);
      world.step();
      const e = world.events;
      for (let i = 0; i < e.count; i++) (e.type[i] === 0 ? begins : ends).push(e.bodyA[i] === falling.body || e.bodyB[i] === falling.body ? falling.body : resting.body);
    }
    expect(begins).to.include(falling.body);
    expect(begins.filter((b) => b === resting.body)).to.have.length(0);
    expect(ends).to.include(resting.body);
  });

  it('a body removed while touching ends its pairs in the next step\'s events, under its old handle; a new body in its slot begins afresh', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    const ground = createBox(world, { x: 0, y: 0.5, width: 20, height: 1, static: true });
    const boxes = [-3, 0, 3].map((x) => createBox(world, { x, y: -0.5, width: 1, height: 1 }));
    // Two boxes side by side, touching each other too.
    const pair = createBox(world, { x: 0, y: -1.5, width: 1, height: 1 });
    const events = () => {
      const e = world.events;
      return Array.from({ length: e.count }, (_, i) => [e.type[i], ...[e.bodyA[i], e.bodyB[i]].sort((p, q) => p - q)]);
    };
    for (let k = 0; k < 30; k++) {
      world.step();
      events();
    }
    const sorted = (a: number, b: number) => [a, b].sort((p, q) => p - q);
    const middle = boxes[1].body;
    world.removeBody(middle);
    // No step yet: the end comes with the next step's events, first, under the removed body's handle.
    world.step();
    expect(events()).to.have.deep.members([
      [1, ...sorted(ground.body, middle)],
      [1, ...sorted(middle, pair.body)],
    ]);
    // Nothing more about it; the box that rested on it falls, lands on the ground (a begin), and no end repeats.
    const later: number[][] = [];
    for (let k = 0; k < 60; k++) {
      world.step();
      later.push(...events());
    }
    expect(later.filter((e) => e.includes(middle))).to.deep.equal([]);
    expect(later).to.deep.include([0, ...sorted(ground.body, pair.body)]);
    // A new body takes the freed slot at once: it touches the ground from its first step, and begins (the old pair's
    // end was not taken for it).
    const again = createBox(world, { x: 6, y: -0.5, width: 1, height: 1 });
    world.step();
    expect(events()).to.deep.include([0, ...sorted(ground.body, again.body)]);
  });
});

describe('pipeline: queries', () => {
  const { world, byId } = buildScene({
    world: { gravity: { x: 0, y: 0 } },
    bodies: [
      { type: 'box', id: 'a', x: 0, y: 0, width: 2, height: 2 },
      { type: 'box', id: 'b', x: 5, y: 0, width: 2, height: 1, angle: Math.PI / 4 },
      { type: 'circle', id: 'c', x: 0, y: 5, radius: 1 },
    ],
  });
  world.step();
  const A = byId.get('a')!;
  const B = byId.get('b')!;
  const C = byId.get('c')!;

  it('bodies at a point: inside, outside, on a rotated box, in a circle', () => {
    expect(world.bodiesAtPoint(0.9, -0.9)).to.deep.equal([A]);
    expect(world.bodiesAtPoint(1.1, 0)).to.deep.equal([]);
    expect(world.bodiesAtPoint(5.6, 0.6)).to.deep.equal([B]); // along the rotated box's diagonal axis
    expect(world.bodiesAtPoint(5.9, 0)).to.deep.equal([]); // inside its AABB, outside the box
    expect(world.bodiesAtPoint(0.6, 5.6)).to.deep.equal([C]);
    expect(world.bodiesAtPoint(0.75, 5.75)).to.deep.equal([]);
  });

  it('bodies in a box', () => {
    expect(world.bodiesInBox(-3, -3, 3, 3)).to.deep.equal([A]);
    expect(world.bodiesInBox(-10, -10, 10, 10).sort()).to.deep.equal([A, B, C].sort());
    // Inside the rotated box's AABB (which reaches x = 6.06) but beside the box (at y = ±0.2 it reaches x ≤ 5.91).
    expect(world.bodiesInBox(6.0, -0.2, 6.5, 0.2)).to.deep.equal([]);
    expect(world.bodiesInBox(5.8, -0.2, 6.5, 0.2)).to.deep.equal([B]);
    expect(world.bodiesInBox(0.8, 5.8, 2, 7)).to.deep.equal([]); // beside the circle
  });

  it('a ray cast returns the nearest hit with its point, normal and distance', () => {
    const hit = world.rayCast(-5, 0, 10, 0)!;
    expect(hit.body).to.equal(A);
    expect(hit.x).to.be.closeTo(-1, 1e-9);
    expect(hit.normalX).to.be.closeTo(-1, 1e-9);
    expect(hit.distance).to.be.closeTo(4, 1e-9);
    const down = world.rayCast(0, 10, 0, 0)!;
    expect(down.body).to.equal(C);
    expect(down.y).to.be.closeTo(6, 1e-9);
    expect(world.rayCast(-5, 3, 10, 3)).to.equal(null);
  });
});

describe('pipeline: pointer drag', () => {
  it('a grabbed box follows the pointer and keeps its speed when released (a throw)', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    createBox(world, { x: 0, y: 0.5, width: 40, height: 1, static: true });
    const box = createBox(world, { x: 0, y: -0.5, width: 1, height: 1 });
    const grab = world.grab(0.3, -0.7)!;
    expect(grab).to.not.equal(null);
    // Pull it up and to the right at 3 units/s for 1 s.
    for (let k = 1; k <= 60; k++) {
      world.moveGrab(grab, 0.3 + (3 * k) / 60, -0.7 - (2 * k) / 60);
      world.step();
    }
    // It hangs from the held point (0.36 from its centre) a little behind the moving target (3.3, −2.7).
    const held = world.bodyCentroid(box.body);
    expect(Math.hypot(held.x - 3.3, held.y + 2.7)).to.be.below(0.6);
    world.release(grab);
    const before = world.bodyCentroid(box.body);
    world.step();
    const after = world.bodyCentroid(box.body);
    // Thrown: its centre keeps moving right at about the pointer's 3 units/s.
    expect((after.x - before.x) * 60).to.be.within(2, 4);
    expect(world.grab(10, -10)).to.equal(null); // nothing there
  });

  it('a cloth is grabbed at its nearest particle', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    const cloth = createCloth(world, { origin: { x: 0, y: 0 }, columns: 10, rows: 10, spacing: 0.2 });
    const grab = world.grab(1.01, 1.79)!;
    for (let k = 0; k < 60; k++) {
      world.moveGrab(grab, 2.5, 1.8);
      world.step();
    }
    const corner = world.getPosition(cloth.particles[9 * 10 + 5]);
    expect(corner.x).to.be.above(1.8);
  });
});

describe('pipeline: sleeping', () => {
  it('a gravity change wakes sleeping bodies, set as a property or through setGravity(), and they fall the new way', () => {
    for (const change of ['property', 'setGravity'] as const) {
      const world = new World({ gravity: { x: 0, y: 9.81 }, bounds: null });
      createBox(world, { x: 0, y: 5, width: 20, height: 1, static: true });
      const ball = createCircle(world, { x: 0, y: 4, radius: 0.5 });
      for (let k = 0; k < 300 && world.isAwake(ball.body); k++) world.step();
      expect(world.isAwake(ball.body), `${change}: asleep first`).to.equal(false);
      if (change === 'property') world.gravity = { x: 0, y: -9.81 };
      else world.setGravity(0, -9.81);
      for (let k = 0; k < 60; k++) world.step();
      // Up ½·g·t² = 4.9 in a second.
      expect(world.bodyPose(ball.body).y, change).to.be.closeTo(4 - 4.905, 0.05);
    }
  });

  it('a body that only turns is moving: a disc and a box spinning in place without gravity never fall asleep (both kernels)', () => {
    // Sleep measured how far a body's particles went; a turn in place moves none of them: it counts as its rim's
    // travel. Left out, the spinning bodies stopped dead after the time to sleep.
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: true, bounds: null });
      const disc = createCircle(world, { x: 0, y: 0, radius: 0.5, angularVelocity: 1 }).body;
      const box = createBox(world, { x: 3, y: 0, width: 1, height: 1, angularVelocity: -1 }).body;
      for (let k = 0; k < 600; k++) world.step();
      expect(world.bodyPose(disc).angle, `${kernel}: disc`).to.be.closeTo(world.time, 1e-9);
      expect(world.bodyPose(box).angle, `${kernel}: box`).to.be.closeTo(-world.time, 1e-9);
      expect(world.bodyAngularVelocity(disc), kernel).to.be.closeTo(1, 1e-9);
    }
  });

  it('a settled pyramid falls asleep within 5 s, and an impulse wakes it', () => {
    const { world, bodies } = scene('pyramid');
    let asleepAt = -1;
    for (let k = 0; k < 300 && asleepAt < 0; k++) {
      world.step();
      if (world.settled) asleepAt = k;
    }
    console.log(`pyramid asleep after ${(asleepAt / 60).toFixed(2)} s`);
    expect(asleepAt).to.be.within(0, 300);
    expect(bodies.slice(1).every((b) => !world.isAwake(b.body))).to.equal(true);
    const top = bodies[bodies.length - 1].body;
    world.applyBodyImpulse(top, 5, 0);
    world.step();
    expect(world.isAwake(top)).to.equal(true);
    expect(world.settled).to.equal(false);
  });

  it('a box balanced on its corner a hair off (10⁻³, 10⁻⁴ rad) topples instead of falling asleep balanced', () => {
    // Its corner speeds up from almost nothing, step after step, and was still under the sleep threshold after
    // timeToSleep: both fell asleep at step 30 on their corner. Now they lie flat (and sleep there).
    const square = [{ x: -0.5, y: -0.5 }, { x: 0.5, y: -0.5 }, { x: 0.5, y: 0.5 }, { x: -0.5, y: 0.5 }];
    for (const off of [1e-3, 1e-4]) {
      const world = new World();
      world.addRigidBody({ points: square.map((p) => ({ x: 20 * p.x, y: p.y })), x: 0, y: 0.5, type: 'static', friction: 0.8 });
      const box = world.addRigidBody({ points: square, x: 0, y: -Math.SQRT1_2 - 1e-4, angle: Math.PI / 4 + off, friction: 0.8 });
      for (let k = 0; k < 600; k++) world.step();
      const turned = world.bodyPose(box).angle - Math.PI / 4;
      expect(Math.abs(Math.abs(turned) - Math.PI / 4), `${off} rad off: turned ${turned.toFixed(3)}`).to.be.below(0.01);
      expect(world.settled, `${off} rad off: asleep at last`).to.equal(true);
    }
  });

  it('a box dropped on a sleeping pile wakes it', () => {
    const { world, bodies } = scene('stack');
    for (let k = 0; k < 120; k++) world.step();
    expect(world.settled).to.equal(true);
    const ball = createCircle(world, { x: 0.2, y: -14, radius: 0.5, mass: 5 });
    let woke = false;
    for (let k = 0; k < 120; k++) {
      world.step();
      if (world.isAwake(bodies[bodies.length - 1].body)) woke = true;
    }
    expect(woke).to.equal(true);
    expect(world.bodyCentroid(ball.body).y).to.be.below(-10); // it landed on the stack, not through it
  });

  it('moving a body with setBodyPose wakes what rested on it, and what it rested on: the box above falls, or follows a lowered ground', () => {
    const square = [{ x: -0.5, y: -0.5 }, { x: 0.5, y: -0.5 }, { x: 0.5, y: 0.5 }, { x: -0.5, y: 0.5 }];
    const slab = [{ x: -20, y: -0.5 }, { x: 20, y: -0.5 }, { x: 20, y: 0.5 }, { x: -20, y: 0.5 }];
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, sleeping: true });
      const ground = world.addRigidBody({ x: 0, y: 10, points: slab, type: 'static' });
      const under = world.addRigidBody({ x: 0, y: 9, points: square });
      const over = world.addRigidBody({ x: 0, y: 8, points: square });
      for (let k = 0; k < 120; k++) world.step();
      expect(world.settled, `${kernel}: asleep`).to.equal(true);
      // The lower box teleported away: the upper one (asleep, on nothing now) falls onto the ground.
      world.setBodyPose(under, 10, 9, 0);
      for (let k = 0; k < 60; k++) world.step();
      expect(world.bodyPose(over).y, `${kernel}: fell onto the ground`).to.be.closeTo(9, 0.01);
      for (let k = 0; k < 120; k++) world.step();
      // The ground lowered by 0.5: the boxes on it follow.
      world.setBodyPose(ground, 0, 10.5, 0);
      for (let k = 0; k < 60; k++) world.step();
      expect(world.bodyPose(over).y, `${kernel}: followed the ground down`).to.be.closeTo(9.5, 0.01);
      expect(world.bodyPose(under).y, `${kernel}: the other one too`).to.be.closeTo(9.5, 0.01);
    }
  });

  it('setPinTarget moves a pinned particle of no body in a settled world', () => {
    const world = new World({ sleeping: true });
    const p = world.addParticle({ x: 0, y: 0 });
    const pin = world.addPin(p, {});
    world.step();
    expect(world.settled).to.equal(true);
    world.setPinTarget(pin, 1, 1);
    world.step();
    expect(world.getPosition(p)).to.deep.equal({ x: 1, y: 1 });
  });

  it('a sleeping body about to be hit wakes before the solve: a pendulum ball passes its momentum to a resting one', () => {
    // Two balls of a Newton's cradle: the second hangs still long enough to sleep; the first, let go from 45°, hits it
    // at the bottom. Elastic, equal masses: the first stops and the second leaves with its speed. Woken only after
    // the step, the sleeper would have met the impact as a static body and sent the first ball back.
    const world = new World({ gravity: { x: 0, y: 9.81 } });
    const pendulum = (pivotX: number, x: number, y: number) => {
      const body = world.addRigidBody({ radius: 0.5, x, y, restitution: 1, friction: 0 });
      world.addJoint({ type: 'distance', a: body, anchorA: { x, y }, anchorB: { x: pivotX, y: 1 } });
      return body;
    };
    const first = pendulum(6, 6 - 4 * Math.SQRT1_2, 1 + 4 * Math.SQRT1_2);
    const second = pendulum(7.001, 7.001, 5);
    let hitAt = -1;
    for (let k = 0; k < 120 && hitAt < 0; k++) {
      const wasAwake = world.isAwake(second);
      world.step();
      if (k === 50) expect(wasAwake, 'the second ball sleeps before the hit').to.equal(false);
      if (world.bodyVelocity(second).x > 0.1) hitAt = k;
    }
    expect(hitAt).to.be.within(51, 119);
    const v1 = world.bodyVelocity(first).x;
    const v2 = world.bodyVelocity(second).x;
    const before = Math.sqrt(2 * 9.81 * 4 * (1 - Math.SQRT1_2)); // speed at the bottom: 4.79
    expect(Math.abs(v1)).to.be.below(0.02 * before);
    expect(v2).to.be.closeTo(before, 0.02 * before);
  });
});

describe('pipeline: determinism with collisions', () => {
  it('the same scene gives the same hash, and snapshot/restore replays it exactly', () => {
    const run = () => {
      const { world } = buildScene(catalogue.ragdolls.make());
      for (let k = 0; k < 120; k++) world.step();
      return world;
    };
    const a = run();
    const b = run();
    expect(a.stateHash()).to.equal(b.stateHash());
    const snap = structuredClone(a.snapshot());
    for (let k = 0; k < 60; k++) a.step();
    const expected = a.stateHash();
    a.restore(snap);
    for (let k = 0; k < 60; k++) a.step();
    expect(a.stateHash()).to.equal(expected);
  });
});

describe('pipeline: concave bodies', () => {
  for (const model of ['rigid', 'particles'] as const) {
    it(`an L-shaped polygon (${model}) collides as convex parts: a ball lands in its notch, not on its hull`, () => {
      const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
      // An L (y down): a 3×1 foot and a 1×3 upright on the left; the notch is above the foot, right of the upright.
      const l = createPolygon(world, { points: [{ x: 0, y: 0 }, { x: 3, y: 0 }, { x: 3, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 3 }, { x: 0, y: 3 }].map((p) => ({ x: p.x, y: -p.y })), static: true, model });
      const ball = createCircle(world, { x: 2.2, y: -5, radius: 0.4, model });
      for (let k = 0; k < 120; k++) world.step();
      if (model === 'particles') expect(world.colliders.partCount[l.body % 4194304]).to.equal(2);
      // It rests on the foot's top (y = −1), inside the notch, not on the hull's diagonal.
      expect(world.bodyCentroid(ball.body).y).to.be.closeTo(-1.4, 0.02);
      expect(world.bodiesAtPoint(2, -2)).to.deep.equal([]); // the notch is empty space
      expect(world.bodiesAtPoint(0.5, -2)).to.deep.equal([l.body]);
    });
  }
});

describe('pipeline: picking soft bodies and pulling cloth', () => {
  it('a point inside a soft ring finds the ring (both models), a point outside does not', () => {
    const world = new World({ gravity: { x: 0, y: 0 } });
    const pressure = createSoftBody(world, { center: { x: 0, y: 0 }, radius: 1, segments: 16 });
    const springs = createSoftBody(world, { center: { x: 5, y: 0 }, radius: 1, model: 'springs' });
    world.step();
    expect(world.bodiesAtPoint(0.3, -0.2)).to.deep.equal([pressure.body]);
    expect(world.bodiesAtPoint(5.2, 0.3)).to.deep.equal([springs.body]);
    expect(world.bodiesAtPoint(2.5, 0)).to.deep.equal([]);
    expect(world.grab(0.3, -0.2)).to.not.equal(null);
  });

  it('a cloth grabbed at one particle follows the pointer as a whole body would', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    const cloth = createCloth(world, { origin: { x: 0, y: 0 }, columns: 12, rows: 12, spacing: 0.2, pins: 'none' });
    const corner = cloth.particles[0];
    const grab = world.grab(0, 0)!;
    for (let k = 1; k <= 120; k++) {
      world.moveGrab(grab, (2 * k) / 120, (-2 * k) / 120);
      world.step();
    }
    // The whole cloth hangs from the held corner, which is near the pointer despite the cloth's weight.
    const held = world.getPosition(corner);
    expect(Math.hypot(held.x - 2, held.y + 2)).to.be.below(0.2);
  });
});
