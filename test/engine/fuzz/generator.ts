// Seeded random scenes for fuzzing the engine: every body and constraint kind, degenerate-but-valid shapes, mass
// ratios up to 1:1000, very fast bodies, random drags, impulses, gravity changes, and bodies added and removed while
// the scene runs. The same seed always makes the same scene and the same script of actions.
import {
  World, buildBody, createRope, createBox, type BodyDescription, type Handle,
} from '../../../src/engine/index.js';

export function mulberry32(seed: number): () => number {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

export const FUZZ_BOUNDS = { minX: -60, minY: -80, maxX: 60, maxY: 20 };

function randomBody(rnd: () => number): BodyDescription {
  const pick = <T>(xs: T[]) => xs[Math.floor(rnd() * xs.length)];
  const x = (rnd() * 2 - 1) * 30;
  const y = -rnd() * 40;
  const mass = 10 ** (rnd() * 3 - 1.5); // 0.03 .. 30: ratios up to 1:1000
  const common = { friction: rnd() * 1.2, restitution: rnd() < 0.3 ? rnd() : 0, static: rnd() < 0.1 };
  // Boxes, circles and polygons: rigid bodies mostly (some kinematic, some spinning), particle frames sometimes.
  const model = rnd() < 0.25 ? ('particles' as const) : ('rigid' as const);
  const motion = model === 'rigid' ? { kinematic: !common.static && rnd() < 0.05, angularVelocity: rnd() < 0.2 ? (rnd() * 2 - 1) * 20 : 0, model } : { model };
  switch (pick(['box', 'box', 'thin', 'circle', 'polygon', 'rope', 'cloth', 'soft', 'springs', 'ragdoll'])) {
    case 'box':
      return { type: 'box', x, y, width: 0.2 + rnd() * 3, height: 0.2 + rnd() * 3, angle: rnd() * 7, mass, ...common, ...motion };
    case 'thin': // a sliver: valid but nearly degenerate
      return { type: 'box', x, y, width: 0.01 + rnd() * 0.02, height: 1 + rnd() * 5, angle: rnd() * 7, mass, ...common, ...motion };
    case 'circle':
      return { type: 'circle', x, y, radius: 0.05 + rnd() * 1.5, mass, ...common, ...motion };
    case 'polygon': {
      const n = 3 + Math.floor(rnd() * 6);
      const r = 0.3 + rnd() * 2;
      const points = Array.from({ length: n }, (_, k) => {
        const t = (2 * Math.PI * k) / n + rnd() * 0.3;
        return { x: r * Math.cos(t), y: r * Math.sin(t) };
      });
      return { type: 'polygon', x, y, points, mass, ...common, ...motion };
    }
    case 'rope':
      return { type: 'rope', from: { x, y }, to: { x: x + (rnd() * 2 - 1) * 8, y: y + rnd() * 5 }, segments: 2 + Math.floor(rnd() * 30), mass, collide: rnd() < 0.5, radius: 0.05, pinStart: rnd() < 0.7 };
    case 'cloth':
      return { type: 'cloth', origin: { x, y }, columns: 2 + Math.floor(rnd() * 10), rows: 2 + Math.floor(rnd() * 10), spacing: 0.1 + rnd() * 0.5, shear: rnd() < 0.5 ? 1e-4 : null, pins: pick(['top', 'corners', 'none'] as const), collide: rnd() < 0.3, radius: 0.05 };
    case 'soft':
      return { type: 'softbody', center: { x, y }, radius: 0.3 + rnd() * 2, segments: 3 + Math.floor(rnd() * 20), pressure: 0.5 + rnd(), mass, ...common };
    case 'springs':
      return { type: 'softbody', center: { x, y }, radius: 0.3 + rnd() * 2, model: 'springs', stiffness: rnd() * 2000, damping: rnd() * 5, mass, ...common };
    default:
      return { type: 'ragdoll', x, y, height: 0.5 + rnd() * 2.5, mass: mass * 20, jointCompliance: rnd() < 0.5 ? 0 : 1e-4 };
  }
}

export interface FuzzRun {
  world: World;
  /** Runs `steps` steps, doing the scripted random actions between them. */
  run(steps: number): void;
}

/** A random scene and its action script, fully determined by the seed; under `kernel` when given (else the World's default). */
export function fuzzScene(seed: number, kernel?: 'js' | 'wasm'): FuzzRun {
  const rnd = mulberry32(seed);
  const world = new World({
    ...(kernel ? { kernel } : {}),
    gravity: { x: (rnd() * 2 - 1) * 3, y: 5 + rnd() * 15 },
    substeps: 1 + Math.floor(rnd() * 12),
    iterations: 1 + Math.floor(rnd() * 3),
    damping: rnd() < 0.5 ? 0 : rnd(),
    bounds: FUZZ_BOUNDS,
    broadphase: rnd() < 0.8 ? 'grid' : 'brute',
    narrowphase: rnd() < 0.7 ? 'sat' : 'gjk',
    sleeping: rnd() < 0.7,
  });
  createBox(world, { x: 0, y: 1, width: 100, height: 2, static: true });
  const bodies: Handle[] = [];
  const count = 3 + Math.floor(rnd() * 25);
  for (let k = 0; k < count; k++) bodies.push(buildBody(world, randomBody(rnd)).body);
  // Joints between bodies: distance links and springs between random particles of two bodies.
  for (let k = 0; k < Math.floor(rnd() * 4) && bodies.length > 1; k++) {
    const a = world.bodyParticleHandles(bodies[Math.floor(rnd() * bodies.length)]);
    const b = world.bodyParticleHandles(bodies[Math.floor(rnd() * bodies.length)]);
    const pa = a[Math.floor(rnd() * a.length)];
    const pb = b[Math.floor(rnd() * b.length)];
    if (pa === pb) continue;
    // Joints start satisfied, as markup joints do (they link bodies at their current distance).
    const gap = Math.hypot(world.getPosition(pa).x - world.getPosition(pb).x, world.getPosition(pa).y - world.getPosition(pb).y);
    if (rnd() < 0.5) world.addDistance(pa, pb, { minLength: 0, maxLength: gap * (1 + rnd()) });
    else world.addSpring(pa, pb, { stiffness: rnd() * 500, damping: rnd() * 3 });
  }
  // Rigid joints between a rigid body and a rigid body near it, a particle near it, or the world, at a point near it
  // (as markup joins neighbours; a joint across half the scene would make a lever whose spinning tip outruns the
  // invariants' speed limit without anything being wrong).
  const rigid = bodies.filter((h) => world.bodyKindOf(h) === 'rigid' && world.bodyParticleHandles(h).length === 1);
  const near = (h: Handle, p: { x: number; y: number }) => {
    const q = world.getPosition(world.bodyParticleHandles(h)[0]);
    return Math.hypot(q.x - p.x, q.y - p.y) < 4;
  };
  for (let k = 0; k < Math.floor(rnd() * 5) && rigid.length > 0; k++) {
    const a = rigid[Math.floor(rnd() * rigid.length)];
    const pose = world.bodyPose(a);
    const anchor = { x: pose.x + (rnd() * 2 - 1), y: pose.y + (rnd() * 2 - 1) };
    const type = (['revolute', 'weld', 'prismatic', 'distance', 'spring'] as const)[Math.floor(rnd() * 5)];
    const neighbours = rigid.filter((h) => h !== a && near(h, anchor));
    const loose = bodies.filter((h) => world.bodyKindOf(h) !== 'rigid' && near(h, anchor));
    const other = rnd();
    const side =
      other < 0.3 || (neighbours.length === 0 && loose.length === 0)
        ? {}
        : (other < 0.7 && neighbours.length > 0) || loose.length === 0
          ? { b: neighbours[Math.floor(rnd() * neighbours.length)] }
          : { particleB: world.bodyParticleHandles(loose[Math.floor(rnd() * loose.length)])[0] };
    world.addJoint({
      type, a, ...side, anchor,
      lowerAngle: type === 'revolute' && rnd() < 0.5 ? -rnd() : undefined,
      upperAngle: type === 'revolute' && rnd() < 0.5 ? rnd() : undefined,
      motorSpeed: type === 'revolute' && rnd() < 0.3 ? (rnd() * 2 - 1) * 10 : undefined,
      maxMotorTorque: type === 'revolute' && rnd() < 0.3 ? rnd() * 100 : undefined,
      lower: type === 'prismatic' ? -rnd() * 2 : undefined,
      upper: type === 'prismatic' ? rnd() * 2 : undefined,
      stiffness: type === 'spring' ? 1 + rnd() * 500 : undefined,
      damping: type === 'spring' ? rnd() * 5 : undefined,
    });
  }
  let grab: Handle | null = null;
  return {
    world,
    run(steps: number) {
      for (let k = 0; k < steps; k++) {
        const r = rnd();
        const live = bodies.filter((h) => world.hasBody(h));
        if (r < 0.02 && live.length) {
          // A very fast body: a kick of up to 500 units/s (impulse = its mass × the speed).
          const h = live[Math.floor(rnd() * live.length)];
          let mass = 0;
          for (const q of world.bodyParticleHandles(h)) if (world.getMass(q) < Infinity) mass += world.getMass(q);
          world.applyBodyImpulse(h, (rnd() * 2 - 1) * 350 * mass, (rnd() * 2 - 1) * 350 * mass);
        } else if (r < 0.04) {
          if (grab !== null && world.hasConstraint(grab)) world.release(grab);
          grab = world.grab((rnd() * 2 - 1) * 30, -rnd() * 40, { pickRadius: 3 });
        } else if (r < 0.2 && grab !== null && world.hasConstraint(grab)) {
          world.moveGrab(grab, (rnd() * 2 - 1) * 40, -rnd() * 60);
        } else if (r < 0.21 && live.length) {
          world.removeBody(live[Math.floor(rnd() * live.length)]);
        } else if (r < 0.22) {
          bodies.push(buildBody(world, randomBody(rnd)).body);
        } else if (r < 0.225) {
          world.setGravity((rnd() * 2 - 1) * 20, (rnd() * 2 - 1) * 20);
        } else if (r < 0.23) {
          const rope = createRope(world, { from: { x: rnd() * 10, y: -30 }, to: { x: rnd() * 10 + 5, y: -30 }, segments: 5, collide: true, radius: 0.1 });
          bodies.push(rope.body);
        }
        world.step();
      }
    },
  };
}

/** Checks the invariants; returns a description of the first violation, or null. */
export function violation(world: World, speedLimit = 5000): string | null {
  const p = world.particles;
  const margin = 1;
  for (let i = 0; i < p.count; i++) {
    if (!p.alive[i]) continue;
    for (const [name, col] of [['x', p.x], ['y', p.y], ['px', p.px], ['py', p.py], ['vx', p.vx], ['vy', p.vy], ['invMass', p.invMass], ['angle', p.angle], ['omega', p.omega], ['invInertia', p.invInertia]] as const) {
      if (!Number.isFinite(col[i])) return `particle ${i}: ${name} is ${col[i]}`;
    }
    if (p.x[i] < FUZZ_BOUNDS.minX - margin || p.x[i] > FUZZ_BOUNDS.maxX + margin || p.y[i] < FUZZ_BOUNDS.minY - margin || p.y[i] > FUZZ_BOUNDS.maxY + margin) {
      return `particle ${i} left the bounds: (${p.x[i]}, ${p.y[i]})`;
    }
    const speed = Math.sqrt(p.vx[i] ** 2 + p.vy[i] ** 2);
    if (speed > speedLimit) return `particle ${i} moves at ${speed.toFixed(0)} units/s`;
  }
  return null;
}
