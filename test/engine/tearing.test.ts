import { expect } from 'chai';
import { World, createCloth, type KernelChoice } from '../../src/engine/index.js';
import { allFinite } from './helpers.js';

/** A compliant link from a fixed point to a bob of mass 1 hanging under gravity g = 10. */
function hangingBob(breakStrain: number, startY = 1, compliance = 0.02) {
  const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
  const pivot = world.addParticle({ x: 0, y: 0, mass: Infinity });
  const bob = world.addParticle({ x: 0, y: startY, mass: 1 });
  const link = world.addDistance(pivot, bob, { length: 1, compliance, breakStrain });
  return { world, bob, link };
}

/** A 12 × 8 cloth pinned along its top, grabbed at a bottom corner and pulled 6 units down and right over 2 s
 *  (the default kernel unless `kernel` names one). */
function pulledCloth(tear?: number, kernel?: KernelChoice) {
  const world = new World({ gravity: { x: 0, y: 10 }, kernel });
  const cloth = createCloth(world, { origin: { x: 0, y: 0 }, columns: 12, rows: 8, spacing: 0.5, pins: 'top', tear });
  for (let k = 0; k < 30; k++) world.step();
  const grab = world.grab(5.5, 3.5)!;
  let breaks = 0;
  for (let k = 1; k <= 120; k++) {
    world.moveGrab(grab, 5.5 + k * 0.05, 3.5 + k * 0.05);
    world.step();
    breaks += world.breaks.count;
  }
  return { world, cloth, grab, breaks };
}

