// Rigid bodies against analytic answers: a disc rolling down a slope, a box holding or sliding on it, bounce heights
// e²·h, a fast box stopped dead by a thin wall, Newton's cradle, a domino's toppling time and the spin that topples a standing one, a revolute pendulum's period, stacks and a
// pyramid that stand (a heavy box placed or dropped on them too), a kinematic drum that carries 200 boxes, and particles (a cloth, a rope) attached to and
// colliding with rigid bodies.
import { expect } from 'chai';
import { createBox, createCircle, createCloth, createRope, World, type Handle, type Vec2 } from '../../../src/engine/index.js';
import { BOUNCE_THRESHOLD } from '../../../src/engine/impact.js';
import type { StepContext } from '../../../src/engine/pipeline/context.js';
import { box, rigidEnergy } from '../helpers.js';
import { rng } from '../collision/helpers.js';

const g = 9.81;

function steps(world: World, n: number, each?: (k: number) => void): void {
  for (let k = 1; k <= n; k++) {
    world.step();
    each?.(k);
  }
}

/** A 40-wide static slab whose top face passes through the origin at angle θ (descending to the right, y down). */
/**
 * A random hard hit on a 0.6 × 0.6 box at the origin (the held-joint tests): the box's angle, a joint anchor on it, and
 * the hammer's mass ratio (1–200), speed (5–105 units/s) and heading, drawn in this order.
 */
function randomHit(random: () => number): { angle: number; anchor: Vec2; ratio: number; speed: number; heading: number } {
  const angle = (random() - 0.5) * 2;
  const anchor = { x: (random() - 0.5) * 0.8, y: (random() - 0.5) * 0.8 };
  const ratio = Math.exp(random() * Math.log(200));
  const speed = 5 + random() * 100;
  const heading = random() * 2 * Math.PI;
  return { angle, anchor, ratio, speed, heading };
}

function slope(world: World, theta: number, friction: number): { t: Vec2; n: Vec2 } {
  const t = { x: Math.cos(theta), y: Math.sin(theta) };
  const n = { x: Math.sin(theta), y: -Math.cos(theta) };
  world.addRigidBody({ points: box(20, 0.5), x: -0.5 * n.x, y: -0.5 * n.y, angle: theta, type: 'static', friction });
  return { t, n };
}

/**
 * Newton's cradle: five balls r 0.5 (e = 1, no friction) on distance joints 4 long from pivots `gap` apart at y = 1,
 * the first released from `release` rad; `drop` is its height above the others.
 */
function cradle(release: number, gap: number): { world: World; balls: Handle[]; drop: number } {
  const world = new World({ gravity: { x: 0, y: g }, sleeping: false });
  const balls: Handle[] = [];
  for (let k = 0; k < 5; k++) {
    const pivotX = 6 + k * (1 + gap);
    const [x, y] = k === 0 ? [pivotX - 4 * Math.sin(release), 1 + 4 * Math.cos(release)] : [pivotX, 5];
    const ball = world.addRigidBody({ radius: 0.5, x, y, restitution: 1, friction: 0 });
    world.addJoint({ type: 'distance', a: ball, anchorA: { x, y }, anchorB: { x: pivotX, y: 1 } });
    balls.push(ball);
  }
  return { world, balls, drop: 4 - 4 * Math.cos(release) };
}

describe('rigid bodies: motion on a slope', () => {
  const theta = (20 * Math.PI) / 180;

  it('a solid disc rolls (1/3)·g·sinθ·t² in 2 s within 2%, with ω·r = v within 0.5%', () => {
    const world = new World({ sleeping: false });
    const { t, n } = slope(world, theta, 1);
    const r = 0.5;
    const start = { x: -10 * t.x + r * n.x, y: -10 * t.y + r * n.y };
    const disc = world.addRigidBody({ radius: r, x: start.x, y: start.y, friction: 1 });
    steps(world, 120);
    const p = world.bodyPose(disc);
    const along = (p.x - start.x) * t.x + (p.y - start.y) * t.y;
    const expected = (g * Math.sin(theta) * 4) / 3;
    const v = world.bodyVelocity(disc);
    const speed = v.x * t.x + v.y * t.y;
    const spin = world.bodyAngularVelocity(disc) * r;
    console.log(`      disc on 20°: ${along.toFixed(4)} m (analytic ${expected.toFixed(4)}), v ${speed.toFixed(3)}, ω·r ${spin.toFixed(3)}`);
    expect(along).to.be.closeTo(expected, 0.02 * expected);
    // 0.94% apart while a round side's friction anchor was the rim point at the contact when the step began.
    expect(spin).to.be.closeTo(speed, 0.005 * speed);
    // It stays on the surface.
    expect((p.x - start.x) * n.x + (p.y - start.y) * n.y).to.be.closeTo(0, 1e-3);
  });

  it('a disc set spinning or sliding on a rough floor ends rolling as angular momentum about the contact says, within 0.5%', () => {
    // L = m·v·r + I·ω about the contact point is kept through the slide: v_end = (v0 + ω0·r/2)/(3/2) for a solid disc,
    // then ω·r = v. Friction held the rim point found at the contact when a step began; as the disc turned that
    // point left the contact, and it ended rolling 0.3% fast (r 0.5, spun 6 rad/s) to 1.9% slow (r 0.25, 12 rad/s).
    for (const kernel of ['js', 'wasm'] as const)
      for (const r of [0.25, 0.5, 1])
        for (const [v0, spin0] of [[3, 3], [0, 3], [3, 0], [3, -3]]) {
          const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: 10 } });
          world.addRigidBody({ points: box(200, 1), x: 0, y: 1, type: 'static', friction: 0.5 });
          const disc = world.addRigidBody({ radius: r, x: 0, y: -r, vx: v0, angularVelocity: spin0 / r, friction: 0.5 });
          steps(world, 300);
          const at = `${kernel}, r ${r}, v0 ${v0}, ω0·r ${spin0}`;
          const expected = (v0 + spin0 / 2) / 1.5;
          const v = world.bodyVelocity(disc).x;
          expect(v, at).to.be.closeTo(expected, 0.005 * Math.abs(expected));
          expect(world.bodyAngularVelocity(disc) * r, at).to.be.closeTo(v, 0.005 * Math.abs(v));
        }
  });

  it('a disc rolling on a rough floor keeps its speed, turning up to 2.5 rad a step, in both kernels', () => {
    // Friction holds a material point of the rim through the step; measured straight along the tangent it moves
    // r·(φ − sin φ) more than the disc rolls as it passes the contact, which friction could not undo: the disc slid,
    // braking, 2.2% of its speed lost in 10 s at r 0.25 and 5 units/s, 14% at 10, 32% at 20 (9.1% at r 0.5 and 20).
    // Measured along the rim (contacts.ts arcBeyond) it rolls on: within 0.01% up to 0.67 rad a step. Past it the
    // series for the arc fell short (5.7% lost at 1.3 rad, 30% at 2.5: a marble of radius 0.1 at 15 units/s), where
    // Math.asin now measures it, in the JS solver (the kernel's lanes leave such steps to it).
    let worst = 0;
    let worstFast = 0;
    for (const kernel of ['js', 'wasm'] as const)
      for (const [r, v0, mu] of [[0.25, 5, 0.6], [0.25, 10, 0.6], [0.25, 10, 1], [0.5, 20, 0.6], [1, 10, 0.2], [0.25, 20, 0.6], [0.1, 10, 0.6], [0.15, 20, 1], [0.1, 15, 0.2]]) {
        const world = new World({ kernel, sleeping: false });
        world.addRigidBody({ points: box(200, 0.5), x: 150, y: 0.5, type: 'static', friction: mu });
        const disc = world.addRigidBody({ radius: r, x: 0, y: -r, vx: v0, angularVelocity: v0 / r, friction: mu });
        steps(world, 600);
        const at = `${kernel}, r ${r}, v0 ${v0}, μ ${mu}`;
        const v = world.bodyVelocity(disc).x;
        const turn = (v0 / r) / 60;
        expect(v, at).to.be.closeTo(v0, (turn < 1 ? 0.001 : 0.006) * v0);
        expect(world.bodyAngularVelocity(disc) * r, at).to.be.closeTo(v, 0.001 * v);
        if (turn < 1) worst = Math.max(worst, Math.abs(v / v0 - 1));
        else worstFast = Math.max(worstFast, Math.abs(v / v0 - 1));
      }
    console.log(`      rolling discs: speed kept within ${(100 * worst).toFixed(3)}% over 10 s up to 0.67 rad a step, ${(100 * worstFast).toFixed(2)}% up to 2.5`);
  });

  it('a box holds with μ above tanθ and slides ½·g·(sinθ − μ·cosθ)·t² below it, within 2%', () => {
    const moved = (mu: number) => {
      const world = new World({ sleeping: false });
      const { t, n } = slope(world, theta, mu);
      const start = { x: -10 * t.x + 0.5 * n.x, y: -10 * t.y + 0.5 * n.y };
      const b = world.addRigidBody({ points: box(0.5, 0.5), x: start.x, y: start.y, angle: theta, friction: mu });
      steps(world, 120);
      const p = world.bodyPose(b);
      return (p.x - start.x) * t.x + (p.y - start.y) * t.y;
    };
    expect(Math.abs(moved(0.5))).to.be.lessThan(1e-4);
    const slid = moved(0.2);
    const expected = 0.5 * g * (Math.sin(theta) - 0.2 * Math.cos(theta)) * 4;
    console.log(`      box on 20°, μ 0.2: ${slid.toFixed(4)} m (analytic ${expected.toFixed(4)})`);
    expect(slid).to.be.closeTo(expected, 0.02 * expected);
  });
});

