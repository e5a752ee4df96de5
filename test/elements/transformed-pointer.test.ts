// Scenes the page rotates, skews, mirrors or turns in 3D (or whose ancestor does): worldToClient() and clientToWorld()
// follow every CSS transform on the way, so a point maps to where the browser shows it, and a press lands on the body
// drawn under it. Where a point is on screen is told without the scene's mapping: from the transform (DOMMatrix), and
// back by the browser (a PointerEvent's offsetX / offsetY on the canvas: its own inverse of the transforms).
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsSceneElement } from '../../src/index.js';
import { EDGE_MARGIN } from '../../src/render/renderer.js';
import { colourDistance, drawn, mount, rgb, simulated, unmount, waitFor } from './helpers.js';

/** 400 × 400 CSS pixels showing a 10 × 10 world: 39.8 pixels per unit within the renderer's 1 px edge margin. */
const SIZE = 400;
const PX = (SIZE - 2 * EDGE_MARGIN) / 10;

/** Canvas CSS pixel of world coordinate u on either axis of the square scene. */
const canvasAt = (u: number): number => EDGE_MARGIN + u * PX;

const BODIES = `<physics-box id="crate" x="3" y="5" width="1.2" height="1.2" fill="#ff0000" stroke="none"></physics-box>
  <physics-box id="east" x="7" y="5" width="1.2" height="1.2" fill="#00ff00" stroke="none"></physics-box>
  <physics-box id="north" x="5" y="3" width="1.2" height="1.2" fill="#0000ff" stroke="none"></physics-box>`;

// Off the transform's origin (the box's centre, world (5, 5)), so that a mapping that ignores the rotation or the
// mirroring presses elsewhere: under rotate(180deg) or scale(-1,1) the crate is drawn where #east is laid out, under
// rotate(90deg) where #north is.
const CASES: { name: string; transform: string; on: 'scene' | 'ancestor'; rtl?: boolean }[] = [
  { name: 'no transform', transform: 'none', on: 'scene' },
  { name: 'scale(0.5)', transform: 'scale(0.5)', on: 'scene' },
  { name: 'rotate(30deg)', transform: 'rotate(30deg)', on: 'scene' },
  { name: 'rotate(90deg)', transform: 'rotate(90deg)', on: 'scene' },
  { name: 'rotate(180deg)', transform: 'rotate(180deg)', on: 'scene' },
  { name: 'scale(-1,1)', transform: 'scale(-1, 1)', on: 'scene' },
  { name: 'skewX(20deg)', transform: 'skewX(20deg)', on: 'scene' },
  { name: 'perspective(600px) rotateY(35deg)', transform: 'perspective(600px) rotateY(35deg)', on: 'scene' },
  { name: 'rotate(30deg) on an ancestor', transform: 'rotate(30deg)', on: 'ancestor' },
  // A right-to-left page: the corner markers' static position must not follow the page's direction.
  { name: 'no transform, right-to-left page', transform: 'none', on: 'scene', rtl: true },
  { name: 'rotate(30deg), right-to-left page', transform: 'rotate(30deg)', on: 'scene', rtl: true },
];

/** Where the browser puts canvas point (x, y) (CSS pixels) on a page that transforms a box laid out at `origin`. */
function expectedClient(origin: DOMRect, transform: string, x: number, y: number): { x: number; y: number } {
  // transform-origin 50% 50%: the box's centre (the scene fills the box, the canvas the scene).
  const m = new DOMMatrix().translate(SIZE / 2, SIZE / 2).multiply(new DOMMatrix(transform)).translate(-SIZE / 2, -SIZE / 2);
  const p = m.transformPoint(new DOMPoint(x, y, 0, 1));
  return { x: origin.left + p.x / p.w, y: origin.top + p.y / p.w };
}

/** The canvas point (CSS pixels) the browser finds under client point (x, y), by its own hit geometry. */
function browserCanvasPoint(canvas: HTMLCanvasElement, x: number, y: number): { x: number; y: number } {
  let at = { x: NaN, y: NaN };
  // A PointerEvent of a type no one listens for: fractional offsetX / offsetY, and the stage's handlers stay out.
  const probe = (e: Event) => void (at = { x: (e as PointerEvent).offsetX, y: (e as PointerEvent).offsetY });
  canvas.addEventListener('probe', probe);
  canvas.dispatchEvent(new PointerEvent('probe', { clientX: x, clientY: y }));
  canvas.removeEventListener('probe', probe);
  return at;
}

