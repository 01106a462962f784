/**
 * G-code mode: the editor (a textarea with line numbers and two line marks),
 * the program's errors and warnings marked where it is edited (in the gutter,
 * the error's line tinted, and said above the editor), the sample programs, the machine's settings, the run's progress with
 * Cancel, the program's diagnostics and its move list. Sync goes both ways
 * through the program the worker holds:
 * - picking a line (the editor's cursor, a move or a diagnostic) asks which
 *   steps that line made: they are highlighted in the view and the step
 *   moves to the end of them;
 * - the current step asks which move made it: its line is marked in the
 *   editor (scrolled into view unless the user is typing) and in the move list.
 *
 * A program of more than EDITABLE_LINES lines is shown read-only in a
 * listing that lays out only the lines in view (form/long-text.ts). Pasting
 * over the listing replaces the program; "Edit as text" puts it in the text
 * box anyway, at the cost the listing avoids.
 *
 * A program the user typed or pasted that the page replaces (a sample
 * picked, a link's program) is kept (AppState's replacedProgram, stored as
 * the program is) and offered back beside the editor until it is brought
 * back or the user types a program again: a listed program has no undo, and
 * a reload kept only the sample. A program typed in two tabs at the same
 * time is offered in both, each saying whose it is (OfferSide); when the
 * one kept is replaced in turn, both are offered, one under the other.
 */
import type { GcodeDiagnostic, GcodeMove, GcodeProgress } from '../core/index.js';
import { OptionsForm, element } from '../form/options-form.js';
import { diagnosticText } from '../form/page-advice.js';
import { lineAt, linesInView, linesOfText, LongTextField, tooLongToEdit } from '../form/long-text.js';
import { linesBar, RunProgress } from '../form/run-progress.js';
import { countOf, formatPoint, sentence } from '../format.js';
import { ANOTHER_TABS_PROGRAM, type AppState, type Catalogue, machineSpecs, OptionSetter, programBroughtBack, programReplaced } from '../state/app-state.js';
import { OfferSide } from '../state/offer-side.js';
import type { Store } from '../state/store.js';
import type { RemoteProgram } from '../worker/client.js';
import type { InputError, LineSteps } from '../worker/protocol.js';

/** Moves listed at a time around the current one. */
const MOVES_SHOWN = 12;

export interface GcodePanelElements {
  sample: HTMLSelectElement;
  text: HTMLTextAreaElement;
  /** The read-only listing of a long program, a scrollable box over the text box's place. */
  listing: HTMLElement;
  /** The note shown with the listing, and its button that puts the program in the text box anyway. */
  longNote: HTMLElement;
  editAnyway: HTMLButtonElement;
  /** The offer of the user's program that the page replaced, and its button that brings it back. */
  replaced: HTMLElement;
  bringBack: HTMLButtonElement;
  /** The offer of the second program kept (AppState's secondReplacedProgram), and its button. */
  secondReplaced: HTMLElement;
  secondBringBack: HTMLButtonElement;
  gutter: HTMLElement;
  /** Above the editor: the program's error (and how many warnings), each with a way to its line. */
  problems: HTMLElement;
  backdrop: HTMLElement;
  machine: HTMLElement;
  formError: HTMLElement;
  run: HTMLButtonElement;
  progress: HTMLProgressElement;
  cancel: HTMLButtonElement;
  moves: HTMLElement;
}

interface SampleInfo {
  file: string;
  title: string;
  description: string;
}

/** The text of the site's file `path`; `what` names it in the error when it cannot be loaded. */
async function fetchedText(path: string, what: string): Promise<string> {
  const response = await fetch(path);
  if (!response.ok) throw new Error(`${what} could not be loaded (HTTP ${response.status})`);
  return response.text();
}

/** The sample program `file` as loaded. */
function sampleText(file: string): Promise<string> {
  return fetchedText(`samples/${encodeURIComponent(file)}`, `the sample ${file}`);
}

