// Live markup: the children are the source of truth while the simulation runs.
import { expect } from '@open-wc/testing';
import type { PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, drawn, mount, pixelAt, rgb, unmount, waitFor } from './helpers.js';

const WHITE = rgb('#ffffff');

async function bodyCount(scene: PhysicsSceneElement): Promise<number> {
  return (await scene.diagnostics()).bodyCount;
}

describe('<physics-scene> live markup', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('appending a <physics-circle> adds a body to the running simulation; removing it removes it', async () => {
    scene = await mount('width="10" height="10" gravity="0 0" bounds="none" background="#ffffff"', `<physics-box x="2" y="2" width="1" height="1" fill="#0000ff"></physics-box>`);
    expect(await bodyCount(scene)).to.equal(1);
    await waitFor(() => scene!.stepCount > 10, 'the simulation to run');
    const before = scene.stepCount;
    const circle = document.createElement('physics-circle');
    circle.setAttribute('x', '7');
    circle.setAttribute('y', '3');
    circle.setAttribute('radius', '1');
    circle.setAttribute('fill', '#00ff00');
    scene.append(circle);
    await waitFor(async () => (await bodyCount(scene!)) === 2, 'two bodies');
    // Not restarted: the step count went on.
    expect(scene.stepCount).to.be.at.least(before);
    // Beside its centre: a rigid ball's radius line starts there.
    await waitFor(() => colourDistance(pixelAt(scene!, 7, 3.4), rgb('#00ff00')) < 8, 'the circle to be drawn');
    expect(circle.x).to.be.closeTo(7, 1e-6);
    expect(circle.y).to.be.closeTo(3, 1e-6);
    circle.remove();
    await waitFor(async () => (await bodyCount(scene!)) === 1, 'one body');
    await drawn(scene, 2);
    expect(colourDistance(pixelAt(scene, 7, 3.4), WHITE)).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 2, 2), rgb('#0000ff'))).to.be.below(8);
  });

  it('changing gravity changes the direction of motion', async () => {
    scene = await mount('width="10" height="10" gravity="0 10" bounds="none" paused', `<physics-circle id="ball" x="5" y="5" radius="0.5"></physics-circle>`);
    const ball = scene.querySelector('physics-circle')!;
    const sample = async () => {
      await scene!.step(10);
      return { x: ball.x, y: ball.y };
    };
    // Second differences over 10 steps of 1/60 s: g · (10/60)².
    const expected = 10 * (10 / 60) ** 2;
    let [p0, p1, p2] = [await sample(), await sample(), await sample()];
    expect(p2.y - 2 * p1.y + p0.y).to.be.closeTo(expected, 1e-6);
    expect(p2.x - 2 * p1.x + p0.x).to.be.closeTo(0, 1e-9);
    expect(p2.y).to.be.greaterThan(p0.y);
    scene.setAttribute('gravity', '-10 0');
    await scene.updateComplete;
    [p0, p1, p2] = [await sample(), await sample(), await sample()];
    expect(p2.x - 2 * p1.x + p0.x).to.be.closeTo(-expected, 1e-6);
    expect(p2.y - 2 * p1.y + p0.y).to.be.closeTo(0, 1e-6);
    expect(p2.x).to.be.lessThan(p0.x);
  });

  it("changing a body's fill (attribute or property) changes its pixels; changing its width changes its shape", async () => {
    scene = await mount('width="10" height="10" paused background="#ffffff"', `<physics-box x="5" y="5" width="2" height="2" fill="#ff0000" stroke="none"></physics-box>`);
    const box = scene.querySelector('physics-box')!;
    await drawn(scene, 2);
    expect(colourDistance(pixelAt(scene, 5, 5), rgb('#ff0000'))).to.be.below(8);
    box.setAttribute('fill', '#00ff00');
    await waitFor(() => colourDistance(pixelAt(scene!, 5, 5), rgb('#00ff00')) < 8, 'green pixels');
    box.fill = '#0000ff';
    await waitFor(() => colourDistance(pixelAt(scene!, 5, 5), rgb('#0000ff')) < 8, 'blue pixels');
    expect(colourDistance(pixelAt(scene, 6.6, 5), WHITE)).to.be.below(8);
    box.setAttribute('width', '4');
    await waitFor(() => colourDistance(pixelAt(scene!, 6.6, 5), rgb('#0000ff')) < 8, 'the wider box');
    expect(colourDistance(pixelAt(scene, 7.2, 5), WHITE)).to.be.below(8);
  });

  it('a body element reads its live pose and takes impulses', async () => {
    scene = await mount('width="10" height="10" gravity="0 0" bounds="none" paused', `<physics-box x="2" y="5" width="1" height="1" angle="30"></physics-box>`);
    const box = scene.querySelector('physics-box')!;
    expect(box.x).to.be.closeTo(2, 1e-9);
    expect(box.y).to.be.closeTo(5, 1e-9);
    expect(box.angle).to.be.closeTo(30, 1e-9);
    // Unit box, density 1: mass 1. An impulse of (2, -1) gives it the velocity (2, -1).
    box.applyImpulse(2, -1);
    await scene.step(60);
    expect(box.x).to.be.closeTo(4, 1e-6);
    expect(box.y).to.be.closeTo(4, 1e-6);
    expect(box.angle).to.be.closeTo(30, 1e-6);
    // Setting a pose property moves the body there (the markup's value changes too), from where it is: the other parts
    // keep their live values (it went back to the markup's y = 5 before), unless they are set in the same task.
    box.x = 7;
    await scene.step(1);
    expect(box.x).to.be.closeTo(7, 1e-9);
    expect(box.y).to.be.closeTo(4, 1e-6);
    expect(box.angle).to.be.closeTo(30, 1e-6);
    box.y = 2;
    box.x = 3;
    await scene.step(1);
    expect([box.x, box.y, box.angle].map((v) => Number(v.toFixed(6)))).to.deep.equal([3, 2, 30]);
  });
  it("setting a cloth's y rebuilds it at its markup x (its corner, not its particles' mean); its pins and columns changed live hang it as markup would", async () => {
    // cloth.y = 0.5 took the cloth's centroid (4.75) for its top-left x: rebuilt 2.75 to the right, into the wall,
    // it crumpled. Changing pins rebuilt it into reused slots, where the kernel's tethers flung particles.
    scene = await mount('width="10" height="8" paused', `<physics-cloth x="2" y="1" columns="12" rows="10" spacing="0.5"></physics-cloth>`);
    const cloth = scene.querySelector('physics-cloth')!;
    await scene.step(30);
    cloth.y = 0.5;
    await scene.step(30);
    // Hanging from its top row at rest: its mean is the grid's centre.
    expect(cloth.x).to.be.closeTo(2 + 5.5 / 2, 0.01);
    expect(cloth.y).to.be.closeTo(0.5 + 4.5 / 2, 0.01);
    cloth.setAttribute('pins', 'corners');
    cloth.setAttribute('columns', '8');
    await scene.step(240);
    // Hung from its two top corners 3.5 apart: it sags but stays between them and below them, whole.
    expect(cloth.x).to.be.closeTo(2 + 3.5 / 2, 0.05);
    expect(cloth.y).to.be.within(0.5 + 4.5 / 2, 0.5 + 4.5);
    expect((await scene.diagnostics()).particleCount).to.equal(80);
  });

  it("a scene's or a preset's attribute removed: its property reads the default again, as the simulation uses it", async () => {
    // Lit read a removed attribute as null: scene.width was null while the view went back to 16 wide.
    scene = await mount('width="12" height="7" gravity="0 3" substeps="4" max-restarts="1" draw-mode="replace" kernel="js"', '');
    for (const name of ['width', 'height', 'gravity', 'substeps', 'max-restarts', 'draw-mode', 'kernel']) scene.removeAttribute(name);
    expect([scene.width, scene.height, scene.gravity, scene.substeps, scene.maxRestarts, scene.drawMode, scene.kernel]).to.deep.equal([16, 9, '0 9.81', 'auto', 3, 'over', 'auto']);
    const cloth = document.createElement('cloth-sim') as HTMLElement & { columns: number; wind: number; height: number };
    cloth.setAttribute('columns', '10');
    cloth.setAttribute('wind', '4');
    cloth.setAttribute('height', '6');
    document.body.append(cloth);
    try {
      for (const name of ['columns', 'wind', 'height']) cloth.removeAttribute(name);
      expect([cloth.columns, cloth.wind, cloth.height]).to.deep.equal([24, 1.5, 10]);
    } finally {
      cloth.remove();
    }
  });

  it('the view walls follow width and height changed live; bounds="none" takes them away', async () => {
    // Gravity to the right: the ball rests against the right wall, at x = width − radius.
    scene = await mount('width="8" height="8" gravity="10 0"', `<physics-circle id="ball" x="4" y="4" radius="0.5"></physics-circle>`);
    const ball = scene.querySelector('physics-circle')!;
    await waitFor(() => Math.abs(ball.x - 7.5) < 0.05, 'the ball against the wall at x = 7.5');
    const steps = scene.stepCount;
    scene.width = 12;
    await waitFor(() => Math.abs(ball.x - 11.5) < 0.05, 'the ball against the moved wall at x = 11.5');
    // The same simulation went on (no rebuild).
    expect(scene.stepCount).to.be.above(steps);
    scene.bounds = 'none';
    await waitFor(() => ball.x > 14, 'the ball to leave the view with no walls');
  });
});
