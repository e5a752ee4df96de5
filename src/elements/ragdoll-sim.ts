import { html, nothing, type TemplateResult } from 'lit';
import { property } from 'lit/decorators.js';
import { ifDefined } from 'lit/directives/if-defined.js';
import { Checker, numberAttribute, type Problem } from './checks.js';
import { PresetSceneElement } from './preset-scene.js';
import type { PhysicsRagdollElement } from './physics-ragdoll.js';
import './physics-box.js';
import './physics-circle.js';
import './physics-ragdoll.js';

interface RagdollSetup {
  count: number;
  size: number;
  obstacles: 'stairs' | 'pegs' | 'none';
  respawn: boolean;
  stroke: string | undefined;
  obstacleFill: string | undefined;
  problems: Problem[];
}

/** Simulated seconds a ragdoll must lie still before it is put back at the top (with `respawn`). */
const REST_SECONDS = 1.5;

/**
 * Lit converter for `respawn`: a boolean attribute that is on by default, so "off" (or "false") turns it off; any other
 * value, or none, leaves it on (removing the attribute turns it on again).
 */
const respawnAttribute = {
  fromAttribute: (value: string | null): boolean => value === null || !['off', 'false'].includes(value.trim().toLowerCase()),
};

/**
 * Ragdolls tumbling down stairs or through pegs, ready to embed: one tag, no children. Limbs bend within angle limits;
 * grab a ragdoll to drag it and let go to throw it. A ragdoll that has come to rest is put back at the top (unless
 * `respawn="off"`), so the scene never goes still; rest is judged in simulated time, so `step(n)` on a paused scene
 * respawns as running would. Everything `<physics-scene>` has (attributes, methods, events, embedding behaviour) works
 * here too.
 *
 * @summary A ragdoll preset.
 *
 * @fires physics-ready - The engine runs and the ragdolls are loaded (detail: `{mode, transport}`).
 * @fires physics-error - A bad attribute value or a failing engine (detail: `{element, attribute, value, message}`); the scene keeps running with the default.
 *
 * @csspart stage - The box that holds the canvas.
 * @csspart canvas - The p5 canvas. A margin, border or padding given to it is allowed for: pointers and coordinates map to its content box.
 * @csspart status - The loading message.
 * @csspart error - The visible list of current problems.
 * @csspart play-button - The play control (reduced motion, or paused with Space).
 */
export class RagdollSimElement extends PresetSceneElement<RagdollSetup> {
  /** Number of ragdolls (whole number 1..12). Default 3. The first stand in view; the rest fall in from above. */
  @property({ type: Number, converter: numberAttribute }) count = 3;
  /** Height of a ragdoll in world units (> 0, at most 100). Default 1.6. */
  @property({ type: Number, converter: numberAttribute }) size = 1.6;
  /** What they fall over: "stairs" (default), "pegs" or "none". */
  @property() obstacles: 'stairs' | 'pegs' | 'none' = 'stairs';
  /**
   * Put a ragdoll back at the top once it has lain still for 1.5 s of simulated time. On by default (and with any
   * value but "off" or "false"); `respawn="off"` lets them lie.
   */
  @property({ converter: respawnAttribute }) respawn = true;
  /**
   * Ragdoll line colour (CSS colour, or "none": the ragdolls are not drawn). Default "#333a44", or "#d3d8e0" on a page
   * whose colour scheme is dark.
   */
  @property() stroke?: string;
  /** Obstacle fill colour (CSS colour, or "none": outlines only). Default "#8a8f98". */
  @property({ attribute: 'obstacle-fill' }) obstacleFill?: string;

  /** Ragdolls put back at the top so far. */
  respawned = 0;

  /** Per ragdoll: where it was last seen moving, and since when (simulated seconds) it has stayed there. */
  // Weak: a doll removed from the markup (count changed, re-rendered) must not stay alive through this table.
  private still = new WeakMap<Element, { x: number; y: number; since: number }>();

  constructor() {
    super();
    // Off the top steps with a push to the right and up, so they tumble down the stairs.
    this.addEventListener('physics-ready', () => {
      for (const doll of this.dolls()) this.push(doll);
    });
  }

  /** Rebuilds the scene at time 0 as a fresh load starts it: the dolls pushed off the top step, no respawns yet. */
  override async reset(): Promise<void> {
    await super.reset();
    this.respawned = 0;
    this.still = new WeakMap();
    for (const doll of this.dolls()) this.push(doll);
  }

  private dolls(): PhysicsRagdollElement[] {
    return Array.from(this.bodyContainer.querySelectorAll('physics-ragdoll'));
  }

  private push(doll: PhysicsRagdollElement): void {
    if (this.setup?.obstacles === 'stairs') doll.setVelocity(4.5, -2);
  }

  protected override get defaultLabel(): string {
    return 'Ragdoll simulation: drag a ragdoll and let go to throw it';
  }

