// The stage on its own, with a fake renderer: the view follows each update (also for a renderer made later), looping
// and styles pass through, and coordinates are NaN without a canvas.
import { expect } from '@open-wc/testing';
import { StageController, type Renderer, type StageView } from '../../../src/elements/physics-scene/stage.js';
import type { BodyStyle } from '../../../src/render/renderer.js';
import { makeHost } from './fakes.js';

class FakeRenderer implements Renderer {
  viewWidth = 16;
  viewHeight = 9;
  background = '';
  debug = false;
  drawMode: 'over' | 'replace' = 'over';
  hook = null;
  drawn = 3;
  canvas: HTMLCanvasElement | null = null;
  looping: boolean[] = [];
  styles = new Map<number, BodyStyle>();
  disposed = false;
  setLooping(on: boolean): void {
    this.looping.push(on);
  }
  setStyle(key: number, style: BodyStyle): void {
    this.styles.set(key, style);
  }
  deleteStyle(key: number): void {
    this.styles.delete(key);
  }
  worldToCanvas(x: number, y: number) {
    return { x: x * 10, y: y * 10 };
  }
  canvasToWorld(x: number, y: number) {
    return { x: x / 10, y: y / 10 };
  }
  dispose(): void {
    this.disposed = true;
  }
}

describe('StageController', () => {
  it('the view follows each update, also into a renderer made later; looping and styles pass through; close disposes', () => {
    const host = makeHost();
    let view: StageView = { width: 10, height: 5, background: '#ffffff', debug: false, drawMode: 'over', hook: null };
    const made: FakeRenderer[] = [];
    const stage = new StageController(host, { source: () => null, view: () => view, create: () => (made[made.length] = new FakeRenderer()) });
    expect([stage.drawn, stage.canvas]).to.deep.equal([0, null]);
    // No renderer yet: nothing to do, nothing breaks.
    host.update();
    stage.setLooping(true);
    stage.setStyle(1, { fill: 'red', stroke: null, lineWidth: 1 });
    view = { ...view, width: 20, debug: true, drawMode: 'replace' };
    stage.open(document.createElement('div'), false);
    const [r] = made;
    expect([r.viewWidth, r.viewHeight, r.background, r.debug, r.drawMode]).to.deep.equal([20, 5, '#ffffff', true, 'replace']);
    expect(r.looping).to.deep.equal([false]);
    view = { ...view, background: 'transparent' };
    host.update();
    expect(r.background).to.equal('transparent');
    stage.setLooping(true);
    stage.setStyle(2, { fill: null, stroke: 'blue', lineWidth: 1.5 });
    stage.deleteStyle(3);
    expect(r.looping).to.deep.equal([false, true]);
    expect([...r.styles.keys()]).to.deep.equal([2]);
    expect(stage.drawn).to.equal(3);
    stage.close();
    expect(r.disposed).to.equal(true);
    expect(stage.drawn).to.equal(0);
  });

  it('maps world and viewport through the canvas box; NaN without a canvas', () => {
    const host = makeHost();
    const stage = new StageController(host, { source: () => null, view: () => ({ width: 10, height: 5, background: '', debug: false, drawMode: 'over', hook: null }), create: () => renderer });
    const renderer = new FakeRenderer();
    expect(stage.worldToClient(1, 1).x).to.be.NaN;
    stage.open(document.createElement('div'), true);
    expect(stage.clientToWorld(1, 1).y).to.be.NaN;
    const canvas = document.createElement('canvas');
    canvas.style.cssText = 'position: fixed; left: 30px; top: 40px; width: 100px; height: 50px';
    document.body.append(canvas);
    renderer.canvas = canvas;
    try {
      expect(stage.worldToClient(2, 1)).to.deep.equal({ x: 50, y: 50 });
      expect(stage.clientToWorld(50, 50)).to.deep.equal({ x: 2, y: 1 });
    } finally {
      canvas.remove();
    }
  });

  it('refuses coordinates that are not finite numbers, naming the method and the argument (with a canvas or without)', () => {
    const host = makeHost();
    const renderer = new FakeRenderer();
    const stage = new StageController(host, { source: () => null, view: () => ({ width: 10, height: 5, background: '', debug: false, drawMode: 'over', hook: null }), create: () => renderer });
    const calls: [string, (x: number, y: number) => unknown][] = [
      ['worldToClient', (x, y) => stage.worldToClient(x, y)],
      ['clientToWorld', (x, y) => stage.clientToWorld(x, y)],
    ];
    const canvas = document.createElement('canvas');
    for (const withCanvas of [false, true]) {
      if (withCanvas) {
        stage.open(document.createElement('div'), true);
        document.body.append(canvas);
        renderer.canvas = canvas;
      }
      try {
        for (const [name, call] of calls) {
          const bad: [unknown[], ErrorConstructor, string][] = [
            [['a', 1], TypeError, `${name}(x, y): x must be a number, got "a"`],
            [[1, '2'], TypeError, `${name}(x, y): y must be a number, got "2"`],
            [[], TypeError, `${name}(x, y): x must be a number, got undefined`],
            [[1], TypeError, `${name}(x, y): y must be a number, got undefined`],
            [[NaN, 1], RangeError, `${name}(x, y): x must be a finite number, got NaN`],
            [[1, -Infinity], RangeError, `${name}(x, y): y must be a finite number, got -Infinity`],
          ];
          for (const [args, type, message] of bad) {
            expect(() => (call as (...a: unknown[]) => unknown)(...args), `${name}(${args.map(String)})`).to.throw(type, message);
          }
        }
      } finally {
        canvas.remove();
      }
    }
  });
});
