// Stopgaps for the worker host where the World facade does not serve rigid bodies yet. Each belongs on World (a
// getter beside `contacts`, a fix in setCollider); until then they reach the world's step context, which World keeps
// private.
import type { Handle } from './handles.js';
import { resolveCollider } from './options.js';
import type { StepContext } from './pipeline/context.js';
import type { RigidContacts } from './rigid/contacts.js';
import type { World } from './world.js';

function contextOf(world: World): StepContext {
  return (world as unknown as { ctx: StepContext }).ctx;
}

/** This step's contact points where at least one side is a rigid body (see RigidContacts), for debug drawing. */
export function rigidContactsOf(world: World): RigidContacts {
  return contextOf(world).rigidContacts;
}

/**
 * Changes a rigid body's friction and restitution, checked as setCollider checks them. (World.setCollider checks a
 * rigid body's collider as if its one particle were its outline, and refuses it; and it would read a rigid
 * collider's shape back as 'none'.)
 */
export function setRigidMaterial(world: World, body: Handle, friction: number, restitution: number): void {
  const o = resolveCollider({ friction, restitution }, 3);
  const ctx = contextOf(world);
  const slot = ctx.bodies.slotOf(body);
  ctx.colliders.friction[slot] = o.friction;
  ctx.colliders.restitution[slot] = o.restitution;
  world.wake(body);
}
