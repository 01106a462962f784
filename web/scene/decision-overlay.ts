/**
 * The shown step's decision in the 3D view (the "Decision in 3D" toggle),
 * drawn from the row the inspector replayed (its listener hands it over), by
 * the first kind below whose columns apply to the step. A G-code trace has
 * the columns of its line and its arc algorithm and each step fills only its
 * own algorithm's, so a program shows the exit face on its lines and the
 * candidates on its arcs.
 */
import type * as THREE from 'three';
import type { ColumnSpec } from '../core/types.js';
import { ARC_CANDIDATE_COLUMNS, type DecisionRow, EXIT_FACE_COLUMNS, arcCandidatesOf, exitFaceOf, hasColumns } from '../inspector/decision-figure.js';
import { ArcCandidateCells } from './arc-candidates.js';
import { RegionFace } from './region-face.js';

export type Overlay = THREE.Object3D & { dispose(): void };

/** What the overlay reads of a trace: its columns and its points (3 coordinates). */
export interface OverlaidTrace {
  readonly columns: readonly ColumnSpec[];
  point(pointIndex: number): ArrayLike<number>;
}

interface OverlayKind {
  /** The columns the overlay is drawn from: a trace without them has none of it. */
  columns: readonly string[];
  /** What the toggle draws for such a trace, for its tooltip. */
  describe: string;
  /** The overlay for the step that reached `pointIndex` (>= 1), or undefined when its columns do not apply there. */
  draw(trace: OverlaidTrace, pointIndex: number, row: DecisionRow): Overlay | undefined;
}

const KINDS: OverlayKind[] = [
  {
    columns: EXIT_FACE_COLUMNS,
    describe: "Wang's exit face, its regions a-d, where the ideal line crosses it and the corner A-D taken",
    draw(trace, pointIndex, row) {
      const face = exitFaceOf(trace.columns, row);
      return face && new RegionFace(face, trace.point(pointIndex - 1), trace.point(pointIndex));
    },
  },
  {
    columns: ARC_CANDIDATE_COLUMNS,
    describe: "Saleem's two candidate cells, each with its residual x² + y² − r², the one taken solid",
    draw(trace, pointIndex, row) {
      const candidates = arcCandidatesOf(trace.columns, row);
      return candidates && new ArcCandidateCells(candidates, trace.point(pointIndex));
    },
  },
];

/** What the toggle would draw for a trace with `columns`, one phrase per overlay kind; empty when none applies. */
export function decisionOverlayKinds(columns: readonly ColumnSpec[]): string[] {
  return KINDS.filter((k) => hasColumns(columns, k.columns)).map((k) => k.describe);
}

/** The overlay of the decision `row` that reached point `pointIndex` of `trace`, or undefined when none applies (the start point has no decision). */
export function decisionOverlay(trace: OverlaidTrace, pointIndex: number, row: DecisionRow | undefined): Overlay | undefined {
  if (!row || pointIndex < 1) return undefined;
  for (const kind of KINDS) {
    const overlay = kind.draw(trace, pointIndex, row);
    if (overlay) return overlay;
  }
  return undefined;
}
