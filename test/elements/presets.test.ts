// <cloth-sim> and <ragdoll-sim>: one tag each, bodies generated in their shadow root by <physics-scene>'s machinery.
import { expect } from '@open-wc/testing';
import { ClothSimElement, RagdollSimElement, type PhysicsClothElement, type PhysicsErrorDetail, type PhysicsRagdollElement, type PhysicsSceneElement } from '../../src/index.js';
import { colourDistance, drawn, pointerAt, rgb, simulated, stepUntil, steppedDrag, unmount, waitFor } from './helpers.js';

/** Mounts `<tag attrs>` in a 480 × 300 container; waits for `ready` unless told not to. */
async function mountSim<T extends PhysicsSceneElement>(tag: string, attrs = '', ready = true): Promise<T> {
  const box = document.createElement('div');
  box.style.cssText = 'width: 480px; height: 300px; position: relative;';
  // Test markup only: fixed strings written in the tests.
  box.innerHTML = `<${tag} ${attrs} style="width: 100%; height: 100%"></${tag}>`;
  document.body.append(box);
  const sim = box.firstElementChild as T;
  if (ready) await sim.ready;
  return sim;
}

/** Pixels of the canvas within `tolerance` of a colour. */
function countColour(scene: PhysicsSceneElement, hex: string, tolerance = 12): number {
  const canvas = scene.canvas!;
  const data = canvas.getContext('2d')!.getImageData(0, 0, canvas.width, canvas.height).data;
  const c = rgb(hex);
  let n = 0;
  for (let i = 0; i < data.length; i += 4) if (colourDistance([data[i], data[i + 1], data[i + 2]], c) <= tolerance) n++;
  return n;
}

const clothOf = (sim: ClothSimElement) => sim.shadowRoot!.querySelector<PhysicsClothElement>('physics-cloth')!;
const dollsOf = (sim: RagdollSimElement) => Array.from(sim.shadowRoot!.querySelectorAll<PhysicsRagdollElement>('physics-ragdoll'));

