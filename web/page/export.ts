/**
 * The page's exports: the traces on screen as the CLI writes them (CSV,
 * JSON, written by the core's writers in the worker), the random lines as
 * CSV, and the view as a PNG.
 */
import { randomLinesToCsv } from '../core/export.js';
import type { RemoteTrace } from '../worker/client.js';
import { staleness } from '../state/stale.js';
import type { Shown } from './shown.js';

export interface ExportButtons {
  csv: HTMLButtonElement;
  json: HTMLButtonElement;
  png: HTMLButtonElement;
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
   * is not), said nothing of it.
   */
  refresh(tracing: boolean): void;
}

/** Why nothing can be exported now, or undefined when what is shown can. */
function notExportable(shown: Shown, tracing: boolean): string | undefined {
  if (tracing) return 'Not exported yet: the inputs as they are now are being traced.';
  if (!shown.a && !shown.program && !shown.experiment) return 'Nothing to export: nothing was traced (see the message by the inputs).';
  if (staleness() !== undefined) return 'Not exported: what is shown is out of date with the inputs (see the message by them).';
  return undefined;
}

/**
 * Wires the export buttons: `shown` says what is on screen when one is
 * pressed, `view` draws the PNG, `viewName` names it.
 */
export function wireExports(buttons: ExportButtons, shown: () => Shown, view: { toPng(): Promise<Blob> }, viewName: () => string): Exports {
  buttons.csv.addEventListener('click', async () => {
    const { experiment } = shown();
    if (experiment) return download(`random-lines-${experiment.algorithm}.csv`, new Blob([randomLinesToCsv(experiment)], { type: 'text/csv' }));
    for (const [trace, name] of exported(shown())) download(`${name}-steps.csv`, new Blob([await trace.exportAs('csv')], { type: 'text/csv' }));
  });
  buttons.json.addEventListener('click', async () => {
    for (const [trace, name] of exported(shown())) download(`${name}-steps.json`, new Blob([await trace.exportAs('json')], { type: 'application/json' }));
  });
  buttons.png.addEventListener('click', async () => {
    download(`${viewName()}-view.png`, await view.toPng());
  });
  return {
    refresh(tracing) {
      const why = notExportable(shown(), tracing);
      for (const button of [buttons.csv, buttons.json, buttons.png]) {
        button.disabled = why !== undefined;
        if (why === undefined) button.removeAttribute('title');
        else button.title = why;
      }
    },
  };
}
