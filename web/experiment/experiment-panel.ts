/**
 * Experiment mode: Wang et al.'s batch of random lines (section 3.2, Figure
 * 9) as tables: one row per line (steps and the error statistics of each
 * measure), and the spread of each per-line statistic over all lines beside
 * Figure 9 as printed, with the erratum the core states about that figure.
 * The core computes every number; this only lays them out. A row opens its
 * line in Trace mode, to step through it. When another algorithm gave the
 * very same statistics on the same lines just before, that is said, so two
 * equal tables are not taken for a page that did not update.
 */
import type { ErrorStats, LineResult, MeasureSummary, RandomLinesResult } from '../core/index.js';
import { element } from '../form/options-form.js';
import { stateLink } from '../embed/embed.js';
import { AXIS_NAMES } from '../format.js';
import { type AppState, type Catalogue, axisChoices, defaultProjection } from '../state/app-state.js';
import { newHistoryEntry } from '../state/persist.js';
import type { Store } from '../state/store.js';

/** Rows of the per-line table drawn at most; the CSV export has them all. */
const LINE_ROWS_SHOWN = 500;

const f4 = (v: number) => v.toFixed(4);

function table(caption: string, header: string[], rows: string[][], testId: string): HTMLTableElement {
  const t = element(
    'table',
    { className: 'data-table' },
    element('caption', { textContent: caption }),
    element('thead', {}, element('tr', {}, ...header.map((h) => element('th', { scope: 'col', textContent: h })))),
    element('tbody', {}, ...rows.map((r) => element('tr', {}, ...r.map((c, i) => (i === 0 ? element('th', { scope: 'row', textContent: c }) : element('td', { textContent: c })))))),
  );
  t.dataset.testid = testId;
  return t;
}

/**
 * Two statistics that differ only by floating-point rounding: paths that
 * part at ties can visit cells whose distances are the same numbers in
 * another order, and sums in another order round differently in the last bit.
 */
const ROUNDING = 1e-12;

/** True when `a` and `b` traced the same lines and every per-line statistic came out the same (to rounding). */
function sameStatistics(a: RandomLinesResult, b: RandomLinesResult): boolean {
  const close = (x: number, y: number) => Math.abs(x - y) <= ROUNDING * Math.max(1, Math.abs(x), Math.abs(y));
  const same = (x: ErrorStats, y: ErrorStats) => close(x.max, y.max) && close(x.mean, y.mean) && close(x.std, y.std);
  return (
    a.lines.length === b.lines.length &&
    a.lines.every((l, i) => {
      const m = b.lines[i]!;
      return l.to.length === m.to.length && l.to.every((c, k) => c === m.to[k]) && l.steps === m.steps && same(l.perpendicular, m.perpendicular) && same(l.axisError, m.axisError);
    })
  );
}

export class ExperimentPanel {
  readonly #container: HTMLElement;
  readonly #store: Store<AppState>;
  readonly #catalogue: Catalogue;
  /** The result shown before this one, to say when two algorithms gave the same statistics. */
  #previous: RandomLinesResult | undefined;
  /** What takes the keyboard's focus once a line is open in Trace mode: the view (the skip link's target), where the arrows step the path. */
  readonly #focusInTrace: HTMLElement;
  /** The line last opened, by its 1-based number, whose button takes the focus back when its table shows again (Back). */
  #openedLine: number | undefined;

  constructor(container: HTMLElement, store: Store<AppState>, catalogue: Catalogue, focusInTrace: HTMLElement) {
    this.#container = container;
    this.#store = store;
    this.#catalogue = catalogue;
    this.#focusInTrace = focusInTrace;
  }

