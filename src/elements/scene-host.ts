// What child elements need from the scene that owns them: the scene's markup sync (physics-scene/markup.ts) implements
// it and sets itself as each child's `_scene`. Kept apart so that the children do not import the scene (a cycle).
export interface SceneHost {
  /** A child's attributes or properties changed. */
  childChanged(child: Element): void;
  /** Live pose [x, y, angle (radians)] of a body element, or null before it is simulated. */
  poseOf(child: Element): [number, number, number] | null;
  applyImpulse(child: Element, ix: number, iy: number): void;
  setVelocity(child: Element, vx: number, vy: number): void;
}

/**
 * What a scene element offers a child it has not adopted yet (added in this task; the scene's observer reports it in a
 * microtask): the child is adopted now, and its host returned (null when the scene is not running it).
 */
export interface SceneParent {
  _hostOf(child: Element): SceneHost | null;
}
