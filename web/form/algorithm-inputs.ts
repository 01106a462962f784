/**
 * The inputs of the trace, compare and experiment modes: the algorithm
 * picker (with its citation, rule and errata from the catalogue), the second
 * algorithm and layout of a comparison, the number of axes, and the options
 * form generated from the OptionSpecs of the traced algorithm(s).
 */
import type { AlgorithmInfo } from '../core/types.js';
import {
  type AppState,
  type Catalogue,
  COMPARE_LAYOUTS,
  type Mode,
  MODE_INPUT_KEYS,
  type OptionValue,
  axisChoices,
  axisCount,
  type ComparedValues,
  comparableWith,
  comparedValues,
  defaultAlgorithm,
  defaultOptions,
  defaultOther,
  defaultProjection,
  experimentAlgorithm,
  offeredAlgorithms,
  sharedOptionSpecs,
  tracedAlgorithms,
  OptionSetter,
  withAxes,
  withOption,
} from '../state/app-state.js';
import type { Store } from '../state/store.js';
import type { InputError } from '../worker/protocol.js';
import { OptionsForm, element } from './options-form.js';
import { pathLimitAdvice } from './page-advice.js';

export interface AlgorithmInputElements {
  algorithm: HTMLSelectElement;
  title: HTMLElement;
  citation: HTMLElement;
  teaching: HTMLElement;
  errata: HTMLElement;
  errataBox: HTMLDetailsElement;
  other: HTMLSelectElement;
  otherCitation: HTMLElement;
  layout: HTMLInputElement[];
  axes: HTMLSelectElement;
  axesField: HTMLElement;
  axesHint: HTMLElement;
  fields: HTMLElement;
  formError: HTMLElement;
}

/**
 * Options for `infos` after a change of algorithm: the defaults (the first
 * one's example move), with the values the user had for options the new
 * algorithms still take, when the axis count still fits.
 */
export function carriedOptions(infos: readonly AlgorithmInfo[], current: Readonly<Record<string, OptionValue>>, keep: boolean): Record<string, OptionValue> {
  const defaults = defaultOptions(infos);
  if (!keep) return defaults;
  const names = new Set(sharedOptionSpecs(infos).map((s) => s.name));
  const kept = Object.fromEntries(Object.entries(current).filter(([name]) => names.has(name)));
  // Each kept value over the defaults as if typed: a kept tolerance clears
  // the example's segmentLength (the two were refused together).
  const merged = Object.entries(kept).reduce((options, [name, value]) => withOption(options, name, value), defaults);
  return withAxes(merged, axisCount(infos, kept));
}

/** A picker's entry for `info`; `runs`: the value of its compared option it runs, when compared with itself. */
function option(info: AlgorithmInfo, runs?: ComparedValues): HTMLOptionElement {
  const title = runs ? `${info.title}, ${runs.option} ${runs.values[1]}` : info.title;
  return element('option', { value: info.id, textContent: `${title} (${info.id})` });
}

export class AlgorithmInputs {
  readonly #e: AlgorithmInputElements;
  readonly #catalogue: Catalogue;
  readonly #store: Store<AppState>;
  #form: OptionsForm | undefined;
  /** What the form was built for: mode, algorithm ids and axis count. */
  #formKey = '';
  /** Where each mode was left: its step, its camera, and its inputs then (MODE_INPUT_KEYS' values). */
  readonly #left = new Map<Mode, { pointIndex: number; camera: AppState['camera']; inputs: unknown[] }>();

