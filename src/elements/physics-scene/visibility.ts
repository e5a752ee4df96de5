// When the scene may run: on screen (IntersectionObserver) with the page visible (Page Visibility) and not paused.
// When it may start: once it comes near the viewport (within about a viewport's height or width of it, a second
// observer with a root margin), or once a script asks for it (ready, step(), …): a post with many scenes starts only
// those a reader is about to see.
// With `prefers-reduced-motion: reduce` it starts paused and shows a play control, as a pause with Space does (the
// keyboard controller's, while the scene has focus: it is focusable, with a role, a label and its key shortcuts, unless
// the page set its own).
import type { ReactiveController, ReactiveControllerHost } from 'lit';
import { track } from '../../worker/resources.js';

/** The scene as the visibility controller sees it. */
export interface VisibilityHost extends ReactiveControllerHost, HTMLElement {
  paused: boolean;
}

/**
 * Something that reports whether an element is on screen (an IntersectionObserver), until disconnected; with
 * `margin` (a CSS rootMargin), whether it is within that margin of the viewport.
 */
export type IntersectionWatch = (target: Element, changed: (onScreen: boolean) => void, margin?: string) => { disconnect(): void };

/** How near the viewport a scene starts: one viewport's size around it. */
export const NEAR_MARGIN = '100% 100% 100% 100%';

/**
 * A scene near the viewport but not on it starts once the page is idle (at most this many ms later), so the scenes a
 * reader sees start first; on screen meanwhile, it starts at once.
 */
const OFF_SCREEN_START_MS = 1000;

export interface VisibilityOptions {
  /** On screen or the page's visibility changed. */
  changed(): void;
  /** The default `aria-label`. */
  label(): string;
  /** Watches the element on screen; default: an IntersectionObserver (none where there is no IntersectionObserver). */
  intersection?: IntersectionWatch | null;
  /** Watches the element come near the viewport (called with NEAR_MARGIN); default: as `intersection`'s default. */
  nearby?: IntersectionWatch | null;
  /** Whether the user asks for reduced motion; default: the `prefers-reduced-motion` media query. */
  reducedMotion?: () => boolean;
}

const intersectionObserver: IntersectionWatch = (target, changed, margin) => {
  const io = new IntersectionObserver(
    (entries) => {
      const e = entries[entries.length - 1];
      if (e) changed(e.isIntersecting);
    },
    margin ? { rootMargin: margin } : undefined,
  );
  io.observe(target);
  return io;
};

const prefersReducedMotion = (): boolean => typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;

/** @internal */
export class VisibilityController implements ReactiveController {
  /** The play control is shown (while paused). */
  playControl = false;
  /** On screen, as the observer last reported (assumed until its first report, the next frame). */
  private inView = true;
  private pageVisible = typeof document === 'undefined' || document.visibilityState !== 'hidden';
  private watch: { disconnect(): void } | null = null;
  private watching = false;
  /** Near the viewport once (or asked for by a script) since connected: the scene may start. */
  private near = false;
  private nearWatch: { disconnect(): void } | null = null;
  /** Near but not on screen: the idle callback (or timer) that will start it. */
  private nearSoon: (() => void) | null = null;
  /** Starts waiting for the scene to come near. */
  private nearWaiters: (() => void)[] = [];
  private motionChecked = false;
  /** play() was called: the page wants motion, reduced-motion preference or not. */
  private playRequested = false;
  private readonly intersection: IntersectionWatch | null;
  private readonly nearby: IntersectionWatch | null;
  private readonly reducedMotion: () => boolean;

  constructor(
    private readonly host: VisibilityHost,
    private readonly options: VisibilityOptions,
  ) {
    const observer = typeof IntersectionObserver === 'function' ? intersectionObserver : null;
    this.intersection = options.intersection !== undefined ? options.intersection : observer;
    this.nearby = options.nearby !== undefined ? options.nearby : observer;
    this.reducedMotion = options.reducedMotion ?? prefersReducedMotion;
    host.addController(this);
  }

  /** In the document, on screen and the page visible (frames are drawn). */
  get onScreen(): boolean {
    // Removed, it is on no screen: its last observer report (kept for a move back) no longer counts.
    return this.host.isConnected && this.inView && this.pageVisible;
  }

  /** Not paused, on screen and the page visible (the engine steps). */
  get running(): boolean {
    return !this.host.paused && this.onScreen;
  }

