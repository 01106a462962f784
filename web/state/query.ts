/**
 * AppState <-> URL query, the permalink format, also used for localStorage:
 *
 *   ?algorithm=regions&from=0,0,0&to=10,7,6&tie=advance&step=3&speed=2
 *
 * Option keys are the API's option names, so a link reads like the CLI's
 * flags (--from 0,0,0). `step` is the point index shown (steps taken).
 * `playing` is left out on purpose: a page opened from a link starts paused,
 * as moving content should not start by itself.
 */
import type { AlgorithmInfo, OptionSpec } from '../core/types.js';
import {
  type AppState,
  type OptionValue,
  PAGE_OPTIONS,
  SPEEDS_STEPS_PER_SECOND,
  defaultAlgorithm,
  defaultState,
} from './app-state.js';

/** A number as typed in the query, or undefined for text that is not one. */
function numberOf(text: string): number | undefined {
  const value = Number(text);
  return text.trim() !== '' && Number.isFinite(value) ? value : undefined;
}

/**
 * An option's value from its query text, or undefined when the text cannot be
 * that kind of value. Numbers are kept as given (even out of range or
 * fractional): the core judges them and the form shows its verdict.
 */
function parseOption(spec: OptionSpec, text: string): OptionValue | undefined {
  switch (spec.kind.type) {
    case 'point': {
      const coords = text.split(',').map(numberOf);
      return coords.every((c) => c !== undefined) ? (coords as number[]) : undefined;
    }
    case 'choice':
      return spec.kind.values.includes(text) ? text : undefined;
    case 'number':
    case 'integer':
      return numberOf(text);
    case 'boolean':
      return text === 'true' ? true : text === 'false' ? false : undefined;
  }
}

function formatOption(value: OptionValue): string {
  return Array.isArray(value) ? value.join(',') : String(value);
}

/** Query text (without '?') for a state; commas are left readable. */
export function stateToQuery(state: AppState): string {
  const pairs: [string, string][] = [['algorithm', state.algorithm]];
  for (const [name, value] of Object.entries(state.options)) pairs.push([name, formatOption(value)]);
  pairs.push(['step', String(state.pointIndex)], ['speed', String(state.speed)]);
  return pairs.map(([k, v]) => `${encodeURIComponent(k)}=${encodeURIComponent(v).replaceAll('%2C', ',')}`).join('&');
}

/**
 * The state a query describes, or undefined when it has none of the state's
 * keys. Keys it lacks, or whose text is unusable, take their defaults: a link
 * shows what its sender saw, not a mix with the reader's last visit. Without
 * `algorithm` (or with an id the catalogue lacks) it is the default algorithm.
 */
export function stateFromQuery(query: string, catalogue: readonly AlgorithmInfo[]): AppState | undefined {
  const params = new URLSearchParams(query);
  const info = catalogue.find((a) => a.id === params.get('algorithm')) ?? defaultAlgorithm(catalogue);
  const keys = ['algorithm', 'step', 'speed', ...info.options.map((o) => o.name)];
  if (!keys.some((k) => params.has(k))) return undefined;
  const state = defaultState(info);
  for (const spec of info.options) {
    const text = params.get(spec.name);
    if (text === null || spec.name in PAGE_OPTIONS) continue;
    const value = parseOption(spec, text);
    if (value !== undefined) state.options[spec.name] = value;
  }
  const step = numberOf(params.get('step') ?? '');
  if (step !== undefined && Number.isSafeInteger(step) && step >= 0) state.pointIndex = step;
  const speed = numberOf(params.get('speed') ?? '');
  if (SPEEDS_STEPS_PER_SECOND.some((s) => s === speed)) state.speed = speed!;
  return state;
}
