// A dark page gets a dark scene: the default colours follow the colour scheme the page declares (color-scheme on an
// ancestor, or "light dark" with the reader's preference), also when the page switches it later while the scene is
// paused; forced colours (a high-contrast theme) do not flip it; colours the page sets stay as set. Checked by what
// the canvas shows and by the computed colours of the messages.
import { expect } from '@open-wc/testing';
import { emulateForcedColors, emulateMedia } from './commands.js';
import type { PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, mount, pixelAt, rgb, unmount, waitFor } from './helpers.js';

const LIGHT = { background: '#f7f5f0', ragdoll: '#333a44', rope: '#8e5a2b' };
const DARK = { background: '#1d2025', ragdoll: '#d3d8e0', rope: '#b57a45' };

/** A ragdoll standing still in the middle (its head is a disc drawn in its line colour) and a rope across the top. */
const BODIES =
  '<physics-ragdoll x="5" y="6" height="3"></physics-ragdoll>' + '<physics-rope x1="1" y1="1.5" x2="9" y2="1.5" segments="8" pin="both"></physics-rope>';

/** Canvas pixels within 6 of `hex` in every channel. */
function pixelsNear(scene: PhysicsSceneElement, hex: string): number {
  const canvas = scene.canvas!;
  const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
  const colour = rgb(hex);
  let n = 0;
  for (let i = 0; i < data.length; i += 4) if (colourDistance([data[i], data[i + 1], data[i + 2]], colour) <= 6) n++;
  return n;
}

/** WCAG contrast ratio of two `rgb(…)` / `rgba(…)` computed colours (alpha ignored). */
function contrast(a: string, b: string): number {
  const luminance = (c: string) => {
    const [r, g, bl] = c.match(/[\d.]+/g)!.slice(0, 3).map((v) => {
      const s = Number(v) / 255;
      return s <= 0.03928 ? s / 12.92 : ((s + 0.055) / 1.055) ** 2.4;
    });
    return 0.2126 * r + 0.7152 * g + 0.0722 * bl;
  };
  const [hi, lo] = [luminance(a), luminance(b)].sort((x, y) => y - x);
  return (hi + 0.05) / (lo + 0.05);
}

// Discriminating both ways: no blend of one scheme's line colours with the other scheme's background comes near the
// other scheme's line colours (the dark ones are lighter than the light ones, and the backgrounds lie beyond both).
/** Waits until the canvas shows `palette`: its background in a corner, ragdoll heads and rope in its colours. */
async function shows(scene: PhysicsSceneElement, palette: typeof LIGHT, what: string): Promise<void> {
  await waitFor(() => colourDistance(pixelAt(scene, 0.2, 9.8), rgb(palette.background)) <= 2, `${what}: the background ${palette.background}`);
  await waitFor(() => pixelsNear(scene, palette.ragdoll) >= 20, `${what}: the ragdoll in ${palette.ragdoll}`);
  await waitFor(() => pixelsNear(scene, palette.rope) >= 20, `${what}: the rope in ${palette.rope}`);
}