  /**
   * Opens line `line` of `result` in Trace mode: the same algorithm, from
   * the origin to its point. The focus goes with it: the button pressed
   * vanished with the table, and left it on the page's body.
   */
  #open(result: RandomLinesResult, line: LineResult): void {
    const traced: Partial<AppState> = {
      mode: 'trace',
      algorithm: result.algorithm,
      options: { from: line.to.map(() => 0), to: [...line.to] },
      pointIndex: 0,
      playing: false,
      camera: null,
      projection: defaultProjection(line.to.length),
    };
    if (this.#store.state.embed) {
      // An embedded experiment stays the experiment its page shows (the
      // frame turned into Trace mode, and a reader had no way back to the
      // table): the line opens in the full page, in a tab of its own.
      window.open(stateLink({ ...this.#store.state, ...traced }, false), '_blank', 'noopener');
      return;
    }
    this.#openedLine = result.lines.indexOf(line) + 1;
    // Back returns to the table.
    newHistoryEntry(this.#store.state);
    this.#store.update(traced);
    this.#focusInTrace.focus();
  }

  /** Shows no tables: what they showed is no longer held (another mode's run replaced it). */
  clear(): void {
    this.#container.replaceChildren();
  }

  show(result: RandomLinesResult): void {
    const previous = this.#previous;
    this.#previous = result;
    const dims = result.lines[0]?.to.length ?? 3;
    const info = this.#catalogue.algorithms.find((a) => a.id === result.algorithm);
    // Trace mode shows 2 or 3 axes: lines of more stay in the table.
    const openable = info !== undefined && axisChoices([info]).includes(dims);
    const stats = (s: ErrorStats) => [f4(s.max), f4(s.mean), f4(s.std)];
    const spread = (key: 'max' | 'mean' | 'std', m: MeasureSummary) => [f4(m[key].max), f4(m[key].min), f4(m[key].mean)];
    const spreadRows = (['mean', 'max', 'std'] as const).map((key) => [
      `δ_${key[0]!.toUpperCase()}${key.slice(1)} per line`,
      ...spread(key, result.perpendicular),
      ...spread(key, result.axisError),
      ...spread(key, result.paperFigure9),
    ]);
    const shown = result.lines.length > LINE_ROWS_SHOWN ? ` (the first ${LINE_ROWS_SHOWN}; CSV has all ${result.lines.length})` : '';
    const lines = table(
      `Each line${shown}${openable ? (this.#store.state.embed ? '; pick one to step through it in voxpath, in a new tab' : '; pick one to step through it in Trace mode') : ''}`,
      ['line', 'to', 'steps', 'perp max', 'perp mean', 'perp std', 'eq. 11 max', 'eq. 11 mean', 'eq. 11 std'],
      result.lines.slice(0, LINE_ROWS_SHOWN).map((l, i) => [String(i + 1), `(${l.to.join(', ')})`, String(l.steps), ...stats(l.perpendicular), ...stats(l.axisError)]),
      'lines-table',
    );
    if (openable) {
      lines.tBodies[0]!.querySelectorAll('tr').forEach((row, i) => {
        const line = result.lines[i]!;
        const cell = row.cells[0]!;
        const open = element('button', { type: 'button', className: 'link', textContent: cell.textContent ?? '' });
        open.setAttribute('aria-label', `Trace line ${i + 1}, to (${line.to.join(', ')}), with ${result.algorithm}`);
        open.dataset.testid = `open-line-${i + 1}`;
        open.addEventListener('click', () => this.#open(result, line));
        cell.replaceChildren(open);
        row.classList.add('openable');
        // The whole row, for a pointer; the button is the keyboard's way.
        row.addEventListener('click', (event) => {
          if (event.target !== open) this.#open(result, line);
        });
      });
    }
    const same =
      previous && previous.algorithm !== result.algorithm && sameStatistics(previous, result)
        ? [
            element('p', {
              className: 'same-statistics',
              textContent:
                `Every statistic here is the one ${previous.algorithm} gave on these ${result.lines.length} lines, line for line (to the last bit of rounding): on each line the two paths stray from the ideal line alike. ` +
                'Algorithms that differ only in how they break ties can do that (open a line to see where they part).',
            }),
          ]
        : [];
    for (const note of same) note.dataset.testid = 'same-statistics';
    this.#container.replaceChildren(
      element('h2', { textContent: `${result.lines.length} random lines traced with ${result.algorithm}` }),
      element('p', { textContent: `From the origin to points with ${dims} coordinates in 0..${result.maxCoordinate} (${AXIS_NAMES.slice(0, dims).join(', ')}), seed ${result.seed}: the same seed gives the same lines everywhere.` }),
      ...same,
      element(
        'div',
        { className: 'table-scroll' },
        table(
          'Spread over the lines of each per-line statistic: perpendicular distance, Wang eq. (11) error, and Figure 9 as printed',
          ['statistic', 'perp max', 'perp min', 'perp mean', 'eq. 11 max', 'eq. 11 min', 'eq. 11 mean', 'Fig. 9 max', 'Fig. 9 min', 'Fig. 9 mean'],
          spreadRows,
          'spread-table',
        ),
      ),
      element('p', { className: 'erratum', textContent: `Erratum: ${result.paperFigure9Erratum}` }),
      element('div', { className: 'table-scroll lines-scroll' }, lines),
    );
    // Back from the line opened: its button takes the focus again, unless the focus is somewhere already.
    const opened = this.#openedLine;
    this.#openedLine = undefined;
    if (opened !== undefined && (document.activeElement === null || document.activeElement === document.body)) {
      this.#container.querySelector<HTMLButtonElement>(`[data-testid=open-line-${opened}]`)?.focus();
    }
  }
}
