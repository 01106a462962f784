/**
 * Colours of the 3D view, from the Okabe-Ito palette, which stays
 * distinguishable under the common colour-vision deficiencies. Visited and
 * not-yet-visited cells also differ in lightness and opacity, not hue alone.
 */
export const PALETTE = {
  background: '#f4f4f0',
  /** Cells visited before the current one (Okabe-Ito sky blue). */
  visited: '#56b4e9',
  /** The current cell (Okabe-Ito vermillion). */
  current: '#d55e00',
  /** Cells the path has not reached yet: a faint neutral grey. */
  ahead: '#8c8c8c',
  /** The ideal path (Okabe-Ito black, softened). */
  ideal: '#1a1a1a',
  /** The second path of an overlaid comparison (Okabe-Ito bluish green). */
  second: '#009e73',
  /** A learner's points checked against the rule (Check points; Okabe-Ito blue). */
  learner: '#0072b2',
  /** Cells only the first compared path visits, the first difference of checked points, and the steps of the picked G-code line (Okabe-Ito orange). */
  onlyFirst: '#e69f00',
  /** Cells only the second compared path visits (Okabe-Ito reddish purple). */
  onlySecond: '#cc79a7',
  /**
   * The exit face's regions a-d (Wang Fig. 4b), one Okabe-Ito hue each,
   * always drawn with their letters too: blue, bluish green, reddish purple
   * and orange differ in lightness as well as hue.
   */
  regionA: '#e69f00',
  regionB: '#0072b2',
  regionC: '#009e73',
  regionD: '#cc79a7',
  /**
   * The circle's two candidate cells (Okabe-Ito blue), outlined: the one
   * taken solid and thicker, the other dashed, so they differ in more than
   * hue. Shared with region b, which is never shown at the same step.
   */
  candidate: '#0072b2',
  /** Where the ideal line crosses the exit plane (Okabe-Ito yellow, ringed in black): no other part of the view is yellow. */
  crossing: '#f0e442',
  /** Grid lines on the floor and axis arrows. */
  grid: '#cfcfc6',
  axis: '#555555',
} as const;

/**
 * One colour per axis x, y, z, a, b, c in charts: black, vermillion and blue
 * for x, y and z, as Wang's Figure 6 draws them in black, red and blue, in
 * Okabe-Ito shades that survive colour blindness; then orange, bluish green
 * and reddish purple.
 */
export const AXIS_COLOURS = ['#1a1a1a', '#d55e00', '#0072b2', '#e69f00', '#009e73', '#cc79a7'] as const;
