/**
 * A trace written out for people and programs: JSON, CSV and a plain-text
 * table. The CLI and the page's export both use these, so the formats agree.
 *
 * Row convention (CSV and table): row k is point k together with the
 * decision that produced it (the decision of step k - 1, empty on row 0),
 * as Wang's Tables 1 and 2 print them.
 */
import { AXIS_NAMES } from './axes.js';
import type { Check } from './check.js';
import { argumentError, describeValue, plainData } from './guard.js';
import type { Comparison, StepWhy } from './compare.js';
import type { MeasureSummary, RandomLinesResult } from './experiment.js';
import { type Trace, requireTrace } from './trace.js';
import { type ColumnSpec, type DecisionColumns, NO_VALUE } from './types.js';

/**
 * A decision value as people read it: a category's label, a flag's boolean,
 * a plain number, or null where the column does not apply to the step (NaN
 * in a number column, NO_VALUE in a category or flag column).
 */
export function readDecision(column: ColumnSpec, value: number): string | number | boolean | null {
  plainData<ColumnSpec>('column', column, ['name', 'kind'], "a decision column (from a trace's columns)");
  if (typeof value !== 'number') throw argumentError('value', `expected a decision value (a number), got ${describeValue(value)}`);
  // A category's value is a label's index and a flag's 0 or 1 (or NO_VALUE):
  // anything else came from another column, and was handed back as it was.
  const labels = column.kind === 'category' ? (column.labels?.length ?? 0) : column.kind === 'flag' ? 2 : undefined;
  if (labels !== undefined && !Number.isNaN(value) && value !== NO_VALUE && !(Number.isInteger(value) && value >= 0 && value < labels)) {
    throw argumentError('value', `${value} is not a value of the ${column.kind} column ${column.name}: 0 to ${labels - 1}, or NO_VALUE (${NO_VALUE}) where it does not apply`);
  }
  return decisionValue(column, value);
}

/** readDecision, unchecked: for the writers' loops over a trace's own columns. */
function decisionValue(column: ColumnSpec, value: number): string | number | boolean | null {
  if (Number.isNaN(value)) return null;
  if (column.kind === 'category') return value === NO_VALUE ? null : (column.labels?.[value] ?? value);
  if (column.kind === 'flag') return value === NO_VALUE ? null : value === 1;
  return value;
}

/** A table's cell for a column that does not apply to the step (JSON's null). */
const TABLE_NO_VALUE = '-';

export interface TraceJson {
  algorithm: string;
  dims: number;
  steps: number;
  /** steps + 1 points; points[k] is the position after k steps. */
  points: number[][];
  /** decisions[name][k] is the value that produced points[k + 1]. */
  decisions: Record<string, (string | number | boolean | null)[]>;
  /** deviation[k] belongs to points[k]. */
  deviation: number[];
  metrics: Trace['metrics'];
  /** What each segment's setup was (line type, initial discriminants, ...). */
  notes: string[];
}

/** The whole trace as one plain object. For long traces prefer traceJsonChunks, whose text is the same. */
export function traceToJson(trace: Trace): TraceJson {
  return JSON.parse([...traceJsonChunks(trace)].join('')) as TraceJson;
}

/**
 * Rows of a trace an export reads from the core at a time: its strings then
 * take a few megabytes, whatever the length of the trace (a 10,000,000-step
 * CSV streams from the CLI in about as much memory as the trace itself).
 */
export const EXPORT_CHUNK_ROWS = 16_384;

/** Indices [from, to) of 0..count in chunks of at most EXPORT_CHUNK_ROWS (rows of points, steps or moves). */
export function* indexChunks(count: number): Generator<[number, number]> {
  for (let from = 0; from < count; from += EXPORT_CHUNK_ROWS) yield [from, Math.min(count, from + EXPORT_CHUNK_ROWS)];
}

/**
 * The trace as JSON text (the CLI's --format json), in pieces of at most
 * EXPORT_CHUNK_ROWS rows: the object of TraceJson, key for key. Decisions
 * are column by column, as TraceJson holds them, so each column replays the
 * steps once.
 */