describe('<cloth-sim>', () => {
  let sim: ClothSimElement | null = null;
  afterEach(() => unmount(sim));

  it('is one tag: a 24 × 16 cloth in its shadow root, nothing in the page, drawn in its fill colour', async () => {
    sim = await mountSim<ClothSimElement>('cloth-sim');
    expect(document.createElement('cloth-sim')).to.be.instanceOf(ClothSimElement);
    expect(sim.children.length).to.equal(0);
    const d = await sim.diagnostics();
    expect(d.particleCount).to.equal(24 * 16);
    expect(d.bodyCount).to.equal(1);
    await waitFor(() => sim!.renderedFrames > 2 && countColour(sim!, '#9cc3ec') > 5000, 'the cloth drawn in #9cc3ec');
    // Five pins spread along the top; the cloth hangs centred in a 16 × 10 view.
    expect(clothOf(sim).getAttribute('pins')).to.equal('0 6 12 17 23');
    expect(clothOf(sim).x).to.be.closeTo(8, 0.3);
  });

  it('columns, rows, pins and colours reach the cloth; changing one rebuilds it', async () => {
    sim = await mountSim<ClothSimElement>('cloth-sim', 'columns="6" rows="5" pins="corners" fill="#ff0000" stroke="none"');
    expect((await sim.diagnostics()).particleCount).to.equal(30);
    await waitFor(() => countColour(sim!, '#ff0000') > 2000, 'a red cloth');
    sim.columns = 10;
    await waitFor(async () => (await sim!.diagnostics()).particleCount === 50, '10 × 5 particles');
    expect(clothOf(sim).getAttribute('columns')).to.equal('10');
  });

  it('a drag pulls the cloth sideways', async () => {
    sim = await mountSim<ClothSimElement>('cloth-sim', 'columns="8" rows="6" spacing="1" pins="top" paused');
    const cloth = clothOf(sim);
    // Top-left corner at ((16 − 7) / 2, 0.8) = (4.5, 0.8): the bottom-middle particle hangs at (7.5, 5.8).
    await simulated(sim, cloth);
    const x0 = cloth.x;
    expect(x0).to.be.closeTo(8, 1e-6);
    await steppedDrag(sim, [7.5, 5.8], [11.5, 5.8], 12, 2);
    await stepUntil(sim, () => cloth.x > x0 + 0.5, 'the cloth to follow the pointer to the right', 60);
    pointerAt(sim, 'pointerup', 11.5, 5.8);
  });

  it('tear: a hard pull tears the cloth, the torn cells are not drawn, it stays torn until reset(); no tear, no tearing', async () => {
    /** Cloth pixels on the canvas, once it shows the newest step (a paused scene draws its newest frame as it is). */
    const cloth = async (s: ClothSimElement) => {
      await drawn(s, 2);
      return countColour(s, '#9cc3ec');
    };
    /** Pulls the bottom-middle particle 7 units down over 24 steps, holds it for 10, lets go and steps 60 more. */
    const pullDown = async (s: ClothSimElement) => {
      await steppedDrag(s, [7.5, 5.8], [7.5, 12.8], 24, 1);
      await s.step(10);
      pointerAt(s, 'pointerup', 7.5, 12.8);
      await s.step(60);
    };
    for (const tear of [null, '0.2']) {
      sim = await mountSim<ClothSimElement>('cloth-sim', `columns="8" rows="6" spacing="1" pins="top" stroke="none" wind="0" paused ${tear ? `tear="${tear}"` : ''}`);
      await sim.step(30);
      const whole = await cloth(sim);
      expect(whole).to.be.above(3000);
      await pullDown(sim);
      const broken = (await sim.diagnostics()).brokenLinks;
      if (!tear) {
        expect(broken).to.equal(0);
        // Released, the untorn cloth hangs whole again.
        await stepUntil(sim, async () => (await cloth(sim!)) > whole * 0.95, 'the cloth whole again', 600, 30);
        unmount(sim);
        continue;
      }
      expect(broken).to.be.at.least(2);
      // Torn cells are left undrawn and the torn-off piece falls away: clearly less cloth on the canvas, and it stays so.
      expect(await cloth(sim)).to.be.below(whole * 0.9);
      await sim.step(60);
      expect((await sim.diagnostics()).brokenLinks).to.be.at.least(broken);
      expect(await cloth(sim)).to.be.below(whole * 0.9);
      await sim.reset();
      expect((await sim.diagnostics()).brokenLinks).to.equal(0);
      await sim.step(30);
      expect(await cloth(sim)).to.be.above(whole * 0.95);
    }
  });

  it('reset() starts over as a fresh load does, in the wind of time 0 (not of the last gust)', async () => {
    sim = await mountSim<ClothSimElement>('cloth-sim', 'paused');
    const atLoad = await sim.stateHash();
    await sim.step(90);
    const first = await sim.stateHash();
    await sim.reset();
    expect(await sim.stateHash()).to.equal(atLoad);
    await sim.step(90);
    expect(await sim.stateHash()).to.equal(first);
  });

  it('wind pushes the cloth downwind; with no wind it hangs still', async () => {
    sim = await mountSim<ClothSimElement>('cloth-sim', 'columns="8" rows="6" pins="top" wind="0"');
    const cloth = clothOf(sim);
    await waitFor(() => sim!.stepCount > 20, '20 steps');
    // No wind: pinned along its top, the cloth hangs straight down, centred at x = 8.
    expect(cloth.x).to.be.closeTo(8, 0.01);
    sim.wind = 30;
    await waitFor(() => cloth.x > 8.5, 'the wind to blow the cloth right');
    sim.wind = -30;
    await waitFor(() => cloth.x < 7.5, 'the wind to blow it back left');
  });

  it('bad attributes: physics-error and a console warning naming them, defaults used, the error box shows them until fixed', async () => {
    const errors: PhysicsErrorDetail[] = [];
    const warnings: string[] = [];
    const warn = console.warn;
    console.warn = (...args: unknown[]) => warnings.push(args.join(' '));
    const listener = (e: Event) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail);
    document.addEventListener('physics-error', listener);
    try {
      sim = await mountSim<ClothSimElement>('cloth-sim', 'columns="abc" stiffness="2" pins="0 99"');
      expect((await sim.diagnostics()).particleCount).to.equal(24 * 16);
      const mine = errors.filter((e) => e.element === sim);
      expect(mine.map((e) => `${e.attribute}=${e.value}`).sort()).to.deep.equal(['columns=abc', 'pins=0 99', 'stiffness=2']);
      expect(warnings.some((w) => w.includes('<cloth-sim> columns="abc"'))).to.equal(true);
      // A bad pin list is told every form pins may take (24 columns: the default, columns being bad).
      expect(mine.find((e) => e.attribute === 'pins')!.message).to.equal('must be top, corners, none or column numbers from 0 to 23');
      sim.setAttribute('pins', 'top row');
      await waitFor(() => errors.some((e) => e.value === 'top row'), 'the second bad pins value reported');
      expect(errors.find((e) => e.value === 'top row')!.message).to.equal('must be top, corners, none or column numbers from 0 to 23');
      const box = sim.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!;
      expect(box.textContent).to.contain('columns="abc"');
      expect(box.getBoundingClientRect().height).to.be.greaterThan(10);
      sim.setAttribute('columns', '12');
      sim.setAttribute('stiffness', '0.5');
      sim.setAttribute('pins', 'top');
      await waitFor(() => sim!.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!.getBoundingClientRect().height === 0, 'the error box to go');
      expect((await sim.diagnostics()).particleCount).to.equal(12 * 16);
    } finally {
      console.warn = warn;
      document.removeEventListener('physics-error', listener);
    }
  });
});

