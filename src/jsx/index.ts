// physics-elements/jsx: the elements' attributes and events as types for JSX, for no framework in particular. Types
// only: this module has no JavaScript (package.json gives it a "types" entry alone). The framework entries
// (physics-elements/react, /preact, /solid, /vue: src/jsx/*.d.ts, copied into dist/types/jsx by the build) add these
// to their framework's JSX; another framework's typings can be built from PhysicsElementAttributes and
// PhysicsEventHandlers the same way.
//
// Attributes are named as in the markup (kebab-case: `collision-events`, `lower-angle`, `static`) and typed from the
// element's property: a number attribute takes a number or numeric text (`wind={2}` or `wind="2"`), an enum-like one
// its literal union (`kernel="wasm"`), a boolean one a boolean (`paused` or `paused={false}`; React, Preact and Vue set
// a property the element has rather than the attribute). test/e2e/pack.mjs holds these lists to custom-elements.json.
import type { ClothSimElement } from '../elements/cloth-sim.js';
import type { PhysicsEventMap, PhysicsEventName } from '../elements/physics-scene/events.js';
import type { PhysicsSceneElement } from '../elements/physics-scene/physics-scene.js';
import type { PhysicsBoxElement } from '../elements/physics-box.js';
import type { PhysicsCircleElement } from '../elements/physics-circle.js';
import type { PhysicsClothElement } from '../elements/physics-cloth.js';
import type { PhysicsJointElement } from '../elements/physics-joint.js';
import type { PhysicsPinElement } from '../elements/physics-pin.js';
import type { PhysicsPolygonElement } from '../elements/physics-polygon.js';
import type { PhysicsRagdollElement } from '../elements/physics-ragdoll.js';
import type { PhysicsRopeElement } from '../elements/physics-rope.js';
import type { PhysicsSoftbodyElement } from '../elements/physics-softbody.js';
import type { PhysicsSpringElement } from '../elements/physics-spring.js';
import type { RagdollSimElement } from '../elements/ragdoll-sim.js';

/**
 * An attribute's value in JSX, from its property's type T: a number as a number or numeric text ("2", "1e-3"), the rest
 * as typed (undefined left out: every attribute is optional).
 */
export type AttributeValue<T> = T extends undefined ? never : T extends number ? T | `${T}` : T;

/** The attributes whose name is not their property's lowercased (Lit's `attribute:` option), by property name. */
interface AttributeNames {
  isStatic: 'static';
  collisionEvents: 'collision-events';
  maxRestarts: 'max-restarts';
  drawMode: 'draw-mode';
  obstacleFill: 'obstacle-fill';
  jointCompliance: 'joint-compliance';
  angularVelocity: 'angular-velocity';
  lowerAngle: 'lower-angle';
  upperAngle: 'upper-angle';
  motorSpeed: 'motor-speed';
  maxMotorTorque: 'max-motor-torque';
  collideConnected: 'collide-connected';
}

/** The attribute of property P. */
type AttributeName<P> = P extends keyof AttributeNames ? AttributeNames[P] : P;

/**
 * The attributes of element E that set its properties P, each optional and named as in the markup. Mapped over E's
 * own properties, so an editor shows each attribute's documentation.
 */
export type AttributesOf<E, P extends keyof E> = { [K in keyof Pick<E, P> as AttributeName<K>]?: AttributeValue<E[K]> };

type SceneProperty = 'width' | 'height' | 'gravity' | 'iterations' | 'substeps' | 'timestep' | 'paused' | 'debug' | 'broadphase' | 'narrowphase' | 'bounds' | 'background' | 'worker' | 'kernel' | 'collisionEvents' | 'maxRestarts' | 'drawMode';
type BodyProperty = 'x' | 'y' | 'angle' | 'mass' | 'density' | 'isStatic' | 'friction' | 'restitution' | 'fill' | 'stroke';
type ShapeProperty = BodyProperty | 'model' | 'kinematic' | 'velocity' | 'angularVelocity';
type LinkProperty = 'x' | 'y';

/** Each tag's attributes, as JSX props (no events, no framework's own props such as `key`, `ref`, `class`). */
export interface PhysicsElementAttributes {
  'physics-scene': AttributesOf<PhysicsSceneElement, SceneProperty>;
  'cloth-sim': AttributesOf<ClothSimElement, SceneProperty | 'columns' | 'rows' | 'spacing' | 'pins' | 'stiffness' | 'wind' | 'gusts' | 'tear' | 'fill' | 'stroke'>;
  'ragdoll-sim': AttributesOf<RagdollSimElement, SceneProperty | 'count' | 'size' | 'obstacles' | 'respawn' | 'stroke' | 'obstacleFill'>;
  'physics-box': AttributesOf<PhysicsBoxElement, ShapeProperty | 'width' | 'height'>;
  'physics-circle': AttributesOf<PhysicsCircleElement, ShapeProperty | 'radius'>;
  'physics-polygon': AttributesOf<PhysicsPolygonElement, ShapeProperty | 'points'>;
  'physics-rope': AttributesOf<PhysicsRopeElement, BodyProperty | 'x1' | 'y1' | 'x2' | 'y2' | 'segments' | 'slack' | 'pin' | 'radius' | 'rigid' | 'collide'>;
  'physics-cloth': AttributesOf<PhysicsClothElement, BodyProperty | 'columns' | 'rows' | 'spacing' | 'pins' | 'compliance' | 'shear' | 'bend' | 'tear' | 'collide'>;
  'physics-softbody': AttributesOf<PhysicsSoftbodyElement, BodyProperty | 'radius' | 'segments' | 'pressure' | 'model' | 'compliance'>;
  'physics-ragdoll': AttributesOf<PhysicsRagdollElement, BodyProperty | 'height' | 'jointCompliance'>;
  'physics-joint': AttributesOf<PhysicsJointElement, LinkProperty | 'type' | 'a' | 'b' | 'x1' | 'y1' | 'x2' | 'y2' | 'lowerAngle' | 'upperAngle' | 'motorSpeed' | 'maxMotorTorque' | 'axis' | 'lower' | 'upper' | 'length' | 'stiffness' | 'damping' | 'compliance' | 'collideConnected'>;
  'physics-spring': AttributesOf<PhysicsSpringElement, LinkProperty | 'a' | 'b' | 'stiffness' | 'damping' | 'length'>;
  'physics-pin': AttributesOf<PhysicsPinElement, LinkProperty | 'body' | 'particle' | 'compliance'>;
}

/** Every tag of the library. */
export type PhysicsTagName = keyof PhysicsElementAttributes;

/** The scenes' tags: they fire every `physics-*` event; the bodies and links fire `physics-error`. */
type SceneTag = 'physics-scene' | 'cloth-sim' | 'ragdoll-sim';

/** The `physics-*` events an element of tag T fires (each bubbles, so a scene also hears its children's). */
export type PhysicsEventsOf<T extends PhysicsTagName> = T extends SceneTag ? PhysicsEventName : 'physics-error';

/**
 * Optional event-listener props for tag T, named `${Prefix}${event}`: `onphysics-error` for React 19 and Preact
 * (Prefix 'on'), `on:physics-error` for Solid (Prefix 'on:'). Each listener gets the event with its typed detail.
 */
export type PhysicsEventHandlers<T extends PhysicsTagName, Prefix extends string = 'on'> = {
  [E in PhysicsEventsOf<T> as `${Prefix}${E}`]?: (event: PhysicsEventMap[E]) => void;
};
