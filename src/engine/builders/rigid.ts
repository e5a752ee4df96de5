import type { Vec2, World } from '../world.js';
import { angleOf, coordinate, finite, oneOf, positive, speed } from '../validate.js';
import { BODY_MODELS, BODY_OPTIONS, builderOptions, collisionOptions, colliderOf, complianceOf, massEach, point, transactional, type BodyModel, type BodyOptions, type Built } from './common.js';
import { checkSimple, decompose } from '../collision/decompose.js';

/** What a rigid box, polygon or circle takes besides its shape. */
export interface RigidOptions extends BodyOptions {
  /** 'rigid' (default): one rigid body (pose, velocity, spin, inertia from the shape); 'particles': a frame of
   *  corner particles braced by sticks, deformable with `compliance` (the thesis' model). */
  model?: BodyModel;
  /** Moved by its velocities only (a moving platform, a turning drum); rigid model only. */
  kinematic?: boolean;
  /** Initial velocity and (rigid model) angular velocity, rad/s. */
  vx?: number;
  vy?: number;
  angularVelocity?: number;
}

export interface PolygonOptions extends RigidOptions {
  /** Outline in body coordinates, at least 3 points, either orientation; any simple polygon (a concave one collides
   *  as convex parts from an ear-clipping + Hertel–Mehlhorn decomposition). */
  points: { x: number; y: number }[];
  /** Where the body's origin goes. Default (0, 0). */
  x?: number;
  y?: number;
  /** Rotation in radians. Default 0. */
  angle?: number;
  /** Total mass. Default: the outline's area (density 1). */
  mass?: number;
  /** Compliance of the frame's sticks; 0 (default) is rigid. */
  compliance?: number;
}

export interface BoxOptions extends RigidOptions {
  x: number;
  y: number;
  width: number;
  height: number;
  angle?: number;
  mass?: number;
  compliance?: number;
}

export const RIGID_OPTIONS = { ...BODY_OPTIONS, model: true, kinematic: true, vx: true, vy: true, angularVelocity: true } satisfies Record<keyof RigidOptions, true>;
const POLYGON_OPTIONS = { ...RIGID_OPTIONS, points: true, x: true, y: true, angle: true, mass: true, compliance: true } satisfies Record<keyof PolygonOptions, true>;
const BOX_OPTIONS = { ...RIGID_OPTIONS, x: true, y: true, width: true, height: true, angle: true, mass: true, compliance: true } satisfies Record<keyof BoxOptions, true>;

/**
 * A rigid polygon as perimeter particles braced by sticks (seed 2.3): the n perimeter links plus a fan of
 * n − 3 diagonals from vertex 0, which is 2n − 3 links, exactly what fixes a planar frame of n points.
 */
export function createPolygon(world: World, o: PolygonOptions): Built {
  builderOptions(world, 'polygon', o, POLYGON_OPTIONS);
  if (modelOf(o) === 'rigid') return createRigid(world, o, o.points);
  return createFrame(world, o, []);
}

/** The model asked for ('rigid' by default); a particle frame cannot be kinematic. */
export function modelOf(o: RigidOptions | undefined): BodyModel {
  const model = oneOf('model', o?.model ?? 'rigid', BODY_MODELS);
  if (model === 'particles' && o?.kinematic) throw new TypeError("kinematic needs model 'rigid' (a particle frame has no prescribed motion)");
  return model;
}

/** The rigid model of a box, polygon or circle: one rigid body (World.addRigidBody) and its one particle. */
export function createRigid(world: World, o: RigidOptions & { x?: number; y?: number; angle?: number; mass?: number }, points?: { x: number; y: number }[], radius?: number): Built {
  if (o.static && o.kinematic) throw new TypeError('a body is either static or kinematic, not both');
  const body = world.addRigidBody({
    points,
    radius,
    x: o.x ?? 0,
    y: o.y ?? 0,
    angle: o.angle,
    vx: o.vx,
    vy: o.vy,
    angularVelocity: o.angularVelocity,
    type: o.static ? 'static' : o.kinematic ? 'kinematic' : 'dynamic',
    mass: o.static ? undefined : o.mass,
    ...collisionOptions(o),
  });
  return { body, particles: world.bodyParticleHandles(body), constraints: [] };
}

