/**
 * The current point and why the algorithm went there: its coordinates, its
 * distance from the ideal path, the decision values of the step that produced
 * it, the core's one-sentence explanation and the decision's picture, all
 * from the core's StepDetail of the point (point-details.ts asks for it).
 * Decision cells come read by the core (a category's label, a flag's yes or
 * no), so a new algorithm's columns appear without code here.
 *
 * Counting as the counter does and as the papers index M_i: after k steps the
 * point shown is point index k, produced by step k (1-based), which is step
 * index k - 1 of the core.
 */
import type { ColumnSpec, DecisionCell, StepDetail } from '../core/types.js';
import { formatPoint, NO_VALUE_TEXT } from '../format.js';
import { decisionFigure } from './decision-figure.js';

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

/** What the inspector reads of a trace itself: its columns and its points. */
export interface InspectedTrace {
  readonly columns: readonly ColumnSpec[];
  /** The point when the page holds it (a long path's comes with its detail). */
  point(pointIndex: number): ArrayLike<number> | undefined;
}

/** How a learner reads one decision value (a dash where the column does not apply to this step). */
function formatCell(cell: DecisionCell): string {
  const reading = cell.reading;
  if (reading === null) return NO_VALUE_TEXT;
  if (typeof reading === 'boolean') return reading ? 'yes' : 'no';
  if (typeof reading === 'number' && cell.kind === 'float') return String(Number(reading.toPrecision(6)));
  return String(reading);
}

/** A column's name as a card's title, breakable between its camelCase words (otherCandidate wrapped as otherCandid/ate). */
function breakableName(name: string): HTMLElement {
  const title = document.createElement('dt');
  name.split(/(?<=[a-z0-9])(?=[A-Z])/).forEach((word, i) => {
    if (i > 0) title.append(document.createElement('wbr'));
    title.append(word);
  });
  return title;
}

/** The point's text while its coordinates are on their way from the worker (a long path's point the page does not hold). */
const POINT_ON_ITS_WAY = '…';

export class Inspector {
  readonly #e: InspectorElements;
  #trace: InspectedTrace | undefined;
  /** The point index shown (showPoint): a detail of another point, arriving late, does not write its coordinates. */
  #pointIndex = 0;
  /** The value cell of each column, by column name. */
  #cells = new Map<string, HTMLElement>();

  constructor(elements: InspectorElements) {
    this.#e = elements;
  }

  /** Lays out the rows for `trace`'s columns and shows `pointIndex`. */
  setTrace(trace: InspectedTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#cells.clear();
    const rows: HTMLElement[] = [];
    const docs: HTMLElement[] = [];
    for (const column of trace?.columns ?? []) {
      const value = document.createElement('dd');
      value.dataset.testid = `inspector-value-${column.name}`;
      this.#cells.set(column.name, value);
      // A <div> per name/value pair (allowed in a <dl>) lets each pair be laid out as one tile.
      const row = document.createElement('div');
      row.append(breakableName(column.name), value);
      rows.push(row);
      docs.push(Object.assign(document.createElement('dt'), { textContent: column.name }), Object.assign(document.createElement('dd'), { textContent: column.doc }));
    }
    this.#e.decisions.replaceChildren(...rows);
    this.#e.columnDocs.replaceChildren(...docs);
    this.showPoint(pointIndex);
  }

  /** Shows the decision cards of the columns in `names` only (a G-code step's own algorithm's), or all of them (undefined). */
  showColumns(names: ReadonlySet<string> | undefined): void {
    for (const [name, cell] of this.#cells) cell.parentElement!.hidden = names !== undefined && !names.has(name);
  }

  /** Shows point index `pointIndex` at once from the trace's points the page holds; its detail follows (showDetail). */
  showPoint(pointIndex: number): void {
    const trace = this.#trace;
    const e = this.#e;
    if (!trace) {
      e.point.textContent = e.deviation.textContent = e.explanation.textContent = e.setupNote.textContent = '';
      e.figure.replaceChildren();
      e.decisionHeading.textContent = 'Decision';
      return;
    }
    this.#pointIndex = pointIndex;
    // A long path's point the page does not hold comes with its detail (showDetail).
    const point = trace.point(pointIndex);
    e.point.textContent = point ? formatPoint(point) : POINT_ON_ITS_WAY;
    e.decisionHeading.textContent = pointIndex === 0 ? 'Decision: none yet' : `Decision of step ${pointIndex}`;
  }

  /** Shows the core's detail of a point of the current trace. */
  showDetail(detail: StepDetail): void {
    const e = this.#e;
    if (detail.pointIndex === this.#pointIndex) e.point.textContent = formatPoint(detail.point);
    e.deviation.textContent = detail.deviation === null ? NO_VALUE_TEXT : `${detail.deviation.toFixed(6)} grid units`;
    for (const cell of detail.decision) {
      const value = this.#cells.get(cell.name);
      if (!value) continue;
      const text = formatCell(cell);
      value.textContent = text;
      // A value longer than a card holds at full size (-0.166667) is set
      // smaller, not broken across lines: cards never move as values change.
      value.dataset.size = text.length > 9 ? 'smaller' : text.length > 7 ? 'small' : '';
    }
    const figure = decisionFigure(detail.figure);
    e.figure.replaceChildren(...(figure ? [figure] : []));
    e.explanation.textContent = detail.explanation ?? 'This is the start point: no step has been decided yet.';
    e.setupNote.textContent = detail.segment?.note ?? '';
  }

  /** Says that the current point's detail could not be read (a bug, reported here). */
  showError(error: unknown): void {
    this.#e.explanation.textContent = `Could not read this step: ${String(error)}`;
  }
}
