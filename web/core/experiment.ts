/**
 * Batch experiments: many traces summarised (Wang et al. 2020, section 3.2
 * and Figure 9). The core runs them; this module only carries the result.
 */
import { catalogue } from './catalogue.js';
import { callCore } from './errors.js';
import { encodeRequest } from './request.js';
import { advanceInSlices, checkSliceOptions, freeStopped, type SliceOptions, yieldToEventLoop } from './slices.js';
import type { ExperimentInfo, ExperimentProgress, RandomLines, RandomLinesOptions } from './pkg/voxpath.js';
import { loadCore } from './wasm.js';

export type { ErrorStats, ExperimentInfo, ExperimentProgress, LineResult, MeasureSummary, RandomLines, RandomLinesOptions, Spread } from './pkg/voxpath.js';
/** The result of random-lines (the core's `experiment::RandomLines`). */
export type RandomLinesResult = RandomLines;

/** Options of randomLines: onProgress gets each slice's ExperimentProgress (lines traced, of count). */
export type RandomLinesRunOptions = SliceOptions<ExperimentProgress>;

/**
 * Traces `count` seeded random lines from the origin and summarises their
 * errors. The core traces them a slice of lines at a time (100,000 lines of
 * up to 10,000 steps take tens of seconds): `onProgress` hears after each
 * slice, and `signal` stops the run between slices.
 */
export async function randomLines(options: RandomLinesOptions, runOptions: RandomLinesRunOptions = {}): Promise<RandomLinesResult> {
  const request = encodeRequest(options);
  const sliceMs = checkSliceOptions('randomLines', runOptions);
  const core = await loadCore();
  const run = callCore(() => new core.RandomLinesRun(request));
  try {
    await advanceInSlices((lines) => callCore(() => run.advance(lines)), runOptions, sliceMs, { first: 16, least: 1 });
    // A cancel sent while the last slice ran is still honoured.
    await yieldToEventLoop();
    runOptions.signal?.throwIfAborted();
  } catch (error) {
    freeStopped(run);
    throw error;
  }
  return run.finish();
}

/** The experiments voxpath runs, with their options. */
export async function experiments(): Promise<ExperimentInfo[]> {
  return (await catalogue()).experiments;
}