/** createPolygon plus extra bracing links between the given vertex pairs. */
function createFrame(world: World, o: PolygonOptions, extraBraces: [number, number][]): Built {
  if (!Array.isArray(o.points) || o.points.length < 3) {
    throw new RangeError(`points must be a list of at least 3 points, got ${Array.isArray(o.points) ? o.points.length : String(o.points)}`);
  }
  let local = withoutRepeats(o.points.map((p, k) => point(`points[${k}]`, p)));
  // Parts and edge normals assume counter-clockwise order (positive area): reverse a clockwise outline.
  if (shoelace(local) < 0) local = local.reverse();
  const area = shoelace(local);
  if (!(area > 0)) throw new RangeError(`points must enclose a non-zero area, got ${JSON.stringify(o.points)}`);
  checkSimple(local.map((p) => p.x), local.map((p) => p.y), 'points');
  const ox = coordinate('x', o.x ?? 0);
  const oy = coordinate('y', o.y ?? 0);
  const angle = angleOf('angle', o.angle ?? 0);
  const each = o.static ? Infinity : massEach('mass', o.mass, local.length, area, 'the area');
  const compliance = complianceOf('compliance', o.compliance);
  const cos = Math.cos(angle);
  const sin = Math.sin(angle);
  const corners = local.map((p) => ({ x: ox + p.x * cos - p.y * sin, y: oy + p.x * sin + p.y * cos }));
  const velocities = o.static ? corners.map(() => ({ x: 0, y: 0 })) : frameVelocities(corners, o);
  return transactional(world, (particles, constraints) => {
    corners.forEach((c, k) => particles.push(world.addParticle({ x: c.x, y: c.y, mass: each, vx: velocities[k].x, vy: velocities[k].y })));
    const n = particles.length;
    for (let k = 0; k < n; k++) constraints.push(world.addDistance(particles[k], particles[(k + 1) % n], { compliance }));
    for (let k = 2; k < n - 1; k++) constraints.push(world.addDistance(particles[0], particles[k], { compliance }));
    for (const [a, b] of extraBraces) constraints.push(world.addDistance(particles[a], particles[b], { compliance }));
    // A fan-braced outline can be pushed inside out (a vertex across a diagonal), after which its edge normals
    // point inward and contacts push the wrong way: keeping the signed area stops that. Boxes, braced both ways,
    // do not need it.
    if (extraBraces.length === 0) constraints.push(world.addAreaConstraint(particles.slice(), { compliance }));
    // A concave outline (seed 2.8) collides as convex parts: indices into the outline, i.e. into `particles`.
    const parts = isConvex(local) ? undefined : decompose(local);
    return world.addBody('rigid', particles, constraints, colliderOf(o, 'polygon', true, parts));
  });
}

/** A box centred on (x, y): a rigid body, or (model 'particles') 4 corner particles, 4 edges and 2 diagonals. */
export function createBox(world: World, o: BoxOptions): Built {
  builderOptions(world, 'box', o, BOX_OPTIONS);
  const w = coordinate('width', positive('width', o.width)) / 2;
  const h = coordinate('height', positive('height', o.height)) / 2;
  if (modelOf(o) === 'rigid') return createRigid(world, { ...o, x: coordinate('x', o.x), y: coordinate('y', o.y) }, [{ x: -w, y: -h }, { x: w, y: -h }, { x: w, y: h }, { x: -w, y: h }]);
  // The fan gives one diagonal; the second keeps the frame square under large loads as well.
  return createFrame(
    world,
    {
    points: [
      { x: -w, y: -h },
      { x: w, y: -h },
      { x: w, y: h },
      { x: -w, y: h },
    ],
    x: o.x,
    y: o.y,
    angle: o.angle,
    mass: o.mass ?? 4 * w * h,
    compliance: o.compliance,
    static: o.static,
    vx: o.vx,
    vy: o.vy,
    angularVelocity: o.angularVelocity,
    ...collisionOptions(o),
    },
    [[1, 3]],
  );
}

/**
 * A particle frame's vx, vy and angularVelocity as each corner's start velocity: a point of a rigid body turning about
 * the corners' mean, v + ω × r. Checked before anything is built, so a speed past the limit leaves nothing behind.
 */
function frameVelocities(corners: Vec2[], o: RigidOptions): Vec2[] {
  const vx = speed('vx', o.vx ?? 0);
  const vy = speed('vy', o.vy ?? 0);
  const w = finite('angularVelocity', o.angularVelocity ?? 0);
  const cx = corners.reduce((sum, c) => sum + c.x, 0) / corners.length;
  const cy = corners.reduce((sum, c) => sum + c.y, 0) / corners.length;
  return corners.map((c) => ({ x: speed('vx', vx - w * (c.y - cy)), y: speed('vy', vy + w * (c.x - cx)) }));
}

/**
 * The outline without a point that repeats the one before it, nor a last point that repeats the first (an SVG outline
 * closed by its first point): they add no corner, only a zero-length edge (the rigid model's cleanOutline drops them
 * too). Later repeats go, so the points kept keep their places.
 */
function withoutRepeats(points: Vec2[]): Vec2[] {
  const kept: Vec2[] = [];
  for (const p of points) {
    const last = kept[kept.length - 1];
    if (!last || last.x !== p.x || last.y !== p.y) kept.push(p);
  }
  while (kept.length > 1 && kept[kept.length - 1].x === kept[0].x && kept[kept.length - 1].y === kept[0].y) kept.pop();
  return kept;
}

/** Whether a counter-clockwise outline turns left (or goes straight) at every vertex. */
function isConvex(points: { x: number; y: number }[]): boolean {
  const n = points.length;
  for (let k = 0; k < n; k++) {
    const a = points[k];
    const b = points[(k + 1) % n];
    const c = points[(k + 2) % n];
    if ((b.x - a.x) * (c.y - b.y) - (b.y - a.y) * (c.x - b.x) < 0) return false;
  }
  return true;
}

export function shoelace(points: { x: number; y: number }[]): number {
  let s = 0;
  for (let k = 0; k < points.length; k++) {
    const a = points[k];
    const b = points[(k + 1) % points.length];
    s += a.x * b.y - b.x * a.y;
  }
  return s / 2;
}
