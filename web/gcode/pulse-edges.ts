/**
 * Where the timing diagram draws a program's STEP pulses (timing-diagram.ts).
 * A driver's pulse is some µs, too thin to see at the diagram's scale, so a
 * pulse is drawn as wide as its neighbours leave room for.
 */

/** Rows of the diagram a step: its STEP pulse's rise and fall, and where DIR settles for the next step. */
export const ROWS_PER_STEP = 3;

/** How long after a lone step (or steps all at one instant) the diagram runs, seconds: no gap gives it a scale. */
export const LONE_STEP_SECONDS = 1e-3;

/**
 * The instants of `times` (seconds, one per step, in order) as the diagram's
 * rows, ROWS_PER_STEP a step: where its STEP pulse rises (the step's
 * instant), where it is drawn falling, half-way to the nearer of the steps
 * beside it, and half-way to the next step, where a DIR the next step needs
 * is set (as the VCD sets it: settled before the edge, not at it); then the
 * right edge, as far after the last step as the one before it was from it
 * (1 ms for a single step, or two at one instant). Half the shorter gap,
 * not the gap to the next step: across a stop or a dwell a pulse stays as
 * narrow as its neighbours', rather than high for half the time the
 * machine stands still.
 */
export function pulseEdges(times: Float64Array): Float64Array {
  const ticks = times.length;
  const x = new Float64Array(ROWS_PER_STEP * ticks + 1);
  if (ticks === 0) return x;
  const lastGap = (ticks > 1 ? times[ticks - 1]! - times[ticks - 2]! : 0) || LONE_STEP_SECONDS;
  for (let i = 0; i < ticks; i++) {
    const next = i + 1 < ticks ? times[i + 1]! : times[i]! + lastGap;
    const gap = Math.min(next - times[i]!, i > 0 ? times[i]! - times[i - 1]! : Number.POSITIVE_INFINITY);
    x[ROWS_PER_STEP * i] = times[i]!;
    x[ROWS_PER_STEP * i + 1] = times[i]! + gap / 2;
    x[ROWS_PER_STEP * i + 2] = (times[i]! + next) / 2;
  }
  x[ROWS_PER_STEP * ticks] = times[ticks - 1]! + lastGap;
  return x;
}

/**
 * Whether a window of steps at instants `times` (seconds; the program's
 * first steps when `first`) is drawn from 0 s, idle until its first step:
 * from rest the first steps come slowly, which the wait before them shows,
 * unless the wait is longer than the steps drawn take (a dwell of 2 s before
 * them pressed their pulses into one bar at the edge of a 2.2 s window).
 */
export function drawnFromZero(times: Float64Array, first: boolean): boolean {
  return first && times.length > 0 && times[0]! > 0 && times[0]! <= times[times.length - 1]! - times[0]!;
}
