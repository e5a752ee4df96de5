// Checks the gallery (demo/index.html): every story loads with no console error and a non-blank canvas that changes
// over time (or, for a scene at rest, whose bodies do not move while it steps: an idle scene does not redraw); the controls panel edits the markup snippet; a deep link opens its story. Starts and stops its own dev
// server on a free port, drives Debian's chromium with playwright-core, keeps a screenshot of every story under
// artifacts/stories/. Then the engine demo and the report page load without console errors. Usage: node scripts/check-stories.mjs [--only id,id]
import { mkdirSync } from 'node:fs';
import { chromium } from 'playwright-core';
import { startDevServer } from './dev-server.mjs';

const t0 = performance.now();
const onlyArg = process.argv.indexOf('--only');
const only = onlyArg > 0 ? new Set(process.argv[onlyArg + 1].split(',')) : null;
const outDir = new URL('../artifacts/stories/', import.meta.url);
mkdirSync(outDir, { recursive: true });

const server = await startDevServer();
const browser = await chromium.launch({
  executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
  args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
});
const failures = [];
try {
  const page = await browser.newPage({ viewport: { width: 1100, height: 800 } });
  let errors = [];
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  page.on('pageerror', (e) => errors.push(String(e)));

  // A deep link opens its story, with its toggles.
  await page.goto(`${server.url}/demo/#physics-circle?debug=1`);
  await page.waitForFunction(() => document.querySelector('#stage physics-scene')?.hasAttribute('debug'), null, { timeout: 60000 });
  const deep = await page.evaluate(() => ({ title: document.getElementById('story-title').textContent, debug: document.getElementById('t-debug').checked }));
  if (deep.title !== '<physics-circle>' || !deep.debug) failures.push(`deep link: got ${JSON.stringify(deep)}`);

  const ids = await page.evaluate(() => [...document.querySelectorAll('#stories a')].map((a) => a.dataset.story));
  if (ids.length < 20) failures.push(`only ${ids.length} stories listed`);

  /** Reads the scene's canvas: a hash of its pixels and the number of distinct colours (on a 4-pixel lattice). */
  const sample = () =>
    page.evaluate(async () => {
      const scene = document.querySelector('#stage > *');
      const canvas = scene?.canvas ?? scene?.shadowRoot?.querySelector('canvas');
      if (!canvas || !canvas.width) return null;
      const ctx = canvas.getContext('2d', { willReadFrequently: true });
      const { data } = ctx.getImageData(0, 0, canvas.width, canvas.height);
      let hash = 0;
      const colours = new Set();
      for (let i = 0; i < data.length; i += 4) {
        const v = (data[i] << 16) | (data[i + 1] << 8) | data[i + 2];
        hash = (Math.imul(hash, 31) + v) | 0;
        if (i % 16 === 0 && colours.size < 50) colours.add(v);
      }
      // The bodies' poses and the step count: a canvas that does not change is right only when nothing moved.
      const poses = [...scene.querySelectorAll('*')].flatMap((c) => scene.poseOf?.(c) ?? []);
      return { hash, colours: colours.size, poses, steps: scene.stepCount };
    });

  for (const id of ids) {
    if (only && !only.has(id)) continue;
    const started = performance.now();
    errors = [];
    await page.evaluate((id) => (location.hash = id), id);
    try {
      await page.waitForFunction((id) => document.querySelector(`#stories a.active`)?.dataset.story === id && document.querySelector('#stage > *')?.renderedFrames > 2, id, { timeout: 45000 });
      await page.evaluate(() => document.querySelector('#stage > *').ready);
    } catch (e) {
      failures.push(`${id}: never drew (${e.message.split('\n')[0]})`);
      continue;
    }
    await page.waitForTimeout(300);
    const a = await sample();
    let b = a;
    for (let k = 0; k < 10 && b && a && b.hash === a.hash; k++) {
      await page.waitForTimeout(250);
      b = await sample();
    }
    await page.screenshot({ path: new URL(`${id}.png`, outDir).pathname });
    const problems = [];
    if (!a || !b) problems.push('no canvas');
    else {
      if (a.colours < 3) problems.push(`blank canvas (${a.colours} colours)`);
      // Still: no pose moved by a visible amount, 0.01 world units or radians (the stack story draws 34 px a unit,
      // so that is a third of a pixel): the stack settles by 1.3e-4 between 0.3 and 2.8 s, then sleeps, and no redraw
      // can show that (one CI run failed it as "bodies moved but the canvas did not change").
      const moved = a.poses.length !== b.poses.length || a.poses.some((v, k) => !(Math.abs(v - b.poses[k]) < 0.01));
      const atRest = a.poses.length > 0 && !moved && b.steps > a.steps;
      if (a.hash === b.hash && !atRest) problems.push(moved ? 'bodies moved but the canvas did not change in 2.5 s' : 'canvas did not change and the scene took no step in 2.5 s');
    }
    const snippet = await page.evaluate(() => document.getElementById('snippet').textContent);
    if (!snippet.startsWith('<')) problems.push('no markup snippet');
    if (errors.length) problems.push(`console errors: ${errors.join(' | ')}`);
    if (problems.length) failures.push(`${id}: ${problems.join('; ')}`);
    console.log(`${problems.length ? 'FAIL' : 'ok  '} ${id} (${Math.round(performance.now() - started)} ms)${problems.length ? ' ' + problems.join('; ') : ''}`);
  }

  // The controls panel edits the element and the snippet; values are escaped in the snippet and never parsed as markup.
  if (!only) {
    await page.evaluate(() => (location.hash = 'physics-box'));
    await page.waitForFunction(() => document.getElementById('story-title').textContent === '<physics-box>');
    const input = page.locator('fieldset:nth-of-type(2) input[data-attr="fill"]');
    await input.fill('"><img src=x onerror=alert(1)>');
    // The panel applies a value once it is committed (Enter or leaving the field), not at each keystroke.
    await input.press('Enter');
    const edited = await page.evaluate(() => ({
      snippet: document.getElementById('snippet').textContent,
      attr: document.querySelector('#stage physics-box:nth-of-type(2)').getAttribute('fill'),
      imgs: document.querySelectorAll('img').length,
    }));
    if (!edited.snippet.includes('fill="&quot;&gt;&lt;img src=x onerror=alert(1)&gt;"')) failures.push('controls: the snippet does not show the edited, escaped value');
    if (edited.attr !== '"><img src=x onerror=alert(1)>') failures.push('controls: the attribute was not set on the element');
    if (edited.imgs) failures.push('controls: an attribute value became markup');
  }

  // The other demo pages load without console errors: the engine demo, and the report (its plots drawn from bench/results/).
  for (const [path, ready] of [
    ['engine.html', () => document.querySelector('canvas')],
    ['report.html', () => document.querySelectorAll('svg').length >= 8 && !document.getElementById('closing').textContent.startsWith('Loading')],
  ]) {
    errors = [];
    await page.goto(`${server.url}/demo/${path}`);
    try {
      await page.waitForFunction(ready, null, { timeout: 15000 });
      await page.waitForTimeout(500);
      await page.screenshot({ path: new URL(`page-${path.replace('.html', '')}.png`, outDir).pathname, fullPage: path === 'report.html' });
      if (path === 'report.html') {
        // On a phone the page fits its width: wide tables scroll in their own box, plots take one column.
        const viewport = page.viewportSize();
        await page.setViewportSize({ width: 390, height: 844 });
        const width = await page.evaluate(() => document.documentElement.scrollWidth);
        if (width > 390) failures.push(`report.html: ${width} px wide at a 390 px viewport (the page scrolls sideways)`);
        await page.setViewportSize(viewport);
      }
    } catch (e) {
      failures.push(`${path}: not ready (${e.message.split('\n')[0]})`);
    }
    if (errors.length) failures.push(`${path}: console errors: ${errors.join(' | ')}`);
    console.log(`${errors.length ? 'FAIL' : 'ok  '} demo/${path}`);
  }
} finally {
  await browser.close();
  await server.stop();
}
const seconds = ((performance.now() - t0) / 1000).toFixed(1);
if (failures.length) {
  console.error(`check-stories: ${failures.length} failure(s) in ${seconds} s\n${failures.join('\n')}`);
  process.exit(1);
}
console.log(`check-stories: every story passed in ${seconds} s (screenshots in artifacts/stories/)`);
