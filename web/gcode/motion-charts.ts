/**
 * Time in G-code mode, from the core's plan (Grbl 1.1's planner,
 * rust/src/planner.rs): the tool's speed along the path over time, with each
 * block's trapezoid (accelerate, cruise, decelerate) and each corner's
 * junction speed marked, and each axis's planned step rate in Hz. The cursor
 * is the current step's instant; clicking picks the step taken then.
 */
import type uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS, PALETTE } from '../scene/palette.js';
import type { MotionProfile } from '../worker/protocol.js';
import { formatSeconds } from './time-format.js';

/** What the charts need of a program the worker holds. */
export interface TimedProgram {
  dims: number;
  steps: number;
  motion(): Promise<MotionProfile>;
  stepTimes(fromStep: number, toStep: number): Promise<Float64Array>;
  stepAtSeconds(seconds: number): Promise<number>;
}

export class MotionCharts {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  #program: TimedProgram | undefined;
  #charts: StepChart[] = [];
  #request = 0;
  #cursor = 0;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
  }

  /** Charts `program`'s plan (undefined: none) once the worker sends it. */
  async setProgram(program: TimedProgram | undefined, pointIndex: number): Promise<void> {
    const request = ++this.#request;
    this.#program = program;
    const profile = program ? await program.motion() : undefined;
    if (request !== this.#request) return;
    for (const chart of this.#charts) chart.destroy();
    this.#charts = [];
    this.#container.querySelector('.total-time')?.remove();
    if (!program || !profile) return;
    const total = document.createElement('p');
    total.className = 'total-time';
    total.dataset.testid = 'total-time';
    total.textContent = `Total time on the planned profile: ${formatSeconds(profile.durationSeconds)} (${program.steps.toLocaleString('en-US')} steps).`;
    this.#container.append(total);
    const pick = (seconds: number) => {
      void program.stepAtSeconds(seconds).then((point) => {
        if (program === this.#program) this.#onPick(point);
      });
    };
    // (seconds, mm/s) corners -> columns; the junctions as a points-only series on the same x.
    const corners = profile.speed.length / 2;
    const junctions = profile.junctions.length / 2;
    const x = new Float64Array(corners + junctions);
    // uPlot's gaps are nulls (a NaN would spoil the y range).
    const speed: (number | null)[] = new Array<number | null>(corners + junctions).fill(null);
    const corner: (number | null)[] = new Array<number | null>(corners + junctions).fill(null);
    // Merge both sorted lists by time, so uPlot's x stays ascending.
    for (let i = 0, j = 0, row = 0; row < x.length; row++) {
      const takeCorner = j >= junctions || (i < corners && profile.speed[2 * i]! <= profile.junctions[2 * j]!);
      if (takeCorner) {
        x[row] = profile.speed[2 * i]!;
        speed[row] = profile.speed[2 * i + 1]!;
        i++;
      } else {
        x[row] = profile.junctions[2 * j]!;
        corner[row] = profile.junctions[2 * j + 1]!;
        j++;
      }
    }
    const speedSeries: uPlot.Series[] = [
      { label: 'planned speed, mm/s', stroke: PALETTE.onlyFirst, width: 2, spanGaps: true },
      { label: 'junction speed at a move start', stroke: PALETTE.onlySecond, width: 0, points: { show: true, size: 7, fill: PALETTE.onlySecond } },
    ];
    this.#charts.push(
      new StepChart(
        this.#container,
        {
          title: `Tool speed along the path, mm/s, over time (planned trapezoids; dots: each move's entry speed, its corner's junction speed); total ${formatSeconds(profile.durationSeconds)}`,
          xLabel: 'time (s)',
          yLabel: 'mm/s',
          series: speedSeries,
          pickX: pick,
        },
        [x, speed, corner],
        () => undefined,
      ),
    );
    const stride = 1 + program.dims;
    const rows = profile.stepRates.length / stride;
    const times = new Float64Array(rows);
    const rates = AXIS_NAMES.slice(0, program.dims).map(() => new Float64Array(rows));
    for (let r = 0; r < rows; r++) {
      times[r] = profile.stepRates[r * stride]!;
      for (let a = 0; a < program.dims; a++) rates[a]![r] = profile.stepRates[r * stride + 1 + a]!;
    }
    this.#charts.push(
      new StepChart(
        this.#container,
        {
          title: 'Step rate per axis, Hz (steps/s), planned',
          xLabel: 'time (s)',
          yLabel: 'Hz',
          series: AXIS_NAMES.slice(0, program.dims).map((axis, a) => ({ label: `${axis} steps/s`, stroke: AXIS_COLOURS[a], width: 2 })),
          pickX: pick,
        },
        [times, ...rates],
        () => undefined,
      ),
    );
    await this.showPoint(pointIndex);
  }

  /** Moves the cursor to the instant point `pointIndex` is reached (the instant of step pointIndex - 1; 0 at the start). */
  async showPoint(pointIndex: number): Promise<void> {
    const program = this.#program;
    if (!program || this.#charts.length === 0) return;
    const cursor = ++this.#cursor;
    const seconds = pointIndex === 0 ? 0 : (await program.stepTimes(pointIndex - 1, pointIndex))[0]!;
    if (cursor !== this.#cursor || program !== this.#program) return;
    for (const chart of this.#charts) chart.showX(seconds);
  }
}
