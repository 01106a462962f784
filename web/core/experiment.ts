/**
 * Batch experiments: many traces summarised (Wang et al. 2020, section 3.2
 * and Figure 9). The core runs them; this module only carries the result.
 */
import { catalogue } from './catalogue.js';
import { callCore } from './errors.js';
import { encodeRequest } from './request.js';
import type { ExperimentInfo, RandomLines, RandomLinesOptions } from './pkg/voxpath.js';
import { loadCore } from './wasm.js';

export type { ErrorStats, ExperimentInfo, LineResult, MeasureSummary, RandomLinesOptions, Spread } from './pkg/voxpath.js';
/** The result of random-lines (the core's `experiment::RandomLines`). */
export type RandomLinesResult = RandomLines;

/** Traces `count` seeded random lines from the origin and summarises their errors. */
export async function randomLines(options: RandomLinesOptions): Promise<RandomLinesResult> {
  const core = await loadCore();
  const request = encodeRequest(options);
  return callCore(() => core.randomLines(request));
}

/** The experiments voxpath runs, with their options. */
export async function experiments(): Promise<ExperimentInfo[]> {
  return (await catalogue()).experiments;
}
