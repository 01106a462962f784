/**
 * A long run's progress bar and its Cancel button: a G-code program's, the
 * random-lines experiment's, an export's, a pass over a path's points
 * (its metrics, its charts' rows), and a check of a learner's points. Hidden while nothing runs,
 * when the run's own button (Run program, Run experiment) runs it again.
 */

import type { PointsProgress } from '../core/index.js';
import type { CheckRunProgress } from '../worker/protocol.js';
import { countOf, grouped } from '../format.js';

/**
 * A long run's progress is shown at once, then at most this often, ms, and
 * at its end.
 * The worker reports it after every slice of its work (about 20 ms), and
 * each update repaints the page: where the compositor draws on the CPU,
 * that took the run's time in the worker from 50 to 55 ms to 58 to 71 ms at
 * 1 step/mm for the G-code bench's program on the project's 2-core
 * machine. Four updates a second are as many as a reader follows.
 */
export const PROGRESS_EVERY_MS = 250;

/**
 * `show`, called for a run's progress at once, then at most every
 * PROGRESS_EVERY_MS, and at its end; not once `current()` says the run is
 * no longer the one shown.
 */
export function throttled<Progress extends { done: boolean }>(current: () => boolean, show: (progress: Progress) => void): (progress: Progress) => void {
  let shownAt = -Infinity;
  return (progress) => {
    const now = performance.now();
    // The last report is shown too, so the bar does not end at its first.
    if (!current() || (now - shownAt < PROGRESS_EVERY_MS && !progress.done)) return;
    shownAt = now;
    show(progress);
  };
}

/** How far a run has got: the lines run (of a program, or of the experiment) and the steps they took. */
export interface LinesProgress {
  linesDone: number;
  lines: number;
  steps: number;
  /** A program's first error's line, where its run stopped: the lines after it are read (linesDone) for their syntax only. */
  stoppedAtLine?: number | null;
}

/** A run's progress as its bar shows it: `done` of `total` (undefined: not known before the end, so the bar only says the run goes on), and in words. */
export interface BarProgress {
  done: number;
  total?: number;
  said: string;
}

/** A run of lines as its bar shows it: the lines run, of all, and the steps they took. */
export function linesBar(progress: LinesProgress): BarProgress {
  return { done: progress.linesDone, total: Math.max(1, progress.lines), said: `${grouped(progress.linesDone)} of ${countOf(progress.lines, 'line')}, ${countOf(progress.steps, 'step')}` };
}

/** A pass over a path's points as its bar shows it: the points measured, of all. */
export function pointsBar(progress: PointsProgress): BarProgress {
  return { done: progress.pointsDone, total: Math.max(1, progress.points), said: `${grouped(progress.pointsDone)} of ${countOf(progress.points, 'point')}` };
}

/**
 * A check of a learner's points as its bar shows it, with what it does now
 * (`verb`): reading them (the rule traced first, then their text a slice at
 * a time, its bytes read of all and the points read so far), comparing
 * their steps with the rule's, then tracing the rule's family's option
 * combinations along them (alsoMatches).
 */
export function checkBar(progress: CheckRunProgress): { bar: BarProgress; verb: string } {
  if (progress.stage === 'reading') {
    // The worker's report before the core's first slice has no counts yet.
    if (!('bytes' in progress) || progress.bytes === 0) return { bar: { done: 0, said: 'your points and the rule' }, verb: 'Reading' };
    const percent = Math.floor((100 * progress.bytesRead) / progress.bytes);
    return { bar: { done: progress.bytesRead, total: progress.bytes, said: `${countOf(progress.pointsRead, 'point')}, ${percent}% of the text` }, verb: 'Reading your points' };
  }
  if (progress.stage === 'comparing') {
    return {
      bar: { done: progress.stepsCompared, total: Math.max(1, progress.stepsShared), said: `${grouped(progress.stepsCompared)} of ${countOf(progress.stepsShared, 'step')}` },
      verb: 'Comparing with the rule',
    };
  }
  return {
    bar: { done: progress.variantsTried, total: Math.max(1, progress.variants), said: `${grouped(progress.variantsTried)} of ${countOf(progress.variants, 'option combination')}` },
    verb: 'Finding the rules your points follow',
  };
}

export interface RunProgressElements {
  bar: HTMLProgressElement;
  cancel: HTMLButtonElement;
  /** The button that runs the inputs as they are (again, after a Cancel): disabled while a run goes on. */
  start?: HTMLButtonElement;
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

  /** Shows how far the run has got (undefined: no run under way); `verb`, when given, says what it does instead of the elements' own. */
  set(progress: BarProgress | undefined, verb = this.#e.verb): void {
    const { bar, cancel, start, box, text } = this.#e;
    for (const shown of box ? [box] : [bar, cancel]) shown.hidden = progress === undefined;
    if (start) start.disabled = progress !== undefined;
    if (!progress) return;
    if (progress.total === undefined) {
      // Indeterminate: the bar moves without saying how far.
      bar.removeAttribute('value');
    } else {
      bar.max = progress.total;
      bar.value = progress.done;
    }
    const said = `${verb ? `${verb}: ` : ''}${progress.said}`;
    bar.setAttribute('aria-valuetext', said);
    if (text) text.textContent = said;
  }
}
