/**
 * The algorithm's options as form fields, generated from the catalogue's
 * OptionSpecs (as the CLI generates its flags), so a new algorithm's options
 * or machine settings appear without code here. A point is one integer field
 * per axis; a choice is a select; a number is a number field; a per-axis
 * setting is one text field taking one number for every axis or x,y,z.
 *
 * The form only reads what was typed. Whether a value is acceptable is the
 * core's call: its errors come back naming the option and are shown beside
 * that field. The checks made here are that a field holds a number at all,
 * because an empty field has no value to send, and that a whole number (an
 * integer option, a point's coordinate) is whole and within the range its
 * spec declares, said in the core's words for the range: a value refused
 * here stays out of the state, and so out of the link (a coordinate of 2.5
 * went into the link, then the core refused it).
 */
import { readDecimal } from '../core/guard.js';
import { perAxisRefusal, rangeRefusal } from '../core/ranges.js';
import type { IntegerRangeInfo, OptionSpec, PerAxisInfo } from '../core/types.js';
import { AXIS_NAMES } from '../format.js';
import type { OptionValue } from '../state/app-state.js';
import { dropDraft, keepDraft, restoredDraft } from '../state/drafts.js';
import type { InputError } from '../worker/protocol.js';

interface Field {
  controls: (HTMLInputElement | HTMLSelectElement)[];
  /** What a control shows while the option is absent (the core's default applies). */
  absent: string;
  error: HTMLElement;
  /** Why the page refused what the field holds (no number, or one its declaration refuses), so its value was not sent. */
  localError?: string;
  /** What the core said about this option in the last trace request. */
  coreError?: string;
  /** Where a refused text is kept over a reload (drafts.ts), for fields whose text can be put back (points, per-axis text, integers); else undefined. */
  draftId?: string;
}

export function element<K extends keyof HTMLElementTagNameMap>(tag: K, props: Partial<HTMLElementTagNameMap[K]> = {}, ...children: (Node | string)[]): HTMLElementTagNameMap[K] {
  const e = Object.assign(document.createElement(tag), props);
  e.append(...children);
  return e;
}

/**
 * A per-axis setting as typed: one number, or one per axis separated by
 * commas; undefined when empty (the core's default applies), null when it is
 * not numbers. How many axes, and whether they are whole, is the core's call.
 */
export function readPerAxis(text: string): number | number[] | undefined | null {
  if (text.trim() === '') return undefined;
  const values = text.split(',').map(readDecimal);
  if (values.some((v) => v === undefined)) return null;
  return values.length === 1 ? values[0]! : (values as number[]);
}

/**
 * The event a form's container sends (bubbling) when its fields' own checks
 * change: `invalid` while any field holds a value the page refused before
 * the core saw it (an empty coordinate, "80,abc").
 */
export const INPUTS_VALIDITY = 'inputs-validity';
export interface InputsValidity {
  invalid: boolean;
}

export class OptionsForm {
  readonly #fields = new Map<string, Field>();
  readonly #container: HTMLElement;
  /** The state's values the fields last showed: a refused draft is kept over its field's value. */
  #values: Readonly<Record<string, OptionValue>>;
  /** Where errors naming no field of this form go (say the algorithm, or maxSteps, which the page sets). */
  readonly #formError: HTMLElement;
  readonly #onChange: (name: string, value: OptionValue | undefined) => void;

  readonly #idPrefix: string;