  /**
   * Resolves once the scene is near the viewport, or a script asked for it (demand()), or it left the document (the
   * start waiting on it is then stale). At once where there is no IntersectionObserver.
   */
  whenNear(): Promise<void> {
    if (this.near || !this.host.isConnected) return Promise.resolve();
    return new Promise((resolve) => this.nearWaiters.push(resolve));
  }

  /** A script wants the scene (ready, step(), …): it starts wherever it is. */
  demand(): void {
    this.nowNear();
  }

  /** Runs the scene (clears `paused`); from now on a reduced-motion preference does not pause it. */
  play(): void {
    this.playRequested = true;
    this.host.paused = false;
  }

  /** Space: plays a paused scene, or pauses it and shows the play control. Returns whether it is paused now. */
  toggle(): boolean {
    if (this.host.paused) this.play();
    else {
      this.host.paused = this.playControl = true;
      this.host.requestUpdate();
    }
    return this.host.paused;
  }

  hostConnected(): void {
    const host = this.host;
    if (!host.hasAttribute('tabindex')) host.tabIndex = 0;
    if (!host.hasAttribute('role')) host.setAttribute('role', 'group');
    if (!host.hasAttribute('aria-label') && !host.hasAttribute('aria-labelledby')) host.setAttribute('aria-label', this.options.label());
    if (!host.hasAttribute('aria-keyshortcuts')) host.setAttribute('aria-keyshortcuts', 'Space R');
    if (!this.motionChecked) {
      this.motionChecked = true;
      if (!this.host.paused && !this.playRequested && this.reducedMotion()) this.toggle();
    }
    this.setWatching(true);
    // Back in the document (or in it for the first time): the scene's running state follows at once.
    this.options.changed();
  }

  hostDisconnected(): void {
    this.setWatching(false);
    // Back in the document it waits to come near again; starts waiting now are stale and let go.
    this.near = false;
    this.releaseNear();
  }

  hostUpdate(): void {
    if (!this.host.paused) this.playControl = false;
  }

  /** The play control's click handler. */
  readonly onPlayClick = (e: Event): void => {
    e.stopPropagation();
    this.play();
    this.host.focus();
  };

  private setWatching(on: boolean): void {
    if (on === this.watching) return;
    this.watching = on;
    if (on) {
      if (this.intersection) {
        this.watch = this.intersection(this.host, (inView) => {
          this.inView = inView;
          if (inView && this.nearWatch) this.nowNear();
          this.options.changed();
        });
        track('observers', 1);
      }
      if (!this.near) {
        if (this.nearby) {
          this.nearWatch = this.nearby(this.host, (near) => near && (this.inView ? this.nowNear() : this.nearWhenIdle()), NEAR_MARGIN);
          track('observers', 1);
          // A watch that answered at once.
          if (this.near) this.stopNearWatch();
        } else this.nowNear();
      }
      this.pageVisible = document.visibilityState !== 'hidden';
      document.addEventListener('visibilitychange', this.onVisibility);
      track('listeners', 1);
    } else {
      if (this.watch) {
        this.watch.disconnect();
        this.watch = null;
        track('observers', -1);
      }
      this.stopNearWatch();
      document.removeEventListener('visibilitychange', this.onVisibility);
      track('listeners', -1);
    }
  }

  /** Near for good (until disconnected): the near watch ends, the starts waiting go on. */
  private nowNear(): void {
    this.near = true;
    this.stopNearWatch();
    this.releaseNear();
  }

  /** Near, not on screen: starts when the page is idle, after the scenes on screen. */
  private nearWhenIdle(): void {
    if (this.nearSoon) return;
    if (typeof requestIdleCallback === 'function') {
      const id = requestIdleCallback(() => this.nowNear(), { timeout: OFF_SCREEN_START_MS });
      this.nearSoon = () => cancelIdleCallback(id);
    } else {
      const id = setTimeout(() => this.nowNear(), OFF_SCREEN_START_MS / 4);
      this.nearSoon = () => clearTimeout(id);
    }
  }

  private stopNearWatch(): void {
    this.nearSoon?.();
    this.nearSoon = null;
    if (!this.nearWatch) return;
    this.nearWatch.disconnect();
    this.nearWatch = null;
    track('observers', -1);
  }

  private releaseNear(): void {
    for (const resolve of this.nearWaiters.splice(0)) resolve();
  }

  private readonly onVisibility = (): void => {
    this.pageVisible = document.visibilityState !== 'hidden';
    this.options.changed();
  };

}
