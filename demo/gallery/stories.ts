// The gallery's stories as plain data: a tree of elements (tag, attributes, children). Catalogue scenes are turned
// into the same data, so every story is rendered, edited and shown as markup the same way.
import { catalogue, SCENE_NAMES } from '../../src/engine/scenes/catalogue.js';
import type { BodyDescription } from '../../src/engine/scene.js';

export interface Node {
  tag: string;
  attrs: Record<string, string | true>;
  children?: Node[];
}

export interface Story {
  id: string;
  group: 'Elements' | 'Links' | 'Rigid bodies' | 'Presets' | 'Markup demos' | 'Catalogue scenes';
  title: string;
  description: string;
  /** The scene (or preset) element and its children. */
  root: Node;
  /** Index path (into root.children) of the element the controls panel features next to the scene. */
  featured?: number;
  /** Runs once the scene is ready (e.g. a throw). */
  onReady?: (scene: HTMLElement) => void;
}

const n = (tag: string, attrs: Record<string, string | number | true> = {}, children?: Node[]): Node => ({
  tag,
  // Numbers to at most 6 decimals: the markup shown is what a person would write (8.6, not 8.600000000000001).
  attrs: Object.fromEntries(Object.entries(attrs).map(([k, v]) => [k, v === true ? true : typeof v === 'number' ? String(+v.toFixed(6)) : v])),
  children,
});

const floor = (w = 16, h = 9) => n('physics-box', { x: w / 2, y: h - 0.4, width: w, height: 0.8, static: true });

function scene(attrs: Record<string, string | number | true>, children: Node[]): Node {
  return n('physics-scene', { width: 16, height: 9, gravity: '0 9.81', ...attrs }, children);
}

/**
 * `count` planks of length 1 hinged end to end from `from` to `to` (closer than `count`), sagging on a circular arc,
 * the end planks hinged to the world: a loop through the world.
 */
function bridge(count: number, from: { x: number; y: number }, to: { x: number; y: number }): Node[] {
  const half = (to.x - from.x) / 2;
  // The circle's radius r whose `count` chords of length 1 span the gap: count·asin(1/2r) is the half angle φ, r·sin φ = half.
  let lo = 0.5;
  let hi = 1e6;
  for (let k = 0; k < 200; k++) {
    const r = (lo + hi) / 2;
    const phi = count * Math.asin(1 / (2 * r));
    if (phi > Math.PI / 2 || r * Math.sin(phi) < half) lo = r;
    else hi = r;
  }
  const phi = count * Math.asin(1 / (2 * lo));
  const points = Array.from({ length: count + 1 }, (_, k) => {
    const t = -phi + (2 * phi * k) / count;
    return { x: from.x + half + lo * Math.sin(t), y: from.y + lo * (Math.cos(t) - Math.cos(phi)) };
  });
  const nodes: Node[] = [];
  for (let k = 0; k < count; k++) {
    const [p, q] = [points[k], points[k + 1]];
    nodes.push(n('physics-box', { id: `plank${k}`, x: (p.x + q.x) / 2, y: (p.y + q.y) / 2, width: 1, height: 0.18, angle: (Math.atan2(q.y - p.y, q.x - p.x) * 180) / Math.PI, fill: k % 2 ? '#c9a66b' : '#b8935a', stroke: '#8a6d3b' }));
  }
  nodes.push(n('physics-joint', { type: 'revolute', a: 'plank0', x: points[0].x, y: points[0].y }));
  for (let k = 1; k < count; k++) nodes.push(n('physics-joint', { type: 'revolute', a: `plank${k}`, b: `plank${k - 1}`, x: points[k].x, y: points[k].y }));
  nodes.push(n('physics-joint', { type: 'revolute', a: `plank${count - 1}`, x: points[count].x, y: points[count].y }));
  return nodes;
}

// ---- one story per element --------------------------------------------------------------------------------------

