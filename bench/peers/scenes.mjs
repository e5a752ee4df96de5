// S1–S5 of the cross-engine benchmark (issue 4) in engine-neutral numbers: metres, y UP, gravity 10 downward.
// The numbers are those of our scene catalogue (src/engine/scenes/catalogue.ts, y down) mirrored in y; the
// adapter for our engine checks that the catalogue still builds exactly these bodies.
//
// A scene lists static boxes and exactly one kind of dynamic body, in this order in every adapter:
//   boxes   [{ x, y, w, h }]          S1, S2 (centre, size)
//   circles [{ x, y, r }]             S3
//   chain   { links, length, thickness }   S4: link k spans x in [k·length, (k+1)·length] at y = 0; link 0 is
//           pinned to the world at (0, 0); links are jointed end to end and never collide.
//   cloth   { columns, rows, spacing, left, top, nodeRadius }   S5: node (c, r) at (left + c·spacing,
//           top − r·spacing), row-major; structural links to the right and below; row 0 pinned; no collisions.

export const GRAVITY = 10;
export const DT = 1 / 60;
export const FRICTION = 0.6;
export const DENSITY = 1;

const box = (x, y, w, h) => ({ x, y, w, h });

/** A U container `inside` wide with walls `height` high; floor top at y = 0 (catalogue's container()). */
function container(inside, height) {
  const wall = 1;
  return [box(0, -0.5, inside + 2 * wall, 1), box(-inside / 2 - wall / 2, height / 2, wall, height), box(inside / 2 + wall / 2, height / 2, wall, height)];
}

/** The drop grid of S2/S3: 25 columns 1.1 apart, rows 1.2 apart from y = 2 up, alternate rows shifted ±0.3. */
function dropGrid(count) {
  const out = [];
  for (let k = 0; k < count; k++) {
    const row = Math.floor(k / 25);
    const col = k % 25;
    out.push({ x: (col - 12) * 1.1 + (row % 2 === 0 ? 0.3 : -0.3), y: 2 + row * 1.2 });
  }
  return out;
}

function pyramid(base = 20) {
  const boxes = [];
  for (let row = 0; row < base; row++) {
    for (let k = 0; k < base - row; k++) boxes.push(box(k - (base - row - 1) / 2, 0.5 + row, 1, 1));
  }
  return boxes;
}

export const SCENES = {
  S1: {
    id: 'S1',
    catalogue: 'pyramid',
    title: 'pyramid, base 20 (210 boxes)',
    statics: [box(0, -0.5, 80, 1)],
    boxes: pyramid(20),
  },
  S2: {
    id: 'S2',
    catalogue: 'boxes',
    title: '1000 boxes into a container',
    statics: container(30, 100),
    inside: 30,
    boxes: dropGrid(1000).map((p) => box(p.x, p.y, 1, 1)),
  },
  S3: {
    id: 'S3',
    catalogue: 'circles',
    title: '2000 circles r 0.5 into a container',
    statics: container(30, 100),
    inside: 30,
    circles: dropGrid(2000).map((p) => ({ x: p.x, y: p.y, r: 0.5 })),
  },
  S4: {
    id: 'S4',
    catalogue: 'chain',
    title: 'chain of 100 links 1.0 × 0.25, first pinned',
    statics: [],
    chain: { links: 100, length: 1, thickness: 0.25 },
  },
  S5: {
    id: 'S5',
    catalogue: 'cloth',
    title: 'cloth 30×30, spacing 0.5, top row pinned',
    statics: [],
    // Peers model nodes as small circles (radius 0.1, density 1) with collisions off; ours as particles.
    cloth: { columns: 30, rows: 30, spacing: 0.5, left: -7.25, top: 0, nodeRadius: 0.1 },
  },
};

export const SCENE_IDS = Object.keys(SCENES);

/** Centre of chain link k. */
export const linkCentre = (chain, k) => ({ x: (k + 0.5) * chain.length, y: 0 });

/** Position of cloth node (c, r). */
export const clothNode = (cloth, c, r) => ({ x: cloth.left + c * cloth.spacing, y: cloth.top - r * cloth.spacing });

/** Structural links of the cloth as pairs of row-major node indices. */
export function clothLinks(cloth) {
  const out = [];
  const { columns, rows } = cloth;
  for (let r = 0; r < rows; r++) {
    for (let c = 0; c < columns; c++) {
      if (c + 1 < columns) out.push([r * columns + c, r * columns + c + 1]);
      if (r + 1 < rows) out.push([r * columns + c, (r + 1) * columns + c]);
    }
  }
  return out;
}

/** Calls make(x, y, pinned) for every cloth node, row by row (index r·columns + c); the top row is pinned. */
export function eachClothNode(cloth, make) {
  for (let r = 0; r < cloth.rows; r++) {
    for (let c = 0; c < cloth.columns; c++) {
      const p = clothNode(cloth, c, r);
      make(p.x, p.y, r === 0);
    }
  }
}

/** Measurement of the bodies' poses, [x, y, angle] per body (y up, counter-clockwise), read by pose(body, out). */
export function measurePoses(bodies, pose) {
  const poses = new Float64Array(bodies.length * 3);
  const out = [0, 0, 0];
  bodies.forEach((body, k) => {
    pose(body, out);
    poses.set(out, 3 * k);
  });
  return { poses };
}
