// The page's colour scheme, which the scene's default colours follow: a page that declares itself dark (`color-scheme:
// dark` on its root or any ancestor of the scene, `<meta name="color-scheme" content="dark">`, or "light dark" for a
// reader whose system prefers dark) gets a dark canvas and light lines; a page that declares nothing stays light
// whatever the reader's system prefers (its own text and background are light then too). Colours the page sets on
// the scene (`background`, `fill`, `stroke`) are never changed.
//
// The browser resolves the scheme: a hidden probe in the shadow root has `light-dark()` colours and the controller
// reads which one applies. A page that switches its scheme later (a theme toggle on <html>, the system going dark at
// dusk) changes the probe's colour, whose transition fires an event: no polling, no observer of the whole page.
import { css, type ReactiveController, type ReactiveControllerHost } from 'lit';

export type ColourScheme = 'light' | 'dark';

/**
 * The probe's styles (part of the scene's styles). Its background is read: white where the used scheme is dark
 * (browsers without light-dark() keep the black: light). Its colour is not read: its transition announces a change of
 * scheme (transitionrun), when the final background can be read. Forced colours (a high-contrast theme) would paint
 * it the theme's Canvas colour, white for a light theme: they are turned off for the probe. @internal
 */
export const schemeProbeStyles = css`
  .scheme {
    position: absolute;
    width: 0;
    height: 0;
    overflow: hidden;
    visibility: hidden;
    forced-color-adjust: none;
    background-color: #000;
    background-color: light-dark(#000, #fff);
    color: #000001;
    color: light-dark(#000001, #fffffe);
    transition: color 1ms;
  }
`;

export interface SchemeOptions {
  /** The probe element in the shadow root (made with the root: read before the first render), or null. */
  probe(): HTMLElement | null;
  /** The scheme changed since the last reading (the first reading counts when it is not light, the default). */
  changed(scheme: ColourScheme): void;
}

/** A probe for the shadow root: `.scheme` in the scene's styles. @internal */
export function schemeProbe(): HTMLElement {
  const probe = document.createElement('span');
  probe.className = 'scheme';
  probe.setAttribute('aria-hidden', 'true');
  return probe;
}

/** The probe's transition events: any of them means its colour may have changed (one is enough; all are cheap). */
const TRANSITION_EVENTS = ['transitionrun', 'transitionend', 'transitioncancel'] as const;

/** @internal */
export class ColourSchemeController implements ReactiveController {
  /** The scheme the page's CSS gives the scene (read before each update and when the page switches it). */
  scheme: ColourScheme = 'light';
  private watched: HTMLElement | null = null;
  /** The reader's preference: a page of "light dark" follows it (also read there through the probe). */
  private preference: MediaQueryList | null = null;

  constructor(
    host: ReactiveControllerHost,
    private readonly options: SchemeOptions,
  ) {
    host.addController(this);
  }

  /** Connected (again, after a move): listening, and the scheme read, as it may have changed meanwhile. */
  hostConnected(): void {
    this.watch();
    this.preference = typeof matchMedia === 'function' ? matchMedia('(prefers-color-scheme: dark)') : null;
    this.preference?.addEventListener('change', this.read);
    this.read();
  }

  /** Before each update (before the configuration is read), so the first render already has the page's scheme. */
  hostUpdate(): void {
    this.watch();
    this.read();
  }

  hostDisconnected(): void {
    for (const type of TRANSITION_EVENTS) this.watched?.removeEventListener(type, this.read);
    this.watched = null;
    this.preference?.removeEventListener('change', this.read);
    this.preference = null;
  }

  private watch(): void {
    const probe = this.options.probe();
    if (probe === this.watched) return;
    for (const type of TRANSITION_EVENTS) {
      this.watched?.removeEventListener(type, this.read);
      probe?.addEventListener(type, this.read);
    }
    this.watched = probe;
  }

  /** Reads the scheme from the probe and tells the host when it changed. */
  private readonly read = (): void => {
    const probe = this.watched;
    if (!probe?.isConnected) return;
    const scheme: ColourScheme = getComputedStyle(probe).backgroundColor === 'rgb(255, 255, 255)' ? 'dark' : 'light';
    if (scheme === this.scheme) return;
    this.scheme = scheme;
    this.options.changed(scheme);
  };
}

/** The default colours that differ between the schemes. @internal */
export const SCHEME_COLOURS = {
  light: { background: '#f7f5f0', ragdoll: '#333a44', rope: '#8e5a2b' },
  dark: { background: '#1d2025', ragdoll: '#d3d8e0', rope: '#b57a45' },
} as const satisfies Record<ColourScheme, Record<string, string>>;
