/**
 * What a user typed into a field that the page refused before the core saw
 * it (an empty coordinate, "80,abc" for steps per mm). The state, and so the
 * link and localStorage, holds valid values only; the typed text is kept
 * here, so that a reload shows the field as it was typed, with its message,
 * not the last valid value. A draft goes with the state's value of its
 * field when it was typed, and is shown again only over that same value: a
 * link or a later edit with another value wins.
 *
 * Each draft is kept twice: in this tab's sessionStorage, which a reload of
 * the tab reads first, and in localStorage, for a new visit. With one copy,
 * shared by every tab, another tab that typed in the same field (and then
 * typed it right, dropping the draft) took this tab's away: its text, typed
 * and refused, came back on reload as the last valid value.
 */
import { storage, tabStorage } from './storage-areas.js';

const KEY = 'voxpath-drafts';

/** A field's controls' texts as typed, and the state's value of the field then (as JSON). */
interface Draft {
  texts: string[];
  value: string;
}

function read(area: Storage | undefined): Record<string, Draft> {
  try {
    const drafts: unknown = JSON.parse(area?.getItem(KEY) ?? '{}');
    return typeof drafts === 'object' && drafts !== null ? (drafts as Record<string, Draft>) : {};
  } catch {
    return {};
  }
}

function write(area: Storage | undefined, drafts: Record<string, Draft>): void {
  try {
    if (Object.keys(drafts).length === 0) area?.removeItem(KEY);
    else area?.setItem(KEY, JSON.stringify(drafts));
  } catch {
    // Storage full or blocked: the draft is lost on reload, as before.
  }
}

/** Keeps the texts typed into field `id` (refused), over the state's value `value`. */
export function keepDraft(id: string, texts: string[], value: unknown): void {
  const draft = { texts, value: JSON.stringify(value ?? null) };
  for (const area of [tabStorage(), storage()]) write(area, { ...read(area), [id]: draft });
}

/** Forgets this tab's draft of field `id` (its value was accepted, or typed right again), and the shared copy if it is this tab's. */
export function dropDraft(id: string): void {
  const mine = read(tabStorage());
  const shared = read(storage());
  const own = mine[id];
  if (own) {
    delete mine[id];
    write(tabStorage(), mine);
  }
  if (shared[id] && (own === undefined || JSON.stringify(shared[id]) === JSON.stringify(own))) {
    delete shared[id];
    write(storage(), shared);
  }
}

/**
 * The texts last typed into field `id` and refused, to put back when the
 * field is made while the state still holds `value` for it: as the page
 * loads, and when a mode's form is made again (Trace after G-code mode,
 * which dropped an empty coordinate for the last valid value). Else the
 * draft is dropped: a field made for another algorithm, whose example move
 * replaces the inputs, shows the state's value, and so does a field whose
 * value a link changed.
 */
export function restoredDraft(id: string, value: unknown): string[] | undefined {
  const draft = read(tabStorage())[id] ?? read(storage())[id];
  if (draft && draft.value === JSON.stringify(value ?? null) && Array.isArray(draft.texts)) return draft.texts;
  dropDraft(id);
  return undefined;
}

/**
 * Whether this tab holds a text typed and refused in a field whose id
 * starts with `prefix` (a form's): an input being edited here, which the
 * state does not show.
 */
export function draftedHere(prefix: string): boolean {
  return Object.keys(read(tabStorage())).some((id) => id.startsWith(prefix));
}
