/**
 * The shown step's decision in the 3D view (the "Decision in 3D" toggle),
 * drawn from the core's picture of it (StepDetail.figure, the value the
 * inspector's figure draws too), by its kind. A G-code trace has the steps
 * of its line and its arc algorithm, each with its own picture, so a program
 * shows the exit face on its lines and the candidates on its arcs.
 */
import type * as THREE from 'three';
import type { FigureKind, StepDetail } from '../core/types.js';
import { ArcCandidateCells } from './arc-candidates.js';
import { RegionFace } from './region-face.js';

export type Overlay = THREE.Object3D & { dispose(): void };

/** What the toggle draws for each picture that has a 3D form, for its tooltip. */
const DESCRIBED: Partial<Record<FigureKind, string>> = {
  exitFace: "Wang's exit face, its regions a-d, where the ideal line crosses it and the corner A-D taken",
  arcCandidates: "Saleem's two candidate cells, each with its residual x² + y² − r², the one taken solid",
};

/**
 * Pictures with no form in the 2D view: the exit face holds both passive
 * axes, and a path in one plane has the plane's normal among them, so seen
 * down that normal the face is a line, its corners and regions two by two
 * on one another (A on D, a on d: a column of overlapping letters).
 */
const EDGE_ON_IN_2D: readonly FigureKind[] = ['exitFace'];

/** Whether a picture of this kind has a form in the 2D view (`flat`) or in 3D. */
function drawnIn(kind: FigureKind, flat: boolean): boolean {
  return !(flat && EDGE_ON_IN_2D.includes(kind));
}

/**
 * What the toggle would draw for a trace whose steps have the pictures
 * `figures` (its summary's), one phrase each, in the 2D view (`flat`) or
 * in 3D; empty when none has a form there.
 */
export function decisionOverlayKinds(figures: readonly FigureKind[], flat: boolean): string[] {
  return figures.filter((kind) => drawnIn(kind, flat)).flatMap((kind) => DESCRIBED[kind] ?? []);
}

/** The overlay of the step a detail describes in the 2D view (`flat`) or in 3D, or undefined when its decision has no picture there (the start point has no decision). */
export function decisionOverlay(detail: StepDetail, flat: boolean): Overlay | undefined {
  const figure = detail.figure;
  if (figure && !drawnIn(figure.kind, flat)) return undefined;
  switch (figure?.kind) {
    case 'exitFace':
      return new RegionFace(figure, detail.point);
    case 'arcCandidates':
      return new ArcCandidateCells(figure);
    default:
      return undefined;
  }
}
