/**
 * Results that no longer match the inputs: after the core rejected an input
 * (or a run was cancelled), the view, the inspector, the comparison and the
 * experiment's tables still show what was traced last. They stay, because
 * they are still worth reading and the next valid input replaces them, but
 * they are marked: dimmed, with a note saying what they are (style.css,
 * body[data-stale]).
 */

/** Why what is on screen is not of the inputs shown. */
export type Staleness = 'rejected' | 'cancelled';

const NOTES: Record<Staleness, string> = {
  rejected: 'Out of date: the inputs were not traced (see the message by them). Shown: the last ones that were.',
  cancelled: 'Out of date: the run was cancelled. Shown: the last run that went to its end.',
};

/** Why what is on screen is out of date, if it is (as markStale last said). */
export function staleness(): Staleness | undefined {
  return document.body.dataset.stale as Staleness | undefined;
}

/** Marks the results on screen as out of date (why), or as those of the inputs again (undefined). */
export function markStale(note: HTMLElement, why: Staleness | undefined): void {
  if (why) document.body.dataset.stale = why;
  else delete document.body.dataset.stale;
  note.textContent = why ? NOTES[why] : '';
}
