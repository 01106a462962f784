/**
 * A trace written out for people and programs: JSON, CSV and a plain-text
 * table. The CLI and the page's export both use these, so the formats agree.
 *
 * Row convention (CSV and table): row k is point k together with the
 * decision that produced it (the decision of step k - 1, empty on row 0),
 * as Wang's Tables 1 and 2 print them.
 */
import { AXIS_NAMES } from './axes.js';
import type { MeasureSummary, RandomLinesResult } from './experiment.js';
import type { Trace } from './trace.js';
import type { ColumnSpec, DecisionColumns } from './types.js';


/** A decision value as people read it: category labels, booleans, plain numbers. */
function readable(column: ColumnSpec, value: number): string | number | boolean | null {
  if (Number.isNaN(value)) return null;
  if (column.kind === 'category') return column.labels?.[value] ?? value;
  if (column.kind === 'flag') return value === 1;
  return value;
}

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

/** The whole trace as one plain object (the CLI's --format json). */
export function traceToJson(trace: Trace): TraceJson {
  const points: number[][] = [];
  const flat = trace.points;
  for (let k = 0; k <= trace.steps; k++) {
    points.push(Array.from(flat.subarray(k * trace.dims, (k + 1) * trace.dims)));
  }
  const decisions: TraceJson['decisions'] = {};
  for (const column of trace.columns) {
    decisions[column.name] = Array.from(trace.decisions[column.name]!, (v) => readable(column, v));
  }
  return {
    algorithm: trace.algorithm,
    dims: trace.dims,
    steps: trace.steps,
    points,
    decisions,
    deviation: Array.from(trace.deviation),
    metrics: trace.metrics,
    notes: trace.segments.map((s) => s.note),
  };
}

/** Columns separated by two spaces: numbers right-aligned, a label column (the first, if asked) left-aligned. */
function alignedTable(header: string[], body: string[][], labelFirst = false): string[] {
  const widths = header.map((h, i) => Math.max(h.length, ...body.map((r) => r[i]!.length)));
  const pad = (cell: string, i: number) => (labelFirst && i === 0 ? cell.padEnd(widths[i]!) : cell.padStart(widths[i]!));
  const line = (r: string[]) => r.map(pad).join('  ');
  return [line(header), ...body.map(line)];
}

/** Header and rows of the per-point table; cells are strings. */
function rows(trace: Trace): { header: string[]; body: string[][] } {
  const header = ['k', ...AXIS_NAMES.slice(0, trace.dims), ...trace.columns.map((c) => c.name), 'deviation'];
  const flat = trace.points;
  const decisions: DecisionColumns = trace.decisions;
  const deviation = trace.deviation;
  const body: string[][] = [];
  for (let k = 0; k <= trace.steps; k++) {
    const row = [String(k)];
    for (let a = 0; a < trace.dims; a++) row.push(String(flat[k * trace.dims + a]));
    for (const column of trace.columns) {
      const value = k === 0 ? null : readable(column, decisions[column.name]![k - 1]!);
      row.push(value === null ? '' : typeof value === 'boolean' ? (value ? '1' : '0') : String(value));
    }
    row.push(deviation[k]!.toFixed(6));
    body.push(row);
  }
  return { header, body };
}

function csvCell(cell: string): string {
  return /[",\n]/.test(cell) ? `"${cell.replaceAll('"', '""')}"` : cell;
}

/** One CSV row per point, with a header row (the CLI's --format csv). */
export function traceToCsv(trace: Trace): string {
  const { header, body } = rows(trace);
  return [header, ...body].map((r) => r.map(csvCell).join(',')).join('\n') + '\n';
}

/** An aligned plain-text table with the metrics below it (the CLI's --format table). */
export function traceToTable(trace: Trace): string {
  const { header, body } = rows(trace);
  const m = trace.metrics;
  const moving = m.stepsMovingAxes.map((n, i) => `${n} x ${i + 1}-axis`).join(', ');
  return [
    `${trace.algorithm}: ${trace.steps} steps from (${trace.start.join(', ')}) to (${trace.end.join(', ')})`,
    ...trace.segments.map((s) => s.note),
    '',
    ...alignedTable(header, body),
    '',
    `steps moving: ${moving}; pulses per axis: ${m.pulsesByAxis.join(', ')}; ties: ${m.ties}`,
    `deviation: max ${m.maxDeviation.toFixed(6)}, mean ${m.meanDeviation.toFixed(6)}, std ${m.stdDeviation.toFixed(6)}`,
    `max axis error (eq. 11): ${m.maxAxisError.map((e) => e.toFixed(6)).join(', ')}`,
    '',
  ].join('\n');
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

/** One CSV row per random line (the CLI's experiment --format csv). */
export function randomLinesToCsv(result: RandomLinesResult): string {
  const { header, body } = lineRows(result);
  return [header, ...body].map((r) => r.join(',')).join('\n') + '\n';
}

/** Per-line rows, then the spread of each statistic beside Wang's Figure 9. */
export function randomLinesToTable(result: RandomLinesResult): string {
  const { header, body } = lineRows(result);
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
    ...alignedTable(summaryHeader, summary, true),
    '',
    `Note: ${result.paperFigure9Erratum}`,
    '',
  ].join('\n');
}
