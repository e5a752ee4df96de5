// The scene's JS API refuses bad arguments where they are given (TypeError / RangeError naming the argument and its
// value), instead of flooring, capping or ignoring them; a throwing draw hook is warned of once; a Symbol set on a
// number property is a physics-error like any bad value, not an uncaught exception.
import { expect } from '@open-wc/testing';
import { PhysicsSceneElement, type PhysicsBoxElement, type PhysicsErrorDetail } from '../../src/index.js';
import { afterEachScene, frames, mount, waitFor } from './helpers.js';

describe('<physics-scene> API arguments', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEachScene(() => scene);

  it('step(n) takes a whole number from 0 to 100,000 and rejects anything else, the scene untouched', async () => {
    scene = await mount('width="10" height="10" paused', '<physics-box x="5" y="2" width="1" height="1"></physics-box>');
    const s = scene;
    expect(await s.step(3)).to.equal(3);
    for (const [n, type, text] of [
      [-1, RangeError, 'got -1'],
      [1.5, RangeError, 'got 1.5'],
      [NaN, RangeError, 'got NaN'],
      [Infinity, RangeError, 'got Infinity'],
      [1e9, RangeError, '100000, got 1000000000'],
      ['3', TypeError, 'got string'],
    ] as const) {
      const error = await s.step(n as number).then(() => null, (e: Error) => e);
      expect(error, String(n)).to.be.instanceOf(type);
      expect(error!.message, String(n)).to.include('step(n)').and.include(text);
    }
    expect(await s.step(0)).to.equal(3);
    // A preset checks the same before its behaviour's ticks.
    const cloth = document.createElement('cloth-sim');
    cloth.setAttribute('paused', '');
    document.body.append(cloth);
    try {
      await cloth.ready;
      const error = await cloth.step(2.5).then(() => null, (e: Error) => e);
      expect(error).to.be.instanceOf(RangeError);
      expect(await cloth.step(2)).to.equal(2);
    } finally {
      cloth.remove();
    }
  });

  it('callTimeout takes milliseconds > 0; drawHook a function or null', async () => {
    const before = PhysicsSceneElement.callTimeout;
    // Past 2³¹ − 1 ms a timer fires at once: 3e9 failed every new worker's start.
    for (const bad of [-1, 0, NaN, 3e9, Infinity, 2 ** 31] as unknown[]) {
      expect(() => (PhysicsSceneElement.callTimeout = bad as number), String(bad)).to.throw(RangeError, 'callTimeout');
    }
    expect(() => (PhysicsSceneElement.callTimeout = '100' as unknown as number)).to.throw(TypeError, 'callTimeout');
    expect(PhysicsSceneElement.callTimeout).to.equal(before);
    // workerFactory: a function or null; anything else failed at the next scene's start ("Invalid value used as weak map key").
    for (const bad of [5, 'x', {}] as unknown[]) {
      expect(() => (PhysicsSceneElement.workerFactory = bad as () => Worker), String(bad)).to.throw(TypeError, 'workerFactory');
    }
    expect(PhysicsSceneElement.workerFactory).to.equal(null);
    scene = await mount('width="10" height="10" paused', '');
    const s = scene;
    for (const bad of ['draw', {}, 42] as unknown[]) expect(() => (s.drawHook = bad as never), String(bad)).to.throw(TypeError, 'drawHook');
    expect(s.drawHook).to.equal(null);
    const hook = () => {};
    s.drawHook = hook;
    expect(s.drawHook).to.equal(hook);
    s.drawHook = null;
    expect(s.drawHook).to.equal(null);
    // undefined counts as null (docs/embedding.md, Custom drawing).
    s.drawHook = hook;
    s.drawHook = undefined as unknown as null;
    expect(s.drawHook).to.equal(null);
  });

  it('worldToClient(x, y) and clientToWorld(x, y) take finite numbers (a bad one was NaN, like "not laid out")', async () => {
    scene = await mount('width="10" height="10" paused', '');
    const s = scene as unknown as Record<'worldToClient' | 'clientToWorld', (...a: unknown[]) => { x: number; y: number }>;
    for (const name of ['worldToClient', 'clientToWorld'] as const) {
      const call = (...a: unknown[]) => s[name].call(scene, ...a);
      expect(() => call('a', 1)).to.throw(TypeError, `${name}(x, y): x must be a number, got "a"`);
      expect(() => call(NaN, 1)).to.throw(RangeError, `${name}(x, y): x must be a finite number, got NaN`);
      expect(() => call()).to.throw(TypeError, `${name}(x, y): x must be a number, got undefined`);
      expect(() => call(1)).to.throw(TypeError, `${name}(x, y): y must be a number, got undefined`);
      const p = call(5, 5);
      expect([Number.isFinite(p.x), Number.isFinite(p.y)], name).to.deep.equal([true, true]);
    }
    const c = scene.worldToClient(5, 5);
    const w = scene.clientToWorld(c.x, c.y);
    expect(w.x).to.be.closeTo(5, 1e-6);
    expect(w.y).to.be.closeTo(5, 1e-6);
  });

  it('a draw hook that throws on every frame is warned of once; another hook that throws, once more', async () => {
    const warnings: string[] = [];
    console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
    scene = await mount('width="10" height="10"', '<physics-box x="5" y="2" width="1" height="1"></physics-box>');
    let calls = 0;
    scene.drawHook = () => {
      calls++;
      throw new Error('broken hook');
    };
    await waitFor(() => calls >= 20, 'twenty frames through the hook');
    expect(warnings.filter((w) => w.includes('broken hook'))).to.have.length(1);
    let other = 0;
    scene.drawHook = () => {
      other++;
      throw new Error('another broken hook');
    };
    await waitFor(() => other >= 10, 'ten frames through the other hook');
    expect(warnings.filter((w) => w.includes('another broken hook'))).to.have.length(1);
    expect(warnings.filter((w) => w.includes('draw hook threw'))).to.have.length(2);
  });

  it('a Symbol set on a number property is reported as a bad value, with no uncaught error', async () => {
    console.warn = () => {};
    const uncaught: string[] = [];
    const onError = (e: ErrorEvent) => uncaught.push(e.message);
    window.addEventListener('error', onError);
    const errors: PhysicsErrorDetail[] = [];
    try {
      scene = await mount('width="10" height="10" paused', '<physics-box id="box" x="5" y="2" width="1" height="1"></physics-box>', {
        before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
      });
      const box = scene.querySelector<PhysicsBoxElement>('#box')!;
      (box as unknown as { width: unknown }).width = Symbol('w');
      await waitFor(() => errors.some((e) => e.attribute === 'width'), 'the bad width reported');
      (scene as unknown as { timestep: unknown }).timestep = Symbol('t');
      await waitFor(() => errors.some((e) => e.attribute === 'timestep'), 'the bad timestep reported');
      await frames(2);
      expect(uncaught).to.deep.equal([]);
      expect(await scene.step(5)).to.equal(5);
    } finally {
      window.removeEventListener('error', onError);
    }
  });
});
