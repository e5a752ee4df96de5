// Quality measures computed the same way for every engine, from what an adapter's measure() returns:
//   { poses }    Float64Array of (x, y, angle) per dynamic body in scene order (rigid-body engines), or
//   { polygons } world vertices per box, { points } Float64Array of (x, y) per circle / chain particle / cloth node
//   (our particle engine), and optionally { strain } (our world.maxStrain()).
// All coordinates are the neutral frame of scenes.mjs (metres, y up).
import { clothLinks } from './scenes.mjs';

/** Corners of a w × h box at (x, y) rotated by angle, counter-clockwise. */
export function boxCorners(x, y, angle, w, h) {
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const out = new Float64Array(8);
  const local = [-w / 2, -h / 2, w / 2, -h / 2, w / 2, h / 2, -w / 2, h / 2];
  for (let k = 0; k < 4; k++) {
    const lx = local[2 * k];
    const ly = local[2 * k + 1];
    out[2 * k] = x + lx * c - ly * s;
    out[2 * k + 1] = y + lx * s + ly * c;
  }
  return out;
}

/** Makes a flat vertex list counter-clockwise (y up). */
function ccw(poly) {
  let a = 0;
  const n = poly.length / 2;
  for (let k = 0; k < n; k++) {
    const j = (k + 1) % n;
    a += poly[2 * k] * poly[2 * j + 1] - poly[2 * j] * poly[2 * k + 1];
  }
  if (a >= 0) return poly;
  const out = new Float64Array(poly.length);
  for (let k = 0; k < n; k++) {
    out[2 * k] = poly[2 * (n - 1 - k)];
    out[2 * k + 1] = poly[2 * (n - 1 - k) + 1];
  }
  return out;
}

/** How deep point (px, py) lies inside convex CCW polygon `poly` (≤ 0 when outside). */
function depthInside(px, py, poly) {
  const n = poly.length / 2;
  let depth = Infinity;
  for (let k = 0; k < n; k++) {
    const ax = poly[2 * k];
    const ay = poly[2 * k + 1];
    const bx = poly[2 * ((k + 1) % n)];
    const by = poly[2 * ((k + 1) % n) + 1];
    const ex = bx - ax;
    const ey = by - ay;
    const len = Math.sqrt(ex * ex + ey * ey);
    // Inward normal of a CCW edge is (-ey, ex).
    const d = ((px - ax) * -ey + (py - ay) * ex) / len;
    if (d < depth) depth = d;
    if (depth <= 0) return depth;
  }
  return depth;
}

function bounds(poly) {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let k = 0; k < poly.length; k += 2) {
    x0 = Math.min(x0, poly[k]);
    x1 = Math.max(x1, poly[k]);
    y0 = Math.min(y0, poly[k + 1]);
    y1 = Math.max(y1, poly[k + 1]);
  }
  return [x0, y0, x1, y1];
}

/** Deepest penetration of a vertex of one polygon into another, over every pair (brute force with a bounds test). */
export function deepestPolygonPenetration(polys) {
  const ps = polys.map(ccw);
  const bs = ps.map(bounds);
  let worst = 0;
  for (let i = 0; i < ps.length; i++) {
    for (let j = i + 1; j < ps.length; j++) {
      const a = bs[i];
      const b = bs[j];
      if (a[2] < b[0] || b[2] < a[0] || a[3] < b[1] || b[3] < a[1]) continue;
      for (const [p, q] of [[ps[i], ps[j]], [ps[j], ps[i]]]) {
        for (let k = 0; k < p.length; k += 2) {
          const d = depthInside(p[k], p[k + 1], q);
          if (d > worst) worst = d;
        }
      }
    }
  }
  return worst;
}

/** Deepest overlap of circles with each other and with static boxes (r − distance to the box, or r + depth inside it). */
export function deepestCirclePenetration(xy, r, statics) {
  const n = xy.length / 2;
  let worst = 0;
  // Circles against circles through a uniform grid of cell 2r (exact: only neighbours can overlap).
  const cell = 2 * r;
  const grid = new Map();
  for (let i = 0; i < n; i++) {
    const key = `${Math.floor(xy[2 * i] / cell)},${Math.floor(xy[2 * i + 1] / cell)}`;
    (grid.get(key) ?? grid.set(key, []).get(key)).push(i);
  }
  for (let i = 0; i < n; i++) {
    const cx = Math.floor(xy[2 * i] / cell);
    const cy = Math.floor(xy[2 * i + 1] / cell);
    for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (const j of grid.get(`${cx + dx},${cy + dy}`) ?? []) {
          if (j <= i) continue;
          const ex = xy[2 * j] - xy[2 * i];
          const ey = xy[2 * j + 1] - xy[2 * i + 1];
          const d = 2 * r - Math.sqrt(ex * ex + ey * ey);
          if (d > worst) worst = d;
        }
      }
    }
  }
  for (const s of statics) {
    for (let i = 0; i < n; i++) {
      const px = xy[2 * i] - s.x;
      const py = xy[2 * i + 1] - s.y;
      const qx = Math.abs(px) - s.w / 2;
      const qy = Math.abs(py) - s.h / 2;
      const outside = Math.sqrt(Math.max(qx, 0) ** 2 + Math.max(qy, 0) ** 2);
      const d = outside > 0 ? r - outside : r - Math.max(qx, qy);
      if (d > worst) worst = d;
    }
  }
  return worst;
}

