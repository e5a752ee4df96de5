// Pointer drag: a press on a body grabs it (the engine holds it at the pointer with a soft constraint), moves follow
// the pointer, and letting go releases it with the speed the drag gave it. One pointer at a time.
//
// Touch (and pen) on a page that scrolls: the element allows panning and pinch-zoom (touch-action: manipulation), so
// a finger that lands where no body is drawn scrolls or zooms the page as anywhere else. Whether a touch drags is
// decided when it lands, synchronously, by a hit test against the newest frame as drawn (`hit`): a touch on a body
// starts a drag and its touchstart is cancelled (the page does not scroll); any other touch is left to the browser.
// Only the primary pointer drags, so a second finger makes a pinch, not a second drag. A mouse press asks the engine
// (the page never scrolls on a mouse press).
//
// A grab is the engine's answer to the press, and it comes later (a worker round trip; longer under load). Until it
// comes, the pointer's moves are recorded with their times; once it comes, the grab replays them at the pace they were
// made, behind the pointer by the time the answer took, and a lift is replayed as a release at its place in that
// replay. At most the last MAX_LAG of the drag is replayed (the grab first jumps to where the pointer was then). So a quick flick lifted before the answer throws the body as a flick whose grab was there from
// the start would (the release is the normal one: the body keeps the velocity the moving grab gave it); a tap, lifted
// without moving, releases at once (no throw). While the pointer is held, the replay ends as soon as it has caught up
// (the pointer rested for the lag): from then on moves go straight to the grab.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { realClock, type Clock } from './recovery.js';
import type { Engine } from './session.js';

/** How often a replay sends the pointer's next recorded position (ms). */
const REPLAY_TICK = 8;
/**
 * How much of a drag a late answer replays (ms): the last this long before the answer (pointer held) or before the
 * lift. Earlier moves are skipped (the grab jumps to where the pointer was then), so a long drag under load does not
 * trail its pointer by seconds, while a flick lifted before the answer is replayed to its end, however late the answer.
 */
const MAX_LAG = 250;

export interface PointerOptions {
  /** The engine to grab in (null: none). */
  engine(): Pick<Engine, 'api'> | null;
  /** Viewport → world units (NaN without a canvas). */
  toWorld(x: number, y: number): { x: number; y: number };
  /**
   * A body one may drag drawn at (or within a finger's width of) this viewport point, now: the viewport point on it
   * where to take it, or null.
   */
  hit(x: number, y: number): { x: number; y: number } | null;
  /** Time and timers (performance.now and window's intervals unless told; unit tests pass a fake clock). */
  clock?: Clock;
}

/** Where the grab should go (world units) and when the pointer was there (clock ms). */
interface Sample {
  t: number;
  x: number;
  y: number;
}

interface Drag {
  pointer: number;
  /** The engine the grab was asked of (it holds the grab). */
  engine: Pick<Engine, 'api'>;
  /** The engine's grab, once it answered (null until then, after the release, or when the press hit nothing). */
  grab: number | null;
  /** Where the pointer holds the body now, in world units: the pointer, plus `dx`, `dy`. */
  x: number;
  y: number;
  /** From the pointer to the point taken (a touch near a body's edge takes the nearest point on it). */
  dx: number;
  dy: number;
  /** A finger or pen: its touchstart is cancelled so the page does not scroll. */
  touch: boolean;
  /** When the press was made (clock ms). */
  at: number;
  /** Moves not yet sent to the grab (before the answer, and while a replay runs), oldest first. */
  queue: Sample[];
  /** How far the grab's replay runs behind the pointer (ms). */
  lag: number;
  /** When the pointer was lifted (clock ms), null while it is held. */
  liftedAt: number | null;
  /** Over: released, or given up (scene left, engine gone); a grab answered later is released at once. */
  over: boolean;
  /** The replay's interval while one runs. */
  timer: number | null;
}

/** @internal */
export class PointerDragController implements ReactiveController {
  /** The drag of the pointer held now. */
  private drag: Drag | null = null;
  /** A drag whose pointer was lifted and whose grab is still to answer or to replay to the lift (at most one). */
  private tail: Drag | null = null;
  private readonly clock: Clock;

  constructor(
    host: ReactiveControllerHost,
    private readonly options: PointerOptions,
  ) {
    this.clock = options.clock ?? realClock;
    host.addController(this);
  }

  /** Out of the document the pointer capture is lost and no pointerup will come: let go now (replays too). */
  hostDisconnected(): void {
    if (this.drag) this.finish(this.drag);
    if (this.tail) this.finish(this.tail);
  }

  /** The grab held now (snapshots note it, so that a restore lets go of it), or null. */
  get grab(): number | null {
    return this.drag?.grab ?? this.tail?.grab ?? null;
  }

  /** Forgets the drags (the engine that held them is gone): nothing more is sent to it, and a late answer is released. */
  cancel(): void {
    for (const d of [this.drag, this.tail]) {
      if (!d) continue;
      d.over = true;
      d.grab = null;
      this.stop(d);
    }
    this.drag = this.tail = null;
  }

