// Rigid boxes, polygons and balls in the page: drawn from their pose (a turned box's pixels, a ball's radius line),
// their motion attributes (model, kinematic, velocity, angular-velocity, valid and not, live), and <physics-joint>
// of every type holding from markup. Paused scenes driven by step(n).
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsErrorDetail, PhysicsJointElement, PhysicsSceneElement } from '../../src/index.js';
import { afterEachScene, colourDistance, drawn, mount, pixelAt, rgb } from './helpers.js';

const WHITE = rgb('#ffffff');
const RED = rgb('#ff0000');

type Posed = Element & { x: number; y: number; angle: number };

/** Whether the canvas shows `colour` at the world point (x, y). */
function shows(scene: PhysicsSceneElement, x: number, y: number, colour: number[]): boolean {
  return colourDistance(pixelAt(scene, x, y), colour) < 8;
}

/** The darkest green channel within 2 pixels of the world point (x, y): a dark line through a green disc. */
function darkest(scene: PhysicsSceneElement, x: number, y: number): number {
  const canvas = scene.canvas!;
  const rect = canvas.getBoundingClientRect();
  const ratio = canvas.width / rect.width;
  const p = scene.worldToClient(x, y);
  const cx = Math.floor((p.x - rect.left) * ratio);
  const cy = Math.floor((p.y - rect.top) * ratio);
  const data = canvas.getContext('2d')!.getImageData(cx - 2, cy - 2, 5, 5).data;
  let least = 255;
  for (let k = 1; k < data.length; k += 4) least = Math.min(least, data[k]);
  return least;
}

/** Records physics-error details and console warnings while a scene mounts and runs. */
function reports() {
  const errors: PhysicsErrorDetail[] = [];
  const warnings: string[] = [];
  const warn = console.warn;
  console.warn = (...args: unknown[]) => void warnings.push(args.map(String).join(' '));
  return {
    errors,
    warnings,
    listen: (s: PhysicsSceneElement) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    restore: () => (console.warn = warn),
  };
}