  constructor(elements: AlgorithmInputElements, catalogue: Catalogue, store: Store<AppState>) {
    this.#e = elements;
    this.#catalogue = catalogue;
    this.#store = store;
    elements.algorithm.addEventListener('change', () => this.#pickAlgorithm(elements.algorithm.value));
    elements.other.addEventListener('change', () => this.#pickOther(elements.other.value));
    for (const radio of elements.layout) {
      radio.addEventListener('change', () => {
        const layout = COMPARE_LAYOUTS.find((l) => l === radio.value);
        if (radio.checked && layout) store.update({ layout, camera: null });
      });
    }
    elements.axes.addEventListener('change', () => {
      const axes = Number(elements.axes.value);
      store.update({ options: withAxes(store.state.options, axes), projection: defaultProjection(axes), camera: null, pointIndex: 0 });
    });
    store.subscribe(() => this.render());
    this.render();
  }

  /**
   * Traces `id` on the line typed, when one was (its points differ from the
   * example move of the line algorithm left) and `id` is a line algorithm
   * that takes as many axes, with the options it takes kept too: comparing
   * rules on one's own line is what switching is for (the move went back to
   * the example, and the one typed was lost). Else from its own example move
   * (in `mode`): an arc's options do not carry between its algorithms (the
   * helix's rise, which circle and arc-segments refuse; arc-segments' chord
   * options, which the helix takes with method segments only). The second algorithm of a
   * comparison stays when it can still be compared with `id`; else it
   * becomes the default partner of `id`, so that no mode is left comparing a
   * circle with a line, or an algorithm with itself by nothing. The helix
   * takes its partner, itself by its other method, always: its example move
   * rises, which neither circle nor arc-segments takes.
   */
  #pickAlgorithm(id: string): void {
    const state = this.#store.state;
    const { algorithms } = this.#catalogue;
    const info = algorithms.find((a) => a.id === id) ?? defaultAlgorithm(algorithms);
    const partner = defaultOther(info, algorithms);
    const keep = partner !== info && comparableWith(info, algorithms).some((a) => a.id === state.other);
    const other = keep ? state.other : partner.id;
    const next = tracedAlgorithms({ ...state, algorithm: info.id, other }, algorithms);
    const left = tracedAlgorithms(state, algorithms);
    const example = defaultOptions(left);
    const points = (left[0]?.options ?? []).filter((spec) => spec.kind.type === 'point').map((spec) => spec.name);
    const typed = points.some((name) => JSON.stringify(state.options[name]) !== JSON.stringify(example[name]));
    const traceable = left[0]?.family === 'line' && info.family === 'line' && axisChoices(next).includes(axisCount(left, state.options));
    const options = carriedOptions(next, state.options, typed && traceable);
    this.#store.update({ algorithm: info.id, other, options, pointIndex: 0, camera: null, projection: defaultProjection(axisCount(next, options)) });
  }

  /**
   * Switches to `mode`, the algorithm and its move kept as they are. The
   * experiment traces lines only: entered with an arc algorithm it runs its
   * default line algorithm (experimentAlgorithm), and the arc is still there
   * on the way back. A mode whose inputs have not changed since it was left
   * comes back at the step and camera it was left at (it came back at step
   * 0, framed anew); else at step 0, framed.
   */
  switchMode(mode: Mode): void {
    const state = this.#store.state;
    this.#left.set(state.mode, { pointIndex: state.pointIndex, camera: state.camera, inputs: MODE_INPUT_KEYS[state.mode].map((k) => state[k]) });
    const left = this.#left.get(mode);
    const unchanged = left !== undefined && MODE_INPUT_KEYS[mode].every((k, i) => state[k] === left.inputs[i]);
    this.#store.update({ mode, pointIndex: unchanged ? left.pointIndex : 0, camera: unchanged ? left.camera : null });
  }

  #pickOther(id: string): void {
    const state = this.#store.state;
    const infos = tracedAlgorithms({ ...state, other: id }, this.#catalogue.algorithms);
    const options = carriedOptions(infos, state.options, true);
    this.#store.update({ other: id, options, pointIndex: 0, camera: null, projection: defaultProjection(axisCount(infos, options)) });
  }

  /**
   * Shows the core's verdict on the last request: beside the option it
   * names, or under the form. A cap the page sets itself (maxSteps) has no
   * field of its own, so the page says what can be done here instead, beside
   * the end point, where a move is shortened (under the form it was below
   * the fold, away from the field just typed).
   */
  showCoreError(error: InputError | undefined): void {
    const shown = error?.limit ? { field: 'to', message: pathLimitAdvice(error.limit) } : error;
    if (this.#form) this.#form.showCoreError(shown);
    else this.#e.formError.textContent = shown ? shown.message : '';
  }

  render(): void {
    const state = this.#store.state;
    const e = this.#e;
    const infos = state.mode === 'experiment' ? [experimentAlgorithm(state, this.#catalogue)] : tracedAlgorithms(state, this.#catalogue.algorithms);
    const info = infos[0]!;
    const offered = offeredAlgorithms(state.mode, this.#catalogue);
    if (e.algorithm.options.length !== offered.length) {
      // Grouped by family, lines first, as the catalogue lists them.
      e.algorithm.replaceChildren(
        ...(['line', 'arc'] as const).flatMap((family) => {
          const members = offered.filter((a) => a.family === family);
          return members.length ? [element('optgroup', { label: family === 'line' ? 'Lines' : 'Arcs and helices' }, ...members.map((a) => option(a)))] : [];
        }),
      );
    }
    e.algorithm.value = info.id;
    e.title.textContent = info.title;
    e.citation.textContent = info.citation;
    e.teaching.textContent = info.teaching;
    e.errata.replaceChildren(...info.errata.map((text) => element('li', { textContent: text })));
    e.errataBox.hidden = info.errata.length === 0;

    // The first algorithm itself is offered by the other value of its compared option (the helix by its other method), which follows the first's.
    const compatible = comparableWith(info, this.#catalogue.algorithms);
    const itself = comparedValues({ ...state, mode: 'compare', other: info.id }, this.#catalogue.algorithms);
    const entries = compatible.map((a) => option(a, a === info ? itself : undefined));
    if (e.other.options.length !== entries.length || [...e.other.options].some((o, i) => o.value !== entries[i]!.value || o.text !== entries[i]!.text)) {
      e.other.replaceChildren(...entries);
    }
    e.other.value = state.other;
    e.otherCitation.textContent = infos[1]?.citation ?? '';
    for (const radio of e.layout) radio.checked = radio.value === state.layout;

    if (state.mode === 'experiment') return;
    const choices = axisChoices(infos);
    const axes = axisCount(infos, state.options);
    if (e.axes.options.length !== choices.length || [...e.axes.options].some((o, i) => Number(o.value) !== choices[i])) {
      e.axes.replaceChildren(...choices.map((n) => element('option', { value: String(n), textContent: `${n} (${n === 2 ? 'x, y' : 'x, y, z'})` })));
    }
    e.axes.value = String(axes);
    e.axesField.hidden = choices.length < 2;
    const widest = Math.max(...infos.map((i) => i.maxDims));
    e.axesHint.textContent = widest > 3 ? `${info.id} takes ${info.minDims} to ${info.maxDims} axes; the page shows 2 or 3 (the CLI and the API take them all).` : '';

    const key = `${state.mode} ${infos.map((i) => i.id).join(' ')} ${axes}`;
    if (key !== this.#formKey) {
      this.#formKey = key;
      const setter = new OptionSetter();
      this.#form = new OptionsForm(e.fields, e.formError, sharedOptionSpecs(infos), axes, state.options, (name, value) => {
        this.#store.update({ options: setter.set(this.#store.state.options, name, value) });
      });
    } else {
      this.#form?.setValues(state.options);
    }
  }
}
