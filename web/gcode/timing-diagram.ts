/**
 * The step/direction signals as a logic analyser draws them: one lane per
 * signal (x STEP, x DIR, y STEP, ...) over a window of ticks around the
 * current step. One tick is one step of the trace (the core's tick model,
 * web/core/pulses.ts: the feed is not modelled). An axis that moves in a
 * tick gets one STEP pulse: it rises at the tick's start and falls at its
 * middle, so that steps on every tick still read as separate pulses. DIR is
 * a level, high while the axis moves (or last moved) towards -, labelled
 * with the direction each level means. The signals are the core's
 * pulseTrains, read in the worker.
 */
import uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import type { PulseTrain } from '../core/index.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS } from '../scene/palette.js';

/**
 * Ticks shown at once: as many as leave each tick this many CSS pixels, so
 * a STEP pulse (half a tick) stays apart from the next one.
 */
const TICK_PX = 14;
/** Fewest ticks shown, however narrow the panel. */
const MIN_WINDOW_TICKS = 12;
/** Width of the lane labels and margins, CSS pixels, left of the plot. */
const LABELS_PX = 80;
/** Height per lane, CSS pixels, and for the title and the step axis. */
const LANE_PX = 26;
const FRAME_PX = 64;
/** Lane pitch and signal swing, in lane units. */
const LANE = 1.5;
const SWING = 1;

export interface PulsedTrace {
  dims: number;
  steps: number;
  pulseTrains(fromStep: number, toStep: number): Promise<PulseTrain[]>;
}

export class TimingDiagram {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  #trace: PulsedTrace | undefined;
  #chart: StepChart | undefined;
  /** Step indices shown: fromStep..fromStep + #windowTicks. */
  #fromStep = -1;
  #windowTicks = MIN_WINDOW_TICKS;
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
    const margin = Math.floor(this.#windowTicks / 8);
    const inside = this.#fromStep >= 0 && pointIndex >= this.#fromStep + margin && pointIndex <= this.#fromStep + this.#windowTicks - margin;
    if (!inside) {
      const request = ++this.#request;
      const ticks = Math.max(MIN_WINDOW_TICKS, Math.floor((this.#container.clientWidth - LABELS_PX) / TICK_PX));
      const fromStep = Math.max(0, Math.min(pointIndex - Math.floor(ticks / 3), trace.steps - ticks));
      const toStep = Math.min(trace.steps, fromStep + ticks);
      const trains = await trace.pulseTrains(fromStep, toStep);
      if (request !== this.#request || trace !== this.#trace) return;
      this.#fromStep = fromStep;
      this.#windowTicks = ticks;
      this.#draw(trains);
    }
    this.#chart?.showPoint(pointIndex);
  }

  #draw(trains: PulseTrain[]): void {
    const ticks = trains[0]!.step.length;
    // Two samples a tick, at its start and its middle, and the right edge of the last tick.
    const x = Float64Array.from({ length: 2 * ticks + 1 }, (_, i) => this.#fromStep + i / 2);
    const lanes: Float64Array[] = [];
    const series: uPlot.Series[] = [];
    /** Tick labels of the y axis: where each lane's levels are, and what they say. */
    const labels: { at: number; text: string }[] = [];
    const count = trains.length * 2;
    trains.forEach((train, axis) => {
      const name = AXIS_NAMES[axis];
      for (const signal of ['STEP', 'DIR'] as const) {
        const lane = (count - 1 - lanes.length) * LANE;
        const values = new Float64Array(2 * ticks + 1);
        for (let i = 0; i < ticks; i++) {
          // STEP: a pulse, high for the first half of a tick its axis moves in. DIR: high for -.
          values[2 * i] = lane + (signal === 'STEP' ? train.step[i]! : train.dir[i]! < 0 ? 1 : 0) * SWING;
          values[2 * i + 1] = signal === 'STEP' ? lane : values[2 * i]!;
        }
        values[2 * ticks] = values[2 * ticks - 1]!;
        lanes.push(values);
        if (signal === 'STEP') labels.push({ at: lane + SWING / 2, text: `${name} STEP` });
        else labels.push({ at: lane, text: `${name} DIR +` }, { at: lane + SWING, text: `${name} DIR -` });
        series.push({
          label: `${name} ${signal}`,
          stroke: AXIS_COLOURS[axis],
          width: 1.5,
          paths: uPlot.paths.stepped!({ align: 1 }),
        });
      }
    });
    const data: uPlot.AlignedData = [x, ...lanes];
    if (this.#chart) {
      this.#chart.setData(data);
      return;
    }
    this.#chart = new StepChart(
      this.#container,
      {
        title: 'STEP and DIR per axis (one tick per step: a STEP pulse per step taken, DIR high for -)',
        xLabel: 'step',
        yLabel: '',
        series,
        yRange: [-0.3, count * LANE],
        legend: false,
        heightPx: count * LANE_PX + FRAME_PX,
        // A label per STEP lane and per DIR level, naming the signal and what the level means.
        yValues: (_u, splits) => splits.map((v) => labels.find((l) => Math.abs(l.at - v) < 1e-9)?.text ?? ''),
        ySplits: labels.map((l) => l.at).sort((a, b) => a - b),
      },
      data,
      this.#onPick,
    );
  }
}