describe('<ragdoll-sim>', () => {
  let sim: RagdollSimElement | null = null;
  afterEach(() => unmount(sim));

  it('count ragdolls tumble down six stairs', async () => {
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'count="2"');
    expect(document.createElement('ragdoll-sim')).to.be.instanceOf(RagdollSimElement);
    const d = await sim.diagnostics();
    expect(d.bodyCount).to.equal(2 + 6);
    const dolls = dollsOf(sim);
    expect(dolls.length).to.equal(2);
    const start = dolls.map((r) => [r.x, r.y]);
    // They fall in and are pushed down the stairs (to the right).
    await waitFor(() => dolls.every((r, k) => r.y > start[k][1] + 1.5 && r.x > start[k][0] + 1.5), 'both ragdolls to fall and move down the stairs');
  });

  it('obstacles="pegs" and "none"; count changes live', async () => {
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'count="1" obstacles="pegs"');
    expect(sim.shadowRoot!.querySelectorAll('physics-circle').length).to.be.greaterThan(10);
    sim.obstacles = 'none';
    sim.count = 4;
    await waitFor(async () => (await sim!.diagnostics()).bodyCount === 4, 'four ragdolls and no obstacles');
  });

  it('reset() starts over as a fresh load does: the same state after the same steps (the dolls pushed again)', async () => {
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'paused respawn="off"');
    await sim.step(60);
    const first = await sim.stateHash();
    await sim.reset();
    await sim.step(60);
    expect(await sim.stateHash()).to.equal(first);
  });

  it('respawn puts a ragdoll that lies still back at the top', async () => {
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'count="1" obstacles="none" respawn');
    const [doll] = dollsOf(sim);
    await waitFor(() => doll.y > 8, 'the ragdoll to land on the floor');
    // It must lie still for 1.5 s of the page's clock: a generous deadline, not a measure of speed.
    await waitFor(() => sim!.respawned >= 1, 'a respawn after lying still', 30000);
    await waitFor(() => doll.y < 4, 'the ragdoll back near the top');
  });

  it('drag a ragdoll and let go: it is thrown', async () => {
    // No gravity and no obstacles: the ragdoll stands where it spawned until the pointer takes its pelvis.
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'count="1" obstacles="none" gravity="0 0" paused');
    const [doll] = dollsOf(sim);
    await simulated(sim, doll);
    const x0 = doll.x;
    const y0 = doll.y;
    await steppedDrag(sim, [x0, y0], [x0 + 5, y0 + 2], 12, 2);
    await stepUntil(sim, () => doll.x > x0 + 2, 'the ragdoll to follow the pointer', 60);
    const atRelease = doll.x;
    pointerAt(sim, 'pointerup', x0 + 5, y0 + 2);
    // Thrown: it keeps the speed it had and flies on to the right after the pointer let go (no gravity, no walls
    // in its way for a while).
    await sim.step(30);
    const flown = doll.x - atRelease;
    expect(flown, 'distance flown in 0.5 s').to.be.above(0.5);
    await sim.step(30);
    expect(doll.x - atRelease - flown, 'distance flown in the next 0.5 s').to.be.above(0.5);
  });

  it('stroke="none" and obstacle-fill="none" (attribute or property) draw no ragdoll lines and no obstacle fill', async () => {
    const DOLL = '#333a44';
    const OBSTACLE = '#8a8f98';
    // Drawn by default: the dolls' lines and the stairs' fill.
    sim = await mountSim<RagdollSimElement>('ragdoll-sim', 'paused');
    await drawn(sim, 2);
    expect(countColour(sim, DOLL)).to.be.above(100);
    expect(countColour(sim, OBSTACLE)).to.be.above(5000);
    const s = sim;
    s.stroke = 'none';
    s.obstacleFill = 'none';
    // Not in another colour either (a ragdoll with neither stroke nor fill was drawn in #333).
    const dark = () => countColour(s, DOLL) + countColour(s, '#333333') + countColour(s, '#000000');
    await waitFor(() => dark() === 0 && countColour(s, OBSTACLE) === 0, 'dolls and stair fill gone (properties)');
    expect(dollsOf(s).map((d) => d.getAttribute('stroke'))).to.deep.equal(['none', 'none', 'none']);
    expect((await s.diagnostics()).bodyCount).to.equal(3 + 6);
    unmount(s);
    // Written as attributes (with spaces, as a CMS may leave them), from the start: nothing reported, nothing drawn.
    const errors: PhysicsErrorDetail[] = [];
    const box = document.createElement('div');
    box.style.cssText = 'width: 480px; height: 300px;';
    sim = document.createElement('ragdoll-sim');
    sim.setAttribute('paused', '');
    sim.setAttribute('stroke', ' none');
    sim.setAttribute('obstacle-fill', 'none ');
    sim.style.cssText = 'width: 100%; height: 100%';
    sim.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail));
    box.append(sim);
    document.body.append(box);
    await sim.ready;
    await drawn(sim, 2);
    expect(errors).to.deep.equal([]);
    expect([countColour(sim, DOLL), countColour(sim, '#333333'), countColour(sim, OBSTACLE)]).to.deep.equal([0, 0, 0]);
    // A colour still colours them (and the stroke "none" of the cloth still works: see above).
    sim.stroke = '#ff0000';
    await waitFor(() => countColour(sim!, '#ff0000') > 100, 'red ragdolls');
  });

  it('bad attributes fall back to defaults and are reported on the element', async () => {
    const errors: PhysicsErrorDetail[] = [];
    const warn = console.warn;
    console.warn = () => {};
    try {
      const box = document.createElement('div');
      box.style.cssText = 'width: 480px; height: 300px;';
      sim = document.createElement('ragdoll-sim');
      sim.setAttribute('count', '-2');
      sim.setAttribute('obstacles', 'lava');
      sim.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail));
      box.append(sim);
      document.body.append(box);
      await sim.ready;
      expect(errors.map((e) => `${e.attribute}=${e.value}`).sort()).to.deep.equal(['count=-2', 'obstacles=lava']);
      expect((await sim.diagnostics()).bodyCount).to.equal(3 + 6);
    } finally {
      console.warn = warn;
    }
  });
});

