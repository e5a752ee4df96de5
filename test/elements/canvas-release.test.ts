// A scene far from the viewport gives its canvas' pixels back (memory per embed in a long post) and shows its picture
// again, without a blank frame, when the reader scrolls back to it.
import { expect } from '@open-wc/testing';
import type { PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, drawn, frames, mount, nextFrame, pixelAt, rgb, unmount, waitFor } from './helpers.js';

const FILL = '#d03020';
const BACKGROUND = '#f7f5f0';

describe('canvas pixels of a scene far from the viewport', () => {
  let scene: PhysicsSceneElement | null = null;
  const spacers: HTMLElement[] = [];
  afterEach(() => {
    unmount(scene);
    scene = null;
    for (const s of spacers.splice(0)) s.remove();
    window.scrollTo(0, 0);
  });

  /** A paused scene with a big static box in its middle, drawn, and a page tall enough to scroll it far away. */
  async function tallPage(): Promise<PhysicsSceneElement> {
    const s = await mount('paused', `<physics-box x="8" y="4.5" width="6" height="4" static fill="${FILL}"></physics-box>`, { width: 400, height: 300 });
    const spacer = document.createElement('div');
    spacer.style.height = `${innerHeight * 6}px`;
    document.body.append(spacer);
    spacers.push(spacer);
    await drawn(s, 2);
    return s;
  }

  it('holds no pixels once more than a viewport off screen; its CSS box stays', async () => {
    scene = await tallPage();
    const canvas = scene.canvas!;
    const cssBox = canvas.getBoundingClientRect();
    expect(canvas.width * canvas.height).to.be.greaterThan(0);
    expect(colourDistance(pixelAt(scene, 8, 4.5), rgb(FILL))).to.be.below(8);
    // Off screen but within a viewport of it: pixels kept (it may come back any moment).
    window.scrollTo(0, scene.getBoundingClientRect().bottom + window.scrollY + innerHeight / 2);
    await waitFor(() => !scene!.onScreen, 'the scene off screen');
    await frames(3);
    expect(canvas.width * canvas.height, 'pixels near the viewport').to.be.greaterThan(0);
    // Far: 0 × 0 pixels, the same CSS box.
    window.scrollTo(0, innerHeight * 4);
    await waitFor(() => canvas.width === 0 && canvas.height === 0, 'the canvas to give its pixels back');
    expect(scene.canvas).to.equal(canvas);
    const box = canvas.getBoundingClientRect();
    expect([box.width, box.height]).to.deep.equal([cssBox.width, cssBox.height]);
  });

  it('scrolled back: the scene is on the canvas by the time it is on screen, no blank frame', async () => {
    scene = await tallPage();
    const canvas = scene.canvas!;
    const pixels = canvas.width * canvas.height;
    window.scrollTo(0, innerHeight * 4);
    await waitFor(() => canvas.width === 0, 'the canvas to give its pixels back');
    // Scroll back in viewport-sized jumps, as a reader would flick: at every animation frame in which the scene is on
    // screen, its canvas has its pixels and shows the box.
    let seenOnScreen = 0;
    for (let y = innerHeight * 4; y >= 0; y -= innerHeight / 2) {
      window.scrollTo(0, Math.max(0, y));
      await nextFrame();
      const r = scene.getBoundingClientRect();
      if (r.bottom > 0 && r.top < innerHeight) {
        seenOnScreen++;
        expect(canvas.width * canvas.height, `pixels at scroll ${y}`).to.equal(pixels);
        expect(colourDistance(pixelAt(scene, 8, 4.5), rgb(FILL)), `the box at scroll ${y}`).to.be.below(8);
        expect(colourDistance(pixelAt(scene, 1, 1), rgb(BACKGROUND)), `the background at scroll ${y}`).to.be.below(8);
      }
    }
    expect(seenOnScreen).to.be.greaterThan(0);
  });

  it('a scene that moved while far away shows its newest state when back', async () => {
    scene = await mount('', `<physics-circle x="3" y="2" radius="0.8" fill="${FILL}"></physics-circle>`, { width: 400, height: 300 });
    const spacer = document.createElement('div');
    spacer.style.height = `${innerHeight * 6}px`;
    document.body.append(spacer);
    spacers.push(spacer);
    scene.pause();
    await drawn(scene, 2);
    const canvas = scene.canvas!;
    window.scrollTo(0, innerHeight * 4);
    await waitFor(() => canvas.width === 0, 'the canvas to give its pixels back');
    // Steps taken far away (step() runs paused and off screen): the ball is somewhere else now.
    await scene.step(30);
    const [x, y] = scene.poseOf(scene.querySelector('physics-circle')!)!;
    window.scrollTo(0, 0);
    await waitFor(() => scene!.onScreen && canvas.width > 0, 'the scene back on screen with its pixels');
    await drawn(scene, 1);
    // Off the radius line that shows the ball's spin.
    expect(colourDistance(pixelAt(scene, x - 0.3, y + 0.4), rgb(FILL)), `the ball at ${x}, ${y}`).to.be.below(8);
    expect(colourDistance(pixelAt(scene, 3, 2), rgb(BACKGROUND)), `${pixelAt(scene, 3, 2)}: no ball where it was`).to.be.below(8);
  });
});
