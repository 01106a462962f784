/**
 * Step/direction pulse trains for a timing diagram. On step index k an axis
 * pulses STEP when it moves in step k, and its DIR level is the direction of
 * that move (set before the STEP edge, as drivers need) or, when it does not
 * move, the level it was left at; DIR starts positive.
 *
 * Two clocks: without times, one tick is one step (step index k); with the
 * step instants of a G-code program (`GcodeProgram.stepTimes`, the planned
 * motion profile), each axis's STEP edges get their instants in seconds and
 * the step rate in Hz between them.
 */
import { argumentError, describeValue } from './guard.js';
import { type Trace, requireTrace } from './trace.js';

/** One axis's signals over a range of step indices. */
export interface PulseTrain {
  /** step[i] = 1 when the axis pulses on step from + i. */
  step: Uint8Array;
  /** dir[i] = +1 or -1: the DIR level on step from + i. */
  dir: Int8Array;
  /** With times: the instant of each of this axis's STEP edges in the range, seconds. */
  edgeSeconds?: Float64Array;
  /**
   * With times: the step rate at each edge, Hz, 1 / (time since this axis's
   * previous edge in the range); NaN at the range's first edge.
   */
  rateHz?: Float64Array;
}

/**
 * The STEP and DIR signals of every axis over step indices from..to; given
 * `stepSeconds` (the instant of each step index from..to), also each axis's
 * STEP edges in seconds and its step rate in Hz.
 */
export function pulseTrains(trace: Trace, from: number, to: number, stepSeconds?: Float64Array): PulseTrain[] {
  requireTrace('trace', trace);
  // Checks from and to, naming them.
  const codes = trace.stepCodes(from, to);
  const levels = trace.directionLevels(from, to);
  if (stepSeconds !== undefined && !(stepSeconds instanceof Float64Array && stepSeconds.length === to - from)) {
    throw argumentError('stepSeconds', `expected the ${to - from} instants of steps ${from}..${to}, got ${describeValue(stepSeconds)}`);
  }
  if (stepSeconds !== undefined) requireInstantsInOrder(stepSeconds, from);
  const trains: PulseTrain[] = [];
  for (let axis = 0; axis < trace.dims; axis++) {
    const step = new Uint8Array(to - from);
    const dir = new Int8Array(to - from);
    let edges = 0;
    for (let i = 0; i < step.length; i++) {
      // Packed step (grid::Step): bit a = axis a moves.
      step[i] = (codes[i]! >> axis) & 1;
      edges += step[i]!;
      dir[i] = (levels[i]! >> axis) & 1 ? -1 : 1;
    }
    const train: PulseTrain = { step, dir };
    if (stepSeconds !== undefined) {
      const edgeSeconds = new Float64Array(edges);
      const rateHz = new Float64Array(edges);
      for (let i = 0, e = 0; i < step.length; i++) {
        if (step[i] === 0) continue;
        edgeSeconds[e] = stepSeconds[i]!;
        rateHz[e] = e === 0 ? Number.NaN : 1 / (edgeSeconds[e]! - edgeSeconds[e - 1]!);
        e++;
      }
      train.edgeSeconds = edgeSeconds;
      train.rateHz = rateHz;
    }
    trains.push(train);
  }
  return trains;
}

/**
 * Refuses step instants that are not finite or that go back: a step given
 * an instant before the step ahead of it made a negative step rate (and a
 * NaN a rate of NaN), said nowhere. Equal instants are steps planned at one
 * instant, as a program may plan them: their rate is Infinity.
 */
function requireInstantsInOrder(stepSeconds: Float64Array, from: number): void {
  for (let i = 0; i < stepSeconds.length; i++) {
    const seconds = stepSeconds[i]!;
    if (!Number.isFinite(seconds)) throw argumentError('stepSeconds', `step ${from + i}'s instant is ${seconds}, not a finite number of seconds`);
    const before = stepSeconds[i - 1];
    if (before !== undefined && seconds < before) {
      throw argumentError('stepSeconds', `step ${from + i} comes at ${seconds} s, before step ${from + i - 1} at ${before} s: instants go in step order`);
    }
  }
}
