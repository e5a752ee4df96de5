// Many scenes on one page share a small pool of engine workers: 8 scenes in at most 2 workers, each drawing and
// stepping on its own (step(n) on one moves no other, pausing one pauses no other); a pool worker that dies takes
// every scene in it through recovery while the other worker's scenes go on untouched; scenes far below the viewport
// start only when scrolled near (or asked for by script); adding and removing scenes leaves no worker behind.
import { expect } from '@open-wc/testing';
import { PhysicsSceneElement, type PhysicsErrorDetail } from '../../src/index.js';
import { liveResources } from '../../src/worker/resources.js';
import { frames, mount, unmount, waitFor } from './helpers.js';

/** Counts the workers made and the most alive at once, by replacing the global Worker for the duration of a test. */
function countWorkers() {
  const Real = window.Worker;
  const live = new Set<Worker>();
  const counts = { made: 0, most: 0 };
  class CountingWorker extends Real {
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      counts.made++;
      live.add(this);
      counts.most = Math.max(counts.most, live.size);
    }
    override terminate(): void {
      live.delete(this);
      super.terminate();
    }
  }
  window.Worker = CountingWorker;
  return { counts, live, restore: () => (window.Worker = Real) };
}

// Slow and tall: a box falls for seconds, so it is still falling after a restart.
const FALLING = 'width="30" height="30" gravity="0 2"';
const BOX = '<physics-box x="15" y="1" width="1" height="1"></physics-box>';

type Box = HTMLElement & { x: number; y: number };

