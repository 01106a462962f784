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
  AlgorithmInfo,
  Catalogue,
  ColumnKind,
  DeviationBound,
  Example,
  Family,
  Limit,
  Metrics,
  OptionKind,
  OptionSpec,
  PerAxis,
  TiePolicy,
  TraceOptions,
  TraceSummary,
} from './pkg/voxpath.js';
import type { Column, IdealPathInfo, SegmentSummary } from './pkg/voxpath.js';

/** How to read one decision column (the core's `trace::Column`). */
export type ColumnSpec = Column;

/** One stretch of a trace produced by one stepper (the core's `trace::SegmentSummary`). */
export type SegmentInfo = SegmentSummary;

/** The path the steps approximate, as the core describes it (grid units). */
export type IdealPath = IdealPathInfo;

/** Decision columns over a range of step indices; each array has one entry per step. */
export type DecisionColumns = Record<string, Float64Array | Uint8Array>;
