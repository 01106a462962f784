/**
 * A test matcher for a learner's implementation, for vitest and Jest alike
 * (both take it with `expect.extend`; this module imports neither):
 *
 *   import { expect, test } from 'vitest';
 *   import { voxpathMatchers } from 'voxpath/vitest';
 *   expect.extend(voxpathMatchers);
 *
 *   test('my 3D Bresenham', async () => {
 *     await expect(myLine([0, 0, 0], [10, 7, 6])).toFollowRule({ algorithm: 'bresenham3d', from: [0, 0, 0], to: [10, 7, 6] });
 *   });
 *
 * The points are anything checkPoints takes (rows, a flat typed array with
 * `dims` in the request's place is not supported: pass rows or text). The
 * failure message is the CLI's `voxpath check` table: the first difference,
 * the rule's reason and decisions, the points around it side by side, and
 * the rules the points do follow.
 */
import { checkPoints } from './check.js';
import type { Check, LearnerPoints } from './check.js';
import { VoxpathError } from './errors.js';
import { checkToTable } from './export.js';
import { argumentError, describeValue, isPromiseLike, isTextOrUtf8 } from './guard.js';
import type { TraceOptions } from './types.js';

/** What vitest and Jest pass a matcher as `this` (the part used here). */
interface MatcherContext {
  isNot?: boolean;
}

/**
 * An error about the learner's points rather than the request: points that
 * are not a path (a skipped cell, a wrong number of coordinates, a row of
 * text that is not a point). The core names them `points`, or the line and
 * column of text.
 */
function isAboutThePoints(error: unknown, request: TraceOptions): error is VoxpathError {
  // A request that itself carries an option named points is wrong as a request.
  return error instanceof VoxpathError && (error.field === 'points' || error.line !== undefined) && !Object.hasOwn(request, 'points');
}

/** Whether `received` has the shape of a learner's points (what it holds is checkPoints' to judge). */
function isLearnerPointsShape(received: unknown): boolean {
  // Text as a string or as a file's bytes, as checkPoints takes it (its type says so; bytes were refused).
  if (isTextOrUtf8(received) || Array.isArray(received)) return true;
  if (typeof received !== 'object' || received === null) return false;
  const { points, dims } = received as { points?: unknown; dims?: unknown };
  return (points instanceof Int32Array || points instanceof Float64Array) && typeof dims === 'number';
}

export const voxpathMatchers = {
  /**
   * Passes when `received` is the path of `request`, point for point. Points
   * that are not a path at all fail it (and pass `.not`), saying why; a bad
   * request, or points not awaited, throw.
   */
  async toFollowRule(this: MatcherContext, received: LearnerPoints, request: TraceOptions) {
    if (isPromiseLike(received)) {
      throw argumentError('points', 'got a Promise, not the points: await it first (expect(await points).toFollowRule(request))');
    }
    // Points in none of the shapes a learner's points come in are a misuse of the matcher, which
    // throws: failed as "not a path", undefined passed .not.toFollowRule without testing anything.
    if (!isLearnerPointsShape(received)) {
      throw argumentError('points', `expected rows of coordinates, text (a string, or its UTF-8 bytes in a Uint8Array), or { points: Int32Array or Float64Array, dims }, got ${describeValue(received)}`);
    }
    let result: Check;
    try {
      result = await checkPoints(request, received);
    } catch (error) {
      if (!isAboutThePoints(error, request)) throw error;
      return { pass: false, message: () => `${request.algorithm}: your points are not a path, so they cannot follow the rule: ${error.message}` };
    }
    const table = checkToTable(result);
    return {
      pass: result.matches,
      message: () => (this.isNot ? `expected the points not to follow ${request.algorithm}, but they do.\n${table}` : table),
    };
  },
};

/**
 * The matcher's type, for a test file to add to its runner's matchers:
 *
 *   declare module 'vitest' { interface Matchers<T = any> extends VoxpathMatchers {} }
 *   declare module 'expect' { interface Matchers<R extends void | Promise<void>, T = unknown> extends VoxpathMatchers<R> {} }
 *
 * (this module does not depend on either runner, so it does not do it itself).
 */
export interface VoxpathMatchers<R = Promise<void>> {
  /** The points are the path of the request; await it. */
  toFollowRule(request: TraceOptions): R;
}
