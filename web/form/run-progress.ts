/**
 * A long run's progress bar and its Cancel button: a G-code program's, and
 * the random-lines experiment's. Hidden while nothing runs.
 */

/** How far a run has got, in units of `total` (lines), and the same in words. */
export interface RunShare {
  done: number;
  total: number;
  text: string;
}

export interface RunProgressElements {
  bar: HTMLProgressElement;
  cancel: HTMLButtonElement;
  /** What is shown only while a run goes on: the bar and Cancel themselves when absent. */
  box?: HTMLElement;
  /** Where the progress is said in words beside the bar (a screen reader hears it as the bar's value). */
  text?: HTMLElement;
}

export class RunProgress {
  readonly #e: RunProgressElements;

  constructor(elements: RunProgressElements, onCancel: () => void) {
    this.#e = elements;
    elements.cancel.addEventListener('click', onCancel);
  }

  /** Shows how far the run has got (undefined: no run under way). */
  set(share: RunShare | undefined): void {
    const { bar, cancel, box, text } = this.#e;
    for (const shown of box ? [box] : [bar, cancel]) shown.hidden = share === undefined;
    if (!share) return;
    bar.max = Math.max(1, share.total);
    bar.value = share.done;
    bar.setAttribute('aria-valuetext', share.text);
    if (text) text.textContent = share.text;
  }
}
