/** The subset of @web/test-runner-commands the element tests use (see commands.js). */
export function emulateMedia(media: { reducedMotion?: 'reduce' | 'no-preference'; colorScheme?: 'light' | 'dark' | 'no-preference'; media?: 'screen' | 'print' }): Promise<void>;
export function sendKeys(payload: { press: string } | { type: string } | { down: string } | { up: string }): Promise<void>;
/** Forced colours (a high-contrast theme) on or off; the other emulated media features go back to none. */
export function emulateForcedColors(value: 'active' | 'none'): Promise<void>;
