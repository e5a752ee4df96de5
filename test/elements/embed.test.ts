// Embedding behaviour of every element: steps only on screen and with the page visible, reduced motion starts paused
// with a play control, keyboard, ARIA, loading and error states, sizing, and use from other components and frameworks.
import { expect } from '@open-wc/testing';
import { emulateMedia, sendKeys } from './commands.js';
import { ClothSimElement, type PhysicsBoxElement, type PhysicsErrorDetail, type PhysicsSceneElement } from '../../src/index.js';
import { drawn, frames, mount, unmount, waitFor } from './helpers.js';

const part = (el: Element, name: string) => el.shadowRoot!.querySelector<HTMLElement>(`[part="${name}"]`);
const shown = (el: HTMLElement | null) => !!el && el.getBoundingClientRect().height > 0;

/**
 * Asserts that the engine takes no step over 20 animation frames, nor (off screen, hidden page) does the renderer draw.
 * A still scene draws nothing either: the renderer redraws only when something changes (a step() while paused shows
 * at once; the idle tests cover that).
 */
async function expectStill(scene: PhysicsSceneElement): Promise<void> {
  await waitFor(async () => !(await scene.diagnostics()).running, 'the engine to stop');
  // p5 draws once more from the animation frame it had already asked for.
  await frames(2);
  const steps = scene.stepCount;
  const drawnFrames = scene.renderedFrames;
  await frames(20);
  expect(scene.stepCount, 'steps').to.equal(steps);
  expect(scene.renderedFrames, 'drawn frames').to.equal(drawnFrames);
  expect((await scene.diagnostics()).stepCount).to.equal(steps);
}

/**
 * The scene steps and its canvas keeps up: it draws again (a moving scene) or shows the newest state (a still one).
 * drawn() alone is not enough for a moving scene: with frames arriving every animation frame and blended, it is almost
 * never "showing the newest state" at the moment a test's frame callback looks (the breezy cloth in a shadow root
 * timed out after 15 s in one CI run).
 */
async function expectSteps(scene: PhysicsSceneElement): Promise<void> {
  const steps = scene.stepCount;
  await waitFor(() => scene.stepCount > steps + 5, 'the scene to step again');
  await frames(3);
  const drawings = scene.renderedFrames;
  await waitFor(() => scene.renderedFrames > drawings + 2 || !scene.drawPending, 'the canvas to draw again or show the newest state');
}