export class GcodePanel {
  readonly #e: GcodePanelElements;
  readonly #store: Store<AppState>;
  readonly #machineForm: OptionsForm;
  readonly #currentMark: HTMLElement;
  readonly #pickedMark: HTMLElement;
  /** The line of the program's error (a run stops at its first). */
  readonly #errorMark: HTMLElement;
  /** Lines with a diagnostic of the program on screen, marked in the gutter: an error wins over a warning. */
  #diagnosticLines = new Map<number, 'error' | 'warning'>();
  /** Called with the steps of a picked line, to highlight them and move the step there. */
  readonly #onPick: (line: number, steps: LineSteps) => void;
  /** Called with the decision columns of the current step's algorithm (undefined: no step, so all), for the inspector to show those only. */
  readonly #onColumns: (names: ReadonlySet<string> | undefined) => void;
  readonly #catalogue: Catalogue;
  #program: RemoteProgram | undefined;
  #pickedLine: number | undefined;
  #currentLine: number | undefined;
  /** The latest step asked about; answers for older ones are dropped. */
  #stepRequest = 0;
  #lineHeightPx = 18;
  #paddingTopPx = 4;
  /** True while the page inserts a program into the box as an edit (its input event is not the user's). */
  #programInserted = false;
  /** The samples listed (samples/index.json), fetched once. */
  readonly #samples: Promise<SampleInfo[]>;
  /** The sample programs' texts, fetched when first needed: a program that is one of them as loaded is not the user's own. */
  #sampleTexts: Promise<Set<string>> | undefined;
  /** The replaced programs, and what replaced the first, that the offers were last made for (or withdrawn, as a sample's). */
  #offered = { program: '', by: '', second: '' };
  /** Whether the offer's program is this tab's, replaced, or another tab's this tab's program was kept over. */
  readonly #side = new OfferSide('voxpath.keptOverProgram');
  /** The gutter's numbers: only the lines in view (a program can have 100,000). */
  readonly #gutterLines: HTMLElement;
  /** The program, in the text box or listed read-only. */
  readonly #field: LongTextField;
  /** The run's progress bar and Cancel. */
  readonly #progress: RunProgress;

