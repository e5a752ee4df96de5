import { chromeLauncher } from '@web/test-runner-chrome';
import { crossOriginIsolation, jsToTs, plugins } from './web-dev-server.config.js';

// Debian's chromium (scripts/test.sh installs it when missing); no browser download.
const executablePath = process.env.CHROME_PATH ?? '/usr/bin/chromium';
const args = [
  '--no-sandbox', // we run as root
  '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync',
];

/**
 * `emulateForcedColors('active' | 'none')` (test/elements/commands.js): forced colours, as a high-contrast theme sets
 * them. @web/test-runner-commands' emulateMedia passes `forcedColors` to Playwright only; this launcher is Puppeteer's.
 * It sets the page's emulated media features to this one alone (prefers-color-scheme and the others back to none).
 */
const cdpSessions = new WeakMap();
const forcedColorsCommand = {
  name: 'emulate-forced-colors',
  async executeCommand({ command, payload, session }) {
    if (command !== 'emulate-forced-colors') return undefined;
    if (payload !== 'active' && payload !== 'none') throw new Error(`emulate-forced-colors: 'active' or 'none', not ${payload}`);
    // Puppeteer's emulateMediaFeatures() refuses the name: straight to the DevTools protocol, on a session kept open
    // (its emulation ends with it).
    const page = session.browser.getPage(session.id);
    cdpSessions.set(page, cdpSessions.get(page) ?? (await page.createCDPSession()));
    await cdpSessions.get(page).send('Emulation.setEmulatedMedia', { features: [{ name: 'forced-colors', value: payload }] });
    return true;
  },
};

export default {
  // .test.html files are pages of their own (their URL can carry "transfer", see below). The engine's and the worker
  // host's tests need no browser: they run in Node (npm run test:engine, .mocharc.json).
  files: ['test/**/*.test.ts', 'test/**/*.test.html', '!test/engine/**', '!test/worker/host/**'],
  nodeResolve: true,
  // Cross-origin isolation everywhere except for test files whose name says "transfer": those run without it, so
  // both ways of publishing state (SharedArrayBuffer, transferred ArrayBuffer) are exercised.
  middleware: [crossOriginIsolation({ when: (ctx) => !/transfer/.test(ctx.headers.referer ?? '') && !/transfer/.test(ctx.path) }), jsToTs],
  plugins: [...plugins, forcedColorsCommand],
  browsers: [
    chromeLauncher({
      launchOptions: { executablePath, headless: true, args },
      // Each test page in a browser context of its own: with concurrency 2, a second tab of one context is a hidden
      // page that gets no animation frames, and canvas tests starve.
      createPage: async ({ browser }) => {
        const context = await browser.createBrowserContext();
        const page = await context.newPage();
        page.once('close', () => context.close().catch(() => {}));
        return page;
      },
    }),
  ],
  concurrency: 2,
  testFramework: { config: { timeout: 60000 } },
  testsFinishTimeout: 15 * 60 * 1000,
  // CI may run while the machine is busy: under two CPU hogs the first test page took more than the default 30 s to
  // open in some runs ("unable to create and start a test page"), and a page's tests more than 20 s to start.
  browserStartTimeout: 2 * 60 * 1000,
  testsStartTimeout: 2 * 60 * 1000,
};
