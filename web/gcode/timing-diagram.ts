/**
 * The step/direction signals as a logic analyser draws them: one lane per
 * signal (x STEP, x DIR, y STEP, ...) over a window of steps around the
 * current one. An axis that moves in a step gets one STEP pulse; DIR is a
 * level, high while the axis moves (or last moved) towards -, labelled with
 * the direction each level means. The signals are the core's pulseTrains,
 * read in the worker.
 *
 * Two clocks. A trace: one tick per step (the core's tick model,
 * web/core/pulses.ts); a STEP pulse rises at its tick's start and falls at
 * its middle, so that steps on every tick still read as separate pulses. A
 * G-code program: each step at its planned instant (the core's stepTimes,
 * Grbl's planner), the axis in ms or µs; a STEP pulse rises at its step's
 * instant and is drawn falling half-way to the nearer of the steps beside
 * it (a driver's pulse is some µs, too thin to see at this scale; across a
 * stop or a dwell it stays as narrow as its neighbours'). The cursor is the instant the
 * current point is reached.
 */
import uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS } from '../scene/palette.js';
import type { PulseWindow } from '../worker/protocol.js';
import { drawnFromZero, pulseEdges, ROWS_PER_STEP } from './pulse-edges.js';
import { timeUnit } from './time-format.js';

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
  pulseTrains(fromStep: number, toStep: number): Promise<PulseWindow>;
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
  /** A program's window: its steps' instants, seconds, and the axis unit's factor from seconds. */
  #stepSeconds: Float64Array | null = null;
  #perSecond = 1;
  /** The x axis's label, to know when the chart must be made again (the unit changed). */
  #xLabel = '';

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
  }

  setTrace(trace: PulsedTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#fromStep = -1;
    // The old chart stays until the new trace's first window replaces it
    // (#draw makes a new chart for a new label), so the box never empties
    // for the moment the window is fetched; none stays for no steps.
    this.#xLabel = '';
    if (!trace || trace.steps === 0) {
      this.#chart?.destroy();
      this.#chart = undefined;
    }
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
      let window: PulseWindow;
      try {
        window = await trace.pulseTrains(fromStep, toStep);
      } catch (error) {
        // The last trace's chart, kept until this window came, must not stay.
        if (request === this.#request && this.#fromStep < 0) {
          this.#chart?.destroy();
          this.#chart = undefined;
        }
        throw error;
      }
      if (request !== this.#request || trace !== this.#trace) return;
      this.#fromStep = fromStep;
      this.#windowTicks = ticks;
      this.#draw(window);
    }
    this.#chart?.showX(this.#xOfPoint(pointIndex));
  }

  /** The x of point index k: k ticks, or (a program) the instant of the step that reached it. */
  #xOfPoint(pointIndex: number): number {
    const times = this.#stepSeconds;
    if (!times) return pointIndex;
    if (pointIndex === 0) return 0;
    const i = Math.max(0, Math.min(times.length - 1, pointIndex - 1 - this.#fromStep));
    return times[i]! * this.#perSecond;
  }

  /** The point index reached at x (a program: the steps of the window at or before that instant). */
  #pointOfX(x: number): number {
    const times = this.#stepSeconds!;
    let k = 0;
    while (k < times.length && times[k]! * this.#perSecond <= x) k++;
    return this.#fromStep + k;
  }

  /**
   * The rows' x: ROWS_PER_STEP a step, where its STEP pulse rises, where it
   * falls and where DIR is set for the next step, and the right edge of the
   * last step. Ticks: pulseEdges of steps a tick apart; a program:
   * pulseEdges of its instants, in the axis's unit, which is chosen by the
   * time the axis spans, right edge included, from 0 s when `fromZero`
   * (chosen by the steps' spread alone, one step read in µs over a
   * millisecond: 50,000 to 51,000 µs).
   */
  #rowsX(ticks: number, times: Float64Array | null, fromZero: boolean): { x: Float64Array; unit: string } {
    if (!times) return { x: pulseEdges(Float64Array.from({ length: ticks }, (_, i) => this.#fromStep + i)), unit: 'tick' };
    const edges = pulseEdges(times.subarray(0, ticks));
    // The span drawn: from 0 s when the window starts there (#draw).
    const { unit, perSecond } = timeUnit(edges[edges.length - 1]! - (fromZero ? 0 : edges[0]!));
    this.#perSecond = perSecond;
    return { x: edges.map((t) => t * perSecond), unit };
  }

  #draw({ trains, stepSeconds }: PulseWindow): void {
    const ticks = trains[0]!.step.length;
    this.#stepSeconds = stepSeconds;
    this.#perSecond = 1;
    const idle = stepSeconds !== null && drawnFromZero(stepSeconds.subarray(0, ticks), this.#fromStep === 0);
    const { x, unit } = this.#rowsX(ticks, stepSeconds, idle);
    const lanes: Float64Array[] = [];
    const series: uPlot.Series[] = [];
    /** Tick labels of the y axis: where each lane's levels are, and what they say. */
    const labels: { at: number; text: string }[] = [];
    const count = trains.length * 2;
    /** Lane i's low level, from the top: a STEP lane's rest, a DIR lane's + (the VCD's level before any step). */
    const laneBase = (i: number) => (count - 1 - i) * LANE;
    trains.forEach((train, axis) => {
      const name = AXIS_NAMES[axis];
      for (const signal of ['STEP', 'DIR'] as const) {
        const lane = laneBase(lanes.length);
        const values = new Float64Array(ROWS_PER_STEP * ticks + 1);
        const dirLevel = (i: number) => lane + (train.dir[i]! < 0 ? SWING : 0);
        for (let i = 0; i < ticks; i++) {
          const row = ROWS_PER_STEP * i;
          if (signal === 'STEP') {
            // A pulse, high from the step's instant to its drawn fall.
            values[row] = lane + train.step[i]! * SWING;
            values[row + 1] = values[row + 2] = lane;
          } else {
            // High for -; set for the next step half-way to it, settled before its edge (as the VCD).
            values[row] = values[row + 1] = dirLevel(i);
            values[row + 2] = dirLevel(Math.min(i + 1, ticks - 1));
          }
        }
        values[ROWS_PER_STEP * ticks] = values[ROWS_PER_STEP * ticks - 1]!;
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
    // Drawn from 0 s: two rows before the first step, at 0 s and half-way to
    // it, where a DIR its first step needs is set (the VCD's DIR is + before
    // any step); every lane low until then.
    const withStart = (values: Float64Array, atZero: number, halfWay: number) => (idle ? Float64Array.of(atZero, halfWay, ...values) : values);
    const data: uPlot.AlignedData = [
      withStart(x, 0, x[0]! / 2),
      ...lanes.map((values, i) => withStart(values, laneBase(i), i % 2 === 0 ? laneBase(i) : values[0]!)),
    ];
    const xLabel = stepSeconds ? `planned instant (${unit})` : 'step';
    if (this.#chart && xLabel === this.#xLabel) {
      this.#chart.setData(data);
      return;
    }
    this.#chart?.destroy();
    this.#xLabel = xLabel;
    this.#chart = new StepChart(
      this.#container,
      {
        title: stepSeconds
          ? `STEP and DIR per axis at each step's planned instant, ${unit} (a STEP pulse per step, drawn half-way to the nearer step; DIR high for -)`
          : 'STEP and DIR per axis (one tick per step: a STEP pulse per step taken, DIR high for -)',
        xLabel,
        // No pick while a new trace's first window is fetched: the chart
        // still shows the last trace's instants.
        pickX: stepSeconds ? (at) => this.#fromStep >= 0 && this.#onPick(this.#pointOfX(at)) : undefined,
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
