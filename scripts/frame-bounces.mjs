// Particle frames' bounces (docs/engine.md, Rigid bodies and joints: bounces): how much energy a frame (a unit box of
// model 'particles', mass 1) has after its first landing against before, over its impact energy, for seeded random
// drops (tilt, spin, height) onto the bounds, a rigid and a particle floor; the slide a frame thrown at 45° with e = 0
// keeps (Coulomb: 1 − μ); the flat drops' bounce heights against e²ᵏ·h; and spun elastic frames hitting each other.
// Usage: node scripts/frame-bounces.mjs [js|wasm] [drops=200]
import { importTs } from './build-engine-for-node.mjs';

const { World, createBox } = await importTs();
const kernel = process.argv[2] ?? 'js';
const drops = Number(process.argv[3] ?? 200);
const g = 9.81;
const floors = ['bounds', 'rigid', 'particles'];

/** A seeded generator of uniform reals in [0, 1) (mulberry32). */
function random(seed) {
  return () => {
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

function world(floor, e, mu, gravity) {
  const w = new World({ kernel, sleeping: false, gravity: { x: 0, y: gravity }, boundsFriction: mu, bounds: floor === 'bounds' ? { minX: -50, maxX: 50, minY: -50, maxY: 0 } : null });
  if (floor !== 'bounds') createBox(w, { x: 0, y: 0.5, width: 100, height: 1, static: true, model: floor, restitution: e, friction: mu });
  return w;
}

/**
 * Energy (kinetic, and potential above the floor y = 0) before the first landing and after it (the first step after
 * it in which only gravity acts: the frame's mean velocity gains g·dt exactly), over the impact energy.
 */
function drop(floor, e, tilt, spin, h) {
  const w = world(floor, e, 0, g);
  const box = createBox(w, { x: 0, y: -h - 0.8, width: 1, height: 1, angle: tilt, angularVelocity: spin, restitution: e, friction: 0, model: 'particles' });
  const rows = w.bodyParticleIndices(box.body);
  const p = w.particles;
  // Position Verlet's velocity is the mean over the substep before: its height is half a substep back.
  const half = w.timestep / w.substepCount / 2;
  const energy = () => rows.reduce((s, i) => s + (0.5 * (p.vx[i] ** 2 + p.vy[i] ** 2) - g * (p.y[i] - p.vy[i] * half)) / p.invMass[i], 0);
  const mean = (v) => rows.reduce((s, i) => s + v[i], 0) / rows.length;
  w.step();
  const before = energy();
  let vx = mean(p.vx);
  let vy = mean(p.vy);
  let landed = false;
  for (let n = 0; n < 600; n++) {
    w.step();
    const free = Math.abs(mean(p.vy) - vy - g * w.timestep) < 1e-6 && Math.abs(mean(p.vx) - vx) < 1e-6;
    vx = mean(p.vx);
    vy = mean(p.vy);
    if (!free) landed = true;
    else if (landed) return (energy() - before) / (before - 0.5 * g);
  }
  return NaN;
}

const percent = (x) => `${x >= 0 ? '+' : ''}${(100 * x).toFixed(2)}%`;
function summary(values) {
  const v = values.filter((x) => x === x).sort((a, b) => a - b);
  const at = (q) => v[Math.min(v.length - 1, Math.floor(q * v.length))];
  return `median ${percent(at(0.5))}, 10th–90th ${percent(at(0.1))} to ${percent(at(0.9))}, least ${percent(v[0])}, most ${percent(v[v.length - 1])}; over 0.5%: ${v.filter((x) => x > 0.005).length}, over 1%: ${v.filter((x) => x > 0.01).length}${v.length < values.length ? `; ${values.length - v.length} never left` : ''}`;
}

console.log(`kernel ${kernel}: energy after the first landing against before, over the impact energy (e = 1, μ = 0, ${drops} drops from 1–3)`);
for (const [label, tiltMax, spinMax] of [['almost flat (3°, 0.5 rad/s)', 0.05, 0.5], ['tilted, spun (45°, 6 rad/s)', Math.PI / 4, 6]])
  for (const floor of floors) {
    const next = random(7);
    const gains = [];
    for (let k = 0; k < drops; k++) {
      const tilt = (2 * next() - 1) * tiltMax;
      const spin = (2 * next() - 1) * spinMax;
      gains.push(drop(floor, 1, tilt, spin, 1 + 2 * next()));
    }
    console.log(`  ${label}, ${floor}: ${summary(gains)}`);
  }

console.log('energy kept of the impact energy, tilted (45°) and spun (6 rad/s), e = 0.8 and 0.5 (1 = all of it)');
for (const floor of floors)
  for (const e of [0.8, 0.5]) {
    const next = random(11);
    const kept = [];
    for (let k = 0; k < drops / 2; k++) {
      const tilt = (2 * next() - 1) * (Math.PI / 4);
      const spin = (2 * next() - 1) * 6;
      kept.push(1 + drop(floor, e, tilt, spin, 1 + 2 * next()));
    }
    kept.sort((a, b) => a - b);
    console.log(`  ${floor}, e ${e}: least ${kept[0].toFixed(3)}, median ${kept[kept.length >> 1].toFixed(3)}, most ${kept[kept.length - 1].toFixed(3)}`);
  }

console.log('flat drops from 2: each bounce height against e²ᵏ·h');
for (const floor of floors)
  for (const e of [1, 0.8, 0.5]) {
    const w = world(floor, 0, 0, g);
    const box = createBox(w, { x: 0, y: -2.5, width: 1, height: 1, restitution: e, friction: 0, model: 'particles' });
    const peaks = [];
    let last = w.bodyCentroid(box.body).y;
    let rising = false;
    for (let n = 0; n < 60 * 8 && peaks.length < 3; n++) {
      w.step();
      const y = w.bodyCentroid(box.body).y;
      if (y < last) rising = true;
      else if (rising) {
        peaks.push(-(last + 0.5));
        rising = false;
      }
      last = y;
    }
    console.log(`  ${floor}, e ${e}: ${peaks.map((y, k) => percent(y / (2 * e ** (2 * k + 2)) - 1)).join(', ')}`);
  }

console.log('thrown at 45° (10 units/s, no gravity), e = 0: slide kept (Coulomb: 1 − μ) and normal speed, landing 0–0.07 later in a step');
for (const floor of floors)
  for (const mu of [0.5, 0.2]) {
    const slide = [];
    let normal = 0;
    for (const late of [0, 0.01, 0.02, 0.03, 0.05, 0.07]) {
      const w = world(floor, 0, mu, 0);
      const v = 10 / Math.SQRT2;
      const box = createBox(w, { x: 0, y: -2 - late, width: 1, height: 1, vx: v, vy: v, restitution: 0, friction: mu, model: 'particles' });
      for (let n = 0; n < 30; n++) w.step();
      const rows = w.bodyParticleIndices(box.body);
      slide.push(rows.reduce((s, i) => s + w.particles.vx[i], 0) / rows.length / v);
      normal = Math.max(normal, Math.abs(rows.reduce((s, i) => s + w.particles.vy[i], 0) / rows.length / v));
    }
    console.log(`  ${floor}, μ ${mu}: ${slide.map((s) => s.toFixed(3)).join(' ')} (normal at most ${normal.toFixed(3)})`);
  }

{
  const next = random(5);
  const gains = [];
  let drift = 0;
  for (let k = 0; k < drops; k++) {
    const w = new World({ kernel, gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
    const a = createBox(w, { x: -2, y: (2 * next() - 1) * 0.8, width: 1, height: 1, angle: next() * 6, angularVelocity: (2 * next() - 1) * 6, vx: 3 + 5 * next(), restitution: 1, friction: 0, model: 'particles' });
    const b = createBox(w, { x: 0, y: 0, width: 1, height: 1, angle: next() * 6, angularVelocity: (2 * next() - 1) * 6, vx: -2 * next(), restitution: 1, friction: 0, model: 'particles', mass: 0.5 + next() });
    const rows = [...w.bodyParticleIndices(a.body), ...w.bodyParticleIndices(b.body)];
    const p = w.particles;
    const sums = () => rows.reduce(([e, px], i) => [e + (0.5 * (p.vx[i] ** 2 + p.vy[i] ** 2)) / p.invMass[i], px + p.vx[i] / p.invMass[i]], [0, 0]);
    w.step();
    const [e0, p0] = sums();
    for (let n = 0; n < 90; n++) w.step();
    const [e1, p1] = sums();
    gains.push(e1 / e0 - 1);
    drift = Math.max(drift, Math.abs(p1 / p0 - 1));
  }
  console.log(`${drops} spun elastic frames hitting each other (no gravity), energy after against before: ${summary(gains)}; momentum within ${drift.toExponential(1)}`);
}
