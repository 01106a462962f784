/**
 * G-code mode: the editor (a textarea with line numbers and two line marks),
 * the sample programs, the machine's settings, the run's progress with
 * Cancel, the program's diagnostics and its move list. Sync goes both ways
 * through the program the worker holds:
 * - picking a line (the editor's cursor, a move or a diagnostic) asks which
 *   steps that line made: they are highlighted in the view and the step
 *   moves to the end of them;
 * - the current step asks which move made it: its line is marked in the
 *   editor (scrolled into view unless the user is typing) and in the move list.
 */
import type { GcodeDiagnostic, GcodeMove, GcodeProgress } from '../core/index.js';
import { OptionsForm, element } from '../form/options-form.js';
import { formatPoint } from '../format.js';
import { type AppState, type Catalogue, machineSpecs } from '../state/app-state.js';
import type { Store } from '../state/store.js';
import type { RemoteProgram } from '../worker/client.js';
import type { InputError, LineSteps } from '../worker/protocol.js';

/** Moves listed at a time around the current one. */
const MOVES_SHOWN = 12;

export interface GcodePanelElements {
  sample: HTMLSelectElement;
  text: HTMLTextAreaElement;
  gutter: HTMLElement;
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

/** The 1-based line of character offset `offset` in `text`. */
function lineAt(text: string, offset: number): number {
  let line = 1;
  for (let i = text.indexOf('\n'); i !== -1 && i < offset; i = text.indexOf('\n', i + 1)) line++;
  return line;
}

export class GcodePanel {
  readonly #e: GcodePanelElements;
  readonly #store: Store<AppState>;
  readonly #machineForm: OptionsForm;
  readonly #currentMark: HTMLElement;
  readonly #pickedMark: HTMLElement;
  /** Called with the steps of a picked line, to highlight them and move the step there. */
  readonly #onPick: (line: number, steps: LineSteps) => void;
  #program: RemoteProgram | undefined;
  #pickedLine: number | undefined;
  #currentLine: number | undefined;
  /** The latest step asked about; answers for older ones are dropped. */
  #stepRequest = 0;
  #lineHeightPx = 18;

  constructor(elements: GcodePanelElements, catalogue: Catalogue, store: Store<AppState>, events: { onPick(line: number, steps: LineSteps): void; onRun(): void; onCancel(): void }) {
    this.#e = elements;
    this.#store = store;
    this.#onPick = events.onPick;
    this.#currentMark = element('div', { className: 'line-mark current' });
    this.#currentMark.dataset.testid = 'gcode-current-line';
    this.#pickedMark = element('div', { className: 'line-mark picked' });
    this.#pickedMark.dataset.testid = 'gcode-picked-line';
    elements.backdrop.append(this.#currentMark, this.#pickedMark);

    elements.text.value = store.state.gcode;
    this.#renderGutter();
    elements.text.addEventListener('input', () => {
      this.#renderGutter();
      store.update({ gcode: elements.text.value });
    });
    elements.text.addEventListener('scroll', () => this.#placeMarks());
    for (const type of ['click', 'keyup']) elements.text.addEventListener(type, () => this.#pick(lineAt(elements.text.value, elements.text.selectionStart)));
    elements.run.addEventListener('click', events.onRun);
    elements.cancel.addEventListener('click', events.onCancel);

    this.#machineForm = new OptionsForm(elements.machine, elements.formError, machineSpecs(catalogue.algorithms), 3, store.state.machine, (name, value) => {
      const machine = { ...store.state.machine };
      if (value === undefined) delete machine[name];
      else machine[name] = value;
      store.update({ machine });
    }, 'machine');

    elements.sample.addEventListener('change', () => void this.#loadSample(elements.sample.value));
    void this.#listSamples();
  }

  async #listSamples(): Promise<void> {
    const response = await fetch('samples/index.json');
    if (!response.ok) throw new Error(`the sample list could not be loaded (HTTP ${response.status})`);
    const samples = (await response.json()) as SampleInfo[];
    this.#e.sample.append(...samples.map((s) => element('option', { value: s.file, textContent: s.title, title: s.description })));
  }

  async #loadSample(file: string): Promise<void> {
    if (!file) return;
    const response = await fetch(`samples/${encodeURIComponent(file)}`);
    if (!response.ok) throw new Error(`the sample ${file} could not be loaded (HTTP ${response.status})`);
    const text = await response.text();
    this.#e.text.value = text;
    this.#renderGutter();
    this.#store.update({ gcode: text, pointIndex: 0, camera: null });
  }

  #renderGutter(): void {
    const lines = this.#e.text.value.split('\n').length;
    this.#e.gutter.textContent = Array.from({ length: lines }, (_, i) => i + 1).join('\n');
    this.#lineHeightPx = parseFloat(getComputedStyle(this.#e.text).lineHeight) || this.#lineHeightPx;
  }

