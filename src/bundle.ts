// physics-elements/bundle: what the single-file builds (physics-elements.bundle.js, and .iife.js on
// window.PhysicsElements) export: the elements, their event details, the drawing hook's types and EngineStoppedError,
// not the headless engine's API (rollup.config.js, sharedEngine: a page that wants it imports physics-elements/engine).
// Importing it registers the elements. package.json's "exports" gives its declarations as the types of
// 'physics-elements/bundle'; the package entry (src/index.ts) exports this and the engine.

export { PhysicsSceneElement } from './elements/physics-scene/physics-scene.js';
export type { PhysicsErrorDetail, PhysicsCollisionDetail, PhysicsReadyDetail, PhysicsEventDetails, PhysicsEventMap, PhysicsEventName } from './elements/physics-scene/events.js';
export { PhysicsBodyElement } from './elements/body-element.js';
export { PhysicsLinkElement } from './elements/link-element.js';
export { PhysicsBoxElement } from './elements/physics-box.js';
export { PhysicsCircleElement } from './elements/physics-circle.js';
export { PhysicsPolygonElement } from './elements/physics-polygon.js';
export { PhysicsRopeElement } from './elements/physics-rope.js';
export { PhysicsClothElement } from './elements/physics-cloth.js';
export { PhysicsSoftbodyElement } from './elements/physics-softbody.js';
export { PhysicsRagdollElement } from './elements/physics-ragdoll.js';
export { PhysicsJointElement } from './elements/physics-joint.js';
export { PhysicsSpringElement } from './elements/physics-spring.js';
export { PhysicsPinElement } from './elements/physics-pin.js';
export { ClothSimElement } from './elements/cloth-sim.js';
export { RagdollSimElement } from './elements/ragdoll-sim.js';

export type { DrawHook, DrawView, BodyStyle } from './render/renderer.js';
// The type of the cloths' `pins` attribute (the other enum-like attributes are written out as literal unions).
export type { ClothPinsAttribute } from './elements/checks.js';
// What an engine call on a scene that is not in the page (or was removed) rejects with: `e instanceof EngineStoppedError`.
export { EngineStoppedError } from './worker/client.js';
// What the public API above names: diagnostics(), snapshot()/restore(), physics-ready's transport, DrawView's topology.
export type { Diagnostics, HostSnapshot, Topology, TopologyBody, TopologyLink, LinkEnd, Transport } from './worker/protocol.js';
