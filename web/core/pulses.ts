/**
 * Step/direction pulse trains for a timing diagram. Tick model: one tick is
 * one step of the trace (step index k). On tick k an axis pulses STEP when it
 * moves in step k, and its DIR level is the direction of that move (set
 * before the STEP edge, as drivers need) or, when it does not move, the
 * level it was left at; DIR starts positive. Ticks are not time: the feed
 * is not modelled.
 */
import type { Trace } from './trace.js';

/** One axis's signals over a range of ticks. */
export interface PulseTrain {
  /** step[i] = 1 when the axis pulses on tick from + i. */
  step: Uint8Array;
  /** dir[i] = +1 or -1: the DIR level on tick from + i. */
  dir: Int8Array;
}

/** The STEP and DIR signals of every axis over step indices from..to. */
export function pulseTrains(trace: Trace, from: number, to: number): PulseTrain[] {
  const codes = trace.stepCodes(from, to);
  const levels = trace.directionLevels(from, to);
  const trains: PulseTrain[] = [];
  for (let axis = 0; axis < trace.dims; axis++) {
    const step = new Uint8Array(to - from);
    const dir = new Int8Array(to - from);
    for (let i = 0; i < step.length; i++) {
      // Packed step (grid::Step): bit a = axis a moves.
      step[i] = (codes[i]! >> axis) & 1;
      dir[i] = (levels[i]! >> axis) & 1 ? -1 : 1;
    }
    trains.push({ step, dir });
  }
  return trains;
}