describe('many scenes, one pool of workers', () => {
  let scenes: PhysicsSceneElement[] = [];
  let workers: ReturnType<typeof countWorkers>;
  const spacers: HTMLElement[] = [];

  beforeEach(async () => {
    // Workers of earlier tests are past their grace period: every test counts from none.
    await waitFor(() => liveResources().workers === 0, 'no engine worker left from before');
    workers = countWorkers();
  });
  afterEach(() => {
    scenes.forEach(unmount);
    scenes = [];
    spacers.splice(0).forEach((s) => s.remove());
    workers.restore();
    PhysicsSceneElement.maxWorkers = null;
    window.scrollTo(0, 0);
  });

  const mountMany = async (n: number, attrs: string, children: string) => {
    const made = await Promise.all(Array.from({ length: n }, () => mount(attrs, children, { width: 120, height: 70 })));
    scenes.push(...made);
    return made;
  };

  it('8 scenes share 2 workers; each draws its own canvas and step(n) on one moves no other', async () => {
    PhysicsSceneElement.maxWorkers = 2;
    const all = await mountMany(8, `paused ${FALLING}`, BOX);
    expect(workers.counts.made).to.equal(2);
    expect(liveResources().workers).to.equal(2);
    const byWorker = new Map<number, number>();
    for (const s of all) {
      expect(s.mode).to.equal('worker');
      byWorker.set(s.client!.worker!, (byWorker.get(s.client!.worker!) ?? 0) + 1);
    }
    expect([...byWorker.values()]).to.deep.equal([4, 4]);
    // Each has drawn its own canvas (a paused scene draws once, then only what changes).
    await waitFor(() => all.every((s) => s.renderedFrames > 0 && s.canvas !== null), 'every scene drawn');
    const start = await all[1].stateHash();
    expect(await all[0].step(30)).to.equal(30);
    expect(all.map((s) => s.stepCount)).to.deep.equal([30, 0, 0, 0, 0, 0, 0, 0]);
    const boxes = all.map((s) => s.querySelector<Box>('physics-box')!);
    // Half a second at g = 2: a quarter unit down; the others where they were described.
    expect(boxes[0].y).to.be.closeTo(1.25, 0.02);
    for (const b of boxes.slice(1)) expect(b.y).to.equal(1);
    for (const s of all.slice(1)) expect(await s.stateHash()).to.equal(start);
    // Its neighbour in the same worker steps on its own count.
    const neighbour = all.find((s, k) => k > 0 && s.client!.worker === all[0].client!.worker)!;
    expect(await neighbour.step(5)).to.equal(5);
    expect(all[0].stepCount).to.equal(30);
  });

  it('pausing one scene pauses no other in the same worker', async () => {
    PhysicsSceneElement.maxWorkers = 1;
    const all = await mountMany(3, FALLING, BOX);
    expect(new Set(all.map((s) => s.client!.worker)).size).to.equal(1);
    await waitFor(() => all.every((s) => s.stepCount > 5), 'all three to run');
    all[0].pause();
    await waitFor(async () => !(await all[0].diagnostics()).running, 'the first to stop stepping');
    const held = all[0].stepCount;
    const others = all.slice(1).map((s) => s.stepCount);
    await waitFor(() => all.slice(1).every((s, k) => s.stepCount > others[k] + 30), 'the other two to take 30 more steps');
    expect(all[0].stepCount).to.equal(held);
    expect(all.slice(1).every((s) => s.running)).to.equal(true);
    all[0].play();
    await waitFor(() => all[0].stepCount > held + 10, 'the first to run again');
  });

  for (const fault of ['throw', 'terminate'] as const) {
    it(`a pool worker that dies (${fault}): every scene in it is restored where it was drawn, the other worker's scenes go on untouched`, async () => {
      PhysicsSceneElement.maxWorkers = 2;
      const errors = new Map<PhysicsSceneElement, PhysicsErrorDetail[]>();
      const atError = new Map<PhysicsSceneElement, number>();
      const atResume = new Map<PhysicsSceneElement, Promise<number>>();
      const all = await Promise.all(
        Array.from({ length: 4 }, () =>
          mount(FALLING, BOX, {
            width: 120,
            height: 70,
            before: (s) => {
              errors.set(s, []);
              s.addEventListener('physics-error', (e) => {
                errors.get(s)!.push(e.detail);
                const box = s.querySelector<Box>('physics-box')!;
                atError.set(s, box.y);
                atResume.set(s, s.ready.then(() => box.y));
              });
            },
          }),
        ),
      );
      scenes.push(...all);
      const victim = all[0].client!.worker!;
      const hit = all.filter((s) => s.client!.worker === victim);
      const spared = all.filter((s) => s.client!.worker !== victim);
      expect([hit.length, spared.length]).to.deep.equal([2, 2]);
      const sparedClients = spared.map((s) => s.client);
      await waitFor(() => all.every((s) => s.querySelector<Box>('physics-box')!.y > 1.5), 'the boxes to fall');
      await all[0]._debugFault(fault);
      await waitFor(() => hit.every((s) => errors.get(s)!.length === 1), 'physics-error on both scenes of the dead worker');
      for (const s of hit) {
        expect(errors.get(s)![0].message).to.match(/^engine worker died \(.*\); restarting it \(attempt 1 of 3\)$/);
        const yAfter = await atResume.get(s)!;
        await s.ready;
        expect(s.mode).to.equal('worker');
        expect(s.client!.worker).to.not.equal(victim);
        expect(Math.abs(yAfter - atError.get(s)!), `y ${yAfter} after the restart, ${atError.get(s)} at the death`).to.be.below(0.3);
      }
      // The other worker: no error, the same engine clients, still stepping.
      expect(spared.map((s) => errors.get(s)!.length)).to.deep.equal([0, 0]);
      expect(spared.every((s, k) => s.client === sparedClients[k])).to.equal(true);
      const steps = all.map((s) => s.stepCount);
      await waitFor(() => all.every((s, k) => s.stepCount > steps[k] + 20), 'all four scenes to keep stepping');
      expect(liveResources().workers).to.be.at.most(2);
      expect(workers.live.size).to.be.at.most(2);
    });
  }

  it('a scene far below the viewport makes no canvas and no world until it is scrolled near, or a script asks for it', async () => {
    const near = await mount('paused', BOX, { width: 120, height: 70 });
    scenes.push(near);
    const spacer = document.createElement('div');
    spacer.style.height = `${4 * window.innerHeight}px`;
    document.body.append(spacer);
    spacers.push(spacer);
    const far = await mount('paused', BOX, { width: 120, height: 70, ready: false });
    const farther = await mount('paused', BOX, { width: 120, height: 70, ready: false });
    scenes.push(far, farther);
    await frames(10);
    expect([far.client, far.canvas, farther.client, farther.canvas]).to.deep.equal([null, null, null, null]);
    expect(liveResources().sketches).to.equal(1);
    // Scrolled to within a viewport of it: it starts (the next one, right below, too).
    window.scrollTo(0, spacer.offsetTop + spacer.offsetHeight - 1.5 * window.innerHeight);
    await waitFor(() => far.client !== null && far.canvas !== null, 'the scrolled-near scene to start');
    await far.ready;
    expect(far.mode).to.equal('worker');
    // A script asking for a scene starts it wherever it is.
    window.scrollTo(0, 0);
    const last = await mount('paused', BOX, { width: 120, height: 70, ready: false });
    scenes.push(last);
    await frames(5);
    expect(last.client).to.equal(null);
    expect(await last.step(3)).to.equal(3);
    expect(last.mode).to.equal('worker');
  });

  it('adding and removing scenes 20 times: never more workers than the pool size, none once every scene is gone', async () => {
    PhysicsSceneElement.maxWorkers = 2;
    for (let k = 0; k < 20; k++) {
      const pair = await mountMany(2, 'paused', BOX);
      expect(pair.every((s) => s.mode === 'worker')).to.equal(true);
      expect(liveResources().workers).to.be.at.most(2);
      pair.forEach(unmount);
      scenes = [];
      await frames(1);
    }
    expect(workers.counts.most).to.be.at.most(2);
    await waitFor(() => liveResources().workers === 0 && workers.live.size === 0, 'the pool to terminate its empty workers');
    expect(liveResources()).to.deep.include({ workers: 0, pendingCalls: 0 });
  });
});
