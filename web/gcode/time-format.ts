/** Seconds for people: "3.000 s", "12.500 ms", "40.0 µs". */
export function formatSeconds(seconds: number): string {
  const abs = Math.abs(seconds);
  if (abs >= 1 || abs === 0) return `${seconds.toFixed(3)} s`;
  if (abs >= 1e-3) return `${(seconds * 1e3).toFixed(3)} ms`;
  return `${(seconds * 1e6).toFixed(1)} µs`;
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
