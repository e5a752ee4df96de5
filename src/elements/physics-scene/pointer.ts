// Pointer drag: a press on a body grabs it (the engine holds it at the pointer with a soft constraint), moves follow
// the pointer, and letting go releases it with the speed the drag gave it. One pointer at a time.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Engine } from './session.js';

export interface PointerOptions {
  /** The engine to grab in (null: none). */
  engine(): Pick<Engine, 'api'> | null;
  /** Viewport → world units (NaN without a canvas). */
  toWorld(x: number, y: number): { x: number; y: number };
}

interface Drag {
  pointer: number;
  /** The engine's grab, once it answered (null until then, or when the press hit nothing). */
  grab: number | null;
  /** Where the pointer is, in world units. */
  x: number;
  y: number;
  /** Let go (possibly before the engine answered the grab). */
  done: boolean;
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
    if (!engine || this.drag || (e.pointerType === 'mouse' && e.button !== 0)) return;
    const p = this.options.toWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    try {
      (e.currentTarget as Element).setPointerCapture(e.pointerId);
    } catch {
      // Synthetic events have no active pointer to capture.
    }
    const drag: Drag = { pointer: e.pointerId, grab: null, x: p.x, y: p.y, done: false };
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

  readonly move = (e: PointerEvent): void => {
    const d = this.drag;
    const engine = this.options.engine();
    if (!d || e.pointerId !== d.pointer || !engine) return;
    const p = this.options.toWorld(e.clientX, e.clientY);
    if (!Number.isFinite(p.x)) return;
    d.x = p.x;
    d.y = p.y;
    if (d.grab !== null) engine.api.moveGrab(d.grab, p.x, p.y).catch(() => {});
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