  /**
   * Fills `container` with a field per option of `specs`, points with `axes`
   * coordinates, showing `values`, and calls `onChange` with each value the
   * user types (undefined: left empty, so the core's default applies).
   * Control ids are `${idPrefix}-${name}` (and `-x`, `-y`... for points).
   */
  constructor(
    container: HTMLElement,
    formError: HTMLElement,
    specs: readonly OptionSpec[],
    axes: number,
    values: Readonly<Record<string, OptionValue>>,
    onChange: (name: string, value: OptionValue | undefined) => void,
    idPrefix = 'option',
  ) {
    this.#formError = formError;
    this.#container = container;
    this.#onChange = onChange;
    this.#idPrefix = idPrefix;
    this.#values = values;
    container.replaceChildren(...specs.map((spec) => this.#field(spec, axes, values[spec.name])));
    // A text typed and refused before a reload, or before this form was
    // made again (another mode and back), is put back, with its message,
    // where the state still holds the value it was typed over (restoredDraft).
    for (const [name, field] of this.#fields) {
      const texts = field.draftId === undefined ? undefined : restoredDraft(field.draftId, values[name]);
      if (!texts || texts.length !== field.controls.length) continue;
      field.controls.forEach((c, i) => (c.value = texts[i]!));
      field.controls[0]!.dispatchEvent(new Event('input'));
    }
    // The fields of a form built anew (another algorithm, axis count or
    // mode) hold values of the state, or a refused draft: the validity of
    // the form they replace is over.
    this.#reportValidity();
  }

  /** Sends INPUTS_VALIDITY from the container: whether a field holds a value the page refused. */
  #reportValidity(): void {
    const invalid = [...this.#fields.values()].some((f) => f.localError !== undefined);
    this.#container.dispatchEvent(new CustomEvent<InputsValidity>(INPUTS_VALIDITY, { bubbles: true, detail: { invalid } }));
  }

  #field(spec: OptionSpec, axes: number, value: OptionValue | undefined): HTMLElement {
    const id = `${this.#idPrefix}-${spec.name}`;
    // An option that applies only with another's value says so (the core
    // refuses it with another; compare mode gives it to the side it applies to).
    const condition = spec.appliesWith ? ` With ${spec.appliesWith.option} ${spec.appliesWith.value} only.` : '';
    const hint = element('p', { className: 'hint', id: `${id}-hint`, textContent: spec.doc + condition });
    const error = element('p', { className: 'field-error', id: `${id}-error` });
    error.dataset.testid = `error-${id.replace(/^option-/, '')}`;
    error.setAttribute('aria-live', 'polite');
    const describedBy = `${hint.id} ${error.id}`;
    const field: Field = { controls: [], error, absent: spec.kind.type === 'choice' ? (spec.default ?? '') : '' };
    this.#fields.set(spec.name, field);

    const control = <T extends HTMLInputElement | HTMLSelectElement>(c: T, controlId: string): T => {
      c.id = controlId;
      c.name = controlId;
      c.dataset.testid = `input-${controlId.replace(/^option-/, '')}`;
      c.setAttribute('aria-describedby', describedBy);
      field.controls.push(c);
      return c;
    };

    // A point's number inputs can be put back empty, a per-axis text as typed,
    // a number's or an integer's input as the number refused; such an input
    // holding no number reads as '' and would be put back as "use the
    // default", so that keeps no draft (#setLocalError's `keep`). A choice or
    // a checkbox holds nothing the core refuses.
    if (spec.kind.type !== 'choice' && spec.kind.type !== 'boolean') field.draftId = id;
    switch (spec.kind.type) {
      case 'point': {
        const range: IntegerRangeInfo = spec.kind;
        const coords = Array.isArray(value) ? value : [];
        const fields = AXIS_NAMES.slice(0, axes).map((axis, a) => {
          const input = control(element('input', { type: 'number', step: '1', value: coords[a] === undefined ? '' : String(coords[a]) }), `${id}-${axis}`);
          input.addEventListener('input', () => this.#pointTyped(spec.name, range, field));
          return element('label', { className: 'axis' }, element('span', { textContent: axis }), input);
        });
        return element('fieldset', { className: 'option' }, element('legend', { textContent: spec.name }), hint, element('div', { className: 'axes' }, ...fields), error);
      }
      case 'choice': {
        const select = control(element('select'), id);
        // Without a stated default the algorithm decides (say helix's tie, from its method): an empty choice leaves it to it.
        if (spec.default === null) select.append(element('option', { value: '', textContent: "the algorithm's default" }));
        for (const word of spec.kind.values) {
          select.append(element('option', { value: word, textContent: word === spec.default ? `${word} (default)` : word }));
        }
        select.value = typeof value === 'string' ? value : field.absent;
        select.addEventListener('change', () => this.#onChange(spec.name, select.value === '' ? undefined : select.value));
        return element('div', { className: 'option' }, element('label', { htmlFor: id, textContent: spec.name }), select, hint, error);
      }
      case 'number':
      case 'integer': {
        const kind = spec.kind;
        const input = control(element('input', { type: 'number', step: kind.type === 'integer' ? '1' : 'any' }), id);
        if (kind.min !== undefined) input.min = String(kind.min);
        if (kind.max !== undefined) input.max = String(kind.max);
        input.value = typeof value === 'number' ? String(value) : '';
        input.placeholder = spec.default ?? '';
        input.addEventListener('input', () => {
          const given = input.value === '' ? undefined : input.valueAsNumber;
          // Each field checked as it is typed, against the range its spec
          // declares (the core checks the same declaration): every field out
          // of range says so at once, where the core names only the first.
          const refused = input.validity.badInput ? 'not a number' : given === undefined ? undefined : rangeRefusal(kind, given);
          this.#setLocalError(spec.name, field, refused, !input.validity.badInput);
          if (refused === undefined) this.#onChange(spec.name, given);
        });
        return element('div', { className: 'option' }, element('label', { htmlFor: id, textContent: spec.name }), input, hint, error);
      }
      case 'perAxis': {
        const range: PerAxisInfo = spec.kind;
        const input = control(element('input', { type: 'text', inputMode: 'decimal' }), id);
        input.value = Array.isArray(value) ? value.join(',') : typeof value === 'number' ? String(value) : '';
        input.placeholder = spec.default ?? '';
        input.addEventListener('input', () => {
          const read = readPerAxis(input.value);
          const refused = read === null ? 'give one number, or x,y,z' : read === undefined ? undefined : perAxisRefusal(range, read);
          this.#setLocalError(spec.name, field, refused);
          if (refused === undefined) this.#onChange(spec.name, read ?? undefined);
        });
        return element('div', { className: 'option' }, element('label', { htmlFor: id, textContent: spec.name }), input, hint, error);
      }
      case 'boolean': {
        const box = control(element('input', { type: 'checkbox' }), id);
        box.checked = typeof value === 'boolean' ? value : spec.default === 'true';
        box.addEventListener('change', () => this.#onChange(spec.name, box.checked));
        return element('div', { className: 'option option-boolean' }, box, element('label', { htmlFor: id, textContent: spec.name }), hint, error);
      }
    }
  }

  /** A point's coordinates as typed, each held to `range`, the coordinates' declared range. */
  #pointTyped(name: string, range: IntegerRangeInfo, field: Field): void {
    const inputs = field.controls as HTMLInputElement[];
    const refusals = inputs.map((input, a) => {
      if (input.value.trim() === '' || input.validity.badInput) return `${AXIS_NAMES[a]} needs a number`;
      const refused = rangeRefusal(range, input.valueAsNumber);
      return refused === undefined ? undefined : `${AXIS_NAMES[a]} ${refused}`;
    });
    const refused = refusals.find((r) => r !== undefined);
    this.#setLocalError(name, field, refused);
    if (refused === undefined) this.#onChange(name, inputs.map((input) => input.valueAsNumber));
  }

  /** Shows `message` (undefined: none) as the page's own refusal of the field; `keep`: its text can be put back as typed (drafts.ts). */
  #setLocalError(name: string, field: Field, message: string | undefined, keep = true): void {
    field.localError = message;
    this.#render(field);
    if (field.draftId !== undefined) {
      if (message === undefined || !keep) dropDraft(field.draftId);
      else keepDraft(field.draftId, field.controls.map((c) => c.value), this.#values[name]);
    }
    // The page's own check stopped a value short of the core: what is on
    // screen is no longer of the inputs shown, as when the core refuses one.
    this.#reportValidity();
  }

  #render(field: Field): void {
    const message = field.localError ?? field.coreError;
    field.error.textContent = message ?? '';
    for (const c of field.controls) c.setAttribute('aria-invalid', String(message !== undefined));
  }

  /**
   * Shows `values` in the fields, except in the field being edited (focused),
   * for values that changed elsewhere (a handle dragged in the view).
   */
  setValues(values: Readonly<Record<string, OptionValue>>): void {
    this.#values = values;
    for (const [name, field] of this.#fields) {
      // A refused text stays as typed until it is typed right: the value
      // the state holds for it is the last valid one, not what is meant.
      if (field.localError !== undefined) continue;
      const value = values[name];
      field.controls.forEach((c, i) => {
        if (c === document.activeElement) return;
        const text = Array.isArray(value) ? (field.controls.length === 1 ? value.join(',') : String(value[i] ?? '')) : value === undefined ? field.absent : String(value);
        if (c instanceof HTMLInputElement && c.type === 'checkbox') c.checked = value === true;
        else if (c.value !== text) c.value = text;
      });
    }
  }

  /** Shows the core's verdict on the last trace request: its error beside the option it names, or none. */
  showCoreError(error: InputError | undefined): void {
    for (const field of this.#fields.values()) {
      field.coreError = undefined;
      this.#render(field);
    }
    const field = error?.field === undefined ? undefined : this.#fields.get(error.field);
    if (error && field) {
      field.coreError = error.message;
      this.#render(field);
    }
    this.#formError.textContent = error && !field ? (error.field ? `${error.field}: ${error.message}` : error.message) : '';
  }
}
