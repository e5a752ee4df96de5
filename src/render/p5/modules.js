// The p5 the renderer ships: p5 2.x's core (the sketch, its loop, the 2D renderer, transforms) and the addons a draw
// hook can count on (docs/drawing.md): shape (circle, rect, line, beginShape…), colour (fill, stroke, color…) and math
// (random, noise, map, createVector…; shape's circle and ellipse need p5.Vector). Not loaded: events (mouseX, keyIsDown:
// the element handles pointer and keys itself), typography, image, io, dom, data, webgl, accessibility, friendly errors.
// Bundled by bundle.mjs into one ES module whose default export is p5; builds alias the bare specifier 'p5' to it.
import p5 from 'p5/core';
import shape from 'p5/shape';
import color from 'p5/color';
import math from 'p5/math';

p5.registerAddon(shape);
p5.registerAddon(color);
p5.registerAddon(math);
// Without the accessibility addon, p5 2.3's resizeCanvas() (and createCanvas' set-up) call this._addAccsOutput()
// unguarded and throw: answer "no accessible outputs", which is what it answers when none are asked for.
p5.registerAddon((_p5, fn) => {
  fn._addAccsOutput ??= function () {
    return false;
  };
});

export default p5;
