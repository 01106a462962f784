/** How the page writes grid quantities, the same way in every view. */

/** Axis names by axis index, as the core names them in its messages. */
export const AXIS_NAMES = ['x', 'y', 'z', 'a', 'b', 'c'] as const;

/** "(3, 2, 2)": a grid point, in grid units. */
export function formatPoint(coords: ArrayLike<number>): string {
  return `(${Array.from(coords).join(', ')})`;
}
