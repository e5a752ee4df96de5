import { chromeLauncher } from '@web/test-runner-chrome';
import { crossOriginIsolation, jsToTs, plugins } from './web-dev-server.config.js';

// Debian's chromium (scripts/test.sh installs it when missing); no browser download.
const executablePath = process.env.CHROME_PATH ?? '/usr/bin/chromium';
const args = [
  '--no-sandbox', // we run as root
  '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
  '--disable-component-update', '--disable-sync',
];

export default {
  files: ['test/**/*.test.ts'],
  nodeResolve: true,
  // Cross-origin isolation everywhere except for test files whose name says "transfer": those run without it, so
  // both ways of publishing state (SharedArrayBuffer, transferred ArrayBuffer) are exercised.
  middleware: [crossOriginIsolation({ when: (ctx) => !/transfer/.test(ctx.headers.referer ?? '') && !/transfer/.test(ctx.path) }), jsToTs],
  plugins,
  browsers: [chromeLauncher({ launchOptions: { executablePath, headless: true, args } })],
  concurrency: 2,
  testFramework: { config: { timeout: 60000 } },
  testsFinishTimeout: 15 * 60 * 1000,
};
