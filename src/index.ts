// physics-elements: the element library entry. Importing it registers the elements; it also re-exports the headless
// engine, so one import gives both.
export * from './engine/index.js';

export { PhysicsSceneElement, type PhysicsErrorDetail, type PhysicsCollisionDetail, type PhysicsReadyDetail } from './elements/physics-scene.js';
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

export { SceneRenderer, type DrawHook, type DrawView, type BodyStyle } from './render/renderer.js';
export { EngineClient, FrameStore, createEngineWorker, type ClientOptions } from './worker/client.js';
export { EngineHost } from './worker/engine-host.js';
export { liveResources } from './worker/resources.js';
export type {
  EngineApi, HostScene, HostParams, HostSnapshot, HostError, KeyedBody, KeyedLink, LinkDescription, Topology, TopologyBody,
  Diagnostics, Transport,
} from './worker/protocol.js';
