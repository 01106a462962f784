/** `seconds` in the unit formatSeconds writes it in: s from a second (and 0), ms from a millisecond, µs under. */
function inUnit(seconds: number): { value: number; unit: 's' | 'ms' | 'µs' } {
  const abs = Math.abs(seconds);
  if (abs >= 1 || abs === 0) return { value: seconds, unit: 's' };
  if (abs >= 1e-3) return { value: seconds * 1e3, unit: 'ms' };
  return { value: seconds * 1e6, unit: 'µs' };
}

/** Seconds for people: "3.000 s", "12.500 ms", "40.0 µs". */
export function formatSeconds(seconds: number): string {
  const { value, unit } = inUnit(seconds);
  return `${value.toFixed(unit === 'µs' ? 1 : 3)} ${unit}`;
}

/**
 * Seconds in few characters, to two significant digits in formatSeconds'
 * unit: "2 s", "1.1 s", "4.1 ms", "130 µs" (the timing diagram's pause
 * label where its box is too narrow for formatSeconds' "+2.000 s").
 */
export function formatSecondsBrief(seconds: number): string {
  // Rounded before the unit is chosen: 0.9996 s is "1 s", not "1000 ms".
  const { value, unit } = inUnit(Number(seconds.toPrecision(2)));
  return `${Number(value.toPrecision(2))} ${unit}`;
}

/**
 * The unit a span of time reads best in on an axis (ms, or µs under a
 * millisecond), and its factor from seconds. A millisecond less the float
 * error of a difference of instants is one: a single step's window, 1 ms
 * from its instant, came out 0.9999999999998899 ms at some instants and was
 * read in µs, labelled 50,000 to 51,000.
 */
export function timeUnit(spanSeconds: number): { unit: 'ms' | 'µs'; perSecond: number } {
  return spanSeconds < 1e-3 * (1 - 1e-9) ? { unit: 'µs', perSecond: 1e6 } : { unit: 'ms', perSecond: 1e3 };
}
