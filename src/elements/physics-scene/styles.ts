// The styles of <physics-scene> (and of the presets built on it).
//
// The box: a block as wide as its container (300 px where the layout sizes it by its content: .sizer), `aspect-ratio`
// from the view (width / height) unless CSS gives it a height, overflow hidden. A page reserves the same box before the
// script has run with the snippet's inline style (style="display:block;aspect-ratio:16/9" for a default scene, 16/10
// for the presets; overflow:hidden too when the tag holds fallback content), which wins over these styles once
// defined, so nothing moves when the element upgrades (scripts/measure-loading.mjs: layout shift 0 with it, 0.13
// desktop / 0.16 phone without). Colours: each light one is followed by its light-dark() pair (ignored by browsers
// without it), so the messages and the rings follow the page's colour scheme as the canvas does (scheme.ts). Touch:
// panning and pinch-zoom stay the page's (pointer.ts decides which touches drag).
import { css } from 'lit';
import { schemeProbeStyles } from './scheme.js';

// The rules, and why (here, not in the stylesheet, whose comments would ship in every build):
// - :host: min-width 0, as a flex row may shrink it below the sizer's width (as it shrinks text).
// - .stage: direction and writing-mode, as the canvas's corner markers (stage.ts) sit at their static position, which
//   a right-to-left or vertical page would move to the other side.
// - .sizer: the only child in flow: the box's width where the layout asks for one from the content (a flex row, an
//   inline-block, a float, an auto grid column): 300 px as a canvas or a video would have, or the container's width
//   when narrower; no height. Elsewhere a block fills its container and this changes nothing.
// - .fallback: under the stage: seen until the canvas draws its first frame over it, hidden once the scene is ready.
// - .error: at the top, where a scene is mostly empty (bodies fall and rest on a floor at the bottom); opaque, and at
//   least about five lines tall in a small scene (a phone's), so the list reads over a busy scene and scrolls past
//   them. Its background: a shade along the bottom edge while more lines are below (the cover, attached to the
//   content, hides it at the end): a scrolling list shows that it scrolls.
// - .play: a dark disc on a light canvas, a light one on a dark canvas (the page's dark scheme).
// - slot: body and link elements (the default slot) are never shown; fallback elements keep their own display.
/** @internal */
export const sceneStyles = css`
  :host {
    display: block;
    position: relative;
    aspect-ratio: var(--physics-scene-aspect, var(--physics-scene-view-aspect, 16 / 9));
    overflow: hidden;
    touch-action: manipulation;
    user-select: none;
    -webkit-user-select: none;
    contain: layout paint;
    min-width: 0;
  }
  :host([hidden]) {
    display: none;
  }
  :host(:focus-visible) {
    outline: 2px solid #2f6fb5;
    outline-color: light-dark(#2f6fb5, #7fb0ee);
    outline-offset: 2px;
  }
  .stage {
    position: absolute;
    inset: 0;
    direction: ltr;
    writing-mode: horizontal-tb;
  }
  .sizer {
    width: 300px;
    max-width: 100%;
    height: 0;
  }
  .fallback {
    position: absolute;
    inset: 0;
    overflow: hidden;
  }
  .fallback[hidden],
  .ring[hidden] {
    display: none;
  }
  .ring {
    position: absolute;
    box-sizing: border-box;
    border: 2px solid #2f6fb5;
    border-color: light-dark(#2f6fb5, #7fb0ee);
    border-radius: 6px;
    box-shadow: 0 0 0 2px #ffffffcc;
    pointer-events: none;
  }
  .announcer {
    position: absolute;
    width: 1px;
    height: 1px;
    overflow: hidden;
    clip-path: inset(50%);
    white-space: nowrap;
  }
  .status {
    position: absolute;
    inset: 0;
    display: flex;
    align-items: center;
    justify-content: center;
    font: 14px/1.3 system-ui, sans-serif;
    color: #5b6270;
    color: light-dark(#5b6270, #aeb5c0);
    pointer-events: none;
  }
  .error[hidden] {
    display: none;
  }
  .error {
    position: absolute;
    left: 6px;
    right: 6px;
    top: 6px;
    max-height: min(max(45%, 7.5em), calc(100% - 12px));
    overflow: auto;
    overscroll-behavior: contain;
    padding: 4px 8px;
    border: 1px solid #e0a090;
    border-color: light-dark(#e0a090, #9a5447);
    border-radius: 4px;
    --error-paper: #fff3ef;
    --error-paper: light-dark(#fff3ef, #3a1e1a);
    background:
      linear-gradient(transparent, var(--error-paper) 70%) center bottom / 100% 1.6em no-repeat local,
      radial-gradient(farthest-side at 50% 100%, #8a1c0c55, transparent) center bottom / 100% 0.7em no-repeat scroll,
      var(--error-paper);
    color: #8a1c0c;
    color: light-dark(#8a1c0c, #ffc4b8);
    font: 12px/1.35 system-ui, sans-serif;
    white-space: pre-wrap;
    overflow-wrap: anywhere;
  }
  .play {
    position: absolute;
    left: 50%;
    top: 50%;
    width: 56px;
    height: 56px;
    margin: -28px 0 0 -28px;
    border: 0;
    border-radius: 50%;
    background: #14181ebb;
    background: light-dark(#14181ebb, #eef1f5dd);
    color: #fff;
    color: light-dark(#fff, #14181e);
    font: 22px/56px system-ui, sans-serif;
    cursor: pointer;
    padding: 0 0 0 4px;
  }
  .play:focus-visible {
    outline: 3px solid;
    outline-offset: -6px;
  }
  ${schemeProbeStyles}
  slot:not([name])::slotted(*) {
    display: none;
  }
`;
