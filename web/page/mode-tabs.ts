/**
 * The mode tabs (trace, compare, G-code, experiment) and the parts of the
 * page each mode shows: elements of class mode-part list their modes in
 * data-modes.
 */
import { type AppState, MODES, type Mode } from '../state/app-state.js';
import type { Store } from '../state/store.js';

export interface ModeElements {
  /** One button per mode, its mode in data-mode. */
  buttons: HTMLButtonElement[];
  parts: HTMLElement[];
  /** The second path view, shown for a side-by-side comparison. */
  secondViewport: HTMLElement;
  inputsHeading: HTMLElement;
  /** Exports an experiment has no use for. */
  exportPng: HTMLElement;
  exportJson: HTMLElement;
}

const INPUTS_HEADINGS: Record<Mode, string> = { trace: 'Path', compare: 'Two algorithms, one move', gcode: 'G-code program', experiment: 'Random lines' };

export class ModeTabs {
  readonly #e: ModeElements;
  readonly #store: Store<AppState>;

  /** `switchMode` is called with the mode of a tab pressed while another is on. */
  constructor(elements: ModeElements, store: Store<AppState>, switchMode: (mode: Mode) => void) {
    this.#e = elements;
    this.#store = store;
    for (const button of elements.buttons) {
      button.addEventListener('click', () => {
        const mode = MODES.find((m) => m === button.dataset.mode);
        if (mode && mode !== store.state.mode) switchMode(mode);
      });
      // The page's HTML has them disabled: pressed while the page loaded the
      // core, before this listener, a tab did nothing (the page opened in the
      // mode it was leaving) without a word.
      button.disabled = false;
    }
    this.render();
  }

  /** Shows the current mode's parts (and layout's second view). */
  render(): void {
    const { mode, layout } = this.#store.state;
    const e = this.#e;
    document.body.dataset.mode = mode;
    for (const part of e.parts) part.hidden = !(part.dataset.modes ?? '').split(' ').includes(mode);
    for (const button of e.buttons) button.setAttribute('aria-pressed', String(button.dataset.mode === mode));
    e.secondViewport.hidden = !(mode === 'compare' && layout === 'side');
    e.inputsHeading.textContent = INPUTS_HEADINGS[mode];
    e.exportPng.hidden = mode === 'experiment';
    e.exportJson.hidden = mode === 'experiment';
  }
}