describe('tearing (breakable distance links)', () => {
  it('a link below its break strain holds at the analytic stretch compliance·m·g', () => {
    // Static XPBD stretch of a link of compliance c under force m·g: c·m·g = 0.02 · 1 · 10 = 0.2. The bob starts
    // there (released from the unstretched length it would swing on to twice that, 0.4).
    const { world, bob, link } = hangingBob(0.3, 1.2);
    for (let k = 0; k < 600; k++) world.step();
    expect(world.isBroken(link)).to.equal(false);
    expect(world.getPosition(bob).y - 1).to.be.closeTo(0.2, 0.01);
  });

  it('past its break strain the link breaks once, is reported that step, and the bob then falls freely', () => {
    const { world, bob, link } = hangingBob(0.1);
    let brokeAt = -1;
    let reports = 0;
    for (let k = 0; k < 120; k++) {
      world.step();
      for (let i = 0; i < world.breaks.count; i++) {
        expect(world.breaks.handles[i]).to.equal(link);
        reports++;
        if (brokeAt < 0) brokeAt = k;
      }
      if (brokeAt >= 0) break;
    }
    expect(reports).to.equal(1);
    expect(world.isBroken(link)).to.equal(true);
    // From here on only gravity acts: y(t) = y0 + v0·t + g·t²/2 over the next second.
    const y0 = world.getPosition(bob).y;
    const v0 = world.getVelocity(bob).y;
    for (let k = 0; k < 60; k++) {
      world.step();
      expect(world.breaks.count).to.equal(0);
    }
    expect(world.getPosition(bob).y).to.be.closeTo(y0 + v0 + 0.5 * 10, 0.02);
    expect(world.maxStrain()).to.equal(0);
  });

  // The JS solver's tear: 8 links, the whole right-hand column from its pin down and the corner's other link, in one
  // step (15 of the pull). The WebAssembly kernel sweeps the links in coloured batches (even links, then odd), which
  // carries the pull less far up the column per sweep: the corner's two links reach the break strain alone and it
  // tears just them (steps 14 and 17; largest strain before 0.145 against 0.149), so "at least 3" is the JS
  // solver's number. The next test holds under both kernels.
  it('a cloth pulled hard tears, stays torn, and a snapshot from before puts it back whole (JS solver)', () => {
    const whole = new World({ gravity: { x: 0, y: 10 }, kernel: 'js' });
    createCloth(whole, { origin: { x: 0, y: 0 }, columns: 12, rows: 8, spacing: 0.5, pins: 'top', tear: 0.15 });
    const before = whole.snapshot();
    const { world, cloth, grab, breaks } = pulledCloth(0.15, 'js');
    expect(breaks).to.be.at.least(3);
    const torn = cloth.constraints.filter((h) => world.constraintKindOf(h) === 'distance' && world.isBroken(h));
    expect(torn.length).to.equal(breaks);
    world.release(grab);
    for (let k = 0; k < 300; k++) world.step();
    // Broken links never mend; nothing is NaN.
    expect(cloth.constraints.filter((h) => world.constraintKindOf(h) === 'distance' && world.isBroken(h)).length).to.be.at.least(breaks);
    expect(allFinite(world)).to.equal(true);
    world.restore(before);
    expect(cloth.constraints.filter((h) => world.constraintKindOf(h) === 'distance' && world.isBroken(h)).length).to.equal(0);
    for (let k = 0; k < 60; k++) world.step();
    expect(world.maxStrain()).to.be.below(0.05);
  });

  it('under either kernel the pulled corner tears free: every link at the grabbed particle breaks, and only pulled links do', () => {
    const { world, cloth, grab, breaks } = pulledCloth(0.15);
    const corner = world.particleIndex(cloth.particles[cloth.particles.length - 1]);
    expect(world.getPosition(world.particleHandle(corner)).x).to.be.above(9); // the grabbed one, pulled to x ≈ 11.5
    const links = cloth.constraints.filter((h) => world.constraintKindOf(h) === 'distance');
    const atCorner = links.filter((h) => Array.from(world.distanceParticleIndices(h)).includes(corner));
    expect(atCorner.length).to.equal(2);
    for (const h of atCorner) expect(world.isBroken(h)).to.equal(true);
    const torn = links.filter((h) => world.isBroken(h));
    expect(torn.length).to.equal(breaks);
    // Torn links are on the pulled side: each has an end in the right-hand column (the cloth is 12 particles a row).
    const rightColumn = new Set(cloth.particles.filter((_, k) => k % 12 === 11).map((h) => world.particleIndex(h)));
    expect(rightColumn.has(corner)).to.equal(true);
    for (const h of torn) expect(Array.from(world.distanceParticleIndices(h)).some((i) => rightColumn.has(i))).to.equal(true);
    world.release(grab);
    for (let k = 0; k < 300; k++) world.step();
    expect(links.filter((h) => world.isBroken(h)).length).to.equal(breaks);
    expect(allFinite(world)).to.equal(true);
  });

  it('off by default: the same pull tears nothing', () => {
    const { breaks, world, cloth } = pulledCloth(undefined);
    expect(breaks).to.equal(0);
    expect(cloth.constraints.some((h) => world.constraintKindOf(h) === 'distance' && world.isBroken(h))).to.equal(false);
  });

  it('tearing is deterministic: a replay gives the same state hash', () => {
    const a = pulledCloth(0.15);
    const b = pulledCloth(0.15);
    expect(a.breaks).to.equal(b.breaks);
    expect(a.world.stateHash()).to.equal(b.world.stateHash());
  });

  it('bad break strains are refused with errors naming them', () => {
    const world = new World();
    const p = world.addParticle({ x: 0, y: 0 });
    const q = world.addParticle({ x: 1, y: 0 });
    for (const bad of [0, -1, NaN, Infinity]) expect(() => world.addDistance(p, q, { breakStrain: bad })).to.throw(RangeError, /breakStrain/);
    expect(() => world.addDistance(p, q, { minLength: 1, maxLength: Infinity, breakStrain: 0.5 })).to.throw(RangeError, /breakStrain/);
    expect(() => createCloth(world, { origin: { x: 0, y: 0 }, columns: 3, rows: 3, spacing: 1, tear: -2 })).to.throw(RangeError, /tear/);
    expect(world.particleCount).to.equal(2);
  });
});
