/**
 * Long texts (a G-code program, a learner's points) shown without freezing
 * the page: a text box holding 100,000 lines takes Chromium over a second
 * to lay out, in one task, at every change of its value (and 200,000
 * points about 4 s). Past EDITABLE_LINES lines such a text is listed
 * read-only in a TextListing, which lays out only the lines in view; a
 * paste that would make the text box's text that long goes to the listing
 * before the box lays it out (divertLongPastes).
 */
import { countOf, grouped } from '../format.js';
import { element } from './options-form.js';

/**
 * Texts up to this many lines are edited in a text box; longer ones are
 * listed read-only. Chromium laid out 100,000 lines of G-code in a text box
 * in 1.2 to 1.6 s on this project's 2-core test machine, so the box costs at
 * most about 150 ms at this length.
 */
export const EDITABLE_LINES = 10_000;

/** Where each line of `text` starts (its character offset), and one past the end. */
export function lineStarts(text: string): number[] {
  const starts = [0];
  for (let i = text.indexOf('\n'); i !== -1; i = text.indexOf('\n', i + 1)) starts.push(i + 1);
  starts.push(text.length + 1);
  return starts;
}

/** The line (from 0) of a text (its line starts `starts`, lineStarts) holding character `offset`: by bisection of the line starts, not a scan of the text. */
export function lineAt(starts: readonly number[], offset: number): number {
  let [low, high] = [0, starts.length - 2];
  while (low < high) {
    const middle = (low + high + 1) >> 1;
    if (starts[middle]! <= offset) low = middle;
    else high = middle - 1;
  }
  return low;
}

/**
 * Character `offset` of a text (its line starts `before`) at the same line
 * and column in another text (its line starts `after`): past the other's
 * last line, on its last line; past a line's end, at that end.
 */
export function sameLineAndColumn(offset: number, before: readonly number[], after: readonly number[]): number {
  const line = lineAt(before, offset);
  const shown = Math.min(line, after.length - 2);
  return Math.min(after[shown]! + offset - before[line]!, after[shown + 1]! - 1);
}

/** Whether `text` has more than EDITABLE_LINES lines: found by counting no further than that. */
export function tooLongToEdit(text: string): boolean {
  let breaks = 0;
  for (let i = text.indexOf('\n'); i !== -1 && breaks < EDITABLE_LINES; i = text.indexOf('\n', i + 1)) breaks++;
  return breaks === EDITABLE_LINES;
}

/** Lines of `text` as the core counts them (and the status line says): a final line break ends the last line rather than starting an empty one. */
export function countedLines(text: string, starts: readonly number[]): number {
  return starts.length - 1 - (/[\n\r]$/.test(text) ? 1 : 0);
}

/** "3 lines": how many lines `text` has as the core counts them, as an offer of a replaced text says it. */
export function linesOfText(text: string): string {
  return countOf(countedLines(text, lineStarts(text)), 'line');
}

/** The lines of a `lineCount`-line text in view in `scroller` (lines `lineHeightPx` tall): first (from 0) and last (from 1, inclusive). */
export function linesInView(scroller: HTMLElement, lineHeightPx: number, lineCount: number): { first: number; last: number } {
  const first = Math.floor(scroller.scrollTop / lineHeightPx);
  return { first, last: Math.min(lineCount, first + Math.ceil(scroller.clientHeight / lineHeightPx) + 1) };
}

/**
 * A paste into `box` that would give it more than EDITABLE_LINES lines goes
 * to `onLong` (with the text the box would have held) instead of the box.
 * `shown` is the box's text as last read, with its line count: reading a
 * long box's value copies it. A text already that long in the box is there
 * because the user chose to edit it there, and its pastes stay in the box.
 */
function divertLongPastes(box: HTMLTextAreaElement, shown: () => { text: string; lineCount: number }, onLong: (text: string) => void): void {
  box.addEventListener('paste', (event) => {
    const { text, lineCount } = shown();
    if (lineCount > EDITABLE_LINES) return;
    const pasted = event.clipboardData?.getData('text/plain') ?? '';
    const after = text.slice(0, box.selectionStart) + pasted + text.slice(box.selectionEnd);
    if (!tooLongToEdit(after)) return;
    event.preventDefault();
    onLong(after);
  });
}

/**
 * A long text listed read-only in `listing` (a scrollable box): only the
 * lines in view are in the page, over a spacer as tall as the whole text.
 * Pasting over the listing replaces the text (`onPaste`).
 */
class TextListing {
  readonly #spacer = element('div', { className: 'listing-spacer' });
  readonly #lines = element('pre', { className: 'listing-lines' });
  #text = '';
  #starts: readonly number[] = [0, 1];
  #lineHeightPx = 18;

