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
import type { CompareOptions, Comparison, FirstDifference } from './pkg/voxpath.js';
import { loadCore } from './wasm.js';

export type { Cells, CompareOptions, Comparison, FirstDifference, StepWhy, TraceDigest } from './pkg/voxpath.js';

/** Traces the move with both algorithms and compares the paths. */
export async function compare(options: CompareOptions): Promise<Comparison> {
  const core = await loadCore();
  const request = encodeRequest(options);
  return callCore(() => core.compare(request));
}

/**
 * Where two traces of one move differ, as a view shows them
 * (Trace.differenceWith): the first point where they part, and every cell
 * only one visits.
 */
export interface TraceDifference {
  /** The first point where the paths differ, with each side's reason and decision values; null when they are the same. */
  firstDifference: FirstDifference | null;
  /** Every distinct cell only one path visits, in its path order, flat with stride dims. */
  onlyInA: Int32Array;
  onlyInB: Int32Array;
}