describe('rigid bodies: impacts', () => {
  it('a box dropped flat from h bounces to e²·h within 0.05·h for e in {0, 0.25, 0.5, 0.75, 1}, without turning', () => {
    const h = 2;
    for (const e of [0, 0.25, 0.5, 0.75, 1]) {
      const world = new World({ sleeping: false });
      world.addRigidBody({ points: box(10, 0.5), x: 0, y: 0.5, type: 'static' });
      const b = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -h - 0.5, restitution: e });
      let peak = Infinity;
      let bounced = false;
      let fell = false;
      steps(world, 240, () => {
        const v = world.bodyVelocity(b).y;
        if (v > 0.5) fell = true;
        if (fell && v < 0) bounced = true;
        if (bounced) peak = Math.min(peak, world.bodyPose(b).y);
      });
      const height = bounced ? -(peak + 0.5) : 0;
      expect(height, `e = ${e}`).to.be.closeTo(e * e * h, 0.05 * h);
      expect(Math.abs(world.bodyPose(b).angle), `e = ${e}: turned`).to.be.lessThan(1e-6);
    }
  });

  it('bounce after bounce keeps e²ᵏ·h: e = 1 within 0.1% over 8 bounces, e = 0.8 within 1% over 4 (disc and box, both kernels)', () => {
    // Each bounce once left at −e × the speed stored before it (under position Verlet the mean over the substep
    // before), g·h slower than the hit, and lost the fall through the gap it closed in its substep: e = 1 from 2
    // reached 1.964 at the first bounce and 1.847 at the seventh.
    const h = 2;
    for (const kernel of ['js', 'wasm'] as const)
      for (const shape of ['disc', 'box'] as const)
        for (const [e, bounces, tolerance] of [[1, 8, 1e-3], [0.8, 4, 1e-2]] as const) {
          const world = new World({ kernel, sleeping: false });
          world.addRigidBody({ points: box(10, 0.5), x: 0, y: 0.5, type: 'static' });
          const at = { x: 0, y: -h - 0.5, restitution: e };
          const b = world.addRigidBody(shape === 'disc' ? { radius: 0.5, ...at } : { points: box(0.5, 0.5), ...at });
          const peaks: number[] = [];
          let top = Infinity;
          let falling = true;
          for (let n = 0; n < 60 * 20 && peaks.length <= bounces; n++) {
            world.step();
            const y = world.bodyPose(b).y;
            const v = world.bodyVelocity(b).y;
            if (!falling) top = Math.min(top, y);
            if (falling && v < 0) falling = false;
            else if (!falling && v >= 0) {
              peaks.push(-(top + 0.5));
              top = Infinity;
              falling = true;
            }
          }
          expect(peaks.length, `${kernel} ${shape} e ${e}`).to.be.greaterThan(bounces);
          for (let k = 1; k <= bounces; k++) {
            const expected = h * e ** (2 * k);
            expect(peaks[k - 1], `${kernel} ${shape} e ${e}, bounce ${k}`).to.be.closeTo(expected, tolerance * expected);
          }
        }
  });

  it('elastic box–box hits (e = 1, μ = 0, no gravity) gain no energy: of 200 spun random hits none gains 1%, at most 3 lose 1%', () => {
    // A manifold's point that only joined its touching partner bounced from its speed after the partner's correction
    // had swung it in, or bounced alone; a touching point kept the speed its overlap's push gave it, or was stopped
    // dead after its bounce. Before, on these 200: 9 off by more than 1%, gains up to 22% and losses up to 19%.
    // What is left are losses of corners that go on overlapping the face after their bounce, a spin turning them
    // about the step's fixed normal (other seeds: up to 10%).
    const random = rng(16);
    const errors: number[] = [];
    for (let k = 0; k < 200; k++) {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
      const side = (): number => 0.3 + 0.5 * random();
      const a = world.addRigidBody({ points: box(side(), side()), x: -2, y: 0, angle: 6 * random(), vx: 3 + 5 * random(), vy: random() - 0.5, angularVelocity: 4 * (random() - 0.5), restitution: 1, friction: 0 });
      const b = world.addRigidBody({ points: box(side(), side()), x: 2, y: random() - 0.5, angle: 6 * random(), vx: -3 - 5 * random(), angularVelocity: 4 * (random() - 0.5), restitution: 1, friction: 0 });
      const before = rigidEnergy(world, [a, b], 0);
      steps(world, 90);
      errors.push(rigidEnergy(world, [a, b], 0) / before - 1);
    }
    const off = errors.filter((e) => Math.abs(e) > 0.01).length;
    const gained = Math.max(...errors);
    const lost = -Math.min(...errors);
    console.log(`      elastic box hits: ${off} of 200 off by more than 1%; most gained ${(100 * gained).toFixed(2)}%, most lost ${(100 * lost).toFixed(1)}%`);
    expect(gained).to.be.lessThan(0.01);
    expect(off).to.be.at.most(3);
    expect(lost).to.be.lessThan(0.05);
  });

  it('with e = 0 a box at 300 u/s is stopped by a 0.1-thick wall and leaves it at < 0.5 u/s, not through it', () => {
    const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
    world.addRigidBody({ points: box(0.05, 2), x: 10, y: 0, type: 'static' });
    const b = world.addRigidBody({ points: box(0.25, 0.25), x: 0, y: 0, vx: 300 });
    steps(world, 60);
    const p = world.bodyPose(b);
    const v = world.bodyVelocity(b);
    expect(p.x).to.be.closeTo(9.7, 1e-3);
    expect(Math.hypot(v.x, v.y)).to.be.lessThan(0.5);
    expect(Math.abs(p.angle)).to.be.lessThan(1e-6);
  });

  it("a disc thrown at the floor leaves its impact rolling, as Coulomb's law says, wherever in a step it lands", () => {
    // μ = 1 is ample: a solid disc (I = m·r²/2) at vx = 5 comes out rolling at vx = ω·r = (2/3)·5. Twelve start heights
    // 0.0137 apart land at different moments within a step. Friction once undid the slide through the air before the
    // landing as well: the disc left spinning backwards at up to ω·r = 14.7 (vx −2.4), its energy up by half.
    const rolling = (2 / 3) * 5;
    for (const kernel of ['js', 'wasm'] as const)
      for (const restitution of [0, 0.5])
        for (let k = 0; k < 12; k++) {
          const world = new World({ kernel, sleeping: false });
          world.addRigidBody({ points: box(30, 0.5), x: 0, y: 0.5, type: 'static', friction: 1 });
          const disc = world.addRigidBody({ radius: 0.5, x: -3, y: -3.5 + 0.0137 * k, vx: 5, friction: 1, restitution });
          const energy = (): number => {
            const v = world.bodyVelocity(disc);
            const spin = world.bodyAngularVelocity(disc) * 0.5;
            return v.x * v.x + v.y * v.y + 0.5 * spin * spin - 2 * g * world.bodyPose(disc).y;
          };
          const before = energy();
          // Until it leaves the floor again (e > 0), or has been on it for ten steps (e = 0).
          let landed = 0;
          for (let n = 0; n < 120 && landed < 10; n++) {
            world.step();
            if (world.bodyPose(disc).y > -0.7) landed++;
            if (restitution > 0 && world.bodyVelocity(disc).y < 0) break;
          }
          const vx = world.bodyVelocity(disc).x;
          const spin = world.bodyAngularVelocity(disc) * 0.5;
          const at = `${kernel}, e ${restitution}, start ${k}: vx ${vx.toFixed(3)}, ω·r ${spin.toFixed(3)}`;
          expect(landed, at).to.be.greaterThan(0);
          expect(vx, at).to.be.closeTo(rolling, 0.03);
          expect(spin, at).to.be.closeTo(rolling, 0.03);
          expect(energy(), at).to.be.lessThan(before * 1.001);
        }
  });

  it('a box or a ball thrown onto the floor comes to rest where Coulomb says, wherever in a step it lands', () => {
    // Thrown at vx = 5 from 3 units above the floor (g = 10, μ = 0.3, e = 0): the landing's friction takes μ·vn off
    // vx (vn = √(2·g·3)), then it slides to rest in v²/(2·μ·g). The sweep's friction alone once depended on the overlap
    // the landing substep reached: the box came to rest anywhere from 2.35 to 4.61 (the ball 2.16 to 4.86).
    const g = 10;
    const mu = 0.3;
    const restFrom = (height: number): number => {
      const vn = Math.sqrt(2 * g * height);
      const after = 5 - mu * vn;
      return -3 + (5 * vn) / g + (after * after) / (2 * mu * g);
    };
    for (const kernel of ['js', 'wasm'] as const)
      for (const shape of ['ball', 'box'] as const) {
        const misses: number[] = [];
        for (let k = 0; k < 12; k++) {
          const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: g } });
          world.addRigidBody({ points: box(100, 0.5), x: 0, y: 0.5, type: 'static', friction: mu });
          let x: () => number;
          if (shape === 'box') {
            const b = world.addRigidBody({ points: box(1, 0.1), x: -3, y: -3.1 + 0.0137 * k, vx: 5, friction: mu });
            x = () => world.bodyPose(b).x;
          } else {
            const ball = createCircle(world, { x: -3, y: -3.5 + 0.0137 * k, radius: 0.5, model: 'particles', friction: mu, vx: 5 });
            x = () => world.getPosition(ball.particles[0]).x;
          }
          steps(world, 300);
          misses.push(x() - restFrom(3 - 0.0137 * k));
        }
        const at = `${kernel}, ${shape}: rests this far from Coulomb's point: ${misses.map((e) => e.toFixed(3)).join(' ')}`;
        for (const miss of misses) expect(Math.abs(miss), at).to.be.below(shape === 'ball' ? 0.01 : 0.1);
      }
  });

  it("a disc that slides through its bounce takes Coulomb's tangential impulse, μ times the normal one, wherever in a step it lands", () => {
    // μ = 0.1 is too little to make it roll: over the bounce Δvx = μ·Δvy (Δvy includes one step of gravity, 1/600 of
    // it), and the spin gained is 2·Δvx/r. The bounce's friction once depended on the overlap the landing substep
    // happened to reach: Δvx/Δvy from 0.013 to 0.065.
    for (const restitution of [0.5, 0.9])
      for (let k = 0; k < 8; k++) {
        const world = new World({ sleeping: false });
        world.addRigidBody({ points: box(30, 0.5), x: 0, y: 0.5, type: 'static', friction: 0.1 });
        const disc = world.addRigidBody({ radius: 0.5, x: -3, y: -3.5 + 0.0137 * k, vx: 5, friction: 0.1, restitution });
        let before = world.bodyVelocity(disc);
        // Until it bounces (the first reading, before any step, is the mean over the first substep: −½·g·h).
        for (let n = 0; n < 120 && (n === 0 || world.bodyVelocity(disc).y >= 0); n++) {
          before = world.bodyVelocity(disc);
          world.step();
        }
        const after = world.bodyVelocity(disc);
        const at = `e ${restitution}, start ${k}`;
        expect(after.y, at).to.be.lessThan(0);
        expect((before.x - after.x) / (before.y - after.y), at).to.be.closeTo(0.1, 0.003);
        expect((world.bodyAngularVelocity(disc) * 0.5) / (before.x - after.x), at).to.be.closeTo(2, 0.05);
      }
  });
  it('a disc struck off-centre leaves along the line of centres at contact, at any speed and wherever in a step it is hit', () => {
    // Billiards: equal discs, no friction, the struck one at rest, impact parameter b (sin of the angle between the
    // hitter's path and the line of centres at contact). The struck disc leaves at asin(b) with speed v·cos·(1 + e)/2
    // (e = 0 for an approach slower than BOUNCE_THRESHOLD, 0.5 units/s along the normal).
    // The normal was once fixed where the discs were when the step began: at 20–60 units/s it was 3–31° off.
    let worstAngle = 0;
    for (const restitution of [1, 0.5, 0])
      for (const b of [0.5, 0.9])
        for (const v of [1, 5, 20, 60])
          for (const x0 of [3, 3.37, 3.71]) {
            const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
            const hitter = world.addRigidBody({ radius: 0.5, x: 0, y: 0, vx: v, friction: 0, restitution });
            const struck = world.addRigidBody({ radius: 0.5, x: x0, y: b, friction: 0, restitution });
            steps(world, Math.ceil((60 * (x0 + 2)) / v) + 5);
            const at = `e ${restitution}, b ${b}, v ${v}, x0 ${x0}`;
            const u = world.bodyVelocity(struck);
            const w = world.bodyVelocity(hitter);
            const e = v * Math.sqrt(1 - b * b) > BOUNCE_THRESHOLD ? restitution : 0;
            const angle = Math.atan2(u.y, u.x) - Math.asin(b);
            worstAngle = Math.max(worstAngle, Math.abs(angle));
            expect(angle, at).to.be.closeTo(0, 1e-3);
            expect(Math.hypot(u.x, u.y), at).to.be.closeTo((v * Math.sqrt(1 - b * b) * (1 + e)) / 2, 1e-3 * v);
            // Momentum kept; no friction, so no spin.
            expect(u.x + w.x, at).to.be.closeTo(v, 1e-9 * v);
            expect(u.y + w.y, at).to.be.closeTo(0, 1e-9 * v);
            expect(world.bodyAngularVelocity(hitter), at).to.equal(0);
          }
    console.log(`      off-centre hits: exit angle within ${((worstAngle * 180) / Math.PI).toExponential(1)}° of the line of centres`);
  });

  it('a ball dropped on a static peg off-centre bounces off the line of centres at contact (a Galton board)', () => {
    // e = 1, no friction: the horizontal speed after the bounce is −2(v·n)·nx for the speed v = √(2gh) at contact.
    // Fixed where the ball was at the step's start, the normal missed by up to 55% of that speed falling from 20.
    for (const h of [0.5, 3, 20])
      for (const b of [0.3, 0.7, 0.95])
        for (const phase of [0, 0.37, 0.71]) {
          const world = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
          world.addRigidBody({ radius: 0.5, x: 0, y: 0, type: 'static', friction: 0, restitution: 1 });
          const contactY = -Math.sqrt(1 - b * b);
          const startY = contactY - h - 0.05 * phase;
          const ball = world.addRigidBody({ radius: 0.5, x: b, y: startY, friction: 0, restitution: 1 });
          while (world.bodyVelocity(ball).x === 0 && world.bodyPose(ball).y < contactY + 0.2) world.step();
          world.step();
          const vn = Math.sqrt(2 * 10 * (contactY - startY)) * contactY;
          const at = `h ${h}, b ${b}, phase ${phase}`;
          expect(world.bodyVelocity(ball).x / (-2 * vn * b), at).to.be.closeTo(1, 0.01);
        }
  });

  it("a disc meeting a box's corner bounces off the line from the corner to its centre at contact, either body moving", () => {
    // e = 1, no friction. The disc's velocity relative to the box is mirrored in the normal from the corner to the
    // disc's centre when they touch. Found where they were at the step's start, that normal was 3-74° wrong.
    const square = box(1, 1);
    for (const v of [5, 20, 60])
      for (const b of [0.2, 0.4])
        for (const x0 of [3, 3.37, 3.71])
          for (const moving of ['disc', 'box', 'box first'] as const) {
            // The box's top-left corner at (x0, 0) (y down), the disc's centre b above that corner's height.
            const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
            const boxBody = () =>
              world.addRigidBody({ points: square, x: x0 + 1, y: 1, friction: 0, restitution: 1, ...(moving === 'disc' ? { type: 'static' as const } : { type: 'kinematic' as const, vx: -v }) });
            if (moving === 'box first') boxBody();
            const disc = world.addRigidBody({ radius: 0.5, x: 0, y: -b, vx: moving === 'disc' ? v : 0, friction: 0, restitution: 1 });
            if (moving !== 'box first') boxBody();
            steps(world, Math.ceil((60 * (x0 + 1)) / v) + 3);
            const n = { x: -Math.sqrt(0.25 - b * b) / 0.5, y: -b / 0.5 };
            // Relative to the box the disc comes at (v, 0) either way.
            const boxV = moving === 'disc' ? 0 : -v;
            const along = v * n.x;
            const expected = { x: boxV + v - 2 * along * n.x, y: -2 * along * n.y };
            const u = world.bodyVelocity(disc);
            const at = `v ${v}, b ${b}, x0 ${x0}, ${moving} moving`;
            expect(u.x, at).to.be.closeTo(expected.x, 1e-3 * v);
            expect(u.y, at).to.be.closeTo(expected.y, 1e-3 * v);
          }
  });

  it("Newton's cradle: the first ball's impact passes down the row of five to the last one, which swings up", () => {
    // Five balls (e = 1, no friction) hung by distance joints 0.001 apart, the first released from about 45°. The
    // impact reaches the last ball through three touching ones within a substep or two: each point bounces on the
    // fastest approach it has seen in the step, its own before the hit (touch()) or the one an earlier point of the
    // sweep just gave it. With the approach taken at the first touch only, the last ball left at 28% of the speed, the
    // middle ones followed at 25% and the row swung as one. Where in a step the hit falls matters (a release 0.002 rad
    // higher or lower can move the middle balls from 5% to 20%), so the first ball is released from 12 angles, 30° to
    // 57.5°, the hit falling anywhere in a step.
    const middles: number[] = [];
    for (let i = 0; i < 12; i++) {
      const release = ((30 + 2.5 * i) * Math.PI) / 180;
      const { world, balls, drop } = cradle(release, 0.001);
      const before = Math.sqrt(2 * g * drop); // the first ball's speed at the bottom: 4.79 from 45°
      let hit = -1;
      let first = 0;
      let middle = 0;
      let last = 0;
      let rise = 0;
      steps(world, 200, (n) => {
        if (hit < 0 && world.bodyVelocity(balls[4]).x > 0.1) hit = n;
        if (hit < 0) return;
        rise = Math.max(rise, 5 - world.bodyPose(balls[4]).y);
        if (n > hit + 5) return;
        first = Math.max(first, Math.abs(world.bodyVelocity(balls[0]).x));
        for (const k of [1, 2, 3]) middle = Math.max(middle, Math.abs(world.bodyVelocity(balls[k]).x));
        last = Math.max(last, world.bodyVelocity(balls[4]).x);
      });
      const at = `released from ${30 + 2.5 * i}°`;
      if (i % 3 === 0) console.log(`      cradle, ${at}: after the hit the first ball ${(first / before).toFixed(3)}, middle ${(middle / before).toFixed(3)}, last ${(last / before).toFixed(3)} of ${before.toFixed(2)}; the last rises ${(rise / drop).toFixed(3)} of the drop`);
      expect(hit, at).to.be.within(2, 120);
      expect(last, at).to.be.greaterThan(0.85 * before);
      expect(first, at).to.be.lessThan(0.15 * before);
      expect(rise, at).to.be.greaterThan(0.7 * drop);
      middles.push(middle / before);
    }
    // Most hits leave the middle balls nearly at rest; one that falls badly in a step lets them follow at up to a fifth.
    const told = `middle balls: ${middles.map((m) => m.toFixed(3)).join(' ')}`;
    expect(middles.filter((m) => m < 0.15).length, told).to.be.at.least(6);
    for (const m of middles) expect(m, told).to.be.lessThan(0.25);
  });

  it("Newton's cradle hung 1% of a diameter apart (the gallery's): the last ball rises within 3% of the first one's drop, the others stay", () => {
    // 0.001 apart, a ball struck at 4.8 units/s is pushed into the next within the substep of the hit (it moves 0.008
    // a substep), and the position pass shares the hit among the three; 0.01 apart, each hit is its own.
    for (const degrees of [35, 45, 55]) {
      const { world, balls, drop } = cradle((degrees * Math.PI) / 180, 0.01);
      let rise = 0;
      let others = 0;
      // Until the last ball's swing tops out (before it swings back for the next hit).
      for (let k = 0; k < 300; k++) {
        world.step();
        const up = 5 - world.bodyPose(balls[4]).y;
        if (rise > 0.1 && up < rise) break;
        rise = Math.max(rise, up);
        if (rise > 0.01) for (const j of [0, 1, 2, 3]) others = Math.max(others, 5 - world.bodyPose(balls[j]).y);
      }
      expect(rise / drop, `${degrees}°`).to.be.greaterThan(0.97);
      expect(others / drop, `${degrees}°: the first four`).to.be.lessThan(0.05);
    }
  });
});

