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
 * same after a reload. When the text kept is replaced in turn (a sample
 * picked), both programs are offered (AppState's secondReplacedProgram):
 * the two change places, each still the same tab's.
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
  /** The text and the replaced ones at the last look (none yet: the page has just loaded). */
  #seen: { text: string; replaced: string; second: string } | undefined;
  /** Whether the replaced text last seen is another tab's, written over by this tab's. */
  #othersText = false;

  constructor(key: string) {
    this.#key = key;
  }

  /**
   * Whether `replaced` (the text offered back, '' for none), beside `text`
   * (the program or points the state holds now), is another tab's text that
   * this tab's was kept over, rather than a text of this tab's replaced.
   * `second` (a program: AppState's secondReplacedProgram; '' for none) is
   * the other of the two tabs' texts, so the other way round. Called at
   * every render of the offer's panel: a new offer is judged against the
   * texts of the render before it.
   */
  othersText(text: string, replaced: string, second = ''): boolean {
    const seen = this.#seen;
    this.#seen = { text, replaced, second };
    if (seen && replaced === seen.replaced && second === seen.second) return this.#othersText;
    const store = tabStorage();
    const noted = store?.getItem(this.#key) ?? undefined;
    if (seen && seen.replaced !== '' && replaced !== '' && (replaced === seen.text || replaced === seen.second)) {
      // The two tabs' texts changed places (the one shown replaced, the
      // second one or the one shown brought back): the offer now holds the
      // other one of the two.
      this.#othersText = !this.#othersText;
    } else if (seen && replaced !== '' && text === seen.text) {
      // A new offer beside the same text: the other tab's, written over.
      this.#othersText = true;
    } else {
      // Hashed only where this tab noted a text of the other tab's (the page loaded, or the texts moved).
      this.#othersText = replaced !== '' && noted !== undefined && noted === fingerprint(replaced);
    }
    const others = this.#othersText ? replaced : second;
    const mark = others === '' ? undefined : fingerprint(others);
    try {
      if (mark !== undefined) {
        if (mark !== noted) store?.setItem(this.#key, mark);
      } else if (noted !== undefined) store?.removeItem(this.#key);
    } catch {
      // Storage full or blocked: after a reload, the offer says the text was this tab's.
    }
    return this.#othersText;
  }
}
