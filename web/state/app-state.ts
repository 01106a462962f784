/**
 * The page's one state: which algorithm, its options as the user typed them,
 * the point shown and the playback. Every view reads it; inputs change it
 * through the Store; state/persist.ts keeps it in the URL and localStorage.
 */
import type { AlgorithmInfo, TraceOptions } from '../core/types.js';

/** An option's value: a point as integers per axis, a choice as its word, a number, a yes/no. */
export type OptionValue = number[] | number | string | boolean;

export interface AppState {
  /** Algorithm id from the catalogue. */
  algorithm: string;
  /** The algorithm's options, by OptionSpec name (from, to, tie...); absent ones take the core's default. */
  options: Record<string, OptionValue>;
  /** Point index shown: the position after this many steps (0..=steps). */
  pointIndex: number;
  playing: boolean;
  /** Playback speed in steps per second, one of SPEEDS_STEPS_PER_SECOND. */
  speed: number;
}

export const SPEEDS_STEPS_PER_SECOND = [0.5, 1, 2, 4, 8, 16, 32, 64] as const;

export const DEFAULT_SPEED = 2;

/** The algorithm a first visit shows: DEFAULT_ALGORITHM, or the catalogue's first. */
export function defaultAlgorithm(catalogue: readonly AlgorithmInfo[]): AlgorithmInfo {
  const info = catalogue.find((a) => a.id === DEFAULT_ALGORITHM) ?? catalogue[0];
  if (!info) throw new Error('the core lists no algorithms');
  return info;
}

const DEFAULT_ALGORITHM = 'regions';

/**
 * Options the page sets itself instead of showing a field. Every voxel of the
 * path is drawn, so the page caps the path length at what a browser draws
 * comfortably (the core's own default, 50,000,000, is for files and the CLI).
 */
export const PAGE_OPTIONS: Readonly<Record<string, OptionValue>> = { maxSteps: 1_000_000 };

/** Axes a point option has on the page: 3 (the view is 3D) within what the algorithm accepts. */
export function axisCount(info: AlgorithmInfo): number {
  return Math.min(Math.max(3, info.minDims), info.maxDims);
}

/**
 * The options of a first visit: the catalogue's example move for the
 * algorithm (for regions, Wang et al.'s (0,0,0)->(10,7,6), the line of their
 * Tables 1 and 2, so a learner can check the page against the paper), points
 * cut to the axes the page shows, and each other choice at its default.
 */
export function defaultOptions(info: AlgorithmInfo): Record<string, OptionValue> {
  const options: Record<string, OptionValue> = {};
  for (const spec of info.options) {
    if (spec.name in PAGE_OPTIONS) continue;
    const example = info.example.options[spec.name] as OptionValue | undefined;
    if (spec.kind.type === 'point' && Array.isArray(example)) options[spec.name] = example.slice(0, axisCount(info));
    else if (example !== undefined) options[spec.name] = example;
    else if (spec.kind.type === 'choice' && spec.default !== null) options[spec.name] = spec.default;
  }
  return options;
}

export function defaultState(info: AlgorithmInfo): AppState {
  return { algorithm: info.id, options: defaultOptions(info), pointIndex: 0, playing: false, speed: DEFAULT_SPEED };
}

/**
 * The request the core receives for this state. Options are passed as typed,
 * unchecked: the core validates each and names the one at fault.
 */
export function traceOptions(state: AppState): TraceOptions {
  return { algorithm: state.algorithm, ...state.options, ...PAGE_OPTIONS } as TraceOptions;
}
