// The catalogue of named scenes shared by tests, benchmarks and the demo. Each entry makes a plain-data scene
// description; units are metres-like (boxes of 1), y grows downward, gravity 10.
import type { BodyDescription, SceneDescription } from '../scene.js';

export interface CatalogueEntry {
  title: string;
  description: string;
  make(): SceneDescription;
}

const GRAVITY = { x: 0, y: 10 };

/** A static ground whose top surface is at y = 0. */
function ground(width = 80): BodyDescription {
  return { type: 'box', id: 'ground', x: 0, y: 0.5, width, height: 1, static: true, fill: '#8a8f98' };
}

/** A U container, `inside` wide, walls `height` high, floor top at y = 0. */
function container(inside: number, height: number): BodyDescription[] {
  const wall = 1;
  return [
    { type: 'box', id: 'floor', x: 0, y: 0.5, width: inside + 2 * wall, height: 1, static: true, fill: '#8a8f98' },
    { type: 'box', id: 'left-wall', x: -inside / 2 - wall / 2, y: -height / 2, width: wall, height, static: true, fill: '#8a8f98' },
    { type: 'box', id: 'right-wall', x: inside / 2 + wall / 2, y: -height / 2, width: wall, height, static: true, fill: '#8a8f98' },
  ];
}

/** S2/S3's drop grid: 25 columns 1.1 apart, rows 1.2 apart, alternate rows shifted ±0.3. */
function dropGrid(count: number, make: (x: number, y: number) => BodyDescription): BodyDescription[] {
  const out: BodyDescription[] = [];
  for (let k = 0; k < count; k++) {
    const row = Math.floor(k / 25);
    const col = k % 25;
    const shift = row % 2 === 0 ? 0.3 : -0.3;
    out.push(make((col - 12) * 1.1 + shift, -2 - row * 1.2));
  }
  return out;
}

export const catalogue = {
  pyramid: {
    title: 'Pyramid (S1)',
    description: 'Box2D\'s pyramid: base 20, 210 unit boxes exactly touching, rows shifted by half a box.',
    make: () => {
      const bodies: BodyDescription[] = [ground()];
      for (let row = 0; row < 20; row++) {
        for (let k = 0; k < 20 - row; k++) bodies.push({ type: 'box', x: k - (20 - row - 1) / 2, y: -0.5 - row, width: 1, height: 1 });
      }
      return { world: { gravity: GRAVITY }, bodies };
    },
  },
  stack: {
    title: 'Stack of 10',
    description: 'Ten unit boxes in a column on a static ground.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [ground(), ...Array.from({ length: 10 }, (_, k): BodyDescription => ({ type: 'box', x: 0, y: -0.5 - k, width: 1, height: 1 }))],
    }),
  },
  boxes: {
    title: '1000 boxes (S2)',
    description: '1000 unit boxes dropped from a 25-column grid into a container 30 wide, walls 100 high.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [...container(30, 100), ...dropGrid(1000, (x, y) => ({ type: 'box', x, y, width: 1, height: 1 }))],
    }),
  },
  circles: {
    title: '2000 circles (S3)',
    description: '2000 circles of radius 0.5 dropped from the same grid into the same container.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [...container(30, 100), ...dropGrid(2000, (x, y) => ({ type: 'circle', x, y, radius: 0.5 }))],
    }),
  },
  chain: {
    title: '100-link chain (S4)',
    description: 'A chain of 100 links of length 1, first link pinned, released horizontally.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [{ type: 'rope', id: 'chain', from: { x: 0, y: 0 }, to: { x: 100, y: 0 }, segments: 100, mass: 100 * 0.25, ropeLike: false }],
    }),
  },
  cloth: {
    title: '30×30 cloth (S5)',
    description: 'A 30×30 cloth, spacing 0.5, structural links only, top row pinned.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [{ type: 'cloth', id: 'cloth', origin: { x: -7.25, y: 0 }, columns: 30, rows: 30, spacing: 0.5 }],
    }),
  },
  thrown: {
    title: 'Box thrown at a thin wall',
    description: 'A unit box at 300 units/s against a static wall 0.1 thick.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [
        ground(200),
        { type: 'box', id: 'wall', x: 10, y: -5, width: 0.1, height: 10, static: true, fill: '#8a8f98' },
        { type: 'box', id: 'bullet', x: 0, y: -5, width: 1, height: 1 },
      ],
    }),
  },
  ragdolls: {
    title: 'Ragdolls',
    description: 'Five ragdolls falling onto a row of static steps.',
    make: () => {
      const bodies: BodyDescription[] = [ground(60)];
      for (let k = 0; k < 6; k++) bodies.push({ type: 'box', x: -6 + k * 2.5, y: -0.5 - k * 0.6, width: 2.5, height: 1 + k * 1.2, static: true, fill: '#8a8f98' });
      for (let k = 0; k < 5; k++) bodies.push({ type: 'ragdoll', x: -6 + k * 2.4, y: -9 - k * 1.5 });
      return { world: { gravity: GRAVITY }, bodies };
    },
  },
  soft: {
    title: 'Soft bodies',
    description: 'Pressure rings and a mass–spring ring dropped on boxes, in a container.',
    make: () => ({
      world: { gravity: GRAVITY },
      bodies: [
        // Walls: the mass–spring ring, struck by the falling 16-link ring, rolled on for 40 s and 16 units.
        ...container(16, 3),
        { type: 'box', x: -2, y: -1, width: 3, height: 2, static: true, angle: 0.2, fill: '#8a8f98' },
        { type: 'softbody', center: { x: -2, y: -6 }, radius: 1.2, segments: 20 },
        { type: 'softbody', center: { x: 1.5, y: -9 }, radius: 1, segments: 16, pressure: 1.2 },
        { type: 'softbody', center: { x: 3, y: -4 }, radius: 1, model: 'springs' },
      ],
    }),
  },
} satisfies Record<string, CatalogueEntry>;

export type SceneName = keyof typeof catalogue;
export const SCENE_NAMES = Object.keys(catalogue) as SceneName[];
