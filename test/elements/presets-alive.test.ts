// The presets do not go still: with default attributes a <cloth-sim> sways in a gentle gusty breeze and a
// <ragdoll-sim> puts ragdolls that came to rest back at the top. Driven by step(n) on paused scenes (the presets'
// behaviour follows simulated time, not the page's clock), so what is asserted does not depend on the machine's speed.
import { expect } from '@open-wc/testing';
import type { ClothSimElement, PhysicsSceneElement, RagdollSimElement } from '../../src/index.js';
import { drawn, unmount } from './helpers.js';

/** Mounts `<tag paused attrs>` in a 480 × 300 container and waits for `ready`. */
async function mountPaused<T extends PhysicsSceneElement>(tag: string, attrs = ''): Promise<T> {
  const box = document.createElement('div');
  box.style.cssText = 'width: 480px; height: 300px; position: relative;';
  // Test markup only: fixed strings written in the tests.
  box.innerHTML = `<${tag} paused ${attrs} style="width: 100%; height: 100%"></${tag}>`;
  document.body.append(box);
  const sim = box.firstElementChild as T;
  await sim.ready;
  return sim;
}

/** The canvas's pixels once it shows the newest step. */
async function pixels(sim: PhysicsSceneElement): Promise<Uint8ClampedArray> {
  await drawn(sim, 2);
  const canvas = sim.canvas!;
  return canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
}

/** Pixels whose colour differs by more than 8 in a channel. */
function changed(a: Uint8ClampedArray, b: Uint8ClampedArray): number {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) > 8 || Math.abs(a[i + 1] - b[i + 1]) > 8 || Math.abs(a[i + 2] - b[i + 2]) > 8) n++;
  }
  return n;
}

/** Canvas pixels that change between simulated second 10 and 10 + `later` seconds. */
async function changeAfterTenSeconds(sim: PhysicsSceneElement, later: number): Promise<number> {
  await sim.step(600);
  const at10 = await pixels(sim);
  await sim.step(Math.round(later * 60));
  return changed(at10, await pixels(sim));
}

describe('presets stay alive with default attributes', () => {
  let sim: PhysicsSceneElement | null = null;
  afterEach(() => unmount(sim));

  it('<cloth-sim>: a gentle breeze by default, the cloth still sways after 10 s; pinned along the top in still air it hangs still', async () => {
    const counts: Record<string, number> = {};
    for (const attrs of ['', 'pins="top"', 'pins="top" wind="0"']) {
      const cloth = await mountPaused<ClothSimElement>('cloth-sim', attrs);
      sim = cloth;
      if (attrs === '') expect(cloth.wind).to.equal(1.5);
      counts[attrs || 'default'] = await changeAfterTenSeconds(cloth, 0.5);
      unmount(cloth);
    }
    console.log(`cloth: pixels changed from 10 s to 10.5 s: ${JSON.stringify(counts)}`);
    expect(counts.default).to.be.above(2000);
    expect(counts['pins="top"']).to.be.above(2000);
    expect(counts['pins="top" wind="0"']).to.be.below(100);
  });

  it('<ragdoll-sim>: ragdolls that come to rest are put back at the top by default, so it still moves after 10 s; respawn="off" goes still', async () => {
    const dolls = await mountPaused<RagdollSimElement>('ragdoll-sim');
    sim = dolls;
    expect(dolls.respawn).to.equal(true);
    const alive = await changeAfterTenSeconds(dolls, 2);
    const respawned = dolls.respawned;
    unmount(dolls);
    const off = await mountPaused<RagdollSimElement>('ragdoll-sim', 'respawn="off"');
    sim = off;
    expect(off.respawn).to.equal(false);
    const still = await changeAfterTenSeconds(off, 2);
    console.log(`ragdolls: ${alive} pixels changed from 10 s to 12 s with ${respawned} respawns, ${still} with respawn="off" (${off.respawned} respawns)`);
    expect(respawned).to.be.at.least(1);
    expect(alive).to.be.above(500);
    expect(off.respawned).to.equal(0);
    expect(still).to.be.below(alive / 10);
  });

  it('the presets act on simulated time: the same steps give the same state, however they are split', async () => {
    for (const [tag, steps] of [['cloth-sim', 200], ['ragdoll-sim', 420]] as const) {
      const a = await mountPaused<PhysicsSceneElement>(tag);
      await a.step(steps);
      const whole = await a.stateHash();
      unmount(a);
      const b = await mountPaused<PhysicsSceneElement>(tag);
      sim = b;
      for (let taken = 0; taken < steps; taken += 7) await b.step(Math.min(7, steps - taken));
      expect(b.stepCount).to.equal(steps);
      expect(await b.stateHash(), `${tag}: ${steps} steps at once and 7 at a time`).to.equal(whole);
      if (tag === 'ragdoll-sim') expect((b as RagdollSimElement).respawned, 'respawns on the way').to.be.at.least(1);
      unmount(b);
    }
  });

  it('respawn is on without the attribute and with any value but "off" or "false"', () => {
    const el = document.createElement('ragdoll-sim');
    expect(el.respawn).to.equal(true);
    for (const [value, on] of [['', true], ['on', true], ['off', false], ['sometimes', true], ['FALSE', false], [null, true]] as const) {
      if (value === null) el.removeAttribute('respawn');
      else el.setAttribute('respawn', value);
      expect(el.respawn, `respawn=${JSON.stringify(value)}`).to.equal(on);
    }
  });
});