  readonly down = (e: PointerEvent): void => {
    const engine = this.options.engine();
    const touch = e.pointerType !== 'mouse';
    if (!engine || this.drag || (touch ? !e.isPrimary : e.button !== 0)) return;
    const pointer = this.options.toWorld(e.clientX, e.clientY);
    if (!Number.isFinite(pointer.x)) return;
    // Nothing to drag under the finger: the touch belongs to the page (scroll, zoom).
    const at = touch ? this.options.hit(e.clientX, e.clientY) : null;
    if (touch && !at) return;
    const p = at ? this.options.toWorld(at.x, at.y) : pointer;
    try {
      (e.currentTarget as Element).setPointerCapture(e.pointerId);
    } catch {
      // Synthetic events have no active pointer to capture.
    }
    // One grab at a time: a throw still being replayed lets go where it is.
    if (this.tail) this.finish(this.tail);
    const drag: Drag = {
      pointer: e.pointerId, engine, grab: null, x: p.x, y: p.y, dx: p.x - pointer.x, dy: p.y - pointer.y, touch,
      at: this.clock.now(), queue: [], lag: 0, liftedAt: null, over: false, timer: null,
    };
    this.drag = drag;
    e.preventDefault();
    engine.api.grab(p.x, p.y).then(
      (grab) => this.answered(drag, grab),
      () => this.finish(drag),
    );
  };

  /**
   * The touchstart listener (not passive): cancelled when the touch drags a body, so the page does not scroll. Pointer
   * events come first (the drag is decided by then); a touchstart with no pointerdown before it asks the hit test.
   */
  readonly touchStart = (e: TouchEvent): void => {
    if (e.touches.length !== 1 || !e.cancelable) return;
    const t = e.changedTouches[0];
    if (this.drag?.touch || (!this.drag && t && this.options.hit(t.clientX, t.clientY) !== null)) e.preventDefault();
  };

  readonly move = (e: PointerEvent): void => {
    const d = this.drag;
    if (!d || e.pointerId !== d.pointer || !this.options.engine()) return;
    const p = this.options.toWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    const x = p.x + d.dx;
    const y = p.y + d.dy;
    if (x === d.x && y === d.y) return;
    d.x = x;
    d.y = y;
    if (d.grab !== null && d.timer === null) d.engine.api.moveGrab(d.grab, x, y).catch(() => {});
    else d.queue.push({ t: this.clock.now(), x, y });
  };

  readonly up = (e: PointerEvent): void => {
    const d = this.drag;
    if (!d || e.pointerId !== d.pointer) return;
    this.drag = null;
    d.liftedAt = this.clock.now();
    // Held and caught up: let go now. Else the release waits for the answer and the replay up to the lift.
    if (d.grab !== null && d.timer === null) this.finish(d);
    else this.tail = d;
    try {
      (e.currentTarget as Element).releasePointerCapture(e.pointerId);
    } catch {
      // Not captured.
    }
  };

  /** The engine answered the press of `d`. */
  private answered(d: Drag, grab: number | null): void {
    if (grab === null) {
      this.finish(d);
      return;
    }
    // Given up meanwhile (the scene left, a new press, the engine replaced): release at once.
    if (d.over || this.options.engine() !== d.engine) {
      d.engine.api.release(grab).catch(() => {});
      this.finish(d);
      return;
    }
    d.grab = grab;
    if (d.queue.length === 0) {
      // Not moved: held where pressed; a tap (already lifted) lets go at once, with nothing to throw.
      if (d.liftedAt !== null) this.finish(d);
      return;
    }
    const now = this.clock.now();
    d.lag = now - Math.max(d.at, (d.liftedAt ?? now) - MAX_LAG);
    d.timer = this.clock.setInterval(() => this.replay(d), REPLAY_TICK);
    this.replay(d);
  }

  /** Sends the newest recorded move now due; at the end of the queue, goes live (held) or lets go (lifted). */
  private replay(d: Drag): void {
    if (d.grab === null || this.options.engine() !== d.engine) {
      this.finish(d);
      return;
    }
    const due = this.clock.now() - d.lag;
    let next: Sample | null = null;
    while (d.queue.length > 0 && d.queue[0].t <= due) next = d.queue.shift()!;
    if (next) d.engine.api.moveGrab(d.grab, next.x, next.y).catch(() => {});
    if (d.queue.length > 0) return;
    if (d.liftedAt === null) this.stop(d);
    else if (d.liftedAt <= due) this.finish(d);
  }

  /** Ends a drag: its grab (if answered) is released, its replay stopped; an answer still to come is released. */
  private finish(d: Drag): void {
    d.over = true;
    this.stop(d);
    if (this.drag === d) this.drag = null;
    if (this.tail === d) this.tail = null;
    if (d.grab === null) return;
    d.engine.api.release(d.grab).catch(() => {});
    d.grab = null;
  }

  private stop(d: Drag): void {
    if (d.timer === null) return;
    this.clock.clearInterval(d.timer);
    d.timer = null;
  }
}
