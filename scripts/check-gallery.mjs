// Checks the gallery's layout and accessibility (demo/index.html) on a desktop (1280×800) and a phone (390×844, DPR 3,
// touch): axe-core finds no serious or critical WCAG violation; nothing overflows sideways at 390 px; on the phone the
// story list is behind a button and the scene is on the first screen; the stats, when shown, sit under the scene, not
// over it; the snippet box is reachable with Tab; what Copy copies starts with the README's script line. Starts its own
// dev server, drives Debian's chromium with playwright-core, keeps screenshots in artifacts/gallery/.
// Usage: node scripts/check-gallery.mjs [--story physics-cloth]
import { mkdirSync, readFileSync } from 'node:fs';
import { createRequire } from 'node:module';
import { chromium } from 'playwright-core';
import { startDevServer } from './dev-server.mjs';

const t0 = performance.now();
const storyArg = process.argv.indexOf('--story');
const story = storyArg > 0 ? process.argv[storyArg + 1] : 'physics-cloth';
const outDir = new URL('../artifacts/gallery/', import.meta.url);
mkdirSync(outDir, { recursive: true });
const axePath = createRequire(import.meta.url).resolve('axe-core/axe.min.js');
const readme = readFileSync(new URL('../README.md', import.meta.url), 'utf8');
const readmeScript = /```html\n(<script[^\n]*<\/script>)/.exec(readme)?.[1];

const failures = [];
const check = (ok, what) => {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
  if (!ok) failures.push(what);
};

const server = await startDevServer();
const browser = await chromium.launch({
  executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
try {
  for (const [name, options] of [
    ['desktop', { viewport: { width: 1280, height: 800 } }],
    ['phone', { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true }],
  ]) {
    const context = await browser.newContext(options);
    const page = await context.newPage();
    const errors = [];
    page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
    page.on('pageerror', (e) => errors.push(String(e)));
    await page.goto(`${server.url}/demo/#${story}`);
    try {
      await page.waitForFunction(() => document.querySelector('#stage > *')?.renderedFrames > 2, null, { timeout: 60000 });
    } catch (e) {
      check(false, `${name}: the story never drew (${e.message.split('\n')[0]}; ${errors.join(' | ')})`);
      await context.close();
      continue;
    }

    // Layout.
    const layout = await page.evaluate(() => {
      const box = (sel) => {
        const r = document.querySelector(sel).getBoundingClientRect();
        return { top: r.top, bottom: r.bottom, left: r.left, right: r.right, width: r.width, height: r.height };
      };
      return { scrollWidth: document.documentElement.scrollWidth, innerWidth, innerHeight, stage: box('#stage-wrap'), nav: box('nav'), stats: document.getElementById('stats').hidden };
    });
    check(layout.scrollWidth <= layout.innerWidth, `${name}: no horizontal overflow (page ${layout.scrollWidth} px wide, viewport ${layout.innerWidth} px)`);
    check(layout.stats, `${name}: the stats are off until asked for`);
    check(layout.stage.width >= layout.innerWidth * 0.5 && layout.stage.top < layout.innerHeight * 0.6, `${name}: the scene is on the first screen (${Math.round(layout.stage.width)} px wide, top at ${Math.round(layout.stage.top)} px)`);
    if (name === 'phone') {
      check(layout.nav.height < 80, `phone: the story list is collapsed (nav ${Math.round(layout.nav.height)} px tall)`);
      const hasButton = await page.evaluate(() => document.getElementById('nav-toggle') !== null);
      check(hasButton, 'phone: a Stories button');
      if (hasButton) {
        await page.click('#nav-toggle');
        const open = await page.evaluate(() => ({ expanded: document.getElementById('nav-toggle').getAttribute('aria-expanded'), visible: document.querySelector('#stories a').getBoundingClientRect().height > 0 }));
        check(open.expanded === 'true' && open.visible, `phone: the Stories button opens the list (${JSON.stringify(open)})`);
        await page.screenshot({ path: new URL(`${name}-nav.png`, outDir).pathname });
        await page.click('#nav-toggle');
      }
    }

    // The stats, when shown, do not cover the scene.
    const hasToggle = await page.evaluate(() => document.getElementById('t-stats') !== null);
    check(hasToggle, `${name}: a 'stats' toggle`);
    if (hasToggle) {
      await page.check('#t-stats');
      await page.waitForFunction(() => !document.getElementById('stats').textContent.startsWith('starting'), null, { timeout: 10000 });
    }
    const overlap = await page.evaluate(() => {
      const a = document.getElementById('stage-wrap').getBoundingClientRect();
      const b = document.getElementById('stats').getBoundingClientRect();
      return Math.max(0, Math.min(a.right, b.right) - Math.max(a.left, b.left)) * Math.max(0, Math.min(a.bottom, b.bottom) - Math.max(a.top, b.top));
    });
    check(overlap === 0, `${name}: the stats do not cover the scene (${Math.round(overlap)} px² overlap)`);

    // The snippet: reachable with the keyboard, and what Copy copies is complete.
    const snippet = await page.evaluate(() => ({ tabIndex: document.getElementById('snippet').tabIndex, text: document.getElementById('snippet').textContent }));
    check(snippet.tabIndex === 0, `${name}: the snippet box is in the tab order`);
    const [first, second = '', third = ''] = snippet.text.split('\n');
    check(readmeScript !== undefined && first === readmeScript, `${name}: the snippet starts with the README's script line (${first})`);
    check(/^<[a-z-]+ .*style="display:block;aspect-ratio:\d+(\.\d+)?\/\d+(\.\d+)?"/.test(second), `${name}: the tag reserves its box (${second.slice(0, 90)})`);
    check(/^ {2}<p slot="fallback">[^<]+<\/p>$/.test(third), `${name}: the tag holds fallback text (${third.slice(0, 90)})`);
    await page.screenshot({ path: new URL(`${name}.png`, outDir).pathname, fullPage: name === 'phone' });

    // axe-core, the whole page.
    await page.addScriptTag({ path: axePath });
    const violations = await page.evaluate(async () => {
      const result = await window.axe.run(document, { resultTypes: ['violations'] });
      return result.violations.map((v) => ({ id: v.id, impact: v.impact, nodes: v.nodes.slice(0, 3).map((n) => n.target.join(' ')), count: v.nodes.length }));
    });
    const serious = violations.filter((v) => v.impact === 'serious' || v.impact === 'critical');
    for (const v of violations) console.log(`     axe ${v.impact}: ${v.id} ×${v.count} (${v.nodes.join(', ')})`);
    check(serious.length === 0, `${name}: axe finds no serious or critical violation${serious.length ? ` (${serious.map((v) => v.id).join(', ')})` : ''}`);
    check(errors.length === 0, `${name}: no console errors${errors.length ? `: ${errors.join(' | ')}` : ''}`);

    if (name === 'desktop') {
      // The panel applies a typed value once committed: a half-typed gravity is neither applied nor reported.
      const warnings = [];
      page.on('console', (m) => m.type() === 'warning' && warnings.push(m.text()));
      const gravity = page.locator('#c-physics-scene-gravity');
      await gravity.fill('');
      await gravity.pressSequentially('0 -3', { delay: 30 });
      const typed = await page.evaluate(() => document.querySelector('#stage > *').getAttribute('gravity'));
      await gravity.press('Enter');
      const committed = await page.evaluate(() => document.querySelector('#stage > *').getAttribute('gravity'));
      check(typed !== '0 -3' && committed === '0 -3' && warnings.length === 0, `${name}: a typed value applies on Enter, with no warning on the way (${JSON.stringify({ typed, committed, warnings })})`);
      // The scene paused with Space: the panel's paused box says so.
      await page.focus('#stage > *');
      await page.keyboard.press('Space');
      const paused = await page.waitForFunction(() => document.querySelector('#c-physics-scene-paused')?.checked === true, null, { timeout: 5000 }).then(() => true, () => false);
      check(paused, `${name}: the paused box follows a pause from the scene (Space)`);
    }
    await context.close();
  }

  // The other pages of the demo: axe on the whole page; on the phone the report's chart labels stay readable.
  for (const [name, options] of [
    ['desktop', { viewport: { width: 1280, height: 800 } }],
    ['phone', { viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true }],
  ]) {
    for (const path of ['/demo/report.html', '/demo/engine.html']) {
      const context = await browser.newContext(options);
      const page = await context.newPage();
      await page.goto(`${server.url}${path}`);
      await page.waitForTimeout(1500);
      await page.addScriptTag({ path: axePath });
      const serious = await page.evaluate(async () => (await window.axe.run(document, { resultTypes: ['violations'] })).violations.filter((v) => v.impact === 'serious' || v.impact === 'critical').map((v) => v.id));
      check(serious.length === 0, `${name} ${path}: axe finds no serious or critical violation${serious.length ? ` (${serious.join(', ')})` : ''}`);
      if (path.endsWith('report.html')) {
        const smallest = await page.evaluate(() => Math.min(...[...document.querySelectorAll('svg text')].map((t) => t.getBoundingClientRect().height).filter((h) => h > 0)));
        check(smallest >= 9, `${name} ${path}: chart labels at least 9 px tall (smallest ${smallest.toFixed(1)} px)`);
      }
      await context.close();
    }
  }
} finally {
  await browser.close();
  await server.stop();
}
const seconds = ((performance.now() - t0) / 1000).toFixed(1);
console.log(failures.length ? `check-gallery: ${failures.length} failed in ${seconds} s` : `check-gallery: all passed in ${seconds} s (screenshots in artifacts/gallery/)`);
process.exit(failures.length ? 1 : 0);