/** [r, g, b] of the canvas's backing store at canvas point (x, y) (CSS pixels). */
function canvasPixel(canvas: HTMLCanvasElement, x: number, y: number): number[] {
  const ratio = canvas.width / canvas.clientWidth;
  return Array.from(canvas.getContext('2d')!.getImageData(Math.floor(x * ratio), Math.floor(y * ratio), 1, 1).data.subarray(0, 3));
}

describe('<physics-scene> transformed by the page', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => {
    unmount(scene);
    document.documentElement.removeAttribute('dir');
  });

  for (const { name, transform, on, rtl } of CASES) {
    it(`maps world ↔ viewport and drags the body under the pointer: ${name}`, async () => {
      if (rtl) document.documentElement.dir = 'rtl';
      scene = await mount(`width="10" height="10" gravity="0 0" bounds="none" paused background="#ffffff"`, BODIES, { width: SIZE, height: SIZE });
      const s = scene;
      const [crate, east, north] = ['#crate', '#east', '#north'].map((id) => s.querySelector<PhysicsBoxElement>(id)!);
      await waitFor(() => s.canvas !== null, 'the canvas');
      const origin = s.getBoundingClientRect();
      (on === 'scene' ? s : s.parentElement!).style.transform = transform;
      await simulated(s, crate);
      await drawn(s, 2);
      const canvas = s.canvas!;
      expect([canvas.clientWidth, canvas.clientHeight], 'canvas CSS size').to.deep.equal([SIZE, SIZE]);

      // Each world point: to the viewport where the transform puts it, and back to itself.
      for (const [x, y] of [[0, 0], [10, 0], [10, 10], [0, 10], [3, 5], [7, 5], [5, 3], [2.5, 7.3], [8.9, 1.1]]) {
        const client = s.worldToClient(x, y);
        const expected = expectedClient(origin, transform, canvasAt(x), canvasAt(y));
        expect(client.x, `client x of (${x}, ${y})`).to.be.closeTo(expected.x, 0.01);
        expect(client.y, `client y of (${x}, ${y})`).to.be.closeTo(expected.y, 0.01);
        const back = s.clientToWorld(client.x, client.y);
        expect(back.x, `round trip x of (${x}, ${y})`).to.be.closeTo(x, 1e-6);
        expect(back.y, `round trip y of (${x}, ${y})`).to.be.closeTo(y, 1e-6);
      }

      // Each body's centre, mapped to the viewport: the browser finds the canvas there at the body's place, and the
      // canvas shows the body's colour there.
      for (const [x, y, colour] of [[3, 5, '#ff0000'], [7, 5, '#00ff00'], [5, 3, '#0000ff']] as const) {
        const client = s.worldToClient(x, y);
        const seen = browserCanvasPoint(canvas, client.x, client.y);
        expect(seen.x, `canvas x under (${x}, ${y})`).to.be.closeTo(canvasAt(x), 0.1);
        expect(seen.y, `canvas y under (${x}, ${y})`).to.be.closeTo(canvasAt(y), 0.1);
        expect(colourDistance(canvasPixel(canvas, seen.x, seen.y), rgb(colour)), `colour under (${x}, ${y})`).to.be.below(8);
      }

      // A press on the crate where the page shows it (worldToClient's point: equal, as checked above; placed from the
      // transform here, so that the drag tests the pointer's own mapping) takes the crate: it follows the drag (down
      // the world's y, away from the others); the others stay put.
      const press = (type: string, x: number, y: number) => {
        const p = expectedClient(origin, transform, canvasAt(x), canvasAt(y));
        const init = { clientX: p.x, clientY: p.y, pointerId: 7, pointerType: 'mouse', isPrimary: true, button: 0, buttons: type === 'pointerup' ? 0 : 1 };
        canvas.dispatchEvent(new PointerEvent(type, { ...init, bubbles: true, composed: true, cancelable: true }));
      };
      press('pointerdown', 3, 5);
      await s.step(1);
      for (let k = 1; k <= 10; k++) {
        press('pointermove', 3, 5 + 0.25 * k);
        await s.step(2);
      }
      await s.step(30);
      press('pointerup', 3, 7.5);
      expect(crate.x).to.be.closeTo(3, 0.1);
      expect(crate.y).to.be.closeTo(7.5, 0.1);
      expect(east.x, '#east x').to.be.closeTo(7, 1e-6);
      expect(east.y, '#east y').to.be.closeTo(5, 1e-6);
      expect(north.x, '#north x').to.be.closeTo(5, 1e-6);
      expect(north.y, '#north y').to.be.closeTo(3, 1e-6);
    });
  }

  for (const sizing of ['content-box', 'border-box'])
  it(`a page's ::part(canvas) margin, border and padding (${sizing}): the view is mapped where its content box is, a press takes the body there`, async () => {
    const sheet = document.createElement('style');
    sheet.textContent = `physics-scene.framed::part(canvas) { margin: 12px 0 0 20px; border: 3px solid #000; padding: 5px 7px 4px 6px; box-sizing: ${sizing}; }`;
    document.head.append(sheet);
    try {
      scene = await mount(`class="framed" width="10" height="10" gravity="0 0" bounds="none" paused background="#ffffff"`, BODIES, { width: SIZE, height: SIZE });
      const s = scene;
      const crate = s.querySelector<PhysicsBoxElement>('#crate')!;
      await waitFor(() => s.canvas !== null, 'the canvas');
      await simulated(s, crate);
      await drawn(s, 2);
      const canvas = s.canvas!;
      const box = canvas.getBoundingClientRect();
      // The content box: inside the 3 px border and the padding; its CSS size is what the renderer draws in.
      const content = { left: box.left + 3 + 6, top: box.top + 3 + 5, width: box.width - 6 - 6 - 7, height: box.height - 6 - 5 - 4 };
      expect(box.left - s.getBoundingClientRect().left, 'the margin moved the canvas').to.be.closeTo(20, 0.01);
      // The renderer draws the scene's SIZE × SIZE box; the browser fits that image into the content box.
      for (const [x, y] of [[0, 0], [10, 0], [10, 10], [3, 5], [8.9, 1.1]]) {
        const client = s.worldToClient(x, y);
        expect(client.x, `client x of (${x}, ${y})`).to.be.closeTo(content.left + (canvasAt(x) * content.width) / SIZE, 0.01);
        expect(client.y, `client y of (${x}, ${y})`).to.be.closeTo(content.top + (canvasAt(y) * content.height) / SIZE, 0.01);
        const back = s.clientToWorld(client.x, client.y);
        expect(back.x).to.be.closeTo(x, 1e-6);
        expect(back.y).to.be.closeTo(y, 1e-6);
      }
      // The canvas shows the crate where worldToClient says (offsetX / offsetY count from the padding box).
      const at = s.worldToClient(3, 5);
      const seen = browserCanvasPoint(canvas, at.x, at.y);
      expect(colourDistance(canvasPixel(canvas, seen.x - 6, seen.y - 5), rgb('#ff0000')), 'colour under the crate').to.be.below(8);
      const press = (type: string, y: number) => {
        const p = s.worldToClient(3, y);
        const init = { clientX: p.x, clientY: p.y, pointerId: 9, pointerType: 'mouse', isPrimary: true, button: 0, buttons: type === 'pointerup' ? 0 : 1 };
        canvas.dispatchEvent(new PointerEvent(type, { ...init, bubbles: true, composed: true, cancelable: true }));
      };
      press('pointerdown', 5);
      await s.step(1);
      for (let k = 1; k <= 10; k++) {
        press('pointermove', 5 + 0.25 * k);
        await s.step(2);
      }
      await s.step(30);
      press('pointerup', 7.5);
      expect(crate.y, 'the crate followed the drag').to.be.closeTo(7.5, 0.1);
    } finally {
      sheet.remove();
    }
  });

  it('a plane turned edge-on maps nothing (NaN) and a press on it takes nothing', async () => {
    scene = await mount(`width="10" height="10" gravity="0 0" bounds="none" paused`, BODIES, { width: SIZE, height: SIZE });
    const s = scene;
    const crate = s.querySelector<PhysicsBoxElement>('#crate')!;
    await waitFor(() => s.canvas !== null, 'the canvas');
    await simulated(s, crate);
    const middle = s.worldToClient(3, 5);
    s.style.transform = 'rotateY(90deg)';
    const mapped = s.worldToClient(3, 5);
    const back = s.clientToWorld(middle.x, middle.y);
    for (const v of [mapped.x, mapped.y, back.x, back.y]) expect(v).to.be.NaN;
    const init = { clientX: middle.x, clientY: middle.y, pointerId: 5, pointerType: 'mouse', isPrimary: true, button: 0, bubbles: true, composed: true, cancelable: true };
    s.canvas!.dispatchEvent(new PointerEvent('pointerdown', { ...init, buttons: 1 }));
    await s.step(1);
    s.canvas!.dispatchEvent(new PointerEvent('pointermove', { ...init, clientY: middle.y + 80, buttons: 1 }));
    await s.step(20);
    s.canvas!.dispatchEvent(new PointerEvent('pointerup', { ...init, buttons: 0 }));
    expect(crate.x).to.be.closeTo(3, 1e-6);
    expect(crate.y).to.be.closeTo(5, 1e-6);
  });
});
