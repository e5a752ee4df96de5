// Shared by the element tests: mounting scenes from markup, polling for conditions, pointer drags, sampling canvas
// pixels. No test may depend on how fast a loaded machine runs: a scene is driven by step(n) while paused, or a test
// waits for a condition with a generous deadline; it never asserts how far something moved in wall-clock time.
import '../../src/index.js';
import type { PhysicsSceneElement } from '../../src/index.js';

/** Mounts `<physics-scene {attrs}>{children}</physics-scene>` in a sized container and waits for physics-ready. */
export async function mount(attrs: string, children: string, options: { width?: number; height?: number; ready?: boolean; before?: (scene: PhysicsSceneElement) => void } = {}): Promise<PhysicsSceneElement> {
  const box = document.createElement('div');
  box.style.cssText = `width: ${options.width ?? 400}px; height: ${options.height ?? 400}px; position: relative;`;
  // Test markup only: fixed strings written in the tests.
  box.innerHTML = `<physics-scene ${attrs} style="width: 100%; height: 100%">${children}</physics-scene>`;
  const scene = box.querySelector('physics-scene')!;
  options.before?.(scene);
  document.body.append(box);
  if (options.ready !== false) await scene.ready;
  return scene;
}

/**
 * Within a describe: after each test, console.warn is put back (tests that collect warnings replace it) and the scene
 * `current()` gives is removed with its container (again: a no-op).
 */
export function afterEachScene(current: () => Element | null): void {
  const warn = console.warn;
  afterEach(() => {
    console.warn = warn;
    unmount(current());
  });
}

/** Removes a mounted scene with its container. */
export function unmount(scene: Element | null | undefined): void {
  const box = scene?.parentElement;
  if (box && box !== document.body) box.remove();
  else scene?.remove();
}

/** How long a condition may take by default (ms): generous, so a loaded machine is slow, not failing. */
export const DEADLINE = 15000;

/** Polls `condition` every animation frame until it holds; fails with `what` after `timeout` ms. */
export async function waitFor(condition: () => boolean | Promise<boolean>, what: string, timeout = DEADLINE): Promise<void> {
  const until = performance.now() + timeout;
  while (!(await condition())) {
    if (performance.now() > until) throw new Error(`timed out after ${timeout} ms waiting for ${what}`);
    await nextFrame();
  }
}

/** The next animation frame, or 100 ms if the page gets none (a background page), so polling never hangs. */
export function nextFrame(): Promise<void> {
  return new Promise((resolve) => {
    const timer = setTimeout(() => {
      cancelAnimationFrame(frame);
      resolve();
    }, 100);
    const frame = requestAnimationFrame(() => {
      clearTimeout(timer);
      resolve();
    });
  });
}

export async function frames(n: number): Promise<void> {
  for (let k = 0; k < n; k++) await nextFrame();
}

/** Waits `n` animation frames, then until the canvas shows the scene's newest state (a still scene draws nothing more). */
export async function drawn(scene: PhysicsSceneElement, n = 1): Promise<void> {
  await frames(n);
  await waitFor(() => scene.renderedFrames > 0 && !scene.drawPending, 'the canvas to show the newest state');
}

/** Dispatches a synthetic pointer event at the world point (x, y) on the scene's canvas. */
export function pointerAt(scene: PhysicsSceneElement, type: string, x: number, y: number, pointerId = 7): void {
  const p = scene.worldToClient(x, y);
  const init = { clientX: p.x, clientY: p.y, pointerId, pointerType: 'mouse', isPrimary: true, button: 0, buttons: type === 'pointerup' ? 0 : 1 };
  scene.canvas!.dispatchEvent(new PointerEvent(type, { ...init, bubbles: true, composed: true, cancelable: true }));
}

/**
 * Drags on a paused scene from (x0, y0) to (x1, y1) in `moves` pointer moves, taking `steps` fixed steps after each,
 * and keeps holding (release with pointerAt(…, 'pointerup', …)). What the bodies do depends on the steps taken, not
 * on how fast the machine runs: the engine answers calls in order, so the grab is in place before the first step.
 */
export async function steppedDrag(scene: PhysicsSceneElement, from: [number, number], to: [number, number], moves: number, steps: number): Promise<void> {
  await waitFor(() => scene.canvas !== null, 'the canvas');
  pointerAt(scene, 'pointerdown', from[0], from[1]);
  await scene.step(1);
  for (let k = 1; k <= moves; k++) {
    pointerAt(scene, 'pointermove', from[0] + ((to[0] - from[0]) * k) / moves, from[1] + ((to[1] - from[1]) * k) / moves);
    await scene.step(steps);
  }
}

/** Waits until the body element's live pose has reached the page (frames travel apart from the answers to calls). */
export async function simulated(scene: PhysicsSceneElement, body: Element): Promise<void> {
  await waitFor(() => scene.poseOf(body) !== null, `<${body.localName}> simulated`);
}

/** Steps a paused scene `chunk` steps at a time until `condition` holds; fails with `what` after `most` steps. */
export async function stepUntil(scene: PhysicsSceneElement, condition: () => boolean | Promise<boolean>, what: string, most = 600, chunk = 5): Promise<void> {
  for (let taken = 0; !(await condition()); taken += chunk) {
    if (taken >= most) throw new Error(`${what}: not after ${most} steps`);
    await scene.step(chunk);
  }
}

/** [r, g, b, a] of the canvas pixel under the world point (x, y). */
export function pixelAt(scene: PhysicsSceneElement, x: number, y: number): [number, number, number, number] {
  const canvas = scene.canvas!;
  const client = scene.worldToClient(x, y);
  const rect = canvas.getBoundingClientRect();
  const ratio = canvas.width / rect.width;
  const px = Math.floor((client.x - rect.left) * ratio);
  const py = Math.floor((client.y - rect.top) * ratio);
  const data = canvas.getContext('2d')!.getImageData(px, py, 1, 1).data;
  return [data[0], data[1], data[2], data[3]];
}

/** CSS hex colour → [r, g, b]. */
export function rgb(hex: string): [number, number, number] {
  const n = parseInt(hex.slice(1), 16);
  return [(n >> 16) & 255, (n >> 8) & 255, n & 255];
}

/** Largest channel difference between a pixel and a colour. */
export function colourDistance(pixel: readonly number[], colour: readonly number[]): number {
  return Math.max(Math.abs(pixel[0] - colour[0]), Math.abs(pixel[1] - colour[1]), Math.abs(pixel[2] - colour[2]));
}