describe('rigid bodies: mass properties and rotation', () => {
  it("a box's inertia is m(w² + h²)/12; an L-shaped polygon's centroid and inertia are the exact integrals", () => {
    const world = new World();
    const b = world.addRigidBody({ points: box(1, 0.25), x: 3, y: 4, angle: 0.7, density: 2 });
    const m = world.bodyMassInfo(b);
    expect(m.mass).to.be.closeTo(2 * 2 * 0.5, 1e-12);
    expect(m.inertia).to.be.closeTo((m.mass * (4 + 0.25)) / 12, 1e-12);
    expect([m.centerX, m.centerY]).to.deep.equal([3, 4]);
    // L: [0,2]×[0,1] ∪ [0,1]×[1,2], area 3, centroid (5/6, 5/6), I = 11/6 at density 1.
    const L = world.addRigidBody({ points: [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 2, y: 1 }, { x: 1, y: 1 }, { x: 1, y: 2 }, { x: 0, y: 2 }], x: 10, y: 0 });
    const l = world.bodyMassInfo(L);
    expect(l.mass).to.be.closeTo(3, 1e-12);
    expect(l.inertia).to.be.closeTo(11 / 6, 1e-12);
    expect(l.centerX).to.be.closeTo(10 + 5 / 6, 1e-12);
    expect(l.centerY).to.be.closeTo(5 / 6, 1e-12);
    // The pose is the origin the points were given about, not the centroid.
    expect(world.bodyPose(L)).to.deep.equal({ x: 10, y: 0, angle: 0 });
  });

  it('a domino tipped past balance topples in the analytic time of a block pivoting on its edge, within 3%', () => {
    const world = new World({ sleeping: false });
    world.addRigidBody({ points: box(5, 0.5), x: 0, y: 0.5, type: 'static', friction: 1 });
    const w = 0.2;
    const H = 1;
    const beta = Math.atan(w / H);
    const psi0 = 0.05;
    const phi0 = beta + psi0;
    // Bottom-right corner at the origin, turned by φ0 about it.
    const c = Math.cos(phi0);
    const s = Math.sin(phi0);
    const domino = world.addRigidBody({ points: box(w / 2, H / 2), x: -c * (w / 2) + s * (H / 2), y: -s * (w / 2) - c * (H / 2), angle: phi0, friction: 1 });
    // ψ'' = (3g / 2d)·sin ψ about the edge (I = m·d²/3, d the diagonal); time from ψ0 to φ = 1 rad by RK4.
    const k = (3 * g) / (2 * Math.hypot(w, H));
    const phiEnd = 1;
    let psi = psi0;
    let om = 0;
    let analytic = 0;
    const dt = 1e-5;
    while (psi + beta < phiEnd) {
      const f = (p: number) => k * Math.sin(p);
      const k1x = om;
      const k1v = f(psi);
      const k2x = om + (dt / 2) * k1v;
      const k2v = f(psi + (dt / 2) * k1x);
      const k3x = om + (dt / 2) * k2v;
      const k3v = f(psi + (dt / 2) * k2x);
      const k4x = om + dt * k3v;
      const k4v = f(psi + dt * k3x);
      psi += (dt / 6) * (k1x + 2 * k2x + 2 * k3x + k4x);
      om += (dt / 6) * (k1v + 2 * k2v + 2 * k3v + k4v);
      analytic += dt;
    }
    let previous = phi0;
    let measured = 0;
    for (let n = 1; n <= 300 && measured === 0; n++) {
      world.step();
      const a = world.bodyPose(domino).angle;
      if (a >= phiEnd) measured = (n - 1 + (phiEnd - previous) / (a - previous)) / 60;
      previous = a;
    }
    console.log(`      domino: ${measured.toFixed(4)} s to 1 rad (analytic ${analytic.toFixed(4)})`);
    expect(measured).to.be.closeTo(analytic, 0.03 * analytic);
  });

  // A standing domino set spinning about its centre at ω lands on a bottom corner at once: the corner's impulse keeps
  // the angular momentum about that corner, I_cm·ω = I_c·ω' (the centre still, I_c = I_cm + m·d², d the half diagonal),
  // so it pivots at ω' = ω·I_cm/I_c = ω/4 for a uniform block, and goes over only if ½·I_c·ω'² lifts its centre to
  // above the corner, by d − H/2: ω* = 4·√(2·g·(d − H/2)·m/I_c), 2.270 rad/s for 0.15 × 1. Below it, the tilt where that
  // energy runs out: d·cos(β − φ) = H/2 + (ω/ω*)²·(d − H/2), β = atan(w/H) the balance angle. A landing turned into a
  // bounce, or a spin kept through it, would topple the domino below ω*.
  for (const kernel of ['js', 'wasm'] as const)
    it(`a standing domino spun about its centre topples only above the spin its corner's angular momentum allows (${kernel})`, () => {
      const w = 0.15;
      const H = 1;
      const d = Math.hypot(w, H) / 2;
      const beta = Math.atan(w / H);
      const threshold = 4 * Math.sqrt((2 * g * (d - H / 2)) / ((w * w + H * H) / 3));
      expect(threshold).to.be.closeTo(2.270, 0.001);
      for (const factor of [0.8, 0.9, 0.97, 1.03, 1.2]) {
        for (const sign of [1, -1]) {
          const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: g } });
          world.addRigidBody({ points: box(5, 0.5), x: 0, y: 0.5, type: 'static', friction: 1 });
          const domino = world.addRigidBody({ points: box(w / 2, H / 2), x: 0, y: -H / 2, friction: 1 });
          world.setBodyAngularVelocity(domino, sign * factor * threshold);
          let most = 0;
          for (let n = 0; n < 180; n++) {
            world.step();
            most = Math.max(most, Math.abs(world.bodyPose(domino).angle));
          }
          const final = Math.abs(world.bodyPose(domino).angle);
          const at = `ω = ${sign * factor}·ω*`;
          if (factor > 1) {
            expect(final, at).to.be.within(Math.PI / 2 - 0.01, Math.PI / 2 + 0.01);
          } else {
            // It rocks on its base, never past the balance angle, its largest tilt the analytic one within 10%
            // (0.8·ω*: 0.0597 rad, 0.9: 0.0841, 0.97: 0.1128).
            const tilt = beta - Math.acos((H / 2 + factor * factor * (d - H / 2)) / d);
            expect(most, `${at}: largest tilt`).to.be.closeTo(tilt, 0.1 * tilt);
            expect(final, `${at}: standing after 3 s`).to.be.below(beta);
          }
        }
      }
    });
});

