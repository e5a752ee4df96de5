// snapshot() and restore() on the element: a snapshot of this scene round-trips (also through structuredClone); one
// of another scene, one taken before the markup changed, a JSON copy or anything else is refused with a TypeError or
// RangeError and leaves the simulation as it was.
import { expect } from '@open-wc/testing';
import type { PhysicsSceneElement, RagdollSimElement } from '../../src/index.js';
import type { HostSnapshot } from '../../src/worker/protocol.js';
import { mount, unmount } from './helpers.js';

const S = `<physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
  <physics-circle id="c" x="5" y="2" radius="0.5" fill="red"></physics-circle>`;
const T = `<physics-box x="2" y="2" width="1" height="1"></physics-box>
  <physics-cloth x="4" y="1" columns="4" rows="3"></physics-cloth>
  <physics-softbody x="8" y="3" radius="0.8"></physics-softbody>`;

async function refusal(scene: PhysicsSceneElement, snapshot: unknown): Promise<Error> {
  const error = await scene.restore(snapshot as HostSnapshot).then(() => null, (e: Error) => e);
  expect(error, 'restore() rejects').to.be.instanceOf(Error);
  return error!;
}

describe('<physics-scene> snapshot() and restore()', () => {
  let s: PhysicsSceneElement | null = null;
  let t: PhysicsSceneElement | null = null;
  afterEach(() => {
    unmount(s);
    unmount(t);
    s = t = null;
  });

  it('refuses another scene\'s snapshot, a JSON copy and what is not a snapshot, leaving the scene as it was', async () => {
    s = await mount('width="10" height="10" paused', S);
    t = await mount('width="10" height="10" paused', T);
    await s.step(10);
    const hash = await s.stateHash();
    const circle = s.querySelector<HTMLElement & { y: number }>('#c')!;
    const y = circle.y;

    const other = await refusal(s, await t.snapshot());
    expect(other).to.be.instanceOf(RangeError);
    expect(other.message).to.include("snapshot of this scene").and.include('another scene');

    const own = await s.snapshot();
    const json = await refusal(s, JSON.parse(JSON.stringify(own)));
    // Refused in the worker (the engine's TypeError): the same class on the page, not a plain Error named after it.
    expect(json).to.be.instanceOf(TypeError);
    expect(json.message).to.include('structuredClone');

    for (const bad of [null, undefined, 42, { foo: 1 }]) {
      const e = await refusal(s, bad);
      expect(e, String(bad)).to.be.instanceOf(TypeError);
      expect(e.message).to.include('restore() takes an object snapshot() gave');
    }
    expect(await s.stateHash()).to.equal(hash);
    expect(circle.y).to.equal(y);
    // Still its own simulation: it steps on, the circle falls.
    await s.step(30);
    expect(circle.y).to.be.above(y);
  });

  it('a <ragdoll-sim> restores its snapshot after its dolls respawned (its own behaviour changed its bodies, not the page)', async () => {
    const box = document.createElement('div');
    box.style.cssText = 'width: 480px; height: 300px; position: relative;';
    const dolls = document.createElement('ragdoll-sim') as RagdollSimElement;
    dolls.setAttribute('paused', '');
    dolls.style.cssText = 'width: 100%; height: 100%';
    box.append(dolls);
    document.body.append(box);
    s = dolls;
    await dolls.ready;
    const snap = await dolls.snapshot();
    const hash = await dolls.stateHash();
    for (let k = 0; k < 40 && dolls.respawned === 0; k++) await dolls.step(60);
    expect(dolls.respawned, 'a respawn within 40 s').to.be.at.least(1);
    await dolls.restore(snap);
    expect(await dolls.stateHash()).to.equal(hash);
  });

  it('round-trips its own snapshot, also through structuredClone; a markup change since refuses it until undone', async () => {
    s = await mount('width="10" height="10" paused', S);
    await s.step(20);
    const snap = await s.snapshot();
    const hash = await s.stateHash();
    const circle = s.querySelector<HTMLElement & { y: number }>('#c')!;
    const y = circle.y;
    await s.step(20);
    await s.restore(structuredClone(snap));
    expect(await s.stateHash()).to.equal(hash);
    expect(circle.y).to.be.closeTo(y, 1e-9);
    // A colour is drawing, not simulation: still the same scene.
    circle.setAttribute('fill', 'blue');
    await s.restore(snap);
    // A size is not: the snapshot holds the old circle.
    circle.setAttribute('radius', '0.7');
    await s.step(1);
    const changed = await refusal(s, snap);
    expect(changed.name).to.equal('RangeError');
    expect(changed.message).to.include('before the markup changed');
    circle.setAttribute('radius', '0.5');
    await s.step(1);
    await s.restore(snap);
    expect(await s.stateHash()).to.equal(hash);
  });
});
