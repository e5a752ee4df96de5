// physics-collision: detail names the two body elements, the normal and the depth; events cross the worker
// boundary only while someone listens.
import { expect } from '@open-wc/testing';
import type { PhysicsCollisionDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

describe('<physics-scene> collision events', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('fires physics-collision with the two body elements, the normal and the depth, only while listened to', async () => {
    scene = await mount('width="10" height="10" gravity="0 20"', `
      <physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
      <physics-box id="crate" x="5" y="6" width="1" height="1"></physics-box>`);
    const quiet = await scene.diagnostics();
    expect([quiet.events, quiet.eventsSent]).to.deep.equal([false, 0]);
    const seen: PhysicsCollisionDetail[] = [];
    const listener = (e: Event) => seen.push((e as CustomEvent<PhysicsCollisionDetail>).detail);
    scene.addEventListener('physics-collision', listener);
    expect((await scene.diagnostics()).events).to.equal(true);
    await waitFor(() => seen.length > 0, 'a collision');
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
});