export function* traceJsonChunks(trace: Trace): Generator<string> {
  requireTrace('trace', trace);
  yield `{"algorithm":${JSON.stringify(trace.algorithm)},"dims":${trace.dims},"steps":${trace.steps},"points":[`;
  yield* pointsJsonChunks(trace);
  yield '],"decisions":{';
  for (const [i, column] of trace.columns.entries()) {
    yield `${i > 0 ? ',' : ''}${JSON.stringify(column.name)}:[`;
    yield* jsonListChunks(
      trace.steps,
      (from, to) => trace.decisionsInRange(from, to)[column.name]!,
      (v) => decisionValue(column, v),
    );
    yield ']';
  }
  yield '},"deviation":[';
  yield* jsonListChunks(trace.steps + 1, (from, to) => trace.deviationInRange(from, to));
  yield `],"metrics":${JSON.stringify(trace.metrics)},"notes":${JSON.stringify(trace.segments.map((s) => s.note))}}`;
}

/**
 * Values 0..count as JSON list items (without the list's brackets), read
 * `read(from, to)` EXPORT_CHUNK_ROWS at a time, each written as `value` gives it.
 */
export function* jsonListChunks<T>(count: number, read: (from: number, to: number) => ArrayLike<T>, value: (v: T) => unknown = (v) => v): Generator<string> {
  for (const [from, to] of indexChunks(count)) yield (from > 0 ? ',' : '') + Array.from(read(from, to), (v) => JSON.stringify(value(v))).join(',');
}

/**
 * Every point of a trace as JSON rows (`[0,0,0],[1,1,1],...`, without the
 * list's brackets), EXPORT_CHUNK_ROWS rows at a time.
 */
export function* pointsJsonChunks(trace: Trace): Generator<string> {
  for (const [from, to] of indexChunks(trace.steps + 1)) {
    const flat = trace.pointsInRange(from, to);
    const rows: string[] = [];
    for (let k = 0; k < to - from; k++) rows.push(`[${flat.subarray(k * trace.dims, (k + 1) * trace.dims).join(',')}]`);
    yield (from > 0 ? ',' : '') + rows.join(',');
  }
}

/** Columns separated by two spaces: numbers right-aligned, the label columns of indices `labels` left-aligned. */
export function alignedTable(header: string[], body: string[][], labels: readonly number[] = []): string[] {
  const widths = header.map((h, i) => body.reduce((width, r) => Math.max(width, r[i]!.length), h.length));
  const pad = (cell: string, i: number) => (labels.includes(i) ? cell.padEnd(widths[i]!) : cell.padStart(widths[i]!));
  const line = (r: string[]) => r.map(pad).join('  ');
  return [line(header), ...body.map(line)];
}

/** The per-point table's header: k, the axes, the decision columns, deviation. */
function rowHeader(trace: Trace): string[] {
  return ['k', ...AXIS_NAMES.slice(0, trace.dims), ...trace.columns.map((c) => c.name), 'deviation'];
}

/**
 * Rows from..to - 1 of the per-point table, each row's cells as `cell`
 * returns them and `row` joins them. Row 0 has no decision (empty cells); a
 * column that does not apply to a step gets `absent` (CSV: empty, as null;
 * table: '-').
 */
function rows<R>(trace: Trace, from: number, to: number, absent: string, cell: (text: string) => string, row: (cells: string[]) => R): R[] {
  const flat = trace.pointsInRange(from, to);
  // Row k shows the decision of step k - 1: steps from - 1 .. to - 2.
  const firstStep = Math.max(from - 1, 0);
  const decisions: DecisionColumns = trace.decisionsInRange(firstStep, Math.max(to - 1, firstStep));
  const deviation = trace.deviationInRange(from, to);
  // Each column's text for each of its values, found once per chunk rather than per cell.
  const texts = trace.columns.map((column) => {
    const values = decisions[column.name]!;
    const known = new Map<number, string>();
    return (i: number) => {
      const value = values[i]!;
      let text = known.get(value);
      if (text === undefined) {
        const read = decisionValue(column, value);
        text = cell(read === null ? absent : typeof read === 'boolean' ? (read ? '1' : '0') : String(read));
        if (column.kind === 'category' || column.kind === 'flag') known.set(value, text);
      }
      return text;
    };
  });
  const out: R[] = [];
  const cells: string[] = new Array(1 + trace.dims + texts.length + 1);
  for (let k = from; k < to; k++) {
    let c = 0;
    cells[c++] = String(k);
    for (let a = 0; a < trace.dims; a++) cells[c++] = String(flat[(k - from) * trace.dims + a]);
    for (const text of texts) cells[c++] = k === 0 ? '' : text(k - 1 - firstStep);
    cells[c++] = deviation[k - from]!.toFixed(6);
    out.push(row(cells));
  }
  return out;
}