const elementStories: Story[] = [
  {
    id: 'physics-box',
    group: 'Elements',
    title: '<physics-box>',
    description: 'A rigid rectangle: it falls, turns and comes to rest on a corner or a face as a box does. Edit its attributes: the body is rebuilt where the markup says; model="particles" makes it the thesis\' frame of four corner particles.',
    featured: 1,
    root: scene({}, [floor(), n('physics-box', { x: 8, y: 2, width: 2, height: 1, angle: 25, fill: '#3d7dd8' }), n('physics-box', { x: 6.5, y: 5, width: 1, height: 1 }), n('physics-box', { x: 9.5, y: 4, width: 1.4, height: 0.7, fill: '#f2c14e', stroke: '#a5812a' })]),
  },
  {
    id: 'physics-circle',
    group: 'Elements',
    title: '<physics-circle>',
    description: 'A rigid disc that rolls (the line from its centre shows it turning). Try restitution between 0 and 1.',
    featured: 1,
    root: scene({}, [floor(), n('physics-circle', { x: 8, y: 1, radius: 0.8, restitution: 0.6, fill: '#c0392b', stroke: '#7a241b' }), n('physics-circle', { x: 5, y: 3, radius: 0.5 }), n('physics-circle', { x: 11, y: 2, radius: 0.4, restitution: 0.9 })]),
  },
  {
    id: 'physics-polygon',
    group: 'Elements',
    title: '<physics-polygon>',
    description: 'A rigid outline from points in body coordinates; concave outlines collide as convex parts.',
    featured: 1,
    root: scene({}, [floor(), n('physics-polygon', { x: 8, y: 2, points: '-1,-0.5 1,-0.5 1,0.5 0.4,0.5 0.4,0 -0.4,0 -0.4,0.5 -1,0.5', fill: '#7d5ba6', stroke: '#4e3670' }), n('physics-polygon', { x: 5, y: 3, points: '-0.8,0.6 0,-0.8 0.8,0.6' }), n('physics-polygon', { x: 11, y: 3, angle: 15, points: '0,-0.8 0.76,-0.25 0.47,0.65 -0.47,0.65 -0.76,-0.25' })]),
  },
  {
    id: 'physics-rope',
    group: 'Elements',
    title: '<physics-rope>',
    description: 'Particles and links from (x1, y1) to (x2, y2); `rigid` makes a chain of sticks, `pin` chooses the fixed ends, `collide` lets it catch the ball.',
    featured: 1,
    root: scene({}, [floor(), n('physics-rope', { x1: 3, y1: 1, x2: 13, y2: 1, segments: 30, pin: 'both', slack: 1.2, radius: 0.08, collide: true }), n('physics-circle', { x: 8, y: -1, radius: 0.6 })]),
  },
  {
    id: 'physics-cloth',
    group: 'Elements',
    title: '<physics-cloth>',
    description: 'A grid of particles with structural, shear and bend links; `pins` holds the top row, the corners or chosen columns; `collide` lets it catch the ball.',
    featured: 1,
    root: scene({}, [floor(), n('physics-cloth', { x: 4, y: 0.5, columns: 20, rows: 14, spacing: 0.4, pins: 'corners', shear: 0.001, collide: true }), n('physics-circle', { x: 8, y: -2, radius: 0.7 })]),
  },
  {
    id: 'physics-softbody',
    group: 'Elements',
    title: '<physics-softbody>',
    description: 'A pressurised ring (or, with model="springs", a mass–spring wheel).',
    featured: 1,
    root: scene({}, [floor(), n('physics-softbody', { x: 8, y: 3, radius: 1.4, segments: 24, pressure: 1 }), n('physics-softbody', { x: 4, y: 2, radius: 1, model: 'springs' }), n('physics-box', { x: 11, y: 6.8, width: 3, height: 2, static: true, angle: 10 })]),
  },
  {
    id: 'physics-ragdoll',
    group: 'Elements',
    title: '<physics-ragdoll>',
    description: 'A stick figure with joint limits, placed by its pelvis. Drag a limb.',
    featured: 1,
    root: scene({}, [floor(), n('physics-ragdoll', { x: 8, y: 3, height: 2.2 }), n('physics-box', { x: 8, y: 7.2, width: 3, height: 1.2, static: true })]),
  },
];

const linkStories: Story[] = [
  {
    id: 'physics-joint',
    group: 'Links',
    title: '<physics-joint>',
    description: 'Two bars hinged at (x, y) (type="revolute"). Try type weld, distance or prismatic, lower-angle and upper-angle, or a motor-speed.',
    featured: 3,
    root: scene({}, [floor(), n('physics-box', { id: 'ja', x: 6, y: 3, width: 1.6, height: 0.5, fill: '#3aa0a0' }), n('physics-box', { id: 'jb', x: 8, y: 3, width: 1.6, height: 0.5, fill: '#3aa0a0' }), n('physics-joint', { type: 'revolute', a: 'ja', b: 'jb', x: 7, y: 3 })]),
  },
  {
    id: 'physics-spring',
    group: 'Links',
    title: '<physics-spring>',
    description: 'A damped Hooke spring between two bodies.',
    featured: 3,
    root: scene({}, [floor(), n('physics-box', { id: 'sa', x: 7, y: 2, width: 0.8, height: 0.8, static: true, fill: '#a2a7b0' }), n('physics-circle', { id: 'sb', x: 10, y: 2, radius: 0.5 }), n('physics-spring', { a: 'sa', b: 'sb', stiffness: 40, damping: 0.5, length: 2 })]),
  },
  {
    id: 'physics-pin',
    group: 'Links',
    title: '<physics-pin>',
    description: 'Holds a body at the world point (x, y); a rigid body still turns about it, like a lamp on a hook.',
    featured: 2,
    root: scene({}, [floor(), n('physics-box', { id: 'lamp', x: 9, y: 3, width: 1.2, height: 0.6, fill: '#f2c14e' }), n('physics-pin', { body: 'lamp', x: 8.4, y: 2.7, compliance: 0 })]),
  },
];

