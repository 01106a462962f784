/**
 * The current step's reason under the timeline: the core's one-sentence
 * explanation of the step that produced the point shown (for each path, in
 * compare mode). It is the inspector's sentence, put where it stays in sight
 * with the view and the timeline when the inspector is not: in a medium or
 * narrow window, in compare mode (whose table tops the inspector) and in an
 * embedded view. The stylesheet decides where it shows.
 *
 * The main path's sentence is the one of the detail the page already asks
 * for every point (PointDetails hands it here, as to the inspector), so it
 * costs no request of its own; only the second path of a comparison is
 * asked of the worker, while the line shows, for the latest point only.
 */
import type { StepDetail } from '../core/types.js';
import { element } from '../form/options-form.js';
import { afterNextFrame } from '../main-thread.js';
import { CoreCrash, type RemoteTrace } from '../worker/client.js';

/** Whether a step of `trace` produced point index `pointIndex`: not at its start, nor past its end. */
function tookStep(trace: RemoteTrace, pointIndex: number): boolean {
  return pointIndex > 0 && pointIndex <= trace.steps;
}

/** What a path says at a point: its sentence, or undefined while the main path's detail is on its way. */
type Sentence = string | undefined;

export class StepReason {
  readonly #element: HTMLElement;
  /** The path whose details the page reads anyway, and the compared second path (or none). */
  #main: RemoteTrace | undefined;
  #second: RemoteTrace | undefined;
  #mainDetail: StepDetail | undefined;
  /** The point the line should explain, and the one it explains (undefined: none yet for these traces). */
  #wantedPointIndex = 0;
  #shownPointIndex: number | undefined;
  /** The second path's sentence, for the point it was read at. */
  #secondSentence: { pointIndex: number; text: string } | undefined;
  #fetching = false;
  /** Resolves once the current traces' first frame is drawn: no replay shares the CPU with it. */
  #drawn: Promise<void> = Promise.resolve();

  constructor(container: HTMLElement) {
    this.#element = container;
    // Shown after being hidden (a narrower window, another mode): explain what is there now.
    new ResizeObserver(() => this.#update()).observe(container);
  }

  /** The traces to explain: the main one, whose details the page reads, and a compared second one. */
  setTraces(main: RemoteTrace | undefined, second: RemoteTrace | undefined, pointIndex: number): void {
    this.#main = main;
    this.#second = second;
    this.#mainDetail = undefined;
    this.#secondSentence = undefined;
    this.#shownPointIndex = undefined;
    this.#element.replaceChildren();
    this.#drawn = afterNextFrame();
    this.show(pointIndex);
  }

  /** The main path's detail, as the page's one request per point brought it. */
  setMainDetail(detail: StepDetail): void {
    this.#mainDetail = detail;
    this.#shownPointIndex = undefined;
    this.#update();
  }

  /** Explains point index `pointIndex`: the step that produced it. */
  show(pointIndex: number): void {
    this.#wantedPointIndex = pointIndex;
    this.#update();
  }

  #update(): void {
    if (!this.#element.checkVisibility()) return;
    const second = this.#second;
    const pointIndex = this.#wantedPointIndex;
    if (second && this.#secondSentence?.pointIndex !== pointIndex) {
      if (tookStep(second, pointIndex)) {
        if (!this.#fetching) void this.#fetchSecond();
        return;
      }
      // Nothing to ask the worker (the start, where a new comparison opens,
      // or past its end): said in the task that shows the traces. Asked for
      // after their first frame, the line came then and took its room from
      // the views, which were sized and drawn again (two 1,400,000-step
      // lines compared: a frame of 80 to 160 ms on a software GPU).
      this.#secondSentence = { pointIndex, text: '' };
    }
    this.#render();
  }

  #render(): void {
    const pointIndex = this.#wantedPointIndex;
    if (this.#shownPointIndex === pointIndex) return;
    const traces = [this.#main, this.#second].filter((t) => t !== undefined);
    if (traces.length === 0) return;
    // At the start point there is nothing to explain, for either path.
    const explained = pointIndex === 0 ? [] : traces;
    const sentences: Sentence[] = explained.map((t) => {
      if (pointIndex > t.steps) return `its path ended at step ${t.steps}.`;
      if (t === this.#second) return this.#secondSentence?.text;
      return this.#mainDetail?.pointIndex === pointIndex ? (this.#mainDetail.explanation ?? '') : undefined;
    });
    // The main path's detail has not come yet: it will, and call back.
    if (sentences.some((s) => s === undefined)) return;
    const lines = explained.map((t, i) => {
      const label = traces.length > 1 ? `${t.name}, step ${pointIndex}: ` : `Step ${pointIndex}: `;
      return element('span', { className: 'reason' }, element('strong', { textContent: label }), sentences[i]!);
    });
    if (pointIndex === 0) lines.push(element('span', { className: 'reason', textContent: 'The start point: no step has been decided yet.' }));
    this.#element.replaceChildren(...lines);
    this.#shownPointIndex = pointIndex;
  }

  /** Reads the second path's sentence at the latest wanted point, one request at a time. */
  async #fetchSecond(): Promise<void> {
    this.#fetching = true;
    try {
      await this.#drawn;
      while (this.#second && this.#secondSentence?.pointIndex !== this.#wantedPointIndex && this.#element.checkVisibility()) {
        const second = this.#second;
        const pointIndex = this.#wantedPointIndex;
        const text = tookStep(second, pointIndex) ? ((await second.stepDetail(pointIndex)).explanation ?? '') : '';
        if (second !== this.#second) continue;
        this.#secondSentence = { pointIndex, text };
      }
      this.#render();
    } catch (error) {
      // A crash is reported by the page's crash banner; anything else is a bug shown here.
      if (!(error instanceof CoreCrash)) this.#element.textContent = `Could not read this step: ${String(error)}`;
    } finally {
      this.#fetching = false;
    }
  }
}