describe('rigid bodies in the page', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEachScene(() => scene);

  it('a turning box is drawn where its pose puts it: its pixels follow the angle', async () => {
    // A long thin box at (5, 5), turning clockwise on screen at 90°/s.
    scene = await mount(
      'width="10" height="10" gravity="0 0" bounds="none" background="#ffffff" paused',
      `<physics-box x="5" y="5" width="6" height="0.6" angular-velocity="90" fill="#ff0000" stroke="none"></physics-box>`,
    );
    const box = scene.querySelector<PhysicsBoxElement>('physics-box')!;
    await drawn(scene, 2);
    expect([shows(scene, 7.5, 5, RED), shows(scene, 5, 7.5, WHITE), shows(scene, 2.5, 5, RED)]).to.deep.equal([true, true, true]);
    // A second: a quarter turn, about its centre.
    await scene.step(60);
    expect(box.angle).to.be.closeTo(90, 1e-6);
    expect([box.x, box.y]).to.deep.equal([5, 5]);
    await drawn(scene, 2);
    expect([shows(scene, 5, 7.5, RED), shows(scene, 5, 2.5, RED), shows(scene, 7.5, 5, WHITE), shows(scene, 2.5, 5, WHITE)]).to.deep.equal([true, true, true, true]);
    // Half a second more: 135°, along the other diagonal (x down-left to up-right on screen).
    await scene.step(30);
    await drawn(scene, 2);
    const d = 2 / Math.SQRT2;
    expect([shows(scene, 5 - d, 5 + d, RED), shows(scene, 5 + d, 5 - d, RED), shows(scene, 5 + d, 5 + d, WHITE)]).to.deep.equal([true, true, true]);
  });

  it('a rigid ball shows its spin: its radius line turns with it; a ball of particles has none', async () => {
    scene = await mount(
      'width="10" height="10" gravity="0 0" bounds="none" background="#ffffff" paused',
      `<physics-circle x="3" y="5" radius="2" angular-velocity="90" fill="#00ff00" stroke="#000000"></physics-circle>
       <physics-circle x="8" y="5" radius="1.5" model="particles" fill="#00ff00" stroke="#000000"></physics-circle>`,
    );
    const ball = scene.querySelector<Posed>('physics-circle')!;
    await drawn(scene, 2);
    // Angle 0: the line runs right of the centre, not below it.
    expect(darkest(scene, 4.2, 5)).to.be.below(120);
    expect(darkest(scene, 3, 6.2)).to.be.above(200);
    // A quarter turn (clockwise on screen): the line points down.
    await scene.step(60);
    expect(ball.angle).to.be.closeTo(90, 1e-6);
    await drawn(scene, 2);
    expect(darkest(scene, 3, 6.2)).to.be.below(120);
    expect(darkest(scene, 4.2, 5)).to.be.above(200);
    // The particle ball: green all through, no line.
    for (const [x, y] of [[8.8, 5], [8, 5.8], [7.2, 5], [8, 4.2]]) expect(darkest(scene, x, y), `${x}, ${y}`).to.be.above(200);
  });

  it('velocity, angular-velocity, kinematic and model from markup', async () => {
    scene = await mount(
      'width="20" height="10" gravity="0 10" bounds="none" paused',
      `<physics-box id="thrown" x="2" y="5" width="1" height="1" velocity="2 -5" angular-velocity="-45"></physics-box>
       <physics-box id="platform" x="8" y="5" width="2" height="0.5" kinematic velocity="1 -1" angular-velocity="30"></physics-box>
       <physics-box id="frame" x="14" y="2" width="1" height="1" model="particles" velocity="3 0"></physics-box>
       <physics-circle id="wheel" x="18" y="2" radius="0.5" model="rigid"></physics-circle>`,
    );
    const [thrown, platform, frame, wheel] = ['thrown', 'platform', 'frame', 'wheel'].map((id) => scene!.querySelector<Posed>(`#${id}`)!);
    await scene.step(60);
    // A thrown box: x = 2 + 2t, y = 5 − 5t + g t²/2, turning at −45°/s.
    expect(thrown.x).to.be.closeTo(4, 1e-6);
    expect(thrown.y).to.be.closeTo(5 - 5 + 5, 0.01);
    expect(thrown.angle).to.be.closeTo(-45, 1e-6);
    // A kinematic platform moves by its velocities alone: gravity does not pull it.
    expect(platform.x).to.be.closeTo(9, 1e-9);
    expect(platform.y).to.be.closeTo(4, 1e-9);
    expect(platform.angle).to.be.closeTo(30, 1e-6);
    // A box of particles takes its velocity too; it is four particles, the rigid ones one each.
    expect(frame.x).to.be.closeTo(17, 0.01);
    expect(wheel.y).to.be.closeTo(2 + 5, 0.01);
    expect((await scene.diagnostics()).particleCount).to.equal(1 + 1 + 4 + 1);
  });

  it('changing velocity, angular-velocity or kinematic on a scene sets them on the body where it is, without a rebuild', async () => {
    scene = await mount('width="20" height="10" gravity="0 10" bounds="none" paused', `<physics-box id="crate" x="3" y="2" width="1" height="1"></physics-box>`);
    const crate = scene.querySelector<PhysicsBoxElement>('#crate')!;
    await scene.step(30);
    // Falling for half a second: 1.25 down, at 5 u/s.
    expect(crate.y).to.be.closeTo(3.25, 0.01);
    // Kinematic: it keeps the 5 u/s it had and moves by it, gravity or not (a rebuild would put it back at y = 2).
    crate.setAttribute('kinematic', '');
    await crate.updateComplete;
    let y = crate.y;
    await scene.step(30);
    expect(crate.y - y).to.be.closeTo(2.5, 0.01);
    // A new velocity and spin: taken as they are, from where it is.
    crate.setAttribute('velocity', '4 0');
    crate.setAttribute('angular-velocity', '180');
    await crate.updateComplete;
    const x = crate.x;
    y = crate.y;
    await scene.step(30);
    expect(crate.x - x).to.be.closeTo(2, 1e-6);
    expect(crate.y - y).to.be.closeTo(0, 1e-6);
    expect(crate.angle).to.be.closeTo(90, 1e-6);
    // Dynamic again: gravity takes it (second differences of g·(10/60)²).
    crate.removeAttribute('kinematic');
    await crate.updateComplete;
    const ys: number[] = [];
    for (let k = 0; k < 3; k++) {
      await scene.step(10);
      ys.push(crate.y);
    }
    expect(ys[2] - 2 * ys[1] + ys[0]).to.be.closeTo(10 * (10 / 60) ** 2, 1e-6);
    expect((await scene.diagnostics()).stepCount).to.equal(120);
  });

  it('bad model, kinematic, velocity and angular-velocity values: a physics-error and a warning each; the bodies are built', async () => {
    const r = reports();
    try {
      scene = await mount(
        'width="20" height="10" paused',
        `<physics-box id="a" x="2" y="2" model="soft"></physics-box>
         <physics-box id="b" x="4" y="2" velocity="1"></physics-box>
         <physics-box id="c" x="6" y="2" velocity="a b"></physics-box>
         <physics-circle id="d" x="8" y="2" angular-velocity="fast"></physics-circle>
         <physics-box id="e" x="10" y="2" static kinematic></physics-box>
         <physics-polygon id="f" x="12" y="2" points="0,0 1,0 0,1" model="particles" kinematic></physics-polygon>`,
        { before: r.listen },
      );
      const seen = r.errors.map((e) => [e.element.id, e.attribute, e.value]);
      expect(seen).to.have.deep.members([
        ['a', 'model', 'soft'],
        ['b', 'velocity', '1'],
        ['c', 'velocity', 'a b'],
        ['d', 'angular-velocity', 'fast'],
        ['e', 'kinematic', ''],
        ['f', 'kinematic', ''],
      ]);
      expect(r.errors.find((e) => e.element.id === 'e')!.message).to.match(/static/);
      expect(r.errors.find((e) => e.element.id === 'f')!.message).to.match(/model="rigid"/);
      for (const [id, attribute, value] of seen) expect(r.warnings.filter((w) => w.includes(`id="${id}"`) && w.includes(`${attribute}="${value}"`)).length, `a warning for #${id}`).to.equal(1);
      expect(r.warnings.length).to.equal(6);
      // Each body is built with the fallback (rigid, no velocity, not kinematic): six bodies.
      const d = await scene.diagnostics();
      expect([d.bodyCount, d.particleCount]).to.deep.equal([6, 5 + 3]);
    } finally {
      r.restore();
    }
  });

  it('angular-velocity and motor-speed are kept as written up to ±5.7e10 °/s (a rate is not taken modulo 360); past it a physics-error and a warning each', async () => {
    const r = reports();
    try {
      scene = await mount(
        'width="20" height="10" gravity="0 0" bounds="none" paused',
        `<physics-box id="spun" x="4" y="4" kinematic angular-velocity="1000000090"></physics-box>
         <physics-box id="fast" x="8" y="4" angular-velocity="1e12"></physics-box>
         <physics-joint id="motor" type="revolute" a="spun" motor-speed="-5e10"></physics-joint>
         <physics-joint id="racing" type="revolute" a="fast" motor-speed="6e10"></physics-joint>`,
        { before: r.listen },
      );
      expect(r.errors.map((e) => [e.element.id, e.attribute, e.value])).to.have.deep.members([
        ['fast', 'angular-velocity', '1e12'],
        ['racing', 'motor-speed', '6e10'],
      ]);
      expect(r.errors[0].message).to.equal('must be within ±5.7e10 (degrees per second: 1e9 radians)');
      expect(r.warnings.filter((w) => w.includes('angular-velocity="1e12"') || w.includes('motor-speed="6e10"'))).to.have.length(2);
      expect(r.warnings.length).to.equal(2);
      // In range, as written: 1000000090 °/s, not 1000000090 mod 360 = 10 °/s; -5e10 °/s, not -5e10 mod 360 = -80.
      const spun = scene.querySelector<PhysicsBoxElement>('#spun')!;
      expect((spun.describe().desc as { angularVelocity?: number }).angularVelocity).to.equal((1000000090 * Math.PI) / 180);
      const motor = scene.querySelector<PhysicsJointElement>('#motor')!;
      expect((motor.describe(() => 1).desc as { motorSpeed?: number }).motorSpeed).to.equal((-5e10 * Math.PI) / 180);
      // The kinematic box turns at that rate, as far as the engine turns a body in a step (0.5 rad a substep, 3 rad in
      // six), where 10 °/s turned it a sixth of a degree.
      await scene.step(1);
      expect(spun.angle).to.be.above(90);
    } finally {
      r.restore();
    }
  });

  it('<physics-joint> of every type holds from markup', async () => {
    scene = await mount(
      'width="24" height="10" gravity="0 9.81" bounds="none" paused',
      `<physics-box id="bob" x="2" y="3" width="0.6" height="0.4" velocity="4 0"></physics-box>
       <physics-joint type="revolute" a="bob" x="2" y="1"></physics-joint>
       <physics-box id="arm" x="7.5" y="1" width="0.6" height="0.4"></physics-box>
       <physics-box id="hand" x="8.5" y="1" width="0.6" height="0.4"></physics-box>
       <physics-joint type="revolute" a="arm" x="7" y="1"></physics-joint>
       <physics-joint type="weld" a="arm" b="hand" x="8" y="1"></physics-joint>
       <physics-box id="slider" x="12" y="2" width="0.6" height="0.4"></physics-box>
       <physics-joint type="prismatic" a="slider" axis="0 1" lower="-1" upper="1"></physics-joint>
       <physics-box id="weight" x="15" y="4" width="0.6" height="0.4"></physics-box>
       <physics-joint type="spring" a="weight" x1="15" y1="4" x2="15" y2="2" stiffness="20" damping="2"></physics-joint>
       <physics-circle id="hook" x="20" y="1" radius="0.2" static></physics-circle>
       <physics-circle id="ball" x="22" y="1" radius="0.3"></physics-circle>
       <physics-joint a="ball" b="hook"></physics-joint>`,
    );
    const [bob, arm, hand, slider, weight, ball] = ['bob', 'arm', 'hand', 'slider', 'weight', 'ball'].map((id) => scene!.querySelector<Posed>(`#${id}`)!);
    expect((await scene.diagnostics()).linkCount).to.equal(6);
    const weld = [hand.x - arm.x, hand.y - arm.y];
    await scene.step(120);
    // The pendulum swings about its anchor, 2 below it.
    expect(Math.hypot(bob.x - 2, bob.y - 1)).to.be.closeTo(2, 1e-3);
    expect(Math.abs(bob.angle)).to.be.above(15);
    // The welded pair turned as one, about the arm's hinge.
    expect(hand.angle).to.be.closeTo(arm.angle, 0.05);
    expect(Math.abs(arm.angle)).to.be.above(15);
    const a = (arm.angle * Math.PI) / 180;
    expect(hand.x - arm.x).to.be.closeTo(Math.cos(a) * weld[0] - Math.sin(a) * weld[1], 1e-3);
    expect(hand.y - arm.y).to.be.closeTo(Math.sin(a) * weld[0] + Math.cos(a) * weld[1], 1e-3);
    expect(Math.hypot(arm.x - 7, arm.y - 1)).to.be.closeTo(0.5, 1e-3);
    // The slider went straight down its rail to the limit, unturned.
    expect([slider.x, slider.y, slider.angle].map((v) => Math.round(v * 1000) / 1000)).to.deep.equal([12, 3, 0]);
    // The ball swings from the hook on a stick (the default type) as long as it was made.
    expect(Math.hypot(ball.x - 20, ball.y - 1)).to.be.closeTo(2, 1e-3);
    expect(ball.x).to.be.below(21.5);
    // The weight settles on its spring where k·stretch = m·g (m = 0.24, rest length 2).
    await scene.step(600);
    expect(weight.y - 2).to.be.closeTo(2 + (0.24 * 9.81) / 20, 0.01);
    expect(weight.x).to.be.closeTo(15, 1e-3);
  });

  it('a joint ties a rigid box to a rope: at the rope\'s particle nearest the anchor', async () => {
    scene = await mount(
      'width="10" height="10" gravity="0 9.81" bounds="none" paused',
      `<physics-rope id="rope" x1="5" y1="1" x2="5" y2="4" segments="10"></physics-rope>
       <physics-box id="load" x="5" y="4.5" width="0.8" height="0.6"></physics-box>
       <physics-joint type="revolute" a="load" b="rope" x="5" y="4.2"></physics-joint>`,
    );
    const load = scene.querySelector<Posed>('#load')!;
    await scene.step(120);
    // Tied: it hangs below the rope's pinned start, about the rope's length plus its own lever away (it would have
    // fallen 20 units in two seconds).
    expect(Math.hypot(load.x - 5, load.y - 1)).to.be.within(3.1, 3.6);
  });

  it('bad <physics-joint> values and a <physics-spring> of stiffness 0: a physics-error and a warning each', async () => {
    const r = reports();
    try {
      scene = await mount(
        'width="10" height="10" paused',
        `<physics-box id="p" x="2" y="2"></physics-box><physics-box id="q" x="5" y="2"></physics-box>
         <physics-joint id="j1" type="hinge" a="p" b="q"></physics-joint>
         <physics-joint id="j2" type="revolute" a="p" lower-angle="30" upper-angle="10"></physics-joint>
         <physics-joint id="j3" type="prismatic" a="p" b="q" axis="0 0"></physics-joint>
         <physics-joint id="j4" type="revolute" a="p" motor-speed="90" max-motor-torque="-1"></physics-joint>
         <physics-joint id="j5" type="spring" a="p" b="q" stiffness="0"></physics-joint>
         <physics-spring id="s1" a="p" b="q" stiffness="0"></physics-spring>
         <physics-spring id="s2" a="p" b="q" stiffness="1e-9"></physics-spring>
         <physics-joint id="j6" type="spring" a="p" b="q" stiffness="1e-9"></physics-joint>`,
        { before: r.listen },
      );
      expect(r.errors.map((e) => [e.element.id, e.attribute, e.value])).to.have.deep.members([
        ['j1', 'type', 'hinge'],
        ['j2', 'upper-angle', '10'],
        ['j3', 'axis', '0 0'],
        ['j4', 'max-motor-torque', '-1'],
        ['j5', 'stiffness', '0'],
        // One rule for a spring's stiffness, a joint's or a <physics-spring>'s: > 0 (at least 1e-9).
        ['s1', 'stiffness', '0'],
      ]);
      expect(r.errors.find((e) => e.element.id === 's1')!.message).to.equal('must be a number > 0');
      expect(r.warnings.length).to.equal(6);
      // Each link is made with the fallback (a distance joint; no limits; the default axis; no torque cap; k = 50).
      expect((await scene.diagnostics()).linkCount).to.equal(8);
    } finally {
      r.restore();
    }
  });
});
