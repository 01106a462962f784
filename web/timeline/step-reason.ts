/**
 * The current step's reason under the timeline: the core's one-sentence
 * explanation of the step that produced the point shown (for each path, in
 * compare mode). It is the inspector's sentence, put where it stays in sight
 * with the view and the timeline when the inspector is not: in a medium or
 * narrow window, in compare mode (whose table tops the inspector) and in an
 * embedded view. The stylesheet decides where it shows; the worker is asked
 * only while it does, for the latest point only.
 */
import { element } from '../form/options-form.js';
import { afterNextFrame } from '../main-thread.js';
import { CoreCrash, type RemoteTrace } from '../worker/client.js';

export class StepReason {
  readonly #element: HTMLElement;
  #traces: RemoteTrace[] = [];
  /** The point the line should explain, and the one it explains (undefined: none yet for these traces). */
  #wantedPointIndex = 0;
  #shownPointIndex: number | undefined;
  #fetching = false;
  /** Resolves once the current traces' first frame is drawn. */
  #drawn: Promise<void> = Promise.resolve();

  constructor(container: HTMLElement) {
    this.#element = container;
    // Shown after being hidden (a narrower window, another mode): explain what is there now.
    new ResizeObserver(() => this.#update()).observe(container);
  }

  /** The traces to explain (one, or the compared pair; undefined ones left out) and the point shown. */
  setTraces(traces: readonly (RemoteTrace | undefined)[], pointIndex: number): void {
    this.#traces = traces.filter((t) => t !== undefined);
    this.#shownPointIndex = undefined;
    this.#element.replaceChildren();
    this.#drawn = afterNextFrame();
    this.show(pointIndex);
  }

  /** Explains point index `pointIndex`: the step that produced it. */
  show(pointIndex: number): void {
    this.#wantedPointIndex = pointIndex;
    this.#update();
  }

  #update(): void {
    if (!this.#fetching && this.#element.checkVisibility()) void this.#fetch();
  }

  async #fetch(): Promise<void> {
    this.#fetching = true;
    try {
      await this.#drawn;
      while (this.#traces.length > 0 && this.#shownPointIndex !== this.#wantedPointIndex && this.#element.checkVisibility()) {
        const traces = this.#traces;
        const pointIndex = this.#wantedPointIndex;
        // At the start point there is nothing to explain, for either path.
        const explained = pointIndex === 0 ? [] : traces;
        const sentences = await Promise.all(explained.map((t) => (pointIndex > t.steps ? `its path ended at step ${t.steps}.` : t.stepDetail(pointIndex).then((d) => d.explanation ?? ''))));
        if (traces !== this.#traces) continue;
        const lines = explained.map((t, i) => {
          const label = traces.length > 1 ? `${t.algorithm}, step ${pointIndex}: ` : `Step ${pointIndex}: `;
          return element('span', { className: 'reason' }, element('strong', { textContent: label }), sentences[i]!);
        });
        if (pointIndex === 0) lines.push(element('span', { className: 'reason', textContent: 'The start point: no step has been decided yet.' }));
        this.#element.replaceChildren(...lines);
        this.#shownPointIndex = pointIndex;
      }
    } catch (error) {
      // A crash is reported by the page's crash banner; anything else is a bug shown here.
      if (!(error instanceof CoreCrash)) this.#element.textContent = `Could not read this step: ${String(error)}`;
    } finally {
      this.#fetching = false;
    }
  }
}
