/** How the page writes grid quantities, the same way in every view. */

export { AXIS_NAMES } from './core/axes.js';

/** "(3, 2, 2)": a grid point, in grid units. */
export function formatPoint(coords: ArrayLike<number>): string {
  return `(${Array.from(coords).join(', ')})`;
}