describe('embedding', () => {
  let scene: PhysicsSceneElement | null = null;
  const spacers: HTMLElement[] = [];
  /** A block `width` px wide holding `html` (test markup), in the page until the test ends. */
  const pageOf = (width: number, html: string): HTMLElement => {
    const page = document.createElement('div');
    page.style.width = `${width}px`;
    page.innerHTML = html;
    spacers.push(page);
    document.body.append(page);
    return page;
  };
  afterEach(async () => {
    unmount(scene);
    scene = null;
    for (const s of spacers.splice(0)) s.remove();
    window.scrollTo(0, 0);
    await emulateMedia({ reducedMotion: 'no-preference' });
  });

  it('is focusable with a role and a label; the page can override them', async () => {
    scene = await mount('', '');
    expect(scene.tabIndex).to.equal(0);
    expect(scene.getAttribute('role')).to.equal('group');
    expect(scene.getAttribute('aria-label')).to.equal('Physics simulation');
    expect(scene.getAttribute('aria-keyshortcuts')).to.equal('Space R');
    unmount(scene);
    scene = await mount('role="img" aria-label="Crates falling" tabindex="-1"', '');
    expect(scene.getAttribute('role')).to.equal('img');
    expect(scene.getAttribute('aria-label')).to.equal('Crates falling');
    expect(scene.tabIndex).to.equal(-1);
    const cloth = document.createElement('cloth-sim');
    document.body.append(cloth);
    expect(cloth.getAttribute('aria-label')).to.match(/^Cloth simulation/);
    cloth.remove();
  });

  it('Space toggles pause when focused; the play control appears and plays', async () => {
    scene = await mount('', '<physics-box x="8" y="2" width="1" height="1"></physics-box>');
    scene.focus();
    await expectSteps(scene);
    await sendKeys({ press: 'Space' });
    expect(scene.paused).to.equal(true);
    await expectStill(scene);
    await scene.updateComplete;
    expect(shown(part(scene, 'play-button'))).to.equal(true);
    await sendKeys({ press: 'Space' });
    expect(scene.paused).to.equal(false);
    await expectSteps(scene);
    await scene.updateComplete;
    expect(part(scene, 'play-button')).to.equal(null);
    // The page does not scroll: Space was taken.
    expect(window.scrollY).to.equal(0);
    // The play control works with the pointer too.
    await sendKeys({ press: 'Space' });
    await scene.updateComplete;
    part(scene, 'play-button')!.click();
    expect(scene.paused).to.equal(false);
  });

  it('prefers-reduced-motion: starts paused with a visible play control; play() runs it', async () => {
    await emulateMedia({ reducedMotion: 'reduce' });
    scene = await mount('', '<physics-box x="8" y="2" width="1" height="1"></physics-box>');
    expect(scene.paused).to.equal(true);
    await drawn(scene, 3);
    expect(scene.stepCount).to.equal(0);
    const button = part(scene, 'play-button')!;
    expect(shown(button)).to.equal(true);
    expect(button.getAttribute('aria-label')).to.equal('Play the simulation');
    button.click();
    await expectSteps(scene);
    // A page that calls play() before the element connects is not overridden.
    const other = document.createElement('physics-scene');
    other.play();
    document.body.append(other);
    expect(other.paused).to.equal(false);
    other.remove();
  });

  it('scrolled out of view: no steps and no frames; scrolled back: runs again', async () => {
    scene = await mount('', '<physics-box x="8" y="-50" width="1" height="1"></physics-box>');
    const spacer = document.createElement('div');
    spacer.style.height = '3000px';
    document.body.append(spacer);
    spacers.push(spacer);
    await expectSteps(scene);
    window.scrollTo(0, 2000);
    await waitFor(() => !scene!.onScreen, 'the scene to be off screen');
    await expectStill(scene);
    window.scrollTo(0, 0);
    await waitFor(() => scene!.onScreen, 'the scene on screen again');
    await expectSteps(scene);
  });

  it('a hidden page pauses; a visible page resumes', async () => {
    scene = await mount('', '<physics-box x="8" y="-50" width="1" height="1"></physics-box>');
    await expectSteps(scene);
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
    try {
      document.dispatchEvent(new Event('visibilitychange'));
      expect(scene.running).to.equal(false);
      await expectStill(scene);
    } finally {
      delete (document as unknown as Record<string, unknown>).visibilityState;
    }
    document.dispatchEvent(new Event('visibilitychange'));
    await expectSteps(scene);
  });

  it('shows a loading state until the engine runs, and an error state for bad attributes', async () => {
    const warn = console.warn;
    console.warn = () => {};
    try {
      scene = await mount('gravity="down"', '<physics-box x="8" y="2" width="1" height="abc"></physics-box>', { ready: false });
      await scene.updateComplete;
      expect(shown(part(scene, 'status'))).to.equal(true);
      expect(part(scene, 'status')!.textContent).to.contain('Loading');
      await scene.ready;
      await scene.updateComplete;
      expect(part(scene, 'status')).to.equal(null);
      const box = part(scene, 'error')!;
      expect(shown(box)).to.equal(true);
      expect(box.getAttribute('role')).to.equal('alert');
      expect(box.textContent).to.contain('<physics-scene> gravity="down"');
      expect(box.textContent).to.contain('<physics-box> height="abc"');
      // Fixed markup clears it, one problem at a time.
      scene.gravity = '0 9.81';
      await waitFor(() => !box.textContent!.includes('gravity'), 'the gravity line to go');
      expect(shown(box)).to.equal(true);
      scene.querySelector('physics-box')!.setAttribute('height', '1');
      await waitFor(() => !shown(box), 'the error box to go');
    } finally {
      console.warn = warn;
    }
  });

  it('sizes its canvas when created hidden and when its container resizes', async () => {
    scene = await mount('hidden', '<physics-box x="8" y="2" width="1" height="1"></physics-box>');
    expect(scene.getBoundingClientRect().width).to.equal(0);
    scene.hidden = false;
    await waitFor(() => scene!.canvas?.getBoundingClientRect().width === 400, 'a 400 px canvas once shown');
    const ratio = window.devicePixelRatio;
    expect(scene.canvas!.width).to.equal(Math.round(400 * ratio));
    expect(scene.canvas!.getBoundingClientRect().height).to.equal(400);
    await expectSteps(scene);
    scene.parentElement!.style.width = '240px';
    scene.parentElement!.style.height = '135px';
    await waitFor(() => scene!.canvas!.getBoundingClientRect().width === 240, 'a 240 px canvas');
    expect(scene.canvas!.getBoundingClientRect().height).to.equal(135);
    expect(scene.canvas!.width).to.equal(Math.round(240 * ratio));
  });

  it('has a width where the layout sizes it by its content (flex row, inline-block, float), and fills a block', async () => {
    // A CMS puts an embed beside a label or in a shrink-to-fit box: it takes 300 px there, as a canvas or a video would,
    // keeping its aspect ratio (it was 0 × 0: nothing on the page); in a plain block it still fills the container.
    const page = pageOf(
      640,
      '<div style="display:flex"><span>label</span><cloth-sim></cloth-sim></div>' +
        '<span style="display:inline-block"><cloth-sim></cloth-sim></span>' +
        '<div style="float:left"><physics-scene width="12" height="9"></physics-scene></div><div style="clear:both"></div>' +
        '<div style="display:flex;width:200px"><span>label</span><cloth-sim></cloth-sim></div>' +
        '<cloth-sim></cloth-sim>',
    );
    const [row, inline, float, narrow, block] = page.querySelectorAll<PhysicsSceneElement>('cloth-sim, physics-scene');
    await Promise.all([row, inline, float, narrow, block].map((el) => el.updateComplete));
    const size = (el: Element) => {
      const r = el.getBoundingClientRect();
      return [Math.round(r.width), Math.round(r.height)];
    };
    expect(size(row), 'in a flex row').to.deep.equal([300, 188]);
    expect(size(inline), 'in an inline-block').to.deep.equal([300, 188]);
    expect(size(float), 'in a float').to.deep.equal([300, 225]);
    // A row narrower than label + 300 px shrinks the embed, not past the row.
    const label = narrow.previousElementSibling!.getBoundingClientRect().width;
    expect(size(narrow)[0], 'in a narrow flex row').to.equal(Math.round(200 - label));
    expect(size(block), 'in a block').to.deep.equal([640, 400]);
    await block.ready;
    await waitFor(() => block.canvas?.getBoundingClientRect().width === 640, 'the block embed\'s canvas at 640 px');
    await row.ready;
    await waitFor(() => row.canvas?.getBoundingClientRect().width === 300, 'the flex-row embed\'s canvas at 300 px');
    for (const el of [row, inline, float, narrow, block]) el.remove();
  });

  it('--physics-scene-aspect overrides the ratio of the view: on the element, from a stylesheet, or from an ancestor', async () => {
    const sheet = document.createElement('style');
    sheet.textContent = '.wide-embed { --physics-scene-aspect: 3 / 1; }';
    document.head.append(sheet);
    spacers.push(sheet);
    const page = pageOf(
      600,
      '<physics-scene width="12" height="9"></physics-scene>' +
        '<physics-scene width="12" height="9" style="--physics-scene-aspect: 2 / 1"></physics-scene>' +
        '<physics-scene class="wide-embed" width="12" height="9"></physics-scene>' +
        '<div style="--physics-scene-aspect: 1 / 1"><cloth-sim></cloth-sim></div>',
    );
    const [own, inline, styled, inherited] = page.querySelectorAll<PhysicsSceneElement>('physics-scene, cloth-sim');
    await Promise.all([own, inline, styled, inherited].map((el) => el.updateComplete));
    const height = (el: Element) => Math.round(el.getBoundingClientRect().height);
    expect(height(own), 'the view\'s own 12 / 9').to.equal(450);
    expect(height(inline), 'inline 2 / 1').to.equal(300);
    expect(height(styled), 'a stylesheet\'s 3 / 1').to.equal(200);
    expect(height(inherited), 'an ancestor\'s 1 / 1').to.equal(600);
    expect(inline.getAttribute('style'), 'the page\'s inline style kept').to.contain('--physics-scene-aspect: 2 / 1');
  });
});

