/**
 * The current point and why the algorithm went there: its coordinates, its
 * distance from the ideal path, the decision values of the step that produced
 * it, and the core's one-sentence explanation. Decision columns are rendered
 * from their ColumnSpec (int, float, category through its labels, flag), so a
 * new algorithm's columns appear without code here.
 *
 * Counting as the counter does and as the papers index M_i: after k steps the
 * point shown is point index k, produced by step k (1-based), which is step
 * index k - 1 of the core.
 */
import { readDecision } from '../core/export.js';
import type { ColumnSpec } from '../core/types.js';
import { formatPoint, NO_VALUE_TEXT } from '../format.js';
import { afterNextFrame } from '../main-thread.js';
import { CoreCrash, type RemoteTrace } from '../worker/client.js';
import { type DecisionRow, decisionFigure } from './decision-figure.js';

export interface InspectorElements {
  point: HTMLElement;
  deviation: HTMLElement;
  decisionHeading: HTMLElement;
  /** A <dl>: one <div> with a <dt>/<dd> pair per decision column. */
  decisions: HTMLElement;
  explanation: HTMLElement;
  /** Where the decision's picture goes (decision-figure.ts). */
  figure: HTMLElement;
  /** A <dl> of what each column means. */
  columnDocs: HTMLElement;
  setupNote: HTMLElement;
}

/** How a learner reads one decision value (a dash where the column does not apply to this step). */
function formatValue(column: ColumnSpec, value: number): string {
  const readable = readDecision(column, value);
  if (readable === null) return NO_VALUE_TEXT;
  if (typeof readable === 'boolean') return readable ? 'yes' : 'no';
  if (typeof readable === 'number' && column.kind === 'float') return String(Number(readable.toPrecision(6)));
  return String(readable);
}

/** Called with each decision the inspector shows (row undefined at the start point), for views drawn from the same values. */
export type DecisionListener = (trace: RemoteTrace, pointIndex: number, row: DecisionRow | undefined) => void;

export class Inspector {
  readonly #e: InspectorElements;
  readonly #onDecision: DecisionListener;
  #trace: RemoteTrace | undefined;
  /** The value cell of each column, by column name. */
  #cells = new Map<string, HTMLElement>();
  /** The point the inspector should show; requests chase it one at a time. */
  #wantedPointIndex = 0;
  #shownPointIndex: number | undefined;
  #fetching = false;
  /** Resolves once the current trace's first frame is drawn. */
  #drawn: Promise<void> = Promise.resolve();

  constructor(elements: InspectorElements, onDecision: DecisionListener) {
    this.#e = elements;
    this.#onDecision = onDecision;
  }

  /** Lays out the rows for `trace`'s columns and shows `pointIndex`. */
  setTrace(trace: RemoteTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#shownPointIndex = undefined;
    this.#cells.clear();
    const rows: HTMLElement[] = [];
    const docs: HTMLElement[] = [];
    for (const column of trace?.columns ?? []) {
      const value = document.createElement('dd');
      value.dataset.testid = `inspector-value-${column.name}`;
      this.#cells.set(column.name, value);
      // A <div> per name/value pair (allowed in a <dl>) lets each pair be laid out as one tile.
      const row = document.createElement('div');
      row.append(Object.assign(document.createElement('dt'), { textContent: column.name }), value);
      rows.push(row);
      docs.push(Object.assign(document.createElement('dt'), { textContent: column.name }), Object.assign(document.createElement('dd'), { textContent: column.doc }));
    }
    this.#e.decisions.replaceChildren(...rows);
    this.#e.columnDocs.replaceChildren(...docs);
    // The new path is drawn first: its replayed decision is asked for after that frame.
    this.#drawn = afterNextFrame();
    this.show(pointIndex);
  }

  /** Shows the decision cards of the columns in `names` only (a G-code step's own algorithm's), or all of them (undefined). */
  showColumns(names: ReadonlySet<string> | undefined): void {
    for (const [name, cell] of this.#cells) cell.parentElement!.hidden = names !== undefined && !names.has(name);
  }

  /** Shows point index `pointIndex`: the point at once, the replayed decision when the worker answers. */
  show(pointIndex: number): void {
    const trace = this.#trace;
    const e = this.#e;
    if (!trace) {
      e.point.textContent = e.deviation.textContent = e.explanation.textContent = e.setupNote.textContent = '';
      e.figure.replaceChildren();
      e.decisionHeading.textContent = 'Decision';
      return;
    }
    e.point.textContent = formatPoint(trace.point(pointIndex));
    e.decisionHeading.textContent = pointIndex === 0 ? 'Decision: none yet' : `Decision of step ${pointIndex}`;
    this.#wantedPointIndex = pointIndex;
    if (!this.#fetching) void this.#fetch();
  }

  /**
   * Fetches the replayed values of the wanted point until they are the ones
   * shown. One request set at a time, always for the latest wanted point, so
   * fast playback or scrubbing never queues stale work in the worker.
   */
  async #fetch(): Promise<void> {
    this.#fetching = true;
    try {
      await this.#drawn;
      while (this.#trace && this.#shownPointIndex !== this.#wantedPointIndex) {
        const trace = this.#trace;
        const pointIndex = this.#wantedPointIndex;
        const [deviation, decisions, explanation, note] = await Promise.all([
          trace.deviationInRange(pointIndex, pointIndex + 1),
          pointIndex > 0 ? trace.decisionsInRange(pointIndex - 1, pointIndex) : undefined,
          pointIndex > 0 ? trace.explain(pointIndex - 1) : undefined,
          // The segment whose step produced this point (the first one's at the start).
          trace.segmentNote(Math.max(pointIndex - 1, 0)),
        ]);
        if (trace !== this.#trace) continue;
        this.#e.deviation.textContent = `${deviation[0]!.toFixed(6)} grid units`;
        const row: DecisionRow | undefined = decisions && Object.fromEntries(trace.columns.map((c) => [c.name, decisions[c.name]![0]!]));
        for (const column of trace.columns) {
          this.#cells.get(column.name)!.textContent = row ? formatValue(column, row[column.name]!) : NO_VALUE_TEXT;
        }
        const figure = decisionFigure(trace.columns, row);
        this.#e.figure.replaceChildren(...(figure ? [figure] : []));
        this.#e.explanation.textContent = explanation ?? 'This is the start point: no step has been decided yet.';
        this.#e.setupNote.textContent = note;
        this.#shownPointIndex = pointIndex;
        this.#onDecision(trace, pointIndex, row);
      }
    } catch (error) {
      // A crash is reported by the page's crash banner; anything else is a bug shown here.
      if (!(error instanceof CoreCrash)) this.#e.explanation.textContent = `Could not read this step: ${String(error)}`;
    } finally {
      this.#fetching = false;
    }
  }
}
