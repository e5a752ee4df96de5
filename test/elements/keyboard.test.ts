// The keyboard on a real scene (paused, driven by step(n)): Tab picks the movable bodies in order (a static floor is
// left out) and the live region says which, the ring sits around the picked body as drawn, an arrow key pushes it by a
// third of the view's height per second, R resets, Space pauses and plays (each said in the live region).
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsCircleElement, PhysicsSceneElement } from '../../src/index.js';
import { drawn, frames, mount, simulated, unmount, waitFor } from './helpers.js';

/** Presses `key` on the scene (focused); true when the scene took it. */
function press(scene: PhysicsSceneElement, key: string, init: KeyboardEventInit = {}): boolean {
  const e = new KeyboardEvent('keydown', { key, code: key === ' ' ? 'Space' : key, bubbles: true, composed: true, cancelable: true, ...init });
  scene.dispatchEvent(e);
  return e.defaultPrevented;
}

const said = (scene: PhysicsSceneElement) => scene.shadowRoot!.querySelector('.announcer')!.textContent!.trim();

describe('<physics-scene> keyboard', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('Tab picks the movable bodies in order and says which; the ring surrounds the picked body as drawn', async () => {
    scene = await mount(
      'width="16" height="9" gravity="0 0" paused',
      `<physics-box id="crate" x="4" y="4" width="2" height="1"></physics-box>
       <physics-box static x="8" y="8.5" width="16" height="1"></physics-box>
       <physics-circle id="ball" x="10" y="4" radius="0.75" aria-label="Blue ball"></physics-circle>`,
    );
    await drawn(scene);
    scene.focus();
    expect([press(scene, 'Tab'), said(scene)]).to.deep.equal([true, 'Picked box 1 of 2']);
    expect([press(scene, 'Tab'), said(scene)]).to.deep.equal([true, 'Picked Blue ball 2 of 2']);
    const ring = scene.shadowRoot!.querySelector<HTMLElement>('.ring')!;
    await waitFor(() => !ring.hidden, 'the ring');
    await frames(2);
    // The ball spans (9.25, 3.25)–(10.75, 4.75) in world units: the ring encloses it, a few pixels out.
    const r = ring.getBoundingClientRect();
    const a = scene.worldToClient(9.25, 3.25);
    const b = scene.worldToClient(10.75, 4.75);
    // 4 px of gap and half the traced stroke.
    for (const gap of [a.x - r.left, a.y - r.top, r.right - b.x, r.bottom - b.y]) expect(gap, 'ring outside the body').to.be.within(3.5, 5.5);
    // Past the last body, Tab leaves the scene: the ring goes.
    expect(press(scene, 'Tab')).to.equal(false);
    await frames(1);
    expect(ring.hidden).to.equal(true);
  });

  it('an arrow key pushes the picked body: a third of the view height per second, the same for a heavy body', async () => {
    scene = await mount(
      'width="16" height="9" gravity="0 0" paused',
      `<physics-box id="crate" x="4" y="4" width="1" height="1"></physics-box>
       <physics-box id="heavy" x="4" y="7" width="1" height="1" density="20"></physics-box>`,
    );
    const crate = scene.querySelector<PhysicsBoxElement>('#crate')!;
    const heavy = scene.querySelector<PhysicsBoxElement>('#heavy')!;
    await simulated(scene, crate);
    scene.focus();
    // With nothing picked, the first arrow picks the first body.
    expect([press(scene, 'ArrowRight'), said(scene)]).to.deep.equal([true, 'Picked box 1 of 2']);
    expect(press(scene, 'ArrowRight')).to.equal(true);
    await scene.step(30);
    // 3 units/s for 0.5 s.
    expect(crate.x).to.be.closeTo(5.5, 0.02);
    expect(crate.y).to.be.closeTo(4, 0.02);
    press(scene, 'Tab');
    press(scene, 'ArrowUp');
    await scene.step(30);
    expect(heavy.y).to.be.closeTo(5.5, 0.02);
    expect(heavy.x).to.be.closeTo(4, 0.02);
    // The crate flew on at the same speed meanwhile.
    expect(crate.x).to.be.closeTo(7, 0.03);
  });

  it('R resets the scene and says so; Space pauses and plays and says so', async () => {
    scene = await mount('width="16" height="9" paused', `<physics-circle id="ball" x="8" y="2" radius="0.5"></physics-circle>`);
    const ball = scene.querySelector<PhysicsCircleElement>('#ball')!;
    await simulated(scene, ball);
    const start = await scene.stateHash();
    await scene.step(30);
    expect(ball.y).to.be.above(2.5);
    scene.focus();
    expect(press(scene, 'r')).to.equal(true);
    await waitFor(async () => (await scene!.stateHash()) === start, 'the reset');
    await waitFor(() => Math.abs(ball.y - 2) < 1e-9, 'the ball back at its start');
    expect(said(scene)).to.equal('Reset');
    // Space plays and pauses, and says which (the play control shows while paused).
    expect(press(scene, ' ')).to.equal(true);
    expect([scene.paused, said(scene)]).to.deep.equal([false, 'Playing']);
    expect(press(scene, ' ')).to.equal(true);
    expect([scene.paused, said(scene)]).to.deep.equal([true, 'Paused']);
    await scene.updateComplete;
    expect(scene.shadowRoot!.querySelector('[part="play-button"]')).to.not.equal(null);
  });
});
