/**
 * About the widest label an x axis's ticks over `min..max` can have: the
 * end of larger magnitude, its sign kept, with the decimals ticks over the
 * span take (ticks a tenth of the span apart or more, and one decimal more
 * for the 2.5 and 0.25 steps), at most 3 as uPlot writes them, with
 * thousands separators. A chart sizes its ticks' room from it (chart.ts
 * xTickSpace): with uPlot's fixed 50 px, a long program's time axis seen
 * 100 ms at a time ran its labels together ("1,050.0251,050.05").
 */
export function widestTickLabel(min: number, max: number): string {
  const span = Math.abs(max - min) || 1;
  // Less a hair: 1050.1 - 1050 is 0.09999999999990905, not 0.1.
  const decimals = Math.min(3, Math.max(0, Math.ceil(-Math.log10(span / 10) - 1e-9) + 1));
  const largest = Math.abs(min) > Math.abs(max) ? min : max;
  return largest.toLocaleString('en-US', { minimumFractionDigits: decimals, maximumFractionDigits: decimals });
}
