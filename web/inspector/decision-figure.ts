/**
 * A picture of one decision, chosen by which columns the trace has and the
 * step fills (never by the algorithm's id), drawn from the values the core
 * replayed:
 * - region and corner (Wang's discriminate regions): the exit face with its
 *   regions a-d, the segments e-h and the center o between them, the region
 *   the core says the line crosses, the point where it crosses (faceU,
 *   faceV) and the corner A-D it picked;
 * - threshold and error columns (Bresenham): one bar per error term against
 *   the threshold it is compared with;
 * - residualStay and residualMove (Saleem's circle): the residual of each
 *   candidate, the one the step took marked.
 * A G-code trace has the columns of both its algorithms; each step gets the
 * figure of the algorithm that took it.
 * Nothing else is drawn: the table of values above it has every column.
 */
import { readDecision } from '../core/export.js';
import type { ColumnSpec } from '../core/types.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attributes: Record<string, string | number>, text?: string): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

/** A decision's values by column name, as the core gives them (NaN or NO_VALUE where a column does not apply). */
export type DecisionRow = Record<string, number>;

/** The label of category column `name`, or undefined where it does not apply to the step. */
function label(columns: readonly ColumnSpec[], name: string, value: number): string | undefined {
  const column = columns.find((c) => c.name === name);
  const readable = column && readDecision(column, value);
  return typeof readable === 'string' ? readable : undefined;
}

/**
 * The exit face of a regions decision, read from the core's columns: the
 * region and corner, where the ideal line crosses the exit plane (faceU,
 * faceV) and the grid axis and direction each face coordinate runs along
 * (faceUAxis, faceVAxis). Undefined when the trace has no such columns
 * or the step no face (a type ② line, or a step of another algorithm in a
 * G-code program).
 */
export interface ExitFace {
  region: string;
  corner: string;
  /** Cells from the face's center along the first passive axis, positive the way it travels. */
  u: number;
  /** The same along the second passive axis; undefined with one passive axis (the line leaves through an edge). */
  v: number | undefined;
  /** Grid axis (0 = x) and direction (+1 or -1) of u, and of v when there is one. */
  uAxis: number;
  uSign: 1 | -1;
  vAxis: number | undefined;
  vSign: 1 | -1;
}

/**
 * A signed-axis label ('+y', '-z': the core's SIGNED_AXIS_LABELS) as its grid
 * axis and direction; undefined where the step has none.
 */
function signedAxis(text: string | undefined): { axis: number; sign: 1 | -1 } | undefined {
  if (text === undefined) return undefined;
  return { axis: 'xyz'.indexOf(text[1]!), sign: text[0] === '-' ? -1 : 1 };
}

/** True when the trace has every one of `names` among its columns. */
export const hasColumns = (columns: readonly ColumnSpec[], names: readonly string[]) => names.every((name) => columns.some((c) => c.name === name));

/** The columns exitFaceOf reads. */
export const EXIT_FACE_COLUMNS = ['region', 'corner', 'faceU', 'faceV', 'faceUAxis', 'faceVAxis'] as const;

export function exitFaceOf(columns: readonly ColumnSpec[], row: DecisionRow | undefined): ExitFace | undefined {
  if (!row || !hasColumns(columns, EXIT_FACE_COLUMNS)) return undefined;
  const region = label(columns, 'region', row.region!);
  const corner = label(columns, 'corner', row.corner!);
  const u = signedAxis(label(columns, 'faceUAxis', row.faceUAxis!));
  const v = signedAxis(label(columns, 'faceVAxis', row.faceVAxis!));
  if (!region || !corner || !u || Number.isNaN(row.faceU!)) return undefined;
  return {
    region,
    corner,
    u: row.faceU!,
    v: v && !Number.isNaN(row.faceV!) ? row.faceV! : undefined,
    uAxis: u.axis,
    uSign: u.sign,
    vAxis: v?.axis,
    vSign: v?.sign ?? 1,
  };
}

/**
 * The two candidates of a step of Saleem's circle (section 4, eq. 6-7),
 * read from the core's columns: the cell not taken as a grid axis and
 * direction from the point the step reached (otherCandidate), and the
 * residual x² + y² − r² of each, the stay candidate (only the fast axis
 * steps) and the move candidate (the slow axis steps too). Undefined when
 * the trace has no such columns or the step made no such decision (a
 * correction step, a helix step of the linear axis alone, a line step in a
 * G-code program).
 */
export interface ArcCandidates {
  /** Grid axis (0 = x) and direction (+1 or -1) from the reached point to the candidate not taken. */
  otherAxis: number;
  otherSign: 1 | -1;
  /** Whether the reached point is the move candidate (the slow axis stepped) rather than the stay one. */
  tookMove: boolean;
  residualStay: number;
  residualMove: number;
}

/** The columns arcCandidatesOf reads. */
export const ARC_CANDIDATE_COLUMNS = ['otherCandidate', 'slowSteps', 'residualStay', 'residualMove'] as const;

