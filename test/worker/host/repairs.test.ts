// The host's word on the step guard (engine pipeline/guard.ts): Diagnostics.rowsRepaired, and one console warning per
// realm the first time a world's step put bodies back. The guard itself is tested in test/engine/pipeline/guard.test.ts.
import { expect } from 'chai';
import { World } from '../../../src/engine/index.js';
import { handleSlot } from '../../../src/engine/handles.js';
import { warnIfRowsRepaired } from '../../../src/worker/host/diagnostics.js';

/** A world of two discs, one of them made to leave a step not finite (as a solver fault would). */
function brokenWorld(): World {
  const world = new World({ gravity: { x: 0, y: 10 }, sleeping: false });
  world.addRigidBody({ radius: 0.5, x: 0, y: 0 });
  const broken = world.addRigidBody({ radius: 0.5, x: 3, y: 0 });
  world.step();
  world.particles.vx[handleSlot(world.bodyParticleHandles(broken)[0])] = NaN;
  return world;
}

describe('EngineHost: rows the step put back', () => {
  it('warns once per realm, naming how many bodies, the first time a world reports any, and never for a sound world', () => {
    const warnings: string[] = [];
    const warn = console.warn;
    console.warn = (message: string) => warnings.push(message);
    try {
      const sound = new World({ gravity: { x: 0, y: 10 } });
      sound.addRigidBody({ radius: 0.5, x: 0, y: 0 });
      sound.step();
      warnIfRowsRepaired(sound);
      expect(warnings).to.deep.equal([]);
      const first = brokenWorld();
      warnIfRowsRepaired(first);
      expect(warnings, 'nothing put back yet').to.deep.equal([]);
      first.step();
      expect(first.diagnostics().rowsRepaired).to.equal(1);
      warnIfRowsRepaired(first);
      warnIfRowsRepaired(first);
      const second = brokenWorld();
      second.step();
      warnIfRowsRepaired(second);
      expect(warnings).to.have.length(1);
      expect(warnings[0]).to.match(/^physics-elements: the solver put 1 body back where a step started, at rest: joints it cannot resolve/);
    } finally {
      console.warn = warn;
    }
  });
});
