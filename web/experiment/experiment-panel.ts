/**
 * Experiment mode: Wang et al.'s batch of random lines (section 3.2, Figure
 * 9) as tables: one row per line (steps and the error statistics of each
 * measure), and the spread of each per-line statistic over all lines beside
 * Figure 9 as printed, with the erratum the core states about that figure.
 * The core computes every number; this only lays them out.
 */
import type { ErrorStats, MeasureSummary, RandomLinesResult } from '../core/index.js';
import { element } from '../form/options-form.js';
import { AXIS_NAMES } from '../format.js';

/** Rows of the per-line table drawn at most; the CSV export has them all. */
export const LINE_ROWS_SHOWN = 500;

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

export function renderExperiment(container: HTMLElement, result: RandomLinesResult): void {
  const dims = result.lines[0]?.to.length ?? 3;
  const stats = (s: ErrorStats) => [f4(s.max), f4(s.mean), f4(s.std)];
  const lineRows = result.lines.slice(0, LINE_ROWS_SHOWN).map((l, i) => [String(i + 1), `(${l.to.join(', ')})`, String(l.steps), ...stats(l.perpendicular), ...stats(l.axisError)]);
  const spread = (key: 'max' | 'mean' | 'std', m: MeasureSummary) => [f4(m[key].max), f4(m[key].min), f4(m[key].mean)];
  const spreadRows = (['mean', 'max', 'std'] as const).map((key) => [
    `δ_${key[0]!.toUpperCase()}${key.slice(1)} per line`,
    ...spread(key, result.perpendicular),
    ...spread(key, result.axisError),
    ...spread(key, result.paperFigure9),
  ]);
  const shown = result.lines.length > LINE_ROWS_SHOWN ? ` (the first ${LINE_ROWS_SHOWN}; CSV has all ${result.lines.length})` : '';
  container.replaceChildren(
    element('h2', { textContent: `${result.lines.length} random lines traced with ${result.algorithm}` }),
    element('p', { textContent: `From the origin to points with ${dims} coordinates in 0..${result.maxCoordinate} (${AXIS_NAMES.slice(0, dims).join(', ')}), seed ${result.seed}: the same seed gives the same lines everywhere.` }),
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
    element(
      'div',
      { className: 'table-scroll lines-scroll' },
      table(`Each line${shown}`, ['line', 'to', 'steps', 'perp max', 'perp mean', 'perp std', 'eq. 11 max', 'eq. 11 mean', 'eq. 11 std'], lineRows, 'lines-table'),
    ),
  );
}
