// One suite, run twice: transport-shared.test.ts is served cross-origin isolated (COOP/COEP), so frames travel in a
// SharedArrayBuffer; transport-transfer.test.ts is served without those headers (its name contains "transfer", see
// web-test-runner.config.js), so frames travel as transferred ArrayBuffers from a pool.
import { expect } from '@open-wc/testing';
import { PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, mount, pixelAt, rgb, unmount, waitFor } from './helpers.js';

export function transportSuite(expected: 'shared' | 'transfer'): void {
  describe(`frames over the ${expected} transport`, () => {
    let scene: PhysicsSceneElement | null = null;
    let others: PhysicsSceneElement[] = [];
    afterEach(() => {
      unmount(scene);
      others.forEach(unmount);
      others = [];
      PhysicsSceneElement.maxWorkers = null;
    });

    it(`two scenes in one pool worker each get their own frames over the ${expected} transport`, async () => {
      PhysicsSceneElement.maxWorkers = 1;
      const attrs = 'width="10" height="10" gravity="0 20" background="#ffffff" bounds="none" paused';
      const box = (fill: string) => `<physics-box x="5" y="2" width="2" height="2" fill="${fill}" stroke="none"></physics-box>`;
      const [a, b] = await Promise.all([mount(attrs, box('#ff0000'), { width: 200, height: 200 }), mount(attrs, box('#0000ff'), { width: 200, height: 200 })]);
      others = [a, b];
      expect(a.client!.worker).to.equal(b.client!.worker);
      expect([a.transport, b.transport]).to.deep.equal([expected, expected]);
      const near = (s: PhysicsSceneElement, y: number, colour: string) => colourDistance(pixelAt(s, 5, y), rgb(colour)) < 8;
      await waitFor(() => near(a, 1.5, '#ff0000') && near(b, 1.5, '#0000ff'), 'both boxes drawn');
      await a.step(30);
      const [ya, yb] = [a.querySelector('physics-box')!.y, b.querySelector('physics-box')!.y];
      expect(ya).to.be.closeTo(4.5, 0.1);
      expect(yb).to.equal(2);
      // Each canvas shows its own world: a's box fell, b's is where it was.
      await waitFor(() => near(a, 1.5, '#ffffff') && near(a, ya, '#ff0000'), 'a drawn where its box fell');
      expect(near(b, 1.5, '#0000ff')).to.equal(true);
      expect(near(b, ya, '#ffffff')).to.equal(true);
      expect([a.stepCount, b.stepCount]).to.deep.equal([30, 0]);
    });

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
      // A paused scene draws only what changed: wait for the pixels, not for a number of drawings.
      const red = (x: number, y: number) => colourDistance(pixelAt(scene!, x, y), rgb('#ff0000')) < 8;
      const white = (x: number, y: number) => colourDistance(pixelAt(scene!, x, y), rgb('#ffffff')) < 8;
      await waitFor(() => red(5, 1.5), 'the box drawn');
      const y0 = box.y;
      // Half a second at g = 20: 2.5 units down.
      await scene.step(30);
      expect(box.y - y0).to.be.closeTo(2.5, 0.1);
      // Its old top is background now, its new centre red.
      await waitFor(() => white(5, 1.5) && red(5, box.y), 'the box drawn where it fell');
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
