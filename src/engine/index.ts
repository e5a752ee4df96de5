// physics-elements/engine: the headless engine. No DOM, no worker, no p5: runs in Node, a worker or a page.
export { World, BODY_KINDS, DEFAULT_LIMITS, MAX_STEP_SECONDS, MIN_STEP_SECONDS } from './world.js';
export { WORLD_BOUNDS } from './pipeline/events.js';
export type {
  WorldOptions, WorldSnapshot, ParticleOptions, DistanceOptions, AngleOptions, SpringOptions, PinOptions, AreaOptions,
  BodyKind, ConstraintKind, Vec2, Handle, Integrator, Bounds, ColliderOptions, Limits, GrabOptions, RayCastHit,
  RigidBodyOptions, Pose, MassInfo, JointOptions, JointType,
} from './world.js';
// The other types World's public members name (addRigidBody's options, bodyType's answer, the substeps option,
// world.particles, world.events), so an app can write them down.
export type { SubstepChoice } from './options.js';
export type { BodyTypeName } from './rigid/shapes.js';
export type { ParticleStore } from './particles.js';
export type { CollisionEvents } from './pipeline/events.js';
export { INTEGRATORS } from './integrate.js';
export { KERNELS, setDefaultKernel, defaultKernel, type KernelChoice, type KernelOptions, type KernelDiagnostics, type WorldDiagnostics } from './kernel/choice.js';
export { createRope, type RopeOptions } from './builders/rope.js';
export { createCloth, type ClothOptions, type ClothPins } from './builders/cloth.js';
export { createBox, createPolygon, type BoxOptions, type PolygonOptions, type RigidOptions } from './builders/rigid.js';
export { createSoftBody, type SoftBodyOptions } from './builders/softbody.js';
export { createRagdoll, ragdollJoints, RAGDOLL_JOINTS, RAGDOLL_BONES, type RagdollOptions, type RagdollParticles } from './builders/ragdoll.js';
export type { Built } from './builders/common.js';
export { hashColumns } from './hash.js';
export { createCircle, type CircleOptions } from './builders/circle.js';
export type { BodyOptions, BodyModel } from './builders/common.js';
export { BODY_MODELS } from './builders/common.js';
export { buildScene, buildBody, BODY_TYPES, type SceneDescription, type BodyDescription, type BodyType } from './scene.js';
export { catalogue, SCENE_NAMES, type SceneName, type CatalogueEntry } from './scenes/catalogue.js';
export * from './collision/index.js';