// ---- rigid bodies: what turning, rolling and joints make possible -------------------------------------------------

/**
 * A ring with a narrow slit (a concave outline, which must not touch itself: it collides as convex parts), as points in
 * body coordinates. The slit, 0.004 rad each side, is 0.03 wide at r 4.2: a hairline on the canvas, not a gap.
 */
function ringPoints(outer: number, inner: number, sides: number, slit = 0.004): string {
  const around = (r: number, from: number, to: number) =>
    Array.from({ length: sides + 1 }, (_, k) => from + ((to - from) * k) / sides).map((a) => `${(r * Math.cos(a)).toFixed(3)},${(r * Math.sin(a)).toFixed(3)}`);
  return [...around(outer, slit, 2 * Math.PI - slit), ...around(inner, 2 * Math.PI - slit, slit)].join(' ');
}

const ramp = (x: number, y: number, width: number, angle: number) => n('physics-box', { x, y, width, height: 0.3, angle, static: true, fill: '#a2a7b0' });

const rigidStories: Story[] = [
  {
    id: 'rolling',
    group: 'Rigid bodies',
    title: 'Rolling and sliding',
    description: 'On a 15° slope a ball rolls (friction turns it), an icy block (friction 0.02) slides away and a rough block (friction 0.9, more than tan 15°) stays where it is.',
    root: scene({}, [
      floor(),
      ramp(11.5, 2.6, 7, 15),
      ramp(4.5, 4.6, 8, 15),
      n('physics-circle', { x: 8.7, y: 1.1, radius: 0.45, fill: '#c0392b', stroke: '#7a241b' }),
      n('physics-box', { x: 1.8, y: 3.42, width: 0.8, height: 0.5, angle: 15, friction: 0.9, fill: '#f2c14e', stroke: '#a5812a' }),
      n('physics-box', { x: 3.6, y: 3.9, width: 0.8, height: 0.5, angle: 15, friction: 0.02, fill: '#8ecae6', stroke: '#3b7c99' }),
    ]),
  },
  {
    id: 'tiles',
    group: 'Rigid bodies',
    title: 'Planks and tiles',
    description: 'Crates and a puck slide down a ramp of three planks and across a floor of sixteen tiles: where static pieces meet flush, the join is not an edge to trip on.',
    root: scene({}, [
      // Sixteen tiles, 1 wide, their tops at y = 8.2.
      ...Array.from({ length: 16 }, (_, k) => n('physics-box', { x: k + 0.5, y: 8.6, width: 1, height: 0.8, static: true, fill: k % 2 ? '#b8bec7' : '#a2a7b0' })),
      // Three planks 2.6 long end to end at 20°, from (0.4, 5.7) down to the floor.
      ...Array.from({ length: 3 }, (_, k) =>
        n('physics-box', { x: 0.4 + (k + 0.5) * 2.6 * Math.cos(Math.PI / 9), y: 5.7 + (k + 0.5) * 2.6 * Math.sin(Math.PI / 9), width: 2.6, height: 0.3, angle: 20, static: true, fill: k % 2 ? '#c9a66b' : '#b8925a' }),
      ),
      ...[0, 1, 2].map((k) =>
        n('physics-box', { x: 1.1 + k * 0.9 * Math.cos(Math.PI / 9), y: 5.15 + k * 0.9 * Math.sin(Math.PI / 9), width: 0.6, height: 0.6, angle: 20, friction: 0.05, fill: ['#f2c14e', '#8ecae6', '#e76f51'][k], stroke: '#4a4f57' }),
      ),
      n('physics-circle', { x: 3.9, y: 6.1, radius: 0.3, friction: 0.05, fill: '#2a9d8f', stroke: '#1d6b62' }),
    ]),
  },
  {
    id: 'bounce',
    group: 'Rigid bodies',
    title: 'Bounce heights',
    description: 'Balls dropped from the same height with restitution 0, 0.5, 0.8 and 0.95, and a box with 0.6 landing flat: each bounce reaches e² of the height before it.',
    root: scene({}, [
      floor(),
      ...[0, 0.5, 0.8, 0.95].map((e, k) => n('physics-circle', { x: 3 + 3.25 * k, y: 1, radius: 0.45, restitution: e, friction: 0, fill: ['#596273', '#3d7dd8', '#2a9d8f', '#e76f51'][k] })),
      // Flat: tilted, it landed on a corner, tumbled 3.5 units and knocked the frictionless balls into a pile.
      n('physics-box', { x: 14.8, y: 1, width: 0.7, height: 0.7, restitution: 0.6, fill: '#f2c14e', stroke: '#a5812a' }),
    ]),
  },
  {
    id: 'newtons-cradle',
    group: 'Rigid bodies',
    title: "Newton's cradle",
    description: 'Five balls (restitution 1, no friction) each hung from the world by a distance joint, 1% of a diameter apart; the first is let go from the side, and the last swings up to 98% of its height.',
    root: scene({}, [
      n('physics-box', { x: 8, y: 1, width: 7, height: 0.3, static: true, fill: '#596273' }),
      ...[0, 1, 2, 3, 4].map((k) => {
        const pivotX = 6 + k * 1.01;
        const [x, y] = k === 0 ? [pivotX - 4 * Math.sin(Math.PI / 4), 1 + 4 * Math.cos(Math.PI / 4)] : [pivotX, 5];
        return n('physics-circle', { id: `ball${k}`, x, y, radius: 0.5, restitution: 1, friction: 0, fill: '#b8c0cc', stroke: '#596273' });
      }),
      ...[0, 1, 2, 3, 4].map((k) => {
        const pivotX = 6 + k * 1.01;
        return n('physics-joint', { a: `ball${k}`, x1: k === 0 ? pivotX - 4 * Math.sin(Math.PI / 4) : pivotX, y1: k === 0 ? 1 + 4 * Math.cos(Math.PI / 4) : 5, x2: pivotX, y2: 1 });
      }),
    ]),
  },
  {
    id: 'hinged-chain',
    group: 'Rigid bodies',
    title: 'A chain of hinged bars',
    description: 'Four bars hinged end to end, the first to the world, let go level: the chain folds, whips and keeps swinging. Its hinges are solved together (a tree of revolute joints), so the whips do not drain its energy.',
    root: scene({}, [
      floor(),
      ...[0, 1, 2, 3].map((k) => n('physics-box', { id: `bar${k}`, x: 8.7 + 1.4 * k, y: 1.5, width: 1.4, height: 0.2, fill: k % 2 ? '#3d7dd8' : '#f2c14e', stroke: '#4a4f57' })),
      n('physics-joint', { type: 'revolute', a: 'bar0', x: 8, y: 1.5 }),
      ...[1, 2, 3].map((k) => n('physics-joint', { type: 'revolute', a: `bar${k}`, b: `bar${k - 1}`, x: 8 + 1.4 * k, y: 1.5 })),
    ]),
  },
  {
    id: 'plank-bridge',
    group: 'Rigid bodies',
    title: 'A plank bridge',
    description: 'Thirteen planks hinged end to end between two posts, their ends hinged to the world: the last hinge closes a loop through the world, which the solver takes with the hinge tree in one solve, so the bridge holds its hinges while crates, one of them as heavy as the whole bridge, land on it.',
    root: scene({}, [
      floor(),
      n('physics-box', { x: 1.5, y: 6.2, width: 1, height: 3.6, static: true, fill: '#596273' }),
      n('physics-box', { x: 14.5, y: 6.2, width: 1, height: 3.6, static: true, fill: '#596273' }),
      ...bridge(13, { x: 2, y: 4.4 }, { x: 14, y: 4.4 }),
      n('physics-box', { x: 6.2, y: 0, width: 0.8, height: 0.8, fill: '#f2c14e', stroke: '#a5812a' }),
      n('physics-box', { x: 8.3, y: -2, width: 1.1, height: 1.1, density: 1.8, fill: '#2b2f36', stroke: '#000000' }),
      n('physics-circle', { x: 10.5, y: -1, radius: 0.45, fill: '#c0392b', stroke: '#7a241b' }),
    ]),
  },
  {
    id: 'welded-crane',
    group: 'Rigid bodies',
    title: 'A welded crane',
    description: 'A post welded to the ground, a small plate welded on top and a long arm welded to the plate; from the arm\'s end a bar and a load hang on hinges, let go level. The welds and hinges are solved together as one tree, so the light plate holds the long arm and its swinging load without sagging.',
    root: scene({}, [
      floor(),
      n('physics-box', { id: 'post', x: 4, y: 5.2, width: 0.4, height: 6, fill: '#f2c14e', stroke: '#4a4f57' }),
      n('physics-box', { id: 'plate', x: 4, y: 2, width: 0.4, height: 0.4, fill: '#4a4f57' }),
      n('physics-box', { id: 'arm', x: 7.6, y: 2, width: 7.2, height: 0.3, fill: '#f2c14e', stroke: '#4a4f57' }),
      n('physics-box', { id: 'hook', x: 11.95, y: 2.1, width: 1.5, height: 0.16, fill: '#3d7dd8', stroke: '#4a4f57' }),
      n('physics-box', { id: 'load', x: 13.1, y: 2.1, width: 0.8, height: 0.8, fill: '#3d7dd8', stroke: '#4a4f57' }),
      n('physics-joint', { type: 'weld', a: 'post', x: 4, y: 8.2 }),
      n('physics-joint', { type: 'weld', a: 'plate', b: 'post', x: 4, y: 2.2 }),
      n('physics-joint', { type: 'weld', a: 'arm', b: 'plate', x: 4, y: 2 }),
      n('physics-joint', { type: 'revolute', a: 'hook', b: 'arm', x: 11.2, y: 2.1 }),
      n('physics-joint', { type: 'revolute', a: 'load', b: 'hook', x: 12.7, y: 2.1 }),
    ]),
  },
  {
    id: 'car',
    group: 'Rigid bodies',
    title: 'Car on motorised wheels',
    description: 'A chassis on two wheels, each a revolute joint with a motor (motor-speed 300°/s, max-motor-torque 40): it drives over the bumps. The gallery starts it over when it reaches the far wall.',
    featured: 4,
    onReady: (s) => {
      const scene = s as HTMLElement & { reset(): Promise<void> };
      const chassis = s.querySelector('#chassis') as HTMLElement & { x: number };
      const timer = setInterval(() => {
        if (!s.isConnected) clearInterval(timer);
        else if (chassis.x > 13.5) scene.reset().catch(() => {});
      }, 500);
    },
    root: scene({}, [
      floor(),
      ramp(8, 8.05, 2.5, -10),
      ramp(12.5, 8.05, 2, 12),
      n('physics-box', { id: 'chassis', x: 2.5, y: 6.7, width: 2.4, height: 0.5, fill: '#3d7dd8', stroke: '#1d4f94' }),
      n('physics-joint', { type: 'revolute', a: 'rear', b: 'chassis', x: 1.7, y: 7.2, 'motor-speed': 300, 'max-motor-torque': 40 }),
      n('physics-joint', { type: 'revolute', a: 'front', b: 'chassis', x: 3.3, y: 7.2, 'motor-speed': 300, 'max-motor-torque': 40 }),
      n('physics-circle', { id: 'rear', x: 1.7, y: 7.2, radius: 0.45, friction: 1, fill: '#2b2f36', stroke: '#000000' }),
      n('physics-circle', { id: 'front', x: 3.3, y: 7.2, radius: 0.45, friction: 1, fill: '#2b2f36', stroke: '#000000' }),
    ]),
  },
  {
    id: 'tumbler',
    group: 'Rigid bodies',
    title: 'Tumbler',
    description: 'A kinematic drum (a ring outline, angular-velocity 40°/s: it turns at its own speed, nothing pushes it) tumbles boxes and balls.',
    featured: 0,
    root: scene({ bounds: 'none' }, [
      n('physics-polygon', { x: 8, y: 4.5, kinematic: true, 'angular-velocity': 40, points: ringPoints(4.2, 3.9, 20), fill: '#596273' }),
      ...Array.from({ length: 12 }, (_, k) =>
        k % 3 === 2
          ? n('physics-circle', { x: 6.4 + (k % 4) * 1.1, y: 3.3 + Math.floor(k / 4) * 1.1, radius: 0.35, fill: '#e76f51' })
          : n('physics-box', { x: 6.4 + (k % 4) * 1.1, y: 3.3 + Math.floor(k / 4) * 1.1, width: 0.7, height: 0.5, fill: ['#3d7dd8', '#f2c14e'][k % 2] }),
      ),
    ]),
  },
  {
    id: 'galton-board',
    group: 'Rigid bodies',
    title: 'Galton board',
    description: 'Balls fall from a funnel through rows of pegs: at each peg a ball bounces off the line from the peg to its centre at the moment they touch, and the sixty balls spread over the bins.',
    root: scene({}, [
      floor(),
      // The funnel: two slanted walls, a gap of about four balls at x = 8. A ball that lands on the pile in the funnel
      // can glance off it at 6 units/s and run up a wall; the lips at the walls' upper ends send it back.
      n('physics-box', { x: 5.84, y: 1.3, width: 3.6, height: 0.2, angle: 30, static: true, fill: '#a2a7b0' }),
      n('physics-box', { x: 10.16, y: 1.3, width: 3.6, height: 0.2, angle: -30, static: true, fill: '#a2a7b0' }),
      n('physics-box', { x: 4.33, y: 0.2, width: 0.12, height: 0.4, static: true, fill: '#a2a7b0' }),
      n('physics-box', { x: 11.67, y: 0.2, width: 0.12, height: 0.4, static: true, fill: '#a2a7b0' }),
      // Pegs in a triangle: row r has r + 3 of them, 0.8 apart.
      ...Array.from({ length: 6 }, (_, r) =>
        Array.from({ length: r + 3 }, (_, k) => n('physics-circle', { x: 8 + (k - (r + 2) / 2) * 0.8, y: 2.6 + r * 0.62, radius: 0.1, static: true, fill: '#596273' })),
      ).flat(),
      // Bins between walls 0.8 apart; the outer two rise to y = 4 to catch a ball thrown sideways by the last pegs.
      ...Array.from({ length: 11 }, (_, k) => {
        const outer = k === 0 || k === 10;
        return n('physics-box', { x: 4 + k * 0.8, y: outer ? 6.05 : 7.05, width: 0.08, height: outer ? 4.1 : 2.1, static: true, fill: '#a2a7b0' });
      }),
      // 60 balls in rows of six above the funnel (off the top: they fall in).
      ...Array.from({ length: 60 }, (_, k) =>
        n('physics-circle', { x: 6.9 + (k % 6) * 0.44 + (Math.floor(k / 6) % 2) * 0.2, y: -4 + Math.floor(k / 6) * 0.4, radius: 0.15, restitution: 0.3, friction: 0.05, fill: ['#e76f51', '#2a9d8f', '#3d7dd8'][k % 3] }),
      ),
    ]),
  },
  {
    id: 'seesaw',
    group: 'Rigid bodies',
    title: 'Seesaw and a heavy load',
    description: 'A plank hinged to the world (a revolute joint without b); a crate of density 20 lands on one end and throws the light boxes on the other.',
    root: scene({}, [
      floor(),
      n('physics-polygon', { x: 8, y: 7.85, points: '-0.6,0.35 0.6,0.35 0,-0.35', static: true, fill: '#596273' }),
      n('physics-box', { id: 'plank', x: 8, y: 7.35, width: 8, height: 0.25, angle: -14, fill: '#c9a66b', stroke: '#8a6d3b' }),
      n('physics-joint', { type: 'revolute', a: 'plank', x: 8, y: 7.35 }),
      n('physics-box', { x: 11.2, y: 5.8, width: 0.6, height: 0.6, fill: '#f2c14e' }),
      n('physics-box', { x: 11.2, y: 5.1, width: 0.6, height: 0.6, fill: '#8ecae6' }),
      n('physics-box', { x: 4.6, y: -1, width: 1.2, height: 1.2, density: 20, fill: '#2b2f36', stroke: '#000000' }),
    ]),
  },
  {
    id: 'cloth-on-bar',
    group: 'Rigid bodies',
    title: 'Cloth over a turning bar',
    description: 'A cloth of particles (collide) falls onto a kinematic bar that turns at 30°/s and is tipped off it: particles and rigid bodies collide in one solver. A box hangs from the bar by a distance joint.',
    root: scene({}, [
      floor(),
      n('physics-box', { id: 'bar', x: 8, y: 4.5, width: 6, height: 0.35, kinematic: true, 'angular-velocity': 30, fill: '#596273' }),
      n('physics-cloth', { x: 5.6, y: 0.6, columns: 16, rows: 10, spacing: 0.3, pins: 'none', collide: true, shear: 0.001, fill: '#8ecae6' }),
      n('physics-box', { id: 'weight', x: 12.5, y: 6, width: 0.7, height: 0.7, fill: '#f2c14e', stroke: '#a5812a' }),
      n('physics-joint', { a: 'bar', b: 'weight', x1: 10.8, y1: 4.5, x2: 12.5, y2: 5.65 }),
    ]),
  },
];

