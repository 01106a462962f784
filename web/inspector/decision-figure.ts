/**
 * A picture of one decision, drawn from the picture the core made of it
 * (StepDetail.figure, by kind; the 3D overlay, scene/decision-overlay.ts,
 * draws from the same value):
 * - exitFace (Wang's discriminate regions): the exit face with its regions
 *   a-d, the segments e-h and the center o between them, the region the
 *   line crosses, the point where it crosses and the corner A-D it picked;
 * - errorTerms (Bresenham): one bar per error term against the threshold
 *   it is compared with;
 * - arcCandidates (Saleem's circle): the residual of each candidate, the
 *   one the step took marked.
 * A step with no picture gets none: the table of values above it has every
 * column.
 */
import type { ArcCandidates, DecisionFigure, ErrorTerms, ExitFace } from '../core/types.js';
import { AXIS_NAMES } from '../format.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg<K extends keyof SVGElementTagNameMap>(tag: K, attributes: Record<string, string | number>, text?: string): SVGElementTagNameMap[K] {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attributes)) e.setAttribute(k, String(v));
  if (text !== undefined) e.textContent = text;
  return e;
}

/**
 * The exit face in its own frame, as the core gives it (face coordinates,
 * cells from its center): the first passive axis (u) runs right, the second
 * (v) up. The figure shows half a cell of the exit plane around the face:
 * the crossing lies within (-1, 1) of the center, off the face when the line
 * left Wang's unit cell through a side, and the regions are the plane's
 * quadrants, so they are drawn on past the face, fainter.
 */
const SIZE = 100;
const PAD = 22;
/** Face coordinates the figure shows beyond the face on each side. */
const MARGIN = 0.5;
const EXTENT = (1 + 2 * MARGIN) * SIZE + 2 * PAD;
/** Thickness of an edge's halves (one passive axis), SVG pixels. */
const EDGE_PX = 12;

/** Face coordinates (cells from the face's center, v up) to SVG pixels. */
const px = (u: number) => PAD + (u + 0.5 + MARGIN) * SIZE;
const py = (v: number) => PAD + (0.5 + MARGIN - v) * SIZE;

/** A rectangle between two face points, in SVG pixels. */
function box(u1: number, v1: number, u2: number, v2: number): { x: number; y: number; width: number; height: number } {
  return { x: px(Math.min(u1, u2)), y: py(Math.max(v1, v2)), width: Math.abs(u2 - u1) * SIZE, height: Math.abs(v2 - v1) * SIZE };
}

/** '+y': a signed axis as people read it. */
const signedName = (a: { axis: number; sign: number }) => `${a.sign < 0 ? '-' : '+'}${AXIS_NAMES[a.axis]}`;

function exitFaceFigure(face: ExitFace): SVGSVGElement {
  const { region, corner } = face;
  const edge = face.vAxis === null;
  const [u, v] = face.crossing;
  // An edge needs only a band of the figure around it.
  const top = edge ? py(-0.5) - 3 * EDGE_PX : 0;
  const height = edge ? 6 * EDGE_PX + 16 : EXTENT;
  const root = svg('svg', { viewBox: `0 ${top} ${EXTENT} ${height}`, role: 'img', class: 'face-figure' });
  const where = 'abcd'.includes(region) ? `region ${region}` : region === 'o' ? 'the center o' : `segment ${region}`;
  const at = edge ? `${u} cells from the middle of the edge B-A` : `(${u}, ${v}) cells from the face's center`;
  root.append(svg('title', {}, `The exit face: the ideal line crosses the exit plane at ${at}, in ${where}; the step goes to corner ${corner}.`));
  for (const r of face.regions) {
    const [qu, qv] = r.quadrant;
    const chosen = r.name === region ? ' chosen' : '';
    // The quadrant of the plane out to the figure's edge, under the face's part of it; an edge's halves as bars on it.
    const plane = edge ? box(0, -0.5, qu * (0.5 + MARGIN), -0.5) : box(0, 0, qu * (0.5 + MARGIN), qv * (0.5 + MARGIN));
    const part = edge ? box(0, -0.5, qu * 0.5, -0.5) : box(0, 0, qu * 0.5, qv * 0.5);
    if (edge) for (const b of [plane, part]) Object.assign(b, { y: b.y - EDGE_PX / 2, height: EDGE_PX });
    root.append(svg('rect', { ...plane, class: `face-plane face-plane-${r.name}` }));
    root.append(svg('rect', { ...part, class: `face-region face-region-${r.name}${chosen}` }));
    root.append(svg('text', { x: px(qu * 0.25), y: (edge ? py(-0.5) - EDGE_PX : py(qv * 0.25)) + 5, class: 'face-label' }, r.name));
  }
  for (const s of face.segments) {
    const chosen = s.name === region ? ' chosen' : '';
    const [[u1, v1], [u2, v2]] = [s.from, s.to];
    if (u1 === u2 && v1 === v2) {
      // A point: the center o, or e between A and B on an edge.
      root.append(svg('circle', { cx: px(u1), cy: py(v1), r: chosen ? 6 : 3.5, class: `face-center${chosen}` }));
      continue;
    }
    const vertical = u1 === u2;
    root.append(svg('line', { x1: px(u1), y1: py(v1), x2: px(u2), y2: py(v2), class: `face-segment${chosen}` }));
    root.append(svg('text', { x: px((u1 + u2) / 2) + (vertical ? 8 : 0), y: py((v1 + v2) / 2) + (vertical ? 4 : -5), class: 'face-segment-label' }, s.name));
  }
  for (const c of face.corners) {
    const [cu, cv] = c.at;
    const chosen = c.name === corner;
    root.append(svg('circle', { cx: px(cu), cy: py(cv), r: chosen ? 8 : 5, class: chosen ? 'face-corner chosen' : 'face-corner' }));
    root.append(svg('text', { x: px(cu) + (cu > 0 ? 10 : -18), y: py(cv) + (cv > 0 ? -6 : 16), class: 'face-corner-label' }, c.name));
  }
  root.append(svg('circle', { cx: px(u), cy: py(v), r: 5.5, class: 'face-crossing', 'data-testid': 'face-crossing' }));
  root.append(svg('text', { x: EXTENT / 2, y: top + height - 4, class: 'face-axis' }, `first passive axis ${signedName(face.uAxis)} steps (M > 0) →`));
  if (face.vAxis) {
    root.append(svg('text', { x: 10, y: EXTENT / 2, class: 'face-axis', transform: `rotate(-90 10 ${EXTENT / 2})` }, `second, ${signedName(face.vAxis)} (N > 0) →`));
  }
  return root;
}