/** World polygons of the scene's dynamic boxes from a measurement. */
function dynamicPolygons(scene, m) {
  if (m.polygons) return m.polygons;
  return scene.boxes.map((b, k) => boxCorners(m.poses[3 * k], m.poses[3 * k + 1], m.poses[3 * k + 2], b.w, b.h));
}

/** Centres (x, y) of the scene's dynamic bodies from a measurement. */
function centres(m) {
  if (m.points) return m.points;
  if (m.polygons) {
    const out = new Float64Array(m.polygons.length * 2);
    m.polygons.forEach((p, k) => {
      for (let v = 0; v < p.length; v += 2) {
        out[2 * k] += p[v] / (p.length / 2);
        out[2 * k + 1] += p[v + 1] / (p.length / 2);
      }
    });
    return out;
  }
  const out = new Float64Array((m.poses.length / 3) * 2);
  for (let k = 0; k < out.length / 2; k++) {
    out[2 * k] = m.poses[3 * k];
    out[2 * k + 1] = m.poses[3 * k + 1];
  }
  return out;
}

/** Bodies whose centre left the container (outside the walls or below the floor). */
function escaped(scene, xy) {
  let count = 0;
  for (let k = 0; k < xy.length; k += 2) if (Math.abs(xy[k]) > scene.inside / 2 || xy[k + 1] < 0 || !Number.isFinite(xy[k])) count++;
  return count;
}

/** Largest |d − L| / L over the cloth's structural links, from node positions. */
function clothStrain(cloth, xy) {
  let worst = 0;
  for (const [a, b] of clothLinks(cloth)) {
    const d = Math.sqrt((xy[2 * b] - xy[2 * a]) ** 2 + (xy[2 * b + 1] - xy[2 * a + 1]) ** 2);
    worst = Math.max(worst, Math.abs(d - cloth.spacing) / cloth.spacing);
  }
  return worst;
}

/** Largest gap at a joint of the chain (and at the pin), relative to the link length, from link poses. */
function chainGapFromPoses(chain, poses) {
  const half = chain.length / 2;
  const end = (k, sign) => [poses[3 * k] + sign * half * Math.cos(poses[3 * k + 2]), poses[3 * k + 1] + sign * half * Math.sin(poses[3 * k + 2])];
  let [px, py] = [0, 0]; // the pin
  let worst = 0;
  for (let k = 0; k < chain.links; k++) {
    const [lx, ly] = end(k, -1);
    worst = Math.max(worst, Math.sqrt((lx - px) ** 2 + (ly - py) ** 2) / chain.length);
    [px, py] = end(k, 1);
  }
  return worst;
}

/** Largest |d − L| / L of the links of a particle chain (points 0..links), plus the first point's distance from the pin. */
function chainStrainFromPoints(chain, xy) {
  let worst = Math.sqrt(xy[0] ** 2 + xy[1] ** 2) / chain.length;
  for (let k = 0; k < chain.links; k++) {
    const d = Math.sqrt((xy[2 * k + 2] - xy[2 * k]) ** 2 + (xy[2 * k + 3] - xy[2 * k + 1]) ** 2);
    worst = Math.max(worst, Math.abs(d - chain.length) / chain.length);
  }
  return worst;
}

/** Quality figures of a scene from its first and last measurements. */
export function quality(scene, first, last) {
  const q = {};
  if (scene.boxes) {
    const polys = dynamicPolygons(scene, last);
    const statics = scene.statics.map((s) => boxCorners(s.x, s.y, 0, s.w, s.h));
    q.penetration = deepestPolygonPenetration([...statics, ...polys]);
    const a = centres(first);
    const b = centres(last);
    if (scene.id === 'S1') {
      const top = a.length / 2 - 1;
      q.drift = Math.sqrt((b[2 * top] - a[2 * top]) ** 2 + (b[2 * top + 1] - a[2 * top + 1]) ** 2);
      q.driftX = Math.abs(b[2 * top] - a[2 * top]); // sideways only (Box2D's skin lifts every row a little)
    } else {
      q.escaped = escaped(scene, b);
      let top = 0;
      for (const p of polys) for (let k = 1; k < p.length; k += 2) if (Math.abs(p[k - 1]) < scene.inside / 2) top = Math.max(top, p[k]);
      q.height = top;
    }
  }
  if (scene.circles) {
    const xy = centres(last);
    const r = scene.circles[0].r;
    q.penetration = deepestCirclePenetration(xy, r, scene.statics);
    q.escaped = escaped(scene, xy);
    let top = 0;
    for (let k = 1; k < xy.length; k += 2) if (Math.abs(xy[k - 1]) < scene.inside / 2) top = Math.max(top, xy[k] + r);
    q.height = top;
  }
  if (scene.chain) q.strain = last.strain ?? (last.poses ? chainGapFromPoses(scene.chain, last.poses) : chainStrainFromPoints(scene.chain, last.points));
  if (scene.cloth) q.strain = last.strain ?? clothStrain(scene.cloth, centres(last));
  if (last.strain !== undefined && last.points) {
    // Cross-check of our world.maxStrain() (every distance constraint, tethers included) against the links alone.
    q.linkStrain = scene.chain ? chainStrainFromPoints(scene.chain, last.points) : clothStrain(scene.cloth, last.points);
  }
  return q;
}
