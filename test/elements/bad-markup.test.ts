// Bad markup: a physics-error event and a console warning naming the element, the attribute and the value; the rest
// of the scene keeps running, and no attribute value reaches the DOM as markup.
import { expect } from '@open-wc/testing';
import type { PhysicsBoxElement, PhysicsErrorDetail, PhysicsSceneElement } from '../../src/index.js';
import { mount, unmount, waitFor } from './helpers.js';

/**
 * From here on, console.warn's lines (kept, not printed) and the physics-error details; `before` listens for the errors
 * on the scene mount() makes. The describe's afterEach puts console.warn back.
 */
function reports(): { warnings: string[]; errors: PhysicsErrorDetail[]; before: (scene: PhysicsSceneElement) => void } {
  const warnings: string[] = [];
  const errors: PhysicsErrorDetail[] = [];
  console.warn = (...args: unknown[]) => warnings.push(args.map(String).join(' '));
  return { warnings, errors, before: (s) => s.addEventListener('physics-error', (e) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail)) };
}

describe('<physics-scene> bad markup', () => {
  let scene: PhysicsSceneElement | null = null;
  const warn = console.warn;
  afterEach(() => {
    console.warn = warn;
    unmount(scene);
    delete (window as { pwned?: number }).pwned;
  });

  it('reports width="abc", a two-point polygon, a joint naming a missing id and a negative radius; the rest runs', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="abc" height="10" gravity="0 10"',
      `<physics-box id="box" x="5" y="2" width="1" height="1"></physics-box>
       <physics-polygon id="tri" x="3" y="3" points="0,0 1,1"></physics-polygon>
       <physics-joint a="box" b="missing"></physics-joint>
       <physics-circle id="ball" x="7" y="3" radius="-1"></physics-circle>`,
      { before },
    );
    const seen = errors.map((e) => [e.element.localName, e.attribute, e.value]);
    expect(seen).to.have.deep.members([
      ['physics-scene', 'width', 'abc'],
      ['physics-polygon', 'points', '0,0 1,1'],
      ['physics-joint', 'b', 'missing'],
      ['physics-circle', 'radius', '-1'],
    ]);
    for (const [tag, attribute, value] of seen) {
      expect(warnings.some((w) => w.includes(`<${tag}`) && w.includes(`${attribute}="${value}"`)), `a warning for <${tag}> ${attribute}="${value}"`).to.equal(true);
    }
    expect(warnings.length).to.equal(4);
    // The box is simulated and falls; the ball too, its radius the default 0.5; the polygon that cannot be built and
    // the joint were left out; width fell back to 16.
    const d = await scene.diagnostics();
    expect(d.bodyCount).to.equal(2);
    expect(d.linkCount).to.equal(0);
    expect(scene.style.getPropertyValue('--physics-scene-view-aspect')).to.equal('16 / 10');
    const box = scene.querySelector<PhysicsBoxElement>('#box')!;
    await waitFor(() => box.y > 2.5, 'the good box to fall');
    // Fixing the markup brings the polygon in, without another error.
    scene.querySelector('physics-polygon')!.setAttribute('points', '0,0 1,0 0,1');
    await waitFor(async () => (await scene!.diagnostics()).bodyCount === 3, 'the fixed polygon');
    expect(errors.length).to.equal(4);
  });

  it('a bad size falls back to its default and keeps the body, on a ball as on a box (radius = 0 dropped the ball)', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="10" height="10" gravity="0 10" paused',
      `<physics-box id="floor" x="5" y="9.5" width="10" height="1" static></physics-box>
       <physics-box id="box" x="3" y="7" width="1" height="1"></physics-box>
       <physics-circle id="ball" x="7" y="7" radius="1"></physics-circle>
       <physics-circle id="marked" x="5" y="7" radius="-1"></physics-circle>`,
      { before },
    );
    expect(errors.map((e) => `${e.element.id} ${e.attribute}=${e.value}`)).to.deep.equal(['marked radius=-1']);
    expect((await scene.diagnostics()).bodyCount).to.equal(4);
    const s = scene;
    const [box, ball, marked] = ['#box', '#ball', '#marked'].map((q) => s.querySelector<HTMLElement & { width: number; radius: number; y: number }>(q)!);
    box.width = -2;
    ball.radius = 0;
    await waitFor(() => errors.length === 3, 'both reported');
    expect(errors.slice(1).map((e) => `${e.element.id} ${e.attribute}=${e.value}: ${e.message}`)).to.have.members([
      'box width=-2: must be a number > 0',
      'ball radius=0: must be a number > 0',
    ]);
    expect(warnings.length).to.equal(3);
    expect((await s.diagnostics()).bodyCount).to.equal(4);
    // Simulated at their defaults: each comes to rest on the floor (top at y = 9), the box 1 tall, the balls 0.5 round.
    await s.step(120);
    expect(box.y).to.be.closeTo(8.5, 0.05);
    expect(ball.y).to.be.closeTo(8.5, 0.05);
    expect(marked.y).to.be.closeTo(8.5, 0.05);
  });

  it('a static rope and a static cloth hold still; density on a rope, cloth or ragdoll is reported (they take mass), and they run', async () => {
    const { errors, before } = reports();
    scene = await mount(
      'width="10" height="10" paused',
      `<physics-rope id="rope" x1="1" y1="2" x2="5" y2="2" static pin="none"></physics-rope>
       <physics-cloth id="cloth" x="5" y="1" columns="4" rows="3" static pins="none"></physics-cloth>
       <physics-rope id="heavy" x1="1" y1="5" x2="4" y2="5" density="3"></physics-rope>
       <physics-cloth id="sheet" x="5" y="5" columns="3" rows="3" density="2"></physics-cloth>
       <physics-ragdoll id="doll" x="8" y="4" density="1e-20"></physics-ragdoll>`,
      { before },
    );
    expect(errors.map((e) => [e.element.id, e.attribute, e.value])).to.have.deep.members([
      ['heavy', 'density', '3'],
      ['sheet', 'density', '2'],
      ['doll', 'density', '1e-20'],
    ]);
    expect(errors[0].message).to.include('set mass');
    const [rope, cloth, heavy] = ['#rope', '#cloth', '#heavy'].map((q) => scene!.querySelector<HTMLElement & { y: number }>(q)!);
    await scene.step(1);
    const startY = [rope.y, cloth.y, heavy.y];
    expect(startY[0]).to.be.closeTo(2, 1e-9);
    await scene.step(60);
    // A second under gravity: the static ones where they were, the reported rope (pinned at its start) swung down.
    expect(rope.y).to.equal(startY[0]);
    expect(cloth.y).to.equal(startY[1]);
    expect(heavy.y).to.be.above(startY[2] + 0.3);
    expect((await scene.diagnostics()).bodyCount).to.equal(5);
  });

  it('a view too small (width="1e-300", height="1e-9") is reported on width or height and falls back, on a scene, a <ragdoll-sim> and a <cloth-sim>: the box keeps its height, the presets their bodies', async () => {
    const { warnings, errors } = reports();
    const listen = (e: Event) => errors.push((e as CustomEvent<PhysicsErrorDetail>).detail);
    document.addEventListener('physics-error', listen);
    const box = document.createElement('div');
    box.style.width = '400px';
    try {
      // No height set: the element's box takes the view's aspect ratio, which a view too small made 0 px tall.
      box.innerHTML = `<physics-scene id="wide" width="1e-300" paused><physics-circle x="5" y="2" radius="0.5"></physics-circle></physics-scene>
        <physics-scene id="tall" height="1e-9" paused></physics-scene>
        <physics-scene id="small" width="0.001" height="0.001" paused></physics-scene>
        <ragdoll-sim id="dolls" width="1e-300" paused></ragdoll-sim><ragdoll-sim id="dolls2" paused></ragdoll-sim>
        <cloth-sim id="cloth" height="1e-9" paused></cloth-sim><cloth-sim id="cloth2" paused></cloth-sim>`;
      document.body.append(box);
      const scenes = Array.from(box.children) as PhysicsSceneElement[];
      await Promise.all(scenes.map((s) => s.ready));
      expect(errors.map((e) => [(e.element as Element).id, e.attribute, e.value, e.message])).to.have.deep.members([
        ['wide', 'width', '1e-300', 'must be >= 0.001'],
        ['tall', 'height', '1e-9', 'must be >= 0.001'],
        ['dolls', 'width', '1e-300', 'must be >= 0.001'],
        ['cloth', 'height', '1e-9', 'must be >= 0.001'],
      ]);
      expect(warnings.length).to.equal(4);
      expect(warnings.filter((w) => w.includes('width="1e-300"'))).to.have.length(2);
      // Each falls back to its default view: a 16 × 9 box (16 × 10 for a preset); 0.001 × 0.001 is a valid square.
      const heights = scenes.map((s) => Math.round(s.getBoundingClientRect().height));
      expect(heights).to.deep.equal([225, 225, 400, 250, 250, 250, 250]);
      // The presets build what their defaults build.
      const [dolls, dolls2, cloth, cloth2] = await Promise.all(scenes.slice(3).map((s) => s.diagnostics()));
      expect([dolls.bodyCount, dolls.linkCount]).to.deep.equal([dolls2.bodyCount, dolls2.linkCount]);
      expect(cloth.particleCount).to.equal(cloth2.particleCount);
    } finally {
      document.removeEventListener('physics-error', listen);
      box.remove();
    }
  });

  it('reports misspelt attribute names with the one meant; the page\'s own attributes and globals are left alone', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="10" height="10" gravty="0 1" data-post="7" aria-label="Two crates" class="wide" title="t" my-widget="1"',
      `<physics-circle id="ball" x="5" y="2" radus="1.5"></physics-circle>
       <physics-box id="crate" x="3" y="2" width="1" heigth="2" frction="0.2" data-kind="crate" sound="thud"></physics-box>
       <physics-joint a="ball" b="crate" typ="weld"></physics-joint>`,
      { before },
    );
    expect(errors.map((e) => [e.element.localName, e.attribute, e.value, e.message])).to.have.deep.members([
      ['physics-scene', 'gravty', '0 1', 'unknown attribute, ignored: did you mean gravity?'],
      ['physics-circle', 'radus', '1.5', 'unknown attribute, ignored: did you mean radius?'],
      ['physics-box', 'heigth', '2', 'unknown attribute, ignored: did you mean height?'],
      ['physics-box', 'frction', '0.2', 'unknown attribute, ignored: did you mean friction?'],
      ['physics-joint', 'typ', 'weld', 'unknown attribute, ignored: did you mean type?'],
    ]);
    expect(warnings.length).to.equal(5);
    expect(warnings.some((w) => w.includes('<physics-circle id="ball"> radus="1.5": unknown attribute, ignored: did you mean radius?'))).to.equal(true);
    // They are ignored: the defaults hold and everything is simulated.
    const d = await scene.diagnostics();
    expect([d.bodyCount, d.linkCount]).to.deep.equal([2, 1]);
  });

  it('a misspelt attribute set from script on a running scene or body is reported at once, not at the next real change', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount('width="10" height="10"', `<physics-box id="crate" x="3" y="2" width="1" height="1"></physics-box>`, { before });
    expect(errors).to.deep.equal([]);
    scene.querySelector('#crate')!.setAttribute('wdth', '3');
    scene.setAttribute('gravty', '0 1');
    await waitFor(() => errors.length === 2, 'both reported');
    expect(errors.map((e) => [e.element.localName, e.attribute, e.value, e.message])).to.have.deep.members([
      ['physics-box', 'wdth', '3', 'unknown attribute, ignored: did you mean width?'],
      ['physics-scene', 'gravty', '0 1', 'unknown attribute, ignored: did you mean gravity?'],
    ]);
    expect(warnings.length).to.equal(2);
    // Ignored: the box is simulated as it was.
    expect((await scene.diagnostics()).bodyCount).to.equal(1);
  });

  it('a whole-number attribute names its whole range: columns="1.5" is not told "must be >= 2"', async () => {
    const { errors, before } = reports();
    scene = await mount(
      'width="10" height="10"',
      `<physics-cloth id="sheet" x="2" y="1" columns="1.5" rows="5000" spacing="0.3"></physics-cloth>
       <physics-rope id="line" x1="6" y1="1" x2="8" y2="1" segments="2.5"></physics-rope>
       <physics-pin body="line" x="8" y="1" particle="-1"></physics-pin>`,
      { before },
    );
    const seen = errors.map((e) => [e.element.localName, e.attribute, e.value, e.message]);
    expect(seen, JSON.stringify(seen)).to.have.deep.members([
      ['physics-cloth', 'columns', '1.5', 'must be a whole number from 2 to 4096'],
      ['physics-cloth', 'rows', '5000', 'must be a whole number from 2 to 4096'],
      ['physics-rope', 'segments', '2.5', 'must be a whole number from 1 to 10000'],
      ['physics-pin', 'particle', '-1', 'must be a whole number >= 0'],
    ]);
  });

  it('on a right-to-left page the messages read left to right, marked as English, and the page stays right to left', async () => {
    console.warn = () => {};
    scene = await mount('width="10" height="10"', `<physics-box x="3" y="2" width="1" wdth="3"></physics-box>`, { ready: false });
    const page = scene.parentElement!;
    page.dir = 'rtl';
    page.lang = 'ar';
    await scene.ready;
    const box = scene.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!;
    await waitFor(() => !box.hidden, 'the error box');
    expect(box.textContent).to.include('<physics-box> wdth="3": unknown attribute');
    // Unmarked, the box would take the page's direction and the bidi algorithm would move the leading "<" to the end.
    expect(getComputedStyle(box).direction).to.equal('ltr');
    expect(box.closest('[lang]')!.getAttribute('lang')).to.equal('en');
    expect(getComputedStyle(scene).direction).to.equal('rtl');
  });

  it('reports coordinates beyond ±1e9 (x="1e12" on a box, a pin and a spring\'s length, a polygon point); the rest runs', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="10" height="10" gravity="0 10"',
      `<physics-box id="box" x="5" y="2" width="1" height="1"></physics-box>
       <physics-box id="far" x="1e12" y="2" width="1" height="1"></physics-box>
       <physics-pin body="box" x="-1e12" y="2"></physics-pin>
       <physics-spring a="box" b="far" length="1e12"></physics-spring>
       <physics-polygon x="3" y="3" points="0,0 1e12,0 0,1"></physics-polygon>`,
      { before },
    );
    const seen = errors.map((e) => [e.element.localName, e.attribute, e.value]);
    expect(seen).to.have.deep.members([
      ['physics-box', 'x', '1e12'],
      ['physics-pin', 'x', '-1e12'],
      ['physics-spring', 'length', '1e12'],
      ['physics-polygon', 'points', '0,0 1e12,0 0,1'],
    ]);
    expect(errors.every((e) => e.message.includes('within ±1e9')), errors.map((e) => e.message).join('; ')).to.equal(true);
    for (const [tag, attribute, value] of seen) {
      expect(warnings.filter((w) => w.includes(`<${tag}`) && w.includes(`${attribute}="${value}"`)).length, `one warning for <${tag}> ${attribute}="${value}"`).to.equal(1);
    }
    expect(warnings.length).to.equal(4);
    // The far box falls back to x 0 (at the left wall, which holds it within the view) and is simulated; the spring
    // takes its default rest length (the bodies' distance); the pin and the polygon are left out. Both boxes fall.
    const d = await scene.diagnostics();
    expect([d.bodyCount, d.linkCount]).to.deep.equal([2, 1]);
    const [box, far] = ['#box', '#far'].map((s) => scene!.querySelector<PhysicsBoxElement>(s)!);
    expect(far.x).to.be.within(0, 1);
    await waitFor(() => box.y > 2.5 && far.y > 2.5, 'both boxes to fall');
  });

  it('a pin\'s particle past the body\'s count (a rigid body\'s is 1), or one pinned already, is reported by the pin\'s attribute and the body\'s index', async () => {
    const { warnings, errors, before } = reports();
    // An 11-particle rope (particles 0…10), unpinned; a 4-particle box of particles.
    scene = await mount(
      'width="10" height="10" paused',
      `<physics-rope id="r" x1="2" y1="2" x2="6" y2="2" segments="10" pin="none"></physics-rope>
       <physics-box id="b" model="particles" x="8" y="5" width="1" height="1"></physics-box>
       <physics-pin id="far" body="r" particle="99" x="2" y="2"></physics-pin>
       <physics-pin id="corner" body="b" particle="4" x="8" y="5"></physics-pin>
       <physics-pin id="end" body="r" particle="10" x="6" y="2"></physics-pin>
       <physics-pin id="again" body="r" particle="10" x="6" y="2"></physics-pin>
       <physics-pin id="near" body="r" x="6.1" y="2"></physics-pin>
       <physics-box id="plate" x="8" y="8" width="1" height="1"></physics-box>
       <physics-pin id="centre" body="plate" particle="0" x="8" y="8"></physics-pin>
       <physics-box id="crate" x="3" y="8" width="1" height="1"></physics-box>
       <physics-pin id="row" body="crate" particle="5" x="3" y="7"></physics-pin>`,
      { before },
    );
    await waitFor(() => errors.length >= 5, 'the five refused pins reported');
    const seen = errors.map((e) => [e.element.id, e.attribute, e.value]);
    expect(seen).to.have.deep.members([
      ['far', 'particle', '99'],
      ['corner', 'particle', '4'],
      ['again', 'particle', '10'],
      ['near', 'x', '6.1'],
      ['row', 'particle', '5'],
    ]);
    const message = (id: string) => errors.find((e) => e.element.id === id)!.message;
    expect(message('far')).to.include("less than the body's particle count (11), got 99");
    expect(message('corner')).to.include("less than the body's particle count (4), got 4");
    // A rigid body has one row: its particle 0, the centre.
    expect(message('row')).to.include("less than the body's particle count (1), got 5");
    // The body's own index (10), not the engine's.
    expect(message('again')).to.include('not rigidly pinned already').and.include('got 10');
    expect(message('near')).to.include('particle 10');
    expect(warnings.length).to.equal(5);
    expect(warnings.join('\n')).to.contain('particle="5"');
    // The good pins: the rope's end, and the rigid plate by its centre (particle 0: its one row).
    const d = await scene.diagnostics();
    expect(d.linkCount).to.equal(2);
    await scene.step(30);
    const plate = scene.querySelector<PhysicsBoxElement>('#plate')!;
    expect(plate.x).to.be.closeTo(8, 1e-9);
    expect(plate.y).to.be.closeTo(8, 1e-9);
  });

  it('errors name the attribute that is at fault and the value that was refused: a script\'s value, a size too small for a mass, a share of mass per particle', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="10" height="10" paused',
      `<physics-box id="painted" x="2" y="2" width="1" height="1" fill="#3d7dd8"></physics-box>
       <physics-box id="turned" x="4" y="2" width="1" height="1" angle="0"></physics-box>
       <physics-box id="tiny" x="6" y="2" width="1e-300" height="1"></physics-box>
       <physics-box id="ledge" x="6" y="8" width="1e-300" height="1" static></physics-box>
       <physics-softbody id="pinned" x="2" y="8" radius="1e-6" segments="4096" static></physics-softbody>
       <physics-box id="dense" x="8" y="2" width="1e9" height="1" density="1e300"></physics-box>
       <physics-circle id="speck" x="2" y="5" radius="1e-7" density="1e-2"></physics-circle>
       <physics-softbody id="small" x="5" y="5" radius="1e-6" segments="4096"></physics-softbody>
       <physics-softbody id="light" x="8" y="6" radius="1" segments="4096" mass="1e-10"></physics-softbody>`,
      { before },
    );
    await waitFor(() => errors.length >= 6, 'the six bodies reported');
    const painted = scene.querySelector<PhysicsBoxElement>('#painted')!;
    (painted as unknown as { fill: unknown }).fill = NaN;
    (scene.querySelector<PhysicsBoxElement>('#turned') as unknown as { angle: number }).angle = 1e308;
    await waitFor(() => errors.length >= 7, 'the script\'s fill reported');
    await scene.step(2);
    const seen = errors.map((e) => [e.element.id, e.attribute, e.value]);
    expect(seen).to.have.deep.members([
      ['tiny', 'width', '1e-300'],
      // A static body needs a mass too (setBodyType may make it dynamic): reported on its size, as a movable one is.
      ['ledge', 'width', '1e-300'],
      ['dense', 'density', '1e300'],
      ['speck', 'density', '1e-2'],
      ['small', 'radius', '1e-6'],
      ['light', 'mass', '1e-10'],
      // What the script set, not the attribute it replaced.
      ['painted', 'fill', 'NaN'],
    ]);
    const message = (id: string) => errors.find((e) => e.element.id === id)!.message;
    expect(message('tiny')).to.include('gives a mass of 1e-300').and.include('below the smallest, 1e-12');
    expect(message('dense')).to.include('not a finite number');
    expect(message('small')).to.include('for each of its 4096 particles');
    // 1e308 degrees is a finite angle (it used to overflow on its way to radians and be refused as Infinity).
    expect(errors.some((e) => e.element.id === 'turned')).to.equal(false);
    expect(message('ledge')).to.include('gives a mass of 1e-300');
    // A static ring's particles are pinned: no mass to check, the engine takes it.
    expect(errors.some((e) => e.element.id === 'pinned')).to.equal(false);
    expect(warnings.length).to.equal(7);
    expect(await scene.stateHash()).to.match(/\S/);
  });

  it('a body id used twice is reported on the later element (links name the first), and leaves the box once renamed', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount(
      'width="10" height="10" paused',
      `<physics-box id="a" x="2" y="2" width="1" height="1"></physics-box>
       <physics-box id="a" class="second" x="5" y="2" width="1" height="1"></physics-box>
       <physics-circle id="c" x="8" y="2" radius="0.5"></physics-circle>
       <physics-spring a="a" b="c"></physics-spring>`,
      { before },
    );
    await waitFor(() => errors.length > 0, 'the shared id reported');
    const second = scene.querySelector('.second')!;
    expect(errors.map((e) => [e.element, e.attribute, e.value])).to.deep.equal([[second, 'id', 'a']]);
    expect(errors[0].message).to.include('also the id of an earlier <physics-box');
    expect(warnings.filter((w) => w.includes('also the id'))).to.have.length(1);
    const box = scene.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!;
    await waitFor(() => !box.hidden && box.textContent!.includes('also the id'), 'the error box');
    second.id = 'b';
    await waitFor(() => box.hidden === true, 'the error box to empty once renamed');
    // A third with the id: reported again (a new problem), once.
    const third = document.createElement('physics-box');
    third.id = 'a';
    scene.append(third);
    await waitFor(() => errors.length === 2, 'the new shared id reported');
    expect(errors[1].element).to.equal(third);
    expect((await scene.diagnostics()).bodyCount).to.equal(4);
  });

  it('a body the engine refuses is reported, and leaves the error box once its markup is fixed', async () => {
    const { errors, before } = reports();
    scene = await mount('width="10" height="10" paused', `<physics-box id="box" x="5" y="2" width="1" height="1" density="1e-20"></physics-box>`, { before });
    const box = scene.shadowRoot!.querySelector<HTMLElement>('[part="error"]')!;
    await waitFor(() => errors.some((e) => e.message.includes('1e-12')), 'the refused body reported');
    expect(errors[0].element.id).to.equal('box');
    await waitFor(() => !box.hidden && box.textContent!.includes('1e-12'), 'the refusal in the error box');
    expect((await scene.diagnostics()).bodyCount).to.equal(0);
    scene.querySelector('#box')!.setAttribute('density', '1');
    await waitFor(() => box.hidden === true, 'the error box to empty');
    expect((await scene.diagnostics()).bodyCount).to.equal(1);
  });

  it('setVelocity and applyImpulse refuse bad numbers where they are called; an impulse past the speed limit is a physics-error naming the body, the engine keeps running', async () => {
    const { errors, before } = reports();
    scene = await mount('width="10" height="10" paused', `<physics-box id="box" x="5" y="2" width="1" height="1"></physics-box>`, { before });
    const box = scene.querySelector<PhysicsBoxElement>('#box')!;
    expect(() => box.setVelocity(NaN, 0)).to.throw(RangeError, 'vx');
    expect(() => box.setVelocity('5' as never, 0)).to.throw(TypeError, 'vx');
    expect(() => box.setVelocity(0, 2e9)).to.throw(RangeError, 'vy');
    expect(() => box.applyImpulse(Infinity, 0)).to.throw(RangeError, 'ix');
    box.applyImpulse(1e308, 1e308);
    await waitFor(() => errors.some((e) => e.message.includes('ix / mass')), 'the refused impulse reported');
    // On the body it was asked of (it was the scene's, with nothing to tell which body).
    expect(errors.find((e) => e.message.includes('ix / mass'))!.element).to.equal(box);
    const steps = scene.stepCount;
    expect(await scene.step(10)).to.equal(steps + 10);
    expect(Number.isFinite(box.x) && Number.isFinite(box.y)).to.equal(true);
    expect(errors.every((e) => e.attribute !== 'worker'), 'the worker did not die').to.equal(true);
  });

  it('a bad value set from script is reported as set, not as the attribute text it replaced', async () => {
    const { warnings, errors, before } = reports();
    scene = await mount('width="12" height="10" paused', `<physics-box id="b1" x="4" y="2" width="1" height="1"></physics-box>`, { before });
    const box = scene.querySelector<PhysicsBoxElement>('#b1')!;
    box.x = NaN;
    box.width = -1;
    scene.width = 0;
    await waitFor(() => errors.length >= 3, 'three reports');
    expect(errors.map((e) => [e.attribute, e.value])).to.deep.include.members([['x', 'NaN'], ['width', '-1'], ['width', '0']]);
    expect(warnings.join('\n')).to.contain('x="NaN"').and.contain('width="-1"');
    // An attribute written blank is still reported as written.
    box.setAttribute('y', '');
    await waitFor(() => errors.some((e) => e.attribute === 'y'), 'the blank y');
    expect(errors.find((e) => e.attribute === 'y')!.value).to.equal('');
  });

  it('an attribute value never reaches the DOM as markup', async () => {
    const { warnings, errors, before } = reports();
    const evil = '<img src=x onerror="window.pwned=1">';
    scene = await mount('width="10" height="10"', `<physics-box x="5" y="2" width="1" height="1"></physics-box>`, { before });
    const box = scene.querySelector('physics-box')!;
    box.setAttribute('fill', evil);
    box.setAttribute('id', evil);
    scene.setAttribute('background', evil);
    await waitFor(() => errors.length >= 2, 'two errors');
    await new Promise((r) => setTimeout(r, 100));
    expect(errors.map((e) => [e.attribute, e.value])).to.deep.include.members([['fill', evil], ['background', evil]]);
    expect(scene.shadowRoot!.querySelector('img')).to.equal(null);
    expect(document.querySelector('img')).to.equal(null);
    expect((window as { pwned?: number }).pwned).to.equal(undefined);
    expect(warnings.length).to.equal(2);
  });
});
