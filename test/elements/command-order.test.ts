// Commands and markup changes in the order the page makes them. A body element's setVelocity() / applyImpulse() right
// after a change of its markup (an attribute that rebuilds the body, a new element) acts on the body the change
// builds, not on the one it replaces; and once scene.step() resolves, the live poses of the bodies a change rebuilt are
// readable (the frame's topology has arrived), so el.x / el.y read the simulation, not the markup.
//
// Nothing here depends on timing: the scenes are paused and stepped by the test, the order of the messages is forced.
import { expect } from '@open-wc/testing';
import type { PhysicsCircleElement, PhysicsSceneElement } from '../../src/index.js';
import { MarkupSync } from '../../src/elements/physics-scene/markup.js';
import type { Command, Engine } from '../../src/elements/physics-scene/session.js';
import { F, type KeyedBody } from '../../src/worker/protocol.js';
import { FakeEngine, settle } from './physics-scene/fakes.js';
import { mount, unmount } from './helpers.js';

const G = 9.81;
const DT = 1 / 60;

/** A paused scene with a floor and one ball at (2, 3), no gravity unless asked. */
async function scene(gravity = '0 0'): Promise<{ scene: PhysicsSceneElement; ball: PhysicsCircleElement }> {
  const s = await mount(
    `width="16" height="9" paused gravity="${gravity}"`,
    `<physics-box static x="8" y="8.6" width="16" height="0.8"></physics-box><physics-circle id="ball" x="2" y="3" radius="0.3"></physics-circle>`,
  );
  await s.step(1);
  return { scene: s, ball: s.querySelector<PhysicsCircleElement>('#ball')! };
}

describe('commands after markup changes', function () {
  this.timeout(60000);
  let s: PhysicsSceneElement | null = null;
  afterEach(() => {
    unmount(s);
    s = null;
  });

  it('setVelocity() right after an attribute that rebuilds the body moves the rebuilt body', async () => {
    const made = await scene();
    s = made.scene;
    const { ball } = made;
    // Same task: the attribute's update (Lit, a microtask later) has not reached the engine when the kick is sent.
    ball.setAttribute('y', '4');
    ball.setVelocity(6, 0);
    await s.step(10);
    const pose = s.poseOf(ball)!;
    expect(pose, 'the ball is simulated').to.not.equal(null);
    // Rebuilt at (2, 4), then 10 steps at 6 units/s: x = 2 + 6 * 10 / 60 = 3 (no gravity, nothing in the way).
    expect(pose[1]).to.be.closeTo(4, 1e-9);
    expect(pose[0]).to.be.closeTo(2 + 6 * 10 * DT, 1e-9);
  });

  it('applyImpulse() right after an attribute that rebuilds the body pushes the rebuilt body', async () => {
    const made = await scene();
    s = made.scene;
    const { ball } = made;
    ball.setAttribute('radius', '0.5');
    ball.setAttribute('mass', '2');
    ball.applyImpulse(0, -8);
    await s.step(6);
    const pose = s.poseOf(ball)!;
    // Impulse 8 on mass 2: 4 units/s upward, from (2, 3): y = 3 - 4 * 6 / 60 = 2.6.
    expect(pose[0]).to.be.closeTo(2, 1e-9);
    expect(pose[1]).to.be.closeTo(3 - 4 * 6 * DT, 1e-9);
  });

  it('setVelocity() on a body element just added (before the scene saw it) moves the new body', async () => {
    const made = await scene();
    s = made.scene;
    const ball = document.createElement('physics-circle');
    ball.setAttribute('x', '10');
    ball.setAttribute('y', '2');
    ball.setAttribute('radius', '0.25');
    s.append(ball);
    ball.setVelocity(-3, 0);
    await s.step(12);
    const pose = s.poseOf(ball)!;
    expect(pose, 'the new ball is simulated').to.not.equal(null);
    expect(pose[0]).to.be.closeTo(10 - 3 * 12 * DT, 1e-9);
    expect(pose[1]).to.be.closeTo(2, 1e-9);
  });

  it('a change of the scene in the same task as the kick keeps the kick (gravity, and the body rebuilt)', async () => {
    const made = await scene();
    s = made.scene;
    const { ball } = made;
    s.setAttribute('gravity', `0 ${G}`);
    ball.setAttribute('x', '3');
    ball.setVelocity(0, -2);
    await s.step(1);
    const pose = s.poseOf(ball)!;
    // One step from (3, 3) at 2 units/s upward, gravity pulling back within the step (less than a whole step of it).
    expect(pose[0]).to.be.closeTo(3, 1e-9);
    expect(pose[1]).to.be.within(3 - 2 * DT + 0.3 * G * DT * DT, 3 - 2 * DT + G * DT * DT);
  });

  it('once step() resolves, a rebuilt body\'s live pose is readable though its topology came after the frame', async () => {
    const made = await scene(`0 ${G}`);
    s = made.scene;
    const { ball } = made;
    const client = s.client!;
    expect(client.transport, 'frames travel in shared memory, apart from the topology messages').to.equal('shared');
    // Hold back the topology messages (they travel on the world's port; the frames are in shared memory already).
    const port = (client as unknown as { link: { port: MessagePort } }).link.port;
    const deliver = port.onmessage!.bind(port);
    const held: MessageEvent[] = [];
    let holding = true;
    port.onmessage = (e: MessageEvent) => (holding && e.data?.type === 'topology' ? held.push(e) : deliver(e));
    try {
      ball.setAttribute('y', '2');
      const before = client.latestStep;
      let poseWhenResolved: [number, number, number] | null | undefined;
      const stepped = s.step(1).then((count) => {
        poseWhenResolved = s!.poseOf(ball);
        return count;
      });
      // The frame of that step is in shared memory; the step's answer comes on the worker's port, before the answer
      // of any call made after it. Once a later call has answered (and a task has run), a step() that only waited for
      // its answer and its frame has resolved.
      while (client.latestStep <= before) await new Promise((r) => setTimeout(r, 5));
      await client.api.stateHash();
      await new Promise((r) => setTimeout(r, 0));
      expect(held.length, 'the rebuild\'s topology is held back').to.be.greaterThan(0);
      expect(client.frames.curr[F.topology], 'the newest frame is of the new topology').to.be.greaterThan(client.topology!.version);
      holding = false;
      for (const e of held.splice(0)) deliver(e);
      await stepped;
      expect(poseWhenResolved, 'the pose, read as step() resolves').to.not.equal(null);
      // Rebuilt at (2, 2), then one step of falling from rest (less than g dt^2, more than a third of it).
      expect(poseWhenResolved![1]).to.be.within(2 + 0.3 * G * DT * DT, 2 + G * DT * DT);
      expect(ball.y, 'el.y reads the live pose').to.equal(poseWhenResolved![1]);
    } finally {
      holding = false;
      for (const e of held.splice(0)) deliver(e);
      port.onmessage = deliver;
    }
  });
});

