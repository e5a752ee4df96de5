import { expect } from 'chai';
import { World } from '../../src/engine/index.js';
import { busyWorld } from './helpers.js';

describe('determinism', () => {
  it('two identical runs give identical state hashes', () => {
    const a = busyWorld();
    const b = busyWorld();
    for (let k = 0; k < 300; k++) {
      a.step();
      b.step();
    }
    expect(a.stateHash()).to.equal(b.stateHash());
    expect(a.stateHash()).to.match(/^[0-9a-f]{16}$/);
  });

  it('a different input gives a different hash', () => {
    const a = busyWorld();
    const b = busyWorld();
    b.applyImpulse(b.particleHandle(3), 1e-9, 0);
    for (let k = 0; k < 10; k++) {
      a.step();
      b.step();
    }
    expect(a.stateHash()).to.not.equal(b.stateHash());
  });

  it('snapshot → step → restore → step gives identical hashes', () => {
    const world = busyWorld();
    for (let k = 0; k < 50; k++) world.step();
    const snap = structuredClone(world.snapshot()); // as a worker would receive it
    for (let k = 0; k < 100; k++) world.step();
    const first = world.stateHash();
    world.restore(snap);
    for (let k = 0; k < 100; k++) world.step();
    expect(world.stateHash()).to.equal(first);
  });

  it('restoring into a fresh world reproduces the run, handles included', () => {
    const world = busyWorld();
    const extra = world.addParticle({ x: 1, y: 1 });
    world.removeParticle(extra);
    for (let k = 0; k < 20; k++) world.step();
    const copy = new World();
    copy.restore(world.snapshot());
    for (let k = 0; k < 60; k++) {
      world.step();
      copy.step();
    }
    expect(copy.stateHash()).to.equal(world.stateHash());
    expect(copy.addParticle({ x: 0, y: 0 })).to.equal(world.addParticle({ x: 0, y: 0 }));
  });

  it('advance() takes fixed steps, caps catch-up and leaves the remainder in alpha', () => {
    const world = new World({ timestep: 0.01, maxCatchUpSteps: 5 });
    expect(world.advance(0.035)).to.equal(3);
    expect(world.alpha).to.be.closeTo(0.5, 1e-9);
    expect(world.advance(1)).to.equal(5); // a stalled tab: at most 5 steps, the backlog dropped
    // 1.005 s pending, 5 steps of 0.01 taken: 0.955 s of backlog, of which the part of a step (0.005 s) is kept.
    expect(world.alpha).to.be.closeTo(0.5, 1e-9);
    expect(world.advance(0.004)).to.equal(0);
    expect(world.alpha).to.be.closeTo(0.9, 1e-9);
    expect(world.advance(0.002)).to.equal(1);
    expect(world.alpha).to.be.closeTo(0.1, 1e-9);
    const variable = new World({ variableStep: true, timestep: 0.01 });
    expect(variable.advance(0.023)).to.equal(1);
    expect(variable.time).to.be.closeTo(0.023, 1e-12);
  });

  it('advance() calls afterStep after each step it takes, with that step\'s state', () => {
    const world = new World({ timestep: 0.01, maxCatchUpSteps: 5 });
    const seen: number[] = [];
    expect(world.advance(0.035, () => seen.push(world.stepCount))).to.equal(3);
    expect(seen).to.deep.equal([1, 2, 3]);
    expect(world.advance(0.004, () => seen.push(-1))).to.equal(0); // no step, no call
    expect(world.advance(1, () => seen.push(world.stepCount))).to.equal(5);
    expect(seen).to.deep.equal([1, 2, 3, 4, 5, 6, 7, 8]);
    const variable = new World({ variableStep: true, timestep: 0.01 });
    let calls = 0;
    variable.advance(0.02, () => calls++);
    variable.advance(0, () => calls++);
    expect(calls).to.equal(1);
    expect(() => world.advance(0.01, 'x' as unknown as () => void)).to.throw(TypeError, /afterStep/);
  });
});
