import { html, nothing, type TemplateResult } from 'lit';
import { property } from 'lit/decorators.js';
import { ifDefined } from 'lit/directives/if-defined.js';
import { Checker, numberAttribute, type ClothPinsAttribute, type Problem } from './checks.js';
import { PresetSceneElement } from './preset-scene.js';
import './physics-cloth.js';

interface ClothSetup {
  columns: number;
  rows: number;
  spacing: number;
  x: number;
  y: number;
  pins: string;
  compliance: number;
  wind: number;
  gusts: number;
  tear: number | undefined;
  fill: string | undefined;
  stroke: string | undefined;
  problems: Problem[];
}

/**
 * A cloth hanging from pins, ready to embed: one tag, no children. Drag it to pull. A gentle gusty breeze sways it by
 * default (`wind`, `gusts`; `wind="0"` for still air); the gusts follow simulated time, so `step(n)` on a paused cloth
 * blows it as running would.
 * Everything `<physics-scene>` has (attributes, methods, events, embedding behaviour) works here too; the cloth is
 * generated inside the shadow root, so the page's markup stays one tag.
 *
 * @summary A hanging cloth preset.
 *
 * @fires physics-ready - The engine runs and the cloth is loaded (detail: `{mode, transport}`).
 * @fires physics-error - A bad attribute value or a failing engine (detail: `{element, attribute, value, message}`); the cloth keeps running with the default.
 *
 * @csspart stage - The box that holds the canvas.
 * @csspart canvas - The p5 canvas. A margin, border or padding given to it is allowed for: pointers and coordinates map to its content box.
 * @csspart status - The loading message.
 * @csspart error - The visible list of current problems.
 * @csspart play-button - The play control (reduced motion, or paused with Space).
 */
export class ClothSimElement extends PresetSceneElement<ClothSetup> {
  /** Particles across (whole number 2..200). Default 24. */
  @property({ type: Number, converter: numberAttribute }) columns = 24;
  /** Particles down (whole number 2..200). Default 16. */
  @property({ type: Number, converter: numberAttribute }) rows = 16;
  /** Distance between neighbouring particles in world units (> 0, at most 100); default: the cloth spans about 70% of the view. */
  @property({ type: Number, converter: numberAttribute }) spacing?: number;
  /** Pinned top-row particles: "top", "corners", "none" or column indices ("0 8 16 23"). Default: five pins spread along the top. */
  @property() pins?: ClothPinsAttribute;
  /** 0 < stiffness <= 1: 1 (default) is inextensible, smaller values stretch. */
  @property({ type: Number, converter: numberAttribute }) stiffness = 1;
  /**
   * Wind: horizontal push in world units / s² (-1000..1000; negative blows left). Default 1.5, a gentle breeze that
   * with the default gusts keeps the cloth swaying; 0 is still air.
   */
  @property({ type: Number, converter: numberAttribute }) wind = 1.5;
  /** How gusty the wind is, in [0, 1]: 0 is steady, 1 gusts from calm to twice the strength. Default 0.6. */
  @property({ type: Number, converter: numberAttribute }) gusts = 0.6;
  /**
   * Tearing: a link stretched past its rest length by this fraction breaks (> 0; 0.3 tears under a firm pull). Off by
   * default. A torn cloth stays torn until reset() or a change of its attributes rebuilds it.
   */
  @property({ type: Number, converter: numberAttribute }) tear?: number;
  /** Cloth fill colour (CSS colour or "none"). Default "#9cc3ec". */
  @property() fill?: string;
  /** Cloth line colour (CSS colour or "none"). Default "#2f6fb5". */
  @property() stroke?: string;

  constructor() {
    super();
  }

  protected override get defaultLabel(): string {
    return 'Cloth simulation: drag the cloth to pull it';
  }

  /** Rebuilds the scene at time 0 as a fresh load starts it: in the wind of time 0, not of the last gust. */
  override async reset(): Promise<void> {
    this.tick(0);
    await super.reset();
  }

  protected override updated(changed: Map<string, unknown>): void {
    super.updated(changed);
    // Wind 0 turns the ticks off: the push must go now, not at the next tick.
    if (changed.has('wind') || changed.has('gusts')) this.tick(this.seconds);
  }

  protected override renderBodies(): TemplateResult | typeof nothing {
    const s = this.setup ?? this.readSetup();
    return html`<div class="bodies">
      <physics-cloth
        x=${s.x}
        y=${s.y}
        columns=${s.columns}
        rows=${s.rows}
        spacing=${s.spacing}
        pins=${s.pins}
        compliance=${s.compliance}
        tear=${ifDefined(s.tear)}
        fill=${ifDefined(s.fill)}
        stroke=${ifDefined(s.stroke)}
      ></physics-cloth>
    </div>`;
  }

  protected override ticks(setup: ClothSetup): boolean {
    return setup.wind !== 0;
  }

  /** The wind at simulated time `seconds`: the steady strength scaled by a smooth gust factor in [1 − gusts, 1 + gusts]. */
  protected override tick(seconds: number): void {
    const s = this.setup;
    if (!s) return;
    const t = seconds;
    const n = (Math.sin(t * 1.7) + 0.6 * Math.sin(t * 4.3 + 1.1) + 0.4 * Math.sin(t * 9.1 + 2.3)) / 2;
    this.setGravityOffset(s.wind * (1 + s.gusts * n), 0);
  }

  protected override readSetup(): ClothSetup {
    const check = new Checker(this);
    const columns = check.number('columns', this.columns, { integer: true, min: 2, max: 200, fallback: 24 })!;
    const rows = check.number('rows', this.rows, { integer: true, min: 2, max: 200, fallback: 16 })!;
    const { width: w, height: h } = this.view;
    const auto = Math.min((w * 0.7) / (columns - 1), (h * 0.75) / (rows - 1));
    const spacing = check.number('spacing', this.spacing, { positive: true, max: 100, fallback: auto })!;
    const spread = [...new Set([0, 1, 2, 3, 4].map((k) => Math.round((k * (columns - 1)) / 4)))].join(' ');
    // Not written (or blank): the spread; a bad value is reported and falls back to it.
    const chosen = (this.pins ?? '').trim() === '' ? null : check.pins(this.pins, columns);
    const pins = chosen === null ? spread : Array.isArray(chosen) ? chosen.join(' ') : chosen;
    // From 1e-15: the compliance it gives stays within the engine's 1e9.
    const stiffness = check.number('stiffness', this.stiffness, { min: 1e-15, max: 1, fallback: 1 })!;
    // XPBD compliance (inverse stiffness): 0 at stiffness 1, about 1e-5 at 0.1.
    const compliance = ((1 - stiffness) / stiffness) * 1e-6;
    const wind = check.number('wind', this.wind, { min: -1000, max: 1000, fallback: 1.5 })!;
    const gusts = check.number('gusts', this.gusts, { min: 0, max: 1, fallback: 0.6 })!;
    const tear = check.number('tear', this.tear, { positive: true });
    const fill = check.colorOrNone('fill', this.fill);
    const stroke = check.colorOrNone('stroke', this.stroke);
    const x = (w - spacing * (columns - 1)) / 2;
    const y = Math.min(h * 0.08, 0.8);
    return { columns, rows, spacing, x, y, pins, compliance, wind, gusts, tear, fill, stroke, problems: check.problems };
  }
}

if (!customElements.get('cloth-sim')) customElements.define('cloth-sim', ClothSimElement);

declare global {
  interface HTMLElementTagNameMap {
    'cloth-sim': ClothSimElement;
  }
}