describe('presets: a bad width or height', () => {
  let sim: PhysicsSceneElement | null = null;
  afterEach(() => unmount(sim));

  /** `<tag attrs>` in a 480 px wide container that leaves its height to the element (its view's aspect ratio). */
  async function mountUnsized<T extends PhysicsSceneElement>(tag: string, attrs: string): Promise<T> {
    const box = document.createElement('div');
    box.style.cssText = 'width: 480px;';
    // Test markup only: fixed strings written in the tests.
    box.innerHTML = `<${tag} ${attrs}></${tag}>`;
    document.body.append(box);
    const el = box.firstElementChild as T;
    await el.ready;
    return el;
  }

  it('falls back to the preset\'s own 16 × 10 in the view (aspect, element height) as in the layout of its bodies', async () => {
    const errors: PhysicsErrorDetail[] = [];
    const warn = console.warn;
    console.warn = () => {};
    const listener = (e: Event) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail);
    document.addEventListener('physics-error', listener);
    try {
      const cases: [string, string, (s: PhysicsSceneElement) => void, string][] = [
        ['ragdoll-sim', 'height="oops"', () => {}, 'height=oops'],
        ['ragdoll-sim', '', (s) => (s.height = 0), 'height=0'],
        ['cloth-sim', '', (s) => (s.height = -1), 'height=-1'],
        ['cloth-sim', 'width="-4"', () => {}, 'width=-4'],
      ];
      for (const [tag, attrs, change, reported] of cases) {
        const what = `<${tag} ${attrs}> ${reported}`;
        errors.length = 0;
        sim = await mountUnsized(tag, attrs);
        change(sim);
        await waitFor(() => errors.some((e) => `${e.attribute}=${e.value}` === reported), `${what} reported`);
        await sim.updateComplete;
        expect(sim.style.getPropertyValue('--physics-scene-view-aspect'), what).to.equal('16 / 10');
        expect(sim.getBoundingClientRect().height, what).to.be.closeTo(300, 1);
        if (tag === 'ragdoll-sim') {
          // The stairs stand on the view's floor: the bottom of every step at y = 10, none below it.
          const steps = Array.from(sim.shadowRoot!.querySelectorAll<HTMLElement & { y: number; height: number }>('physics-box'));
          expect(steps.length, what).to.equal(6);
          for (const s of steps) expect(Number(s.getAttribute('y')) + Number(s.getAttribute('height')) / 2, what).to.be.closeTo(10, 1e-9);
        } else {
          // The cloth hangs centred across the 16 units, and its 16 rows fill three quarters of the 10 down at most.
          const cloth = clothOf(sim as ClothSimElement);
          const spacing = Number(cloth.getAttribute('spacing'));
          expect(Number(cloth.getAttribute('x')) + (spacing * 23) / 2, what).to.be.closeTo(8, 1e-9);
          expect(spacing * 15, what).to.be.at.most(10 * 0.75 + 1e-9);
        }
        unmount(sim);
        sim = null;
      }
    } finally {
      console.warn = warn;
      document.removeEventListener('physics-error', listener);
    }
  });
});
