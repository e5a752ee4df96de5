// Worlds the benchmarks step, made from an engine module (bundled by each script, so A/B scripts can pass either of
// two builds): the catalogue's scenes with sleeping off (as bench/peers.mjs runs them), and the large scenes issue 16's
// targets name, which are too heavy for the catalogue's gallery stories and per-scene tests.

/** A catalogue scene, or one of LARGE below, as a World with sleeping off and the given kernel. */
export function benchWorld(engine, name, kernel) {
  if (name in LARGE) return LARGE[name](engine, kernel);
  const d = engine.catalogue[name].make();
  return engine.buildScene({ ...d, world: { ...d.world, sleeping: false, kernel } }).world;
}

export const LARGE = {
  /** 10,000 circles of radius 0.5 dropped from 80 columns into S3's container made 100 wide. */
  circles10k(engine, kernel) {
    const base = engine.catalogue.circles.make();
    const walls = base.bodies.filter((b) => b.static).map((b) => (b.id === 'floor' ? { ...b, width: 102 } : { ...b, x: Math.sign(b.x) * 50.5 }));
    const circles = Array.from({ length: 10000 }, (_, k) => {
      const row = Math.floor(k / 80);
      return { type: 'circle', x: ((k % 80) - 40) * 1.2 + (row % 2 ? 0.3 : -0.3), y: -2 - row * 1.2, radius: 0.5 };
    });
    return engine.buildScene({ world: { ...base.world, sleeping: false, kernel }, bodies: [...walls, ...circles] }).world;
  },
  /** A 200×200 cloth pinned along its top row (createCloth's defaults: tethers; `shear: 0` = rigid diagonals). */
  cloth200(engine, kernel) {
    const world = new engine.World({ gravity: { x: 0, y: 10 }, sleeping: false, kernel });
    engine.createCloth(world, { origin: { x: 0, y: 0 }, columns: 200, rows: 200, spacing: 0.5, shear: 0 });
    return world;
  },
};
