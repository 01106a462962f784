/**
 * Two algorithms on the same move, side by side: steps and metrics, the
 * first point where the paths part with why each took the step it took
 * there, and the cells one visits and the other does not. The core runs and
 * compares both traces; this module only carries the result.
 *
 *   const c = await compare({ algorithms: ['regions', 'bresenham3d'], from: [0, 0, 0], to: [10, 7, 6] });
 *   c.firstDifference?.pointIndex;         // 5
 *   c.firstDifference?.aWhy?.explanation;  // 'x is the active axis; M = 0 and N = 10 > 0, ...'
 */
import { callCore } from './errors.js';
import { encodeRequest } from './request.js';
import type { Metrics } from './types.js';
import { loadCore } from './wasm.js';

/** Options of a comparison. */
export interface CompareOptions {
  /** The two algorithm ids, a then b (for example ['circle', 'arc-segments']). */
  algorithms: readonly [string, string];
  /**
   * Shared options: each goes to every one of the two algorithms that
   * declares it (`from`, `to` to both; `segmentLength` only to arc-segments
   * when compared with circle). An option neither declares is rejected with
   * a VoxpathError whose `field` names it.
   */
  [option: string]: unknown;
}

/** One side's trace in brief. */
export interface TraceDigest {
  algorithm: string;
  steps: number;
  /** First and last point, grid units. */
  start: number[];
  end: number[];
  /** Whole-path statistics; for an arc maxDeviation is the largest radial error. */
  metrics: Metrics;
}

/** Why one trace took one step. */
export interface StepWhy {
  /** Step index k: the step from point k to point k + 1. */
  stepIndex: number;
  /** One sentence, as Trace.explain(k) gives it. */
  explanation: string;
  /**
   * Decision values by column name, in the algorithm's column order: numbers,
   * category labels, true/false for flags, null where a column does not apply.
   */
  decisions: Record<string, number | string | boolean | null>;
}

/** The first point index where the two paths differ. */
export interface FirstDifference {
  /** Point index k (0..=steps); the step before it, k - 1, is the first differing step. */
  pointIndex: number;
  /** a's point there, grid units, or null when a has already ended. */
  a: number[] | null;
  b: number[] | null;
  /** Why a took step pointIndex - 1; null when a has ended or at point 0. */
  aWhy: StepWhy | null;
  bWhy: StepWhy | null;
}

/** Distinct cells one path visits and the other never does. */
export interface Cells {
  /** How many there are. */
  count: number;
  /** The first 1000 of them, in the path's order, grid units. */
  cells: number[][];
}

/** The result of `compare`. */
export interface Comparison {
  a: TraceDigest;
  b: TraceDigest;
  /** Null when the paths are identical. */
  firstDifference: FirstDifference | null;
  onlyInA: Cells;
  onlyInB: Cells;
}

/** Traces the move with both algorithms and compares the paths. */
export async function compare(options: CompareOptions): Promise<Comparison> {
  const core = await loadCore();
  const request = encodeRequest(options);
  return JSON.parse(callCore(() => core.compareJson(request))) as Comparison;
}
