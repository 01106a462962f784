/**
 * What a user typed into a field that the page refused before the core saw
 * it (an empty coordinate, "80,abc" for steps per mm). The state, and so the
 * link and localStorage, holds valid values only; the typed text is kept
 * here, in localStorage too, so that a reload shows the field as it was
 * typed, with its message, not the last valid value. A draft goes with the
 * state's value of its field when it was typed, and is shown again only over
 * that same value: a link or a later edit with another value wins.
 */
import { storage } from './persist.js';

const KEY = 'voxpath-drafts';

/** A field's controls' texts as typed, and the state's value of the field then (as JSON). */
interface Draft {
  texts: string[];
  value: string;
}

function read(): Record<string, Draft> {
  try {
    const drafts: unknown = JSON.parse(storage()?.getItem(KEY) ?? '{}');
    return typeof drafts === 'object' && drafts !== null ? (drafts as Record<string, Draft>) : {};
  } catch {
    return {};
  }
}

function write(drafts: Record<string, Draft>): void {
  try {
    const store = storage();
    if (Object.keys(drafts).length === 0) store?.removeItem(KEY);
    else store?.setItem(KEY, JSON.stringify(drafts));
  } catch {
    // Storage full or blocked: the draft is lost on reload, as before.
  }
}

/** Keeps the texts typed into field `id` (refused), over the state's value `value`. */
export function keepDraft(id: string, texts: string[], value: unknown): void {
  write({ ...read(), [id]: { texts, value: JSON.stringify(value ?? null) } });
}

/** Forgets field `id`'s draft: its value was accepted, or typed right again. */
export function dropDraft(id: string): void {
  const drafts = read();
  if (!(id in drafts)) return;
  delete drafts[id];
  write(drafts);
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
  const draft = read()[id];
  if (draft && draft.value === JSON.stringify(value ?? null) && Array.isArray(draft.texts)) return draft.texts;
  dropDraft(id);
  return undefined;
}
