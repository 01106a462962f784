/**
 * The step/direction signals as a logic analyser draws them: one lane per
 * signal (x STEP, x DIR, y STEP, ...), high or low per tick, over a window of
 * ticks around the current step. One tick is one step of the trace (the
 * core's tick model, web/core/pulses.ts: the feed is not modelled). STEP is
 * high on the ticks its axis moves; DIR is high while its axis is at its
 * negative level. The values are the core's stepCodes and directionLevels.
 */
import uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS } from '../scene/palette.js';
import type { PulseCodes } from '../worker/protocol.js';

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
    this.#chart?.showPoint(pointIndex);
  }

  #draw(dims: number, codes: PulseCodes): void {
    const ticks = codes.stepCodes.length;
    // One row more than ticks: a stepped line needs the right edge of the last tick.
    const x = Float64Array.from({ length: ticks + 1 }, (_, i) => this.#fromStep + i);
    const lanes: Float64Array[] = [];
    const series: uPlot.Series[] = [];
    const names: string[] = [];
    for (let axis = 0; axis < dims; axis++) {
      for (const signal of ['STEP', 'DIR'] as const) {
        const lane = (dims * 2 - 1 - lanes.length) * LANE;
        const values = new Float64Array(ticks + 1);
        for (let i = 0; i < ticks; i++) {
          // Packed step: bit a = axis a moves; DIR level: bit a = negative.
          const high = signal === 'STEP' ? (codes.stepCodes[i]! >> axis) & 1 : (codes.directionLevels[i]! >> axis) & 1;
          values[i] = lane + high * SWING;
        }
        values[ticks] = values[ticks - 1]!;
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
    if (this.#chart) {
      this.#chart.setData(data);
      return;
    }
    const count = lanes.length;
    this.#chart = new StepChart(
      this.#container,
      {
        title: 'STEP and DIR per axis (one tick per step)',
        xLabel: 'step',
        yLabel: '',
        series,
        yRange: [-0.3, count * LANE],
        legend: false,
        // One tick label per lane, at its middle, naming its signal.
        yValues: (_u, splits) => splits.map((v) => names[count - 1 - Math.round((v - SWING / 2) / LANE)] ?? ''),
        ySplits: Array.from({ length: count }, (_, i) => i * LANE + SWING / 2),
      },
      data,
      this.#onPick,
    );
  }
}
