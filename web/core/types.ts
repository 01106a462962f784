/**
 * Types of voxpath's headless API. Index spaces are named in every field:
 * a "point index" k runs 0..=steps (points[k] is the position after k steps),
 * a "step index" k runs 0..steps-1 (step k moves points[k] to points[k+1]).
 * Coordinates are integer grid units (one cell = one motor step).
 */

/**
 * The value a category or flag column holds at a step it does not apply to
 * (a correction step has no fast axis, a line step of a G-code program no
 * octant): the core's `trace::NO_VALUE`. It is no label index and neither 0
 * nor 1, so it is never read as a real value; number columns hold NaN there.
 * JSON gives null for both, a table '-'.
 */
export const NO_VALUE = 255;

/** A point on the grid, one integer per axis, in grid units. */
export type GridPoint = ArrayLike<number>;

/**
 * The types that cross the wasm boundary are the Rust types: tsify writes
 * their TypeScript twins into the wasm package's .d.ts (see rust/src/wasm.rs),
 * with the Rust doc comments. Here they are only re-exported, some under the
 * API's names.
 */
export type {
  AlgorithmId,
  AlgorithmInfo,
  ArcCandidate,
  ArcCandidates,
  Catalogue,
  ColumnKind,
  DecisionCell,
  DecisionFigure,
  DeviationBound,
  ErrorTerm,
  ErrorTerms,
  Example,
  ExitFace,
  FaceCorner,
  FaceRegion,
  FaceSegment,
  Family,
  FigureKind,
  IntegerRangeInfo,
  NumberRangeInfo,
  Limit,
  Metrics,
  OptionKind,
  OptionSpec,
  PerAxis,
  PerAxisInfo,
  PointBounds,
  PointsProgress,
  Reading,
  SignedAxis,
  StepDetail,
  StepClocks,
  TiePolicy,
  TraceLegend,
  TraceOptions,
  TraceSummary,
} from './pkg/voxpath.js';
import type { Column, IdealPathInfo, SegmentSummary } from './pkg/voxpath.js';

// Under their own names too: a declaration file that infers them (a
// consumer's emitted .d.ts) names them so, and could not before.
export type { Column, SegmentSummary };

/** How to read one decision column (the core's `trace::Column`). */
export type ColumnSpec = Column;

/** One stretch of a trace produced by one stepper (the core's `trace::SegmentSummary`). */
export type SegmentInfo = SegmentSummary;

/** The path the steps approximate, as the core describes it (grid units). */
export type IdealPath = IdealPathInfo;

/** Decision columns over a range of step indices; each array has one entry per step. */
export type DecisionColumns = Record<string, Float64Array | Uint8Array>;

/**
 * Per-point quantities for a chart, at most the rows asked for
 * (Trace.chartSeries). Row r is point index pointIndex[r]. A range with more
 * points than rows is cut into equal buckets of consecutive points:
 * positions are the bucket's first point, deviation is the bucket's largest
 * and smallest value, so no peak is lost.
 */
export interface ChartSeries {
  pointIndex: Float64Array;
  /** One array per axis: the point's coordinate, grid units. */
  position: Float64Array[];
  /** One array per axis: where the ideal path is at the same progress (point - Wang eq. 11 error). */
  ideal: Float64Array[];
  deviationMax: Float64Array;
  deviationMin: Float64Array;
  /** True when rows are buckets of several points. */
  bucketed: boolean;
}

/**
 * The ideal path in the form WebGL draws it (Trace.idealLine()): x, y, z of
 * each vertex as 32-bit floats (a 2-axis path at z = 0; axes past the third
 * are not drawn), with the box the vertices lie in.
 */
export interface IdealLine {
  /**
   * Stride 3, grid units from `origin`: a 32-bit float keeps a vertex's
   * fraction of a cell from a point near it, where it would round a
   * coordinate near 2^30 to a multiple of 64.
   */
  xyz: Float32Array;
  /**
   * What rounding each value of `xyz` to a 32-bit float left (the exact
   * value less it, itself as a 32-bit float): xyz + rest, added in doubles,
   * is the vertex from `origin` to about 2^-48 of its distance, for drawing
   * the part of a long path the learner looks at from an origin there
   * (IdealPath). Zero where the float was exact.
   */
  rest: Float32Array;
  /** Smallest and largest x, y, z over the vertices, from `origin` (zeros when there are none). */
  min: [number, number, number];
  max: [number, number, number];
  /** The grid point the vertices are taken from (the path's start; x, y, z, in grid units). */
  origin: [number, number, number];
}
