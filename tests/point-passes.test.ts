// A trace's metrics and a chart's rows made by the core a slice of points at
// a time (metricsInSlices, chartSeriesInSlices), and two traces' difference
// a trace's cells at a time (differenceWith), as the page's worker makes
// them to report progress and take a Cancel: the values of the one call, to
// the bit, whatever the slices; a signal stops the pass between slices.
import { describe, expect, it } from 'vitest';
import { type ChartSeries, type PointsProgress, runGcode, type Trace, trace, type TraceOptions, VoxpathError } from '../web/core/index.js';

/** Paths of each way a point is measured, each long enough to take several slices. */
const PATHS: Record<string, TraceOptions> = {
  'a line (walked)': { algorithm: 'regions', from: [0, 0, 0], to: [90001, 50003, 29999] },
  'a circle (walked)': { algorithm: 'circle', from: [400, 0, 0], to: [400, 0, 0], center: [0, 0, 0], plane: 'xy', turns: 40 },
  'a helix (point by point)': { algorithm: 'helix', from: [300, 0, 0], to: [300, 0, 500], center: [0, 0, 0], plane: 'xy', turns: 30 },
  'a helix in chords': { algorithm: 'helix', method: 'segments', from: [300, 0, 0], to: [300, 0, 500], center: [0, 0, 0], plane: 'xy', turns: 30 },
};

/** A G-code program's trace, whose segments are made again when read. */
async function programTrace(): Promise<Trace> {
  // Lines along x, climbing z now and then, each followed by a half circle of r = 2 mm.
  const moves = Array.from({ length: 300 }, (_, i) => (i % 2 ? `G2 X${(i + 1) * 4} Y0 I2 J0` : `G1 X${(i + 1) * 4} Y0 Z${i % 3}`));
  const program = await runGcode(`F600\n${moves.join('\n')}`, { stepsPerMm: 40 });
  expect(program.errors).toEqual([]);
  return program.trace;
}

const traces: [string, () => Promise<Trace>][] = [...Object.entries(PATHS).map(([name, options]): [string, () => Promise<Trace>] => [name, () => trace(options)]), ['a G-code program', programTrace]];

/** Every value of a series, bit for bit (NaN included). */
function seriesBits(series: ChartSeries): unknown {
  const bits = (values: Float64Array) => Array.from(new BigUint64Array(values.slice().buffer), String);
  return { ...series, pointIndex: bits(series.pointIndex), position: series.position.map(bits), ideal: series.ideal.map(bits), deviationMax: bits(series.deviationMax), deviationMin: bits(series.deviationMin) };
}

describe('passes over the points made in slices', () => {
  it.each(traces)('give the metrics and chart rows of one call, for %s', async (_, make) => {
    const [whole, sliced] = [await make(), await make()];
    const progress: PointsProgress[] = [];
    // A slice aimed at 0.1 ms: many slices, of every size the slicing picks.
    const metrics = await sliced.metricsInSlices({ sliceMs: 0.1, onProgress: (p) => progress.push(p) });
    expect(progress.length).toBeGreaterThan(2);
    expect(progress.at(-1)).toEqual({ pointsDone: whole.steps + 1, points: whole.steps + 1, done: true });
    expect(progress.every((p, i) => i === 0 || p.pointsDone > progress[i - 1]!.pointsDone)).toBe(true);
    expect(metrics).toEqual(whole.metrics);
    for (const rows of [2000, 7, whole.steps + 1]) {
      const series = await sliced.chartSeriesInSlices(rows, { sliceMs: 0.1 });
      expect(seriesBits(series)).toEqual(seriesBits(whole.chartSeries(rows)));
    }
    whole.free();
    sliced.free();
  });

  it('stop between slices when their signal is aborted, and a stopped pass is taken up where it stopped', async () => {
    const [whole, sliced] = [await trace(PATHS['a helix (point by point)']!), await trace(PATHS['a helix (point by point)']!)];
    for (const pass of [(o: object) => sliced.metricsInSlices(o), (o: object) => sliced.chartSeriesInSlices(2000, o)]) {
      const cancel = new AbortController();
      const seen: PointsProgress[] = [];
      const stopped = pass({ signal: cancel.signal, sliceMs: 0.1, onProgress: (p: PointsProgress) => (seen.push(p), cancel.abort()) });
      await expect(stopped).rejects.toMatchObject({ name: 'AbortError' });
      // The slice that heard the abort was the last one made.
      expect(seen).toHaveLength(1);
      expect(seen[0]!.done).toBe(false);
    }
    const resumed: PointsProgress[] = [];
    expect(await sliced.metricsInSlices({ onProgress: (p) => resumed.push(p) })).toEqual(whole.metrics);
    expect(resumed[0]!.pointsDone).toBeGreaterThan(0);
    expect(seriesBits(await sliced.chartSeriesInSlices(2000))).toEqual(seriesBits(whole.chartSeries(2000)));
    whole.free();
    sliced.free();
  });

  it('find where two paths differ, each one\'s cells sorted in turn, as compareWith and cellsOnlyIn find it, stopped between the two', async () => {
    const pairs: [TraceOptions, TraceOptions][] = [
      [PATHS['a line (walked)']!, { ...PATHS['a line (walked)']!, algorithm: 'greedy' }],
      [PATHS['a helix (point by point)']!, PATHS['a helix in chords']!],
      [PATHS['a circle (walked)']!, PATHS['a circle (walked)']!],
    ];
    for (const [first, second] of pairs) {
      const [a, b] = [await trace(first), await trace(second)];
      const seen: PointsProgress[] = [];
      const difference = await a.differenceWith(b, { onProgress: (p) => seen.push(p) });
      expect(seen.map((p) => [p.pointsDone, p.done])).toEqual([
        [a.steps + 1, false],
        [a.steps + b.steps + 2, true],
      ]);
      expect(difference.firstDifference).toEqual(a.compareWith(b).firstDifference);
      expect(Array.from(difference.onlyInA)).toEqual(Array.from(a.cellsOnlyIn(b)));
      expect(Array.from(difference.onlyInB)).toEqual(Array.from(b.cellsOnlyIn(a)));
      const cancel = new AbortController();
      await expect(a.differenceWith(b, { signal: cancel.signal, onProgress: () => cancel.abort() })).rejects.toMatchObject({ name: 'AbortError' });
      a.free();
      b.free();
    }
  });

  it('refuse a freed trace and bad options, naming them', async () => {
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [5, 3, 1] });
    await expect(t.chartSeriesInSlices(0)).rejects.toMatchObject({ field: 'maxRows' });
    await expect(t.metricsInSlices({ onprogress: () => {} } as object)).rejects.toMatchObject({ field: 'onprogress' });
    const flat = await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [5, 3] });
    await expect(t.differenceWith(flat)).rejects.toMatchObject({ field: 'other' });
    flat.free();
    t.free();
    const freed = t.metricsInSlices();
    await expect(freed).rejects.toBeInstanceOf(VoxpathError);
    await expect(freed).rejects.toMatchObject({ field: 'trace' });
  });
});
