// The engine runs in a worker for real, the main-thread mode is the same engine (equal state hashes), and a worker
// that fails to load or to answer surfaces as physics-error and falls back to the main thread instead of hanging.
import { expect } from '@open-wc/testing';
import { PhysicsSceneElement, type PhysicsErrorDetail } from '../../src/index.js';
import { mount, unmount, waitFor } from '../elements/helpers.js';

const MARKUP = `
  <physics-box id="floor" x="8" y="8.5" width="16" height="1" static></physics-box>
  <physics-box id="a" x="4" y="2" width="1" height="1" angle="15"></physics-box>
  <physics-box id="b" x="5.5" y="2" width="1" height="0.5"></physics-box>
  <physics-circle x="7" y="1" radius="0.5" restitution="0.4"></physics-circle>
  <physics-polygon x="9" y="2" points="-1,-0.5 1,-0.5 1,0.5 0.4,0.5 0.4,0 -0.4,0 -0.4,0.5 -1,0.5"></physics-polygon>
  <physics-rope x1="11" y1="1" x2="14" y2="1" segments="12"></physics-rope>
  <physics-cloth x="1" y="0.5" columns="6" rows="5" spacing="0.3" pins="corners"></physics-cloth>
  <physics-softbody x="13" y="4" radius="0.8" segments="12"></physics-softbody>
  <physics-ragdoll x="2" y="5" height="1.5"></physics-ragdoll>
  <physics-joint a="a" b="b"></physics-joint>
  <physics-spring a="b" b="floor" stiffness="20"></physics-spring>
  <physics-pin body="a" x="4" y="1"></physics-pin>`;

