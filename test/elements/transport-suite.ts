// One suite, run twice: transport-shared.test.ts is served cross-origin isolated (COOP/COEP), so frames travel in a
// SharedArrayBuffer; transport-transfer.test.ts is served without those headers (its name contains "transfer", see
// web-test-runner.config.js), so frames travel as transferred ArrayBuffers from a pool.
import { expect } from '@open-wc/testing';
import type { PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, drawn, mount, pixelAt, rgb, unmount, waitFor } from './helpers.js';

export function transportSuite(expected: 'shared' | 'transfer'): void {
  describe(`frames over the ${expected} transport`, () => {
    let scene: PhysicsSceneElement | null = null;
    afterEach(() => unmount(scene));

    it(`runs in a worker and publishes frames over the ${expected} transport`, async () => {
      expect(globalThis.crossOriginIsolated).to.equal(expected === 'shared');
      scene = await mount('width="10" height="10" gravity="0 20" background="#ffffff"', `<physics-box x="5" y="2" width="2" height="2" fill="#ff0000" stroke="none"></physics-box>`);
      const d = await scene.diagnostics();
      expect(d.mode).to.equal('worker');
      expect(d.inWorker).to.equal(true);
      expect(d.transport).to.equal(expected);
      expect(d.crossOriginIsolated).to.equal(expected === 'shared');
      expect(scene.transport).to.equal(expected);
    });

    it('the page sees the motion: positions and pixels change from frame to frame', async () => {
      // Paused and stepped: a paused scene draws its newest frame as it is (no interpolation), the moment it arrives.
      scene = await mount('width="10" height="10" gravity="0 20" background="#ffffff" bounds="none" paused', `<physics-box x="5" y="2" width="2" height="2" fill="#ff0000" stroke="none"></physics-box>`);
      const box = scene.querySelector('physics-box')!;
      await drawn(scene, 1);
      const y0 = box.y;
      expect(colourDistance(pixelAt(scene, 5, 1.5), rgb('#ff0000'))).to.be.below(8);
      // Half a second at g = 20: 2.5 units down.
      await scene.step(30);
      expect(box.y - y0).to.be.closeTo(2.5, 0.1);
      await drawn(scene, 2);
      // Its old top is background now, its new centre red.
      expect(colourDistance(pixelAt(scene, 5, 1.5), rgb('#ffffff'))).to.be.below(8);
      expect(colourDistance(pixelAt(scene, 5, box.y), rgb('#ff0000'))).to.be.below(8);
    });

    it('publishing allocates no buffers in the steady state, and grows once when the scene outgrows them', async () => {
      // Paused and stepped one frame at a time: 120 frames whatever the speed of the machine.
      scene = await mount('width="10" height="10" gravity="0 20" background="#ffffff" paused', `<physics-box x="5" y="9.5" width="10" height="1" static></physics-box><physics-circle x="5" y="2" radius="0.5"></physics-circle>`);
      const first = await scene.diagnostics();
      for (let k = 0; k < 120; k++) await scene.step(1);
      const later = await scene.diagnostics();
      expect(later.published - first.published).to.be.at.least(120);
      if (expected === 'shared') {
        // One triple buffer, made once.
        expect(later.buffersAllocated).to.equal(first.buffersAllocated);
        expect(later.buffersAllocated).to.equal(1);
      } else {
        // A pool of at most four transferred buffers, however many frames: how many of them a page needs depends on
        // how soon it hands each back (a loaded machine may need a second), never on the number of frames.
        expect(later.buffersAllocated).to.be.within(1, 4);
      }
      // A 40×30 cloth needs 2400 more floats than the buffers hold: they grow, and the cloth reaches the page.
      const cloth = document.createElement('physics-cloth');
      for (const [k, v] of Object.entries({ x: '1', y: '1', columns: '40', rows: '30', spacing: '0.2', fill: '#00ff00', stroke: 'none' })) cloth.setAttribute(k, v);
      scene.append(cloth);
      // The floor and the ball are rigid bodies: a particle each.
      await waitFor(async () => (await scene!.diagnostics()).particleCount === 1 + 1 + 1200, 'the cloth particles');
      await scene.step(1);
      await waitFor(() => colourDistance(pixelAt(scene!, 3, 2), rgb('#00ff00')) < 8, 'the cloth on the canvas');
      const grown = await scene.diagnostics();
      expect(grown.buffersAllocated).to.be.greaterThan(later.buffersAllocated);
      expect(grown.buffersAllocated).to.be.at.most(later.buffersAllocated + (expected === 'shared' ? 1 : 4));
    });
  });
}
