// The p5 the builds ship (src/render/p5/modules.js, bundled and trimmed by src/render/p5/bundle.mjs and
// scripts/build/p5-trim.mjs): every function docs/drawing.md promises a draw hook exists and draws what it should,
// checked by reading pixels back; what the page says is left out is absent or throws a clear error.
import { expect } from '@open-wc/testing';
import p5 from 'p5';

type P = InstanceType<typeof p5> & Record<string, any>;

/** A 100 × 100 sketch at pixel density 1, not looping; resolves once setup ran. */
function sketch(box: HTMLElement): Promise<P> {
  return new Promise((resolve) => {
    new p5((p: P) => {
      p.setup = () => {
        p.pixelDensity(1);
        p.createCanvas(100, 100);
        p.noLoop();
        resolve(p);
      };
    }, box);
  });
}

/** The pixel at (x, y) of a 2D context, as [r, g, b, a]. */
function pixel(ctx: CanvasRenderingContext2D, x: number, y: number): number[] {
  return [...ctx.getImageData(x, y, 1, 1).data];
}

describe('p5 as the builds ship it', () => {
  let box: HTMLDivElement;
  let p: P;
  beforeEach(async () => {
    box = document.createElement('div');
    document.body.append(box);
    p = await sketch(box);
  });
  afterEach(() => {
    p.remove();
    box.remove();
  });

  it('has every function docs/drawing.md lists for a draw hook', () => {
    const listed = [
      // core
      'noLoop', 'loop', 'redraw', 'createCanvas', 'resizeCanvas', 'pixelDensity', 'push', 'pop', 'translate', 'rotate',
      'scale', 'applyMatrix', 'resetMatrix', 'createGraphics', 'blendMode', 'erase', 'noErase',
      // shape
      'point', 'line', 'rect', 'square', 'circle', 'ellipse', 'arc', 'quad', 'triangle', 'bezier', 'beginShape',
      'vertex', 'endShape', 'strokeWeight', 'strokeCap', 'strokeJoin', 'rectMode', 'ellipseMode',
      // colour
      'fill', 'noFill', 'stroke', 'noStroke', 'background', 'clear', 'color', 'lerpColor', 'colorMode', 'red', 'green',
      'blue', 'alpha', 'hue', 'saturation', 'brightness',
      // math
      'random', 'randomSeed', 'noise', 'noiseSeed', 'map', 'constrain', 'lerp', 'dist', 'mag', 'norm', 'sq', 'sin',
      'cos', 'angleMode', 'createVector',
    ];
    expect(listed.filter((name) => typeof p[name] !== 'function')).to.deep.equal([]);
    expect(p.width).to.equal(100);
    expect(p.height).to.equal(100);
    expect(p.drawingContext).to.be.instanceOf(CanvasRenderingContext2D);
    expect(typeof p.frameCount).to.equal('number');
  });

  it('draws shapes in the colours asked for', () => {
    const ctx = p.drawingContext as CanvasRenderingContext2D;
    p.background(255, 0, 0);
    p.noStroke();
    p.fill('#0000ff');
    p.circle(25, 25, 20);
    p.fill(p.color(0, 255, 0));
    p.rect(60, 10, 30, 30);
    p.fill(255, 255, 0);
    p.beginShape();
    p.vertex(10, 60);
    p.vertex(40, 60);
    p.vertex(40, 90);
    p.vertex(10, 90);
    p.endShape(p.CLOSE);
    p.stroke(0);
    p.strokeWeight(6);
    p.line(60, 75, 95, 75);
    expect(pixel(ctx, 25, 25)).to.deep.equal([0, 0, 255, 255]); // inside the circle
    expect(pixel(ctx, 25, 40)).to.deep.equal([255, 0, 0, 255]); // below it: background
    expect(pixel(ctx, 75, 25)).to.deep.equal([0, 255, 0, 255]);
    expect(pixel(ctx, 25, 75)).to.deep.equal([255, 255, 0, 255]);
    expect(pixel(ctx, 78, 75)).to.deep.equal([0, 0, 0, 255]); // on the line
    expect(pixel(ctx, 78, 85)).to.deep.equal([255, 0, 0, 255]); // beside it
  });

  it('maps a colour outside sRGB into the canvas gamut (colorjs.io gamut mapping)', () => {
    const ctx = p.drawingContext as CanvasRenderingContext2D;
    p.colorMode(p.OKLCH);
    // p5's OKLCH chroma 100 is colorjs.io's 0.267: just outside sRGB, whose red is oklch(0.628 0.258 29.2). The gamut
    // mapping (CSS's, the default) lowers the chroma until the colour fits: sRGB's red, as with p5 untrimmed.
    p.background(63, 100, 29);
    expect(pixel(ctx, 50, 50)).to.deep.equal([255, 0, 0, 255]);
    p.background(63, 40, 29); // inside sRGB: not mapped, a duller red
    const [r, g, b] = pixel(ctx, 50, 50);
    expect(r).to.be.within(150, 254);
    expect(g).to.be.within(40, 120);
    expect(b).to.be.within(40, 120);
  });

  it('transforms: translate, rotate, scale, push and pop', () => {
    const ctx = p.drawingContext as CanvasRenderingContext2D;
    p.background(255);
    p.noStroke();
    p.fill(0);
    p.push();
    p.translate(50, 50);
    p.angleMode(p.DEGREES);
    p.rotate(90);
    p.scale(2);
    p.rect(0, 0, 10, 5); // after the rotation: x 40..50, y 50..70
    p.pop();
    p.rect(0, 0, 4, 4); // after pop: the identity again
    expect(pixel(ctx, 45, 60)).to.deep.equal([0, 0, 0, 255]);
    expect(pixel(ctx, 55, 60)).to.deep.equal([255, 255, 255, 255]);
    expect(pixel(ctx, 2, 2)).to.deep.equal([0, 0, 0, 255]);
    expect(pixel(ctx, 6, 6)).to.deep.equal([255, 255, 255, 255]);
  });

  it('colour and math helpers give the numbers they document', () => {
    const c = p.lerpColor(p.color(0, 0, 0), p.color(200, 100, 50), 0.5);
    expect([p.red(c), p.green(c), p.blue(c), p.alpha(c)]).to.deep.equal([100, 50, 25, 255]);
    const crimson = p.color('crimson');
    expect([p.red(crimson), p.green(crimson), p.blue(crimson)]).to.deep.equal([220, 20, 60]);
    p.colorMode(p.HSB);
    const hsb = p.color(240, 100, 100);
    p.colorMode(p.RGB);
    expect([p.red(hsb), p.green(hsb), p.blue(hsb)].map(Math.round)).to.deep.equal([0, 0, 255]);
    expect(p.map(5, 0, 10, 100, 200)).to.equal(150);
    expect(p.constrain(12, 0, 10)).to.equal(10);
    expect(p.lerp(2, 4, 0.25)).to.equal(2.5);
    expect(p.dist(0, 0, 3, 4)).to.equal(5);
    expect(p.mag(3, 4)).to.equal(5);
    expect(p.sq(7)).to.equal(49);
    const v = p.createVector(3, 4);
    expect(v.mag()).to.equal(5);
    p.randomSeed(7);
    const a = [p.random(), p.random()];
    p.randomSeed(7);
    expect([p.random(), p.random()]).to.deep.equal(a);
    p.noiseSeed(3);
    const n = p.noise(0.5, 0.25);
    expect(n).to.be.within(0, 1);
    p.noiseSeed(3);
    expect(p.noise(0.5, 0.25)).to.equal(n);
  });

  it('createGraphics draws off screen; the hook puts it on the canvas with the 2D context', () => {
    const ctx = p.drawingContext as CanvasRenderingContext2D;
    const g = p.createGraphics(20, 20) as P;
    g.pixelDensity(1);
    g.background(0, 128, 255);
    g.noStroke();
    g.fill(255);
    g.circle(10, 10, 8);
    p.background(0);
    ctx.drawImage(g.elt as HTMLCanvasElement, 40, 40);
    expect(pixel(ctx, 50, 50)).to.deep.equal([255, 255, 255, 255]);
    expect(pixel(ctx, 41, 41)).to.deep.equal([0, 128, 255, 255]);
    expect(pixel(ctx, 30, 30)).to.deep.equal([0, 0, 0, 255]);
    g.remove();
  });

  it('resizeCanvas and redraw work (the renderer uses both)', async () => {
    let draws = 0;
    p.draw = () => void draws++;
    p.resizeCanvas(60, 40, true);
    expect([p.width, p.height]).to.deep.equal([60, 40]);
    expect((p.drawingContext as CanvasRenderingContext2D).canvas.width).to.equal(60);
    await p.redraw();
    const before = draws;
    expect(before).to.be.greaterThan(0);
    await p.redraw(2);
    expect(draws).to.equal(before + 2);
  });

  it('leaves out what docs/drawing.md says is not loaded, with clear errors where p5 reaches it', () => {
    for (const name of ['text', 'image', 'loadImage', 'filter', 'loadPixels', 'describe', 'model', 'box', 'mouseIsPressed']) {
      expect(typeof p[name], name).to.equal('undefined');
    }
    expect(() => p.createFramebuffer()).to.throw(/WebGL/);
    const g = p.createGraphics(10, 10) as P;
    expect(() => g.createFramebuffer()).to.throw(/WebGL/);
    expect(typeof g.image).to.equal('undefined');
    g.remove();
    // p5.Image stays in the core (the 2D renderer's get() makes one) but its CPU filters are a stand-in.
    const region = (p as unknown as { _renderer: { get(x: number, y: number, w: number, h: number): { filter(op: string): void } } })._renderer.get(0, 0, 2, 2);
    expect(() => region.filter('invert')).to.throw(/image addon/);
  });
});