// ---- the markup demo that used to be demo/index.html ------------------------------------------------------------

const markupStories: Story[] = [
  {
    id: 'playground',
    group: 'Markup demos',
    title: 'Playground',
    description: 'The original markup demo: every body element, a pin holding the lamp and a spring between the teal bars.',
    root: scene({}, [
      n('physics-box', { id: 'floor', x: 8, y: 8.6, width: 16, height: 0.8, static: true }),
      n('physics-box', { x: 3, y: 7.75, width: 3, height: 0.9, angle: -12, static: true, fill: '#a2a7b0' }),
      n('physics-box', { id: 'crate', x: 5, y: 1, width: 1, height: 1, angle: 20 }),
      n('physics-box', { x: 5.4, y: -0.4, width: 1.4, height: 0.7, fill: '#f2c14e', stroke: '#a5812a' }),
      n('physics-circle', { x: 7, y: 0.5, radius: 0.5, restitution: 0.5 }),
      n('physics-circle', { x: 7.8, y: -1, radius: 0.35, fill: '#c0392b', stroke: '#7a241b' }),
      n('physics-polygon', { x: 9.5, y: 1.5, points: '-0.8,0.6 0,-0.8 0.8,0.6' }),
      n('physics-polygon', { x: 11.5, y: 1, points: '-1,-0.5 1,-0.5 1,0.5 0.4,0.5 0.4,0 -0.4,0 -0.4,0.5 -1,0.5', fill: '#7d5ba6', stroke: '#4e3670' }),
      n('physics-softbody', { x: 13.2, y: 4.5, radius: 0.9, segments: 18 }),
      n('physics-rope', { x1: 1, y1: 0.4, x2: 3.4, y2: 0.4, segments: 16, radius: 0.05 }),
      n('physics-cloth', { x: 11.6, y: 0.3, columns: 10, rows: 7, spacing: 0.3, pins: 'corners', shear: 0.001 }),
      n('physics-ragdoll', { x: 2.2, y: 3, height: 1.6 }),
      n('physics-box', { id: 'lamp', x: 15.2, y: 5.2, width: 0.5, height: 0.5, fill: '#f2c14e' }),
      n('physics-pin', { body: 'lamp', x: 15.2, y: 4.2, compliance: 0 }),
      n('physics-box', { id: 'b1', x: 9, y: 4, width: 0.8, height: 0.4, fill: '#3aa0a0' }),
      n('physics-box', { id: 'b2', x: 10.2, y: 4, width: 0.8, height: 0.4, fill: '#3aa0a0' }),
      n('physics-spring', { a: 'b1', b: 'b2', stiffness: 60, damping: 1 }),
    ]),
  },
  {
    id: 'debug-view',
    group: 'Markup demos',
    title: 'Debug view',
    description: '`debug`: axis-aligned boxes (magenta), contacts and normals (red), the broad phase\'s grid.',
    root: scene({ width: 12, height: 5, debug: true }, [
      n('physics-box', { x: 6, y: 4.6, width: 12, height: 0.8, static: true }),
      n('physics-box', { x: 4, y: 1, width: 1, height: 1, angle: 30 }),
      n('physics-box', { x: 4.3, y: 2.6, width: 1.2, height: 1.2 }),
      n('physics-circle', { x: 7, y: 1, radius: 0.6 }),
      n('physics-circle', { x: 7.4, y: 2.5, radius: 0.4 }),
      n('physics-polygon', { x: 9.5, y: 2, points: '-0.7,0.5 0,-0.7 0.7,0.5' }),
    ]),
  },
  {
    id: 'sideways',
    group: 'Markup demos',
    title: 'Sideways gravity, main thread',
    description: '`gravity="6 2"`, `worker="none"`: the same engine behind the same interface, without a worker.',
    root: scene({ width: 12, height: 4, gravity: '6 2', worker: 'none', background: '#20242b' }, [
      n('physics-box', { x: 11.7, y: 2, width: 0.6, height: 4, static: true, fill: '#596273' }),
      n('physics-circle', { x: 1, y: 1, radius: 0.4, fill: '#f2c14e' }),
      n('physics-circle', { x: 2, y: 2, radius: 0.5, fill: '#e0823d' }),
      n('physics-circle', { x: 3, y: 3, radius: 0.3, fill: '#d45d79' }),
      n('physics-box', { x: 4, y: 1.5, width: 0.8, height: 0.8, fill: '#3d7dd8' }),
    ]),
  },
];

