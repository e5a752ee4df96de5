// physics-collision: detail names the two body elements, the normal, the depth and the speed; events cross the worker
// boundary only while someone listens.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsCircleElement, PhysicsCollisionDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, stepUntil, unmount } from './helpers.js';

describe('<physics-scene> collision events', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('fires physics-collision with the two body elements, the normal, the depth and the speed they met at, only while listened to', async () => {
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
    // Dropped 2.5 (from 6.5 to the floor's top at 9) under g = 20: √(2·20·2.5) = 10.
    expect(hit.speed).to.be.closeTo(10, 0.02);
    scene.removeEventListener('physics-collision', listener);
    const off = await scene.diagnostics();
    expect(off.events).to.equal(false);
    expect(off.eventsSent).to.be.at.least(1);
  });

  it('a removeEventListener for a listener never added leaves the one added hearing; removing it with its capture flag wrong too', async () => {
    // The scene counted add and remove calls: a stray remove stopped the engine's events while a listener was still there.
    scene = await mount('width="10" height="10" gravity="0 20" paused', `
      <physics-box x="5" y="9.5" width="10" height="1" static></physics-box>
      <physics-box x="5" y="6" width="1" height="1"></physics-box>`);
    let heard = 0;
    const listener = () => heard++;
    scene.addEventListener('physics-collision', listener);
    scene.removeEventListener('physics-collision', () => {});
    scene.removeEventListener('physics-collision', listener, true);
    expect((await scene.diagnostics()).events).to.equal(true);
    await stepUntil(scene, () => heard > 0, 'a collision heard');
    scene.removeEventListener('physics-collision', listener);
    expect((await scene.diagnostics()).events).to.equal(false);
  });

  for (const model of ['rigid', 'particles'])
  it(`a body (${model}) landing on the view's floor fires physics-collision with b null, the normal from it into the floor; thrown off, physics-collision-end`, async () => {
    scene = await mount('width="10" height="10" gravity="0 20" paused', `<physics-circle id="ball" x="5" y="6" radius="0.5" model="${model}"></physics-circle>`);
    const begins: PhysicsCollisionDetail[] = [];
    const ends: PhysicsCollisionDetail[] = [];
    scene.addEventListener('physics-collision', (e) => begins.push(e.detail));
    scene.addEventListener('physics-collision-end', (e) => ends.push(e.detail));
    await stepUntil(scene, () => begins.length > 0, 'a landing');
    const ball = scene.querySelector('#ball');
    expect([begins[0].a, begins[0].b]).to.deep.equal([ball, null]);
    expect([begins[0].normal.x, begins[0].normal.y]).to.deep.equal([0, 1]);
    // Dropped 3.5 (from 6.5 to the floor at 10) under g = 20.
    expect(begins[0].speed).to.be.closeTo(Math.sqrt(2 * 20 * 3.5), 0.03);
    (ball as PhysicsCircleElement).velocity = '0 -12';
    await stepUntil(scene, () => ends.length > 0, 'the ball thrown off the floor');
    expect([ends[0].a, ends[0].b]).to.deep.equal([ball, null]);
  });

  it('a touching body that is removed or rebuilt ends its pairs, naming its element; a reset ends every pair, then they begin again', async () => {
    scene = await mount('width="10" height="10" gravity="0 20" paused collision-events', `
      <physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
      <physics-box id="crate" x="3" y="7" width="1" height="1"></physics-box>
      <physics-box id="chest" x="7" y="7" width="1" height="1"></physics-box>
      <physics-box id="rest" x="5" y="8.5" width="1" height="1"></physics-box>`);
    const s = scene;
    const log: string[] = [];
    const name = (el: Element | null) => el?.id ?? 'null';
    const record = (kind: string) => (e: CustomEvent<PhysicsCollisionDetail>) => log.push(`${kind} ${[name(e.detail.a), name(e.detail.b)].sort().join(' ')}`);
    s.addEventListener('physics-collision', record('begin'));
    s.addEventListener('physics-collision-end', record('end'));
    const tally = (entry: string) => log.filter((l) => l === entry).length;
    // The box resting on the floor from the start begins at the first step (the events are asked for at the load).
    await s.step(1);
    expect(tally('begin floor rest')).to.equal(1);
    await stepUntil(s, () => tally('begin crate floor') >= 1 && tally('begin chest floor') >= 1, 'both boxes touching the floor');
    await s.step(30);
    // At rest on the floor now (a landing may hop): counts from here on.
    const since = (entry: string) => {
      const base = tally(entry);
      return () => tally(entry) - base;
    };
    const [crateEnds, chestEnds, chestBegins] = [since('end crate floor'), since('end chest floor'), since('begin chest floor')];
    // Removed: its pair ends in the next step's events, naming the element that left.
    s.querySelector('#crate')!.remove();
    await stepUntil(s, () => crateEnds() === 1, 'the removed crate\'s pair to end');
    // Rebuilt (a new size is a new engine body): its pair ends, and begins again as it still rests on the floor.
    s.querySelector('#chest')!.setAttribute('width', '1.2');
    await stepUntil(s, () => chestEnds() === 1 && chestBegins() === 1, 'the rebuilt chest to end and begin again');
    // A reset: every pair the page was told of ends at once, and begins again from the markup (the chest lands again).
    const [restEnds, restBegins] = [since('end floor rest'), since('begin floor rest')];
    await s.reset();
    expect(chestEnds()).to.equal(2);
    expect(restEnds()).to.equal(1);
    // The resting box touches the floor from the rebuilt world's first step: it begins again there.
    await s.step(1);
    expect(restBegins()).to.equal(1);
    await stepUntil(s, () => chestBegins() >= 2, 'the chest to land again after the reset');
    await s.step(30);
    // Begins and ends alternate per pair; nothing ends twice; the crate is not heard of again.
    for (const pair of ['chest floor', 'crate floor', 'floor rest']) {
      const seq = log.filter((l) => l.endsWith(pair)).map((l) => l.split(' ')[0]);
      seq.forEach((kind, k) => expect(kind, `${pair} event ${k}: ${seq.join(', ')}`).to.equal(k % 2 === 0 ? 'begin' : 'end'));
    }
    expect(crateEnds()).to.equal(1);
    expect(log.filter((l) => l.includes('null'))).to.deep.equal([]);
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
