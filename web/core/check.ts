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
import { AXIS_NAMES } from './axes.js';
import { callCore } from './errors.js';
import { argumentError, describeValue, isPromiseLike, isTextOrUtf8, text as guardText, wholeNumber } from './guard.js';
import { encodeRequest } from './request.js';
import { advanceForTime, checkSliceOptions, freeStopped, type SliceOptions, yieldToEventLoop } from './slices.js';
import type { Check, CheckProgress, CheckRun, TextBytes } from './pkg/voxpath.js';
import type { TraceOptions } from './types.js';
import { loadCore, withTextBytes, withTextBytesInSlices } from './wasm.js';

/**
 * A learner's points: rows of [x, y, z] (or [x, y] ...), a flat Int32Array (or Float64Array)
 * of `dims` values per point, or text: CSV or blank-separated rows with an
 * optional header (its x, y, z columns are read, so voxpath's own CSV works),
 * or the list a program printed (`[(0, 0, 0), (1, 1, 0), ...]`), as a string
 * or as its UTF-8 bytes (a file's, in a Uint8Array). Text is read by the
 * core, once.
 */
export type LearnerPoints = readonly (readonly number[])[] | { points: Int32Array | Float64Array; dims: number } | string | Uint8Array;

/** The result and its parts are the core's Rust types (rust/src/check.rs). */
export type { AlsoMatch, AroundRow, Check, CheckProgress, CheckStage, DifferenceKind, Difference as CheckDifference } from './pkg/voxpath.js';

/** Options of a check made in slices: onProgress gets each slice's CheckProgress. */
export type CheckOptions = SliceOptions<CheckProgress>;

/**
 * Points' worth of work each core call of a check in slices makes
 * (CheckRun.advance: a line of text read or a step compared is one, an
 * option combination traced along the points counts as all of them, at
 * least one a call): about 5 ms of text read in Node, 0.1 ms of steps
 * compared, or one combination of a long path (0.05 to 9 ms along a
 * helix's 1,500,000 points in Node), several of a short one.
 */
const CHECK_UNITS_PER_CALL = 65_536;

/** A slot of a sparse array as a message shows it: `[1, , 3]` has no y, which indexing reads as undefined and a typed array as 0. */
function slotValue(array: readonly unknown[], index: number): string {
  return index in array ? describeValue(array[index]) : 'an empty slot (a hole in a sparse array)';
}

/**
 * Rows of numbers as one flat array, for the core; a row that is not one, or
 * of another length, is named by index. Every index is read, holes
 * included: forEach skipped them, so a hole became 0.
 */
function flatten(rows: readonly unknown[]): { values: Float64Array; dims: number } {
  const first = rows[0];
  const dims = Array.isArray(first) ? first.length : 0;
  // Rows of no coordinates flatten to no values, which the core reads as
  // no points: [[], []] was "there are no points".
  if (dims === 0 && Array.isArray(first)) throw argumentError('points', 'point 0 has no coordinates (an empty array); a point has one per axis');
  const values = new Float64Array(rows.length * dims);
  for (let index = 0; index < rows.length; index++) {
    const row = rows[index];
    if (!Array.isArray(row)) throw argumentError('points', `point ${index} is ${slotValue(rows, index)}; expected an array of coordinates`);
    if (row.length !== dims) throw argumentError('points', `point ${index} has ${row.length} coordinates; point 0 has ${dims}`);
    for (let axis = 0; axis < dims; axis++) {
      const value: unknown = row[axis];
      // Float64Array.set would read '0x10' as 16 and throw a TypeError on a BigInt.
      if (typeof value !== 'number') {
        throw argumentError('points', `point ${index}: ${AXIS_NAMES[axis] ?? `coordinate ${axis}`} must be a number, got ${slotValue(row, axis)}`);
      }
      values[index * dims + axis] = value;
    }
  }
  return { values, dims };
}

/**
 * Checks a learner's points against the rule of `request`. Rejects with a
 * VoxpathError for a bad request, or for points that are not a path
 * (naming the point index, and for text the line and column).
 *
 * With `runOptions` (any of onProgress, signal, sliceMs) the core makes the
 * check a slice at a time, the event loop let run between slices:
 * `onProgress` hears after each (text points read, then steps compared,
 * then the family's option combinations tried), and `signal` stops it
 * between them (at the page's cap, 1,500,000 steps, the whole check took
 * about a second in one call, its text read in 0.1 to 0.2 s of it). The
 * result is the one call's, to the bit. Text is put into wasm memory
 * first, in slices too (one call of 70 to 200 ms at the page's cap in a
 * Chromium worker), then the rule is traced, in one call (a few ms), the
 * signal heard before and after it.
 */
export async function checkPoints(request: TraceOptions, points: LearnerPoints, runOptions?: CheckOptions): Promise<Check> {
  const sliceMs = runOptions === undefined ? undefined : checkSliceOptions('checkPoints', runOptions);
  const run = await startCheck(request, points, runOptions?.signal, sliceMs);
  return (await finishCheck(run, runOptions, sliceMs, false)).check;
}

