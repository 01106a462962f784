/**
 * Trace mode's Check points panel: a learner pastes the points their
 * program printed; the core (in the worker) checks them against the rule
 * traced, and this panel shows its answer: the first point where the two
 * part with the core's sentence and the rule's reason and decision values
 * there, the points around it side by side, and every catalogue rule the
 * points do follow. Malformed points show the core's error, which names the
 * line and column. The text goes into the state (learnerPoints), which the
 * link or storage keeps.
 *
 * Points of more than EDITABLE_LINES lines are listed read-only, as a long
 * G-code program is (form/long-text.ts): 200,000 points in the text box
 * took Chromium about 4 s to lay out, in one task, pasted and again at each
 * reload. Pasting over the list replaces them, Clear empties it, and "Edit
 * as text" puts them in the text box anyway, at that cost.
 *
 * A check of many points runs in the worker a slice at a time: the panel
 * shows what it does on a bar with a Cancel (at the page's cap, 1,500,000
 * steps, it takes about a second), and after a Cancel says so, with a
 * button that checks them again.
 *
 * Points changed in two tabs at the same time, one tab's written over by
 * the other's (AppState's replacedPoints), are offered back above the box
 * in both, each saying whose they are (OfferSide), as a program a sample
 * replaced is beside the editor, until brought back or the points are
 * changed again; so are points typed that a link's replaced, and when those
 * were a clash's points kept, the other tab's too, under them
 * (secondReplacedPoints).
 */
import type { Check } from '../core/index.js';
import { element } from '../form/options-form.js';
import { checkBar, RunProgress, type RunProgressElements } from '../form/run-progress.js';
import { LongTextField, linesInView, linesOfText } from '../form/long-text.js';
import { countOf, formatPoint, NO_VALUE_TEXT } from '../format.js';
import { ANOTHER_TABS_POINTS, type AppState, pointsBroughtBack } from '../state/app-state.js';
import { OfferSide } from '../state/offer-side.js';
import type { Store } from '../state/store.js';
import type { CheckRunProgress } from '../worker/protocol.js';

export interface CheckPanelElements {
  /** The disclosure holding the panel: opened when the state has points. */
  box: HTMLDetailsElement;
  text: HTMLTextAreaElement;
  /** The read-only list of long points, in the text box's place. */
  listing: HTMLElement;
  /** The note shown with the list, with its buttons: Clear, and one that puts the points in the text box anyway. */
  longNote: HTMLElement;
  clear: HTMLButtonElement;
  editAnyway: HTMLButtonElement;
  /** The offer of the points another tab's (or a link's) replaced, and its button that brings them back. */
  replaced: HTMLElement;
  bringBack: HTMLButtonElement;
  /** The offer of the second points kept (AppState's secondReplacedPoints), and its button. */
  secondReplaced: HTMLElement;
  secondBringBack: HTMLButtonElement;
  result: HTMLElement;
  /** The bar and Cancel of a check under way. */
  run: RunProgressElements;
}

/** What the panel asks of the page: go to a point, stop the check under way, check the points again. */
export interface CheckPanelActions {
  goTo: (pointIndex: number) => void;
  cancel: () => void;
  checkAgain: () => void;
}

/** A point, or what stands where a path has none. */
function pointText(point: number[] | null | undefined, none: string): string {
  return point ? formatPoint(point) : none;
}

export class CheckPanel {
  readonly #e: CheckPanelElements;
  readonly #actions: CheckPanelActions;
  readonly #store: Store<AppState>;
  readonly #progress: RunProgress;
  /** The points, in the text box or listed read-only. */
  readonly #field: LongTextField;
  /** The replaced points, what replaced them, and the second points kept, that the offers were last made for. */
  #offered = { points: '', by: '', second: '' };
  /** Whether the offer's points are this tab's, replaced, or another tab's this tab's points were kept over. */
  readonly #side = new OfferSide('voxpath.keptOverPoints');