// ---- catalogue scenes as markup -----------------------------------------------------------------------------------

/** Each catalogue scene's view in its own coordinates (left, top, width, height); markup puts (left, top) at 0, 0. */
const VIEWS: Record<string, [number, number, number, number]> = {
  pyramid: [-13, -22, 26, 23],
  stack: [-8, -13, 16, 14],
  boxes: [-17, -52, 34, 53],
  circles: [-17, -100, 34, 101],
  chain: [-105, -5, 210, 110],
  cloth: [-12, -2, 24, 20],
  thrown: [-4, -12, 20, 13],
  ragdolls: [-10, -21, 22, 22],
  soft: [-9, -12, 18, 13],
};

const round = (v: number) => String(Math.round(v * 1e4) / 1e4);

/** One engine body description as an element, moved by (dx, dy). */
export function bodyToNode(d: BodyDescription, dx: number, dy: number): Node {
  const a: Record<string, string | number | true> = {};
  const common = d as unknown as Record<string, unknown>;
  if (typeof common.id === 'string') a.id = common.id;
  for (const key of ['mass', 'density', 'friction', 'restitution', 'fill', 'stroke'] as const) if (common[key] !== undefined) a[key] = common[key] as string | number;
  if (common.static) a.static = true;
  const at = (p: { x: number; y: number }) => [round(p.x + dx), round(p.y + dy)];
  switch (d.type) {
    case 'box': {
      const o = d as unknown as { x?: number; y?: number; width?: number; height?: number; angle?: number };
      [a.x, a.y] = at({ x: o.x ?? 0, y: o.y ?? 0 });
      if (o.width !== undefined) a.width = o.width;
      if (o.height !== undefined) a.height = o.height;
      if (o.angle) a.angle = round((o.angle * 180) / Math.PI);
      return n('physics-box', a);
    }
    case 'circle': {
      const o = d as unknown as { x?: number; y?: number; radius?: number };
      [a.x, a.y] = at({ x: o.x ?? 0, y: o.y ?? 0 });
      if (o.radius !== undefined) a.radius = o.radius;
      return n('physics-circle', a);
    }
    case 'rope': {
      const o = d as unknown as { from: { x: number; y: number }; to: { x: number; y: number }; segments?: number; ropeLike?: boolean; pinStart?: boolean; pinEnd?: boolean; slack?: number };
      [a.x1, a.y1] = at(o.from);
      [a.x2, a.y2] = at(o.to);
      if (o.segments !== undefined) a.segments = o.segments;
      if (o.slack !== undefined) a.slack = o.slack;
      if (o.ropeLike === false) a.rigid = true;
      const start = o.pinStart ?? true;
      const end = o.pinEnd ?? false;
      if (!start || end) a.pin = start && end ? 'both' : end ? 'end' : 'none';
      return n('physics-rope', a);
    }
    case 'cloth': {
      const o = d as unknown as { origin: { x: number; y: number }; columns: number; rows: number; spacing?: number; pins?: unknown };
      [a.x, a.y] = at(o.origin);
      a.columns = o.columns;
      a.rows = o.rows;
      if (o.spacing !== undefined) a.spacing = o.spacing;
      if (o.pins !== undefined) a.pins = Array.isArray(o.pins) ? o.pins.join(' ') : String(o.pins);
      return n('physics-cloth', a);
    }
    case 'softbody': {
      const o = d as unknown as { center: { x: number; y: number }; radius?: number; segments?: number; pressure?: number; model?: string };
      [a.x, a.y] = at(o.center);
      for (const key of ['radius', 'segments', 'pressure', 'model'] as const) if (o[key] !== undefined) a[key] = o[key] as string | number;
      return n('physics-softbody', a);
    }
    case 'ragdoll': {
      const o = d as unknown as { x?: number; y?: number; height?: number };
      [a.x, a.y] = at({ x: o.x ?? 0, y: o.y ?? 0 });
      if (o.height !== undefined) a.height = o.height;
      return n('physics-ragdoll', a);
    }
    case 'polygon': {
      const o = d as unknown as { x?: number; y?: number; angle?: number; points: { x: number; y: number }[] };
      [a.x, a.y] = at({ x: o.x ?? 0, y: o.y ?? 0 });
      if (o.angle) a.angle = round((o.angle * 180) / Math.PI);
      a.points = o.points.map((p) => `${round(p.x)},${round(p.y)}`).join(' ');
      return n('physics-polygon', a);
    }
  }
  return n('physics-box', a);
}

