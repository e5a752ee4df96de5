// A scene's markup as a CMS or a Markdown processor hands it back: WordPress's automatic paragraphs (wpautop, the
// classic editor) put a <br> after each line inside the tag; Markdown ends the raw HTML at a blank line and wraps the
// lines after it in a <p>. Either way every body is simulated, nothing is reported, and the bodies still answer
// commands. A <p> of text, which holds no body, is still reported.
import { expect } from '@open-wc/testing';
import type { PhysicsCircleElement, PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

const BOX = '<physics-box x="6" y="8.6" width="12" height="0.8" static></physics-box>';
const BALL = '<physics-circle id="ball" x="3.6" y="0.5" radius="0.5"></physics-circle>';
const ROPE = '<physics-rope x1="1" y1="2" x2="6.5" y2="2" segments="12" pin="both"></physics-rope>';

/** Mounts a 12 × 9 scene with `children`, recording its physics-error details and the console's warnings. */
async function mountRecording(children: string): Promise<{ scene: PhysicsSceneElement; errors: PhysicsErrorDetail[] }> {
  const errors: PhysicsErrorDetail[] = [];
  const scene = await mount('width="12" height="9" paused', children, {
    before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)),
  });
  return { scene, errors };
}

describe('a scene\'s markup as a CMS rewrites it', () => {
  let scene: PhysicsSceneElement | null = null;
  let warnings: string[] = [];
  const warn = console.warn;
  beforeEach(() => {
    warnings = [];
    console.warn = (...args: unknown[]) => warnings.push(args.join(' '));
  });
  afterEach(() => {
    console.warn = warn;
    unmount(scene);
    scene = null;
  });

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