describe('rigid bodies: joints', () => {
  /** Exact period of a physical pendulum of amplitude θ0 (complete elliptic integral by the AGM). */
  function period(Ip: number, d: number, theta0: number): number {
    let a = 1;
    let b = Math.cos(theta0 / 2);
    for (let i = 0; i < 30; i++) [a, b] = [(a + b) / 2, Math.sqrt(a * b)];
    return 4 * Math.sqrt(Ip / (g * d)) * (Math.PI / (2 * a));
  }

  it('a revolute or rigid distance pendulum swings with the exact large-angle period within 1% and loses < 5% of its amplitude in 10 s, at the default substeps and at 4 and 20', () => {
    const L = 2;
    const theta0 = 1.2;
    for (const [type, substeps] of [['revolute', 'auto'], ['revolute', 4], ['revolute', 20], ['distance', 'auto'], ['distance', 4]] as const) {
      const world = new World({ sleeping: false, substeps });
      const start = { x: L * Math.sin(theta0), y: L * Math.cos(theta0) };
      const bob = world.addRigidBody({ radius: 0.1, ...start, collide: false });
      // A revolute joint turns the bob with the swing (a physical pendulum); a distance joint at its centre does not.
      if (type === 'revolute') world.addJoint({ type, a: bob, anchor: { x: 0, y: 0 } });
      else world.addJoint({ type, a: bob, anchorA: start, anchorB: { x: 0, y: 0 } });
      const T = period((type === 'revolute' ? 0.5 * 0.1 * 0.1 : 0) + L * L, L, theta0);
      const crossings: number[] = [];
      let previous = theta0;
      let late = 0;
      let stretch = 0;
      steps(world, 600, (n) => {
        const p = world.bodyPose(bob);
        const angle = Math.atan2(p.x, p.y);
        if (previous > 0 && angle <= 0) crossings.push((n - angle / (angle - previous)) / 60);
        previous = angle;
        if (n > 540) late = Math.max(late, Math.abs(angle));
        stretch = Math.max(stretch, Math.abs(Math.hypot(p.x, p.y) - L));
      });
      const measured = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
      console.log(`      ${type} pendulum, substeps ${substeps}: period ${measured.toFixed(4)} s (exact ${T.toFixed(4)}), amplitude ${late.toFixed(4)} of ${theta0} after 10 s, stretch ${stretch.toExponential(1)}`);
      expect(crossings.length, `${type}, substeps ${substeps}`).to.be.at.least(3);
      expect(measured, `${type}, substeps ${substeps}`).to.be.closeTo(T, 0.01 * T);
      expect(late, `${type}, substeps ${substeps}`).to.be.greaterThan(0.95 * theta0);
      expect(late, `${type}, substeps ${substeps}: no energy gained`).to.be.lessThan(1.001 * theta0);
      expect(stretch, `${type}, substeps ${substeps}`).to.be.lessThan(1e-6);
    }
  });

  it('an undamped spring joint keeps its swing at the period 2π·√(m/k); a damped one decays as e^(−c·t/2m); a stiff one holds', () => {
    // A disc of mass 1 on a spring from its centre to the world point (−1, 0), rest length 1, let go stretched 0.5, no
    // gravity. As an XPBD compliant constraint the spring lost amplitude at about k·h/(2m) a second (k = 1000: 5% of
    // the swing left after 2 s); soft enough for an explicit step, it is a force now.
    const swing = (k: number, c: number, seconds: number) => {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
      const disc = world.addRigidBody({ radius: 0.2, mass: 1, x: 0.5, y: 0 });
      world.addJoint({ type: 'spring', a: disc, anchorB: { x: -1, y: 0 }, length: 1, stiffness: k, damping: c });
      const xs = [0.5];
      steps(world, Math.round(60 * seconds), () => xs.push(world.bodyPose(disc).x));
      return xs;
    };
    for (const k of [10, 100, 1000, 10000]) {
      const xs = swing(k, 0, 10);
      const late = Math.max(...xs.slice(-60).map(Math.abs));
      expect(late, `k ${k}: amplitude after 10 s`).to.be.closeTo(0.5, 0.01);
      if (k > 1000) continue;
      // Downward zero crossings, interpolated between steps: the mean period.
      const crossings: number[] = [];
      for (let n = 1; n < xs.length; n++) if (xs[n - 1] > 0 && xs[n] <= 0) crossings.push((n - 1 + xs[n - 1] / (xs[n - 1] - xs[n])) / 60);
      const period = (crossings[crossings.length - 1] - crossings[0]) / (crossings.length - 1);
      expect(period, `k ${k}: period`).to.be.closeTo(2 * Math.PI * Math.sqrt(1 / k), 0.005 * 2 * Math.PI * Math.sqrt(1 / k));
    }
    // k = 100, c = 2: each swing's peak e^(−c·T/2m) of the one before, T = 2π/√(k/m − (c/2m)²).
    const xs = swing(100, 2, 3);
    const peaks = xs.filter((x, n) => n > 0 && n < xs.length - 1 && x > xs[n - 1] && x >= xs[n + 1] && x > 0.01);
    const ratio = Math.exp(-(2 * Math.PI) / Math.sqrt(100 - 1));
    expect(peaks.length).to.be.at.least(3);
    for (let n = 1; n < 3; n++) expect(peaks[n] / peaks[n - 1], `peak ${n}`).to.be.closeTo(ratio, 0.03 * ratio);
    // Stiffer than an explicit step can take (k·h²/m ≫ 0.1): still the XPBD constraint, which holds and stays finite.
    const stiff = swing(1e7, 0, 2);
    expect(stiff.every((x) => Number.isFinite(x) && Math.abs(x) <= 0.5 + 1e-9)).to.equal(true);
  });

  it('a box swinging and turning on an undamped spring from its corner keeps its energy', () => {
    const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
    const body = world.addRigidBody({ points: box(0.5, 0.25), mass: 1, x: 0, y: 0, angle: 0.3 });
    const k = 200;
    // Anchors are world points: the box's corner (0.5, 0.25) as it lies, to a point off the line through its centre.
    const corner = { x: Math.cos(0.3) * 0.5 - Math.sin(0.3) * 0.25, y: Math.sin(0.3) * 0.5 + Math.cos(0.3) * 0.25 };
    world.addJoint({ type: 'spring', a: body, anchorA: corner, anchorB: { x: 2, y: -1 }, length: 0.5, stiffness: k, damping: 0 });
    const { inertia } = world.bodyMassInfo(body);
    const energy = () => {
      const p = world.bodyPose(body);
      const v = world.bodyVelocity(body);
      const w = world.bodyAngularVelocity(body);
      // The corner (0.5, 0.25) in the world.
      const cx = p.x + Math.cos(p.angle) * 0.5 - Math.sin(p.angle) * 0.25;
      const cy = p.y + Math.sin(p.angle) * 0.5 + Math.cos(p.angle) * 0.25;
      const stretch = Math.hypot(cx - 2, cy + 1) - 0.5;
      return 0.5 * (v.x * v.x + v.y * v.y) + 0.5 * inertia * w * w + 0.5 * k * stretch * stretch;
    };
    // Each second's mean energy (the energy of the positions and the substep's velocities, half a substep apart,
    // swings by a few % within a swing: symplectic Euler keeps a nearby energy exactly). As a constraint the spring
    // kept 28% of it after 2 s and 0.1% after 8 s.
    const start = energy();
    let turned = 0;
    const means: number[] = [];
    for (let second = 0; second < 10; second++) {
      let sum = 0;
      steps(world, 60, () => {
        sum += energy();
        expect(Math.abs(energy() / start - 1), `second ${second}`).to.be.lessThan(0.06);
        turned = Math.max(turned, Math.abs(world.bodyAngularVelocity(body)));
      });
      means.push(sum / 60 / start);
    }
    console.log(`      spring-held box: each second's mean energy ${Math.min(...means).toFixed(4)}–${Math.max(...means).toFixed(4)} of the start's`);
    expect(turned, 'it turns').to.be.greaterThan(1);
    for (const m of means) expect(m).to.be.closeTo(1, 0.01);
  });

  it('a box hung by a rigid rod from an off-centre anchor never gains energy (100 random rods, both kernels)', () => {
    // A body on an off-centre anchor is a double pendulum whose rod end whips through near-singular poses; there the
    // start pose's levers (SHAKE) and today's disagree, and acting through the start levers overshot: 18 of these
    // 100 rods gained over 1% of their drop energy in 10 s, one 63%. Where they disagree by over SHAKE_AGREEMENT the
    // correction now acts along today's gradient.
    for (let k = 0; k < 100; k++) {
      const rnd = rng(99 + k);
      const world = new World({ kernel: k % 2 ? 'wasm' : 'js', gravity: { x: 0, y: 10 }, sleeping: false });
      const size = 0.1 + rnd() * 2;
      const body = world.addRigidBody({ points: box(size / 2, size / (2 + rnd() * 6)), x: 0, y: 0, angle: rnd() * 6, collide: false });
      const reach = 3 * size * rnd();
      const anchorA = { x: (rnd() * 2 - 1) * reach, y: (rnd() * 2 - 1) * reach };
      world.addJoint({ type: 'distance', a: body, anchorA, anchorB: { x: (rnd() * 2 - 1) * 3, y: -rnd() * 3 } });
      // The scale: the body's weight over 10 units.
      const scale = world.bodyMassInfo(body).mass * 10 * 10;
      const start = rigidEnergy(world, [body], 10);
      let most = -Infinity;
      steps(world, 600, () => (most = Math.max(most, (rigidEnergy(world, [body], 10) - start) / scale)));
      expect(most, `rod ${k}: the largest gain`).to.be.below(0.01);
    }
  });

  it('two welded boxes spinning free keep their energy and angular momentum, as revolute and distance joints do', () => {
    // Zero gravity; after the first step (the weld makes their velocities those of one rigid body) nothing acts on
    // the pair from outside. The weld's correction once followed the current levers: 31–46% of the energy lost in 10 s.
    for (const type of ['weld', 'revolute', 'distance'] as const) {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
      const a = world.addRigidBody({ points: box(0.5, 0.25), mass: 1, x: -0.5, y: 0, angularVelocity: 3, vy: -1.5 });
      const b = world.addRigidBody({ points: box(0.5, 0.25), mass: 2, x: 0.5, y: 0, angularVelocity: 3, vy: 1.5 });
      world.addJoint({ type, a, b, anchor: { x: 0, y: 0 }, ...(type === 'distance' ? { anchorA: { x: -0.5, y: 0 }, anchorB: { x: 0.5, y: 0 } } : {}) });
      const totals = () => {
        let energy = 0;
        let momentum = 0;
        for (const h of [a, b]) {
          const m = world.bodyMassInfo(h);
          const p = world.bodyPose(h);
          const v = world.bodyVelocity(h);
          const w = world.bodyAngularVelocity(h);
          energy += 0.5 * m.mass * (v.x * v.x + v.y * v.y) + 0.5 * m.inertia * w * w;
          momentum += m.mass * (p.x * v.y - p.y * v.x) + m.inertia * w;
        }
        return { energy, momentum };
      };
      world.step();
      const start = totals();
      steps(world, 600);
      const end = totals();
      expect(end.energy / start.energy, `${type}: energy`).to.be.closeTo(1, 2e-3);
      expect(end.momentum / start.momentum, `${type}: angular momentum`).to.be.closeTo(1, 1e-4);
    }
  });

  it('chains of 3, 5 and 10 revolute links released level keep their energy through the whips (their joints solved as one tree)', () => {
    // Each link 1 × 0.1, hinged end to end, the first to the world, released horizontal under gravity 10: the chain
    // folds and whips (angular speeds up to 19 rad/s). One Gauss–Seidel sweep of the joints a substep left each joint
    // nearly its whole correction (about cos²(π/(n+1)) of it), which the next substep took out of the motion: 9.7%,
    // 17% and 34% of the drop energy lost in 10 s at the default 6 substeps (1.2%, 2.3% and 18% at 10).
    for (const kernel of ['js', 'wasm'] as const)
      for (const links of [3, 5, 10]) {
        const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false });
        const bodies: Handle[] = [];
        let previous: Handle | null = null;
        for (let k = 0; k < links; k++) {
          const link = world.addRigidBody({ points: box(0.5, 0.05), x: k + 0.5, y: 0, collide: false });
          world.addJoint({ type: 'revolute', a: link, b: previous, anchor: { x: k, y: 0 } });
          bodies.push(link);
          previous = link;
        }
        const energy = (): number => rigidEnergy(world, bodies, 10);
        // The energy the chain has to spend: its drop to hanging straight down, m·g·L·n/2 over the links' centres.
        const drop = bodies.reduce((sum, b) => sum + world.bodyMassInfo(b).mass, 0) * 10 * links / 2;
        const start = energy();
        let worst = 0;
        let gap = 0;
        for (let s = 1; s <= 600; s++) {
          world.step();
          if (s % 10 === 0) worst = Math.max(worst, Math.abs(energy() - start) / drop);
          // The hinges stay together: each link's end meets the next link's start.
          for (let k = 0; k + 1 < links; k++) {
            const p = world.bodyPose(bodies[k]);
            const q = world.bodyPose(bodies[k + 1]);
            gap = Math.max(gap, Math.hypot(p.x + 0.5 * Math.cos(p.angle) - (q.x - 0.5 * Math.cos(q.angle)), p.y + 0.5 * Math.sin(p.angle) - (q.y - 0.5 * Math.sin(q.angle))));
          }
        }
        expect(worst, `${kernel}, ${links} links: energy`).to.be.below(0.01);
        expect(gap, `${kernel}, ${links} links: hinge gap`).to.be.below(1e-3);
      }
  });

  it('a branching tree of revolute joints, a chain with a limit and a motor, and a loop pinned at both ends hold their joints', () => {
    const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
    // A T: a trunk hinged to the world with two arms hinged at its end, released turned.
    const trunk = world.addRigidBody({ points: box(0.05, 0.5), x: 0, y: 0.5, angularVelocity: 2, collide: false });
    world.addJoint({ type: 'revolute', a: trunk, anchor: { x: 0, y: 0 } });
    const arms = [-1, 1].map((side) => {
      const arm = world.addRigidBody({ points: box(0.5, 0.05), x: side * 0.5, y: 1, collide: false });
      world.addJoint({ type: 'revolute', a: arm, b: trunk, anchor: { x: 0, y: 1 } });
      return arm;
    });
    // A chain of three from (5, 0) whose middle hinge is limited to ±0.3 rad, and whose last hinge is a motor at 2 rad/s.
    const chain: Handle[] = [];
    for (let k = 0; k < 3; k++) chain.push(world.addRigidBody({ points: box(0.5, 0.05), x: 5.5 + k, y: 0, collide: false }));
    world.addJoint({ type: 'revolute', a: chain[0], anchor: { x: 5, y: 0 } });
    world.addJoint({ type: 'revolute', a: chain[1], b: chain[0], anchor: { x: 6, y: 0 }, lowerAngle: -0.3, upperAngle: 0.3 });
    world.addJoint({ type: 'revolute', a: chain[2], b: chain[1], anchor: { x: 7, y: 0 }, motorSpeed: 2, maxMotorTorque: 1e4 });
    // Four links hung in a V from pins 3.5 apart: the last hinge closes a loop through the world (left to the sweep).
    const loop: Handle[] = [];
    const slope = Math.acos(1.75 / 2);
    const hinges: Vec2[] = [0, 1, 2, 3, 4].map((k) => ({ x: 10 + k * Math.cos(slope), y: (k <= 2 ? k : 4 - k) * Math.sin(slope) }));
    for (let k = 0; k < 4; k++) {
      const angle = k < 2 ? slope : -slope;
      loop.push(world.addRigidBody({ points: box(0.5, 0.05), x: (hinges[k].x + hinges[k + 1].x) / 2, y: (hinges[k].y + hinges[k + 1].y) / 2, angle, collide: false }));
    }
    world.addJoint({ type: 'revolute', a: loop[0], anchor: hinges[0] });
    for (let k = 1; k < 4; k++) world.addJoint({ type: 'revolute', a: loop[k], b: loop[k - 1], anchor: hinges[k] });
    world.addJoint({ type: 'revolute', a: loop[3], anchor: hinges[4] });
    const end = (b: Handle, along: number): Vec2 => {
      const p = world.bodyPose(b);
      return { x: p.x + along * Math.cos(p.angle), y: p.y + along * Math.sin(p.angle) };
    };
    const apart = (p: Vec2, q: Vec2): number => Math.hypot(p.x - q.x, p.y - q.y);
    let gap = 0;
    let limit = 0;
    for (let s = 0; s < 300; s++) {
      world.step();
      const t = world.bodyPose(trunk);
      const tip = { x: t.x - 0.5 * Math.sin(t.angle), y: t.y + 0.5 * Math.cos(t.angle) };
      const top = { x: t.x + 0.5 * Math.sin(t.angle), y: t.y - 0.5 * Math.cos(t.angle) };
      gap = Math.max(gap, apart(top, { x: 0, y: 0 }), apart(end(arms[0], 0.5), tip), apart(end(arms[1], -0.5), tip));
      gap = Math.max(gap, apart(end(chain[0], -0.5), { x: 5, y: 0 }), apart(end(chain[0], 0.5), end(chain[1], -0.5)), apart(end(chain[1], 0.5), end(chain[2], -0.5)));
      gap = Math.max(gap, apart(end(loop[0], -0.5), hinges[0]), apart(end(loop[3], 0.5), hinges[4]));
      for (let k = 1; k < 4; k++) gap = Math.max(gap, apart(end(loop[k - 1], 0.5), end(loop[k], -0.5)));
      limit = Math.max(limit, Math.abs(world.bodyPose(chain[1]).angle - world.bodyPose(chain[0]).angle));
    }
    // Measured: 0.0035, of the chain with the limit and the motor (0.0038 when every joint was swept); the tree 3e-9.
    expect(gap, 'joints apart').to.be.below(5e-3);
    expect(limit, 'the limited hinge').to.be.below(0.3 + 0.01);
    // The motor turns its link at 2 rad/s relative to the one before.
    const w = world.bodyAngularVelocity(chain[2]) - world.bodyAngularVelocity(chain[1]);
    expect(w, 'the motor').to.be.closeTo(2, 0.05);
  });

  it('a heavy block welded to the world through a feather-light bar on long levers stays where it is, in both kernels', () => {
    // Welded to the world, the three bodies are one rigid piece and should not move. The bar weighs 6·10⁻⁴ of a unit
    // and the welds act 3 to 8 units from it. Swept weld by weld, a correction turned the bar by radians at once and
    // overshot more each substep: the block flew off at 420 units/s; with each correction's turn kept within MAX_TURN
    // (withinTurn in joints.ts) it still fell 52 units in 5 s. Solved as a tree (joint-tree.ts) nothing moves.
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, gravity: { x: 0, y: 10 }, sleeping: false });
      const disc = world.addRigidBody({ radius: 0.87, x: 3.57, y: 1.79, mass: 3, collide: false });
      const bar = world.addRigidBody({ points: box(0.82, 0.26), x: -1.9, y: 3.44, angle: 0.4, mass: 6e-4, collide: false });
      const block = world.addRigidBody({ points: box(1, 0.95), x: 0.35, y: -2.13, mass: 15.7, collide: false });
      world.addJoint({ type: 'weld', a: disc, anchor: { x: 4.88, y: 3.09 } });
      world.addJoint({ type: 'weld', a: bar, b: disc, anchor: { x: -3.23, y: 5.9 } });
      world.addJoint({ type: 'weld', a: block, b: bar, anchor: { x: 0.17, y: 0.5 } });
      const start = [disc, bar, block].map((h) => world.bodyPose(h));
      let moved = 0;
      steps(world, 300, () => {
        [disc, bar, block].forEach((h, k) => {
          const p = world.bodyPose(h);
          moved = Math.max(moved, Math.hypot(p.x - start[k].x, p.y - start[k].y), Math.abs(p.angle - start[k].angle));
        });
      });
      expect(moved, kernel).to.be.below(1e-6);
    }
  });

  it('weld, prismatic (with limits), distance and spring joints hold what they promise', () => {
    const world = new World({ sleeping: false });
    // Weld: a plank welded to a static post keeps its angle and anchor under gravity.
    const post = world.addRigidBody({ points: box(0.1, 0.1), x: 0, y: 0, type: 'static' });
    const plank = world.addRigidBody({ points: box(1, 0.05), x: 1, y: 0 });
    world.addJoint({ type: 'weld', a: post, b: plank, anchor: { x: 0, y: 0 } });
    // Prismatic: a slider on a horizontal rail through (5, 0), limited to [−1, 1].
    const slider = world.addRigidBody({ points: box(0.2, 0.2), x: 5, y: 0, vx: 3 });
    world.addJoint({ type: 'prismatic', a: post, b: slider, anchor: { x: 5, y: 0 }, axis: { x: 1, y: 0 }, lower: -1, upper: 1 });
    // Distance: a box hanging 2 below the world point (10, 0); spring: a box on a spring of k = 100.
    const hung = world.addRigidBody({ points: box(0.2, 0.2), x: 10, y: 2 });
    world.addJoint({ type: 'distance', a: hung, anchorA: { x: 10, y: 1.8 }, anchorB: { x: 10, y: 0 } });
    const bob = world.addRigidBody({ points: box(0.1, 0.1), x: 20, y: 1, collide: false });
    world.addJoint({ type: 'spring', a: bob, anchorB: { x: 20, y: 0 }, stiffness: 100, damping: 2 });
    steps(world, 300);
    const pl = world.bodyPose(plank);
    expect(Math.abs(pl.angle)).to.be.lessThan(1e-3);
    expect(pl.x).to.be.closeTo(1, 1e-3);
    expect(pl.y).to.be.closeTo(0, 1e-3);
    const sl = world.bodyPose(slider);
    expect(sl.y).to.be.closeTo(0, 1e-3);
    expect(sl.x).to.be.within(4 - 1e-3, 6 + 1e-3);
    expect(Math.abs(sl.angle)).to.be.lessThan(1e-3);
    const hp = world.bodyPose(hung);
    expect(Math.hypot(hp.x - 10, hp.y - 0.2 - 0) - 1.8).to.be.closeTo(0, 2e-3);
    // Spring at rest: stretch = m·g / k (mass 0.04) from rest length 1, within 1% after the damping settles it.
    const m = world.bodyMassInfo(bob).mass;
    expect(world.bodyPose(bob).y).to.be.closeTo(1 + (m * g) / 100, 0.01 * (1 + (m * g) / 100));
  });

  it('a slider to the world or to a static body, hit by bodies up to 200× heavier, gives way but is never thrown off (both kernels)', () => {
    // A 0.6 × 0.6 box on a slider limited to [−1, 1], hit by a 1 × 1 box 1–200 times heavier at 5–105 units/s from
    // any side. A joint to something immovable is a bumper, not a wall (docs/engine.md, Known limits), but its axis
    // is the world's: when it turned with the box, a hit that turned the box swept the far anchor across it, and these
    // hits threw it at up to 40,000 units/s, 3.2 past its limit at the 90th percentile (now 172 and 0.55).
    for (const kernel of ['js', 'wasm'] as const) {
      const random = rng(61);
      const worst = { speed: 0, past: [] as number[], forms: 0 };
      for (let k = 0; k < 40; k++) {
        const angle = (random() - 0.5) * 2;
        const turn = random() * 2 * Math.PI;
        const axis = { x: Math.cos(turn), y: Math.sin(turn) };
        const anchor = { x: (random() - 0.5) * 0.8, y: (random() - 0.5) * 0.8 };
        const ratio = Math.exp(random() * Math.log(200));
        const speed = 5 + random() * 100;
        const heading = random() * 2 * Math.PI;
        const from = { x: -3 * Math.cos(heading) + (random() - 0.5) * 0.6, y: -3 * Math.sin(heading) + (random() - 0.5) * 0.6 };
        const spin = random();
        const gravity = random() < 0.5 ? 0 : 10;
        // The same slider three ways: to the world, from a static post, and to one.
        const runs = [0, 1, 2].map((form) => {
          const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: gravity } });
          const slider = world.addRigidBody({ points: box(0.3, 0.3), x: 0, y: 0, angle });
          const post = world.addRigidBody({ points: box(0.1, 0.1), x: 5, y: 5, type: 'static', collide: false });
          const [a, b] = form === 0 ? [slider, undefined] : form === 1 ? [post, slider] : [slider, post];
          world.addJoint({ type: 'prismatic', a, b, anchor, axis, lower: -1, upper: 1 });
          const hammer = world.addRigidBody({ points: box(0.5, 0.5), ...from, angle: spin, density: ratio * 0.36 });
          world.setBodyVelocity(hammer, speed * Math.cos(heading), speed * Math.sin(heading));
          let past = 0;
          steps(world, 120, () => {
            const p = world.bodyPose(slider);
            const along = p.x * axis.x + p.y * axis.y;
            past = Math.max(past, along - 1, -1 - along);
            const v = world.bodyVelocity(slider);
            worst.speed = Math.max(worst.speed, Math.hypot(v.x, v.y));
          });
          return { past, end: world.bodyPose(slider) };
        });
        worst.past.push(runs[0].past);
        for (const run of runs.slice(1)) worst.forms = Math.max(worst.forms, Math.abs(run.end.x - runs[0].end.x), Math.abs(run.end.y - runs[0].end.y));
      }
      worst.past.sort((p, q) => p - q);
      const p90 = worst.past[Math.floor(0.9 * (worst.past.length - 1))];
      console.log(`      ${kernel}: fastest ${worst.speed.toFixed(0)} units/s, past the limit by ${worst.past[20].toFixed(3)} (median), ${p90.toFixed(2)} (90th percentile); the three forms within ${worst.forms.toExponential(1)}`);
      expect(worst.speed, kernel).to.be.below(1000);
      expect(p90, kernel).to.be.below(1);
      expect(worst.forms, kernel).to.be.below(1e-6);
    }
  });

  it('a box hinged to the world, with or without a motor, hit by bodies up to 200× heavier, gives way but is never thrown off (both kernels)', () => {
    // As for the slider above: hits of 5–105 units/s from any side by boxes 1–200 times heavier. A pivot correction
    // that would turn the box past MAX_TURN was scaled down whole, and what it left of the gap swung the box through
    // its pivot and back, further each time: on the hits without a motor the box was thrown at up to 1,240 units/s
    // and the pivot opened 2.3 at the 90th percentile (now 373 and 1.1).
    for (const kernel of ['js', 'wasm'] as const) {
      for (const motor of [false, true]) {
        const random = rng(motor ? 7 : 8);
        let fastest = 0;
        const gaps: number[] = [];
        for (let k = 0; k < 100; k++) {
          const { angle, anchor, ratio, speed, heading } = randomHit(random);
          const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: random() < 0.5 ? 0 : 10 } });
          const hinged = world.addRigidBody({ points: box(0.3, 0.3), x: 0, y: 0, angle });
          world.addJoint({ type: 'revolute', a: hinged, anchor, ...(motor ? { motorSpeed: 0, maxMotorTorque: 50 } : {}) });
          const from = { x: -3 * Math.cos(heading) + (random() - 0.5) * 0.6, y: -3 * Math.sin(heading) + (random() - 0.5) * 0.6 };
          const hammer = world.addRigidBody({ points: box(0.5, 0.5), ...from, angle: random(), density: ratio * 0.36 });
          world.setBodyVelocity(hammer, speed * Math.cos(heading), speed * Math.sin(heading));
          // The box's own point at the anchor, in its frame.
          const lx = Math.cos(angle) * anchor.x + Math.sin(angle) * anchor.y;
          const ly = -Math.sin(angle) * anchor.x + Math.cos(angle) * anchor.y;
          let gap = 0;
          steps(world, 120, () => {
            const p = world.bodyPose(hinged);
            const c = Math.cos(p.angle);
            const s = Math.sin(p.angle);
            gap = Math.max(gap, Math.hypot(p.x + c * lx - s * ly - anchor.x, p.y + s * lx + c * ly - anchor.y));
            const v = world.bodyVelocity(hinged);
            fastest = Math.max(fastest, Math.hypot(v.x, v.y));
          });
          gaps.push(gap);
        }
        gaps.sort((p, q) => p - q);
        const p90 = gaps[89];
        const name = `${kernel}${motor ? ', motor' : ''}`;
        console.log(`      ${name}: fastest ${fastest.toFixed(0)} units/s; the pivot opened ${gaps[49].toFixed(3)} (median), ${p90.toFixed(2)} (90th percentile)`);
        expect(fastest, name).to.be.below(1000);
        expect(p90, name).to.be.below(1.5);
      }
    }
  });

  it('a box welded rigidly to the world, a static or a kinematic body, hit by bodies up to 200× heavier, holds as a static box does (both kernels)', () => {
    // The weld leaves it no freedom: the shock sweep holds it as the ground (level 0) and moves only what hits it,
    // after holdWelded() has set it back to its pose. Before, the contact moved it as the free body it is and the weld
    // pulled it back: a bumper that gave way 0.1–7 and threw the hammer back at 58–78% of its speed (restitution 0).
    for (const kernel of ['js', 'wasm'] as const) {
      // bench/held-joints.mjs's hits: hammers 10, 10, 50 and 170 times the box's mass at 20, 40, 40 and 276 units/s.
      for (const [ratio, speed] of [[10, 20], [10, 40], [50, 40], [170, 276]]) {
        // 'static, as a': the weld written the other way round (the held box is its b).
        for (const holder of ['world', 'static', 'kinematic', 'static, as a'] as const) {
          const world = new World({ sleeping: false, gravity: { x: 0, y: 0 }, kernel });
          const held = world.addRigidBody({ points: box(0.3, 0.3), x: 0, y: 0, angle: 0.3, friction: 0.6, restitution: 0 });
          const other = holder === 'world' ? undefined : world.addRigidBody({ points: box(0.1, 0.1), x: 3, y: 3, angle: 0.5, type: holder === 'kinematic' ? 'kinematic' : 'static' });
          const anchor = { x: 0.1, y: -0.1 };
          if (holder === 'static, as a') world.addJoint({ type: 'weld', a: other!, b: held, anchor });
          else world.addJoint({ type: 'weld', a: held, ...(other === undefined ? {} : { b: other }), anchor });
          const hammer = world.addRigidBody({ points: box(0.5, 0.5), x: -3, y: 0.1, density: ratio * 0.36, friction: 0.6, restitution: 0 });
          world.setBodyVelocity(hammer, speed, 0);
          let moved = 0;
          steps(world, 120, () => {
            const p = world.bodyPose(held);
            moved = Math.max(moved, Math.hypot(p.x, p.y), Math.abs(p.angle - 0.3));
          });
          const v = world.bodyVelocity(hammer);
          const where = `${kernel}, ${holder}, ${ratio}× at ${speed}`;
          expect(moved, where).to.be.below(0.005);
          // Stopped (it slides off the turned face, as off a static box: back at 3–10% of its speed), not sent back.
          expect(-v.x, where).to.be.below(0.15 * speed);
          expect(world.bodyPose(hammer).x, where).to.be.below(-0.5);
        }
      }
      // Random hits from any side, with gravity half the time: it gives way 0.006 at the median (0.66 before) and
      // never turns (0.83 rad at the median before). A few corners come in unseen by the step's speculative points and
      // end a step deep in it; the box is then pushed out as a static one is not (the largest, 0.43 of 60: 4.7 before).
      const random = rng(9);
      const moves: number[] = [];
      for (let k = 0; k < 60; k++) {
        const { angle, anchor, ratio, speed, heading } = randomHit(random);
        const hammerAngle = random();
        const world = new World({ sleeping: false, gravity: { x: 0, y: random() < 0.5 ? 0 : 10 }, kernel });
        const held = world.addRigidBody({ points: box(0.3, 0.3), x: 0, y: 0, angle, restitution: 0 });
        const b = k % 3 === 0 ? undefined : world.addRigidBody({ points: box(0.1, 0.1), x: 2, y: 2, type: k % 3 === 1 ? 'static' : 'kinematic' });
        world.addJoint({ type: 'weld', a: held, ...(b === undefined ? {} : { b }), anchor });
        const hammer = world.addRigidBody({ points: box(0.5, 0.5), x: -3 * Math.cos(heading), y: -3 * Math.sin(heading), angle: hammerAngle, density: ratio, restitution: 0 });
        world.setBodyVelocity(hammer, speed * Math.cos(heading), speed * Math.sin(heading));
        let moved = 0;
        steps(world, 120, () => {
          const p = world.bodyPose(held);
          moved = Math.max(moved, Math.hypot(p.x, p.y));
          expect(Math.abs(p.angle - angle), `${kernel}, hit ${k}: turned`).to.be.below(1e-9);
        });
        moves.push(moved);
      }
      moves.sort((p, q) => p - q);
      expect(moves[30], `${kernel}: median`).to.be.below(0.01);
      expect(moves[54], `${kernel}: 90th percentile`).to.be.below(0.15);
      expect(moves[59], `${kernel}: largest`).to.be.below(0.6);
    }
  });

  it('two bodies hinged, welded, tied by a rod or on a slider (one to the world half the time), hit by bodies up to 200× heavier, are not thrown off', () => {
    // Hits of 5–105 units/s from any side by boxes 1–200 times heavier on a 0.6 × 0.6 box joined to a 0.8 × 0.4 one,
    // densities e^±2. The joints form a tree (joint-tree.ts) solved at once; after a hit had opened it, the linear
    // answer turned the bodies by radians in a substep and each pass overshot the last: 7 of these 200 hinged pairs
    // and 8 of the 200 welded ones were thrown at 10³–10¹² units/s. Each solve's turns are now capped (TREE_MAX_TURN):
    // none. A rod is swept (joints.ts, correct()): its correction, scaled down to MAX_TURN, left the rest of the error
    // to swing the bodies about it, and one of these 200 pairs was thrown at 3,400 units/s (the next at 690); the rest
    // is now closed by moving them alone (the fastest at 790). A slider's correction across its axis likewise:
    // more than 10 of these 200 slider pairs were thrown at 10¹² units/s.
    for (const kind of ['revolute', 'weld', 'distance', 'prismatic'] as const) {
      const random = rng({ revolute: 30, weld: 31, distance: 32, prismatic: 33 }[kind]);
      const fastest: number[] = [];
      for (let k = 0; k < 200; k++) {
        const world = new World({ sleeping: false, gravity: { x: 0, y: random() < 0.5 ? 0 : 10 } });
        const a = world.addRigidBody({ points: box(0.3, 0.3), x: 0, y: 0, angle: random(), density: Math.exp((random() - 0.5) * 4) });
        const b = world.addRigidBody({ points: box(0.4, 0.2), x: 0.5 + random(), y: random() - 0.5, angle: random(), density: Math.exp((random() - 0.5) * 4) });
        const anchor = { x: random() * 0.8, y: (random() - 0.5) * 0.4 };
        if (kind === 'distance') world.addJoint({ type: kind, a, b, anchorA: anchor, anchorB: { x: anchor.x + 0.5, y: anchor.y } });
        else if (kind === 'prismatic') world.addJoint({ type: kind, a, b, anchor, axis: { x: random() - 0.5, y: random() - 0.5 }, lower: -1, upper: 1 });
        else world.addJoint({ type: kind, a, b, anchor });
        if (random() < 0.5) world.addJoint({ type: 'revolute', a: b, anchor: { x: 1.5, y: 0 } });
        const ratio = Math.exp(random() * Math.log(200));
        const speed = 5 + random() * 100;
        const heading = random() * 2 * Math.PI;
        const hammer = world.addRigidBody({ points: box(0.5, 0.5), x: -3 * Math.cos(heading), y: -3 * Math.sin(heading), angle: random(), density: ratio });
        world.setBodyVelocity(hammer, speed * Math.cos(heading), speed * Math.sin(heading));
        let most = 0;
        steps(world, 120, () => {
          for (const h of [a, b]) most = Math.max(most, Math.hypot(world.bodyVelocity(h).x, world.bodyVelocity(h).y));
        });
        fastest.push(most);
      }
      fastest.sort((p, q) => p - q);
      console.log(`      ${kind}: the fastest of 200 at ${fastest[199].toFixed(0)} units/s, the next ${fastest[198].toFixed(0)}, the 90th percentile ${fastest[179].toFixed(0)}`);
      // One slider pair is spun up over 2 s to 2,070 units/s, the turn cap (docs/engine.md, Known limits).
      expect(fastest[198], kind).to.be.below(1000);
      expect(fastest[199], kind).to.be.below(kind === 'prismatic' ? 2500 : 1500);
    }
  });

  it('a regular polygon rolls down a slope as far as a pivot-and-impact model says, closer to the disc the more sides it has', () => {
    // The model: the polygon turns about its lower corner under gravity; each next corner lands in a perfectly
    // inelastic, non-slipping impact that keeps the angular momentum about it: ω₊/ω₋ = (Ic + m R² cos 2α)/(Ic + m R²),
    // α = π/N, Ic = m R² (1 + 2 cos² α)/6. Distance: the corners landed × the side.
    const theta = (20 * Math.PI) / 180;
    const R = 0.5;
    const model = (N: number, T: number) => {
      const a = Math.PI / N;
      const ic = ((R * R) / 6) * (1 + 2 * Math.cos(a) ** 2);
      const ip = ic + R * R;
      const ratio = (ic + R * R * Math.cos(2 * a)) / ip;
      let phi = -a;
      let w = 0;
      let corners = 0;
      const dt = 1e-5;
      for (let t = 0; t < T; t += dt) {
        w += (dt * g * R * Math.sin(phi + theta)) / ip;
        phi += dt * w;
        if (phi >= a) {
          phi -= 2 * a;
          w *= ratio;
          corners++;
        }
      }
      return corners * 2 * R * Math.sin(a);
    };
    const disc = 0.5 * ((2 / 3) * g * Math.sin(theta)) * 4; // a solid disc rolling 2 s: a = (2/3) g sin θ
    for (const kernel of ['js', 'wasm'] as const) {
      const rolled: number[] = [];
      for (const N of [12, 24, 48]) {
        const world = new World({ kernel, sleeping: false });
        const along = { x: Math.cos(theta), y: Math.sin(theta) };
        const up = { x: Math.sin(theta), y: -Math.cos(theta) };
        world.addRigidBody({ points: box(40, 0.5), x: -0.5 * up.x, y: -0.5 * up.y, angle: theta, type: 'static', friction: 1 });
        const corners = Array.from({ length: N }, (_, k) => ({ x: R * Math.cos((2 * Math.PI * (k + 0.5)) / N), y: R * Math.sin((2 * Math.PI * (k + 0.5)) / N) }));
        const apothem = R * Math.cos(Math.PI / N);
        const start = { x: -10 * along.x + apothem * up.x, y: -10 * along.y + apothem * up.y };
        const body = world.addRigidBody({ points: corners, x: start.x, y: start.y, angle: theta + Math.PI / 2, friction: 1 });
        steps(world, 120);
        const p = world.bodyPose(body);
        const distance = (p.x - start.x) * along.x + (p.y - start.y) * along.y;
        // Before the fix the velocity pass pulled the pivot down as the next corner landed: 1.44, 1.25 and 0.84
        // (a finer polygon rolled less far). The engine's impacts are a little softer than perfectly inelastic.
        expect(distance / model(N, 2), `${kernel}, ${N}-gon: ${distance.toFixed(3)} against the model's ${model(N, 2).toFixed(3)}`).to.be.within(1, 1.15);
        rolled.push(distance);
      }
      expect(rolled[0] < rolled[1] && rolled[1] < rolled[2] && rolled[2] < disc, `${kernel}: ${rolled.map((d) => d.toFixed(3)).join(' < ')} < ${disc.toFixed(3)}`).to.equal(true);
    }
  });

  it('a prismatic joint between two free bodies keeps their kinetic energy and angular momentum (it does no work)', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false });
      const a = world.addRigidBody({ points: box(2, 0.4), x: 0, y: 0, angularVelocity: 3, vx: 1 });
      const b = world.addRigidBody({ points: box(1, 1), x: 2, y: 0, density: 2, vy: 2 });
      world.addJoint({ type: 'prismatic', a, b, anchor: { x: 1, y: 0 } });
      const energyAndMomentum = () => {
        let ke = 0;
        let l = 0;
        for (const h of [a, b]) {
          const { mass, inertia } = world.bodyMassInfo(h);
          const v = world.bodyVelocity(h);
          const p = world.bodyPose(h);
          const w = world.bodyAngularVelocity(h);
          ke += 0.5 * mass * (v.x * v.x + v.y * v.y) + 0.5 * inertia * w * w;
          // About the origin: orbital (r × m v) plus spin; y grows downward, as the engine's angles do.
          l += mass * (p.x * v.y - p.y * v.x) + inertia * w;
        }
        return [ke, l];
      };
      world.step();
      const [ke0, l0] = energyAndMomentum();
      // Before the fix: the energy ×24 after 2 s, 10^5 later, and the momentum changed sign.
      for (let k = 0; k < 600; k++) world.step();
      const [ke, l] = energyAndMomentum();
      expect(Math.abs(l - l0) / Math.abs(l0), `${kernel}: angular momentum after 10 s`).to.be.lessThan(0.01);
      expect(ke / ke0, `${kernel}: kinetic energy after 10 s`).to.be.within(0.98, 1.001);
    }
  });

  it('a revolute motor with enough torque turns a wheel at its speed; with too little it stalls against a load', () => {
    const world = new World({ sleeping: false, gravity: { x: 0, y: 0 } });
    const wheel = world.addRigidBody({ radius: 0.5, x: 0, y: 0, collide: false });
    world.addJoint({ type: 'revolute', a: wheel, anchor: { x: 0, y: 0 }, motorSpeed: 3, maxMotorTorque: 100 });
    steps(world, 60);
    expect(world.bodyAngularVelocity(wheel)).to.be.closeTo(3, 1e-3);
    // A lever with a 1 kg-equivalent weight 1 away: the torque needed is m·g·1; a motor capped below holds nothing.
    const w2 = new World({ sleeping: false });
    const lever = w2.addRigidBody({ points: box(1, 0.05), x: 1, y: 0, density: 10, collide: false });
    w2.addJoint({ type: 'revolute', a: lever, anchor: { x: 0, y: 0 }, motorSpeed: 0, maxMotorTorque: 0.1 * w2.bodyMassInfo(lever).mass * g });
    steps(w2, 60);
    expect(w2.bodyPose(lever).angle).to.be.greaterThan(0.5);
  });

  it('a revolute limit stops a rod pivoted at its end dead (an inelastic stop), its pivot in place', () => {
    // No gravity, spinning at 5 rad/s into upperAngle 1. The limit was solved apart from the point: the angle's turn
    // left the rod's centre moving, the point turned that back into spin, and it rebounded at 0.42 of its speed.
    for (const substeps of ['auto', 20] as const) {
      const world = new World({ sleeping: false, substeps, gravity: { x: 0, y: 0 } });
      const rod = world.addRigidBody({ points: box(1, 0.1), x: 1, y: 0, vy: 5, angularVelocity: 5, collide: false });
      world.addJoint({ type: 'revolute', a: rod, anchor: { x: 0, y: 0 }, lowerAngle: -1, upperAngle: 1 });
      let gap = 0;
      let most = 0;
      steps(world, 60, () => {
        const p = world.bodyPose(rod);
        gap = Math.max(gap, Math.hypot(p.x - Math.cos(p.angle), p.y - Math.sin(p.angle)));
        most = Math.max(most, p.angle);
      });
      const at = `substeps ${substeps}`;
      expect(world.bodyPose(rod).angle, `${at}: at its limit`).to.be.closeTo(1, 1e-3);
      expect(Math.abs(world.bodyAngularVelocity(rod)), `${at}: no rebound`).to.be.lessThan(1e-3);
      expect(most, `${at}: not past it`).to.be.lessThan(1.001);
      expect(gap, `${at}: the pivot's largest gap`).to.be.lessThan(1e-3);
    }
  });

  it('a revolute motor driving into its limit stops there (a flipper), its pivot in place', () => {
    // With the motor solved last, it turned the rod past its bound and off its pivot (to 6 rad, the pivot 5.5 off).
    for (const maxMotorTorque of [undefined, 1e4])
      for (const motorSpeed of [3, 30]) {
        const world = new World({ sleeping: false });
        const rod = world.addRigidBody({ points: box(1, 0.1), x: 1, y: 0, collide: false });
        world.addJoint({ type: 'revolute', a: rod, anchor: { x: 0, y: 0 }, lowerAngle: -0.5, upperAngle: 0.5, motorSpeed, maxMotorTorque });
        let gap = 0;
        steps(world, 60, () => {
          const p = world.bodyPose(rod);
          gap = Math.max(gap, Math.hypot(p.x - Math.cos(p.angle), p.y - Math.sin(p.angle)));
        });
        const at = `torque ${maxMotorTorque}, speed ${motorSpeed}`;
        expect(world.bodyPose(rod).angle, `${at}: at its limit`).to.be.closeTo(0.5, 2e-3);
        expect(gap, `${at}: the pivot's largest gap`).to.be.lessThan(5e-3);
      }
  });

  it('a revolute motor with enough torque holds a load still, and drives it at its speed, its pivot in place', () => {
    // A rod 2 long pivoted at its end, level under gravity: the load torque is m·g·1. The motor once ran before the
    // point constraint, whose turn undid part of it every substep: it sagged at 0.075 rad/s whatever its torque.
    for (const substeps of ['auto', 20] as const)
      for (const motorSpeed of [0, 1]) {
        const world = new World({ sleeping: false, substeps });
        const rod = world.addRigidBody({ points: box(1, 0.1), x: 1, y: 0, collide: false });
        const need = world.bodyMassInfo(rod).mass * g;
        world.addJoint({ type: 'revolute', a: rod, anchor: { x: 0, y: 0 }, motorSpeed, maxMotorTorque: 1.5 * need });
        let gap = 0;
        const spins: number[] = [];
        steps(world, 300, (k) => {
          const p = world.bodyPose(rod);
          gap = Math.max(gap, Math.hypot(p.x - Math.cos(p.angle), p.y - Math.sin(p.angle)));
          if (k > 60) spins.push(world.bodyAngularVelocity(rod));
        });
        const at = `substeps ${substeps}, motorSpeed ${motorSpeed}`;
        if (motorSpeed === 0) expect(Math.abs(world.bodyPose(rod).angle), `${at}: held still`).to.be.lessThan(1e-3);
        expect(Math.min(...spins), `${at}: slowest`).to.be.greaterThan(motorSpeed - 0.02);
        expect(Math.max(...spins), `${at}: fastest`).to.be.lessThan(motorSpeed + 0.02);
        expect(gap, `${at}: the pivot's largest gap`).to.be.lessThan(1e-3);
      }
  });
});