  constructor(elements: CheckPanelElements, store: Store<AppState>, actions: CheckPanelActions) {
    this.#e = elements;
    this.#store = store;
    this.#actions = actions;
    this.#progress = new RunProgress(elements.run, actions.cancel);
    this.#field = new LongTextField(elements, (text) => this.#edited(text));
    this.#setText(store.state.learnerPoints);
    elements.box.open = store.state.learnerPoints !== '';
    elements.text.addEventListener('input', () => this.#edited(elements.text.value, true));
    elements.clear.addEventListener('click', () => {
      this.#edited('');
      elements.text.focus();
    });
    elements.editAnyway.addEventListener('click', () => {
      this.#setText(this.#field.text, { editable: true });
      elements.text.focus();
    });
    for (const [button, which] of [
      [elements.bringBack, 'replacedPoints'],
      [elements.secondBringBack, 'secondReplacedPoints'],
    ] as const) {
      button.addEventListener('click', () => {
        const fields = pointsBroughtBack(this.#store.state, which);
        this.#setText(fields.learnerPoints);
        this.#store.update(fields);
      });
    }
    this.#offerReplaced();
    elements.listing.addEventListener('scroll', () => this.#renderListing());
    // Shown (the panel opened, the mode changed) or resized: more or fewer lines are in view.
    new ResizeObserver(() => this.#renderListing()).observe(elements.listing);
  }

  /** The user changed the points to `text`: in the box (`fromBox`: typed, dropped), or by a paste the box did not take, or Clear. */
  #edited(text: string, fromBox = false): void {
    this.#setText(text, { fromBox });
    // Points of the user's own again: the replaced ones are no longer offered.
    this.#store.update({ learnerPoints: text, replacedPoints: '', replacedPointsBy: '', secondReplacedPoints: '' });
  }

  /** Shows `text` (LongTextField.show), a list from its top. */
  #setText(text: string, options?: { fromBox?: boolean; editable?: boolean }): void {
    this.#field.show(text, options);
    if (this.#field.listed) {
      this.#e.listing.scrollTop = 0;
      this.#renderListing();
    }
  }

  /** Lists the lines in view. */
  #renderListing(): void {
    const field = this.#field;
    if (!field.listed) return;
    const { first, last } = linesInView(this.#e.listing, field.listing.lineHeightPx, field.lineCount);
    field.listing.render(first, last);
  }

  /** Brings the points, and the offer of replaced ones, in line with the state (another tab's, followed). */
  render(): void {
    const points = this.#store.state.learnerPoints;
    if (this.#field.text !== points) {
      this.#setText(points);
      if (points !== '') this.#e.box.open = true;
    }
    this.#offerReplaced();
  }

  /**
   * Offers the points another tab's or a link's replaced, or another tab's
   * this tab's were kept over, above the box, and under them the second
   * points kept, if any (their lines counted only when they change).
   */
  #offerReplaced(): void {
    const { learnerPoints, replacedPoints: replaced, replacedPointsBy: by, secondReplacedPoints: second } = this.#store.state;
    const othersPoints = this.#side.othersText(learnerPoints, replaced, second);
    if (replaced === this.#offered.points && by === this.#offered.by && second === this.#offered.second) return;
    this.#offered = { points: replaced, by, second };
    const { replaced: offer, secondReplaced } = this.#e;
    offer.hidden = replaced === '';
    secondReplaced.hidden = second === '';
    if (second !== '') {
      secondReplaced.querySelector('.replaced-text')!.textContent = othersPoints
        ? `Your points (${linesOfText(second)}), typed at the same time, were written over by the other tab's.`
        : `The other tab's points (${linesOfText(second)}), typed at the same time, were written over by yours.`;
    }
    if (replaced === '') return;
    const lines = linesOfText(replaced);
    offer.querySelector('.replaced-text')!.textContent =
      othersPoints && by === ANOTHER_TABS_POINTS
        ? `The other tab's points (${lines}), typed at the same time, were written over by this tab's.`
        : `${othersPoints ? "The other tab's points" : 'Your points'} (${lines}) were replaced by ${by}.`;
    this.#e.box.open = true;
  }

  /** Nothing to show: no points, or a new rule being traced. */
  clear(): void {
    this.#e.result.replaceChildren();
  }

  /** How far the check under way has got, on the bar (undefined: none under way). */
  setProgress(progress: CheckRunProgress | undefined): void {
    if (progress === undefined) return this.#progress.set(undefined);
    const { bar, verb } = checkBar(progress);
    this.#progress.set(bar, verb);
  }

  /** The check was cancelled (its Cancel): the points are not checked, and a button checks them. */
  cancelled(): void {
    const again = element('button', { type: 'button', textContent: 'Check them' });
    again.dataset.testid = 'check-again';
    again.addEventListener('click', () => this.#actions.checkAgain());
    const p = element('p', { className: 'hint' }, 'Cancelled: your points are not checked. ', again);
    p.dataset.testid = 'check-cancelled';
    this.#e.result.replaceChildren(p);
  }

  /** The core refused the points (or the rule): its message, naming the line and column. */
  showError(message: string): void {
    const p = element('p', { className: 'field-error', textContent: message });
    p.dataset.testid = 'check-error';
    this.#e.result.replaceChildren(p);
  }

  /**
   * The core's check of the points against `check.algorithm`'s path. Steps
   * are counted as the rest of the page counts them ("Step 4 of 10", the
   * inspector's "Decision of step 4"): step n is the one that reaches point
   * n, the core's step index n - 1.
   */
  show(check: Check): void {
    const parts: HTMLElement[] = [];
    const first = check.firstDifference;
    const verdict = element('p', {
      className: 'check-verdict',
      textContent: first
        ? `Your points part from ${check.algorithm} at point ${first.pointIndex}: ${first.message}.`
        : `Your points are the path of ${check.algorithm}, point for point (${countOf(check.steps, 'step')}).`,
    });
    verdict.dataset.testid = 'check-verdict';
    verdict.dataset.matches = String(check.matches);
    parts.push(verdict);
    if (first) {
      const values = Object.entries(first.decisions).map(([name, v]) => `${name} = ${v === null ? NO_VALUE_TEXT : String(v)}`);
      const why = element(
        'div',
        { className: 'first-difference' },
        element('p', {}, element('strong', { textContent: first.stepIndex === null ? 'The rule: ' : `The rule at step ${first.stepIndex + 1}: ` }), first.why),
        ...(values.length > 0 ? [element('p', { className: 'first-difference-values', textContent: values.join(', ') })] : []),
      );
      why.dataset.testid = 'check-why';
      const rows = first.around.map((row) => {
        const tr = element(
          'tr',
          {},
          element('th', { scope: 'row', textContent: String(row.pointIndex) }),
          element('td', { textContent: pointText(row.expected, 'ended') }),
          element('td', { textContent: pointText(row.got, 'ended') }),
        );
        if (row.pointIndex === first.pointIndex) tr.className = 'check-differs';
        return tr;
      });
      const table = element(
        'table',
        { className: 'metrics-table' },
        element('caption', { textContent: 'Around it' }),
        element('thead', {}, element('tr', {}, ...['point', 'rule', 'yours'].map((h) => element('th', { scope: 'col', textContent: h })))),
        element('tbody', {}, ...rows),
      );
      const go = element('button', { type: 'button', textContent: `Go to point ${first.pointIndex}` });
      go.dataset.testid = 'go-check-difference';
      go.addEventListener('click', () => this.#actions.goTo(first.pointIndex));
      parts.push(why, table, go);
    }
    const follows = element(
      'p',
      { className: 'check-follows' },
      check.alsoMatches.length > 0 ? `Your points follow: ${check.alsoMatches.map((m) => m.label).join('; ')}.` : 'Your points follow no rule of the catalogue on this move.',
    );
    follows.dataset.testid = 'check-follows';
    parts.push(follows);
    const errata = check.alsoMatches.flatMap((m) => m.errata.map((e) => element('li', { textContent: `${m.label}: ${e}` })));
    if (errata.length > 0) parts.push(element('ul', { className: 'errata' }, ...errata));
    this.#e.result.replaceChildren(...parts);
  }
}