  /**
   * Where ragdoll k starts (its pelvis): the first ones standing in view (on the top two steps, or in a row above the
   * pegs), so a paused scene shows them; the rest stacked above the view, falling in.
   */
  private spawnPoint(k: number, s: RagdollSetup): { x: number; y: number } {
    const { width: w, height: h } = this.view;
    if (s.obstacles === 'stairs') {
      const step = k % 2;
      const stepW = (w * 0.85) / 6;
      const stepTop = h * 0.3 + step * ((h * 0.62) / 6);
      return { x: stepW * (0.45 + step), y: stepTop - s.size * 0.62 - 1.3 * s.size * Math.floor(k / 2) };
    }
    return { x: w * (0.12 + 0.76 * ((k * 0.618 + 0.2) % 1)), y: s.size * 0.7 - 1.3 * s.size * Math.floor(k / 4) };
  }

  protected override renderBodies(): TemplateResult | typeof nothing {
    const s = this.setup ?? this.readSetup();
    const { width: w, height: h } = this.view;
    const obstacles: TemplateResult[] = [];
    if (s.obstacles === 'stairs') {
      // Steps going down from the top left to the bottom right.
      const n = 6;
      const stepW = (w * 0.85) / n;
      const top = h * 0.3;
      const rise = (h * 0.62) / n;
      for (let k = 0; k < n; k++) {
        const stepTop = top + k * rise;
        const height = h - stepTop;
        obstacles.push(html`<physics-box static x=${stepW * (k + 0.5)} y=${stepTop + height / 2} width=${stepW} height=${height} fill=${ifDefined(s.obstacleFill)}></physics-box>`);
      }
    } else if (s.obstacles === 'pegs') {
      const cols = 7;
      const gap = w / cols;
      for (let row = 0; row < 4; row++) {
        for (let c = 0; c < cols; c++) {
          const x = gap * (c + 0.5 + (row % 2 ? 0.5 : 0));
          if (x > w - gap * 0.3) continue;
          obstacles.push(html`<physics-circle static x=${x} y=${h * (0.3 + row * 0.16)} radius=${Math.min(0.35, gap * 0.15)} fill=${ifDefined(s.obstacleFill)}></physics-circle>`);
        }
      }
    }
    const dolls: TemplateResult[] = [];
    for (let k = 0; k < s.count; k++) {
      const p = this.spawnPoint(k, s);
      dolls.push(html`<physics-ragdoll x=${p.x} y=${p.y} height=${s.size} stroke=${ifDefined(s.stroke)}></physics-ragdoll>`);
    }
    return html`<div class="bodies">${obstacles}${dolls}</div>`;
  }

  protected override ticks(setup: RagdollSetup): boolean {
    return setup.respawn;
  }

  /**
   * Ragdolls that lay still for REST_SECONDS go back to their spawn point, and are pushed again once the engine has
   * their new description.
   */
  protected override async tick(seconds: number): Promise<void> {
    const s = this.setup;
    if (!s?.respawn) return;
    const moved: Promise<void>[] = [];
    this.dolls().forEach((doll, k) => {
      const pose = this.poseOf(doll);
      if (!pose) return; // not simulated yet, or being rebuilt
      const [x, y] = pose;
      const prev = this.still.get(doll);
      if (!prev || seconds < prev.since || Math.hypot(x - prev.x, y - prev.y) > s.size * 0.03) {
        this.still.set(doll, { x, y, since: seconds });
        return;
      }
      if (seconds - prev.since < REST_SECONDS) return;
      const p = this.spawnPoint(k, s);
      this.respawned++;
      // A tiny offset per respawn makes the description differ from the last one sent, so the body is rebuilt.
      doll.x = p.x + (this.respawned % 2 ? 1e-3 : -1e-3);
      doll.y = p.y;
      this.still.delete(doll);
      moved.push(doll.updateComplete.then(() => this.push(doll)));
    });
    await Promise.all(moved);
  }

  protected override readSetup(): RagdollSetup {
    const check = new Checker(this);
    const count = check.number('count', this.count, { integer: true, min: 1, max: 12, fallback: 3 })!;
    const size = check.number('size', this.size, { positive: true, max: 100, fallback: 1.6 })!;
    const obstacles = check.oneOf('obstacles', this.obstacles, ['stairs', 'pegs', 'none'] as const, 'stairs');
    // "none" is passed on as written (the check reads it as null, which meant the default here: drawn all the same).
    const stroke = check.colorOrNone('stroke', this.stroke);
    const obstacleFill = check.colorOrNone('obstacle-fill', this.obstacleFill);
    return { count, size, obstacles, respawn: this.respawn, stroke, obstacleFill, problems: check.problems };
  }
}

if (!customElements.get('ragdoll-sim')) customElements.define('ragdoll-sim', RagdollSimElement);

declare global {
  interface HTMLElementTagNameMap {
    'ragdoll-sim': RagdollSimElement;
  }
}
