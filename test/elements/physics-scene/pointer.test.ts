// Pointer drag on its own: a fake engine answers grab(); the world mapping is the identity. A press grabs, moves
// follow once the grab is answered, letting go releases it, also when the engine answers after the pointer let go.
// A touch drags only where the hit test finds a body (then its touchstart is cancelled: no page scroll).
import { expect } from '@open-wc/testing';
import { PointerDragController } from '../../../src/elements/physics-scene/pointer.js';
import { deferred, FakeEngine, makeHost, settle, type FakeHost } from './fakes.js';

const at = (type: string, x: number, y: number, init: PointerEventInit = {}) =>
  new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, pointerType: 'mouse', button: 0, bubbles: true, cancelable: true, ...init });

/** A touch at (x, y) on `target`. */
const touchAt = (target: Element, type: string, x: number, y: number, id = 1, others: Touch[] = []) => {
  const t = new Touch({ identifier: id, target, clientX: x, clientY: y });
  return new TouchEvent(type, { touches: [...others, t], changedTouches: [t], targetTouches: [...others, t], bubbles: true, cancelable: true });
};

function rig() {
  const host = makeHost();
  const engine = new FakeEngine();
  let current: FakeEngine | null = engine;
  /** Where the fake hit test finds a body: x < 50 (viewport pixels), taken 1 px right of the finger. */
  const hits: [number, number][] = [];
  const drag = new PointerDragController(host, {
    engine: () => current,
    toWorld: (x, y) => ({ x: x / 10, y: y / 10 }),
    hit: (x, y) => {
      hits.push([x, y]);
      return x < 50 ? { x: x + 1, y } : null;
    },
  });
  host.addEventListener('pointerdown', drag.down as EventListener);
  host.addEventListener('pointermove', drag.move as EventListener);
  host.addEventListener('pointerup', drag.up as EventListener);
  host.addEventListener('pointercancel', drag.up as EventListener);
  host.addEventListener('touchstart', drag.touchStart as EventListener, { passive: false });
  return { host, engine, drag, hits, replace: (e: FakeEngine | null) => (current = e) };
}