export function arcCandidatesOf(columns: readonly ColumnSpec[], row: DecisionRow | undefined): ArcCandidates | undefined {
  if (!row || !hasColumns(columns, ARC_CANDIDATE_COLUMNS)) return undefined;
  const other = signedAxis(label(columns, 'otherCandidate', row.otherCandidate!));
  if (!other || Number.isNaN(row.residualStay!) || Number.isNaN(row.residualMove!)) return undefined;
  return { otherAxis: other.axis, otherSign: other.sign, tookMove: row.slowSteps === 1, residualStay: row.residualStay!, residualMove: row.residualMove! };
}

/**
 * Wang's Figure 4b in the face's own frame: the first passive axis (M)
 * runs right, the second (N) up. B is the corner where neither steps, A
 * where the first does, C the second, D both; region x lies at corner X,
 * segment e between A and B, f between B and C, g between C and D, h between
 * D and A (the column docs and the core's explanations name them so).
 *
 * The figure shows half a cell of the exit plane around the face: the ideal
 * line crosses the plane within (-1, 1) of the face's center (the faceU
 * column's doc), off the face when it left Wang's unit cell through a side,
 * and the regions are the plane's quadrants, so they are drawn on past the
 * face, fainter.
 */
const SIZE = 100;
const PAD = 22;
/** Face coordinates the figure shows beyond the face (0..1) on each side. */
const MARGIN = 0.5;
const CORNERS: Record<string, [number, number]> = { A: [1, 0], B: [0, 0], C: [0, 1], D: [1, 1] };
const QUADRANTS: Record<string, [number, number]> = { a: [0.5, 0], b: [0, 0], c: [0, 0.5], d: [0.5, 0.5] };
const SEGMENTS: Record<string, [number, number, number, number]> = {
  e: [0.5, 0, 0.5, 0.5],
  f: [0, 0.5, 0.5, 0.5],
  g: [0.5, 0.5, 0.5, 1],
  h: [0.5, 0.5, 1, 0.5],
};
const EXTENT = (1 + 2 * MARGIN) * SIZE + 2 * PAD;

/** Face coordinates (0..1 on the face, y up) to SVG pixels. */
const px = (u: number) => PAD + (u + MARGIN) * SIZE;
const py = (v: number) => PAD + (1 + MARGIN - v) * SIZE;

/** "(0.6, 0.3)": a crossing as the figure's title reads it. */
const pair = (u: number, v: number | undefined) => (v === undefined ? `${u}` : `(${u}, ${v})`);

function regionFace(face: ExitFace): SVGSVGElement {
  const { region, corner } = face;
  const root = svg('svg', { viewBox: `0 0 ${EXTENT} ${EXTENT}`, role: 'img', class: 'face-figure' });
  const where = region.length === 1 && 'abcd'.includes(region) ? `region ${region}` : region === 'o' ? 'the center o' : `segment ${region}`;
  root.append(
    svg('title', {}, `The exit face: the ideal line crosses the exit plane at ${pair(face.u, face.v)} cells from the face's center, in ${where}; the step goes to corner ${corner}.`),
  );
  for (const [name, [u, v]] of Object.entries(QUADRANTS)) {
    // The quadrant of the plane, out to the figure's edge, under the face's part of it.
    const [u0, v0] = [u === 0 ? -MARGIN : u, v === 0 ? -MARGIN : v];
    root.append(svg('rect', { x: px(u0), y: py(v0 + 0.5 + MARGIN), width: (0.5 + MARGIN) * SIZE, height: (0.5 + MARGIN) * SIZE, class: `face-plane face-plane-${name}` }));
  }
  for (const [name, [u, v]] of Object.entries(QUADRANTS)) {
    const chosen = name === region;
    root.append(svg('rect', { x: px(u), y: py(v + 0.5), width: SIZE / 2, height: SIZE / 2, class: `face-region face-region-${name}${chosen ? ' chosen' : ''}` }));
    root.append(svg('text', { x: px(u + 0.25), y: py(v + 0.25) + 5, class: 'face-label' }, name));
  }
  for (const [name, [u1, v1, u2, v2]] of Object.entries(SEGMENTS)) {
    root.append(svg('line', { x1: px(u1), y1: py(v1), x2: px(u2), y2: py(v2), class: name === region ? 'face-segment chosen' : 'face-segment' }));
    root.append(svg('text', { x: px((u1 + u2) / 2) + (u1 === u2 ? 8 : 0), y: py((v1 + v2) / 2) + (u1 === u2 ? 4 : -5), class: 'face-segment-label' }, name));
  }
  root.append(svg('circle', { cx: px(0.5), cy: py(0.5), r: region === 'o' ? 6 : 3.5, class: region === 'o' ? 'face-center chosen' : 'face-center' }));
  for (const [name, [u, v]] of Object.entries(CORNERS)) {
    const chosen = name === corner;
    root.append(svg('circle', { cx: px(u), cy: py(v), r: chosen ? 8 : 5, class: chosen ? 'face-corner chosen' : 'face-corner' }));
    root.append(svg('text', { x: px(u) + (u ? 10 : -18), y: py(v) + (v ? -6 : 16), class: 'face-corner-label' }, name));
  }
  // The crossing, in the face's frame (its center at 0.5, 0.5). A line with
  // one passive axis leaves through the edge B-A (a missing N counts as
  // negative, as the region says), so it is drawn on that edge.
  root.append(svg('circle', { cx: px(0.5 + face.u), cy: py(face.v === undefined ? 0 : 0.5 + face.v), r: 5.5, class: 'face-crossing', 'data-testid': 'face-crossing' }));
  root.append(svg('text', { x: EXTENT / 2, y: EXTENT - 4, class: 'face-axis' }, 'first passive axis steps (M > 0) →'));
  root.append(svg('text', { x: 10, y: EXTENT / 2, class: 'face-axis', transform: `rotate(-90 10 ${EXTENT / 2})` }, 'second (N > 0) →'));
  return root;
}

