// Problems on their own: one physics-error (bubbling, composed) and one console warning per problem, once while it
// lasts; the error box lists the current ones; engine failures are kept (the latest five); refusals name the attribute.
import { expect } from '@open-wc/testing';
import type { PhysicsErrorDetail } from '../../../src/index.js';
import { ProblemsController } from '../../../src/elements/physics-scene/problems.js';
import { makeHost, type FakeHost } from './fakes.js';

describe('ProblemsController', () => {
  let host: FakeHost;
  let box: HTMLElement;
  let child: HTMLElement;
  let problems: ProblemsController;
  let errors: { detail: PhysicsErrorDetail; target: EventTarget | null; bubbles: boolean; composed: boolean }[];
  let warnings: string[];
  const warn = console.warn;
  const listener = (e: CustomEvent<PhysicsErrorDetail>) => errors.push({ detail: e.detail, target: e.target, bubbles: e.bubbles, composed: e.composed });

  beforeEach(() => {
    host = makeHost();
    box = document.createElement('div');
    box.hidden = true;
    child = document.createElement('physics-box');
    child.id = 'crate';
    host.append(child);
    document.body.append(host, box);
    problems = new ProblemsController(host, { box: () => box, elementOf: (key) => (key === 4 ? child : undefined) });
    errors = [];
    warnings = [];
    console.warn = (...args: unknown[]) => warnings.push(args.join(' '));
    document.addEventListener('physics-error', listener);
  });
  afterEach(() => {
    console.warn = warn;
    document.removeEventListener('physics-error', listener);
    host.remove();
    box.remove();
  });

  it('each problem: one physics-error on its element (bubbling, composed) and one warning, once while it lasts', () => {
    const width = { attribute: 'width', value: 'abc', message: 'must be a number' };
    const fill = { attribute: 'fill', value: 'mauve-ish', message: 'must be a CSS colour or "none"' };
    problems.set(child, child, [width, fill]);
    expect(errors.map((e) => [e.target, e.detail.element, e.detail.attribute, e.detail.value, e.bubbles, e.composed])).to.deep.equal([
      [child, child, 'width', 'abc', true, true],
      [child, child, 'fill', 'mauve-ish', true, true],
    ]);
    expect(warnings).to.deep.equal(['<physics-box id="crate"> width="abc": must be a number', '<physics-box id="crate"> fill="mauve-ish": must be a CSS colour or "none"']);
    // The same problems again (the element updated for another reason): nothing new.
    problems.set(child, child, [width, fill]);
    expect(errors.length).to.equal(2);
    // One fixed, one new value: only the new one is reported.
    problems.set(child, child, [{ ...width, value: 'xyz' }]);
    expect(errors.map((e) => e.detail.value)).to.deep.equal(['abc', 'mauve-ish', 'xyz']);
    expect(warnings.length).to.equal(3);
  });

  it('the error box lists every current problem; fixed ones and forgotten sources leave it', () => {
    problems.set('config', host, [{ attribute: 'gravity', value: 'down', message: 'must be a list of numbers' }]);
    problems.set(child, child, [{ attribute: 'height', value: '-1', message: 'must be a number > 0' }]);
    expect(box.hidden).to.equal(false);
    expect(box.textContent).to.equal('<x-fake-host> gravity="down": must be a list of numbers\n<physics-box id="crate"> height="-1": must be a number > 0');
    problems.set('config', host, []);
    expect(box.textContent).to.equal('<physics-box id="crate"> height="-1": must be a number > 0');
    problems.forget(child);
    expect(box.hidden).to.equal(true);
    expect(box.textContent).to.equal('');
    // Forgotten: the same problem is news again.
    problems.set(child, child, [{ attribute: 'height', value: '-1', message: 'must be a number > 0' }]);
    expect(errors.length).to.equal(3);
  });

  it('engine failures: reported on the scene, the latest five kept in the box; clear() empties it without reporting again', () => {
    for (let k = 1; k <= 7; k++) problems.report(host, '', '', `engine: failure ${k}`);
    expect(errors.length).to.equal(7);
    expect(errors.every((e) => e.target === host)).to.equal(true);
    expect(box.textContent!.split('\n')).to.deep.equal([3, 4, 5, 6, 7].map((k) => `<x-fake-host>: engine: failure ${k}`));
    problems.set('config', host, [{ attribute: 'width', value: '0', message: 'must be a number > 0' }]);
    problems.clear();
    expect(box.hidden).to.equal(true);
    expect(problems.lines).to.deep.equal([]);
    // Still the scene's problem after a restart: back in the box, not reported a second time.
    problems.set('config', host, [{ attribute: 'width', value: '0', message: 'must be a number > 0' }]);
    expect(problems.lines).to.deep.equal(['<x-fake-host> width="0": must be a number > 0']);
    expect(errors.length).to.equal(8);
  });

  it('refused descriptions are reported on the element of the key, naming the attribute behind the engine field', () => {
    child.setAttribute('x1', '3');
    problems.refused({ key: 4, field: 'from', message: 'rope ends must differ' });
    problems.refused({ key: 99, field: '', message: 'too many particles: the limit is 200000' });
    expect(errors.map((e) => [e.target, e.detail.attribute, e.detail.value, e.detail.message])).to.deep.equal([
      [child, 'x1', '3', 'rope ends must differ'],
      [host, '', '', 'too many particles: the limit is 200000'],
    ]);
    // An element no longer in the document: the event goes to the scene.
    child.remove();
    problems.report(child, 'width', '0', 'must be a number > 0', false);
    expect(errors[2].target).to.equal(host);
    expect(errors[2].detail.element).to.equal(child);
  });

  it("an element's refused description stays in the box until the element sends another one, or leaves", () => {
    child.setAttribute('density', '1e-20');
    problems.refused({ key: 4, field: 'density', message: 'mass must be at least 1e-12' });
    problems.refused({ key: 99, field: '', message: 'engine: failure' });
    expect(box.textContent!.split('\n')).to.deep.equal(['<physics-box id="crate"> density="1e-20": mass must be at least 1e-12', '<x-fake-host>: engine: failure']);
    // The same refusal again (a restarted engine): still one line.
    problems.refused({ key: 4, field: 'density', message: 'mass must be at least 1e-12' });
    expect(problems.lines.length).to.equal(2);
    // Fixed and sent again: the refusal leaves; the scene's own failure stays.
    child.setAttribute('density', '1');
    problems.resent(child);
    expect(problems.lines).to.deep.equal(['<x-fake-host>: engine: failure']);
    // Refused again, then removed from the scene: it leaves with the element.
    problems.refused({ key: 4, field: 'density', message: 'mass must be at least 1e-12' });
    expect(problems.lines.length).to.equal(2);
    problems.forget(child);
    expect(problems.lines).to.deep.equal(['<x-fake-host>: engine: failure']);
    expect(warnings.length).to.equal(4);
  });

  it('the box is filled when it appears (after an update), and a hostile value is shown escaped and cut', () => {
    const late = document.createElement('div');
    let rendered: HTMLElement | null = null;
    const p = new ProblemsController(host, { box: () => rendered, elementOf: () => undefined });
    p.set('config', host, [{ attribute: 'width', value: `\u202e${'9'.repeat(200)}`, message: 'must be a finite number' }]);
    rendered = late;
    host.update();
    expect(late.textContent).to.match(/^<x-fake-host> width="\\u202e9{119}… \(201 characters\)": must be a finite number$/);
    expect(late.hidden).to.equal(false);
  });
});