/**
 * checkPoints of text points, and the points as the check read them (flat,
 * `dims` a point, the values readPoints gives), as the core hands them
 * over: an Int32Array, as a trace's points (CheckRun.readPoints), or null
 * when a coordinate does not fit one (the text may hold whole numbers up to
 * 2^53; the check then says where such points leave the rule's path). For
 * a view that draws the points beside the check, the text read once, and
 * in slices with the check when `runOptions` are given.
 */
export async function readAndCheckPoints(request: TraceOptions, text: string, runOptions?: CheckOptions): Promise<{ check: Check; points: Int32Array | null }> {
  const sliceMs = runOptions === undefined ? undefined : checkSliceOptions('readAndCheckPoints', runOptions);
  const run = await startCheck(request, guardText('text', text, 'the points'), runOptions?.signal, sliceMs);
  const { check, points } = await finishCheck(run, runOptions, sliceMs, true);
  return { check, points: points ?? null };
}

/**
 * The core's run of a check of `points` against `request`, not advanced
 * yet. With `sliceMs` (a check in slices), text is put into wasm memory a
 * slice at a time, stopped by `signal` (withTextBytesInSlices).
 */
async function startCheck(request: TraceOptions, points: LearnerPoints, signal: AbortSignal | undefined, sliceMs: number | undefined): Promise<CheckRun> {
  const json = encodeRequest(request);
  const core = await loadCore();
  let run: CheckRun;
  // Text, or its UTF-8 bytes as a file holds them (refused at the line and
  // column of the first byte that is not UTF-8), as runGcode takes a program.
  if (isTextOrUtf8(points)) {
    const fromText = (bytes: TextBytes) => callCore(() => core.CheckRun.fromText(json, bytes));
    run = sliceMs === undefined ? withTextBytes(core, points, fromText) : await withTextBytesInSlices(core, points, fromText, signal, sliceMs);
  } else {
    let given: { values: Int32Array | Float64Array; dims: number };
    if (Array.isArray(points)) given = flatten(points);
    else if (isPromiseLike(points)) throw argumentError('points', 'got a Promise, not the points: await it first (checkPoints(request, await points))');
    else if (typeof points === 'object' && points !== null && !ArrayBuffer.isView(points)) {
      const flat = points as { points: unknown; dims: unknown };
      if (!(flat.points instanceof Int32Array || flat.points instanceof Float64Array)) {
        throw argumentError('points', `expected { points: Int32Array or Float64Array, dims }, got points = ${describeValue(flat.points)}`);
      }
      given = { values: flat.points, dims: wholeNumber('dims', flat.dims, 1, 2 ** 32 - 1, 'coordinates per point') };
    } else {
      throw argumentError('points', `expected rows of coordinates, { points, dims } or text, got ${describeValue(points)}`);
    }
    run = callCore(() => core.CheckRun.fromPoints(json, given.values, given.dims));
  }
  return run;
}

/** `run` advanced to its end (in slices with `runOptions`), its result, and its points as read when `keepPoints` (CheckRun.readPoints); the run freed. */
async function finishCheck(run: CheckRun, runOptions: CheckOptions | undefined, sliceMs: number | undefined, keepPoints: boolean): Promise<{ check: Check; points?: Int32Array }> {
  let check: Check;
  let points: Int32Array | undefined;
  try {
    if (runOptions === undefined || sliceMs === undefined) callCore(() => run.advance(Infinity));
    else {
      // The run was made in one call (the request read, the rule traced,
      // the text taken: 10 to 45 ms in Chromium at the page's cap): a
      // cancel sent meanwhile is honoured before the first slice.
      await yieldToEventLoop();
      await advanceForTime(() => callCore(() => run.advance(CHECK_UNITS_PER_CALL)), runOptions, sliceMs);
      // A cancel sent while the last slice ran is still honoured.
      await yieldToEventLoop();
      runOptions.signal?.throwIfAborted();
    }
    check = callCore(() => run.result());
    if (keepPoints) points = callCore(() => run.readPoints());
  } catch (error) {
    freeStopped(run);
    throw error;
  }
  run.free();
  return { check, points };
}

/**
 * A learner's points read from text as checkPoints reads it (CSV,
 * blank-separated rows or a printed list), `dims` coordinates each, flat:
 * for a view that draws them and then checks them as { points, dims },
 * reading the text once. Rejects with a VoxpathError giving the line and
 * column of what is not a point, or not a path.
 */
export async function readPoints(text: string, dims: number): Promise<Float64Array> {
  const points = guardText('text', text, 'the points');
  const core = await loadCore();
  const perPoint = wholeNumber('dims', dims, 1, AXIS_NAMES.length, 'coordinates per point');
  return callCore(() => withTextBytes(core, points, (bytes) => core.readPoints(bytes, perPoint)));
}
