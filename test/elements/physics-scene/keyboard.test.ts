// The keyboard on its own, with a fake host and fake bodies: Tab and Shift+Tab through the bodies and out of the scene,
// arrow keys push (or pick the first), Escape lets go, R resets, Space pauses and plays, what the live region says, and the ring placed
// around the picked body's box.
import { expect } from '@open-wc/testing';
import { KeyboardController, type PickableBody } from '../../../src/elements/physics-scene/keyboard.js';
import type { Box } from '../../../src/elements/physics-scene/outlines.js';
import { makeHost, type FakeHost } from './fakes.js';
import { nextFrame } from '../helpers.js';

function rig(bodies: PickableBody[] = [{ key: 7, label: 'box' }, { key: 9, label: 'ball' }, { key: 4, label: 'Red crate' }]) {
  const host = makeHost();
  const ring = document.createElement('div');
  ring.hidden = true;
  const live = document.createElement('div');
  host.append(ring, live);
  const pushes: [number, number, number][] = [];
  let resets = 0;
  let paused = false;
  const boxes = new Map<number, Box>([[9, { left: 10, top: 20, right: 30, bottom: 60 }]]);
  const keyboard = new KeyboardController(host, {
    bodies: () => bodies,
    bounds: (key) => boxes.get(key) ?? null,
    push: (key, dx, dy) => pushes.push([key, dx, dy]),
    reset: () => resets++,
    togglePause: () => (paused = !paused),
    ring: () => ring,
    liveRegion: () => live,
  });
  /** Presses `key` on the host; true when the keyboard took it (default prevented). */
  const press = (key: string, init: KeyboardEventInit = {}) => {
    const e = new KeyboardEvent('keydown', { key, bubbles: true, composed: true, cancelable: true, ...init });
    host.dispatchEvent(e);
    return e.defaultPrevented;
  };
  return { host, keyboard, ring, live, pushes, resets: () => resets, paused: () => paused, press, boxes, bodies };
}

