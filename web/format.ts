/** How the page writes grid quantities, the same way in every view. */

export { AXIS_NAMES } from './core/axes.js';
export { countOf, grouped } from './core/export.js';

/** What the page shows for a decision value where its column does not apply to the step. */
export const NO_VALUE_TEXT = '—';

/** "(3, 2, 2)": a grid point, in grid units. */
export function formatPoint(coords: ArrayLike<number>): string {
  return `(${Array.from(coords).join(', ')})`;
}


/** `text` ending as a sentence ends: the core's messages have no full stop of their own ("Y has no number after it The run stopped there."), but some do. */
export function sentence(text: string): string {
  return /[.!?]$/.test(text) ? text : `${text}.`;
}

/** `text` without the full stop it may end with, to go on within a sentence ("--max-steps 60000000.." in the status line). */
export function clause(text: string): string {
  return text.replace(/\.$/, '');
}

/** Items as a sentence lists them: "a", "a and b", "a, b and c". */
export function listed(items: readonly string[]): string {
  return items.length < 2 ? items.join('') : `${items.slice(0, -1).join(', ')} and ${items.at(-1)}`;
}
