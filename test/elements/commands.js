// The test runner's browser commands, re-exported through a plain JS module: their own .d.ts pulls in Node's types
// (setTimeout returning a Timeout), which would change the type-check of every test file.
export { emulateMedia, sendKeys } from '@web/test-runner-commands';