/** Width of a character of a bar's value (12 px system-ui, style.css .bar-value), at most: digits, signs, letters of a note. */
const BAR_VALUE_CHAR_PX = 7;

/** Bars of `values` (label, value, chosen) on one scale, with an optional threshold line. */
function bars(title: string, values: { label: string; value: number; note?: string }[], threshold?: { label: string; value: number }): SVGSVGElement {
  const width = 260;
  const rowHeight = 22;
  const labelWidth = 70;
  const height = values.length * rowHeight + 28;
  const largest = Math.max(1, ...values.map((v) => Math.abs(v.value)), Math.abs(threshold?.value ?? 0));
  const min = Math.min(0, ...values.map((v) => v.value));
  const span = largest - min;
  const valueText = (v: { value: number; note?: string }) => `${v.value}${v.note ? ` ${v.note}` : ''}`;
  // Room right of the longest bar for its value and note ("9 (taken)" ran past the edge in a fixed 40).
  const valueRoom = 8 + BAR_VALUE_CHAR_PX * Math.max(4, ...values.map((v) => valueText(v).length));
  const x = (v: number) => labelWidth + ((v - min) / span) * (width - labelWidth - valueRoom);
  const root = svg('svg', { viewBox: `0 0 ${width} ${height}`, role: 'img', class: 'bars-figure' });
  root.append(svg('title', {}, title));
  values.forEach((v, i) => {
    const y = 6 + i * rowHeight;
    root.append(svg('text', { x: 4, y: y + 14, class: 'bar-label' }, v.label));
    const x0 = x(Math.min(0, v.value));
    const x1 = x(Math.max(0, v.value));
    root.append(svg('rect', { x: x0, y, width: Math.max(1, x1 - x0), height: rowHeight - 6, class: v.note ? 'bar chosen' : 'bar' }));
    root.append(svg('text', { x: x1 + 4, y: y + 13, class: 'bar-value' }, valueText(v)));
  });
  root.append(svg('line', { x1: x(0), y1: 2, x2: x(0), y2: height - 20, class: 'bar-axis' }));
  if (threshold) {
    const t = x(threshold.value);
    root.append(svg('line', { x1: t, y1: 2, x2: t, y2: height - 20, class: 'bar-threshold' }));
    root.append(svg('text', { x: Math.min(t, width - 90), y: height - 6, class: 'bar-threshold-label' }, `${threshold.label} ${threshold.value}`));
  }
  return root;
}

/** Each error term against the threshold it is compared with (Bresenham), the terms whose axis stepped marked. */
function errorTermsFigure(e: ErrorTerms): SVGSVGElement {
  return bars(
    'Each error term against the threshold it is compared with: an axis steps when its error is above it (on it, as the tie policy says).',
    e.terms.map((t) => ({ label: t.name, value: t.value, note: t.steps ? '(steps)' : undefined })),
    { label: 'threshold', value: e.threshold },
  );
}

/** The residual of each of the circle's candidates, the one taken marked. */
function residualsFigure(c: ArcCandidates): SVGSVGElement {
  return bars(
    'The residual x² + y² − r² of each candidate: the step takes the one nearer zero.',
    c.candidates.map((k) => ({ label: k.name, value: k.residual, note: k.taken ? '(taken)' : undefined })),
  );
}

/** The picture of a step's decision, or undefined where it has none (the start point, a step of a rule with no picture). */
export function decisionFigure(figure: DecisionFigure | null): SVGSVGElement | undefined {
  switch (figure?.kind) {
    case 'exitFace':
      return exitFaceFigure(figure);
    case 'errorTerms':
      return errorTermsFigure(figure);
    case 'arcCandidates':
      return residualsFigure(figure);
    case undefined:
      return undefined;
  }
}
