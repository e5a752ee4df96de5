// Markup sync on its own: real body and link elements in a plain container, a fake engine port that records what is
// sent. Children added, changed and removed become addBody / updateBody / removeBody; links follow the ids.
import { expect } from '@open-wc/testing';
import '../../../src/index.js';
import { MarkupSync } from '../../../src/elements/physics-scene/markup.js';
import type { Command, Engine } from '../../../src/elements/physics-scene/session.js';
import type { Problem } from '../../../src/elements/checks.js';
import type { BodyStyle } from '../../../src/render/renderer.js';
import type { KeyedBody, KeyedLink } from '../../../src/worker/protocol.js';
import { FakeEngine, settle } from './fakes.js';

function rig(markup: string) {
  const container = document.createElement('div');
  // Fixed test markup only.
  container.innerHTML = markup;
  document.body.append(container);
  const sent: [Command, unknown[]][] = [];
  const engine = new FakeEngine();
  const port = {
    live: engine as Engine | null,
    shown: engine as Engine | null,
    send: (method: Command, ...args: unknown[]) => void sent.push([method, args]),
  };
  const problems = new Map<unknown, Problem[]>();
  const forgotten: unknown[] = [];
  /** The elements whose description was sent again (an engine refusal of the old one leaves the error box). */
  const resent: Element[] = [];
  const styles = new Map<number, BodyStyle>();
  const sync = new MarkupSync({
    container: () => container,
    engine: port,
    problems: { set: (source, _el, list) => void problems.set(source, list), forget: (source) => void forgotten.push(source), resent: (el) => void resent.push(el) },
    styles: { setStyle: (key, style) => void styles.set(key, style), deleteStyle: (key) => void styles.delete(key) },
  });
  return { container, sent, port, engine, problems, forgotten, resent, styles, sync, $: <T extends Element>(s: string) => container.querySelector(s) as T };
}

/** Waits for the MutationObserver and the elements' own updates. */
async function changes(): Promise<void> {
  await settle();
  await settle();
}