/** A component that renders its own <cloth-sim> in its shadow root, as a framework component would. */
class HostComponent extends HTMLElement {
  sim: ClothSimElement;
  scene: PhysicsSceneElement;
  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.innerHTML =
      '<div style="width: 400px; height: 250px"><cloth-sim style="width: 100%; height: 100%"></cloth-sim></div>' +
      '<physics-scene style="width: 400px; height: 225px"><physics-box x="8" y="2" width="1" height="1"></physics-box></physics-scene>';
    this.sim = root.querySelector('cloth-sim')!;
    this.scene = root.querySelector('physics-scene')!;
  }
}
if (!customElements.get('x-embed-host')) customElements.define('x-embed-host', HostComponent);

describe('inside other components and frameworks', () => {
  const made: Element[] = [];
  afterEach(() => {
    for (const el of made.splice(0)) el.remove();
  });

  it("inside another component's shadow root: runs, draws, sends composed events, stops off screen", async () => {
    const host = document.createElement('x-embed-host') as HostComponent;
    const errors: PhysicsErrorDetail[] = [];
    const listener = (e: Event) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail);
    document.addEventListener('physics-error', listener);
    const warn = console.warn;
    console.warn = () => {};
    try {
      host.sim.setAttribute('rows', 'many');
      document.body.append(host);
      made.push(host);
      const sim = host.sim;
      await sim.ready;
      expect((await sim.diagnostics()).particleCount).to.equal(24 * 16);
      expect(errors.map((e) => [e.element, e.attribute, e.value])).to.deep.equal([[sim, 'rows', 'many']]);
      await expectSteps(sim);
      expect(sim.canvas!.getBoundingClientRect().width).to.equal(400);
      // A <physics-scene> with light-DOM children in the same shadow root: its box falls, and a child added later joins.
      await host.scene.ready;
      const crate = host.scene.querySelector<PhysicsBoxElement>('physics-box')!;
      await waitFor(() => crate.y > 3, 'the box in the shadow-root scene to fall');
      host.scene.append(Object.assign(document.createElement('physics-circle'), { radius: 0.5 }));
      await waitFor(async () => (await host.scene.diagnostics()).bodyCount === 2, 'the added circle');
      const spacer = document.createElement('div');
      spacer.style.height = '3000px';
      document.body.append(spacer);
      made.push(spacer);
      window.scrollTo(0, 2000);
      await waitFor(() => !sim.onScreen, 'off screen');
      await expectStill(sim);
      window.scrollTo(0, 0);
      await expectSteps(sim);
    } finally {
      console.warn = warn;
      document.removeEventListener('physics-error', listener);
      window.scrollTo(0, 0);
    }
  });

  it('properties set before upgrade (React 19, Vue) and after behave like attributes', async () => {
    // Elements made in a template's inert document are not upgraded: their properties are plain own properties.
    const template = document.createElement('template');
    template.innerHTML = '<div style="width: 400px; height: 250px"><cloth-sim></cloth-sim><physics-scene style="width: 400px; height: 200px"><physics-box></physics-box></physics-scene></div>';
    const box = template.content.firstElementChild as HTMLElement;
    const sim = box.querySelector('cloth-sim')! as unknown as Record<string, unknown>;
    const scene = box.querySelector('physics-scene')! as unknown as Record<string, unknown>;
    const crate = box.querySelector('physics-box')! as unknown as Record<string, unknown>;
    expect(sim instanceof ClothSimElement).to.equal(false);
    sim.columns = 6;
    sim.rows = 4;
    sim.fill = '#ff0000';
    scene.gravity = '0 0';
    scene.paused = true;
    crate.x = 5;
    crate.y = 3;
    crate.width = 2;
    crate.height = 1;
    document.body.append(box);
    made.push(box);
    const simEl = box.querySelector('cloth-sim')!;
    const sceneEl = box.querySelector('physics-scene')!;
    expect(simEl).to.be.instanceOf(ClothSimElement);
    await Promise.all([simEl.ready, sceneEl.ready]);
    expect((await simEl.diagnostics()).particleCount).to.equal(24);
    expect(simEl.shadowRoot!.querySelector('physics-cloth')!.getAttribute('fill')).to.equal('#ff0000');
    expect(sceneEl.paused).to.equal(true);
    const crateEl = sceneEl.querySelector<PhysicsBoxElement>('physics-box')!;
    expect([crateEl.x, crateEl.y]).to.deep.equal([5, 3]);
    // After upgrade, properties update the running scenes.
    simEl.rows = 5;
    await waitFor(async () => (await simEl.diagnostics()).particleCount === 30, '6 × 5 particles');
    sceneEl.paused = false;
    sceneEl.gravity = '0 10';
    await waitFor(() => crateEl.y > 3.5, 'the crate to fall once gravity is set and the scene plays');
  });
});