describe('colour scheme', () => {
  let scene: PhysicsSceneElement | null = null;
  afterEach(async () => {
    unmount(scene);
    scene = null;
    document.documentElement.style.colorScheme = '';
    await emulateMedia({ colorScheme: 'light' });
  });

  it('a page declared dark gets a dark canvas with light ragdolls and ropes, and a page switched back the light one while paused', async () => {
    document.documentElement.style.colorScheme = 'dark';
    scene = await mount('width="10" height="10" gravity="0 0" paused', BODIES);
    await shows(scene, DARK, 'dark page');
    // A theme toggle on the page's root, the scene paused and idle.
    document.documentElement.style.colorScheme = 'light';
    await shows(scene, LIGHT, 'switched to light');
    // Moved within the page (disconnected and connected in one task: the engine stays): it still follows.
    const box = scene.parentElement!;
    box.remove();
    document.body.append(box);
    document.documentElement.style.colorScheme = 'dark';
    await shows(scene, DARK, 'switched back to dark after a move');
  });

  it('"light dark" follows the reader\'s preference; a page that declares nothing stays light for a reader who prefers dark; the scene\'s own color-scheme counts', async () => {
    await emulateMedia({ colorScheme: 'dark' });
    scene = await mount('width="10" height="10" gravity="0 0" paused', BODIES);
    await shows(scene, LIGHT, 'no color-scheme, reader prefers dark');
    document.documentElement.style.colorScheme = 'light dark';
    await shows(scene, DARK, '"light dark", reader prefers dark');
    await emulateMedia({ colorScheme: 'light' });
    await shows(scene, LIGHT, '"light dark", reader prefers light');
    // The scene's own color-scheme: one embed made dark on a light page.
    document.documentElement.style.colorScheme = '';
    scene.style.colorScheme = 'dark';
    await shows(scene, DARK, 'color-scheme: dark on the scene itself');
  });

  it('forced colours (a high-contrast theme) do not turn a light page\'s scene dark', async () => {
    await emulateForcedColors('active');
    try {
      expect(matchMedia('(forced-colors: active)').matches, 'forced colours emulated').to.equal(true);
      scene = await mount('width="10" height="10" gravity="0 0" paused', BODIES);
      await shows(scene, LIGHT, 'forced colours on a light page');
    } finally {
      await emulateForcedColors('none');
    }
  });

  it('colours the page sets stay as set on a dark page', async () => {
    document.documentElement.style.colorScheme = 'dark';
    scene = await mount(
      'width="10" height="10" gravity="0 0" paused background="#ffffff"',
      '<physics-ragdoll x="5" y="6" height="3" stroke="#ff0000"></physics-ragdoll><physics-rope x1="1" y1="1.5" x2="9" y2="1.5" segments="8" pin="both" stroke="#0000ff"></physics-rope>',
    );
    await shows(scene, { background: '#ffffff', ragdoll: '#ff0000', rope: '#0000ff' }, 'set colours');
    // On white, no blend of the set colours comes near the dark scheme's.
    expect(pixelsNear(scene, DARK.ragdoll)).to.equal(0);
    expect(pixelsNear(scene, DARK.rope)).to.equal(0);
  });

  it('the play control stands out on the canvas of either scheme: its disc (contrast at least 3) and its triangle on it (at least 4.5)', async () => {
    for (const [scheme, canvas] of [['light', LIGHT.background], ['dark', DARK.background]] as const) {
      document.documentElement.style.colorScheme = scheme;
      scene = await mount('width="10" height="10"', '');
      await waitFor(() => pixelsNear(scene!, canvas) > 0, `the ${scheme} canvas`);
      scene.focus();
      scene.dispatchEvent(new KeyboardEvent('keydown', { key: ' ', code: 'Space', bubbles: true, composed: true, cancelable: true }));
      await scene.updateComplete;
      const button = getComputedStyle(scene.shadowRoot!.querySelector('[part="play-button"]')!);
      // The disc is translucent: what shows is its colour laid over the canvas.
      const [r, g, b, a = 1] = button.backgroundColor.match(/[\d.]+/g)!.map(Number);
      const under = rgb(canvas);
      const disc = `rgb(${[r, g, b].map((c, i) => c * a + under[i] * (1 - a)).join(', ')})`;
      expect(contrast(disc, `rgb(${under.join(', ')})`), `${scheme}: disc ${disc} on the canvas ${canvas}`).to.be.at.least(3);
      expect(contrast(button.color, disc), `${scheme}: triangle ${button.color} on ${disc}`).to.be.at.least(4.5);
      unmount(scene);
      scene = null;
    }
  });

  it('the error box and the loading message are readable on a dark page (contrast at least 4.5)', async () => {
    document.documentElement.style.colorScheme = 'dark';
    document.body.style.background = '#121212';
    try {
      scene = await mount('width="10" height="10" gravity="0 0" paused', '<physics-box x="5" y="5" wdth="1"></physics-box>');
      const root = scene.shadowRoot!;
      const error = root.querySelector<HTMLElement>('.error')!;
      await waitFor(() => !error.hidden, 'the error box');
      const box = getComputedStyle(error);
      expect(contrast(box.color, box.backgroundColor), `error text ${box.color} on ${box.backgroundColor}`).to.be.at.least(4.5);
      // The loading message shows on the page's own background until the engine runs.
      const loading = await mount('', '', { ready: false });
      try {
        const status = await (async () => {
          await waitFor(() => loading.shadowRoot?.querySelector('.status') != null, 'the loading message');
          return getComputedStyle(loading.shadowRoot!.querySelector('.status')!).color;
        })();
        expect(contrast(status, 'rgb(18, 18, 18)'), `loading text ${status} on the page's #121212`).to.be.at.least(4.5);
      } finally {
        unmount(loading);
      }
    } finally {
      document.body.style.background = '';
    }
  });
});
