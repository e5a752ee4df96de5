import type { World } from '../world.js';
import { coordinate, integer, MAX_WORLD_COORDINATE, nonNegative, positive } from '../validate.js';
import { addTethers, BODY_OPTIONS, builderOptions, colliderOf, complianceOf, massEach, point, transactional, type BodyOptions, type Built } from './common.js';

/** Which particles of the top row are pinned: every one, the two corners, none, or a list of column indices. */
export type ClothPins = 'top' | 'corners' | 'none' | number[];

export interface ClothOptions extends BodyOptions {
  /** Top-left corner. */
  origin: { x: number; y: number };
  columns: number;
  rows: number;
  spacing: number;
  /** Total mass. Default 0.01 per particle. */
  mass?: number;
  /** Compliance of the structural (horizontal, vertical) links. Default 0 (rigid). */
  structural?: number;
  /** Compliance of the shear (diagonal) links, or null for none. Default null. */
  shear?: number | null;
  /** Compliance of the bend (two-apart) links, or null for none. Default null. */
  bend?: number | null;
  pins?: ClothPins;
  radius?: number;
  /** Long-range tethers from each particle to the nearest pin (see addTethers). Default true, except when tearing. */
  tethers?: boolean;
  /**
   * Tearing: a link stretched past its length by this fraction breaks (0.3 = 30% longer). Default: never. Tethers
   * are then off by default, since they would keep a torn-off piece hanging from its pin.
   */
  tear?: number;
}

const CLOTH_OPTIONS = {
  ...BODY_OPTIONS, origin: true, columns: true, rows: true, spacing: true, mass: true, structural: true, shear: true, bend: true, pins: true, radius: true, tethers: true, tear: true,
} satisfies Record<keyof ClothOptions, true>;

/** A rectangular cloth of columns × rows particles, row-major from the top-left corner. */
export function createCloth(world: World, o: ClothOptions): Built {
  builderOptions(world, 'cloth', o, CLOTH_OPTIONS);
  const origin = point('origin', o.origin);
  const columns = integer('columns', o.columns, 2, 4096);
  const rows = integer('rows', o.rows, 2, 4096);
  const spacing = coordinate('spacing', positive('spacing', o.spacing));
  const each = o.static ? Infinity : massEach('mass', o.mass, columns * rows, (columns * rows) / 100, 'columns · rows / 100');
  const structural = complianceOf('structural', o.structural);
  const shear = o.shear == null ? null : complianceOf('shear', o.shear);
  const bend = o.bend == null ? null : complianceOf('bend', o.bend);
  // A static cloth is immovable already: no pins (nor their tethers).
  const pins = pinnedColumns(o.pins ?? 'top', columns);
  const pinned = o.static ? [] : pins;
  const radius = coordinate('radius', nonNegative('radius', o.radius ?? 0));
  const breakStrain = o.tear === undefined ? undefined : positive('tear', o.tear);
  const far = { x: origin.x + (columns - 1) * spacing, y: origin.y + (rows - 1) * spacing };
  if (Math.max(Math.abs(far.x), Math.abs(far.y)) > MAX_WORLD_COORDINATE) {
    throw new RangeError(`spacing must keep the cloth within ±1e9 (its far corner would be at (${far.x}, ${far.y})), got ${spacing}`);
  }
  return transactional(world, (particles, constraints) => {
    for (let r = 0; r < rows; r++) {
      for (let c = 0; c < columns; c++) {
        particles.push(world.addParticle({ x: origin.x + c * spacing, y: origin.y + r * spacing, mass: each, radius }));
      }
    }
    const at = (c: number, r: number) => particles[r * columns + c];
    const link = (a: number, b: number, compliance: number) => constraints.push(world.addDistance(a, b, { compliance, breakStrain }));
    for (let r = 0; r < rows; r++) {
      for (let c = 0; c < columns; c++) {
        if (c + 1 < columns) link(at(c, r), at(c + 1, r), structural);
        if (r + 1 < rows) link(at(c, r), at(c, r + 1), structural);
      }
    }
    if (shear !== null) {
      for (let r = 0; r + 1 < rows; r++) {
        for (let c = 0; c + 1 < columns; c++) {
          link(at(c, r), at(c + 1, r + 1), shear);
          link(at(c + 1, r), at(c, r + 1), shear);
        }
      }
    }
    if (bend !== null) {
      for (let r = 0; r < rows; r++) {
        for (let c = 0; c < columns; c++) {
          if (c + 2 < columns) link(at(c, r), at(c + 2, r), bend);
          if (r + 2 < rows) link(at(c, r), at(c, r + 2), bend);
        }
      }
    }
    for (const c of pinned) constraints.push(world.addPin(at(c, 0)));
    if ((o.tethers ?? breakStrain === undefined) && structural === 0) {
      // The path along the structural links (across, then down), not the straight line: a particle can be that far
      // from its pin and no farther. In the plane the straight line locked a cloth hung from two corners (or from
      // pins apart along the top): a column swinging sideways moves away from the nearest pin off its top, and every
      // column's nearest pin held it, so wind and sideways gravity moved the cloth 0.05 in 4 s.
      const rest = (a: number, b: number) => spacing * (Math.abs((a % columns) - (b % columns)) + Math.abs(Math.floor(a / columns) - Math.floor(b / columns)));
      addTethers(world, particles, pinned, rest, constraints);
    }
    // Collides (when asked) as circles of the particles' radius; off by default.
    return world.addBody('cloth', particles, constraints, colliderOf(o, 'particles', false));
  });
}

function pinnedColumns(pins: ClothPins, columns: number): number[] {
  if (pins === 'top') return Array.from({ length: columns }, (_, c) => c);
  if (pins === 'corners') return [0, columns - 1];
  if (pins === 'none') return [];
  if (Array.isArray(pins)) return [...new Set(pins.map((c, k) => integer(`pins[${k}]`, c, 0, columns - 1)))];
  throw new RangeError(`pins must be "top", "corners", "none" or a list of column indices, got ${JSON.stringify(pins)}`);
}