describe('MarkupSync', () => {
  let container: HTMLElement | null = null;
  afterEach(() => container?.remove());

  it('collect() keys every body and link and describes them; a link names its bodies by key; styles are set', async () => {
    const r = rig(`<physics-box id="a" x="1" y="2" width="2" height="1" fill="#ff0000"></physics-box>
      <physics-circle id="b" x="5" y="2" radius="0.5"></physics-circle>
      <physics-joint a="a" b="b"></physics-joint>
      <div>not a body</div>`);
    container = r.container;
    await changes();
    const { bodies, links } = r.sync.collect();
    const a = r.sync.keyOf(r.$('#a'))!;
    const b = r.sync.keyOf(r.$('#b'))!;
    expect(bodies.map((x) => [x.key, x.desc.type])).to.deep.equal([[a, 'box'], [b, 'circle']]);
    expect(bodies[0].desc).to.deep.include({ x: 1, y: 2, width: 2, height: 1 });
    expect(links.length).to.equal(1);
    expect(links[0].desc).to.deep.include({ type: 'joint', a, b });
    expect(r.sync.elementOf(a)).to.equal(r.$('#a'));
    expect(r.styles.get(a)!.fill).to.equal('#ff0000');
    expect(r.sent).to.deep.equal([]);
    // The children now call the sync.
    expect((r.$('#a') as unknown as { _scene: unknown })._scene).to.equal(r.sync);
  });

  it('live: an added child is sent with addBody, a changed one with updateBody, a removed one with removeBody', async () => {
    const r = rig(`<physics-box id="a" x="1" y="2"></physics-box>`);
    container = r.container;
    await changes();
    r.sync.collect();
    r.sync.observe();
    const circle = document.createElement('physics-circle');
    circle.setAttribute('x', '4');
    circle.setAttribute('radius', '0.5');
    r.container.append(circle);
    await changes();
    const key = r.sync.keyOf(circle)!;
    expect(r.sent.map(([m]) => m)).to.deep.equal(['addBody']);
    expect((r.sent[0][1][0] as KeyedBody).key).to.equal(key);
    expect((r.sent[0][1][0] as KeyedBody).desc).to.deep.include({ type: 'circle', x: 4, radius: 0.5 });
    r.sent.length = 0;
    circle.setAttribute('radius', '2');
    await changes();
    expect(r.sent.map(([m, args]) => [m, (args[0] as KeyedBody).key, ((args[0] as KeyedBody).desc as { radius: number }).radius])).to.deep.equal([['updateBody', key, 2]]);
    expect(r.resent).to.deep.equal([circle]);
    // A refusal's call is checked against what the element sent last: the radius-2 description is current, the
    // first one (radius 0.5) was replaced; calls without a description (an impulse's key) always count.
    const latest = r.sent[0][1][0] as KeyedBody;
    const replaced = { key, desc: { ...latest.desc, radius: 0.5 } };
    expect([r.sync.isLatest(latest), r.sync.isLatest(replaced), r.sync.isLatest(key)]).to.deep.equal([true, false, true]);
    r.sent.length = 0;
    // A change of the drawing only (not of the body) sends nothing; the style follows.
    circle.setAttribute('fill', '#00ff00');
    await changes();
    expect(r.sent).to.deep.equal([]);
    expect(r.resent).to.deep.equal([circle]);
    expect(r.styles.get(key)!.fill).to.equal('#00ff00');
    circle.remove();
    await changes();
    expect(r.sent).to.deep.equal([['removeBody', [key]]]);
    expect(r.styles.has(key)).to.equal(false);
    expect(r.sync.keyOf(circle)).to.equal(undefined);
    expect(r.forgotten).to.deep.equal([circle]);
    r.sync.reset();
  });

  it('links follow the ids: a body renamed to the id a joint names joins it (updateLink); naming none removes it', async () => {
    const r = rig(`<physics-box id="a" x="1"></physics-box><physics-box id="c" x="3"></physics-box><physics-joint a="a" b="b"></physics-joint>`);
    container = r.container;
    await changes();
    expect(r.sync.collect().links).to.deep.equal([]);
    expect(r.problems.get(r.$('physics-joint'))!.map((p) => [p.attribute, p.value])).to.deep.equal([['b', 'b']]);
    r.sync.observe();
    r.$('#c').id = 'b';
    await changes();
    const key = (id: string) => r.sync.keyOf(r.$(id))!;
    expect(r.sent.map(([m]) => m)).to.deep.equal(['updateLink']);
    expect((r.sent[0][1][0] as KeyedLink).desc).to.deep.include({ type: 'joint', a: key('#a'), b: key('#b') });
    expect(r.problems.get(r.$('physics-joint'))).to.deep.equal([]);
    r.sent.length = 0;
    const link = r.sync.keyOf(r.$('physics-joint'));
    const b = key('#b');
    r.$('#b').remove();
    await changes();
    expect(r.sent.map(([m, args]) => [m, args[0]])).to.deep.equal([['removeBody', b], ['removeLink', link]]);
    r.sync.reset();
  });

  it("bad markup: an element's problems go out with the element as their source, and nothing is sent for it", async () => {
    const r = rig(`<physics-polygon id="bad" points="0,0 1,1" fill="not-a-colour"></physics-polygon>`);
    container = r.container;
    await changes();
    expect(r.sync.collect().bodies).to.deep.equal([]);
    expect(r.problems.get(r.$('#bad'))!.map((p) => `${p.attribute}=${p.value}`)).to.deep.equal(['points=0,0 1,1', 'fill=not-a-colour']);
    r.sync.observe();
    r.$('#bad').setAttribute('points', '0,0 1,0 0,1');
    await changes();
    expect(r.sent.map(([m]) => m)).to.deep.equal(['updateBody']);
    expect(r.problems.get(r.$('#bad'))!.map((p) => p.attribute)).to.deep.equal(['fill']);
    r.sync.reset();
  });

  it('nothing is sent while no engine has the scene; poseOf reads the shown engine; impulses and velocities only when finite (bad ones throw)', async () => {
    const r = rig(`<physics-box id="a" x="1"></physics-box>`);
    container = r.container;
    await changes();
    r.sync.collect();
    r.sync.observe();
    r.port.live = null;
    r.container.append(document.createElement('physics-box'));
    r.$<HTMLElement & { width: number }>('#a').width = 3;
    await changes();
    expect(r.sent).to.deep.equal([]);
    const box = r.$<HTMLElement & { x: number; applyImpulse(x: number, y: number): void; setVelocity(x: number, y: number): void }>('#a');
    const key = r.sync.keyOf(box)!;
    r.engine.poses.set(key, [7, 8, 0]);
    expect(r.sync.poseOf(box)).to.deep.equal([7, 8, 0]);
    expect(box.x).to.equal(7);
    expect(r.sync.poseOf(document.createElement('physics-box'))).to.equal(null);
    // Bad numbers are refused where the call is made (RangeError), and nothing is sent.
    expect(() => box.applyImpulse(1, NaN)).to.throw(RangeError, 'iy');
    expect(() => box.setVelocity(Infinity, 0)).to.throw(RangeError, 'vx');
    box.applyImpulse(1, 2);
    box.setVelocity(3, 4);
    expect(r.sent).to.deep.equal([['applyImpulse', [key, 1, 2]], ['setVelocity', [key, 3, 4]]]);
    // Reset: the children are no longer this scene's, their problems forgotten.
    r.sync.reset();
    expect(r.sync.keyOf(box)).to.equal(undefined);
    expect((box as unknown as { _scene: unknown })._scene).to.equal(null);
    expect(r.forgotten).to.include(box);
  });
});