  /** Keeps the gutter and the marks level with the text as it scrolls. */
  #placeMarks(): void {
    const { text, gutter } = this.#e;
    gutter.scrollTop = text.scrollTop;
    const top = (line: number | undefined) => (line === undefined ? -1e6 : (line - 1) * this.#lineHeightPx - text.scrollTop + parseFloat(getComputedStyle(text).paddingTop));
    this.#currentMark.style.transform = `translateY(${top(this.#currentLine)}px)`;
    this.#pickedMark.style.transform = `translateY(${top(this.#pickedLine)}px)`;
    this.#currentMark.dataset.line = String(this.#currentLine ?? '');
    this.#pickedMark.dataset.line = String(this.#pickedLine ?? '');
  }

  /** Picks a 1-based line: marks it and reports its steps. */
  async #pick(line: number): Promise<void> {
    if (line === this.#pickedLine) return;
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
    this.#placeMarks();
    this.#e.moves.replaceChildren(...(program ? [this.#diagnostics(program)] : []));
  }

  #diagnostics(program: RemoteProgram): HTMLElement {
    const list = element('ul', { className: 'diagnostics' });
    list.dataset.testid = 'gcode-diagnostics';
    const item = (kind: string, d: GcodeDiagnostic) => {
      const go = element('button', { type: 'button', className: 'link', textContent: `line ${d.line}:${d.column}` });
      go.addEventListener('click', () => this.#goToLine(d.line));
      return element('li', { className: kind }, element('span', { textContent: `${kind} ` }), go, ` ${d.message}`);
    };
    list.append(...program.errors.map((d) => item('error', d)), ...program.warnings.map((d) => item('warning', d)));
    if (program.warningsOmitted > 0) list.append(element('li', { textContent: `and ${program.warningsOmitted} more warnings` }));
    return list;
  }

  /** Puts the editor's cursor on `line` and picks it. */
  #goToLine(line: number): void {
    const { text } = this.#e;
    let offset = 0;
    for (let l = 1; l < line && offset !== -1; l++) offset = text.value.indexOf('\n', offset) + 1;
    text.focus();
    text.setSelectionRange(offset, offset);
    text.scrollTop = Math.max(0, (line - 3) * this.#lineHeightPx);
    void this.#pick(line);
  }

  /** Marks the line (and move) that made the step before point `pointIndex`. */
  async showPoint(pointIndex: number): Promise<void> {
    const program = this.#program;
    const request = ++this.#stepRequest;
    if (!program || program.steps === 0) return;
    const { moveIndex, line } = await program.moveOfStep(Math.max(0, Math.min(pointIndex, program.steps) - 1));
    const from = Math.max(0, Math.min(moveIndex - (MOVES_SHOWN >> 1), program.moveCount - MOVES_SHOWN));
    const moves = await program.moves(from, from + MOVES_SHOWN);
    if (request !== this.#stepRequest || program !== this.#program) return;
    this.#currentLine = line;
    const { text } = this.#e;
    const top = (line - 1) * this.#lineHeightPx;
    if (document.activeElement !== text && (top < text.scrollTop || top > text.scrollTop + text.clientHeight - this.#lineHeightPx)) {
      text.scrollTop = Math.max(0, top - text.clientHeight / 3);
    }
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
    const table = element('table', { className: 'moves-table' }, element('caption', { textContent: `Moves ${from + 1}-${from + moves.length} of ${program.moveCount}` }), element('thead', {}, header), element('tbody', {}, ...rows));
    table.dataset.testid = 'moves-table';
    this.#e.moves.replaceChildren(this.#diagnostics(program), table);
  }

  /** A run's progress (undefined: no run under way). */
  setProgress(progress: GcodeProgress | undefined): void {
    const { progress: bar, cancel, run } = this.#e;
    bar.hidden = cancel.hidden = progress === undefined;
    run.disabled = progress !== undefined;
    if (progress) {
      bar.max = Math.max(1, progress.lines);
      bar.value = progress.linesDone;
      bar.setAttribute('aria-valuetext', `${progress.linesDone} of ${progress.lines} lines, ${progress.steps} steps`);
    }
  }

  /** Shows the core's verdict on the machine settings. */
  showCoreError(error: InputError | undefined): void {
    this.#machineForm.showCoreError(error);
  }

  /** Brings the editor in line with the state (a sample, a link). */
  render(): void {
    if (this.#e.text.value !== this.#store.state.gcode) {
      this.#e.text.value = this.#store.state.gcode;
      this.#renderGutter();
    }
    this.#machineForm.setValues(this.#store.state.machine);
  }
}