/** Bars of `values` (label, value, chosen) on one scale, with an optional threshold line. */
function bars(title: string, values: { label: string; value: number; note?: string }[], threshold?: { label: string; value: number }): SVGSVGElement {
  const width = 260;
  const rowHeight = 22;
  const labelWidth = 70;
  const height = values.length * rowHeight + 28;
  const largest = Math.max(1, ...values.map((v) => Math.abs(v.value)), Math.abs(threshold?.value ?? 0));
  const min = Math.min(0, ...values.map((v) => v.value));
  const span = largest - min;
  const x = (v: number) => labelWidth + ((v - min) / span) * (width - labelWidth - 40);
  const root = svg('svg', { viewBox: `0 0 ${width} ${height}`, role: 'img', class: 'bars-figure' });
  root.append(svg('title', {}, title));
  values.forEach((v, i) => {
    const y = 6 + i * rowHeight;
    root.append(svg('text', { x: 4, y: y + 14, class: 'bar-label' }, v.label));
    const x0 = x(Math.min(0, v.value));
    const x1 = x(Math.max(0, v.value));
    root.append(svg('rect', { x: x0, y, width: Math.max(1, x1 - x0), height: rowHeight - 6, class: v.note ? 'bar chosen' : 'bar' }));
    root.append(svg('text', { x: x1 + 4, y: y + 13, class: 'bar-value' }, `${v.value}${v.note ? ` ${v.note}` : ''}`));
  });
  root.append(svg('line', { x1: x(0), y1: 2, x2: x(0), y2: height - 20, class: 'bar-axis' }));
  if (threshold) {
    const t = x(threshold.value);
    root.append(svg('line', { x1: t, y1: 2, x2: t, y2: height - 20, class: 'bar-threshold' }));
    root.append(svg('text', { x: Math.min(t, width - 90), y: height - 6, class: 'bar-threshold-label' }, `${threshold.label} ${threshold.value}`));
  }
  return root;
}

/**
 * Each error term against the threshold it is compared with (Bresenham);
 * undefined where the step has none. The core marks both kinds of column
 * with their role.
 */
function thresholdFigure(columns: readonly ColumnSpec[], row: DecisionRow): SVGSVGElement | undefined {
  const threshold = columns.find((c) => c.role === 'threshold');
  if (!threshold || Number.isNaN(row[threshold.name]!)) return undefined;
  const errors = columns.filter((c) => c.role === 'errorTerm' && !Number.isNaN(row[c.name]!));
  if (errors.length === 0) return undefined;
  return bars(
    'Each error term against the threshold it is compared with; the sentence above says which axes stepped.',
    errors.map((c) => ({ label: c.name, value: row[c.name]! })),
    { label: threshold.name, value: row[threshold.name]! },
  );
}

/** The residual of each of the circle's candidates, the one taken marked; undefined where the step has none. */
function residualsFigure(columns: readonly ColumnSpec[], row: DecisionRow): SVGSVGElement | undefined {
  const c = arcCandidatesOf(columns, row);
  if (!c) return undefined;
  return bars('The residual x² + y² − r² of each candidate: the step takes the one nearer zero.', [
    { label: 'stay', value: c.residualStay, note: c.tookMove ? undefined : '(taken)' },
    { label: 'move', value: c.residualMove, note: c.tookMove ? '(taken)' : undefined },
  ]);
}

/**
 * The figures, each drawn only where its columns apply to the step: a
 * G-code trace has the columns of its line and its arc algorithm, and a
 * step of one leaves the other's empty, so the first figure that applies is
 * shown, not the first whose columns the trace has.
 */
const FIGURES: ((columns: readonly ColumnSpec[], row: DecisionRow) => SVGSVGElement | undefined)[] = [
  (columns, row) => {
    const face = exitFaceOf(columns, row);
    return face && regionFace(face);
  },
  thresholdFigure,
  residualsFigure,
];

/** The picture for `row`, or undefined when no figure applies to it (or the start point has no decision). */
export function decisionFigure(columns: readonly ColumnSpec[], row: DecisionRow | undefined): SVGSVGElement | undefined {
  if (!row) return undefined;
  for (const figure of FIGURES) {
    const drawn = figure(columns, row);
    if (drawn) return drawn;
  }
  return undefined;
}