  constructor(
    elements: GcodePanelElements,
    catalogue: Catalogue,
    store: Store<AppState>,
    events: { onPick(line: number, steps: LineSteps): void; onColumns(names: ReadonlySet<string> | undefined): void; onRun(): void; onCancel(): void },
  ) {
    this.#e = elements;
    this.#store = store;
    this.#catalogue = catalogue;
    this.#onPick = events.onPick;
    this.#onColumns = events.onColumns;
    this.#currentMark = element('div', { className: 'line-mark current' });
    this.#currentMark.dataset.testid = 'gcode-current-line';
    this.#pickedMark = element('div', { className: 'line-mark picked' });
    this.#pickedMark.dataset.testid = 'gcode-picked-line';
    this.#errorMark = element('div', { className: 'line-mark error' });
    this.#errorMark.dataset.testid = 'gcode-error-line';
    elements.backdrop.append(this.#errorMark, this.#currentMark, this.#pickedMark);
    this.#gutterLines = element('span', { className: 'gutter-lines' });
    elements.gutter.replaceChildren(this.#gutterLines);

    this.#field = new LongTextField(elements, (text) => this.#edited(text));

    this.#setText(store.state.gcode);
    elements.text.addEventListener('input', () => this.#edited(elements.text.value, true));
    elements.listing.addEventListener('click', (event) => {
      const top = elements.listing.getBoundingClientRect().top;
      const line = Math.floor((event.clientY - top + elements.listing.scrollTop - this.#paddingTopPx) / this.#lineHeightPx) + 1;
      if (line >= 1 && line <= this.#lineCount) void this.#pick(line);
    });
    // The up and down arrows pick the line above or below, as a click does,
    // and bring it into view as the problems' links do: a keyboard's way
    // through a listed program (the listing declares them its own keys;
    // left and right still step).
    elements.listing.addEventListener('keydown', (event) => {
      const by = { ArrowUp: -1, ArrowDown: 1 }[event.key];
      if (by === undefined || event.altKey || event.ctrlKey || event.metaKey || this.#lineCount === 0) return;
      event.preventDefault();
      const from = this.#pickedLine ?? this.#currentLine ?? (by > 0 ? 0 : this.#lineCount + 1);
      this.#goToLine(Math.min(this.#lineCount, Math.max(1, from + by)));
    });
    elements.editAnyway.addEventListener('click', () => {
      this.#setText(this.#field.text, { editable: true });
      elements.text.focus();
    });
    for (const scroller of [elements.text, elements.listing]) {
      scroller.addEventListener('scroll', () => this.#placeMarks());
      // Shown (the mode changed) or resized: more or fewer lines are in view.
      new ResizeObserver(() => this.#placeMarks()).observe(scroller);
    }
    for (const type of ['click', 'keyup']) elements.text.addEventListener(type, () => this.#pick(this.#lineAt(elements.text.selectionStart)));
    elements.run.addEventListener('click', events.onRun);
    this.#progress = new RunProgress({ bar: elements.progress, cancel: elements.cancel, start: elements.run }, events.onCancel);

    const setter = new OptionSetter();
    this.#machineForm = new OptionsForm(elements.machine, elements.formError, machineSpecs(catalogue), 3, store.state.machine, (name, value) => {
      store.update({ machine: setter.set(store.state.machine, name, value) });
    }, 'machine');

    elements.sample.addEventListener('change', () => void this.#loadSample(elements.sample.value));
    elements.bringBack.addEventListener('click', () => this.#bringBack('replacedProgram'));
    elements.secondBringBack.addEventListener('click', () => this.#bringBack('secondReplacedProgram'));
    this.#samples = fetchedText('samples/index.json', 'the sample list').then((text) => JSON.parse(text) as SampleInfo[]);
    void this.#listSamples();
    this.#offerReplaced();
  }

  async #listSamples(): Promise<void> {
    const samples = await this.#samples;
    this.#e.sample.append(...samples.map((s) => element('option', { value: s.file, textContent: s.title, title: s.description })));
  }

  async #loadSample(file: string): Promise<void> {
    if (!file) return;
    const text = await sampleText(file);
    const title = [...this.#e.sample.options].find((option) => option.value === file)?.textContent ?? file;
    // Whether the program it replaces (as it is now: the user may have typed while the sample loaded) is the user's own.
    const typed = !(await this.#isSample(this.#store.state.gcode));
    this.#showProgram(text);
    this.#store.update({ ...programReplaced(this.#store.state, text, `the sample '${title}'`, typed), pointIndex: 0, camera: null });
  }

  /** Whether `text` is one of the sample programs as loaded (the default program is the square sample). */
  async #isSample(text: string): Promise<boolean> {
    this.#sampleTexts ??= this.#samples.then((samples) => Promise.all(samples.map(({ file }) => sampleText(file)))).then((texts) => new Set(texts));
    return (await this.#sampleTexts).has(text);
  }

  /** Puts a program the page chose (a sample, a program brought back) in the editor: as an edit the box can undo where it can (#replaceInBox). */
  #showProgram(text: string): void {
    if (!this.#replaceInBox(text)) this.#setText(text);
  }

  /**
   * Offers the program a sample, a link or another tab replaced (or another
   * tab's, which this tab's was kept over: OfferSide), beside the editor,
   * and under it the second one kept, if any (the other of two tabs'
   * programs); a sample's text, as loaded (a link's program replacing a
   * sample), is withdrawn instead: the user can pick it again.
   */
  #offerReplaced(): void {
    const { gcode, replacedProgram, replacedBy, secondReplacedProgram: second } = this.#store.state;
    const { replaced, secondReplaced } = this.#e;
    const othersProgram = this.#side.othersText(gcode, replacedProgram, second);
    // Called at every change of the state (each step played): a long program's lines are counted only when the offer changes.
    if (replacedProgram === this.#offered.program && replacedBy === this.#offered.by && second === this.#offered.second) return;
    const newProgram = replacedProgram !== this.#offered.program;
    this.#offered = { program: replacedProgram, by: replacedBy, second };
    secondReplaced.hidden = second === '';
    if (second !== '') {
      secondReplaced.querySelector('.replaced-text')!.textContent = othersProgram
        ? `Your program (${linesOfText(second)}), typed at the same time, was written over by the other tab's.`
        : `The other tab's program (${linesOfText(second)}), typed at the same time, was written over by yours.`;
    }
    if (replacedProgram === '') {
      replaced.hidden = true;
      return;
    }
    const lines = linesOfText(replacedProgram);
    const whose = othersProgram ? "The other tab's program" : 'Your program';
    replaced.querySelector('.replaced-text')!.textContent =
      othersProgram && replacedBy === ANOTHER_TABS_PROGRAM ? `The other tab's program (${lines}), typed at the same time, was written over by this one.` : `${whose} (${lines}) was replaced by ${replacedBy}.`;
    if (!newProgram) return;
    // Shown once it is known not to be a sample's text.
    replaced.hidden = true;
    void this.#isSample(replacedProgram).then((sample) => {
      const state = this.#store.state;
      if (replacedProgram !== state.replacedProgram) return;
      // The second one kept, if any, is offered in its place, as what replaced the sample's.
      if (sample) this.#store.update({ replacedProgram: state.secondReplacedProgram, replacedBy: state.secondReplacedProgram === '' ? '' : state.replacedBy, secondReplacedProgram: '' });
      else replaced.hidden = false;
    });
  }

  /** Puts the replaced program `which` back, exactly as it was, and runs it; its offer is withdrawn (programBroughtBack). */
  #bringBack(which: 'replacedProgram' | 'secondReplacedProgram'): void {
    const fields = programBroughtBack(this.#store.state, which);
    this.#e.sample.value = '';
    this.#showProgram(fields.gcode);
    this.#store.update({ ...fields, pointIndex: 0, camera: null });
  }

  /**
   * Puts a program the page chose in the text box as an edit the box can
   * undo, so that Ctrl+Z brings back the program it replaced (written as the
   * box's value, the user's own program was gone, and Undo gave a mix of
   * both). Only where both fit the box (a listing has no undo) and the
   * browser still records an inserted text (execCommand). Focus goes back
   * where it was. False when the program is to be shown the plain way.
   */
  #replaceInBox(text: string): boolean {
    const box = this.#e.text;
    if (this.#field.listed || tooLongToEdit(text)) return false;
    const focused = document.activeElement;
    box.focus({ preventScroll: true });
    // A box that cannot take focus (hidden: the mode changed while the
    // sample loaded) would let the insertion land in whatever has it.
    if (document.activeElement !== box) return false;
    box.select();
    this.#programInserted = true;
    const inserted = document.execCommand('insertText', false, text) && box.value === text;
    this.#programInserted = false;
    if (focused instanceof HTMLElement) focused.focus({ preventScroll: true });
    if (!inserted) return false;
    box.setSelectionRange(0, 0);
    box.scrollTop = 0;
    this.#setText(text, { fromBox: true });
    return true;
  }

  /** The line (from 1) holding character `offset` of the program. */
  #lineAt(offset: number): number {
    return lineAt(this.#field.starts, offset) + 1;
  }

  /** Lines of the program. */
  get #lineCount(): number {
    return this.#field.lineCount;
  }

  /** The user changed the program to `text`: in the box (`fromBox`: typed, dropped) or by a paste the box did not take. */
  #edited(text: string, fromBox = false): void {
    // The page's own insertion (#replaceInBox) is shown by its caller.
    if (this.#programInserted) return;
    // No longer the sample as loaded; and picking that sample again must fire a change to load it afresh.
    this.#e.sample.value = '';
    this.#setText(text, { fromBox });
    // A program of the user's own again: the replaced one is no longer offered.
    this.#store.update({ gcode: text, replacedProgram: '', replacedBy: '', secondReplacedProgram: '' });
  }

  /** Shows `text` (LongTextField.show), with its gutter and marks. */
  #setText(text: string, options?: { fromBox?: boolean; editable?: boolean }): void {
    this.#field.show(text, options);
    const box = this.#e.text;
    const style = getComputedStyle(box);
    this.#lineHeightPx = parseFloat(style.lineHeight) || this.#lineHeightPx;
    this.#paddingTopPx = parseFloat(style.paddingTop) || 0;
    // As wide as the longest number (its width is not its content's: style.css contains it).
    this.#e.gutter.style.width = `calc(${Math.max(3, String(this.#lineCount).length)}ch + 12px)`;
    this.#placeMarks();
  }

  /** The box that scrolls the program: the text box, or the listing. */
  get #scroller(): HTMLElement {
    return this.#field.listed ? this.#e.listing : this.#e.text;
  }

  /** Numbers the lines in view (and lists them, in the listing), level with the scrolled text. */
  #renderGutter(): void {
    const scroller = this.#scroller;
    const { first, last } = linesInView(scroller, this.#lineHeightPx, this.#lineCount);
    const numbers: (string | HTMLElement)[] = [];
    // The shown program's problems, over its own text only (see #ofText).
    const problems = this.#ofText ? this.#diagnosticLines : undefined;
    for (let line = first + 1; line <= last; line++) {
      const kind = problems?.get(line);
      if (line > first + 1) numbers.push('\n');
      if (!kind) {
        numbers.push(String(line));
        continue;
      }
      const marked = element('span', { className: `gutter-${kind}`, textContent: String(line), title: `${kind} on line ${line}` });
      marked.dataset.testid = `gutter-${kind}`;
      numbers.push(marked);
    }
    this.#gutterLines.replaceChildren(...numbers);
    this.#gutterLines.style.transform = `translateY(${first * this.#lineHeightPx - scroller.scrollTop}px)`;
    if (this.#field.listed) this.#field.listing.render(first, last);
  }

  /**
   * Whether the text shown is the source of the program on screen: its marks
   * (current step, picked line, error) and its problems' tints in the gutter
   * stand only over its own text, and a line picked in other text (being
   * typed, or a run of it cancelled, the last program still shown) picks
   * none of its steps: its line 4 is not the text's line 4.
   */
  get #ofText(): boolean {
    return this.#program?.source === this.#field.text;
  }

  /** Keeps the gutter and the marks level with the text as it scrolls. */
  #placeMarks(): void {
    const scroller = this.#scroller;
    this.#renderGutter();
    const ofText = this.#ofText;
    const top = (line: number | undefined) => (line === undefined || !ofText ? -1e6 : (line - 1) * this.#lineHeightPx - scroller.scrollTop + this.#paddingTopPx);
    const errorLine = this.#program?.program.errors[0]?.line;
    this.#errorMark.style.transform = `translateY(${top(errorLine)}px)`;
    this.#errorMark.dataset.line = String((ofText && errorLine) || '');
    this.#currentMark.style.transform = `translateY(${top(this.#currentLine)}px)`;
    this.#pickedMark.style.transform = `translateY(${top(this.#pickedLine)}px)`;
    this.#currentMark.dataset.line = String((ofText && this.#currentLine) || '');
    this.#pickedMark.dataset.line = String((ofText && this.#pickedLine) || '');
  }

  /** Picks a 1-based line: marks it and reports its steps. */
  async #pick(line: number): Promise<void> {
    // A line of other text than the shown program's picks none of its steps (#ofText).
    if (line === this.#pickedLine || !this.#ofText) return;
    this.#pickedLine = line;
    this.#placeMarks();
    const program = this.#program;
    if (!program) return;
    const steps = await program.lineSteps(line);
    if (program === this.#program && line === this.#pickedLine) this.#onPick(line, steps);
  }

  /** The program on screen (undefined while none has run). */
  setProgram(program: RemoteProgram | undefined): void {
    this.#program = program;
    this.#currentLine = undefined;
    this.#pickedLine = undefined;
    const { errors = [], warnings = [] } = program?.program ?? {};
    this.#diagnosticLines = new Map([...warnings.map((d) => [d.line, 'warning'] as const), ...errors.map((d) => [d.line, 'error'] as const)]);
    this.#placeMarks();
    this.#e.moves.replaceChildren(...(program ? [this.#diagnostics(program)] : []));
    this.#showProblems(program);
  }

  /** Above the editor: the error the run stopped at, and how many warnings, each a link to its line. */
  #showProblems(program: RemoteProgram | undefined): void {
    const { problems, text } = this.#e;
    const record = program?.program;
    const parts: HTMLElement[] = [];
    const go = (line: number, label: string) => {
      const button = element('button', { type: 'button', className: 'link', textContent: label });
      button.addEventListener('click', () => this.#goToLine(line));
      return button;
    };
    const error = record?.errors[0];
    if (error) {
      const p = element('p', { className: 'gcode-error' }, go(error.line, `Line ${error.line}:${error.column}`), `: ${sentence(diagnosticText(error))} The run stopped there.`);
      p.dataset.testid = 'gcode-error';
      parts.push(p);
    }
    const warnings = record ? record.warnings.length + record.warningsOmitted : 0;
    if (record && warnings > 0) {
      const first = record.warnings[0]!;
      parts.push(element('p', { className: 'gcode-warning' }, `${countOf(warnings, 'warning')}, listed under Moves; the first: `, go(first.line, `line ${first.line}:${first.column}`), `: ${first.message}`));
    }
    problems.replaceChildren(...parts);
    problems.hidden = parts.length === 0;
    text.setAttribute('aria-invalid', String(error !== undefined));
  }

  #diagnostics(program: RemoteProgram): HTMLElement {
    const list = element('ul', { className: 'diagnostics' });
    list.dataset.testid = 'gcode-diagnostics';
    const item = (kind: string, d: GcodeDiagnostic) => {
      const go = element('button', { type: 'button', className: 'link', textContent: `line ${d.line}:${d.column}` });
      go.addEventListener('click', () => this.#goToLine(d.line));
      return element('li', { className: kind }, element('span', { textContent: `${kind} ` }), go, ` ${diagnosticText(d)}`);
    };
    list.append(...program.program.errors.map((d) => item('error', d)), ...program.program.warnings.map((d) => item('warning', d)));
    if (program.program.warningsOmitted > 0) list.append(element('li', { textContent: `and ${program.program.warningsOmitted} more warnings` }));
    return list;
  }

  /** Puts the editor's cursor on `line` (or brings it into the listing's view) and picks it. */
  #goToLine(line: number): void {
    if (!this.#field.listed) {
      const { text } = this.#e;
      const offset = this.#field.starts[Math.min(line, this.#lineCount) - 1]!;
      text.focus();
      text.setSelectionRange(offset, offset);
    }
    this.#bringIntoView(line);
    void this.#pick(line);
  }

  /**
   * Scrolls the text (or the listing) so that `line` is in view, a third of
   * the way down, when it is not; a line in view stays where it is, so that
   * stepping line by line (the arrows, the timeline) does not move the text
   * under the eye. The one way a line is brought into view: a problem's
   * link, the arrows and the step shown all go through it.
   */
  #bringIntoView(line: number): void {
    const scroller = this.#scroller;
    const top = (line - 1) * this.#lineHeightPx;
    if (top < scroller.scrollTop || top > scroller.scrollTop + scroller.clientHeight - this.#lineHeightPx) {
      scroller.scrollTop = Math.max(0, top - scroller.clientHeight / 3);
    }
  }

  /** Marks the line (and move) that made the step before point `pointIndex`. */
  async showPoint(pointIndex: number): Promise<void> {
    const program = this.#program;
    const request = ++this.#stepRequest;
    if (!program || program.steps === 0) return;
    const { moveIndex, line } = await program.moveOfStep(Math.max(0, Math.min(pointIndex, program.steps) - 1));
    const from = Math.max(0, Math.min(moveIndex - (MOVES_SHOWN >> 1), program.program.moveCount - MOVES_SHOWN));
    const moves = await program.moves(from, from + MOVES_SHOWN);
    if (request !== this.#stepRequest || program !== this.#program) return;
    // A program's trace has the columns of every algorithm it ran: the step's own are the ones that mean something here.
    const algorithm = this.#catalogue.algorithms.find((a) => a.id === moves[moveIndex - from]?.algorithm);
    this.#onColumns(algorithm && new Set(algorithm.columns.map((c) => c.name)));
    this.#currentLine = line;
    // Not while the user types in the box: the view would jump away from the cursor.
    if (document.activeElement !== this.#e.text) this.#bringIntoView(line);
    this.#placeMarks();
    this.#renderMoves(program, from, moves, moveIndex);
  }

  #renderMoves(program: RemoteProgram, from: number, moves: GcodeMove[], current: number): void {
    const header = element('tr', {}, ...['#', 'line', 'code', 'from (mm)', 'to (mm)', 'steps'].map((h) => element('th', { scope: 'col', textContent: h })));
    const rows = moves.map((m, i) => {
      const go = element('button', { type: 'button', className: 'link', textContent: String(m.line) });
      go.setAttribute('aria-label', `Pick line ${m.line}`);
      go.addEventListener('click', () => this.#goToLine(m.line));
      const row = element(
        'tr',
        { className: from + i === current ? 'current' : '' },
        element('td', { textContent: String(from + i + 1) }),
        element('td', {}, go),
        element('td', { textContent: `${m.code} ${m.kind}` }),
        element('td', { textContent: formatPoint(m.fromMm.map((v) => Number(v.toFixed(3)))) }),
        element('td', { textContent: formatPoint(m.toMm.map((v) => Number(v.toFixed(3)))) }),
        element('td', { textContent: String(m.steps) }),
      );
      if (from + i === current) row.setAttribute('aria-current', 'step');
      return row;
    });
    const table = element('table', { className: 'moves-table' }, element('caption', { textContent: `Moves ${from + 1}-${from + moves.length} of ${program.program.moveCount}` }), element('thead', {}, header), element('tbody', {}, ...rows));
    table.dataset.testid = 'moves-table';
    // Scrolled in its own box where its columns need more than the panel (long coordinates in a narrow window): 233 px of table held a page of 240 px wider than the window.
    this.#e.moves.replaceChildren(this.#diagnostics(program), element('div', { className: 'table-scroll' }, table));
  }

  /** A run's progress (undefined: no run under way). */
  setProgress(progress: GcodeProgress | undefined): void {
    this.#progress.set(progress && linesBar(progress));
  }

  /** Shows the core's verdict on the machine settings. */
  showCoreError(error: InputError | undefined): void {
    this.#machineForm.showCoreError(error);
  }

  /** Brings the editor in line with the state (a sample, a link). */
  render(): void {
    if (this.#field.text !== this.#store.state.gcode) this.#setText(this.#store.state.gcode);
    this.#offerReplaced();
    this.#machineForm.setValues(this.#store.state.machine);
  }
}
