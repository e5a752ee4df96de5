// Pointer drag on its own: a fake engine answers grab(); the world mapping is the identity. A press grabs, moves
// follow once the grab is answered, letting go releases it, also when the engine answers after the pointer let go.
import { expect } from '@open-wc/testing';
import { PointerDragController } from '../../../src/elements/physics-scene/pointer.js';
import { deferred, FakeEngine, makeHost, settle, type FakeHost } from './fakes.js';

const at = (type: string, x: number, y: number, init: PointerEventInit = {}) =>
  new PointerEvent(type, { clientX: x, clientY: y, pointerId: 1, pointerType: 'mouse', button: 0, bubbles: true, cancelable: true, ...init });

function rig() {
  const host = makeHost();
  const engine = new FakeEngine();
  let current: FakeEngine | null = engine;
  const drag = new PointerDragController(host, { engine: () => current, toWorld: (x, y) => ({ x: x / 10, y: y / 10 }) });
  host.addEventListener('pointerdown', drag.down as EventListener);
  host.addEventListener('pointermove', drag.move as EventListener);
  host.addEventListener('pointerup', drag.up as EventListener);
  return { host, engine, drag, replace: (e: FakeEngine | null) => (current = e) };
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
});
