// The keyboard alternative to dragging, while the scene itself has focus: Tab and Shift+Tab pick the bodies one by one
// (after the last, Tab leaves the scene as usual; before the first, Shift+Tab comes back to the scene), the arrow keys
// push the picked body (with nothing picked, an arrow key picks the first), Escape lets go of it and the Tab after it
// leaves the scene (a scene of many bodies is two keys to pass, not one per body), R resets the scene.
// A ring drawn over the canvas (a DOM overlay placed from the body's box in the newest frame) shows the picked body,
// and a live region tells screen readers ("Picked box 2 of 5", "Reset", "Paused"). Space pauses and plays.
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import type { Box } from './outlines.js';

/** A body one can pick: its key and what to call it ("box", or the element's own label). */
export interface PickableBody {
  key: number;
  label: string;
}

export interface KeyboardOptions {
  /** The bodies one can pick, in order (none before the engine runs). */
  bodies(): PickableBody[];
  /** Where body `key` is drawn now, in the stage's CSS pixels, or null. */
  bounds(key: number): Box | null;
  /** Pushes body `key`: one press of an arrow key in direction (dx, dy), a unit vector (y grows downward). */
  push(key: number, dx: number, dy: number): void;
  reset(): void;
  /** Pauses a running scene or plays a paused one (Space); returns whether it is paused now. */
  togglePause(): boolean;
  /** The ring that shows the picked body (an element of the shadow root), or null before the first render. */
  ring(): HTMLElement | null;
  /** The live region for announcements, or null before the first render. */
  liveRegion(): HTMLElement | null;
}

/** CSS pixels between the picked body's box and its ring. */
const RING_GAP = 4;

const ARROWS: Record<string, [number, number]> = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };

/** @internal */
export class KeyboardController implements ReactiveController {
  private pickedKey: number | null = null;
  /** Escape let go of the bodies: the next Tab leaves the scene instead of picking the first again. */
  private letGo = false;
  private frame = 0;

  constructor(
    private readonly host: ReactiveControllerHost & HTMLElement,
    private readonly options: KeyboardOptions,
  ) {
    host.addController(this);
    host.addEventListener('keydown', this.onKeyDown);
    host.addEventListener('blur', this.onBlur);
  }

  /** The picked body's key, or null. */
  get picked(): number | null {
    return this.pickedKey;
  }

  hostConnected(): void {
    const host = this.host;
    if (!host.hasAttribute('aria-description') && !host.hasAttribute('aria-describedby')) {
      host.setAttribute('aria-description', 'Tab picks a body, arrow keys push it, Escape then Tab leaves, R resets, Space pauses');
    }
  }

  hostDisconnected(): void {
    this.cancel();
  }

  /** Forgets the picked body (the engine that had it stopped, or focus left the scene), silently. */
  cancel(): void {
    this.letGo = false;
    this.pick(null, false);
  }

  /** Says `text` in the live region (again, also when it is what it said last). */
  announce(text: string): void {
    const region = this.options.liveRegion();
    if (!region) return;
    // The same words twice are a change too: alternate a trailing no-break space.
    region.textContent = region.textContent === text ? `${text}\u00a0` : text;
  }

  /** Picks body `key` (null: none); the ring follows it while it is picked. */
  private pick(key: number | null, say: boolean): void {
    this.pickedKey = key;
    if (key === null) {
      cancelAnimationFrame(this.frame);
      this.frame = 0;
      const ring = this.options.ring();
      if (ring) ring.hidden = true;
    } else if (!this.frame) this.frame = requestAnimationFrame(this.follow);
    if (!say) return;
    if (key === null) {
      this.announce('Nothing picked');
      return;
    }
    const bodies = this.options.bodies();
    const k = bodies.findIndex((b) => b.key === key);
    this.announce(`Picked ${bodies[k].label} ${k + 1} of ${bodies.length}`);
  }

  /** Places the ring around the picked body, every frame while one is picked; lets go of a body that is gone. */
  private readonly follow = (): void => {
    this.frame = 0;
    const key = this.pickedKey;
    const ring = this.options.ring();
    if (key === null || !ring) return;
    if (!this.options.bodies().some((b) => b.key === key)) {
      this.pick(null, true);
      return;
    }
    const box = this.options.bounds(key);
    ring.hidden = box === null;
    if (box) {
      ring.style.left = `${box.left - RING_GAP}px`;
      ring.style.top = `${box.top - RING_GAP}px`;
      ring.style.width = `${box.right - box.left + 2 * RING_GAP}px`;
      ring.style.height = `${box.bottom - box.top + 2 * RING_GAP}px`;
    }
    this.frame = requestAnimationFrame(this.follow);
  };

  private readonly onBlur = (): void => {
    this.cancel();
  };

  private readonly onKeyDown = (event: Event): void => {
    const e = event as KeyboardEvent;
    // Keys for the scene itself (not its play button), without a modifier that makes them someone else's shortcut.
    if (e.composedPath()[0] !== this.host || e.altKey || e.ctrlKey || e.metaKey) return;
    const bodies = this.options.bodies();
    const at = this.pickedKey === null ? -1 : bodies.findIndex((b) => b.key === this.pickedKey);
    const letGo = this.letGo;
    this.letGo = false;
    if (e.key === 'Tab') {
      // The scene, then each body, in the page's tab order: past the last body (or back before the scene) Tab leaves;
      // so does Tab after Escape.
      const next = e.shiftKey ? (at < 0 ? -2 : at - 1) : letGo && at < 0 ? bodies.length : at + 1;
      if (next < -1 || next >= bodies.length) {
        this.pick(null, false);
        return;
      }
      e.preventDefault();
      this.pick(next < 0 ? null : bodies[next].key, true);
      return;
    }
    if (e.key === ' ' || e.code === 'Space') {
      e.preventDefault();
      if (!e.repeat) this.announce(this.options.togglePause() ? 'Paused' : 'Playing');
      return;
    }
    if (e.shiftKey) return;
    const arrow = ARROWS[e.key];
    if (arrow) {
      if (bodies.length === 0) return;
      e.preventDefault();
      if (at < 0) this.pick(bodies[0].key, true);
      else this.options.push(bodies[at].key, arrow[0], arrow[1]);
    } else if (e.key === 'Escape') {
      this.letGo = true;
      if (at < 0) return;
      e.preventDefault();
      this.pick(null, true);
    } else if (e.key === 'r' || e.key === 'R') {
      e.preventDefault();
      if (e.repeat) return;
      this.options.reset();
      this.announce('Reset');
    }
  };
}