describe('PointerDragController', () => {
  let host: FakeHost | null = null;
  afterEach(() => host?.remove());

  it('a press grabs at the world point; moves follow once the grab is answered; letting go releases it', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    const answer = deferred<number | null>();
    r.engine.answers.grab = () => answer.promise;
    const down = at('pointerdown', 30, 50);
    host.dispatchEvent(down);
    expect(down.defaultPrevented).to.equal(true);
    expect(r.engine.argsOf('grab')).to.deep.equal([[3, 5]]);
    // Moves before the answer are remembered, not sent.
    host.dispatchEvent(at('pointermove', 40, 50));
    expect(r.engine.argsOf('moveGrab')).to.deep.equal([]);
    answer.resolve(9);
    await settle();
    expect(r.drag.grab).to.equal(9);
    expect(r.engine.argsOf('moveGrab')).to.deep.equal([[9, 4, 5]]);
    host.dispatchEvent(at('pointermove', 70, 50));
    host.dispatchEvent(at('pointermove', 70, 50, { pointerId: 2 }));
    expect(r.engine.argsOf('moveGrab')).to.deep.equal([[9, 4, 5], [9, 7, 5]]);
    host.dispatchEvent(at('pointerup', 70, 50));
    expect(r.engine.argsOf('release')).to.deep.equal([[9]]);
    expect(r.drag.grab).to.equal(null);
  });

  it('let go before the engine answered: the grab is released as soon as it is answered; so too when the engine changed', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    const answer = deferred<number | null>();
    r.engine.answers.grab = () => answer.promise;
    host.dispatchEvent(at('pointerdown', 10, 10));
    host.dispatchEvent(at('pointerup', 10, 10));
    answer.resolve(4);
    await settle();
    expect(r.engine.argsOf('release')).to.deep.equal([[4]]);
    expect(r.engine.argsOf('moveGrab')).to.deep.equal([]);
    const later = deferred<number | null>();
    r.engine.answers.grab = () => later.promise;
    host.dispatchEvent(at('pointerdown', 10, 10));
    r.replace(new FakeEngine('new'));
    later.resolve(5);
    await settle();
    expect(r.engine.argsOf('release')).to.deep.equal([[4], [5]]);
  });

  it('a press on nothing, with the right button, or with no engine makes no drag', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    host.dispatchEvent(at('pointerdown', 10, 10));
    await settle();
    expect(r.drag.grab).to.equal(null);
    host.dispatchEvent(at('pointermove', 20, 10));
    expect(r.engine.argsOf('moveGrab')).to.deep.equal([]);
    r.engine.answers.grab = () => 3;
    host.dispatchEvent(at('pointerdown', 10, 10, { button: 2 }));
    r.replace(null);
    host.dispatchEvent(at('pointerdown', 10, 10));
    await settle();
    expect(r.engine.argsOf('grab').length).to.equal(1);
  });

  it('the scene leaving the document lets go (no pointerup will come); cancel() forgets the drag', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    r.engine.answers.grab = () => 6;
    host.dispatchEvent(at('pointerdown', 10, 10));
    await settle();
    expect(r.drag.grab).to.equal(6);
    host.remove();
    expect(r.engine.argsOf('release')).to.deep.equal([[6]]);
    document.body.append(host);
    host.dispatchEvent(at('pointerdown', 10, 10));
    await settle();
    r.drag.cancel();
    expect(r.drag.grab).to.equal(null);
    host.dispatchEvent(at('pointerup', 10, 10));
    expect(r.engine.argsOf('release')).to.deep.equal([[6]]);
  });

  it('a touch on a body drags it and cancels its touchstart (no scroll); a touch on nothing is left to the page', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    r.engine.answers.grab = () => 5;
    // On a body (x < 50): pointerdown grabs, the touchstart that follows is cancelled.
    const down = at('pointerdown', 30, 20, { pointerType: 'touch', isPrimary: true });
    host.dispatchEvent(down);
    const start = touchAt(host, 'touchstart', 30, 20);
    host.dispatchEvent(start);
    expect([down.defaultPrevented, start.defaultPrevented]).to.deep.equal([true, true]);
    // Taken where the hit test says (1 px = 0.1 units right of the finger), and held that far from it.
    expect(r.engine.argsOf('grab')).to.deep.equal([[3.1, 2]]);
    await settle();
    host.dispatchEvent(at('pointermove', 40, 20, { pointerType: 'touch' }));
    const rounded = (calls: unknown[][]) => calls.map((c) => c.map((v) => Math.round((v as number) * 1e9) / 1e9));
    expect(rounded(r.engine.argsOf('moveGrab'))).to.deep.equal([[5, 3.1, 2], [5, 4.1, 2]]);
    host.dispatchEvent(at('pointerup', 40, 20, { pointerType: 'touch' }));
    expect(r.engine.argsOf('release')).to.deep.equal([[5]]);

    // On nothing (x ≥ 50): no grab, nothing cancelled; the browser scrolls and cancels the pointer.
    const miss = at('pointerdown', 80, 20, { pointerType: 'touch', isPrimary: true });
    host.dispatchEvent(miss);
    const scroll = touchAt(host, 'touchstart', 80, 20);
    host.dispatchEvent(scroll);
    expect([miss.defaultPrevented, scroll.defaultPrevented]).to.deep.equal([false, false]);
    host.dispatchEvent(at('pointercancel', 80, 20, { pointerType: 'touch' }));
    expect(r.engine.argsOf('grab').length).to.equal(1);
    expect(r.hits).to.deep.equal([[30, 20], [80, 20], [80, 20]]);
  });

  it('a second finger makes no drag (a pinch); a touchstart with no pointerdown before it asks the hit test itself', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    r.engine.answers.grab = () => 5;
    const second = at('pointerdown', 30, 20, { pointerType: 'touch', isPrimary: false, pointerId: 2 });
    host.dispatchEvent(second);
    expect(second.defaultPrevented).to.equal(false);
    const first = new Touch({ identifier: 1, target: host, clientX: 80, clientY: 20 });
    const pinch = touchAt(host, 'touchstart', 30, 20, 2, [first]);
    host.dispatchEvent(pinch);
    expect(pinch.defaultPrevented).to.equal(false);
    expect(r.engine.argsOf('grab')).to.deep.equal([]);
    // A lone touchstart: on a body it is cancelled, on nothing not.
    const onBody = touchAt(host, 'touchstart', 10, 10);
    host.dispatchEvent(onBody);
    const onNothing = touchAt(host, 'touchstart', 60, 10);
    host.dispatchEvent(onNothing);
    expect([onBody.defaultPrevented, onNothing.defaultPrevented]).to.deep.equal([true, false]);
    // A mouse press never asks the hit test (the engine answers; the page does not scroll on a mouse press).
    const before = r.hits.length;
    host.dispatchEvent(at('pointerdown', 80, 20));
    expect(r.hits.length).to.equal(before);
    expect(r.engine.argsOf('grab')).to.deep.equal([[8, 2]]);
  });
});
