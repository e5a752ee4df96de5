// Idle costs nothing: a paused scene, a reduced-motion one and a running one whose frames repeat what is drawn make
// no drawing at all, and draw again as soon as something changes (a step, a style, a size, a hook). Counted in drawn
// frames over animation frames and steps, never in wall-clock time.
import { expect } from '@open-wc/testing';
import { emulateMedia } from './commands.js';
import type { PhysicsSceneElement } from '../../src/index.js';
import { frames, mount, unmount, waitFor } from './helpers.js';

/** Drawings the scene makes over `n` animation frames. */
async function drawsOver(scene: PhysicsSceneElement, n = 30): Promise<number> {
  const before = scene.renderedFrames;
  await frames(n);
  return scene.renderedFrames - before;
}

/** Waits until the scene has drawn since `before`, then until it stops (its drawings settle: no more for 3 frames). */
async function drawnOnce(scene: PhysicsSceneElement, before: number, what: string): Promise<void> {
  await waitFor(() => scene.renderedFrames > before, what);
  await waitFor(async () => (await drawsOver(scene, 3)) === 0, `${what}: drawing to stop`);
}

const BOX = '<physics-box x="8" y="2" width="1" height="1" fill="#3366cc"></physics-box>';

describe('idle', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(async () => {
    unmount(scene);
    scene = null;
    await emulateMedia({ reducedMotion: 'no-preference' });
  });

  it('a paused scene draws nothing; step(1), a style, a resize or a draw hook draw it once more', async () => {
    scene = await mount('paused', BOX);
    await drawnOnce(scene, 0, 'the first drawing');
    expect(await drawsOver(scene)).to.equal(0);
    const s = scene;
    const box = s.querySelector('physics-box')!;
    for (const [what, change] of [
      ['step(1)', () => void s.step(1)],
      ['a fill', () => box.setAttribute('fill', '#cc3333')],
      ['a resize', () => (s.parentElement!.style.width = '300px')],
      ['a background', () => (s.background = '#ffffff')],
      ['a draw hook', () => (s.drawHook = () => {})],
    ] as const) {
      const before = s.renderedFrames;
      change();
      await drawnOnce(s, before, what);
      expect(await drawsOver(s), `after ${what}`).to.equal(0);
    }
  });

  it('reduced motion starts paused and draws nothing', async () => {
    await emulateMedia({ reducedMotion: 'reduce' });
    scene = await mount('', BOX);
    expect(scene.paused).to.equal(true);
    await drawnOnce(scene, 0, 'the first drawing');
    expect(await drawsOver(scene)).to.equal(0);
  });

  it('a running scene draws while bodies move and nothing once its frames repeat what is drawn', async () => {
    // Only a static box: the world steps (and publishes a frame each step) but nothing moves.
    scene = await mount('', '<physics-box static x="8" y="8" width="4" height="1"></physics-box>');
    const s = scene;
    await drawnOnce(s, 0, 'the first drawing');
    const steps = s.stepCount;
    const drawn = s.renderedFrames;
    await waitFor(() => s.stepCount > steps + 30, '30 more steps');
    expect(s.renderedFrames - drawn, 'drawings over 30 steps of a still world').to.equal(0);
    // A falling box moves every step: drawn while it falls.
    s.insertAdjacentHTML('beforeend', BOX);
    const moving = s.renderedFrames;
    await waitFor(() => s.renderedFrames > moving + 10, 'ten drawings of a falling box');
  });
});
