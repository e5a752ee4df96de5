// The engine running on the main thread, drawn with p5 straight from its typed arrays. Pointer drag uses a soft pin.
import p5 from 'p5';
import { World, createCloth, createRope, type Handle } from '../src/engine/index.js';

const WIDTH = 12; // world units across the canvas; y grows downward
const HEIGHT = 8;

const world = new World({ gravity: { x: 0, y: 9.81 }, bounds: { minX: 0, minY: 0, maxX: WIDTH, maxY: HEIGHT } });
const COLUMNS = 24;
const ROWS = 18;
const cloth = createCloth(world, { origin: { x: 1, y: 0.8 }, columns: COLUMNS, rows: ROWS, spacing: 0.25, pins: [0, 5, 11, 17, 23], shear: 1e-3, bend: 5e-3 });
const rope = createRope(world, { from: { x: 9, y: 0.8 }, to: { x: 11.5, y: 0.8 }, segments: 30, radius: 0.04 });
world.applyImpulse(cloth.particles[cloth.particles.length - 1], 0.05, -0.02);
// Gather the curtain's pins a little so the cloth drapes in folds between them.
cloth.constraints
  .filter((c) => world.constraintKindOf(c) === 'pin')
  .forEach((pin, k) => world.setPinTarget(pin, 1.6 + k * 1.2, 0.8));
const clothIndex = world.bodyParticleIndices(cloth.body);
const ropeIndex = world.bodyParticleIndices(rope.body);

const stage = document.getElementById('stage')!;
const stats = document.getElementById('stats')!;
let drag: { pin: Handle; particle: Handle } | null = null;
let physicsMs = 0;

new p5((s: p5) => {
  let scale = 1;
  const fit = () => {
    s.resizeCanvas(stage.clientWidth, stage.clientHeight);
    scale = stage.clientWidth / WIDTH;
  };
  s.setup = () => {
    s.createCanvas(stage.clientWidth, stage.clientHeight);
    // Sharp on a 3× phone screen, as the elements are.
    s.pixelDensity(Math.min(3, window.devicePixelRatio));
    fit();
    new ResizeObserver(fit).observe(stage);
  };
  s.draw = () => {
    const t0 = performance.now();
    world.advance(Math.min(s.deltaTime, 100) / 1000);
    physicsMs = 0.9 * physicsMs + 0.1 * (performance.now() - t0);
    s.background('#fbfaf7');
    const { x, y } = world.particles;
    const at = (c: number, r: number) => clothIndex[r * COLUMNS + c];
    // One shape per style: all the cloth's grid lines in one LINES shape, the rope in one polyline.
    s.strokeWeight(1.2);
    s.stroke('#3a6ea5');
    s.noFill();
    s.beginShape(s.LINES);
    for (let r = 0; r < ROWS; r++) {
      for (let c = 0; c < COLUMNS; c++) {
        const i = at(c, r);
        if (c + 1 < COLUMNS) s.vertex(x[i] * scale, y[i] * scale), s.vertex(x[at(c + 1, r)] * scale, y[at(c + 1, r)] * scale);
        if (r + 1 < ROWS) s.vertex(x[i] * scale, y[i] * scale), s.vertex(x[at(c, r + 1)] * scale, y[at(c, r + 1)] * scale);
      }
    }
    s.endShape();
    s.stroke('#8e2a1e');
    s.strokeWeight(2);
    s.beginShape();
    for (const i of ropeIndex) s.vertex(x[i] * scale, y[i] * scale);
    s.endShape();
    s.noStroke();
    s.fill('#c0392b');
    for (const i of ropeIndex) s.circle(x[i] * scale, y[i] * scale, 0.08 * scale);
    stats.textContent = `${world.particleCount} particles · ${world.constraintCount} constraints · physics ${physicsMs.toFixed(2)} ms/frame · ${s.frameRate().toFixed(0)} fps`;
  };
  // Pointer events straight from the stage: the p5 the builds ship has no events addon (no mouseX, mousePressed).
  const toWorld = (e: PointerEvent) => {
    const box = stage.getBoundingClientRect();
    return { mx: (e.clientX - box.left) / scale, my: (e.clientY - box.top) / scale };
  };
  stage.addEventListener('pointerdown', (e) => {
    const { mx, my } = toWorld(e);
    let best = -1;
    let bestD = 0.4;
    const { x, y, invMass } = world.particles;
    for (let i = 0; i < world.particles.count; i++) {
      const dd = Math.sqrt((x[i] - mx) ** 2 + (y[i] - my) ** 2);
      if (world.particles.alive[i] && invMass[i] > 0 && dd < bestD) [best, bestD] = [i, dd];
    }
    if (best >= 0) {
      const particle = world.particleHandle(best);
      drag = { particle, pin: world.addPin(particle, { x: mx, y: my, compliance: 1e-3 }) };
      stage.setPointerCapture(e.pointerId);
    }
  });
  stage.addEventListener('pointermove', (e) => {
    if (!drag) return;
    const { mx, my } = toWorld(e);
    world.setPinTarget(drag.pin, mx, my);
  });
  const release = () => {
    if (drag) world.removeConstraint(drag.pin);
    drag = null;
  };
  stage.addEventListener('pointerup', release);
  stage.addEventListener('pointercancel', release);
}, stage);
