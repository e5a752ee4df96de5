// The world's queries (bodiesAtPoint, bodiesInBox, rayCast) against brute-force oracles on random scenes: concave
// polygons (several convex parts each), rigid and built of particles, and rigid discs, overlapping one another. The
// hand-picked cases in features.test.ts are all convex bodies of one part, so a query that looked at a body's first
// convex part only, or a box query that took a part's bounds a unit too wide, passed them.
import { expect } from 'chai';
import { World, createCircle, createPolygon, type Handle } from '../../../src/engine/index.js';
import { Failures, insideSimple, rng, segDist } from '../collision/helpers.js';

type P = { x: number; y: number };
type Body = { handle: Handle; outline: P[] | null; cx: number; cy: number; r: number };

/** A star-shaped simple polygon about (cx, cy): n vertices at increasing angles, radii from 0.25 to 1.6 (concave). */
function star(r: () => number, cx: number, cy: number): P[] {
  const n = 5 + Math.floor(r() * 5);
  const points: P[] = [];
  for (let k = 0; k < n; k++) {
    const a = ((k + 0.2 + 0.6 * r()) / n) * 2 * Math.PI;
    const radius = k % 2 === 0 ? 1 + 0.6 * r() : 0.25 + 0.5 * r();
    points.push({ x: cx + radius * Math.cos(a), y: cy + radius * Math.sin(a) });
  }
  return points;
}

function randomScene(seed: number): { world: World; bodies: Body[] } {
  const r = rng(seed);
  const world = new World({ gravity: { x: 0, y: 0 }, sleeping: false, bounds: null });
  const bodies: Body[] = [];
  for (let k = 0; k < 14; k++) {
    const cx = -6 + 12 * r();
    const cy = -6 + 12 * r();
    if (k % 4 === 3) {
      const radius = 0.3 + r();
      bodies.push({ handle: createCircle(world, { x: cx, y: cy, radius, static: true }).body, outline: null, cx, cy, r: radius });
    } else {
      let outline = star(r, cx, cy);
      const model = k % 2 === 0 ? 'rigid' : 'particles';
      let handle: Handle;
      try {
        handle = createPolygon(world, { points: outline, static: true, model }).body;
      } catch {
        outline = outline.slice().reverse();
        handle = createPolygon(world, { points: outline, static: true, model }).body;
      }
      bodies.push({ handle, outline, cx, cy, r: 0 });
    }
  }
  return { world, bodies };
}

const inside = (b: Body, x: number, y: number): boolean => (b.outline ? insideSimple(b.outline, x, y) : Math.hypot(x - b.cx, y - b.cy) <= b.r);

/** Distance from (x, y) to the body's boundary. */
function toBoundary(b: Body, x: number, y: number): number {
  if (!b.outline) return Math.abs(Math.hypot(x - b.cx, y - b.cy) - b.r);
  let d = Infinity;
  const o = b.outline;
  for (let k = 0; k < o.length; k++) {
    const q = o[(k + 1) % o.length];
    d = Math.min(d, segDist(x, y, o[k].x, o[k].y, q.x, q.y));
  }
  return d;
}

/** Where along (x0, y0) + t·(dx, dy), t in [0, 1], the segment first meets the body's boundary (Infinity: never). */
function firstT(b: Body, x0: number, y0: number, dx: number, dy: number): number {
  if (!b.outline) {
    const fx = x0 - b.cx;
    const fy = y0 - b.cy;
    const A = dx * dx + dy * dy;
    const B = 2 * (fx * dx + fy * dy);
    const C = fx * fx + fy * fy - b.r * b.r;
    const disc = B * B - 4 * A * C;
    if (disc < 0) return Infinity;
    const t = (-B - Math.sqrt(disc)) / (2 * A);
    return t >= 0 && t <= 1 ? t : Infinity;
  }
  let best = Infinity;
  const o = b.outline;
  for (let k = 0; k < o.length; k++) {
    const a = o[k];
    const c = o[(k + 1) % o.length];
    const ex = c.x - a.x;
    const ey = c.y - a.y;
    const den = dx * ey - dy * ex;
    if (den === 0) continue;
    const t = ((a.x - x0) * ey - (a.y - y0) * ex) / den;
    const u = ((a.x - x0) * dy - (a.y - y0) * dx) / den;
    if (t >= 0 && t <= 1 && u >= 0 && u <= 1) best = Math.min(best, t);
  }
  return best;
}

