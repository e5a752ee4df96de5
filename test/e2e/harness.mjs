// Shared by the end-to-end scripts (cross-origin.mjs, csp.mjs): local HTTP servers, chromium through playwright-core,
// ok/FAIL lines, console capture, and "has this element's canvas changed after N more steps".
import { createServer } from 'node:http';
import { mkdirSync } from 'node:fs';
import { dirname, extname, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { chromium } from 'playwright-core';

export const root = resolve(dirname(fileURLToPath(import.meta.url)), '../..');
export const artifacts = resolve(root, 'artifacts');
mkdirSync(artifacts, { recursive: true });

/** An HTTP server on `host` and a free port; `handler(req, res)`. */
export function listen(host, handler) {
  const server = createServer(handler);
  return new Promise((ok) => server.listen(0, host, () => ok(server)));
}

/**
 * A site of fixed files on a free port: `files` maps a path ('/', '/x.js') to its body, the type taken from the
 * extension (a path without one is a page); /favicon.ico answers 204, anything else 404.
 */
export function serveFiles(host, files) {
  const types = { '.js': 'text/javascript', '.html': 'text/html' };
  return listen(host, (req, res) => {
    const path = req.url.split('?')[0];
    if (Object.hasOwn(files, path)) {
      res.writeHead(200, { 'content-type': types[extname(path)] ?? 'text/html' });
      res.end(files[path]);
    } else {
      res.writeHead(path === '/favicon.ico' ? 204 : 404);
      res.end();
    }
  });
}

/** Chromium from Debian (never a downloaded browser), with the flags this machine needs. */
export function launch() {
  return chromium.launch({
    executablePath: process.env.CHROME_PATH ?? '/usr/bin/chromium',
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
}

/** `check(ok, what)` prints an ok/FAIL line and remembers failures; `checker.failures` lists them. */
export function checker() {
  const failures = [];
  const check = (ok, what) => {
    console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}`);
    if (!ok) failures.push(what);
    return ok;
  };
  check.failures = failures;
  return check;
}

/** Console errors and warnings, uncaught exceptions and failed requests of a tab, as lines. */
export function collectProblems(tab) {
  const problems = [];
  tab.on('console', (m) => (m.type() === 'error' || m.type() === 'warning') && problems.push(`${m.type()}: ${m.text()}`));
  tab.on('pageerror', (e) => problems.push(`pageerror: ${e}`));
  tab.on('requestfailed', (r) => problems.push(`request failed: ${r.url()}`));
  return problems;
}

/** Canvas pixels of the element with this id, as a data URL, after the scene has taken `steps` more steps. */
export function canvasAfter(tab, id, steps) {
  return tab.evaluate(async ([id, steps]) => {
    const el = document.getElementById(id);
    const target = el.stepCount + steps;
    const until = performance.now() + 10000;
    while (el.stepCount < target && performance.now() < until) await new Promise((r) => requestAnimationFrame(r));
    const drawn = el.renderedFrames;
    while (el.renderedFrames < drawn + 2 && performance.now() < until) await new Promise((r) => requestAnimationFrame(r));
    return el.canvas.toDataURL();
  }, [id, steps]);
}

/** True when the element's canvas is drawn and changes between two moments `steps` steps apart. */
export async function animates(tab, id) {
  const a = await canvasAfter(tab, id, 5);
  const b = await canvasAfter(tab, id, 20);
  return a.length > 1000 && a !== b;
}
