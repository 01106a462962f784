/**
 * Where the timing diagram draws a program's STEP pulses (timing-diagram.ts).
 * A driver's pulse is some µs, too thin to see at the diagram's scale, so a
 * pulse is drawn as wide as its neighbours leave room for.
 */

/**
 * The instants of `times` (seconds, one per step, in order) as the diagram's
 * rows: two a step, where its STEP pulse rises (the step's instant) and where
 * it is drawn falling, half-way to the nearer of the steps beside it, then
 * the right edge, as far after the last step as the one before it was from
 * it (1 ms for a single step, or two at one instant). Half the shorter gap,
 * not the gap to the next step: across a stop or a dwell a pulse stays as
 * narrow as its neighbours', rather than high for half the time the
 * machine stands still.
 */
export function pulseEdges(times: Float64Array): Float64Array {
  const ticks = times.length;
  const x = new Float64Array(2 * ticks + 1);
  if (ticks === 0) return x;
  const lastGap = (ticks > 1 ? times[ticks - 1]! - times[ticks - 2]! : 0) || 1e-3;
  for (let i = 0; i < ticks; i++) {
    const next = i + 1 < ticks ? times[i + 1]! : times[i]! + lastGap;
    const gap = Math.min(next - times[i]!, i > 0 ? times[i]! - times[i - 1]! : Number.POSITIVE_INFINITY);
    x[2 * i] = times[i]!;
    x[2 * i + 1] = times[i]! + gap / 2;
  }
  x[2 * ticks] = times[ticks - 1]! + lastGap;
  return x;
}
