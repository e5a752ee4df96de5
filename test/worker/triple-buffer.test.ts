// The SharedArrayBuffer triple buffer under real concurrency: a worker writes frames as fast as it can while the page
// reads; every frame read must be whole (never a mix of two frames) and newer than the one before.
import { expect } from '@open-wc/testing';
import { TripleBuffer } from '../../src/worker/triple-buffer.js';

describe('TripleBuffer', () => {
  it('never hands the reader a torn or older frame while a worker writes', async () => {
    expect(globalThis.crossOriginIsolated).to.equal(true);
    const tb = new TripleBuffer(2048, true);
    const module = new URL('../../src/worker/triple-buffer.js', import.meta.url).href;
    const source = `import { TripleBuffer } from ${JSON.stringify(module)};
      onmessage = (e) => {
        const tb = new TripleBuffer(e.data.buffer);
        const stop = new Int32Array(e.data.stop);
        let k = 0;
        while (Atomics.load(stop, 0) === 0) {
          k++;
          const f = tb.begin();
          for (let i = 0; i < f.length; i++) f[i] = k;
          tb.commit();
        }
        postMessage(k);
      };`;
    const worker = new Worker(URL.createObjectURL(new Blob([source], { type: 'text/javascript' })), { type: 'module' });
    const stop = new SharedArrayBuffer(4);
    let written = 0;
    worker.onmessage = (e) => (written = e.data);
    worker.postMessage({ buffer: tb.buffer, stop });
    let reads = 0;
    let last = 0;
    let torn = 0;
    let older = 0;
    // At least 600 ms of reading and 200 frames read (a loaded machine may start the worker late), 30 s at most.
    const start = performance.now();
    while ((performance.now() < start + 600 || reads < 200) && performance.now() < start + 30000) {
      // Read hard for a while, then let the worker's message through.
      const slice = performance.now() + 50;
      while (performance.now() < slice) {
        const f = tb.read();
        if (!f) continue;
        const k = f[0];
        if (f[f.length - 1] !== k || f[1024] !== k) torn++;
        if (k < last) older++;
        last = k;
        reads++;
      }
      await new Promise((r) => setTimeout(r, 0));
    }
    Atomics.store(new Int32Array(stop), 0, 1);
    const t0 = performance.now();
    while (written === 0 && performance.now() < t0 + 3000) await new Promise((r) => setTimeout(r, 5));
    worker.terminate();
    expect(written).to.be.greaterThan(reads);
    expect(reads).to.be.at.least(200);
    expect(torn).to.equal(0);
    expect(older).to.equal(0);
    // The newest frame is the writer's last one.
    const final = tb.read() ?? null;
    expect(final === null ? last : final[0]).to.equal(written);
  });
});
