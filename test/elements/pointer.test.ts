// Pointer interaction through synthetic pointer events: drag a body, throw it on release, drag a cloth.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsSceneElement } from '../../src/index.js';
import { frames, mount, unmount, waitFor } from './helpers.js';

function pointer(scene: PhysicsSceneElement, type: string, x: number, y: number): void {
  const p = scene.worldToClient(x, y);
  scene.canvas!.dispatchEvent(new PointerEvent(type, { clientX: p.x, clientY: p.y, pointerId: 7, pointerType: 'mouse', isPrimary: true, button: 0, buttons: type === 'pointerup' ? 0 : 1, bubbles: true, composed: true, cancelable: true }));
}

/** Drags from (x0, y0) to (x1, y1) in `steps` animation frames. */
async function drag(scene: PhysicsSceneElement, x0: number, y0: number, x1: number, y1: number, steps: number): Promise<void> {
  pointer(scene, 'pointerdown', x0, y0);
  for (let k = 1; k <= steps; k++) {
    await frames(1);
    pointer(scene, 'pointermove', x0 + ((x1 - x0) * k) / steps, y0 + ((y1 - y0) * k) / steps);
  }
}

describe('<physics-scene> pointer drag', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('drags a body with the pointer and throws it on release', async () => {
    scene = await mount('width="10" height="10" gravity="0 0"', `<physics-box id="crate" x="3" y="5" width="1" height="1"></physics-box>`);
    const crate = scene.querySelector<PhysicsBoxElement>('#crate')!;
    await drag(scene, 3.2, 5.1, 7, 5.1, 20);
    // Let go while the pointer still moves: the crate followed it to the right …
    const atRelease = crate.x;
    pointer(scene, 'pointerup', 7, 5.1);
    expect(atRelease).to.be.greaterThan(4.5);
    expect(crate.y).to.be.closeTo(5, 0.3);
    // … and, thrown, flies on with the speed the drag gave it (no gravity, no friction in the air).
    // Measured from where it was at release: on a loaded machine it may still lag the pointer (x = 7) then.
    await waitFor(() => crate.x > atRelease + 1.5, 'the crate to fly on after release', 8000);
    // Straight on: no gravity pulls it down (a drag held off its centre may have set it spinning a little).
    expect(crate.y).to.be.closeTo(5, 0.75);
  });

  it('a press on empty space moves nothing; a drag pulls a cloth particle', async () => {
    scene = await mount('width="10" height="10" gravity="0 0"', `<physics-box x="3" y="5" width="1" height="1"></physics-box><physics-cloth x="5" y="1" columns="5" rows="5" spacing="0.5" pins="top"></physics-cloth>`);
    const box = scene.querySelector<PhysicsBoxElement>('physics-box')!;
    await drag(scene, 1, 8, 3, 8, 5);
    pointer(scene, 'pointerup', 3, 8);
    await frames(5);
    expect(box.x).to.be.closeTo(3, 1e-6);
    expect(box.y).to.be.closeTo(5, 1e-6);
    const before = (await scene.snapshot()).world as { tables: { columns: Float64Array[] }[] };
    const cloth = scene.querySelector('physics-cloth')!;
    // The bottom-right particle of the cloth hangs at (7, 3), as far below its pin as the cloth allows: fold it up
    // to (6, 2).
    const cx = cloth.x;
    await drag(scene, 7, 3, 6, 2, 10);
    await waitFor(() => cloth.x < cx - 0.02, 'the cloth to move');
    await frames(10);
    pointer(scene, 'pointerup', 6, 2);
    const after = (await scene.snapshot()).world as { tables: { columns: Float64Array[] }[] };
    // The particle table's first two columns are x and y: particles moved by more than a unit (the grabbed one by ~√2).
    const [x0, y0] = before.tables[0].columns;
    const [x1, y1] = after.tables[0].columns;
    let most = 0;
    for (let i = 0; i < x0.length; i++) most = Math.max(most, Math.hypot(x1[i] - x0[i], y1[i] - y0[i]));
    expect(most).to.be.greaterThan(1);
  });

  it('a press inside a soft body (not on its ring) drags it', async () => {
    scene = await mount('width="10" height="10" gravity="0 0"', `<physics-softbody x="5" y="6" radius="1" segments="16"></physics-softbody>`);
    const blob = scene.querySelector('physics-softbody')!;
    expect(blob.y).to.be.closeTo(6, 1e-6);
    await drag(scene, 5, 6, 5, 3, 15);
    await waitFor(() => blob.y < 4.5, 'the soft body to follow the pointer up');
    pointer(scene, 'pointerup', 5, 3);
    expect(blob.x).to.be.closeTo(5, 0.5);
  });
});
