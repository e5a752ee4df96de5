// Pointer drag on its own: a fake engine answers grab(); the world mapping is x / 10; time is a fake clock. A press
// grabs, moves follow once the grab is answered, letting go releases it. An answer that comes late replays the moves
// made before it, at their pace, and the lift as the release (a quick flick throws the body). A touch drags only where
// the hit test finds a body (then its touchstart is cancelled: no page scroll).
import { expect } from '@open-wc/testing';
import { PointerDragController } from '../../../src/elements/physics-scene/pointer.js';
import { World, createBox } from '../../../src/engine/index.js';
import { deferred, FakeClock, FakeEngine, makeHost, settle, type FakeHost } from './fakes.js';

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
  const clock = new FakeClock();
  const drag = new PointerDragController(host, {
    clock,
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
  /** What reached the engine after the press, with the clock's time: [ms, 'move', x, y] or [ms, 'release']. */
  const log: (string | number)[][] = [];
  engine.answers.moveGrab = (_g: number, x: number, y: number) => void log.push([clock.time, 'move', x, y]);
  engine.answers.release = () => void log.push([clock.time, 'release']);
  return { host, engine, drag, hits, clock, log, replace: (e: FakeEngine | null) => (current = e) };
}

describe('PointerDragController', () => {
  // The mounted rig's host (mounted()); removed after each test.
  let host!: FakeHost;
  afterEach(() => host?.remove());

  /** A rig whose host is in the document (removed after the test). */
  function mounted() {
    const r = rig();
    host = r.host;
    document.body.append(host);
    return r;
  }

  /** The engine answers the next press when the test resolves what this returns. */
  function answerLater(r: ReturnType<typeof rig>) {
    const answer = deferred<number | null>();
    r.engine.answers.grab = () => answer.promise;
    return answer;
  }

  /** Pressed at x 1 at 0 ms, moved 2 units every 16 ms to x 7, lifted at 56 ms. */
  function flick(r: ReturnType<typeof rig>) {
    r.host.dispatchEvent(at('pointerdown', 10, 10));
    for (const x of [30, 50, 70]) {
      r.clock.advance(16);
      r.host.dispatchEvent(at('pointermove', x, 10));
    }
    r.clock.advance(8);
    r.host.dispatchEvent(at('pointerup', 70, 10));
  }

  it('a press grabs at the world point; moves follow once the grab is answered; letting go releases it', async () => {
    const r = mounted();
    const answer = answerLater(r);
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

  it('a tap let go before the engine answered: the grab is released as soon as it is answered, nothing thrown; so too when the engine changed', async () => {
    const r = mounted();
    const answer = answerLater(r);
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

  it('a flick lifted before the answer: the answer replays its moves at their pace, then releases where it was lifted', async () => {
    const r = mounted();
    const answer = answerLater(r);
    // Pressed at x 1 at 0 ms, moved 2 units every 16 ms to x 7, lifted at 56 ms; the engine answers at 100 ms.
    flick(r);
    r.clock.advance(44);
    answer.resolve(4);
    await settle();
    // Held, not released: the drag is replayed 100 ms (the answer's delay) behind the pointer.
    expect(r.log).to.deep.equal([]);
    expect(r.drag.grab).to.equal(4);
    r.clock.advance(200);
    expect(r.log).to.deep.equal([[116, 'move', 3, 1], [132, 'move', 5, 1], [148, 'move', 7, 1], [156, 'release']]);
    expect(r.drag.grab).to.equal(null);
    expect(r.clock.pending, 'timers left').to.equal(0);
  });

  it('answered during the drag: the grab replays the moves it missed until it catches up, then follows at once; a lift while it replays releases in its turn', async () => {
    const r = mounted();
    let answer = deferred<number | null>();
    r.engine.answers.grab = () => answer.promise;
    host.dispatchEvent(at('pointerdown', 10, 10));
    r.clock.advance(16);
    host.dispatchEvent(at('pointermove', 30, 10));
    r.clock.advance(24);
    answer.resolve(7);
    await settle();
    // Answered at 40 ms: a move at 48 ms is queued behind the one at 16 ms; both reach the grab 40 ms late.
    r.clock.advance(8);
    host.dispatchEvent(at('pointermove', 50, 10));
    r.clock.advance(52);
    expect(r.log).to.deep.equal([[56, 'move', 3, 1], [88, 'move', 5, 1]]);
    // Caught up (the pointer rested 40 ms): moves and the lift go through at once.
    expect(r.clock.pending).to.equal(0);
    host.dispatchEvent(at('pointermove', 60, 10));
    host.dispatchEvent(at('pointerup', 60, 10));
    expect(r.log.slice(2)).to.deep.equal([[100, 'move', 6, 1], [100, 'release']]);

    // Answered at 30 ms, lifted at 32 ms: the release comes after the replayed moves, 30 ms after the lift.
    r.log.length = 0;
    answer = deferred<number | null>();
    const t0 = r.clock.time;
    host.dispatchEvent(at('pointerdown', 10, 10));
    r.clock.advance(16);
    host.dispatchEvent(at('pointermove', 20, 10));
    r.clock.advance(14);
    answer.resolve(8);
    await settle();
    r.clock.advance(2);
    host.dispatchEvent(at('pointermove', 40, 10));
    host.dispatchEvent(at('pointerup', 40, 10));
    expect(r.drag.grab).to.equal(8);
    r.clock.advance(100);
    expect(r.log.map(([t, ...rest]) => [(t as number) - t0, ...rest])).to.deep.equal([[46, 'move', 2, 1], [62, 'move', 4, 1], [62, 'release']]);
    expect(r.drag.grab).to.equal(null);
  });

  it('a late answer replays at most the last 250 ms of the drag: held, the grab jumps to where the pointer was 250 ms before; lifted, to 250 ms before the lift', async () => {
    const r = mounted();
    /** Pressed at x 1, moved 1 unit every 100 ms to x 10 at 900 ms; answered at 1000 ms (lifted at 900 ms if `lift`). */
    const drag = async (lift: boolean) => {
      const answer = deferred<number | null>();
      r.engine.answers.grab = () => answer.promise;
      const t0 = r.clock.time;
      host!.dispatchEvent(at('pointerdown', 10, 10));
      for (let k = 2; k <= 10; k++) {
        r.clock.advance(100);
        host!.dispatchEvent(at('pointermove', 10 * k, 10));
      }
      if (lift) host!.dispatchEvent(at('pointerup', 100, 10));
      r.clock.advance(100);
      answer.resolve(2);
      await settle();
      r.clock.advance(400);
      if (!lift) host!.dispatchEvent(at('pointerup', 100, 10));
      const log = r.log.map(([t, ...rest]) => [(t as number) - t0, ...rest]);
      r.log.length = 0;
      return log;
    };
    // Held: 250 ms behind: x 8 (moved at 700 ms) at once, then x 9 and x 10 100 ms apart; let go when lifted.
    expect(await drag(false)).to.deep.equal([[1000, 'move', 8, 1], [1056, 'move', 9, 1], [1152, 'move', 10, 1], [1400, 'release']]);
    // Lifted at 900 ms: the 250 ms before the lift, 350 ms behind: x 7 (600 ms) at once, x 8, 9, 10, then the release.
    expect(await drag(true)).to.deep.equal([[1000, 'move', 7, 1], [1056, 'move', 8, 1], [1152, 'move', 9, 1], [1256, 'move', 10, 1], [1256, 'release']]);
    expect(r.clock.pending).to.equal(0);
  });

  it('a quick flick answered 400 ms late (after the lift) is replayed whole, 400 ms behind', async () => {
    const r = mounted();
    const answer = answerLater(r);
    flick(r);
    r.clock.advance(344);
    answer.resolve(4);
    await settle();
    r.clock.advance(200);
    expect(r.log).to.deep.equal([[416, 'move', 3, 1], [432, 'move', 5, 1], [448, 'move', 7, 1], [456, 'release']]);
  });

  it('a grab answered after the scene left the document, or replaced by a new press, or whose engine went, lets go at once', async () => {
    const r = mounted();
    // Flicked, then removed before the answer: released when answered, nothing replayed.
    let answer = deferred<number | null>();
    r.engine.answers.grab = () => answer.promise;
    host.dispatchEvent(at('pointerdown', 10, 10));
    r.clock.advance(16);
    host.dispatchEvent(at('pointermove', 50, 10));
    host.dispatchEvent(at('pointerup', 50, 10));
    host.remove();
    answer.resolve(3);
    await settle();
    r.clock.advance(100);
    expect(r.log).to.deep.equal([[16, 'release']]);
    expect(r.drag.grab).to.equal(null);
    // Removed while replaying: released at once, the replay stops.
    document.body.append(host);
    r.log.length = 0;
    const flick = async (grab: number) => {
      answer = deferred<number | null>();
      r.engine.answers.grab = () => answer.promise;
      host!.dispatchEvent(at('pointerdown', 10, 10));
      r.clock.advance(16);
      host!.dispatchEvent(at('pointermove', 50, 10));
      host!.dispatchEvent(at('pointerup', 50, 10));
      r.clock.advance(20);
      answer.resolve(grab);
      await settle();
      expect(r.drag.grab).to.equal(grab);
      return r.clock.time;
    };
    let t = await flick(5);
    host.remove();
    r.clock.advance(100);
    expect(r.log).to.deep.equal([[t, 'release']]);
    expect(r.clock.pending).to.equal(0);
    // A new press while a throw replays: the throw lets go where it is; the press grabs.
    document.body.append(host);
    r.log.length = 0;
    t = await flick(6);
    r.engine.answers.grab = () => 9;
    host.dispatchEvent(at('pointerdown', 20, 20));
    await settle();
    expect(r.log).to.deep.equal([[t, 'release']]);
    expect(r.engine.argsOf('release').at(-1)).to.deep.equal([6]);
    expect(r.drag.grab).to.equal(9);
    host.dispatchEvent(at('pointerup', 20, 20));
    // The engine replaced while a throw replays: released to the engine that holds it, nothing sent to the new one.
    r.log.length = 0;
    t = await flick(10);
    const next = new FakeEngine('new');
    r.replace(next);
    r.clock.advance(100);
    expect(r.log).to.deep.equal([[t + 8, 'release']]);
    expect(next.calls).to.deep.equal([]);
    // cancel() while a throw replays (the engine is gone): nothing more is sent, no timer is left.
    r.replace(r.engine);
    r.log.length = 0;
    await flick(11);
    r.drag.cancel();
    expect(r.drag.grab).to.equal(null);
    r.clock.advance(100);
    expect(r.log).to.deep.equal([]);
    expect(r.clock.pending).to.equal(0);
  });

  it('with a real engine, a flick lifted before the answer throws the body as the same flick answered at once does, 100 ms later', async () => {
    /** A 1 × 1 box at (3, 5), no gravity; a flick from x 3.2 to 6 in 80 ms; the grab answered after `delay` ms. */
    const throwBox = async (delay: number) => {
      const r = mounted();
      const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false });
      const box = createBox(world, { x: 3, y: 5, width: 1, height: 1 }).body;
      const answer = deferred<number | null>();
      r.engine.answers.grab = (x: number, y: number) => (delay === 0 ? world.grab(x, y) : answer.promise);
      r.engine.answers.moveGrab = (g: number, x: number, y: number) => world.moveGrab(g, x, y);
      r.engine.answers.release = (g: number) => world.release(g);
      // The engine steps at 60 Hz of the same clock.
      const steps = r.clock.setInterval(() => world.step(1 / 60), 1000 / 60);
      host.dispatchEvent(at('pointerdown', 32, 51));
      await settle();
      for (let x = 39; x <= 60; x += 7) {
        r.clock.advance(16);
        host.dispatchEvent(at('pointermove', x, 51));
      }
      r.clock.advance(16);
      host.dispatchEvent(at('pointerup', 60, 51));
      if (delay > 0) {
        r.clock.advance(delay - 80);
        answer.resolve(world.grab(3.2, 5.1));
        await settle();
      }
      // Seen at 700 ms: released at 80 ms, or 100 ms later with the late answer.
      r.clock.advance(700 - r.clock.time);
      const v = world.bodyVelocity(box);
      const p = world.getPosition(box);
      r.clock.clearInterval(steps);
      host.remove();
      return { x: p.x, vx: v.x, vy: v.y, grabs: world.grabs.count };
    };
    const atOnce = await throwBox(0);
    const late = await throwBox(100);
    // Thrown to the right at about the pointer's speed (2.8 units in 80 ms, 35 u/s; the damped grab throws it at 36.5,
    // the undamped one, still swinging when let go, threw it at 70.6), the grab let go.
    expect(atOnce.vx).to.be.within(28, 46);
    expect(atOnce.grabs).to.equal(0);
    expect(late.grabs).to.equal(0);
    // The same throw, 100 ms (6 steps) later.
    expect(late.vx).to.be.closeTo(atOnce.vx, 1e-9);
    expect(late.vy).to.be.closeTo(atOnce.vy, 1e-9);
    expect(late.x).to.be.closeTo(atOnce.x - 6 * atOnce.vx / 60, 1e-6);
  });

  it('a press on nothing, with the right button, or with no engine makes no drag', async () => {
    const r = mounted();
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
    const r = mounted();
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
    const r = mounted();
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
    expect(rounded(r.engine.argsOf('moveGrab'))).to.deep.equal([[5, 4.1, 2]]);
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
    const r = mounted();
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