const catalogueStories: Story[] = SCENE_NAMES.map((name) => {
  const entry = catalogue[name];
  const desc = entry.make();
  const [left, top, width, height] = VIEWS[name] ?? [-10, -10, 20, 11];
  const g = desc.world?.gravity ?? { x: 0, y: 10 };
  const story: Story = {
    id: `scene-${name}`,
    group: 'Catalogue scenes',
    title: entry.title,
    description: `${entry.description} (catalogue scene "${name}", rendered as markup.)`,
    root: n('physics-scene', { width, height, gravity: `${g.x} ${g.y}`, bounds: 'none' }, desc.bodies.map((b) => bodyToNode(b, -left, -top))),
  };
  type Body = HTMLElement & { setVelocity?(x: number, y: number): void };
  if (name === 'thrown') {
    story.description += ' The gallery throws the box at 300 units/s 1 s after the start, and starts over every 3 s.';
    story.onReady = (s) => {
      const scene = s as HTMLElement & { reset(): Promise<void> };
      const THROW = () => (s.querySelector('#bullet') as Body | null)?.setVelocity?.(300, 0);
      setTimeout(THROW, 1000);
      const timer = setInterval(() => (s.isConnected ? scene.reset().then(() => setTimeout(THROW, 1000), () => {}) : clearInterval(timer)), 3000);
    };
  }
  if (name === 'cloth') {
    story.description += ' It starts at rest; the gallery gives it a sideways push so it swings.';
    story.onReady = (s) => (s.querySelector('#cloth') as Body | null)?.setVelocity?.(4, 0);
  }
  return story;
});

// ---- presets (only those registered: cloth-sim and ragdoll-sim are being built) ----------------------------------

function presetStories(): Story[] {
  const out: Story[] = [];
  if (customElements.get('cloth-sim')) out.push({ id: 'cloth-sim', group: 'Presets', title: '<cloth-sim>', description: 'Preset: a ready-made cloth scene in one tag.', root: n('cloth-sim', {}) });
  if (customElements.get('ragdoll-sim')) out.push({ id: 'ragdoll-sim', group: 'Presets', title: '<ragdoll-sim>', description: 'Preset: a ready-made ragdoll scene in one tag.', root: n('ragdoll-sim', {}) });
  return out;
}

export function allStories(): Story[] {
  return [...markupStories, ...elementStories, ...linkStories, ...rigidStories, ...presetStories(), ...catalogueStories];
}
