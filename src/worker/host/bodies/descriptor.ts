// What the host knows about one body type: how a grab holds it, where its pose is read, and which drawing facts it
// puts in the topology. One module per type (box.ts, circle.ts, …), listed in index.ts. How a type is drawn is the
// renderer's half, in src/render/bodies/: the worker never loads drawing code, the page never loads this.
import type { BodyDescription, BodyType, Handle, Vec2, World } from '../../../engine/index.js';
import type { TopologyBody } from '../../protocol.js';

/** The description of a body of type T. */
export type DescriptionOf<T extends BodyType> = Extract<BodyDescription, { type: T }>;

/**
 * Pose bookkeeping measured once, when a body is built (snapshots carry it as it is): the angle of its first edge
 * (particle 0 → 1), the offset from where its pose is read to the described origin, and the described angle.
 */
export type PoseBasis = [edge0: number, dx: number, dy: number, angle0: number];

/**
 * How a type's pose (x, y, angle) follows its particles: from their mean, or from one particle (`anchor`); at the
 * description's x, y carried along (`described`: a rigid shape's origin need not be its particles' mean), turning
 * with its first edge (`turns`) or keeping the described angle.
 */
export interface PoseModel {
  readonly described?: boolean;
  readonly turns?: boolean;
  /** The body's particle whose position is its pose (a ragdoll's pelvis). */
  readonly anchor?: number;
}

/** A body as built in the world, for the descriptor to read. */
export interface BuiltBody {
  world: World;
  handle: Handle;
  /** Its particles' storage indices. */
  indices: Int32Array;
}

export interface BodyDescriptor<T extends BodyType = BodyType> {
  /**
   * How a grab holds it when built of particles (a rigid body is always held softly, at the point). 'soft': at the
   * point, pulled with the body's mass (particle frames). 'firm': its particle under the point, held tight — a soft
   * pull on one light particle would lose to the rigid links of the rest of its body (cloth, ropes, ragdolls, soft
   * rings, particle balls).
   */
  readonly grip: 'soft' | 'firm';
  /** Where its pose is read when built of particles (a rigid body's pose is its centre of mass and angle). */
  readonly pose: PoseModel;
  /** The outline of its rigid model, in its own coordinates (boxes, polygons; a disc has its radius instead). */
  rigidOutline?(desc: DescriptionOf<T>): Vec2[];
  /** Drawing facts beyond the particles (a radius, the cloth grid and its torn links, the soft ring's length). */
  describe?(topology: TopologyBody, desc: DescriptionOf<T>, body: BuiltBody): void;
  /** The closed loop of particles a press inside it grabs by its nearest particle (a soft ring). */
  outline?(desc: DescriptionOf<T>, indices: Int32Array): Int32Array;
}
