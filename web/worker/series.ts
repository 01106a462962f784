/**
 * The charts' data, computed where the trace lives (the worker), so the
 * page receives a few thousand rows however long the path is. Values are the
 * core's: coordinates from its points, the ideal position as the point less
 * its Wang eq. (11) error, and its deviation. Only the bucketing is done
 * here; it decides which rows to send, never a value.
 */
import type { Trace } from '../core/index.js';
import type { ChartSeries } from './protocol.js';

/** Points read from the core per call while scanning deviation. */
const SCAN_CHUNK_POINTS = 1 << 16;

/** Chart rows of `trace`: every point, or buckets of points when it has more than maxPoints. */
export function chartSeries(trace: Trace, maxPoints: number): ChartSeries {
  const points = trace.steps + 1;
  const bucket = Math.max(1, Math.ceil(points / maxPoints));
  const rows = Math.ceil(points / bucket);
  const dims = trace.dims;
  const pointIndex = new Float64Array(rows);
  const position = Array.from({ length: dims }, () => new Float64Array(rows));
  const ideal = Array.from({ length: dims }, () => new Float64Array(rows));
  const deviationMax = new Float64Array(rows).fill(-Infinity);
  const deviationMin = new Float64Array(rows).fill(Infinity);
  for (let r = 0; r < rows; r++) {
    const k = r * bucket;
    pointIndex[r] = k;
    const point = trace.pointsInRange(k, k + 1);
    const error = trace.axisErrorInRange(k, k + 1);
    for (let a = 0; a < dims; a++) {
      position[a]![r] = point[a]!;
      ideal[a]![r] = point[a]! - error[a]!;
    }
  }
  for (let k = 0; k < points; k += SCAN_CHUNK_POINTS) {
    const deviation = trace.deviationInRange(k, Math.min(points, k + SCAN_CHUNK_POINTS));
    for (let i = 0; i < deviation.length; i++) {
      const r = Math.floor((k + i) / bucket);
      const d = deviation[i]!;
      if (d > deviationMax[r]!) deviationMax[r] = d;
      if (d < deviationMin[r]!) deviationMin[r] = d;
    }
  }
  return { pointIndex, position, ideal, deviationMax, deviationMin, bucketed: bucket > 1 };
}