/** Whether the body overlaps the box (a polygon: a vertex in the box, a box corner in it, or crossing edges). */
function overlaps(b: Body, minX: number, minY: number, maxX: number, maxY: number): boolean {
  if (!b.outline) {
    const qx = Math.max(minX, Math.min(b.cx, maxX));
    const qy = Math.max(minY, Math.min(b.cy, maxY));
    return Math.hypot(b.cx - qx, b.cy - qy) <= b.r;
  }
  if (b.outline.some((p) => p.x >= minX && p.x <= maxX && p.y >= minY && p.y <= maxY)) return true;
  const corners: P[] = [{ x: minX, y: minY }, { x: maxX, y: minY }, { x: maxX, y: maxY }, { x: minX, y: maxY }];
  if (corners.some((p) => insideSimple(b.outline!, p.x, p.y))) return true;
  for (let k = 0; k < 4; k++) {
    const a = corners[k];
    const c = corners[(k + 1) % 4];
    if (firstT(b, a.x, a.y, c.x - a.x, c.y - a.y) !== Infinity) return true;
  }
  return false;
}

const sorted = (hs: Handle[]): Handle[] => hs.slice().sort((p, q) => p - q);

describe('world queries against brute force on random concave and round bodies', () => {
  it('bodiesAtPoint: every body whose shape holds the point, and no other (3,000 points in 10 scenes)', () => {
    const fail = new Failures();
    let hits = 0;
    let multiple = 0;
    for (let seed = 1; seed <= 10; seed++) {
      const { world, bodies } = randomScene(seed);
      const r = rng(100 + seed);
      for (let k = 0; k < 300; k++) {
        // Half the points near a body, so most land inside one.
        const b = bodies[Math.floor(r() * bodies.length)];
        const [x, y] = k % 2 === 0 ? [b.cx - 1.6 + 3.2 * r(), b.cy - 1.6 + 3.2 * r()] : [-8 + 16 * r(), -8 + 16 * r()];
        if (bodies.some((q) => toBoundary(q, x, y) < 1e-6)) continue;
        const expected = sorted(bodies.filter((q) => inside(q, x, y)).map((q) => q.handle));
        const got = sorted(world.bodiesAtPoint(x, y));
        if (JSON.stringify(got) !== JSON.stringify(expected)) fail.add(`seed ${seed}, (${x}, ${y}): got ${got}, expected ${expected}`);
        if (expected.length > 0) hits++;
        if (expected.length > 1) multiple++;
      }
    }
    fail.check();
    expect(hits, 'points inside some body').to.be.above(500);
    expect(multiple, 'points inside two or more').to.be.above(50);
  });

  it('bodiesInBox: every body whose shape meets the box, and no other (3,000 boxes in 10 scenes)', () => {
    const fail = new Failures();
    let found = 0;
    let near = 0;
    for (let seed = 1; seed <= 10; seed++) {
      const { world, bodies } = randomScene(seed);
      const r = rng(200 + seed);
      for (let k = 0; k < 300; k++) {
        const b = bodies[Math.floor(r() * bodies.length)];
        const w = 0.05 + (k % 3 === 0 ? 3 : 0.6) * r();
        const h = 0.05 + (k % 3 === 0 ? 3 : 0.6) * r();
        const minX = b.cx - 2 + 4 * r() - w / 2;
        const minY = b.cy - 2 + 4 * r() - h / 2;
        const [maxX, maxY] = [minX + w, minY + h];
        // Ties (the box within 1e-6 of touching a body) are left out: the box grown and shrunk must agree.
        const e = 1e-6;
        const grown = bodies.filter((q) => overlaps(q, minX - e, minY - e, maxX + e, maxY + e)).map((q) => q.handle);
        const shrunk = bodies.filter((q) => overlaps(q, minX + e, minY + e, maxX - e, maxY - e)).map((q) => q.handle);
        if (JSON.stringify(sorted(grown)) !== JSON.stringify(sorted(shrunk))) continue;
        const got = sorted(world.bodiesInBox(minX, minY, maxX, maxY));
        if (JSON.stringify(got) !== JSON.stringify(sorted(grown))) fail.add(`seed ${seed}, box (${minX}, ${minY})-(${maxX}, ${maxY}): got ${got}, expected ${sorted(grown)}`);
        if (grown.length > 0) found++;
        // A body whose bounds the box meets but whose shape it misses: the case a loose bounds test gets wrong.
        if (bodies.some((q) => !grown.includes(q.handle) && Math.hypot(Math.max(minX - q.cx, 0, q.cx - maxX), Math.max(minY - q.cy, 0, q.cy - maxY)) < 1.6)) near++;
      }
    }
    fail.check();
    expect(found, 'boxes meeting some body').to.be.above(1500);
    expect(near, 'boxes near a body they miss').to.be.above(500);
  });

  it('rayCast: the nearest body along the segment, the point and the distance where it first meets it (3,000 rays in 10 scenes)', () => {
    const fail = new Failures();
    let hits = 0;
    for (let seed = 1; seed <= 10; seed++) {
      const { world, bodies } = randomScene(seed);
      const r = rng(300 + seed);
      for (let k = 0; k < 300; k++) {
        const x0 = -9 + 18 * r();
        const y0 = -9 + 18 * r();
        // Toward a body's middle or anywhere, as long as 12 at most.
        const b = bodies[Math.floor(r() * bodies.length)];
        const [tx, ty] = k % 2 === 0 ? [b.cx - 0.5 + r(), b.cy - 0.5 + r()] : [-9 + 18 * r(), -9 + 18 * r()];
        const [dx, dy] = [tx - x0, ty - y0];
        if (bodies.some((q) => inside(q, x0, y0) || toBoundary(q, x0, y0) < 1e-6)) continue;
        const ts = bodies.map((q) => firstT(q, x0, y0, dx, dy)).map((t, i) => ({ t, handle: bodies[i].handle })).sort((p, q) => p.t - q.t);
        const length = Math.hypot(dx, dy);
        // Ties between two bodies, and grazes at the segment's far end, are left out.
        if (ts[1].t !== Infinity && (ts[1].t - ts[0].t) * length < 1e-6) continue;
        const hit = world.rayCast(x0, y0, tx, ty);
        if (ts[0].t === Infinity) {
          if (hit !== null) fail.add(`seed ${seed}, ray (${x0}, ${y0}) → (${tx}, ${ty}): hit ${hit.body} at ${hit.distance}, expected none`);
          continue;
        }
        hits++;
        const d = ts[0].t * length;
        if (!hit) fail.add(`seed ${seed}, ray (${x0}, ${y0}) → (${tx}, ${ty}): no hit, expected ${ts[0].handle} at ${d}`);
        else if (hit.body !== ts[0].handle || Math.abs(hit.distance - d) > 1e-9 || Math.hypot(hit.x - (x0 + ts[0].t * dx), hit.y - (y0 + ts[0].t * dy)) > 1e-9)
          fail.add(`seed ${seed}, ray (${x0}, ${y0}) → (${tx}, ${ty}): hit ${hit.body} at ${hit.distance} (${hit.x}, ${hit.y}), expected ${ts[0].handle} at ${d}`);
      }
    }
    fail.check();
    expect(hits, 'rays that hit a body').to.be.above(1500);
  });
});
