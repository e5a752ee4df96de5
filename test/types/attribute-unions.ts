// Type-only checks (compiled by `npx tsc --noEmit -p test/tsconfig.json`, never run): the literal unions of the
// elements' enum-like properties are the values their checks accept, so the types and the markup checks cannot drift.
// The elements write the unions out (the manifest and docs/elements.md show them); these tie them to the engine's
// types and to the lists the checks take.
import type { BodyModel, JointType, KernelChoice, WorldOptions } from '../../src/engine/index.js';
import type { ClothPinsAttribute, PhysicsJointElement, PhysicsRopeElement, PhysicsSceneElement, PhysicsSoftbodyElement, PhysicsBoxElement, RagdollSimElement } from '../../src/bundle.js';
import type { ClothPins } from '../../src/engine/builders/cloth.js';
import type { SceneConfig } from '../../src/elements/physics-scene/config.js';

/** true when A and B are the same type (not merely assignable one way). */
type Equal<A, B> = (<T>() => T extends A ? 1 : 2) extends <T>() => T extends B ? 1 : 2 ? true : false;
const same = <T extends true>(): T | void => undefined;

// <physics-scene>: what readConfig() checks each against, and what the engine takes.
same<Equal<PhysicsSceneElement['kernel'], KernelChoice>>();
same<Equal<PhysicsSceneElement['broadphase'], NonNullable<WorldOptions['broadphase']>>>();
same<Equal<PhysicsSceneElement['narrowphase'], NonNullable<WorldOptions['narrowphase']>>>();
same<Equal<PhysicsSceneElement['broadphase'], SceneConfig['broadphase']>>();
same<Equal<PhysicsSceneElement['narrowphase'], SceneConfig['narrowphase']>>();
same<Equal<PhysicsSceneElement['bounds'], SceneConfig['bounds']>>();
same<Equal<PhysicsSceneElement['worker'], SceneConfig['worker']>>();
same<Equal<PhysicsSceneElement['drawMode'], SceneConfig['drawMode']>>();
same<Equal<PhysicsSceneElement['substeps'], SceneConfig['substeps']>>();
// Bodies and links: the engine's lists (BODY_MODELS, JOINT_TYPES) and the elements' own checks.
same<Equal<NonNullable<PhysicsBoxElement['model']>, BodyModel>>();
same<Equal<NonNullable<PhysicsJointElement['type']>, JointType>>();
same<Equal<NonNullable<PhysicsSoftbodyElement['model']>, 'pressure' | 'springs'>>();
same<Equal<NonNullable<PhysicsRopeElement['pin']>, 'start' | 'end' | 'both' | 'none'>>();
same<Equal<RagdollSimElement['obstacles'], 'stairs' | 'pegs' | 'none'>>();
// The cloths' pins: the engine's named choices, or column numbers as text.
same<Equal<Extract<ClothPinsAttribute, 'top' | 'corners' | 'none'>, Exclude<ClothPins, number[]>>>();
const pins: ClothPinsAttribute[] = ['top', 'corners', 'none', '3', '0 8 16 23', '0,23', '0, 23'];
// @ts-expect-error a misspelt choice
const misspelt: ClothPinsAttribute = 'corner';
// @ts-expect-error not a column number
const word: ClothPinsAttribute = 'left right';
// @ts-expect-error the kernel's choices are auto, wasm and js
const kernel: PhysicsSceneElement['kernel'] = 'wsam';

export { pins, misspelt, word, kernel };
