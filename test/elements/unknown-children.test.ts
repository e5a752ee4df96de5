// Children of a scene that are not bodies or links (a typo such as <physics-boxx>, a tag that does not exist such as
// <physics-triangle>, a <div>) are reported: a physics-error on the child, one console warning naming its tag and the
// closest known tag, a line in the error box. Text, comments, templates, scripts and styles are not mistakes; nor is
// what a CMS or a Markdown processor does to the lines inside a scene: WordPress's automatic paragraphs (wpautop, the
// classic editor) put a <br> after each line; Markdown ends raw HTML at a blank line and wraps the lines after it in a
// <p>, whose bodies are the scene's. A <p> of text, which holds no body, is still reported.
import { expect } from '@open-wc/testing';
import * as api from '../../src/index.js';
import type { PhysicsCircleElement, PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { BODY_TAGS, LINK_TAGS, unknownChildMessage } from '../../src/elements/physics-scene/markup.js';
import { mount, unmount, waitFor } from './helpers.js';

const BOX = '<physics-box x="6" y="8.6" width="12" height="0.8" static></physics-box>';
const BALL = '<physics-circle id="ball" x="3.6" y="0.5" radius="0.5"></physics-circle>';
const ROPE = '<physics-rope x1="1" y1="2" x2="6.5" y2="2" segments="12" pin="both"></physics-rope>';

/** Mounts a scene with `children`, recording its physics-error details and the console's warnings from the start. */
async function mountRecording(children: string): Promise<{ scene: PhysicsSceneElement; errors: PhysicsErrorDetail[]; warnings: string[] }> {
  const errors: PhysicsErrorDetail[] = [];
  const scene = await mount('paused', children, {
    before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
  });
  return { scene, errors, warnings };
}

const errorBox = (scene: PhysicsSceneElement) => scene.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!;

let warnings: string[] = [];
const warn = console.warn;

describe('unknown children of a scene', () => {
  let scene: PhysicsSceneElement | null = null;
  beforeEach(() => {
    warnings = [];
    console.warn = (...args: unknown[]) => warnings.push(args.join(' '));
  });
  afterEach(() => {
    console.warn = warn;
    unmount(scene);
  });

  it('a typo, a tag that does not exist and a <div> are each reported once; text, comments, template, script and style are not', async () => {
    const rec = await mountRecording(`
      text between the tags
      <!-- a comment -->
      <physics-box x="8" y="4" width="1" height="1"></physics-box>
      <physics-boxx x="4" y="4" width="1" height="1"></physics-boxx>
      <physics-triangle id="tri" x="10" y="4"></physics-triangle>
      <div>a div</div>
      <template><physics-box></physics-box></template>
      <script type="text/plain">not run</script>
      <style>p { color: red }</style>`);
    scene = rec.scene;
    expect((await scene.diagnostics()).bodyCount, 'only the <physics-box> is simulated').to.equal(1);
    const tags = ['physics-boxx', 'physics-triangle', 'div'];
    expect(rec.errors.map((e) => [e.element.localName, e.attribute, e.value])).to.deep.equal(tags.map((t) => [t, '', t]));
    expect(warnings.length, warnings.join('\n')).to.equal(3);
    expect(warnings[0]).to.contain('<physics-boxx>').and.contain('did you mean <physics-box>?');
    expect(warnings[1]).to.contain('<physics-triangle id="tri">: unknown element, ignored: did you mean <physics-polygon>?');
    expect(warnings[2]).to.contain('<div>').and.contain('the scene ignores it');
    expect(errorBox(scene).textContent!.split('\n')).to.have.length(3);

    // Nothing is reported again while they stay, whatever else changes.
    scene.querySelector('physics-box')!.setAttribute('x', '7');
    scene.append(document.createElement('physics-circle'));
    await waitFor(async () => (await scene!.diagnostics()).bodyCount === 2, 'the new circle');
    expect(warnings.length).to.equal(3);
    expect(rec.errors.length).to.equal(3);
  });

  it('children added later are checked too; removed, they leave the error box', async () => {
    const rec = await mountRecording('<physics-box x="8" y="4" width="1" height="1"></physics-box>');
    scene = rec.scene;
    expect(rec.errors).to.deep.equal([]);
    expect(errorBox(scene).hidden).to.equal(true);
    const typo = document.createElement('physics-cirlce');
    scene.append(typo);
    await waitFor(() => rec.errors.length === 1, 'a physics-error for <physics-cirlce>');
    expect(rec.errors[0].element).to.equal(typo);
    expect(warnings).to.have.length(1);
    expect(warnings[0]).to.contain('<physics-cirlce>').and.contain('did you mean <physics-circle>?');
    expect(errorBox(scene).hidden).to.equal(false);
    typo.remove();
    await waitFor(() => errorBox(scene!).hidden === true, 'the error box to empty');
    expect(rec.errors).to.have.length(1);
  });

  it('content the page shows instead of the scene (an image, <noscript>, anything with a slot) is not a mistake', async () => {
    const rec = await mountRecording('<img alt="a cloth" width="1" height="1"><noscript>no script</noscript><p slot="fallback">Loading…</p><physics-box x="8" y="4" width="1" height="1"></physics-box>');
    scene = rec.scene;
    expect(rec.errors).to.deep.equal([]);
    expect(warnings).to.deep.equal([]);
  });

  it('the closest known tag: physics-* tags always get one, others only when close; elements that are not bodies are ignored', () => {
    expect(unknownChildMessage('physics-boxx')).to.equal('unknown element, ignored: did you mean <physics-box>?');
    expect(unknownChildMessage('physics-soft-body')).to.equal('unknown element, ignored: did you mean <physics-softbody>?');
    expect(unknownChildMessage('physics-spirng')).to.equal('unknown element, ignored: did you mean <physics-spring>?');
    expect(unknownChildMessage('circle')).to.equal('unknown element, ignored: did you mean <physics-circle>?');
    expect(unknownChildMessage('rope')).to.equal('unknown element, ignored: did you mean <physics-rope>?');
    // Another word for a known body or link: its tag, though another is nearer by spelling (ball → box).
    expect(unknownChildMessage('physics-ball')).to.equal('unknown element, ignored: did you mean <physics-circle>?');
    expect(unknownChildMessage('physics-triangle')).to.equal('unknown element, ignored: did you mean <physics-polygon>?');
    expect(unknownChildMessage('physics-chain')).to.equal('unknown element, ignored: did you mean <physics-rope>?');
    expect(unknownChildMessage('physics-hinge')).to.equal('unknown element, ignored: did you mean <physics-joint>?');
    expect(unknownChildMessage('rect')).to.equal('unknown element, ignored: did you mean <physics-box>?');
    // A far guess by spelling comes with the whole list.
    expect(unknownChildMessage('physics-lamp')).to.match(/^unknown element, ignored: did you mean <physics-\w+>\? \(bodies are <physics-box>/);
    for (const tag of ['div', 'span', 'p', 'cloth-sim', 'physics-scene']) expect(unknownChildMessage(tag), tag).to.match(/^not a body or link element, so the scene ignores it \(bodies are <physics-box>/);
  });

  it('the known tags are exactly the body and link elements the library defines', () => {
    const defined = { body: [] as string[], link: [] as string[] };
    for (const value of Object.values(api)) {
      if (typeof value !== 'function' || value === api.PhysicsBodyElement || value === api.PhysicsLinkElement) continue;
      const tag = customElements.getName(value as CustomElementConstructor);
      if (value.prototype instanceof api.PhysicsBodyElement) defined.body.push(tag!);
      else if (value.prototype instanceof api.PhysicsLinkElement) defined.link.push(tag!);
    }
    expect([...BODY_TAGS].sort()).to.deep.equal(defined.body.sort());
    expect([...LINK_TAGS].sort()).to.deep.equal(defined.link.sort());
  });

  describe('as a CMS or Markdown rewrites the markup', () => {
    it('WordPress\'s automatic paragraphs: a <br> after every line is not reported', async () => {
      const rec = await mountRecording(`<br>\n  ${BOX}<br>\n  ${BALL}<br>\n  ${ROPE}<br>\n`);
      scene = rec.scene;
      expect((await scene.diagnostics()).bodyCount).to.equal(3);
      expect(rec.errors, JSON.stringify(rec.errors.map((e) => e.message))).to.deep.equal([]);
      expect(warnings).to.deep.equal([]);
    });

    it('Markdown after a blank line: the bodies wrapped in a <p> are simulated, answer commands and follow changes', async () => {
      const rec = await mountRecording(`\n<p>${BOX}\n${BALL}\n${ROPE}</p>\n`);
      scene = rec.scene;
      expect((await scene.diagnostics()).bodyCount).to.equal(3);
      expect(rec.errors, JSON.stringify(rec.errors.map((e) => e.message))).to.deep.equal([]);
      expect(warnings).to.deep.equal([]);
      const ball = scene.querySelector<PhysicsCircleElement>('#ball')!;
      await waitFor(() => Number.isFinite(ball.y), 'the ball\'s pose');
      // A command to a wrapped body reaches it: thrown sideways, it moves sideways.
      ball.setVelocity(3, 0);
      await scene.step(30);
      expect(ball.x).to.be.closeTo(3.6 + 1.5, 0.05);
      // Added into the wrapper later, or removed from it: the scene follows; a command in the same task as the
      // addition reaches the new body.
      const p = scene.querySelector('p')!;
      p.insertAdjacentHTML('beforeend', '<physics-circle id="late" x="9" y="5" radius="0.5"></physics-circle>');
      const late = p.querySelector<PhysicsCircleElement>('#late')!;
      late.setVelocity(-2, 0);
      await scene.step(30);
      expect((await scene.diagnostics()).bodyCount).to.equal(4);
      expect(late.x).to.be.closeTo(9 - 1, 0.05);
      late.remove();
      await waitFor(async () => (await scene!.diagnostics()).bodyCount === 3, 'the circle removed from the <p>');
    });

    it('a <p> of text holds no body and is still reported', async () => {
      const rec = await mountRecording(`${BOX}<p>Some words</p>`);
      scene = rec.scene;
      expect((await scene.diagnostics()).bodyCount).to.equal(1);
      expect(rec.errors.map((e) => e.element.localName)).to.deep.equal(['p']);
      expect(warnings).to.have.length(1);
    });
  });
});
