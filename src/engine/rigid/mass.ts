// Mass properties of rigid shapes from their area and a density: mass, centre of mass (the area centroid) and the
// moment of inertia about the centre of mass. A compound body (a concave outline as convex parts, or several shapes)
// adds its parts' masses and moves each part's inertia to the common centre by the parallel-axis theorem.

/** Mass, centre of mass and moment of inertia about the centre of mass, in the coordinates the shape was given in. */
export interface MassProperties {
  area: number;
  mass: number;
  centroidX: number;
  centroidY: number;
  /** Moment of inertia about the centroid (kg·m² when mass is kg and lengths m). */
  inertia: number;
}

/**
 * A simple polygon's mass properties (counter-clockwise: positive area; a clockwise outline gives negative area and
 * mass). Each edge (a, b) spans a triangle with the first vertex o; with a, b relative to o:
 *   area += a × b / 2,   centroid += (a + b)·(a × b) / 6,   I_o += (a × b)(a·a + a·b + b·b) / 12.
 * Working relative to the first vertex instead of the coordinate origin keeps the digits of a small polygon far
 * from the origin (products of large coordinates would cancel).
 */
export function polygonMass(xs: ArrayLike<number>, ys: ArrayLike<number>, density: number): MassProperties {
  const n = xs.length;
  const ox = xs[0];
  const oy = ys[0];
  let area2 = 0;
  let cx = 0;
  let cy = 0;
  let inertia12 = 0;
  for (let k = 1; k + 1 < n; k++) {
    const ax = xs[k] - ox;
    const ay = ys[k] - oy;
    const bx = xs[k + 1] - ox;
    const by = ys[k + 1] - oy;
    const cross = ax * by - ay * bx;
    area2 += cross;
    cx += (ax + bx) * cross;
    cy += (ay + by) * cross;
    inertia12 += cross * (ax * ax + ax * bx + bx * bx + ay * ay + ay * by + by * by);
  }
  const area = area2 / 2;
  // Centroid relative to o: Σ (a + b)(a × b) / 6 / area = Σ (a + b)(a × b) / (3 · area2).
  const gx = cx / (3 * area2);
  const gy = cy / (3 * area2);
  const mass = density * area;
  // Inertia about o, then about the centroid (parallel axis).
  const inertia = (density * inertia12) / 12 - mass * (gx * gx + gy * gy);
  return { area, mass, centroidX: ox + gx, centroidY: oy + gy, inertia };
}

/** A disc of radius r centred at (x, y): I = m·r²/2. */
export function circleMass(x: number, y: number, r: number, density: number): MassProperties {
  const area = Math.PI * r * r;
  const mass = density * area;
  return { area, mass, centroidX: x, centroidY: y, inertia: (mass * r * r) / 2 };
}

/** A capsule (a segment from a to b with radius r): a rectangle and two half discs, i.e. one disc split in two. */
export function capsuleMass(ax: number, ay: number, bx: number, by: number, r: number, density: number): MassProperties {
  const length = Math.sqrt((bx - ax) ** 2 + (by - ay) ** 2);
  const rect = 2 * r * length;
  const disc = Math.PI * r * r;
  const area = rect + disc;
  const mass = density * area;
  const rectMass = density * rect;
  const discMass = density * disc;
  // Rectangle length × 2r about its centre, plus each half disc's mass at its own centroid (4r/3π past the end)
  // moved to the capsule's centre: I_half = m_h r²/2 − m_h d² + m_h (L/2 + d)² with d = 4r/3π.
  const d = (4 * r) / (3 * Math.PI);
  const half = discMass / 2;
  const inertia = (rectMass * (length * length + 4 * r * r)) / 12 + 2 * (half * r * r * 0.5 - half * d * d + half * (length / 2 + d) ** 2);
  return { area, mass, centroidX: (ax + bx) / 2, centroidY: (ay + by) / 2, inertia };
}

/** The mass properties of parts joined into one body. */
export function combineMass(parts: readonly MassProperties[]): MassProperties {
  let area = 0;
  let mass = 0;
  let mx = 0;
  let my = 0;
  for (const p of parts) {
    area += p.area;
    mass += p.mass;
    mx += p.mass * p.centroidX;
    my += p.mass * p.centroidY;
  }
  const cx = mx / mass;
  const cy = my / mass;
  let inertia = 0;
  for (const p of parts) inertia += p.inertia + p.mass * ((p.centroidX - cx) ** 2 + (p.centroidY - cy) ** 2);
  return { area, mass, centroidX: cx, centroidY: cy, inertia };
}
