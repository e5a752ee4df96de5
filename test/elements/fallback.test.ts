// Fallback content: what a page writes inside the tag for readers without the simulation (slot="fallback" elements,
// and text) shows until the scene is ready and is hidden after; body elements are never shown; the loading message
// stays out of the way of fallback content. (With the script missing altogether, test/e2e/loading.mjs.)
import { expect } from '@open-wc/testing';
import type { PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

const shown = (el: Element) => el.getClientRects().length > 0;
const status = (scene: PhysicsSceneElement) => scene.shadowRoot!.querySelector('.status');

describe('<physics-scene> fallback content', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(() => unmount(scene));

  it('a slot="fallback" element shows until the scene is ready, then hides; body elements never show', async () => {
    scene = await mount(
      '',
      `<p slot="fallback" id="still">A crate falls onto a floor.</p><physics-box id="crate" x="8" y="2" width="1" height="1"></physics-box>`,
      { ready: false },
    );
    await scene.updateComplete;
    const still = scene.querySelector('#still')!;
    const crate = scene.querySelector('#crate')!;
    expect([shown(still), shown(crate), status(scene)]).to.deep.equal([true, false, null]);
    // Laid out inside the element's box, at its top.
    expect(still.getBoundingClientRect().top).to.be.within(scene.getBoundingClientRect().top, scene.getBoundingClientRect().top + 20);
    await scene.ready;
    await waitFor(() => !shown(still), 'the fallback hidden');
    expect(shown(crate)).to.equal(false);
    expect(scene.shadowRoot!.querySelector<HTMLElement>('.fallback')!.hidden).to.equal(true);
  });

  it('the fallback does not blink out between the element\'s upgrade and its first render', async () => {
    const page = document.createElement('div');
    document.body.append(page);
    // The script arrives after the markup: the tag upgrades with its shadow root, and renders a task later.
    page.innerHTML = '<physics-scene style="display:block;aspect-ratio:16/9"><img slot="fallback" alt="A still" width="40" height="30"> A cloth in the wind.</physics-scene>';
    scene = page.querySelector('physics-scene')!;
    const img = scene.querySelector('img')!;
    expect([scene.shadowRoot !== null, scene.hasUpdated]).to.deep.equal([true, false]);
    expect(shown(img)).to.equal(true);
    const text = document.createRange();
    text.selectNodeContents(scene.lastChild!);
    expect(text.getClientRects().length).to.be.above(0);
    await scene.updateComplete;
    expect([shown(img), scene.shadowRoot!.querySelectorAll('.fallback').length]).to.deep.equal([true, 1]);
    await scene.ready;
    await waitFor(() => !shown(img), 'the fallback hidden');
  });

  it('text inside the tag is fallback too; without any, the loading message shows', async () => {
    scene = await mount('', 'A cloth in the wind. <physics-circle x="3" y="3" radius="1"></physics-circle>', { ready: false });
    await scene.updateComplete;
    const box = scene.shadowRoot!.querySelector<HTMLElement>('.fallback')!;
    expect([box.hidden, box.getBoundingClientRect().height > 0, status(scene)]).to.deep.equal([false, true, null]);
    await scene.ready;
    await waitFor(() => box.hidden === true, 'the fallback hidden');
    unmount(scene);
    scene = await mount('', '  <physics-circle x="3" y="3" radius="1"></physics-circle>  ', { ready: false });
    await scene.updateComplete;
    expect(status(scene)?.textContent).to.equal('Loading simulation…');
  });

  it('a scene that stops and starts again shows its fallback until it is ready again', async () => {
    scene = await mount('', '<img slot="fallback" alt="A still of the scene" width="40" height="30">');
    const img = scene.querySelector('img')!;
    await waitFor(() => !shown(img), 'the fallback hidden');
    const box = scene.parentElement!;
    scene.remove();
    // A task later the scene has stopped (a move within one task would keep it running).
    await new Promise((r) => setTimeout(r, 0));
    box.append(scene);
    await scene.updateComplete;
    expect(shown(img)).to.equal(true);
    await scene.ready;
    await waitFor(() => !shown(img), 'the fallback hidden again');
  });
});
