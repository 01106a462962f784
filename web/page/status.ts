/**
 * The status line under the inputs: what the core is doing, what it traced
 * (steps, ends, the largest deviation and the bound the rule promises, ties;
 * a program's lines, moves and stop), and why nothing was traced.
 */
import { diagnosticText } from '../form/page-advice.js';
import type { BarProgress, LinesProgress } from '../form/run-progress.js';
import { clause, countOf, formatPoint, grouped } from '../format.js';
import type { Mode } from '../state/app-state.js';
import type { MeasuredTrace } from '../worker/client.js';
import type { ProgramRecord } from '../worker/protocol.js';
import type { Shown } from './shown.js';

/** One trace in a sentence. */
function traceStatus(trace: MeasuredTrace): string {
  const m = trace.metrics;
  const bound = trace.deviationBound;
  return (
    `${trace.name}: ${countOf(trace.steps, 'step')} from ${formatPoint(trace.start)} to ${formatPoint(trace.end)}; ` +
    `largest distance from the ideal path ${m.maxDeviation.toFixed(3)}` +
    (bound ? ` (the rule keeps it within ${bound.value.toFixed(3)}: ${bound.why})` : '') +
    `; ${countOf(m.ties, 'tie')}.`
  );
}

/** A program run in a sentence: its size, where it stopped and its warnings. */
export function programStatus(p: ProgramRecord): string {
  return (
    `${countOf(p.lines, 'line')}, ${countOf(p.moveCount, 'move')}, ${countOf(p.steps, 'step')} at ${p.stepsPerMm.join(' / ')} steps/mm` +
    `${p.errors.length ? `; stopped at line ${p.stoppedAtLine}: ${clause(diagnosticText(p.errors[0]!))}` : ''}` +
    `${p.warnings.length ? `; ${countOf(p.warnings.length + p.warningsOmitted, 'warning')}` : ''}.`
  );
}

export class Status {
  readonly #element: HTMLElement;
  /** Where an embedded view, which hides the status line, says what it says while a run goes on (empty otherwise). */
  readonly #busy: HTMLElement;

  constructor(element: HTMLElement, busy: HTMLElement) {
    this.#element = element;
    this.#busy = busy;
  }

  /** Says `text`; `running`: of a run under way, said in an embedded view too. */
  #say(text: string, running = false): void {
    this.#element.textContent = text;
    this.#busy.textContent = running ? text : '';
  }

  clear(): void {
    this.#say('');
  }

  /** The core was asked to run for `mode`. */
  tracing(mode: Mode): void {
    this.#say(mode === 'experiment' ? 'Tracing the lines…' : 'Tracing…', true);
  }

  /** How far a long run has got: a program's ('Running') or the experiment's ('Tracing'), at the line it has reached. */
  running(verb: string, progress: LinesProgress): void {
    this.#say(`${verb}: line ${grouped(progress.stoppedAtLine ?? progress.linesDone)} of ${grouped(progress.lines)}, ${countOf(progress.steps, 'step')} so far…`, true);
  }

  /** How far a pass over the points of the path (or both paths) has got: `verb` says which ('Measuring the path'). */
  passing(verb: string, bar: BarProgress): void {
    this.#say(`${verb}: ${bar.said}…`, true);
  }

  /** What is now on screen. */
  shown(shown: Shown): void {
    if (shown.experiment) this.#say(`${countOf(shown.experiment.lines.length, 'line')} traced with ${shown.experiment.algorithm}.`);
    else if (shown.program) this.#say(programStatus(shown.program.program));
    else this.#say([shown.a, shown.b].filter((t) => t !== undefined).map(traceStatus).join(' '));
  }

  /** The run was cancelled; `kept`: what is still on screen from the last run that went to its end. */
  cancelled(kept: 'paths' | 'program' | 'experiment' | undefined): void {
    if (kept === 'paths') this.#say('Cancelled. The view still shows the last paths traced.');
    else if (kept === 'program') this.#say('Cancelled. The view still shows the last program that ran.');
    else if (kept === 'experiment') this.#say('Cancelled. The tables still show the last experiment that ran.');
    else this.#say('Cancelled.');
  }

  /** The core rejected the input (the form shows why); `keptPrevious`: an earlier path is still on screen. */
  rejected(keptPrevious: boolean): void {
    this.#say(keptPrevious ? 'Not traced: see the message above. The view still shows the last valid path.' : 'Not traced: see the message above.');
  }

  /** Not the input's fault: a bug in the page's request, reported as one. */
  bug(error: unknown): void {
    this.#say(`Not traced, because of a bug in voxpath: ${String(error)}`);
  }
}
