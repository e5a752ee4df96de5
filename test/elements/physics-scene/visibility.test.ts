// Visibility on its own: a fake intersection watch and a reduced-motion answer instead of the browser's. Off screen or
// on a hidden page the scene does not run; reduced motion starts it paused with the play control; toggle() (Space) pauses and plays.
import { expect } from '@open-wc/testing';
import { NEAR_MARGIN, VisibilityController, type IntersectionWatch } from '../../../src/elements/physics-scene/visibility.js';
import { liveResources } from '../../../src/worker/resources.js';
import { makeHost, type FakeHost } from './fakes.js';

function rig(reducedMotion = false) {
  const host = makeHost();
  let report: ((onScreen: boolean) => void) | null = null;
  let watching = 0;
  const intersection: IntersectionWatch = (target, changed) => {
    expect(target).to.equal(host);
    report = changed;
    watching++;
    return { disconnect: () => void watching-- };
  };
  let nearReport: ((near: boolean) => void) | null = null;
  let nearWatching = 0;
  const margins: (string | undefined)[] = [];
  const nearby: IntersectionWatch = (target, changed, margin) => {
    expect(target).to.equal(host);
    nearReport = changed;
    margins.push(margin);
    nearWatching++;
    return { disconnect: () => void nearWatching-- };
  };
  let changes = 0;
  const visibility = new VisibilityController(host, { changed: () => changes++, label: () => 'Crates falling', intersection, nearby, reducedMotion: () => reducedMotion });
  return {
    host, visibility, margins,
    changes: () => changes,
    watching: () => watching,
    nearWatching: () => nearWatching,
    scroll: (onScreen: boolean) => report!(onScreen),
    approach: (near: boolean) => nearReport!(near),
  };
}

