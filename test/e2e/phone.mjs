// End-to-end on a phone (390 × 844, DPR 3, touch, mobile viewport): real touch gestures through CDP
// Input.dispatchTouchEvent, so the browser itself decides between scrolling and handing the touch to the page. A swipe
// that starts over the scene's empty space scrolls the page (as one over text does); one that starts on a body drags
// the body and does not scroll; one on a static body scrolls; two fingers spreading over the scene zoom the page.
// The paragraphs' ids run p1 … p12: id="p5" makes a global `p5` on the page (named access on window), which the bundled
// p5 once took for itself and threw at import (src/render/p5/bundle.mjs defines the free name p5 as undefined).
// Run after `npm run build` (uses dist/physics-elements.bundle.js, or the file in $BUNDLE): node test/e2e/phone.mjs
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { checker, collectProblems, launch, root, serveFiles } from './harness.mjs';

const bundle = readFileSync(resolve(root, process.env.BUNDLE ?? 'dist/physics-elements.bundle.js'));
const text = (n) => `<p id="p${n}">Paragraph ${n}: text around the embed, long enough that the page scrolls well past it on a phone.
  Lorem ipsum dolor sit amet, consectetur adipiscing elit, sed do eiusmod tempor incididunt ut labore et dolore magna.</p>`;
// gravity 0: the bodies stay where they are put until a finger moves them.
const page = `<!doctype html>
<html lang="en"><head><meta charset="utf-8"><meta name="viewport" content="width=device-width, initial-scale=1">
<title>phone</title><style>body { margin: 0; padding: 12px; font: 16px/1.5 system-ui; }</style>
<script type="module" src="/physics-elements.bundle.js"></script></head>
<body>
<p id="top">A post with a physics embed.</p>
<physics-scene id="scene" width="10" height="10" gravity="0 0" style="display:block;aspect-ratio:1/1;overflow:hidden">
  <physics-box id="crate" x="5" y="3" width="2.4" height="2.4"></physics-box>
  <physics-box id="shelf" static x="5" y="8" width="6" height="1.2"></physics-box>
</physics-scene>
${[1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12].map(text).join('\n')}
</body></html>`;

const server = await serveFiles('127.0.0.1', { '/physics-elements.bundle.js': bundle, '/': page });

const browser = await launch();
const check = checker();
try {
  const context = await browser.newContext({ viewport: { width: 390, height: 844 }, deviceScaleFactor: 3, hasTouch: true, isMobile: true });
  const tab = await context.newPage();
  const problems = collectProblems(tab);
  const cdp = await context.newCDPSession(tab);
  await tab.goto(`http://127.0.0.1:${server.address().port}/`);
  await tab
    .waitForFunction(() => {
      const s = document.getElementById('scene');
      return s && s.renderedFrames > 0 && s.poseOf(document.getElementById("crate")) !== null;
    }, null, { timeout: 60000 })
    .catch(async (error) => {
      const s = await tab.evaluate(() => {
        const s = document.getElementById('scene');
        return { defined: !!customElements.get('physics-scene'), frames: s.renderedFrames, mode: s.mode, onScreen: s.onScreen };
      });
      throw new Error(`the scene did not start: ${JSON.stringify(s)}; ${problems.join('; ')}`, { cause: error });
    });

  /** Page state: scroll, the crate's pose, the page zoom. */
  const state = () =>
    tab.evaluate(() => {
      const [x, y] = document.getElementById('scene').poseOf(document.getElementById('crate'));
      return { scrollY: window.scrollY, x, y, zoom: window.visualViewport.scale };
    });
  /** Viewport point of a world point of the scene. */
  const at = (x, y) => tab.evaluate(([x, y]) => document.getElementById('scene').worldToClient(x, y), [x, y]);
  /** A settled page: scrolled back to the top, nothing moving. */
  const reset = async () => {
    await tab.evaluate(() => window.scrollTo(0, 0));
    await tab.waitForTimeout(300);
  };
  const touch = (type, points) => cdp.send('Input.dispatchTouchEvent', { type, touchPoints: points.map(([x, y], id) => ({ x, y, id, radiusX: 4, radiusY: 4, force: 1 })) });
  /**
   * One finger from (x, y) up by `dy` CSS pixels in 12 moves (16 ms apart), then lifted; then the fling settles. It
   * moves at once, as a quick swipe does: on a body, the grab is the worker's answer to the press and arrives during the
   * moves, and the element replays the moves made before it (a flick lifted before any answer lets go at once).
   */
  const swipe = async ({ x, y }, dy) => {
    await touch('touchStart', [[x, y]]);
    for (let k = 1; k <= 12; k++) {
      await tab.waitForTimeout(16);
      await touch('touchMove', [[x, y - (dy * k) / 12]]);
    }
    await touch('touchEnd', []);
    await tab.waitForTimeout(700);
  };

  // Over text: the reference.
  await reset();
  const textBox = await tab.evaluate(() => {
    const r = document.getElementById('p1').getBoundingClientRect();
    return { x: r.left + 40, y: r.top + r.height / 2 };
  });
  await swipe(textBox, 200);
  const overText = (await state()).scrollY;
  check(overText > 100, `a swipe over text scrolls the page (${overText} px)`);

  // Over the scene's empty space (the crate is at the top middle, the shelf low in the middle: the left edge is free).
  await reset();
  const empty = await at(1, 5);
  await swipe(empty, 200);
  const overEmpty = await state();
  check(overEmpty.scrollY > 100, `a swipe over the scene's empty space scrolls the page (${overEmpty.scrollY} px)`);
  check(Math.abs(overEmpty.x - 5) < 1e-6 && Math.abs(overEmpty.y - 3) < 1e-6, `… and moves no body (crate at ${overEmpty.x.toFixed(3)}, ${overEmpty.y.toFixed(3)})`);

  // On the static shelf: it cannot be dragged, so the page scrolls.
  await reset();
  await swipe(await at(3, 8), 200);
  const overShelf = (await state()).scrollY;
  check(overShelf > 100, `a swipe on a static body scrolls the page (${overShelf} px)`);

  // On the crate: it is dragged, the page does not scroll.
  await reset();
  const before = await state();
  await swipe(await at(5, 3.5), 120);
  const onBody = await state();
  check(onBody.scrollY === before.scrollY, `a swipe on a body does not scroll the page (${onBody.scrollY - before.scrollY} px)`);
  check(before.y - onBody.y > 1, `… and drags the body up (crate y ${before.y.toFixed(2)} → ${onBody.y.toFixed(2)})`);

  // Two fingers spreading over the scene's empty space: the page zooms.
  await reset();
  const mid = await at(1.5, 5);
  await touch('touchStart', [[mid.x, mid.y - 20], [mid.x, mid.y + 20]]);
  for (let k = 1; k <= 12; k++) {
    await tab.waitForTimeout(16);
    await touch('touchMove', [[mid.x, mid.y - 20 - 10 * k], [mid.x, mid.y + 20 + 10 * k]]);
  }
  await touch('touchEnd', []);
  await tab.waitForTimeout(500);
  const zoom = (await state()).zoom;
  check(zoom > 1.2, `two fingers spreading over the scene zoom the page (scale ${zoom.toFixed(2)})`);
  check(problems.length === 0, `no console errors (${problems.join('; ') || 'none'})`);
  await context.close();
} finally {
  await browser.close();
  server.close();
}
if (check.failures.length > 0) {
  console.log(`${check.failures.length} failed`);
  process.exit(1);
}
console.log('phone: all passed');
