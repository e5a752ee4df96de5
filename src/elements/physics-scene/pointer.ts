// Pointer drag: a press on a body grabs it (the engine holds it at the pointer with a soft constraint), moves follow
// the pointer, and letting go releases it with the speed the drag gave it. One pointer at a time.
//
// Touch (and pen) on a page that scrolls: the element allows panning and pinch-zoom (touch-action: manipulation), so
// a finger that lands where no body is drawn scrolls or zooms the page as anywhere else. Whether a touch drags is
// decided when it lands, synchronously, by a hit test against the newest frame as drawn (`hit`): a touch on a body
// starts a drag and its touchstart is cancelled (the page does not scroll); any other touch is left to the browser.
// Only the primary pointer drags, so a second finger makes a pinch, not a second drag. A mouse press asks the engine
// (the page never scrolls on a mouse press).
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Engine } from './session.js';

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
}

interface Drag {
  pointer: number;
  /** The engine's grab, once it answered (null until then, or when the press hit nothing). */
  grab: number | null;
  /** Where the grab holds the body, in world units: the pointer, plus `dx`, `dy`. */
  x: number;
  y: number;
  /** From the pointer to the point taken (a touch near a body's edge takes the nearest point on it). */
  dx: number;
  dy: number;
  /** Let go (possibly before the engine answered the grab). */
  done: boolean;
  /** A finger or pen: its touchstart is cancelled so the page does not scroll. */
  touch: boolean;
}

/** @internal */
export class PointerDragController implements ReactiveController {
  private drag: Drag | null = null;

  constructor(
    host: ReactiveControllerHost,
    private readonly options: PointerOptions,
  ) {
    host.addController(this);
  }

  /** Out of the document the pointer capture is lost and no pointerup will come: let go now. */
  hostDisconnected(): void {
    this.letGo();
  }

  /** The grab held now (snapshots note it, so that a restore lets go of it), or null. */
  get grab(): number | null {
    return this.drag?.grab ?? null;
  }

  /** Forgets the drag (the engine that held it is gone). */
  cancel(): void {
    this.drag = null;
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
    const drag: Drag = { pointer: e.pointerId, grab: null, x: p.x, y: p.y, dx: p.x - pointer.x, dy: p.y - pointer.y, done: false, touch };
    this.drag = drag;
    e.preventDefault();
    engine.api.grab(p.x, p.y).then(
      (grab) => {
        if (grab === null) {
          if (this.drag === drag) this.drag = null;
          return;
        }
        // Let go before the answer, or the engine replaced meanwhile: release at once.
        if (drag.done || this.options.engine() !== engine) {
          engine.api.release(grab).catch(() => {});
          return;
        }
        drag.grab = grab;
        engine.api.moveGrab(grab, drag.x, drag.y).catch(() => {});
      },
      () => {
        if (this.drag === drag) this.drag = null;
      },
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
    const engine = this.options.engine();
    if (!d || e.pointerId !== d.pointer || !engine) return;
    const p = this.options.toWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    d.x = p.x + d.dx;
    d.y = p.y + d.dy;
    if (d.grab !== null) engine.api.moveGrab(d.grab, d.x, d.y).catch(() => {});
  };

  readonly up = (e: PointerEvent): void => {
    if (!this.drag || e.pointerId !== this.drag.pointer) return;
    this.letGo();
    try {
      (e.currentTarget as Element).releasePointerCapture(e.pointerId);
    } catch {
      // Not captured.
    }
  };

  /** Ends the drag; a grab the engine answers later is released at once. */
  private letGo(): void {
    const d = this.drag;
    if (!d) return;
    d.done = true;
    this.drag = null;
    if (d.grab !== null) this.options.engine()?.api.release(d.grab).catch(() => {});
  }
}