describe('rigid bodies: stacks, pyramids, heavy loads', () => {
  function pyramid(world: World, base: number, size = 1): Handle[] {
    const out: Handle[] = [];
    for (let row = 0; row < base; row++) {
      for (let k = 0; k < base - row; k++) out.push(world.addRigidBody({ points: box(size / 2, size / 2), x: (k - (base - row - 1) / 2) * size, y: -(0.5 + row) * size }));
    }
    return out;
  }

  it('a 20-box stack and a base-20 pyramid stand for 10 s (top drift < 0.05 box)', () => {
    const world = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
    world.addRigidBody({ points: box(40, 0.5), x: 0, y: 0.5, type: 'static' });
    const stack: Handle[] = [];
    for (let k = 0; k < 20; k++) stack.push(world.addRigidBody({ points: box(0.5, 0.5), x: -30, y: -(0.5 + k) }));
    const boxes = pyramid(world, 20);
    const top = boxes[boxes.length - 1];
    const t0 = world.bodyPose(top);
    steps(world, 600);
    const s = world.bodyPose(stack[19]);
    const p = world.bodyPose(top);
    console.log(`      stack top drift ${(s.x + 30).toExponential(2)}, ${(s.y + 19.5).toExponential(2)}; pyramid top ${(p.x - t0.x).toExponential(2)}, ${(p.y - t0.y).toExponential(2)}`);
    expect(Math.hypot(s.x + 30, s.y + 19.5)).to.be.lessThan(0.05);
    expect(Math.hypot(p.x - t0.x, p.y - t0.y)).to.be.lessThan(0.05);
    expect(Math.abs(p.angle)).to.be.lessThan(0.01);
  });

  it('a box 100× heavier placed on a stack and on a pyramid of light boxes is held up', () => {
    const world = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
    world.addRigidBody({ points: box(40, 0.5), x: 0, y: 0.5, type: 'static' });
    const stack: Handle[] = [];
    for (let k = 0; k < 10; k++) stack.push(world.addRigidBody({ points: box(0.5, 0.5), x: -20, y: -(0.5 + k) }));
    const boxes = pyramid(world, 10);
    const onStack = world.addRigidBody({ points: box(0.5, 0.5), x: -20, y: -10.5, density: 100 });
    const onPyramid = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -10.5, density: 100 });
    steps(world, 300);
    for (const b of [...stack, ...boxes]) expect(Math.abs(world.bodyPose(b).angle), 'a light box tipped').to.be.lessThan(0.01);
    // Held up within a tenth of a box (the light boxes under it give a little: one sweep a substep).
    expect(world.bodyPose(onStack).y).to.be.closeTo(-10.5, 0.1);
    expect(world.bodyPose(onPyramid).y).to.be.closeTo(-10.5, 0.1);
    expect(Math.abs(world.bodyPose(onPyramid).x)).to.be.lessThan(0.01);
  });

  it('a box 100× (and 1000×) heavier dropped from one box height onto a stack and a pyramid leaves them standing', () => {
    for (const density of [100, 1000]) {
      const world = new World({ sleeping: false, gravity: { x: 0, y: 10 } });
      world.addRigidBody({ points: box(40, 0.5), x: 0, y: 0.5, type: 'static' });
      const stack: Handle[] = [];
      for (let k = 0; k < 10; k++) stack.push(world.addRigidBody({ points: box(0.5, 0.5), x: -20, y: -(0.5 + k) }));
      const boxes = pyramid(world, 10);
      // Their bottoms one box height above the tops.
      const onStack = world.addRigidBody({ points: box(0.5, 0.5), x: -20, y: -11.5, density });
      const onPyramid = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -11.5, density });
      let tilt = 0;
      let sank = 0;
      steps(world, 300, () => {
        for (const b of [...stack, ...boxes]) tilt = Math.max(tilt, Math.abs(world.bodyPose(b).angle));
        sank = Math.max(sank, world.bodyPose(onStack).y + 10.5, world.bodyPose(onPyramid).y + 10.5);
      });
      expect(tilt, `density ${density}: the most a light box tipped`).to.be.lessThan(0.01);
      expect(sank, `density ${density}: how far a heavy box sank into the light ones`).to.be.lessThan(0.1);
      expect(world.bodyPose(onStack).y).to.be.closeTo(-10.5, 0.02);
      expect(world.bodyPose(onPyramid).y).to.be.closeTo(-10.5, 0.02);
      expect(Math.abs(world.bodyPose(onPyramid).x)).to.be.lessThan(0.01);
      expect(Math.abs(world.bodyPose(stack[9]).x + 20)).to.be.lessThan(0.01);
    }
  });

  it('a heavy box thrown at a light one resting on the ground lands on it, at any speed: no hanging above it, no bounce', () => {
    // The shock sweep's velocity pass stopped every point of its manifolds, touching or not: a box 20 times heavier
    // coming at 60 units/s hung 0.83 above the light one, at 200 units/s 0.11. And its levels came from the points found
    // apart too: at 200 units/s the box was levelled by its speculative point with the ground, beside the light box,
    // then went 0.86 deep into it and came back out at 56 units/s. Now a point that has not acted keeps the approach
    // that closes its gap in one substep, and only points that touch at detection carry a level (SHOCK_TOUCH).
    for (const kernel of ['js', 'wasm'] as const) {
      for (const speed of [10, 60, 200]) {
        for (const ratio of [20, 200]) {
          const world = new World({ sleeping: false, gravity: { x: 0, y: 0 }, kernel });
          world.addRigidBody({ points: box(5, 0.5), x: 0, y: 1, type: 'static' });
          const light = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: 0, restitution: 0 });
          const heavy = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -5, density: ratio, restitution: 0 });
          world.setBodyVelocity(heavy, 0, speed);
          let deepest = 0;
          steps(world, 60, () => (deepest = Math.max(deepest, world.bodyPose(heavy).y + 1 - world.bodyPose(light).y)));
          const where = `${kernel}, ${ratio}× at ${speed}`;
          expect(world.bodyPose(light).y - world.bodyPose(heavy).y - 1, `${where}: gap`).to.be.closeTo(0, 0.01);
          expect(Math.abs(world.bodyVelocity(heavy).y), `${where}: speed`).to.be.below(0.05);
          expect(deepest, `${where}: deepest`).to.be.below(0.05);
        }
      }
    }
  });

  it('towers whose boxes grow heavier upward, each 1.5× to 10× the one below, stand: overlaps under 1% of a box (both kernels)', () => {
    // The shock sweep was for contacts across masses 10× apart: a tower of 6 boxes each 5× the one below sank 69% of
    // a box into itself, each 8× or 10× collapsed, 16 boxes each 1.9× too. It now also takes a contact across 1.5×
    // where the world's masses spread 10×.
    for (const kernel of ['js', 'wasm'] as const)
      for (const [n, ratio] of [[6, 3], [6, 5], [6, 8], [6, 10], [4, 30], [10, 1.5], [16, 1.9]] as const) {
        const world = new World({ kernel, sleeping: false });
        world.addRigidBody({ points: box(10, 0.5), x: 0, y: 0.5, type: 'static' });
        const tower = Array.from({ length: n }, (_, k) => world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -0.5 - k, density: ratio ** k }));
        let deepest = 0;
        steps(world, 300, () => {
          tower.forEach((b, k) => {
            const below = k === 0 ? 0 : world.bodyPose(tower[k - 1]).y - 0.5;
            deepest = Math.max(deepest, world.bodyPose(b).y + 0.5 - below);
          });
        });
        expect(deepest, `${kernel}: ${n} boxes, each ${ratio}×`).to.be.below(0.01);
      }
  });

  it('a box 30× to 1000× heavier resting on a light one is still (no creeping approach speed), does not hop, and sleeps', () => {
    for (const kernel of ['js', 'wasm'] as const)
      for (const ratio of [30, 100, 1000])
        for (const restitution of [0, 0.5]) {
          const at = `${kernel}, ${ratio}×, restitution ${restitution}`;
          const still = new World({ sleeping: false, gravity: { x: 0, y: 9.81 }, kernel });
          const asleep = new World({ gravity: { x: 0, y: 9.81 }, kernel });
          const boxes = [still, asleep].map((world) => {
            world.addRigidBody({ points: box(100, 0.5), x: 0, y: 0.5, type: 'static', restitution });
            const light = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -0.5, mass: 1, restitution });
            const heavy = world.addRigidBody({ points: box(0.5, 0.5), x: 0, y: -1.5, mass: ratio, restitution });
            return { light, heavy };
          });
          let fastest = 0;
          let highest = Infinity;
          for (let k = 0; k < 600; k++) {
            still.step();
            asleep.step();
            const v = still.bodyVelocity(boxes[0].heavy);
            if (k >= 60) fastest = Math.max(fastest, Math.hypot(v.x, v.y));
            highest = Math.min(highest, still.bodyPose(boxes[0].heavy).y);
          }
          // Before, the shock sweep cleared the overlap but left the approach speed, which grew each substep until it
          // counted as an impact: the speed cycled 0.05–0.47, and with restitution the box hopped and never slept.
          expect(fastest, `${at}: the heavy box's fastest speed after 1 s`).to.be.lessThan(1e-3);
          expect(highest, `${at}: the heavy box's highest point`).to.be.greaterThan(-1.5 - 1e-3);
          expect(still.bodyPose(boxes[0].heavy).y, at).to.be.closeTo(-1.5, 2e-3);
          expect(asleep.isAwake(boxes[1].heavy) || asleep.isAwake(boxes[1].light), `${at}: either awake after 10 s`).to.equal(false);
        }
  });
});

