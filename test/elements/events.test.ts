// physics-collision: detail names the two body elements, the normal and the depth; events cross the worker
// boundary only while someone listens.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsCollisionDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, stepUntil, unmount } from './helpers.js';

describe('<physics-scene> collision events', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('fires physics-collision with the two body elements, the normal and the depth, only while listened to', async () => {
    // Paused until the listener is in place: a running crate could land before the engine was asked for events.
    scene = await mount('width="10" height="10" gravity="0 20" paused', `
      <physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
      <physics-box id="crate" x="5" y="6" width="1" height="1"></physics-box>`);
    const quiet = await scene.diagnostics();
    expect([quiet.events, quiet.eventsSent]).to.deep.equal([false, 0]);
    const seen: PhysicsCollisionDetail[] = [];
    const listener = (e: CustomEvent<PhysicsCollisionDetail>) => seen.push(e.detail);
    scene.addEventListener('physics-collision', listener);
    expect((await scene.diagnostics()).events).to.equal(true);
    await stepUntil(scene, () => seen.length > 0, 'a collision');
    const floor = scene.querySelector('#floor');
    const crate = scene.querySelector('#crate');
    const hit = seen[0];
    expect([hit.a, hit.b]).to.have.members([floor, crate]);
    // The normal points from a to b, vertical here.
    expect(Math.abs(hit.normal.y)).to.be.closeTo(1, 1e-6);
    expect(hit.normal.y * (hit.a === floor ? -1 : 1)).to.be.closeTo(1, 1e-6);
    expect(hit.depth).to.be.at.least(0);
    expect(hit.depth).to.be.below(0.1);
    scene.removeEventListener('physics-collision', listener);
    const off = await scene.diagnostics();
    expect(off.events).to.equal(false);
    expect(off.eventsSent).to.be.at.least(1);
  });

  it('every physics-* event leaves shadow roots (bubbles, composed) and is typed on the document without a cast', async () => {
    const host = document.createElement('div');
    host.style.cssText = 'width: 300px; height: 300px';
    const root = host.attachShadow({ mode: 'open' });
    // Fixed test markup only.
    root.innerHTML = `<physics-scene paused collision-events width="10" height="10" gravity="0 20" style="width: 100%; height: 100%">
      <physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
      <physics-box id="crate" x="5" y="8" width="1" height="1"></physics-box>
      <physics-circle id="bad" x="2" y="2" radius="-1"></physics-circle></physics-scene>`;
    const scene = root.querySelector('physics-scene')!;
    const seen: string[] = [];
    const flags = (e: Event) => `${e.bubbles} ${e.composed} ${e.target === host}`;
    const onReady = (e: HTMLElementEventMap['physics-ready']) => seen.push(`ready ${e.detail.mode === scene.mode} ${flags(e)}`);
    const onError = (e: HTMLElementEventMap['physics-error']) => seen.push(`error ${e.detail.attribute}=${e.detail.value} ${flags(e)}`);
    const onBegin = (e: HTMLElementEventMap['physics-collision']) => seen.push(`collision ${[e.detail.a?.id, e.detail.b?.id].sort()} ${flags(e)}`);
    const onEnd = (e: HTMLElementEventMap['physics-collision-end']) => seen.push(`collision-end ${flags(e)}`);
    document.addEventListener('physics-ready', onReady);
    document.addEventListener('physics-error', onError);
    document.addEventListener('physics-collision', onBegin);
    document.addEventListener('physics-collision-end', onEnd);
    const warn = console.warn;
    console.warn = () => {};
    try {
      document.body.append(host);
      await scene.ready;
      expect(seen).to.deep.equal(['error radius=-1 true true true', 'ready true true true true']);
      // Paused and stepped: the crate lands on the floor, then an impulse lifts it off.
      await stepUntil(scene, () => seen.some((s) => s.startsWith('collision ')), 'the crate to land');
      expect(seen.filter((s) => s.startsWith('collision '))[0]).to.equal('collision crate,floor true true true');
      scene.querySelector<PhysicsBoxElement>('#crate')!.applyImpulse(0, -20);
      await stepUntil(scene, () => seen.some((s) => s.startsWith('collision-end')), 'the crate to leave the floor');
      expect(seen.filter((s) => s.startsWith('collision-end'))[0]).to.equal('collision-end true true true');
    } finally {
      console.warn = warn;
      document.removeEventListener('physics-ready', onReady);
      document.removeEventListener('physics-error', onError);
      document.removeEventListener('physics-collision', onBegin);
      document.removeEventListener('physics-collision-end', onEnd);
      host.remove();
    }
  });
});
