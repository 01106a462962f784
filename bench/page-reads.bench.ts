/**
 * What the page asks of a trace after it is drawn, read the way the worker
 * reads it now against the way it read it before:
 * - the charts' rows of a 1,000,000-step line, 2,000 buckets: one
 *   chartSeries call (one pass in the core) against a point and an axis
 *   error read per row (4,000 single-row wasm calls) plus a deviation scan
 *   in 65,536-point chunks;
 * - one point's detail for the inspector, its figure and its overlay: one
 *   stepDetail call (one replay) against the four reads it replaced
 *   (deviation, decisions and explanation of the step, each replaying it,
 *   and the segment's note from the summary).
 *
 * The "before" reads are written out here from the public API, as the
 * worker made them (web/worker/series.ts and the inspector's four requests,
 * removed); they give the same values (tests/api.test.ts).
 */
import { trace } from '../web/core/index.js';
import type { Trace } from '../web/core/index.js';
import type { BenchGroup } from './types.js';

/** Rounds per measurement, after one untimed round; the median counts. */
const ROUNDS = 7;
const CHART_ROWS = 2000;
const SCAN_CHUNK_POINTS = 1 << 16;
/** Points whose detail is read per round, spread over the path. */
const DETAILS = 200;

/** Seconds of the median of ROUNDS runs of `run`, after one that is not timed (V8 and wasm compile in tiers). */
function medianSeconds(run: () => void): number {
  run();
  const times: number[] = [];
  for (let i = 0; i < ROUNDS; i++) {
    const start = performance.now();
    run();
    times.push((performance.now() - start) / 1000);
  }
  times.sort((a, b) => a - b);
  return times[ROUNDS >> 1]!;
}

/** The chart rows as web/worker/series.ts read them: one point and one axis error per row, deviation scanned in chunks. */
function seriesByRow(t: Trace, maxPoints: number): void {
  const points = t.steps + 1;
  const bucket = Math.max(1, Math.ceil(points / maxPoints));
  const rows = Math.ceil(points / bucket);
  const ideal = new Float64Array(rows * t.dims);
  const deviationMax = new Float64Array(rows).fill(-Infinity);
  for (let r = 0; r < rows; r++) {
    const point = t.pointsInRange(r * bucket, r * bucket + 1);
    const error = t.axisErrorInRange(r * bucket, r * bucket + 1);
    for (let a = 0; a < t.dims; a++) ideal[r * t.dims + a] = point[a]! - error[a]!;
  }
  for (let k = 0; k < points; k += SCAN_CHUNK_POINTS) {
    const deviation = t.deviationInRange(k, Math.min(points, k + SCAN_CHUNK_POINTS));
    for (let i = 0; i < deviation.length; i++) {
      const r = Math.floor((k + i) / bucket);
      deviationMax[r] = Math.max(deviationMax[r]!, deviation[i]!);
    }
  }
}

/** A point's values as the inspector read them: four requests, two replaying the same step. */
function detailByParts(t: Trace, pointIndex: number): void {
  t.deviationInRange(pointIndex, pointIndex + 1);
  t.decisionsInRange(pointIndex - 1, pointIndex);
  t.explain(pointIndex - 1);
  // The worker's bisection over the summary's segments.
  const segments = t.segments;
  let [low, high] = [0, segments.length - 1];
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if (segments[middle]!.firstStep <= pointIndex - 1) low = middle;
    else high = middle - 1;
  }
}

export default async function pageReads(): Promise<BenchGroup> {
  const line = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [1_000_000, 700_001, 600_003] });
  const points = line.steps + 1;
  const chartOne = medianSeconds(() => line.chartSeries(CHART_ROWS));
  const chartByRow = medianSeconds(() => seriesByRow(line, CHART_ROWS));
  // Points spread over the path, each away from a checkpoint by a different amount.
  const picks = Array.from({ length: DETAILS }, (_, i) => 1 + Math.floor(((i + 0.37) * line.steps) / DETAILS));
  const detailOne = medianSeconds(() => picks.forEach((p) => line.stepDetail(p)));
  const detailParts = medianSeconds(() => picks.forEach((p) => detailByParts(line, p)));
  line.free();
  return {
    title: 'Page reads of a trace',
    notes: [
      'chart rows: points of the path covered per second, reading 2,000 buckets of a 1,000,000-step regions line.',
      `point details: points read per second (${DETAILS} points spread over the same line); each replays its step from the nearest stepper state (up to 4,095 steps).`,
      `Rates are the median of ${ROUNDS} rounds after one untimed round; the ratio is before over now, in time.`,
    ],
    rows: [
      {
        name: 'chart rows, 2,000 buckets',
        steps: line.steps,
        rates: { now: points / chartOne, before: points / chartByRow },
        ratios: { 'before/now': chartByRow / chartOne },
      },
      {
        name: `point details, ${DETAILS} points`,
        steps: line.steps,
        rates: { now: DETAILS / detailOne, before: DETAILS / detailParts },
        ratios: { 'before/now': detailParts / detailOne },
      },
    ],
  };
}