describe('engine worker', () => {
  const scenes: PhysicsSceneElement[] = [];
  const factory = PhysicsSceneElement.workerFactory;
  const timeout = PhysicsSceneElement.callTimeout;
  afterEach(() => {
    scenes.splice(0).forEach(unmount);
    PhysicsSceneElement.workerFactory = factory;
    PhysicsSceneElement.callTimeout = timeout;
  });

  it('runs the engine in a dedicated worker (diagnostics), and worker="none" on the main thread', async () => {
    const inWorker = await mount('paused', MARKUP);
    const onMain = await mount('paused worker="none"', MARKUP);
    scenes.push(inWorker, onMain);
    const w = await inWorker.diagnostics();
    const m = await onMain.diagnostics();
    expect([w.mode, w.inWorker]).to.deep.equal(['worker', true]);
    expect([m.mode, m.inWorker, m.transport]).to.deep.equal(['main', false, 'direct']);
    expect(w.bodyCount).to.equal(9);
    expect(w.linkCount).to.equal(3);
    expect(m.bodyCount).to.equal(9);
  });

  it('the main-thread mode gives the same state hash as the worker after N steps of the same markup', async () => {
    const inWorker = await mount('paused', MARKUP);
    const onMain = await mount('paused worker="none"', MARKUP);
    scenes.push(inWorker, onMain);
    const start = await inWorker.stateHash();
    expect(await onMain.stateHash()).to.equal(start);
    expect(await inWorker.step(120)).to.equal(120);
    expect(await onMain.step(120)).to.equal(120);
    const hw = await inWorker.stateHash();
    expect(hw).to.not.equal(start);
    expect(await onMain.stateHash()).to.equal(hw);
    // Live edits keep them equal too.
    for (const s of [inWorker, onMain]) s.querySelector('physics-circle')!.setAttribute('radius', '0.7');
    await inWorker.step(60);
    await onMain.step(60);
    expect(await onMain.stateHash()).to.equal(await inWorker.stateHash());
  });

  it('snapshot() and restore() put the simulation back (same hash after the same steps), also across modes', async () => {
    const inWorker = await mount('paused', MARKUP);
    const onMain = await mount('paused worker="none"', MARKUP);
    scenes.push(inWorker, onMain);
    await inWorker.step(30);
    const snap = await inWorker.snapshot();
    await inWorker.step(45);
    const later = await inWorker.stateHash();
    await inWorker.restore(snap);
    await inWorker.step(45);
    expect(await inWorker.stateHash()).to.equal(later);
    // A snapshot is plain data: the main-thread engine continues it identically.
    await onMain.restore(snap);
    await onMain.step(45);
    expect(await onMain.stateHash()).to.equal(later);
  });

  it('a worker script that fails to load gives physics-error and the scene runs on the main thread', async () => {
    PhysicsSceneElement.workerFactory = () => new Worker(new URL('./no-such-worker.js', import.meta.url), { type: 'module' });
    const errors: PhysicsErrorDetail[] = [];
    const scene = await mount('gravity="0 10"', `<physics-circle x="5" y="1" radius="0.5"></physics-circle>`, {
      before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    });
    scenes.push(scene);
    expect(errors.length).to.equal(1);
    // Found by the worker's error event, not by a call left unanswered for callTimeout.
    expect(errors[0].message).not.to.match(/did not answer/);
    expect(errors[0].attribute).to.equal('worker');
    expect(errors[0].message).to.match(/^engine worker failed, running on the main thread instead: /);
    expect(scene.mode).to.equal('main');
    const ball = scene.querySelector('physics-circle')!;
    await waitFor(() => ball.y > 1.5, 'the ball to fall');
  });

  it('a Worker that cannot be created (as under a strict CSP) gives physics-error and the main-thread engine', async () => {
    PhysicsSceneElement.workerFactory = () => {
      throw new DOMException("Refused to create a worker: violates the Content Security Policy directive 'worker-src'", 'SecurityError');
    };
    const errors: PhysicsErrorDetail[] = [];
    const scene = await mount('paused', `<physics-circle x="5" y="1" radius="0.5"></physics-circle>`, {
      before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    });
    scenes.push(scene);
    expect(errors.map((e) => e.message).join()).to.match(/Content Security Policy/);
    expect(scene.mode).to.equal('main');
    expect(await scene.step(3)).to.equal(3);
  });

  it('a workerFactory that is not a function, or a callTimeout past the longest timer delay, is refused when set: scenes go on starting in their worker', async () => {
    // 5 reached the page's pools and failed every scene's start ("Invalid value used as weak map key"); 3e9 or Infinity
    // fired the call timers at once ("the worker did not answer within 3000000000 ms"). The pools' own guards
    // (checkWorkerFactory, timerDelay) are pool.test.ts's.
    for (const bad of [5, 'x']) {
      expect(() => (PhysicsSceneElement.workerFactory = bad as unknown as () => Worker), String(bad)).to.throw(TypeError, `workerFactory must be a function that returns a Worker, or null for the default, got ${bad === 'x' ? '"x"' : bad}`);
    }
    for (const ms of [3e9, Infinity]) expect(() => (PhysicsSceneElement.callTimeout = ms), String(ms)).to.throw(RangeError, 'at most 2147483647');
    const errors: PhysicsErrorDetail[] = [];
    const scene = await mount('paused', `<physics-circle x="5" y="1" radius="0.5"></physics-circle>`, {
      before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    });
    scenes.push(scene);
    expect(errors).to.deep.equal([]);
    expect(scene.mode).to.equal('worker');
    expect(await scene.step(3)).to.equal(3);
  });

  it('a worker that never answers times out with physics-error instead of hanging', async () => {
    PhysicsSceneElement.callTimeout = 300;
    PhysicsSceneElement.workerFactory = () => new Worker(URL.createObjectURL(new Blob(['/* silent */'], { type: 'text/javascript' })), { type: 'module' });
    const errors: PhysicsErrorDetail[] = [];
    const scene = await mount('paused', `<physics-circle x="5" y="1" radius="0.5"></physics-circle>`, {
      before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
    });
    scenes.push(scene);
    expect(errors.map((e) => e.message).join()).to.match(/did not answer within 300 ms/);
    expect(scene.mode).to.equal('main');
    expect(await scene.step(5)).to.equal(5);
  });
});
