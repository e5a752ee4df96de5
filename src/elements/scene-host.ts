// What child elements need from the scene that owns them (kept apart from physics-scene.ts to avoid an import cycle).
export interface SceneHost {
  /** A child's attributes or properties changed. */
  childChanged(child: Element): void;
  /** Live pose [x, y, angle (radians)] of a body element, or null before it is simulated. */
  poseOf(child: Element): [number, number, number] | null;
  applyImpulse(child: Element, ix: number, iy: number): void;
  setVelocity(child: Element, vx: number, vy: number): void;
}
