/**
 * The widest label an x axis's ticks over `min..max` can have, as uPlot
 * writes numbers (en-US, with separators): the range's largest magnitude
 * with the decimals ticks over its span take (ticks a tenth of the span
 * apart or more, and one decimal more for the 2.5 and 0.25 steps). A chart
 * sizes its ticks' room from it (chart.ts xTickSpace): with uPlot's fixed
 * 50 px, a long program's time axis seen 100 ms at a time ran its labels
 * together ("1,050.0251,050.05").
 */
export function widestTickLabel(min: number, max: number): string {
  const span = Math.abs(max - min) || 1;
  // Less a hair: 1050.1 - 1050 is 0.09999999999990905, not 0.1.
  const decimals = Math.min(12, Math.max(0, Math.ceil(-Math.log10(span / 10) - 1e-9) + 1));
  return Math.max(Math.abs(min), Math.abs(max)).toLocaleString('en-US', { minimumFractionDigits: decimals, maximumFractionDigits: decimals });
}
