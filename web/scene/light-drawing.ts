/**
 * Which way a path is drawn (voxel-path.ts): every cell as a cube (the full
 * drawing) or the lighter way, and the box that is decided on. Without
 * three.js, so that the worker decides as the view does: it makes a
 * learner's line through their cells' centers only for a path the view
 * draws whole (LearnerCheck in web/worker/protocol.ts).
 */
import type { PointBounds } from '../core/types.js';

/**
 * A path this many grid units wide (on its widest axis) or more is drawn as
 * points too: framed whole, its cubes would be under 2 pixels, which points
 * (never drawn smaller than 2 pixels) keep visible.
 */
export const LIGHT_DRAWING_SPAN = 300;

/**
 * Whether a path of `cells` cells, its cells' box `widestCells` grid units
 * wide on its widest drawn axis, is drawn the lighter way where paths of
 * `lightCells` cells and more are (lightDrawingCells() on the page, sent to
 * the worker as PointsSent.allBelow).
 */
export function drawnLight(cells: number, widestCells: number, lightCells: number): boolean {
  return cells >= lightCells || widestCells >= LIGHT_DRAWING_SPAN;
}

/** How wide the box of the cells at `bounds` (their centers) is on its widest drawn axis (the first three), grid units: their edges, not their centers. */
export function widestCells(bounds: PointBounds): number {
  const widths = [0, 1, 2].map((a) => (bounds.max[a] ?? 0) - (bounds.min[a] ?? 0) + 1);
  return Math.max(...widths);
}

/**
 * The smallest and largest coordinate of `points` on each axis, as the
 * core's PointBounds: for points that did not come from the core (a
 * learner's, the cells a comparison picks out); a trace's come with it.
 */
export function pointBounds(points: Int32Array, dims: number): PointBounds {
  const min = Array.from(points.subarray(0, dims));
  const max = [...min];
  for (let o = dims; o < points.length; o += dims) {
    for (let a = 0; a < dims; a++) {
      const c = points[o + a]!;
      if (c < min[a]!) min[a] = c;
      else if (c > max[a]!) max[a] = c;
    }
  }
  return { min, max };
}