describe('rigid bodies: kinematic bodies and particles', () => {
  it('a kinematic drum turning at 0.25 rad/s keeps 200 boxes inside', () => {
    const world = new World();
    const R = 6;
    const n = 32;
    const outlines: Vec2[][] = [];
    for (let k = 0; k < n; k++) {
      const a0 = (k / n) * 2 * Math.PI;
      const a1 = ((k + 1) / n) * 2 * Math.PI;
      outlines.push([
        { x: R * Math.cos(a0), y: R * Math.sin(a0) },
        { x: (R + 0.5) * Math.cos(a0), y: (R + 0.5) * Math.sin(a0) },
        { x: (R + 0.5) * Math.cos(a1), y: (R + 0.5) * Math.sin(a1) },
        { x: R * Math.cos(a1), y: R * Math.sin(a1) },
      ]);
    }
    const drum = world.addRigidBody({ outlines, x: 0, y: 0, type: 'kinematic', angularVelocity: 0.25 });
    const boxes: Handle[] = [];
    for (let y = -5; y <= 5 && boxes.length < 200; y += 0.6) for (let x = -5; x <= 5 && boxes.length < 200; x += 0.6) if (Math.hypot(x, y) < 5.2) boxes.push(world.addRigidBody({ points: box(0.25, 0.25), x, y }));
    expect(boxes.length).to.equal(200);
    let farthest = 0;
    let carried = 0;
    steps(world, 600, () => {
      for (const b of boxes) {
        const p = world.bodyPose(b);
        farthest = Math.max(farthest, Math.hypot(p.x, p.y));
      }
    });
    // The drum turned by 2.5 rad; friction carried the pile up its rising side (x > 0 when it turns x toward y... the
    // pile's centre of mass leaves the bottom towards the side the wall moves up).
    for (const b of boxes) carried += world.bodyPose(b).x;
    expect(world.bodyPose(drum).angle).to.be.closeTo(2.5, 1e-9);
    expect(farthest).to.be.lessThan(R);
    expect(carried / boxes.length).to.be.lessThan(-0.2);
  });

  it('a cloth dropped on a turning box drapes over it without passing through, and a rope tied to a swinging box stays tied', () => {
    const world = new World({ sleeping: false });
    // A kinematic plank turning slowly, and a free cloth falling onto it.
    const plank = world.addRigidBody({ points: box(1.5, 0.2), x: 0, y: 3, type: 'kinematic', angularVelocity: 0.2 });
    const cloth = createCloth(world, { origin: { x: -1.2, y: 0 }, columns: 9, rows: 9, spacing: 0.3, pins: 'none', radius: 0.05, collide: true, friction: 0.8 });
    // A box swinging on a revolute joint 2 to the left of its centre, with a rope tied to its bottom-right corner.
    const swing = world.addRigidBody({ points: box(0.5, 0.25), x: 12, y: 2 });
    world.addJoint({ type: 'revolute', a: swing, anchor: { x: 10, y: 2 } });
    const rope = createRope(world, { from: { x: 12.5, y: 2.25 }, to: { x: 12.5, y: 5.25 }, segments: 12, pinStart: false });
    const end = rope.particles[0];
    world.addJoint({ type: 'revolute', a: swing, particleB: end, anchor: { x: 12.5, y: 2.25 } });
    let tied = 0;
    let deepest = 0;
    steps(world, 180, () => {
      const s = world.bodyPose(swing);
      const cx = s.x + 0.5 * Math.cos(s.angle) - 0.25 * Math.sin(s.angle);
      const cy = s.y + 0.5 * Math.sin(s.angle) + 0.25 * Math.cos(s.angle);
      const e = world.getPosition(end);
      tied = Math.max(tied, Math.hypot(e.x - cx, e.y - cy));
      // How far any cloth particle is inside the plank (in the plank's frame), beyond its radius.
      const p = world.bodyPose(plank);
      for (const h of cloth.particles) {
        const q = world.getPosition(h);
        const u = (q.x - p.x) * Math.cos(p.angle) + (q.y - p.y) * Math.sin(p.angle);
        const v = -(q.x - p.x) * Math.sin(p.angle) + (q.y - p.y) * Math.cos(p.angle);
        deepest = Math.max(deepest, Math.min(1.5 + 0.05 - Math.abs(u), 0.2 + 0.05 - Math.abs(v)));
      }
    });
    // The cloth hangs over the plank (fallen off, it would be tens of units below after 3 s).
    let my = 0;
    for (const h of cloth.particles) my += world.getPosition(h).y / cloth.particles.length;
    console.log(`      rope tied within ${tied.toExponential(2)}; deepest cloth particle in the plank ${deepest.toExponential(2)}; cloth mean y ${my.toFixed(3)}`);
    expect(tied).to.be.lessThan(1e-3);
    expect(deepest).to.be.lessThan(0.02);
    expect(my, "the cloth fell off").to.be.lessThan(4);
    expect(world.bodyPose(swing).angle).to.not.be.closeTo(0, 0.1);
  });
});

