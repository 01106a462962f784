/**
 * Whose text an offer to bring back a replaced program or points holds, from
 * this tab's side. After a clash (persist.ts's otherTabEdits: the program,
 * or the points, typed in two tabs at the same time) both tabs hold the same
 * state: the text of the tab that wrote last, and the other tab's, kept to
 * bring back. In the tab whose text was written over, the offer holds its
 * own text ("Your program (3 lines) was replaced by ..."); in the tab whose
 * text was kept, the other tab's, and the offer said the same there, the
 * wrong way round. The state cannot tell the two apart, but each tab saw
 * the offer come: with a new text in the tab whose text it replaced (which
 * followed the other's write; or a sample picked, a link opened), with its
 * own text unchanged in the tab that kept it. That tab notes it in its
 * sessionStorage (a fingerprint of the other's text), so that it says the
 * same after a reload.
 */
import { tabStorage } from './storage-areas.js';

/** A short mark of `text`, its length and FNV-1a hash of its UTF-16 units: sessionStorage holds a few MB, not a copy of a long program. */
function fingerprint(text: string): string {
  let hash = 0x811c9dc5;
  for (let i = 0; i < text.length; i++) hash = Math.imul(hash ^ text.charCodeAt(i), 0x01000193);
  return `${text.length}:${(hash >>> 0).toString(36)}`;
}

export class OfferSide {
  /** This tab's sessionStorage key for the mark of the other tab's text this tab's was kept over. */
  readonly #key: string;
  /** The text and the replaced one at the last look (none yet: the page has just loaded). */
  #seen: { text: string; replaced: string } | undefined;
  /** Whether the replaced text last seen is another tab's, written over by this tab's. */
  #othersText = false;

  constructor(key: string) {
    this.#key = key;
  }

  /**
   * Whether `replaced` (the text offered back, '' for none), beside `text`
   * (the program or points the state holds now), is another tab's text that
   * this tab's was kept over, rather than a text of this tab's replaced.
   * Called at every render of the offer's panel: a new offer is judged
   * against the text of the render before it.
   */
  othersText(text: string, replaced: string): boolean {
    const seen = this.#seen;
    this.#seen = { text, replaced };
    if (seen && replaced === seen.replaced) return this.#othersText;
    const store = tabStorage();
    const noted = store?.getItem(this.#key) ?? undefined;
    // Hashed only where this tab may have kept its text over it: the page
    // loaded with an offer this tab had noted, or a new offer beside the same text.
    const mark = replaced !== '' && (seen ? text === seen.text : noted !== undefined) ? fingerprint(replaced) : undefined;
    this.#othersText = mark !== undefined && (seen !== undefined || noted === mark);
    try {
      if (this.#othersText) store?.setItem(this.#key, mark!);
      else if (noted !== undefined) store?.removeItem(this.#key);
    } catch {
      // Storage full or blocked: after a reload, the offer says the text was this tab's.
    }
    return this.#othersText;
  }
}
