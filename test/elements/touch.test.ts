// Touch on a real scene (paused, driven by step(n)): the element lets the page pan and zoom (touch-action), a touch
// on a body drags it and cancels its touchstart (so the page does not scroll), a touch on empty space or on a static
// body is left to the page. Synthetic events; the browser's own scrolling is checked in test/e2e/phone.mjs.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsSceneElement } from '../../src/index.js';
import { drawn, mount, simulated, unmount } from './helpers.js';

/** A finger at world point (x, y): pointer event first, then the touch event, as the browser sends them. */
function finger(scene: PhysicsSceneElement, phase: 'down' | 'move' | 'up', x: number, y: number): { pointer: PointerEvent; touch: TouchEvent | null } {
  const p = scene.worldToClient(x, y);
  const canvas = scene.canvas!;
  const type = { down: 'pointerdown', move: 'pointermove', up: 'pointerup' }[phase];
  const pointer = new PointerEvent(type, { clientX: p.x, clientY: p.y, pointerId: 3, pointerType: 'touch', isPrimary: true, bubbles: true, composed: true, cancelable: true });
  canvas.dispatchEvent(pointer);
  let touch: TouchEvent | null = null;
  if (phase === 'down') {
    const t = new Touch({ identifier: 3, target: canvas, clientX: p.x, clientY: p.y });
    touch = new TouchEvent('touchstart', { touches: [t], changedTouches: [t], targetTouches: [t], bubbles: true, composed: true, cancelable: true });
    canvas.dispatchEvent(touch);
  }
  return { pointer, touch };
}

describe('<physics-scene> touch', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('lets the page pan and pinch-zoom over the element', async () => {
    scene = await mount('', '');
    expect(getComputedStyle(scene).touchAction).to.equal('manipulation');
  });

  it('a touch on a body drags it without scrolling; on empty space or a static body nothing is taken', async () => {
    scene = await mount(
      'width="10" height="10" gravity="0 0" paused',
      `<physics-box id="crate" x="3" y="5" width="1" height="1"></physics-box>
       <physics-box id="wall" static x="8" y="5" width="1" height="4"></physics-box>`,
    );
    const crate = scene.querySelector<PhysicsBoxElement>('#crate')!;
    await simulated(scene, crate);
    await drawn(scene);
    // Empty space, then the static wall: nothing cancelled (the page would scroll), nothing moves.
    for (const [x, y] of [[5, 8], [8, 5]]) {
      const { pointer, touch } = finger(scene, 'down', x, y);
      expect([pointer.defaultPrevented, touch!.defaultPrevented], `touch at (${x}, ${y})`).to.deep.equal([false, false]);
      finger(scene, 'up', x, y);
    }
    await scene.step(5);
    expect([crate.x, crate.y]).to.deep.equal([3, 5]);
    // Just off the crate's edge (0.05 units = 2 px at 40 px per unit) still takes it: a fingertip's slop.
    const { pointer, touch } = finger(scene, 'down', 3.55, 5);
    expect([pointer.defaultPrevented, touch!.defaultPrevented]).to.deep.equal([true, true]);
    await scene.step(1);
    for (let k = 1; k <= 10; k++) {
      finger(scene, 'move', 3.55, 5 - 0.2 * k);
      await scene.step(2);
    }
    finger(scene, 'up', 3.55, 3);
    // Dragged up by about two units.
    expect(crate.y).to.be.within(2.8, 3.6);
  });
});
