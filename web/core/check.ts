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
import type { Check } from './pkg/voxpath.js';
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

/** The result and its parts are the core's Rust types (rust/src/check.rs). */
export type { AlsoMatch, AroundRow, Check, DifferenceKind, Difference as CheckDifference } from './pkg/voxpath.js';

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
  return callCore(() => {
    if (typeof points === 'string') return core.check(json, points);
    if (Array.isArray(points)) {
      const { values, dims } = flatten(points);
      return core.check(json, values, dims);
    }
    const flat = points as { points: Int32Array; dims: number };
    return core.check(json, flat.points, flat.dims);
  });
}
