/**
 * Compare mode's table: the two traces' metrics side by side (for arcs the
 * largest deviation is the largest radial error), how many cells each
 * visits that the other does not, and the first point where they part with
 * each algorithm's reason and decision values for its step there, as the
 * core compared them.
 */
import { element } from '../form/options-form.js';
import { formatPoint, NO_VALUE_TEXT } from '../format.js';
import type { StepWhy } from '../core/index.js';
import type { MeasuredTrace } from '../worker/client.js';
import type { TraceDifference } from '../worker/protocol.js';

/** The parts of a trace the table reads. */
export type ComparedTrace = Pick<MeasuredTrace, 'name' | 'dims' | 'steps' | 'end' | 'metrics'>;

/** A step's decision values as one line, "M = 2, N = —, region = a", with a dash where a column does not apply. */
function decisionList(why: StepWhy): HTMLElement {
  const values = Object.entries(why.decisions).map(([name, v]) => `${name} = ${v === null ? NO_VALUE_TEXT : String(v)}`);
  return element('p', { className: 'first-difference-values', textContent: values.join(', ') });
}

export class ComparePanel {
  readonly #container: HTMLElement;
  readonly #onGo: (pointIndex: number) => void;

  constructor(container: HTMLElement, onGo: (pointIndex: number) => void) {
    this.#container = container;
    this.#onGo = onGo;
  }

  /** Shows the comparison of a and b (undefined: nothing yet). */
  show(a: ComparedTrace | undefined, b: ComparedTrace | undefined, difference: TraceDifference | undefined): void {
    if (!a || !b || !difference) {
      this.#container.replaceChildren();
      return;
    }
    const [la, lb] = [a.name, b.name];
    const cellCount = (cells: Int32Array, dims: number) => String(cells.length / dims);
    const rows: [string, string, string][] = [
      ['steps', String(a.steps), String(b.steps)],
      ['end', formatPoint(a.end), formatPoint(b.end)],
      ['largest deviation', a.metrics.maxDeviation.toFixed(4), b.metrics.maxDeviation.toFixed(4)],
      ['mean deviation', a.metrics.meanDeviation.toFixed(4), b.metrics.meanDeviation.toFixed(4)],
      ['std deviation', a.metrics.stdDeviation.toFixed(4), b.metrics.stdDeviation.toFixed(4)],
      ['largest axis error (eq. 11)', a.metrics.maxAxisError.map((e) => e.toFixed(3)).join(' '), b.metrics.maxAxisError.map((e) => e.toFixed(3)).join(' ')],
      ['pulses per axis', a.metrics.pulsesByAxis.join(' '), b.metrics.pulsesByAxis.join(' ')],
      ['ties', String(a.metrics.ties), String(b.metrics.ties)],
      ['cells only in this one', cellCount(difference.onlyInA, a.dims), cellCount(difference.onlyInB, b.dims)],
    ];
    const table = element(
      'table',
      { className: 'metrics-table' },
      element('caption', { textContent: 'Both algorithms on the same move' }),
      element('thead', {}, element('tr', {}, element('th', { scope: 'col', textContent: '' }), element('th', { scope: 'col', textContent: la }), element('th', { scope: 'col', textContent: lb }))),
      element('tbody', {}, ...rows.map(([name, va, vb]) => element('tr', {}, element('th', { scope: 'row', textContent: name }), element('td', { textContent: va }), element('td', { textContent: vb })))),
    );
    table.dataset.testid = 'metrics-table';
    const parts: HTMLElement[] = [element('h2', { textContent: 'Comparison' }), table];
    const first = difference.firstDifference;
    if (first === null) {
      parts.push(element('p', { className: 'first-difference', textContent: 'The two paths are the same, point for point.' }));
    } else {
      const k = first.pointIndex;
      const at = (point: number[] | null) => (point ? formatPoint(point) : 'its path has ended');
      const go = element('button', { type: 'button', textContent: `Go to point ${k}` });
      go.dataset.testid = 'go-first-difference';
      go.addEventListener('click', () => this.#onGo(k));
      const why = (name: string, side: StepWhy | null) => [
        element('p', {}, element('strong', { textContent: `${name}: ` }), side?.explanation ?? 'no step there.'),
        ...(side ? [decisionList(side)] : []),
      ];
      const box = element(
        'div',
        { className: 'first-difference' },
        element('p', { textContent: `The paths part at point ${k}: ${la} goes to ${at(first.a)}, ${lb} to ${at(first.b)}.` }),
        ...why(la, first.aWhy),
        ...why(lb, first.bWhy),
        go,
      );
      box.dataset.testid = 'first-difference';
      parts.push(box);
    }
    this.#container.replaceChildren(...parts);
  }
}
