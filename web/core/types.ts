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

/** Tie rule for a discriminant equal to zero. */
export type TiePolicy = 'advance' | 'hold';

/** Options of one trace. Each algorithm documents which extra options it takes. */
export interface TraceOptions {
  /** Algorithm id, as listed by `algorithms()` (for example 'regions'). */
  algorithm: string;
  /** Start point, in grid units (2 to 6 axes, |coordinate| <= 2^30). */
  from: GridPoint;
  /** End point, same number of axes as `from`. */
  to: GridPoint;
  /** What a zero discriminant does; the default is the algorithm's source. */
  tie?: TiePolicy;
  /** Refuse paths longer than this many steps (default 50,000,000). */
  maxSteps?: number;
  /** Further algorithm-specific options. */
  [option: string]: unknown;
}

/** How to read one decision column. */
export interface ColumnSpec {
  /** Column name, as in the paper where the paper names it (M, N, ...). */
  name: string;
  /**
   * int: an exact integer (stored as float64, exact below 2^53);
   * float: a real number; category: an index into `labels`; flag: 0 or 1.
   * Where the column does not apply to a step: NaN for int and float,
   * NO_VALUE for category and flag.
   */
  kind: 'int' | 'float' | 'category' | 'flag';
  /** Labels of a category column, indexed by the stored value. */
  labels?: string[];
  /** One sentence: what the value is and where it comes from. */
  doc: string;
}

/** Decision columns over a range of step indices; each array has one entry per step. */
export type DecisionColumns = Record<string, Float64Array | Uint8Array>;

/** Whole-path statistics, computed by the core while it traces. */
export interface Metrics {
  steps: number;
  /** stepsMovingAxes[k] = number of steps that move exactly k + 1 axes. */
  stepsMovingAxes: number[];
  /** Pulses (unit moves) per axis over the whole path. */
  pulsesByAxis: number[];
  /**
   * Statistics of each point's distance from the ideal path, in grid units:
   * the perpendicular distance for a line, the radial error for an arc, the
   * distance to the helix for a helix (as `Trace.deviation`).
   */
  maxDeviation: number;
  meanDeviation: number;
  stdDeviation: number;
  /** Largest |point - ideal position at the same progress| per axis (Wang eq. 11). */
  maxAxisError: number[];
  /** Steps whose decision was a tie resolved by the tie policy. */
  ties: number;
}

/** The path the steps approximate, as the core describes it. */
export interface IdealPath {
  kind: string;
  /** Human-readable parameters (from, to, centre...), in grid units. */
  [parameter: string]: unknown;
}

/** One option an algorithm takes; CLI flags and page inputs are generated from these. */
export interface OptionSpec {
  /** Name in the JS API; the CLI flag is its kebab-case form (maxSteps -> --max-steps). */
  name: string;
  kind:
    | { type: 'point' }
    | { type: 'number' }
    /** min and max (inclusive) where the option declares a range. */
    | { type: 'integer'; min?: number; max?: number }
    | { type: 'choice'; values: string[] }
    | { type: 'boolean' };
  required: boolean;
  /** Default shown to users, or null when required or derived from other input. */
  default: string | null;
  doc: string;
}

/** One catalogued algorithm. */
export interface AlgorithmInfo {
  id: string;
  /** line: a straight move (from, to); arc: an arc, circle or helix about a centre. */
  family: 'line' | 'arc';
  /** A move that shows what the algorithm teaches (options without `algorithm`), and why. */
  example: { options: Record<string, unknown>; why: string };
  title: string;
  /** Document and section the algorithm comes from. */
  citation: string;
  /** The rule in plain words. */
  teaching: string;
  /** Where the source document is wrong and what voxpath does instead. */
  errata: string[];
  columns: ColumnSpec[];
  options: OptionSpec[];
  /** Axis counts the algorithm accepts. */
  minDims: number;
  maxDims: number;
  /**
   * Default tie policy, or null when the algorithm takes no `tie` option (it has
   * no ties, or, like greedy and walk6, orders tied axes with `tieAxis`).
   */
  defaultTie: TiePolicy | null;
}

/** One stretch of a trace produced by one stepper (a line, a chord, a G-code move). */
export interface SegmentInfo {
  /** Step index of the segment's first step. */
  firstStep: number;
  steps: number;
  /** Point where the segment starts, grid units. */
  start: number[];
  ideal: IdealPath;
  /** What a learner should know about this move before it starts. */
  note: string;
}

/** The small part of a trace: everything but the per-step arrays. */
export interface TraceSummary {
  algorithm: string;
  dims: number;
  steps: number;
  start: number[];
  end: number[];
  columns: ColumnSpec[];
  metrics: Metrics;
  /** The distance from the ideal path no point exceeds, as the algorithm guarantees; null where it guarantees none. */
  deviationBound: DeviationBound | null;
  segments: SegmentInfo[];
}

/** A guaranteed largest distance from the ideal path (grid units), and why it holds. */
export interface DeviationBound {
  value: number;
  why: string;
}
