/**
 * The page's exports: the traces on screen as the CLI writes them (CSV,
 * JSON, written by the core's writers in the worker), a program's STEP and
 * DIR wires (VCD, likewise), the random lines as CSV, and the view as a PNG.
 * A file the worker writes is written a part at a time, its progress shown
 * beside the buttons with a Cancel: a long program's takes a minute.
 */
import { randomLinesToCsv } from '../core/export.js';
import { RunProgress, type RunProgressElements } from '../form/run-progress.js';
import { grouped } from '../format.js';
import { Cancelled, CoreCrash, type RemoteTrace, type Running } from '../worker/client.js';
import type { ExportFormat } from '../worker/protocol.js';
import { staleness } from '../state/stale.js';
import type { Shown } from './shown.js';

export interface ExportButtons {
  csv: HTMLButtonElement;
  json: HTMLButtonElement;
  png: HTMLButtonElement;
  /** G-code mode's: the program's wires. */
  vcd: HTMLButtonElement;
}

/** An export's bar and Cancel, and where it says how it ended when it did not save its file (cancelled, or refused). */
export interface ExportRunElements extends RunProgressElements {
  note: HTMLElement;
}

/** Saves `blob` as a file named `name` through the browser's download. */
export function download(name: string, blob: Blob): void {
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  // After the click has handed the URL to the download.
  setTimeout(() => URL.revokeObjectURL(url), 0);
}

/**
 * The traces on screen and their file names: the program, or the trace, or
 * both compared ones, each under its algorithm's id, and an algorithm
 * compared with itself with each side's value after it (helix-saleem, helix-segments).
 */
function exported(shown: Shown): [RemoteTrace, string][] {
  if (shown.program) return [[shown.program, 'program']];
  return [shown.a, shown.b].filter((t) => t !== undefined).map((t) => [t, t.distinction === undefined ? t.algorithm : `${t.algorithm}-${t.distinction}`]);
}

/** The export buttons' state, kept by the page as what it shows changes. */
export interface Exports {
  /**
   * Enables the exports when what is on screen was traced from the inputs
   * shown; else disables them and says why in their tooltips: while
   * `tracing` (the inputs changed and their trace is not on screen yet),
   * when nothing was traced, or when the inputs were refused since. A
   * button that did nothing, or saved the last path traced under the new
   * inputs' name (in the quarter second before a retrace, or after a
   * refusal, when the view is dimmed and marked out of date but the file
   * is not), said nothing of it. A change of the inputs (`tracing`)
   * cancels an export under way: the traces it reads are about to be freed.
   */
  refresh(tracing: boolean): void;
}

/** Why nothing can be exported now, or undefined when what is shown can. */
function notExportable(shown: Shown, tracing: boolean, exporting: boolean): string | undefined {
  if (exporting) return 'An export is under way: wait for it, or cancel it.';
  if (tracing) return 'Not exported yet: the inputs as they are now are being traced.';
  if (!shown.a && !shown.program && !shown.experiment) return 'Nothing to export: nothing was traced (see the message by the inputs).';
  if (staleness() !== undefined) return 'Not exported: what is shown is out of date with the inputs (see the message by them).';
  return undefined;
}

/** Bytes as the export's progress says them: "12.3 MB". */
function megabytes(bytes: number): string {
  return `${grouped(Math.round(bytes / 1e5) / 10)} MB`;
}

/**
 * Wires the export buttons: `shown` says what is on screen when one is
 * pressed, `view` draws the PNG, `viewName` names it.
 */
export function wireExports(buttons: ExportButtons, run: ExportRunElements, shown: () => Shown, view: { toPng(): Promise<Blob> }, viewName: () => string): Exports {
  /** The file the worker is writing, if any. */
  let running: Running<Blob> | undefined;
  const progress = new RunProgress(run, () => running?.cancel());
  // The buttons' state, as the page last asked for it (refresh).
  let tracing = false;
  const refresh = () => {
    const why = notExportable(shown(), tracing, running !== undefined);
    // The view's PNG is drawn on the page, not written by the worker: an
    // export under way there does not hold it up.
    const whyNotPng = notExportable(shown(), tracing, false);
    for (const [button, reason] of [[buttons.csv, why], [buttons.json, why], [buttons.vcd, why], [buttons.png, whyNotPng]] as const) {
      button.disabled = reason !== undefined;
      if (reason === undefined) button.removeAttribute('title');
      else button.title = reason;
    }
  };
  /** Saves `trace` as `format` under `name`, written in the worker; false when it was not saved (the note says why). */
  const save = async (trace: RemoteTrace, format: ExportFormat, name: string): Promise<boolean> => {
    const verb = `Writing ${name}`;
    progress.set({ done: 0, said: 'starting' }, verb);
    running = trace.exportAs(format, ({ bytes }) => progress.set({ done: bytes, said: `${megabytes(bytes)} so far` }, verb));
    refresh();
    try {
      download(name, await running.result);
      return true;
    } catch (error) {
      // A crash is said by the page's alert; anything else here.
      if (!(error instanceof CoreCrash)) run.note.textContent = error instanceof Cancelled ? `${name} was not saved: the export was cancelled.` : `${name} was not saved: ${error instanceof Error ? error.message : String(error)}`;
      return false;
    } finally {
      running = undefined;
      progress.set(undefined);
      refresh();
    }
  };
  /** Saves every trace on screen as `format`, one after the other, stopping at one not saved. */
  const saveShown = async (format: 'csv' | 'json'): Promise<void> => {
    run.note.textContent = '';
    for (const [trace, name] of exported(shown())) if (!(await save(trace, format, `${name}-steps.${format}`))) return;
  };
  buttons.csv.addEventListener('click', () => {
    const { experiment } = shown();
    if (experiment) return download(`random-lines-${experiment.algorithm}.csv`, new Blob([randomLinesToCsv(experiment)], { type: 'text/csv' }));
    void saveShown('csv');
  });
  buttons.json.addEventListener('click', () => void saveShown('json'));
  buttons.vcd.addEventListener('click', () => {
    // The core's VCD (the CLI's --format vcd): STEP and DIR per axis at the planned instants.
    const { program } = shown();
    run.note.textContent = '';
    if (program) void save(program, 'vcd', 'program-step-dir.vcd');
  });
  buttons.png.addEventListener('click', async () => {
    download(`${viewName()}-view.png`, await view.toPng());
  });
  return {
    refresh(inputsTracing) {
      tracing = inputsTracing;
      if (tracing) running?.cancel();
      refresh();
    },
  };
}
