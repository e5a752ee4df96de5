// Grab policy: how a press at a point holds what is under it. Rigid bodies, and the particle frames their descriptor
// grips softly, are held softly at the point (the engine scales the pull by the body's mass); other particles firmly
// (the engine caps the drag speed, so nothing is flung). A press inside a soft ring takes the ring's nearest particle.
import type { Handle, World } from '../../engine/index.js';
import type { Bindings } from './bindings.js';

/** Pull of a grab on loose particles, per unit mass (1/s²): firm enough to beat the rigid links of a cloth. */
const FIRM_STIFFNESS = 1e6;

/** The grab's handle, or null when nothing is there (or the point is not a number). */
export function grabAt(b: Bindings, x: number, y: number, stiffness?: number): Handle | null {
  try {
    const w = b.world;
    const soft = w.bodiesAtPoint(x, y).some((h) => {
      const r = b.bodies.get(b.keyOf(h));
      return r?.rigid || r?.descriptor?.grip === 'soft';
    });
    if (soft) return w.grab(x, y, stiffness === undefined ? {} : { stiffness });
    const firm = { stiffness: stiffness ?? FIRM_STIFFNESS };
    const held = w.grab(x, y, firm);
    if (held !== null) return held;
    const { x: px, y: py } = w.particles;
    for (const r of b.built()) {
      const loop = r.descriptor!.outline?.(r.desc, r.indices);
      if (!loop || !insideLoop(loop, px, py, x, y)) continue;
      const i = b.nearest(loop, x, y);
      const g = w.grab(px[i], py[i], firm);
      if (g !== null) {
        w.moveGrab(g, x, y);
        return g;
      }
    }
    return null;
  } catch {
    return null;
  }
}

/** A grab still held (a stale handle, e.g. from before a reset, may name nothing or another constraint). */
export function isGrab(w: World, grab: Handle): boolean {
  return w.hasConstraint(grab) && w.constraintKindOf(grab) === 'grab';
}

/** Even–odd test of (x, y) against the closed loop of particles. */
function insideLoop(loop: Int32Array, px: Float64Array, py: Float64Array, x: number, y: number): boolean {
  let inside = false;
  for (let k = 0, j = loop.length - 1; k < loop.length; j = k++) {
    const a = loop[k];
    const c = loop[j];
    if (py[a] > y !== py[c] > y && x < ((px[c] - px[a]) * (y - py[a])) / (py[c] - py[a]) + px[a]) inside = !inside;
  }
  return inside;
}
