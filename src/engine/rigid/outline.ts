// From an outline or a radius to what a rigid body needs: its shape in the body's frame (centre of mass at the
// origin) and its mass properties. Setup-time code (it allocates).
import { checkSimple, decompose } from '../collision/decompose.js';
import { coordinate, positive } from '../validate.js';
import { circleMass, combineMass, polygonMass, type MassProperties } from './mass.js';
import { cleanOutline, RigidShapeKind, type RigidShapeSource } from './shapes.js';

/** A shape at density 1 (mass = area); withDensity() scales it. */
export interface RigidShape {
  source: RigidShapeSource;
}

/** The same shape with a density (mass per unit area). */
export function withDensity(shape: RigidShape, density: number): RigidShapeSource {
  return { ...shape.source, mass: shape.source.mass * density, inertia: shape.source.inertia * density };
}

function sourceOf(kind: RigidShapeKind, parts: Float64Array[], radius: number, unit: MassProperties): RigidShapeSource {
  let extent = radius;
  for (const part of parts) for (let k = 0; k < part.length; k += 2) extent = Math.max(extent, Math.sqrt(part[k] * part[k] + part[k + 1] * part[k + 1]));
  return { kind, parts, radius, centroidX: unit.centroidX, centroidY: unit.centroidY, mass: unit.mass, inertia: unit.inertia, extent };
}

/**
 * A polygon body's shape from its outline (body coordinates, either orientation, any simple polygon): repeated and
 * straight (180°) vertices merged, a concave outline split into convex parts, everything moved so the area centroid
 * is the origin.
 */
export function polygonShape(points: readonly { x: number; y: number }[]): RigidShape {
  return compoundShape([points], 'points');
}

/**
 * A body of several outlines (each any simple polygon, given in the body's coordinates; they may touch or overlap,
 * overlaps count twice in the mass): a drum's wall, a table of legs and top. Convex parts of all of them, around the
 * centre of mass of all of them.
 */
export function compoundShape(outlines: readonly (readonly { x: number; y: number }[])[], name = 'outlines'): RigidShape {
  if (!Array.isArray(outlines) || outlines.length === 0) throw new RangeError(`${name} must be a non-empty list of outlines, got ${String(outlines)}`);
  const pieces = outlines.map((points, k) => outlinePieces(points, outlines.length === 1 && name === 'points' ? 'points' : `${name}[${k}]`));
  const unit = combineMass(pieces.map((p) => p.unit));
  const flat = pieces.flatMap((p) =>
    p.parts.map((part) => {
      const out = new Float64Array(part.length * 2);
      part.forEach((q, k) => {
        out[2 * k] = q.x - unit.centroidX;
        out[2 * k + 1] = q.y - unit.centroidY;
      });
      return out;
    }),
  );
  return { source: sourceOf(RigidShapeKind.Polygon, flat, 0, unit) };
}

/** One outline's convex parts (cleaned) and its mass properties at density 1. */
function outlinePieces(points: readonly { x: number; y: number }[], name: string): { parts: { x: number; y: number }[][]; unit: MassProperties } {
  if (!Array.isArray(points) || points.length < 3) {
    throw new RangeError(`${name} must be a list of at least 3 points, got ${Array.isArray(points) ? points.length : String(points)}`);
  }
  const xs = points.map((p, k) => coordinate(`${name}[${k}].x`, p?.x));
  const ys = points.map((p, k) => coordinate(`${name}[${k}].y`, p?.y));
  const clean = cleanOutline(xs, ys);
  const unit = polygonMass(clean.xs, clean.ys, 1);
  if (!(unit.area > 0) || !Number.isFinite(unit.area) || !Number.isFinite(unit.inertia)) {
    throw new RangeError(`${name} must enclose a finite, non-zero area, got area ${unit.area}`);
  }
  checkSimple(clean.xs, clean.ys, name);
  const outline = clean.xs.map((x, k) => ({ x, y: clean.ys[k] }));
  const parts = isConvex(clean.xs, clean.ys) ? [outline] : decompose(outline).map((part) => part.map((k) => outline[k]));
  return {
    parts: parts.map((part) => {
      const c = cleanOutline(part.map((p) => p.x), part.map((p) => p.y));
      return c.xs.map((x, k) => ({ x, y: c.ys[k] }));
    }),
    unit,
  };
}

/** A disc's shape: radius r about the centre of mass. */
export function circleShape(radius: number): RigidShape {
  const r = coordinate('radius', positive('radius', radius));
  return { source: sourceOf(RigidShapeKind.Circle, [], r, circleMass(0, 0, r, 1)) };
}

/** Whether a counter-clockwise outline turns left (or goes straight) at every vertex. */
function isConvex(xs: number[], ys: number[]): boolean {
  const n = xs.length;
  for (let k = 0; k < n; k++) {
    const a = k;
    const b = (k + 1) % n;
    const c = (k + 2) % n;
    if ((xs[b] - xs[a]) * (ys[c] - ys[b]) - (ys[b] - ys[a]) * (xs[c] - xs[b]) < 0) return false;
  }
  return true;
}