describe('VisibilityController', () => {
  let host: FakeHost | null = null;
  afterEach(() => {
    host?.remove();
    delete (document as unknown as Record<string, unknown>).visibilityState;
  });

  it('runs on screen; scrolled away it does not (and says so); back on screen it runs again', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect(r.changes()).to.equal(1);
    expect([r.visibility.onScreen, r.visibility.running]).to.deep.equal([true, true]);
    r.scroll(false);
    expect([r.visibility.onScreen, r.visibility.running, r.changes()]).to.deep.equal([false, false, 2]);
    r.scroll(true);
    expect([r.visibility.onScreen, r.visibility.running, r.changes()]).to.deep.equal([true, true, 3]);
    host.paused = true;
    expect([r.visibility.onScreen, r.visibility.running]).to.deep.equal([true, false]);
  });

  it('a hidden page: not on screen; visible again: on screen', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    Object.defineProperty(document, 'visibilityState', { configurable: true, get: () => 'hidden' });
    document.dispatchEvent(new Event('visibilitychange'));
    expect([r.visibility.onScreen, r.changes()]).to.deep.equal([false, 2]);
    delete (document as unknown as Record<string, unknown>).visibilityState;
    document.dispatchEvent(new Event('visibilitychange'));
    expect([r.visibility.onScreen, r.changes()]).to.deep.equal([true, 3]);
  });

  it('watches only while connected: its observer and listener counted, and released on disconnect', () => {
    const r = rig();
    host = r.host;
    const before = liveResources();
    document.body.append(host);
    expect(r.watching()).to.equal(1);
    // The on-screen watch and, until the scene has come near, the near watch.
    expect(r.nearWatching()).to.equal(1);
    expect(liveResources().observers - before.observers).to.equal(2);
    expect(liveResources().listeners - before.listeners).to.equal(1);
    host.remove();
    expect([r.watching(), r.nearWatching()]).to.deep.equal([0, 0]);
    expect(liveResources()).to.deep.include({ observers: before.observers, listeners: before.listeners });
    // Hidden while out of the document: no one is told.
    document.dispatchEvent(new Event('visibilitychange'));
    expect(r.changes()).to.equal(1);
  });

  it('whenNear() waits until the scene comes within a viewport of the screen, then the near watch ends', async () => {
    const r = rig();
    host = r.host;
    const before = liveResources().observers;
    document.body.append(host);
    expect(r.margins).to.deep.equal([NEAR_MARGIN]);
    let near = false;
    void r.visibility.whenNear().then(() => (near = true));
    r.approach(false);
    await Promise.resolve();
    expect(near).to.equal(false);
    r.approach(true);
    await Promise.resolve();
    expect(near).to.equal(true);
    expect(r.nearWatching()).to.equal(0);
    expect(liveResources().observers - before).to.equal(1);
    // Near once is near for good while connected: far again, a new start does not wait.
    r.scroll(false);
    let again = false;
    await r.visibility.whenNear().then(() => (again = true));
    expect(again).to.equal(true);
    // Out of the document and back: it waits to come near again; coming on screen, it starts at once.
    host.remove();
    document.body.append(host);
    expect(r.nearWatching()).to.equal(1);
    let third = false;
    void r.visibility.whenNear().then(() => (third = true));
    await Promise.resolve();
    expect(third).to.equal(false);
    r.scroll(true);
    await Promise.resolve();
    expect([third, r.nearWatching()]).to.deep.equal([true, 0]);
  });

  it('near but not on screen: it starts when the page is idle, after the scenes on screen (or at once when it comes on screen)', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    r.scroll(false);
    let near = false;
    void r.visibility.whenNear().then(() => (near = true));
    r.approach(true);
    await Promise.resolve();
    expect(near).to.equal(false);
    await new Promise((resolve) => requestIdleCallback(resolve, { timeout: 2000 }));
    await new Promise((resolve) => setTimeout(resolve, 0));
    expect([near, r.nearWatching()]).to.deep.equal([true, 0]);
    // Out and back, near off screen, then on screen before the page is idle: at once.
    host.remove();
    document.body.append(host);
    r.scroll(false);
    let again = false;
    void r.visibility.whenNear().then(() => (again = true));
    r.approach(true);
    r.scroll(true);
    await Promise.resolve();
    expect(again).to.equal(true);
  });

  it('demand() (a script asks for the scene) ends the wait wherever it is; leaving the document lets a waiting start go', async () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    let near = false;
    void r.visibility.whenNear().then(() => (near = true));
    r.visibility.demand();
    await Promise.resolve();
    expect([near, r.nearWatching()]).to.deep.equal([true, 0]);
    host.remove();
    document.body.append(host);
    let stale = false;
    void r.visibility.whenNear().then(() => (stale = true));
    host.remove();
    await Promise.resolve();
    expect([stale, r.nearWatching()]).to.deep.equal([true, 0]);
  });

  it('prefers-reduced-motion: paused at connect with the play control, which play() hides; not once play() was called', () => {
    const r = rig(true);
    host = r.host;
    document.body.append(host);
    expect(host.paused).to.equal(true);
    expect(r.visibility.playControl).to.equal(true);
    expect(host.requestedUpdates).to.equal(1);
    r.visibility.play();
    expect(host.paused).to.equal(false);
    host.update();
    expect(r.visibility.playControl).to.equal(false);
    const other = rig(true);
    other.visibility.play();
    document.body.append(other.host);
    expect(other.host.paused).to.equal(false);
    other.host.remove();
  });

  it('toggle() (Space) pauses and shows the play control, or plays; the play control\'s click plays and gives the scene focus', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect([r.visibility.toggle(), host.paused, r.visibility.playControl]).to.deep.equal([true, true, true]);
    expect([r.visibility.toggle(), host.paused]).to.deep.equal([false, false]);
    // The play control's click plays and gives the scene focus.
    host.paused = true;
    const click = new MouseEvent('click', { bubbles: true });
    r.visibility.onPlayClick(click);
    expect(host.paused).to.equal(false);
    expect(document.activeElement).to.equal(host);
  });

  it('makes the scene focusable with a role, a label and its key shortcut, unless the page set them', () => {
    const r = rig();
    host = r.host;
    document.body.append(host);
    expect([host.tabIndex, host.getAttribute('role'), host.getAttribute('aria-label'), host.getAttribute('aria-keyshortcuts')]).to.deep.equal([0, 'group', 'Crates falling', 'Space R']);
    const other = rig();
    other.host.setAttribute('tabindex', '-1');
    other.host.setAttribute('role', 'img');
    other.host.setAttribute('aria-labelledby', 'caption');
    document.body.append(other.host);
    expect([other.host.tabIndex, other.host.getAttribute('role'), other.host.getAttribute('aria-label')]).to.deep.equal([-1, 'img', null]);
    other.host.remove();
  });
});