  constructor(listing: HTMLElement, onPaste: (text: string) => void) {
    listing.replaceChildren(this.#spacer, this.#lines);
    listing.addEventListener('paste', (event) => {
      event.preventDefault();
      onPaste(event.clipboardData?.getData('text/plain') ?? '');
    });
  }

  /** How tall a line of the listing is, px (its style's line height). */
  get lineHeightPx(): number {
    return this.#lineHeightPx;
  }

  /** Lists `text` (its line starts `starts`): the spacer as tall as all its lines and their padding. */
  setText(text: string, starts: readonly number[]): void {
    this.#text = text;
    this.#starts = starts;
    const style = getComputedStyle(this.#lines);
    this.#lineHeightPx = parseFloat(style.lineHeight) || this.#lineHeightPx;
    this.#spacer.style.height = `${(starts.length - 1) * this.#lineHeightPx + parseFloat(style.paddingTop) + parseFloat(style.paddingBottom)}px`;
  }

  /** Lays out lines first + 1..last (see linesInView), where they stand in the whole text. */
  render(first: number, last: number): void {
    // Without the last one's line break.
    this.#lines.textContent = this.#text.slice(this.#starts[first], Math.max(this.#starts[first]!, this.#starts[last]! - 1));
    this.#lines.style.top = `${first * this.#lineHeightPx}px`;
  }
}

/** A long text's field: its text box, the listing in its place past EDITABLE_LINES lines, and the note shown with the listing (its `.long-lines` says how many). */
export interface LongTextElements {
  text: HTMLTextAreaElement;
  listing: HTMLElement;
  longNote: HTMLElement;
}

/**
 * A long text shown in a text box, or past EDITABLE_LINES lines in a
 * TextListing in its place (a G-code program, a learner's points): the
 * text as last set or read (reading a long box's value copies it, so it is
 * read once per edit), where its lines start, and which of the two shows
 * it. A paste the box should not take, and a paste over the listing, go to
 * `onEdited` with the text they make.
 */
export class LongTextField {
  readonly listing: TextListing;
  readonly #e: LongTextElements;
  #text = '';
  /** Offsets where the lines of the text start, plus one past its end: lines are starts.length - 1. */
  #starts: readonly number[] = [0, 1];
  #listed = false;

  constructor(elements: LongTextElements, onEdited: (text: string) => void) {
    this.#e = elements;
    this.listing = new TextListing(elements.listing, onEdited);
    divertLongPastes(elements.text, () => ({ text: this.#text, lineCount: this.lineCount }), onEdited);
  }

  get text(): string {
    return this.#text;
  }

  get starts(): readonly number[] {
    return this.#starts;
  }

  get lineCount(): number {
    return this.#starts.length - 1;
  }

  /** True while the text is listed read-only rather than in the text box. */
  get listed(): boolean {
    return this.#listed;
  }

  /**
   * Shows `text`: in the text box when it has at most EDITABLE_LINES lines
   * (or `editable`), else in the listing. `fromBox`: the box already holds
   * it (the user typed it), so the box is not written, which would lose the
   * cursor and the undo history. A text written over the one in the box
   * (another tab's, followed) keeps the box's selection and scroll where
   * they were (#rewriteBox).
   */
  show(text: string, { fromBox = false, editable = false } = {}): void {
    const { text: box, listing, longNote } = this.#e;
    // Where the lines of the text the box holds start (none: the box is empty, its text listed).
    const inBox = this.#listed ? undefined : this.#starts;
    this.#text = text;
    this.#starts = lineStarts(text);
    // Text typed in the box stays there, whatever its length.
    this.#listed = !(editable || (fromBox && !this.#listed)) && this.lineCount > EDITABLE_LINES;
    box.hidden = this.#listed;
    listing.hidden = longNote.hidden = !this.#listed;
    if (this.#listed) {
      // An empty box lays out at once; the listing lays out only what is in view.
      box.value = '';
      longNote.querySelector('.long-lines')!.textContent = grouped(countedLines(text, this.#starts));
      this.listing.setText(text, this.#starts);
    } else if (!fromBox) {
      if (inBox) this.#rewriteBox(text, inBox);
      else box.value = text;
    }
  }

  /**
   * Writes `text` over the text in the box (its line starts `before`),
   * keeping the box's selection (and which way it runs) at the same lines
   * and columns (sameLineAndColumn), and its scroll: written as the box's
   * value, the caret of a user reading the box or about to type in it
   * jumped to the end of the text when another tab's text was followed.
   */
  #rewriteBox(text: string, before: readonly number[]): void {
    const box = this.#e.text;
    const { selectionStart, selectionEnd, selectionDirection, scrollTop, scrollLeft } = box;
    box.value = text;
    const kept = (offset: number) => sameLineAndColumn(offset, before, this.#starts);
    box.setSelectionRange(kept(selectionStart), kept(selectionEnd), selectionDirection ?? undefined);
    box.scrollTop = scrollTop;
    box.scrollLeft = scrollLeft;
  }
}