describe('KeyboardController', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  it('Tab picks each body in turn and says which; past the last it leaves the scene; Shift+Tab goes back', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect(host.getAttribute('aria-description')).to.equal('Tab picks a body, arrow keys push it, Escape then Tab leaves, R resets, Space pauses');
    expect([r.press('Tab'), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, 7, 'Picked box 1 of 3']);
    expect([r.press('Tab'), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, 9, 'Picked ball 2 of 3']);
    expect([r.press('Tab'), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, 4, 'Picked Red crate 3 of 3']);
    // Past the last body Tab is the browser's again (focus moves on), and nothing stays picked.
    expect([r.press('Tab'), r.keyboard.picked]).to.deep.equal([false, null]);
    expect([r.press('Tab', { shiftKey: true }), r.keyboard.picked]).to.deep.equal([false, null]);
    r.press('Tab');
    r.press('Tab');
    expect([r.press('Tab', { shiftKey: true }), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, 7, 'Picked box 1 of 3']);
    // Before the first body: back to the scene itself.
    expect([r.press('Tab', { shiftKey: true }), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, null, 'Nothing picked']);
    // Keys with Ctrl, Alt or Meta are someone else's.
    expect([r.press('Tab', { ctrlKey: true }), r.press('r', { metaKey: true }), r.press('ArrowLeft', { altKey: true })]).to.deep.equal([false, false, false]);
    expect(r.keyboard.picked).to.equal(null);
  });

  it('arrow keys push the picked body one unit step per press; with nothing picked the first arrow picks', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect([r.press('ArrowRight'), r.keyboard.picked, r.pushes]).to.deep.equal([true, 7, []]);
    r.press('ArrowRight');
    r.press('ArrowUp');
    r.press('ArrowLeft');
    r.press('ArrowDown');
    expect(r.pushes).to.deep.equal([[7, 1, 0], [7, 0, -1], [7, -1, 0], [7, 0, 1]]);
    expect([r.press('Escape'), r.keyboard.picked, r.live.textContent]).to.deep.equal([true, null, 'Nothing picked']);
    // Escape with nothing picked is not ours (a dialog around the scene may want it).
    expect(r.press('Escape')).to.equal(false);
  });

  it('Escape, then Tab, leaves the scene from any body (two keys past a scene of many bodies); any other key first and Tab picks again', () => {
    const many = Array.from({ length: 50 }, (_, k) => ({ key: k + 1, label: 'ball' }));
    const r = rig(many);
    host = r.host;
    document.body.append(host);
    for (let k = 0; k < 20; k++) r.press('Tab');
    expect(r.keyboard.picked).to.equal(20);
    expect([r.press('Escape'), r.keyboard.picked]).to.deep.equal([true, null]);
    expect([r.press('Tab'), r.keyboard.picked]).to.deep.equal([false, null]);
    // Tabbed in again (focus back on the scene): Tab picks the first body.
    host.dispatchEvent(new FocusEvent('blur'));
    expect([r.press('Tab'), r.keyboard.picked]).to.deep.equal([true, 1]);
    // Escape with nothing picked, then Tab: leaves too.
    r.press('Escape');
    r.press('Tab', { shiftKey: true });
    expect([r.press('Escape'), r.press('Tab'), r.keyboard.picked]).to.deep.equal([false, false, null]);
    // Escape, then another key, then Tab: the key came between, Tab picks.
    r.press('Escape');
    r.press('r');
    expect([r.press('Tab'), r.keyboard.picked]).to.deep.equal([true, 1]);
  });

  it('R resets and says so, each time (the same words twice still change the live region); held down it resets once', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect([r.press('r'), r.resets(), r.live.textContent]).to.deep.equal([true, 1, 'Reset']);
    expect([r.press('R'), r.resets(), r.live.textContent]).to.deep.equal([true, 2, 'Reset\u00a0']);
    expect([r.press('r', { repeat: true }), r.resets()]).to.deep.equal([true, 2]);
  });

  it('Space pauses and plays and says which ("Paused", "Playing"); held down it toggles once; not with Ctrl, Alt or Meta, not from inside', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect([r.press(' ', { code: 'Space' }), r.paused(), r.live.textContent]).to.deep.equal([true, true, 'Paused']);
    expect([r.press(' ', { code: 'Space', repeat: true }), r.paused(), r.live.textContent]).to.deep.equal([true, true, 'Paused']);
    expect([r.press(' ', { code: 'Space' }), r.paused(), r.live.textContent]).to.deep.equal([true, false, 'Playing']);
    expect([r.press(' ', { code: 'Space', shiftKey: true }), r.paused(), r.live.textContent]).to.deep.equal([true, true, 'Paused']);
    expect([r.press(' ', { code: 'Space', ctrlKey: true }), r.press(' ', { code: 'Space', altKey: true }), r.paused()]).to.deep.equal([false, false, true]);
    const inner = document.createElement('button');
    host.append(inner);
    const e = new KeyboardEvent('keydown', { key: ' ', code: 'Space', bubbles: true, composed: true, cancelable: true });
    inner.dispatchEvent(e);
    expect([e.defaultPrevented, r.paused()]).to.deep.equal([false, true]);
  });

  it('with no bodies Tab and the arrows are the page\'s; keys from inside the shadow root (the play button) are not the scene\'s', () => {
    const r = rig([]);
    host = r.host;
    document.body.append(host);
    expect([r.press('Tab'), r.press('ArrowDown')]).to.deep.equal([false, false]);
    const s = rig();
    document.body.append(s.host);
    const button = document.createElement('button');
    s.host.append(button);
    const e = new KeyboardEvent('keydown', { key: 'Tab', bubbles: true, composed: true, cancelable: true });
    button.dispatchEvent(e);
    expect([e.defaultPrevented, s.keyboard.picked]).to.deep.equal([false, null]);
    s.host.remove();
  });

  it('the ring follows the picked body\'s box every frame, hides when it has none, and goes with blur or a removed body', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    r.press('Tab');
    r.press('Tab');
    await nextFrame();
    await nextFrame();
    expect(r.ring.hidden).to.equal(false);
    // 4 px around the box (10, 20)–(30, 60).
    expect([r.ring.style.left, r.ring.style.top, r.ring.style.width, r.ring.style.height]).to.deep.equal(['6px', '16px', '28px', '48px']);
    r.boxes.set(9, { left: 50, top: 20, right: 70, bottom: 60 });
    await nextFrame();
    await nextFrame();
    expect(r.ring.style.left).to.equal('46px');
    r.boxes.delete(9);
    await nextFrame();
    await nextFrame();
    expect([r.ring.hidden, r.keyboard.picked]).to.deep.equal([true, 9]);
    // The body is gone from the scene: nothing picked, and said so.
    r.bodies.splice(1, 1);
    await nextFrame();
    await nextFrame();
    expect([r.ring.hidden, r.keyboard.picked, r.live.textContent]).to.deep.equal([true, null, 'Nothing picked']);
    r.press('Tab');
    host.dispatchEvent(new FocusEvent('blur'));
    expect([r.ring.hidden, r.keyboard.picked]).to.deep.equal([true, null]);
  });
});
