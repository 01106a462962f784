/**
 * Batch experiments: many traces summarised (Wang et al. 2020, section 3.2
 * and Figure 9). The core runs them; this module only carries the result.
 */
import { callCore } from './errors.js';
import { encodeRequest } from './request.js';
import type { AlgorithmInfo, OptionSpec } from './types.js';
import { loadCore } from './wasm.js';

export interface RandomLinesOptions {
  /** Algorithm that traces every line, e.g. 'regions'. */
  algorithm: string;
  /** How many lines (default 100). */
  count?: number;
  /** Seed of the generator (default 1): the same seed gives the same lines. */
  seed?: number;
  /** End coordinates are uniform in 0..=maxCoordinate (default 100). */
  maxCoordinate?: number;
  /** Axes per line (default 3). */
  dims?: number;
  /** Any other option goes to the algorithm of every line (e.g. tie). */
  [option: string]: unknown;
}

/** Max, mean and population standard deviation of one line's errors (grid units). */
export interface ErrorStats {
  max: number;
  mean: number;
  std: number;
}

/** Largest, smallest and mean value over all lines of one per-line statistic. */
export interface Spread {
  max: number;
  min: number;
  mean: number;
}

/** Spread of each per-line statistic: Figure 9's delta_(Max-Max), delta_(Mean-Min), ... */
export interface MeasureSummary {
  max: Spread;
  mean: Spread;
  std: Spread;
}

export interface RandomLinesResult {
  experiment: 'random-lines';
  algorithm: string;
  seed: number;
  maxCoordinate: number;
  lines: {
    to: number[];
    steps: number;
    /** Perpendicular distance of each point to the ideal line. */
    perpendicular: ErrorStats;
    /** Norm of the per-axis error vector, Wang eq. (11). */
    axisError: ErrorStats;
  }[];
  perpendicular: MeasureSummary;
  axisError: MeasureSummary;
  /** Wang's Figure 9 as printed, to compare with axisError. */
  paperFigure9: MeasureSummary;
  paperFigure9Erratum: string;
}

export interface ExperimentInfo {
  id: string;
  title: string;
  citation: string;
  /** The family of algorithm it traces with (random-lines: 'line'). */
  family: AlgorithmInfo['family'];
  options: OptionSpec[];
}

/** Traces `count` seeded random lines from the origin and summarises their errors. */
export async function randomLines(options: RandomLinesOptions): Promise<RandomLinesResult> {
  const core = await loadCore();
  const request = encodeRequest(options);
  return JSON.parse(callCore(() => core.randomLinesJson(request))) as RandomLinesResult;
}

let catalogue: ExperimentInfo[] | undefined;

/** The experiments voxpath runs, with their options. */
export async function experiments(): Promise<ExperimentInfo[]> {
  const core = await loadCore();
  catalogue ??= JSON.parse(core.experimentsJson()) as ExperimentInfo[];
  return catalogue;
}
