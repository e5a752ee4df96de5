import { css } from 'lit';
import { property } from 'lit/decorators.js';
import { numberAttribute, type Problem } from './checks.js';
import { PhysicsSceneElement } from './physics-scene/physics-scene.js';

/**
 * What `<cloth-sim>` and `<ragdoll-sim>` share: a `<physics-scene>` whose bodies are generated, from a setup read off
 * its own attributes at each update, into a hidden part of its shadow root, so the page's markup stays one tag; the
 * setup's problems are reported like the scene's own.
 */
export abstract class PresetSceneElement<Setup extends { problems: Problem[] }> extends PhysicsSceneElement {
  static override styles = [
    PhysicsSceneElement.styles,
    css`
      .bodies {
        display: none;
      }
    `,
  ];

  /** World units down the view. Default 10. */
  @property({ type: Number, converter: numberAttribute }) override height = 10;

  /** The setup of the last update. */
  protected setup: Setup | null = null;

  /** Reads and checks the preset's attributes (problems listed, defaults used). */
  protected abstract readSetup(): Setup;

  protected override get bodyContainer(): ParentNode & Node {
    return (this.renderRoot?.querySelector('.bodies') as HTMLElement | null) ?? this.renderRoot ?? this;
  }

  protected override willUpdate(changed: Map<string, unknown>): void {
    super.willUpdate(changed);
    this.setup = this.readSetup();
  }

  protected override updated(changed: Map<string, unknown>): void {
    super.updated(changed);
    this.reportPresetProblems(this.setup?.problems ?? []);
  }
}
