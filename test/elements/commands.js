// The test runner's browser commands, re-exported through a plain JS module: their own .d.ts pulls in Node's types
// (setTimeout returning a Timeout), which would change the type-check of every test file.
import { executeServerCommand } from '@web/test-runner-commands';
export { emulateMedia, sendKeys } from '@web/test-runner-commands';

/** Forced colours on or off (web-test-runner.config.js, emulate-forced-colors); other emulated media go back to none. */
export const emulateForcedColors = (value) => executeServerCommand('emulate-forced-colors', value);
