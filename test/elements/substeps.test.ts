// The scene's substeps attribute: "auto" by default (no attribute), which leaves the count to the engine (its rigid
// count while only rigid bodies move, its particle count when a cloth, rope or ragdoll moves, presets included); a
// whole number wins, live too; a bad value is reported like any bad attribute (physics-error and one console warning
// naming it) with auto in its place.
import { expect } from '@open-wc/testing';
import { AUTO_SUBSTEPS } from '../../src/engine/settings.js';
import type { PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { afterEachScene, mount, unmount, waitFor } from './helpers.js';

const RIGID = `<physics-box x="4" y="2" width="1" height="1" angle="15"></physics-box>
  <physics-circle x="8" y="1" radius="0.5"></physics-circle>
  <physics-box x="8" y="8.5" width="16" height="1" static></physics-box>`;
const CLOTH = '<physics-cloth x="2" y="1" columns="8" rows="6" spacing="0.4" pins="top"></physics-cloth>';

/** The substeps the engine takes now, and the choice the scene sent it. */
async function substepsOf(scene: PhysicsSceneElement): Promise<[number, number | 'auto']> {
  return [(await scene.diagnostics()).substepCount, (await scene.snapshot()).params.substeps];
}

/** Mounts `<tag attrs>` (a preset) and waits for it. */
async function mountPreset(tag: string): Promise<PhysicsSceneElement> {
  const box = document.createElement('div');
  box.style.cssText = 'width: 480px; height: 300px; position: relative;';
  // Test markup only: fixed strings written in the tests.
  box.innerHTML = `<${tag} paused style="width: 100%; height: 100%"></${tag}>`;
  document.body.append(box);
  const sim = box.firstElementChild as PhysicsSceneElement;
  await sim.ready;
  return sim;
}

describe('<physics-scene substeps>', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEachScene(() => scene);

  it('defaults to "auto": a fresh element says so, with no attribute', () => {
    const el = document.createElement('physics-scene');
    expect(el.substeps).to.equal('auto');
    expect(el.hasAttribute('substeps')).to.equal(false);
  });

  for (const worker of ['auto', 'none']) {
    it(`no attribute: the engine's rigid count for rigid bodies, its particle count with a cloth (worker="${worker}")`, async () => {
      scene = await mount(`paused worker="${worker}"`, RIGID);
      expect(await substepsOf(scene)).to.deep.equal([AUTO_SUBSTEPS.rigid, 'auto']);
      unmount(scene);
      scene = await mount(`paused worker="${worker}"`, RIGID + CLOTH);
      expect(await substepsOf(scene)).to.deep.equal([AUTO_SUBSTEPS.particles, 'auto']);
    });
  }

  it('the steps taken are the ones said: auto gives the state of substeps="<rigid count>", not of 10', async () => {
    const hashAfter = async (attrs: string): Promise<string> => {
      scene = await mount(`paused ${attrs}`, RIGID);
      await scene.step(40);
      const hash = await scene.stateHash();
      unmount(scene);
      scene = null;
      return hash;
    };
    const auto = await hashAfter('');
    expect(auto).to.equal(await hashAfter(`substeps="${AUTO_SUBSTEPS.rigid}"`));
    expect(auto).to.not.equal(await hashAfter('substeps="10"'));
  });

  it('a count wins, live too; "auto" and removing the attribute give the choice back to the engine', async () => {
    scene = await mount('paused substeps="3"', RIGID + CLOTH);
    expect(await substepsOf(scene)).to.deep.equal([3, 3]);
    const says = async (want: [number, number | 'auto'], what: string) => {
      await waitFor(async () => JSON.stringify(await substepsOf(scene!)) === JSON.stringify(want), what);
    };
    scene.setAttribute('substeps', 'auto');
    await says([AUTO_SUBSTEPS.particles, 'auto'], 'auto with a cloth');
    scene.setAttribute('substeps', '5');
    await says([5, 5], 'substeps="5"');
    scene.removeAttribute('substeps');
    await says([AUTO_SUBSTEPS.particles, 'auto'], 'auto once the attribute is gone');
    // The property takes a count or "auto" too.
    scene.substeps = 7;
    await says([7, 7], 'substeps = 7');
    scene.substeps = 'auto';
    await says([AUTO_SUBSTEPS.particles, 'auto'], "substeps = 'auto'");
    // Taking the cloth out leaves rigid bodies alone: the engine's rigid count.
    scene.querySelector('physics-cloth')!.remove();
    await says([AUTO_SUBSTEPS.rigid, 'auto'], 'the rigid count without the cloth');
  });

  for (const bad of ['x', '0', '2.5', '1001', '']) {
    it(`substeps="${bad}": a physics-error and one warning naming the attribute and the value; auto runs`, async () => {
      const warnings: string[] = [];
      console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
      const errors: PhysicsErrorDetail[] = [];
      scene = await mount(`paused substeps="${bad}"`, RIGID, {
        before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
      });
      expect(errors.map((e) => [e.element, e.attribute, e.value])).to.deep.equal([[scene, 'substeps', bad]]);
      expect(errors[0].message).to.contain('"auto" or a whole number from 1 to 1000');
      expect(warnings.filter((w) => w.includes(`substeps="${bad}"`))).to.have.length(1);
      expect(warnings).to.have.length(1);
      expect(await substepsOf(scene)).to.deep.equal([AUTO_SUBSTEPS.rigid, 'auto']);
    });
  }

  it('a bad value set live is reported once and auto runs; a good one then wins', async () => {
    const warnings: string[] = [];
    console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
    const errors: PhysicsErrorDetail[] = [];
    scene = await mount('paused substeps="4"', RIGID);
    scene.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail));
    scene.setAttribute('substeps', 'many');
    await waitFor(() => errors.length > 0, 'the error');
    await waitFor(async () => (await substepsOf(scene!))[0] === AUTO_SUBSTEPS.rigid, 'auto in place of "many"');
    expect(errors.map((e) => [e.attribute, e.value])).to.deep.equal([['substeps', 'many']]);
    expect(warnings.filter((w) => w.includes('substeps="many"'))).to.have.length(1);
    scene.setAttribute('substeps', '2');
    await waitFor(async () => (await substepsOf(scene!))[0] === 2, 'substeps="2"');
    expect(errors).to.have.length(1);
  });

  for (const tag of ['cloth-sim', 'ragdoll-sim']) {
    it(`<${tag}> runs at the engine's particle count`, async () => {
      scene = await mountPreset(tag);
      expect(await substepsOf(scene)).to.deep.equal([AUTO_SUBSTEPS.particles, 'auto']);
      await scene.step(10);
      expect((await scene.diagnostics()).stepCount).to.equal(10);
    });
  }
});
