/**
 * Checking a learner's own implementation: the points a student's program
 * printed, against the rule of any trace request. The core replays the
 * rule, finds the first point where the two part and says why the rule went
 * where it went (its own explanation and decision values of that step), and
 * names every catalogue rule and option set the points do follow. This
 * module only carries the points in and the result out.
 *
 *   const c = await checkPoints({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] }, studentPoints);
 *   c.matches;                        // false
 *   c.firstDifference?.pointIndex;    // 5
 *   c.firstDifference?.why;           // the rule's sentence for that step
 *   c.alsoMatches.map((m) => m.label) // ['bresenham3d with tie = hold']
 */
import { VoxpathError, callCore } from './errors.js';
import { encodeRequest } from './request.js';
import type { TraceOptions } from './types.js';
import { loadCore } from './wasm.js';

/**
 * A learner's points: rows of [x, y, z] (or [x, y] ...), a flat Int32Array
 * of `dims` values per point, or text: CSV or blank-separated rows with an
 * optional header (its x, y, z columns are read, so voxpath's own CSV works),
 * or the list a program printed (`[(0, 0, 0), (1, 1, 0), ...]`). Text is read
 * by the core, once.
 */
export type LearnerPoints = readonly (readonly number[])[] | { points: Int32Array; dims: number } | string;

/** What the first difference is. */
export type DifferenceKind = 'start' | 'step' | 'stops' | 'goesOn';

/** One point index near the difference, on both paths (null past a path's end). */
export interface AroundRow {
  pointIndex: number;
  expected: number[] | null;
  got: number[] | null;
}

/** The first point where the learner's path and the rule's part. */
export interface CheckDifference {
  kind: DifferenceKind;
  /** Point index k; the rule's step there is step index k - 1. */
  pointIndex: number;
  /** The rule's step index there (pointIndex - 1), null where the rule takes no step. */
  stepIndex: number | null;
  /** The rule's point k, or null after its end. */
  expected: number[] | null;
  /** The learner's point k, or null after their last. */
  got: number[] | null;
  /** What differs, in one sentence ("your path stops at step 7 of 10"). */
  message: string;
  /** Why the rule took its step there: the core's own sentence, as Trace.explain gives it. */
  why: string;
  /** Decision values of that step by column name (empty where the rule takes no step). */
  decisions: Record<string, number | string | boolean | null>;
  /** Up to three point indices either side, both paths. */
  around: AroundRow[];
}

/** A catalogue rule the points follow exactly. */
export interface AlsoMatch {
  algorithm: string;
  /** The options that choose this variant ({ tie: 'hold' }); pass them with the request's others to trace the same path. */
  options: Record<string, unknown>;
  /** "bresenham3d with tie = hold". */
  label: string;
  /** The algorithm's errata about the variant chosen (Saleem's printed 2D pseudo-code, ...). */
  errata: string[];
}

/** The result of `checkPoints`. */
export interface Check {
  /** The points are the rule's path, point for point. */
  matches: boolean;
  algorithm: string;
  /** Steps of the rule's path. */
  steps: number;
  /** Steps of the learner's path (points - 1). */
  yourSteps: number;
  /** Null when the points match. */
  firstDifference: CheckDifference | null;
  /** Every rule of the catalogue (same family), with its variant options, whose path equals the points. */
  alsoMatches: AlsoMatch[];
}

/** Rows of numbers as one flat array, for the core; a row of another length is named by index. */
function flatten(rows: readonly (readonly number[])[]): { values: Float64Array; dims: number } {
  const dims = rows[0]?.length ?? 0;
  const values = new Float64Array(rows.length * dims);
  rows.forEach((row, index) => {
    if (row.length !== dims) {
      throw new VoxpathError(`points: point ${index} has ${row.length} coordinates; point 0 has ${dims}`, {
        field: 'points',
        detail: `point ${index} has ${row.length} coordinates; point 0 has ${dims}`,
      });
    }
    values.set(row, index * dims);
  });
  return { values, dims };
}

/**
 * Checks a learner's points against the rule of `request`. Rejects with a
 * VoxpathError for a bad request, or for points that are not a path
 * (naming the point index, and for text the line and column).
 */
export async function checkPoints(request: TraceOptions, points: LearnerPoints): Promise<Check> {
  const core = await loadCore();
  const json = encodeRequest(request);
  const text = callCore(() => {
    if (typeof points === 'string') return core.checkJson(json, points);
    if (Array.isArray(points)) {
      const { values, dims } = flatten(points);
      return core.checkJson(json, values, dims);
    }
    const flat = points as { points: Int32Array; dims: number };
    return core.checkJson(json, flat.points, flat.dims);
  });
  return JSON.parse(text) as Check;
}