describe('rigid bodies: contacts that never touch', () => {
  it('a disc gliding just clear of a particle-built box is not pushed (its speculative points stay apart)', () => {
    for (const kernel of ['js', 'wasm'] as const)
      for (const vx of [3, -3])
        for (const gap of [0.02, 0.05]) {
          const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false });
          createBox(world, { x: 0, y: 0, width: 6, height: 1, model: 'particles', mass: 1000 });
          const y = -1 - gap;
          const disc = world.addRigidBody({ x: -vx * 0.3, y, radius: 0.5, vx });
          let moved = 0;
          steps(world, 30, () => (moved = Math.max(moved, Math.abs(world.bodyPose(disc).y - y))));
          expect(moved, `${kernel}, vx ${vx}, ${gap} clear`).to.equal(0);
        }
  });
});

describe('rigid bodies: seams between static pieces', () => {
  /** Floors whose top is y = 0 from x = −20 to 20, built of several static pieces (or one). */
  const FLOORS: Record<string, (world: World, friction: number) => void> = {
    one: (world, friction) => void world.addRigidBody({ points: box(20, 0.5), x: 0, y: 0.5, type: 'static', friction }),
    'two pieces': (world, friction) => {
      for (const x of [-10, 10]) world.addRigidBody({ points: box(10, 0.5), x, y: 0.5, type: 'static', friction });
    },
    'tiles 1 wide': (world, friction) => {
      for (let k = 0; k < 40; k++) world.addRigidBody({ points: box(0.5, 0.5), x: k - 19.5, y: 0.5, type: 'static', friction });
    },
    // A concave outline: its convex parts meet along joins inside the floor.
    'U channel': (world, friction) =>
      void world.addRigidBody({
        points: [
          { x: -20, y: -2 }, { x: -19, y: -2 }, { x: -19, y: 0 }, { x: 19, y: 0 }, { x: 19, y: -2 }, { x: 20, y: -2 }, { x: 20, y: 1 }, { x: -20, y: 1 },
        ],
        x: 0,
        y: 0,
        type: 'static',
        friction,
      }),
  };

  it('a box and a disc slide over the joins of flush static pieces as over one floor: frictionless, speed kept and no tilt', () => {
    for (const kernel of ['js', 'wasm'] as const)
      for (const floor of Object.keys(FLOORS))
        for (const shape of ['box', 'disc'])
          for (const v0 of [0.5, 2, 6]) {
            const at = `${kernel}, ${floor}, ${shape} at ${v0}`;
            const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
            FLOORS[floor](world, 0);
            const body = shape === 'box' ? world.addRigidBody({ points: box(0.5, 0.5), x: -3.2, y: -0.5, vx: v0, friction: 0 }) : world.addRigidBody({ radius: 0.5, x: -3.2, y: -0.5, vx: v0, friction: 0 });
            let slowest = Infinity;
            let tilt = 0;
            let lift = 0;
            // Over at least three joins of the tiles and the join of the two pieces at x = 0.
            steps(world, Math.ceil((60 * 6) / v0), () => {
              slowest = Math.min(slowest, world.bodyVelocity(body).x);
              tilt = Math.max(tilt, Math.abs(world.bodyPose(body).angle));
              lift = Math.max(lift, -0.5 - world.bodyPose(body).y);
            });
            // Before, the box met the next piece's side face at each join: at 2 units/s it left the join at 0.72,
            // tilted 0.11 rad; at 6 it was thrown over.
            expect(world.bodyPose(body).x, at).to.be.greaterThan(2.5);
            expect(slowest, `${at}: slowest`).to.be.greaterThan(v0 * (1 - 1e-3));
            expect(tilt, `${at}: tilt`).to.be.lessThan(1e-3);
            expect(lift, `${at}: lift`).to.be.lessThan(1e-3);
          }
  });

  it('a disc or a box sunk into the floor at a join comes out on top (no face of either piece is skipped for it)', () => {
    for (const kernel of ['js', 'wasm'] as const)
      for (const shape of ['disc', 'box'])
        for (const x of [-0.01, 0.01, 0.3])
          for (const y of [-0.3, 0.1]) {
            const at = `${kernel}, ${shape} at ${x}, ${y}`;
            const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
            FLOORS['two pieces'](world, 0.6);
            const b = shape === 'disc' ? world.addRigidBody({ radius: 0.5, x, y }) : world.addRigidBody({ points: box(0.5, 0.5), x, y });
            steps(world, 120);
            // The disc straight up; the box too, but pushed out of 0.6 by two pieces' manifolds in turn it may tip.
            expect(world.bodyPose(b).y, at).to.be.closeTo(-0.5, 0.01);
            expect(Math.abs(world.bodyPose(b).x - x), at).to.be.lessThan(shape === 'disc' ? 1e-6 : 0.3);
          }
  });

  it('a ball rolls over a peak of two static triangles as over one (the corner at the top is real); a disc inside a block of tiles stays finite', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      const path = (split: boolean) => {
        const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
        if (split) {
          world.addRigidBody({ points: [{ x: -2, y: 0 }, { x: 0, y: 0 }, { x: 0, y: -1 }], x: 0, y: 0, type: 'static' });
          world.addRigidBody({ points: [{ x: 0, y: 0 }, { x: 2, y: 0 }, { x: 0, y: -1 }], x: 0, y: 0, type: 'static' });
        } else world.addRigidBody({ points: [{ x: -2, y: 0 }, { x: 2, y: 0 }, { x: 0, y: -1 }], x: 0, y: 0, type: 'static' });
        const ball = world.addRigidBody({ radius: 0.3, x: -0.05, y: -1.3, vx: 1 });
        const out: number[] = [];
        steps(world, 120, () => out.push(world.bodyPose(ball).x, world.bodyPose(ball).y));
        return out;
      };
      // Found by review: the left piece took its own slope's face for a ball already on the right slope and threw
      // it off (an earlier form held it on the peak).
      const one = path(false);
      // The same path but for rounding (the same contact points, found by other arithmetic; rolling over the peak
      // grows a difference of 10⁻¹⁶ to 10⁻⁸ in two seconds; 5·10⁻⁴ since friction measures the ball's rim along its
      // arc: its anchors are fresh on one side of the seam, kept on the other), where being thrown off moves it by tenths.
      path(true).forEach((v, k) => expect(v, `${kernel}: coordinate ${k}`).to.be.closeTo(one[k], 2e-3));
      // A disc spawned inside the middle tile of a 3×3 block, every face of that tile a seam: pushed out somewhere,
      // never an infinite depth or NaN.
      const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
      for (let i = -1; i <= 1; i++) for (let j = -1; j <= 1; j++) world.addRigidBody({ points: box(0.5, 0.5), x: i, y: j, type: 'static' });
      const disc = world.addRigidBody({ radius: 0.3, x: 0.1, y: 0.05 });
      steps(world, 200, () => {
        const p = world.bodyPose(disc);
        expect(Number.isFinite(p.x) && Number.isFinite(p.y) && Number.isFinite(p.angle), `${kernel}: pose ${JSON.stringify(p)}`).to.equal(true);
        const c = (world as unknown as { ctx: StepContext }).ctx.rigidContacts;
        for (let k = 0; k < c.count; k++) expect(Number.isFinite(c.depth[k]) && Number.isFinite(c.rnA[k]), `${kernel}: contact ${k}`).to.equal(true);
      });
    }
  });

  it('a box slides down a 20° ramp of 8 flush pieces at g·sin θ·t, not tilting (before: 3.00 units/s for 6.71 after 2 s)', () => {
    const theta = (20 * Math.PI) / 180;
    const [c, s] = [Math.cos(theta), Math.sin(theta)];
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
      // Pieces 5 long along the ramp, their tops on the line through (0, 1) descending to the right at θ (y down).
      for (let k = 0; k < 8; k++) {
        const u = -20 + 5 * (k + 0.5);
        world.addRigidBody({ points: box(2.5, 0.5), x: u * c + 0.5 * s, y: 1 + u * s + 0.5 * c, angle: theta, type: 'static', friction: 0 });
      }
      const b = world.addRigidBody({ points: box(0.5, 0.5), x: -10 * c + 0.5 * s, y: 1 - 10 * s - 0.5 * c, angle: theta, friction: 0 });
      let tilt = 0;
      steps(world, 120, () => (tilt = Math.max(tilt, Math.abs(world.bodyPose(b).angle - theta))));
      // bodyVelocity is the mean over the last substep (h = 1/360 s), the velocity at t − h/2.
      const v = world.bodyVelocity(b);
      expect(Math.hypot(v.x, v.y), kernel).to.be.closeTo(g * s * (2 - 1 / 720), 1e-4);
      expect(tilt, `${kernel}: tilt`).to.be.lessThan(1e-3);
    }
  });

  it('a rough box slides as far over joins as on one floor (v²/2μg); a piece 0.3 taller still stops it', () => {
    const mu = 0.4;
    const v0 = 4;
    for (const kernel of ['js', 'wasm'] as const) {
      const run = (floor: string) => {
        const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
        FLOORS[floor](world, mu);
        const b = world.addRigidBody({ points: box(0.5, 0.5), x: -1.2, y: -0.5, vx: v0, friction: mu });
        steps(world, 120);
        return world.bodyPose(b).x + 1.2;
      };
      const one = run('one');
      console.log(`      ${kernel}: slid ${one.toFixed(4)} on one floor (analytic ${(v0 * v0 / (2 * mu * g)).toFixed(4)})`);
      expect(one).to.be.closeTo((v0 * v0) / (2 * mu * g), 0.02);
      // Within 0.5% (the tiles: 2.0414, as each join starts new contacts): before, the box stopped at the first join.
      for (const floor of ['two pieces', 'tiles 1 wide', 'U channel']) expect(run(floor), `${kernel}, ${floor}`).to.be.closeTo(one, 0.01);
      // A step: the right piece's top 0.3 above the left's. Its side is a wall, seam or not.
      const world = new World({ kernel, gravity: { x: 0, y: g }, sleeping: false });
      world.addRigidBody({ points: box(10, 0.5), x: -10, y: 0.5, type: 'static', friction: 0 });
      world.addRigidBody({ points: box(10, 0.65), x: 10, y: 0.35, type: 'static', friction: 0 });
      const b = world.addRigidBody({ points: box(0.5, 0.5), x: -2, y: -0.5, vx: 1, friction: 0 });
      let farthest = -Infinity;
      steps(world, 180, () => (farthest = Math.max(farthest, world.bodyPose(b).x + 0.5)));
      expect(farthest, `${kernel}: the box's front against the step at x = 0`).to.be.within(-0.02, 0.005);
      expect(world.bodyVelocity(b).x, `${kernel}: stopped there`).to.be.closeTo(0, 0.01);
    }
  });
  it('a body hinged to one floor piece, swinging through it (they do not collide), stops at the next piece’s side (before: through it, thrown out on top)', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false });
      const left = world.addRigidBody({ points: box(2.5, 0.5), x: -2.5, y: 0.5, type: 'static' });
      world.addRigidBody({ points: box(2.5, 0.5), x: 2.5, y: 0.5, type: 'static' });
      // A 0.4 box hanging 0.6 below a hinge on the left piece's top, inside that piece, swung toward the right one.
      const bob = world.addRigidBody({ points: box(0.2, 0.2), x: -0.5, y: 0.6, vx: 4 });
      world.addJoint({ type: 'revolute', a: bob, b: left, anchor: { x: -0.5, y: 0 } });
      let deepest = -Infinity;
      let highest = Infinity;
      for (let s = 0; s < 120; s++) {
        world.step();
        const { x, y, angle } = world.bodyPose(bob);
        // Its rightmost corner: how far past the right piece's side (x = 0) it went.
        deepest = Math.max(deepest, x + 0.2 * (Math.abs(Math.cos(angle)) + Math.abs(Math.sin(angle))));
        highest = Math.min(highest, y);
      }
      // It touches that side (measured −0.0015; the contact slop is 0.02) and swings back below the top. Before, the
      // side was a seam for it: the bob went 0.29 into the right piece and was thrown out on top (y −0.6).
      expect(deepest, kernel).to.be.below(0.02);
      expect(highest, kernel).to.be.above(0.5);
    }
  });
});