/** Markup sync alone on a plain container, with a fake engine port that records what is sent, in order. */
function rig(markup: string) {
  const container = document.createElement('div');
  // Fixed test markup only.
  container.innerHTML = markup;
  document.body.append(container);
  const sent: [Command, unknown[]][] = [];
  const engine = new FakeEngine();
  const sync = new MarkupSync({
    container: () => container,
    engine: { live: engine as Engine, shown: engine as Engine, send: (method: Command, ...args: unknown[]) => void sent.push([method, args]) },
    problems: { set: () => {}, forget: () => {}, resent: () => {} },
    styles: { setStyle: () => {}, deleteStyle: () => {} },
  });
  sync.collect();
  sync.observe();
  return { container, sent, sync };
}

describe('MarkupSync: a command after a change goes after the change', () => {
  let container: HTMLElement | null = null;
  afterEach(() => container?.remove());

  it('setVelocity() in the task of an attribute change: updateBody first, then setVelocity, and nothing more later', async () => {
    const r = rig('<physics-circle id="b" x="1" y="2" radius="0.5"></physics-circle>');
    container = r.container;
    await settle();
    const ball = r.container.querySelector<PhysicsCircleElement>('#b')!;
    const key = r.sync.keyOf(ball)!;
    ball.setAttribute('y', '4');
    ball.setVelocity(3, 0);
    expect(r.sent.map(([m]) => m)).to.deep.equal(['updateBody', 'setVelocity']);
    expect((r.sent[0][1][0] as KeyedBody).key).to.equal(key);
    expect((r.sent[0][1][0] as KeyedBody).desc).to.deep.include({ y: 4 });
    expect(r.sent[1][1]).to.deep.equal([key, 3, 0]);
    // Lit's own update of the attribute comes next and finds it sent.
    await ball.updateComplete;
    await settle();
    expect(r.sent.map(([m]) => m)).to.deep.equal(['updateBody', 'setVelocity']);
  });

  it('applyImpulse() on a child added in the same task: addBody first, then the impulse on its key', async () => {
    const r = rig('<physics-box x="1" y="2"></physics-box>');
    container = r.container;
    await settle();
    const ball = document.createElement('physics-circle');
    ball.setAttribute('x', '4');
    ball.setAttribute('radius', '0.5');
    r.container.append(ball);
    r.sync.applyImpulse(ball, 0, -2);
    const key = r.sync.keyOf(ball);
    expect(key).to.not.equal(undefined);
    expect(r.sent.map(([m]) => m)).to.deep.equal(['addBody', 'applyImpulse']);
    expect((r.sent[0][1][0] as KeyedBody).key).to.equal(key);
    expect(r.sent[1][1]).to.deep.equal([key, 0, -2]);
    // The observer's record was taken: it does not add the child a second time.
    await settle();
    await settle();
    expect(r.sent.map(([m]) => m)).to.deep.equal(['addBody', 'applyImpulse']);
  });
});