/** A cell as RFC 4180 writes it: quoted when it holds a quote, a comma or a line end (a lone CR ends a line for many readers). */
function csvCell(cell: string): string {
  return /[",\r\n]/.test(cell) ? `"${cell.replaceAll('"', '""')}"` : cell;
}

/** Numbers need no quoting in CSV; a label or a name might. */
const plain = (text: string) => text;

/** One CSV row per point, with a header row (the CLI's --format csv), in pieces of at most EXPORT_CHUNK_ROWS rows. */
export function* traceCsvChunks(trace: Trace): Generator<string> {
  requireTrace('trace', trace);
  yield rowHeader(trace).map(csvCell).join(',') + '\n';
  const line = (cells: string[]) => cells.join(',');
  for (const [from, to] of indexChunks(trace.steps + 1)) yield rows(trace, from, to, '', csvCell, line).join('\n') + '\n';
}

/** One CSV row per point, with a header row. For long traces prefer traceCsvChunks. */
export function traceToCsv(trace: Trace): string {
  return [...traceCsvChunks(trace)].join('');
}

/**
 * An aligned plain-text table with the metrics below it (the CLI's --format
 * table), in pieces. Each block of EXPORT_CHUNK_ROWS rows is aligned on its
 * own and starts with the header again, so that a table of any length is
 * written as it is read, the way vmstat repeats its header.
 */
export function* traceTableChunks(trace: Trace): Generator<string> {
  requireTrace('trace', trace);
  yield [`${trace.algorithm}: ${countOf(trace.steps, 'step')} from (${trace.start.join(', ')}) to (${trace.end.join(', ')})`, ...trace.segments.map((s) => s.note), ''].join('\n') + '\n';
  for (const [from, to] of indexChunks(trace.steps + 1)) {
    yield (from > 0 ? '\n' : '') + alignedTable(rowHeader(trace), rows(trace, from, to, TABLE_NO_VALUE, plain, (cells) => [...cells])).join('\n') + '\n';
  }
  const m = trace.metrics;
  const moving = m.stepsMovingAxes.map((n, i) => `${n} x ${i + 1}-axis`).join(', ');
  yield [
    '',
    `steps moving: ${moving}; pulses per axis: ${m.pulsesByAxis.join(', ')}; ties: ${m.ties}`,
    `deviation: max ${m.maxDeviation.toFixed(6)}, mean ${m.meanDeviation.toFixed(6)}, std ${m.stdDeviation.toFixed(6)}`,
    `max axis error (eq. 11): ${m.maxAxisError.map((e) => e.toFixed(6)).join(', ')}`,
    '',
  ].join('\n');
}

/** An aligned plain-text table with the metrics below it. For long traces prefer traceTableChunks. */
export function traceToTable(trace: Trace): string {
  return [...traceTableChunks(trace)].join('');
}

function lineRows(result: RandomLinesResult): { header: string[]; body: string[][] } {
  const dims = result.lines[0]?.to.length ?? 3;
  const header = [
    'line',
    ...AXIS_NAMES.slice(0, dims).map((a) => `to_${a}`),
    'steps',
    'perp_max',
    'perp_mean',
    'perp_std',
    'eq11_max',
    'eq11_mean',
    'eq11_std',
  ];
  const body = result.lines.map((l, i) => [
    String(i + 1),
    ...l.to.map(String),
    String(l.steps),
    ...[l.perpendicular, l.axisError].flatMap((s) => [s.max, s.mean, s.std].map((v) => v.toFixed(6))),
  ]);
  return { header, body };
}

/** The fields of a random-lines result the writers read. */
const RANDOM_LINES_KEYS = ['algorithm', 'seed', 'maxCoordinate', 'lines', 'perpendicular', 'axisError', 'paperFigure9', 'paperFigure9Erratum'] as const;
const RANDOM_LINES = 'a random-lines result (from randomLines())';

/** One CSV row per random line (the CLI's experiment --format csv). */
export function randomLinesToCsv(result: RandomLinesResult): string {
  const { header, body } = lineRows(plainData<RandomLinesResult>('result', result, RANDOM_LINES_KEYS, RANDOM_LINES));
  return [header, ...body].map((r) => r.join(',')).join('\n') + '\n';
}

/** Per-line rows, then the spread of each statistic beside Wang's Figure 9. */
export function randomLinesToTable(result: RandomLinesResult): string {
  const { header, body } = lineRows(plainData<RandomLinesResult>('result', result, RANDOM_LINES_KEYS, RANDOM_LINES));
  const spread = (m: MeasureSummary, key: 'max' | 'mean' | 'std') => [m[key].max, m[key].min, m[key].mean].map((v) => v.toFixed(4));
  const summary = (['mean', 'max', 'std'] as const).map((key) => [
    `delta_${key[0]!.toUpperCase()}${key.slice(1)} per line`,
    ...spread(result.perpendicular, key),
    ...spread(result.axisError, key),
    ...spread(result.paperFigure9, key),
  ]);
  const summaryHeader = ['statistic', 'perp max', 'perp min', 'perp mean', 'eq11 max', 'eq11 min', 'eq11 mean', 'Fig9 max', 'Fig9 min', 'Fig9 mean'];
  return [
    `random-lines: ${result.lines.length} lines from the origin to points in 0..${result.maxCoordinate}, traced with ${result.algorithm} (seed ${result.seed})`,
    '',
    ...alignedTable(header, body),
    '',
    'Spread over the lines of each per-line statistic (perp = perpendicular distance, eq11 = Wang eq. (11) error, Fig9 = Wang Figure 9 as printed):',
    ...alignedTable(summaryHeader, summary, [0]),
    '',
    `Note: ${result.paperFigure9Erratum}`,
    '',
  ].join('\n');
}

/** "(5, 4, 3)", or "-" for a path that has ended. */
function pointText(point: number[] | null): string {
  return point === null ? '-' : `(${point.join(', ')})`;
}

/** A side's name: its algorithm, with the value it ran where an algorithm is compared with itself by an option ("helix (saleem)"). */
function sideName(side: Comparison['a']): string {
  return side.comparedValue ? `${side.algorithm} (${side.comparedValue})` : side.algorithm;
}

/** Column labels of a comparison: the sides' names, told apart when they are the same. */
function sideLabels(c: Comparison): [string, string] {
  const [a, b] = [sideName(c.a), sideName(c.b)];
  return a === b ? [`${a} (a)`, `${b} (b)`] : [a, b];
}

/** The side-by-side quantities of a comparison: [name, a's value, b's value]. */
function comparisonRows(c: Comparison): string[][] {
  const d = c.firstDifference;
  const list = (values: number[], digits?: number) => values.map((v) => (digits === undefined ? String(v) : v.toFixed(digits))).join(' ');
  const both = (name: string, pick: (side: Comparison['a']) => string): string[] => [name, pick(c.a), pick(c.b)];
  return [
    both('steps', (s) => String(s.steps)),
    both('end', (s) => pointText(s.end)),
    both('max deviation', (s) => s.metrics.maxDeviation.toFixed(6)),
    both('mean deviation', (s) => s.metrics.meanDeviation.toFixed(6)),
    both('std deviation', (s) => s.metrics.stdDeviation.toFixed(6)),
    both('max axis error (eq. 11)', (s) => list(s.metrics.maxAxisError, 6)),
    both('pulses per axis', (s) => list(s.metrics.pulsesByAxis)),
    both('ties', (s) => String(s.metrics.ties)),
    ['cells only in this one', String(c.onlyInA.count), String(c.onlyInB.count)],
    ['first difference at point', d ? String(d.pointIndex) : '-', d ? String(d.pointIndex) : '-'],
    ['point there', pointText(d?.a ?? null), pointText(d?.b ?? null)],
    ['why', d?.aWhy?.explanation ?? '', d?.bWhy?.explanation ?? ''],
  ];
}

/** The fields of a comparison the writers read. */
const COMPARISON_KEYS = ['a', 'b', 'firstDifference', 'onlyInA', 'onlyInB'] as const;
const COMPARISON = 'a Comparison (from compare() or compareWith())';

/** A comparison as CSV: one row per quantity, one column per algorithm (the CLI's compare --format csv). */
export function comparisonToCsv(comparison: Comparison): string {
  const c = plainData<Comparison>('comparison', comparison, COMPARISON_KEYS, COMPARISON);
  return [['quantity', ...sideLabels(c)], ...comparisonRows(c)].map((r) => r.map(csvCell).join(',')).join('\n') + '\n';
}

/** Cells listed in a table, at most this many per side. */
const TABLE_CELLS = 12;

/** "M = 0, N = 10, region = g, ...": a step's decision values. */
function decisionsText(decisions: StepWhy['decisions']): string {
  return Object.entries(decisions)
    .map(([name, value]) => `${name} = ${value === null ? TABLE_NO_VALUE : String(value)}`)
    .join(', ');
}

/** A comparison for people: metrics side by side, where and why the paths part, the cells only in each (the CLI's compare --format table). */
export function comparisonToTable(comparison: Comparison): string {
  const c = plainData<Comparison>('comparison', comparison, COMPARISON_KEYS, COMPARISON);
  const labels = sideLabels(c);
  const d = c.firstDifference;
  const lines = [
    `compare ${sideName(c.a)} (a) with ${sideName(c.b)} (b), from ${pointText(c.a.start)}`,
    '',
    ...alignedTable(['', ...labels], comparisonRows(c).slice(0, 9), [0]),
    '',
  ];
  if (d === null) {
    lines.push('The paths are identical.');
  } else {
    // In steps taken, not a step index: 'after step 4' read as one short of the page's 'Step 5'.
    const where = d.pointIndex === 0 ? 'at the start' : `after ${countOf(d.pointIndex, 'step')}`;
    lines.push(`First difference: point ${d.pointIndex} (${where}): ${labels[0]} ${pointText(d.a)}, ${labels[1]} ${pointText(d.b)}.`);
    const width = Math.max(...labels.map((l) => l.length)) + 2;
    for (const [label, why] of [
      [labels[0], d.aWhy],
      [labels[1], d.bWhy],
    ] as const) {
      const head = `  ${`${label}:`.padEnd(width)}`;
      if (why === null) {
        lines.push(`${head}has no step there (its path has ended).`);
      } else {
        lines.push(`${head}${why.explanation}`, `  ${' '.repeat(width)}${decisionsText(why.decisions)}`);
      }
    }
  }
  for (const [label, cells] of [
    [labels[0], c.onlyInA],
    [labels[1], c.onlyInB],
  ] as const) {
    const shown = cells.cells.slice(0, TABLE_CELLS).map((p) => pointText(p));
    const more = cells.count > shown.length ? ` ... and ${cells.count - shown.length} more` : '';
    lines.push(cells.count === 0 ? `Cells only in ${label}: none` : `Cells only in ${label} (${cells.count}): ${shown.join(' ')}${more}`);
  }
  return lines.join('\n') + '\n';
}

/** "6,400": a count with its thousands grouped, as every count voxpath prints is. */
export function grouped(count: number): string {
  return count.toLocaleString('en-US');
}

/** "1 move", "12 moves", "6,400 steps": a count with its noun, singular for one, its thousands grouped. */
export function countOf(count: number, noun: string, plural = `${noun}s`): string {
  return `${grouped(count)} ${count === 1 ? noun : plural}`;
}

/**
 * A check for people (the CLI's check --format table, and the vitest
 * matcher's failure message): the verdict, the first difference with the
 * rule's reason and decision values, the points around it side by side,
 * and the rules the points do follow.
 */
export function checkToTable(check: Check): string {
  const c = plainData<Check>('check', check, ['algorithm', 'steps', 'yourSteps', 'firstDifference', 'alsoMatches'], 'a Check (from checkPoints())');
  const d = c.firstDifference;
  const lines: string[] = [];
  if (d === null) {
    lines.push(`${c.algorithm}: your ${countOf(c.yourSteps + 1, 'point')} follow the rule (${countOf(c.steps, 'step')}).`);
  } else {
    lines.push(`${c.algorithm}: your path parts from the rule at point ${d.pointIndex}: ${d.message}.`);
    lines.push(`why ${c.algorithm} goes there: ${d.why}`);
    if (Object.keys(d.decisions).length > 0) lines.push(`decisions: ${decisionsText(d.decisions)}`);
    lines.push('');
    const body = d.around.map((r) => [
      String(r.pointIndex),
      pointText(r.expected),
      pointText(r.got),
      r.pointIndex === d.pointIndex ? '<- first difference' : r.expected !== null && r.got !== null && r.expected.join() !== r.got.join() ? '<- differs' : '',
    ]);
    // The markers read as words, from their arrow: left-aligned.
    lines.push(...alignedTable(['k', c.algorithm, 'yours', ''], body, [3]).map((l) => l.trimEnd()));
  }
  lines.push('');
  lines.push(
    c.alsoMatches.length === 0
      ? 'your points follow no catalogue rule of this move.'
      : `your points follow: ${c.alsoMatches.map((m) => m.label).join('; ')}`,
  );
  for (const erratum of new Set(c.alsoMatches.flatMap((m) => m.errata))) lines.push(`  erratum: ${erratum}`);
  return lines.join('\n') + '\n';
}