describe('rigid bodies: changing how they collide', () => {
  it('setCollider changes a rigid body’s friction while it slides, turns its collisions off and on, and refuses parts', () => {
    for (const kernel of ['js', 'wasm'] as const) {
      const world = new World({ kernel, sleeping: false, gravity: { x: 0, y: g } });
      world.addRigidBody({ points: box(100, 0.5), x: 0, y: 0.5, type: 'static', friction: 1 });
      // A flat crate (it slides, it does not tip).
      const crate = world.addRigidBody({ points: box(0.5, 0.1), x: 0, y: -0.1, vx: 10, friction: 0 });
      steps(world, 30);
      // Pairs take √(μa·μb): 0 so far, so it keeps its speed.
      expect(world.bodyVelocity(crate).x, `${kernel}: frictionless`).to.be.closeTo(10, 1e-6);
      world.setCollider(crate, { friction: 0.25 });
      steps(world, 30);
      expect(world.bodyVelocity(crate).x, `${kernel}: slowed by μ·g over 0.5 s, μ = √0.25`).to.be.closeTo(10 - 0.5 * g * 0.5, 0.05);
      expect(world.bodyPose(crate).y, `${kernel}: still on the floor`).to.be.closeTo(-0.1, 0.01);
      world.setCollider(crate, { shape: 'none' });
      steps(world, 10);
      expect(world.bodyPose(crate).y, `${kernel}: through the floor`).to.be.greaterThan(0);
      world.setBodyPose(crate, 0, -3, 0);
      world.setBodyVelocity(crate, 0, 0);
      world.setCollider(crate, { shape: 'polygon' });
      steps(world, 60);
      expect(world.bodyPose(crate).y, `${kernel}: on the floor again`).to.be.closeTo(-0.1, 0.01);
      expect(() => world.setCollider(crate, { parts: [[0, 1, 2]] })).to.throw(RangeError, /parts/);
      expect(() => world.setCollider(crate, { shape: 'particles' })).to.throw(RangeError, /shape/);
    }
  });
});
