/**
 * A long run's progress bar and its Cancel button: a G-code program's, and
 * the random-lines experiment's. Hidden while nothing runs.
 */

import { countOf, grouped } from '../format.js';

/** How far a run has got: the lines run (of a program, or of the experiment) and the steps they took. */
export interface LinesProgress {
  linesDone: number;
  lines: number;
  steps: number;
  /** A program's first error's line, where its run stopped: the lines after it are read (linesDone) for their syntax only. */
  stoppedAtLine?: number | null;
}

export interface RunProgressElements {
  bar: HTMLProgressElement;
  cancel: HTMLButtonElement;
  /** What is shown only while a run goes on: the bar and Cancel themselves when absent. */
  box?: HTMLElement;
  /** Where the progress is said in words beside the bar (a screen reader hears it as the bar's value). */
  text?: HTMLElement;
  /** What the run does, said before its progress ("Tracing: 10 of 100 lines, ..."). */
  verb?: string;
}

export class RunProgress {
  readonly #e: RunProgressElements;

  constructor(elements: RunProgressElements, onCancel: () => void) {
    this.#e = elements;
    elements.cancel.addEventListener('click', onCancel);
  }

  /** Shows how far the run has got (undefined: no run under way). */
  set(progress: LinesProgress | undefined): void {
    const { bar, cancel, box, text, verb } = this.#e;
    for (const shown of box ? [box] : [bar, cancel]) shown.hidden = progress === undefined;
    if (!progress) return;
    bar.max = Math.max(1, progress.lines);
    bar.value = progress.linesDone;
    const said = `${verb ? `${verb}: ` : ''}${grouped(progress.linesDone)} of ${countOf(progress.lines, 'line')}, ${countOf(progress.steps, 'step')}`;
    bar.setAttribute('aria-valuetext', said);
    if (text) text.textContent = said;
  }
}
