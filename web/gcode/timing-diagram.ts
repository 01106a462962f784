/**
 * The step/direction signals as a logic analyser draws them: one lane per
 * signal (x STEP, x DIR, y STEP, ...), over a window of steps around the
 * current one. STEP pulses on the steps its axis moves; DIR is high while
 * its axis is at its negative level. The values are the core's stepCodes and
 * directionLevels.
 *
 * Time: with the steps' instants on the planned profile (a G-code program:
 * the core's stepTimes), the axis is time in ms or µs, each STEP pulse rises
 * at its step's instant and falls halfway to the next step, and the cursor is
 * the instant the current point is reached. Without them one tick is one
 * step (the core's tick model, web/core/pulses.ts).
 */
import uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS } from '../scene/palette.js';
import type { PulseCodes } from '../worker/protocol.js';
import { timeUnit } from './time-format.js';

/** Ticks shown at once. */
export const TIMING_WINDOW_TICKS = 48;
/** Lane pitch and signal swing, in lane units. */
const LANE = 1.5;
const SWING = 1;

export interface PulsedTrace {
  dims: number;
  steps: number;
  pulseCodes(fromStep: number, toStep: number): Promise<PulseCodes>;
}

export class TimingDiagram {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  #trace: PulsedTrace | undefined;
  #chart: StepChart | undefined;
  /** Step indices shown: fromStep..fromStep + TIMING_WINDOW_TICKS. */
  #fromStep = -1;
  #request = 0;
  /** In time mode: the window's step instants and the unit's factor from seconds. */
  #stepSeconds: Float64Array | undefined;
  #perSecond = 1;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
  }

  setTrace(trace: PulsedTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#chart?.destroy();
    this.#chart = undefined;
    this.#fromStep = -1;
    void this.showPoint(pointIndex);
  }

  /** Moves the cursor to `pointIndex`, fetching a new window of ticks when it leaves the one shown. */
  async showPoint(pointIndex: number): Promise<void> {
    const trace = this.#trace;
    if (!trace || trace.steps === 0) return;
    const inside = this.#fromStep >= 0 && pointIndex >= this.#fromStep + 4 && pointIndex <= this.#fromStep + TIMING_WINDOW_TICKS - 4;
    if (!inside) {
      const request = ++this.#request;
      const fromStep = Math.max(0, Math.min(pointIndex - TIMING_WINDOW_TICKS / 3, trace.steps - TIMING_WINDOW_TICKS));
      const toStep = Math.min(trace.steps, Math.round(fromStep) + TIMING_WINDOW_TICKS);
      const codes = await trace.pulseCodes(Math.round(fromStep), toStep);
      if (request !== this.#request || trace !== this.#trace) return;
      this.#fromStep = Math.round(fromStep);
      this.#draw(trace.dims, codes);
    }
    this.#chart?.showX(this.#xOfPoint(pointIndex));
  }

  /** The x of point index p: p ticks, or (in time) the instant of the step that reached it. */
  #xOfPoint(pointIndex: number): number {
    const times = this.#stepSeconds;
    if (!times) return pointIndex;
    const i = Math.max(0, Math.min(times.length - 1, pointIndex - 1 - this.#fromStep));
    return pointIndex === 0 ? 0 : times[i]! * this.#perSecond;
  }

  /** The point index reached at x (in time: the last step at or before it). */
  #pointOfX(x: number): number {
    const times = this.#stepSeconds;
    if (!times) return Math.round(x);
    let k = 0;
    while (k < times.length && times[k]! * this.#perSecond <= x) k++;
    return this.#fromStep + k;
  }

  #draw(dims: number, codes: PulseCodes): void {
    const ticks = codes.stepCodes.length;
    const times = codes.stepSeconds ?? undefined;
    this.#stepSeconds = times;
    const span = times && ticks > 1 ? times[ticks - 1]! - times[0]! : 0;
    const { unit, perSecond } = timeUnit(span);
    this.#perSecond = times ? perSecond : 1;
    // Ticks: one row per step and one more for the right edge of the last.
    // In time: two rows per step, its instant (STEP high) and halfway to
    // the next step (STEP low), so each STEP is a pulse at its instant.
    const rowsPerTick = times ? 2 : 1;
    const rows = ticks * rowsPerTick + 1;
    const x = new Float64Array(rows);
    for (let i = 0; i < ticks; i++) {
      if (!times) {
        x[i] = this.#fromStep + i;
        continue;
      }
      const t = times[i]!;
      const next = i + 1 < ticks ? times[i + 1]! : t + (ticks > 1 ? (t - times[0]!) / (ticks - 1) : 1e-3);
      x[2 * i] = t * perSecond;
      x[2 * i + 1] = ((t + next) / 2) * perSecond;
    }
    x[rows - 1] = times ? (2 * x[rows - 2]! - x[rows - 3]!) : this.#fromStep + ticks;
    const lanes: Float64Array[] = [];
    const series: uPlot.Series[] = [];
    const names: string[] = [];
    for (let axis = 0; axis < dims; axis++) {
      for (const signal of ['STEP', 'DIR'] as const) {
        const lane = (dims * 2 - 1 - lanes.length) * LANE;
        const values = new Float64Array(rows);
        for (let i = 0; i < ticks; i++) {
          // Packed step: bit a = axis a moves; DIR level: bit a = negative.
          const high = signal === 'STEP' ? (codes.stepCodes[i]! >> axis) & 1 : (codes.directionLevels[i]! >> axis) & 1;
          values[i * rowsPerTick] = lane + high * SWING;
          // In time, the second row of a step: STEP has fallen, DIR holds.
          if (times) values[2 * i + 1] = signal === 'STEP' ? lane : lane + high * SWING;
        }
        values[rows - 1] = values[rows - 2]!;
        lanes.push(values);
        names[lanes.length - 1] = `${AXIS_NAMES[axis]} ${signal}`;
        series.push({
          label: `${AXIS_NAMES[axis]} ${signal}`,
          stroke: AXIS_COLOURS[axis],
          width: signal === 'STEP' ? 2 : 1.5,
          dash: signal === 'DIR' ? [4, 3] : undefined,
          paths: uPlot.paths.stepped!({ align: 1 }),
        });
      }
    }
    const data: uPlot.AlignedData = [x, ...lanes];
    const title = times ? `STEP and DIR per axis at each step's planned instant (${unit})` : 'STEP and DIR per axis (one tick per step)';
    if (this.#chart && this.#chart.title === title) {
      this.#chart.setData(data);
      return;
    }
    this.#chart?.destroy();
    const count = lanes.length;
    this.#chart = new StepChart(
      this.#container,
      {
        title,
        xLabel: times ? `time (${unit})` : 'step',
        yLabel: '',
        series,
        yRange: [-0.3, count * LANE],
        legend: false,
        // One tick label per lane, at its middle, naming its signal.
        yValues: (_u, splits) => splits.map((v) => names[count - 1 - Math.round((v - SWING / 2) / LANE)] ?? ''),
        ySplits: Array.from({ length: count }, (_, i) => i * LANE + SWING / 2),
        pickX: (x) => this.#onPick(this.#pointOfX(x)),
      },
      data,
      this.#onPick,
    );
  }
}
