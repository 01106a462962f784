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
  /** Grid lines on the floor and axis arrows. */
  grid: '#cfcfc6',
  axis: '#555555',
} as const;
