/**
 * Time in G-code mode, from the core's plan (Grbl 1.1's planner,
 * rust/src/planner.rs): the program's total time, the current step's
 * instant, the tool's speed along the path over time (the planned
 * trapezoids, with the planned speed at each move's start, its corner's
 * junction speed, marked) and each axis's step rate in Hz. The charts show
 * the whole program or a window of time around the current step; clicking
 * one picks the step the machine had reached at that instant.
 *
 * Nothing here grows with the program: the worker sends chart rows for the
 * window (GcodeProgram.motionChart, about one per pixel: the trapezoids'
 * corners when few blocks are in view, else the least and greatest value in
 * each bucket of time), and it is asked after the new path's first frame.
 */
import type uPlot from 'uplot';
import { StepChart } from '../charts/chart.js';
import type { GcodeProgramInfo, MotionChart } from '../core/index.js';
import { AXIS_NAMES, countOf } from '../format.js';
import { afterNextFrame } from '../main-thread.js';
import { AXIS_COLOURS, PALETTE } from '../scene/palette.js';
import { formatSeconds } from './time-format.js';

/** What the charts need of a program the worker holds (a RemoteProgram). */
export interface TimedProgram {
  readonly program: Pick<GcodeProgramInfo, 'durationSeconds' | 'pulses' | 'steps'>;
  motionChart(fromSeconds: number, toSeconds: number, buckets: number): Promise<MotionChart>;
  secondsAtPoint(pointIndex: number): Promise<number>;
  pointAtSeconds(seconds: number): Promise<number>;
}

/** Spans the charts can show around the current step, seconds; null: the whole program. */
const WINDOWS: readonly { span: number | null; label: string }[] = [
  { span: null, label: 'the whole program' },
  { span: 10, label: '10 s around the current step' },
  { span: 1, label: '1 s around the current step' },
  { span: 0.1, label: '100 ms around the current step' },
];

/** Most rows asked for: about a pixel each on a wide screen. */
const MAX_BUCKETS = 2000;
/** Width of the y axis and margins, CSS pixels, left of a chart's plot. */
const AXIS_PX = 70;

export class MotionCharts {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  readonly #summary: HTMLParagraphElement;
  readonly #instant: HTMLElement;
  readonly #windowSelect: HTMLSelectElement;
  readonly #chartsBox: HTMLDivElement;
  #program: TimedProgram | undefined;
  #charts: StepChart[] = [];
  /** Counts programs and windows asked for, so only the latest answer is drawn. */
  #request = 0;
  /** The window charted, seconds. */
  #shown: { from: number; to: number } | undefined;
  /** The current point, and its instant once known. */
  #pointIndex = 0;
  #cursorSeconds = 0;
  /** True while the instant of a point is being asked for (one question at a time: playback asks every frame). */
  #asking = false;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
    this.#summary = document.createElement('p');
    this.#summary.className = 'total-time';
    this.#summary.dataset.testid = 'total-time';
    const tools = document.createElement('p');
    tools.className = 'motion-tools';
    const label = document.createElement('label');
    label.textContent = 'Time shown ';
    this.#windowSelect = document.createElement('select');
    this.#windowSelect.dataset.testid = 'motion-window';
    for (const { span, label: text } of WINDOWS) this.#windowSelect.append(new Option(text, String(span ?? '')));
    this.#windowSelect.addEventListener('change', () => void this.#load());
    label.append(this.#windowSelect);
    this.#instant = document.createElement('span');
    this.#instant.className = 'step-instant';
    this.#instant.dataset.testid = 'step-instant';
    tools.append(label, ' ', this.#instant);
    this.#chartsBox = document.createElement('div');
    this.#chartsBox.className = 'charts';
    container.append(this.#summary, tools, this.#chartsBox);
    container.hidden = true;
  }

  /** Charts `program`'s plan (undefined: none), after the new path's first frame. */
  async setProgram(program: TimedProgram | undefined, pointIndex: number): Promise<void> {
    const request = ++this.#request;
    this.#program = program;
    this.#pointIndex = pointIndex;
    this.#shown = undefined;
    this.#clearCharts();
    this.#container.hidden = !program;
    if (!program) return;
    const record = program.program;
    this.#summary.textContent = `Total time on the planned profile: ${formatSeconds(record.durationSeconds)} for ${countOf(record.steps, 'step')} (Grbl 1.1's planner: trapezoids, junction deviation, look-ahead over the whole program).`;
    this.#instant.textContent = '';
    await afterNextFrame();
    if (request !== this.#request) return;
    this.#cursorSeconds = await program.secondsAtPoint(pointIndex);
    if (request !== this.#request) return;
    await this.#load();
  }

  /** Moves the cursor to the instant `pointIndex` is reached, and the window with it when it leaves the middle. */
  showPoint(pointIndex: number): void {
    this.#pointIndex = pointIndex;
    if (this.#asking || !this.#program) return;
    void this.#follow(this.#program);
  }

  async #follow(program: TimedProgram): Promise<void> {
    this.#asking = true;
    try {
      // The point may move on while its instant is asked for: ask again until it is the one shown.
      for (let asked = -1; asked !== this.#pointIndex && program === this.#program; ) {
        asked = this.#pointIndex;
        this.#cursorSeconds = await program.secondsAtPoint(asked);
      }
    } catch {
      // The program went with its worker; the next one starts over.
      return;
    } finally {
      this.#asking = false;
    }
    if (program !== this.#program) return;
    const shown = this.#shown;
    const span = this.#span();
    if (shown && span !== null) {
      const margin = (shown.to - shown.from) / 8;
      const duration = program.program.durationSeconds;
      const outside = (this.#cursorSeconds < shown.from + margin && shown.from > 0) || (this.#cursorSeconds > shown.to - margin && shown.to < duration);
      if (outside) return this.#load();
    }
    this.#showCursor();
  }

  /** The span chosen, seconds; null: the whole program. */
  #span(): number | null {
    return this.#windowSelect.value === '' ? null : Number(this.#windowSelect.value);
  }

  #showCursor(): void {
    this.#instant.textContent = `Current step at ${formatSeconds(this.#cursorSeconds)}.`;
    this.#instant.dataset.seconds = String(this.#cursorSeconds);
    for (const chart of this.#charts) chart.showX(this.#cursorSeconds);
  }

  #clearCharts(): void {
    for (const chart of this.#charts) chart.destroy();
    this.#charts = [];
    // Until the next window is drawn: tells a reader (a test) that the charts on screen are not yet this program's.
    this.#chartsBox.dataset.drawn = 'false';
  }

  /** Asks for the chosen window around the cursor and draws it. */
  async #load(): Promise<void> {
    const program = this.#program;
    if (!program) return;
    const request = ++this.#request;
    const duration = program.program.durationSeconds;
    if (!(duration > 0)) {
      this.#clearCharts();
      this.#showCursor();
      return;
    }
    const span = Math.min(this.#span() ?? duration, duration);
    // The cursor a third of the way in, as the timing diagram's window.
    const from = Math.max(0, Math.min(this.#cursorSeconds - span / 3, duration - span));
    const buckets = Math.max(100, Math.min(MAX_BUCKETS, Math.floor(this.#chartsBox.clientWidth - AXIS_PX)));
    let chart: MotionChart;
    try {
      chart = await program.motionChart(from, from + span, buckets);
    } catch {
      return;
    }
    if (request !== this.#request) return;
    this.#shown = { from: chart.fromSeconds, to: chart.toSeconds };
    this.#draw(chart, program);
    this.#showCursor();
  }

  #draw(chart: MotionChart, program: TimedProgram): void {
    this.#clearCharts();
    const pick = (seconds: number) => {
      void program.pointAtSeconds(seconds).then(
        (pointIndex) => {
          if (program === this.#program) this.#onPick(pointIndex);
        },
        () => undefined,
      );
    };
    const rows = chart.seconds.length;
    const bucketNote = chart.exact ? 'each block its trapezoid' : `${rows} buckets of ${formatSeconds((chart.toSeconds - chart.fromSeconds) / rows)}: the band from the least to the greatest in each`;
    // In seconds, as the charts' time axis reads (formatSeconds wrote a 100 ms
    // window in ms over an axis in seconds).
    const window = `${chart.fromSeconds.toFixed(3)} s to ${chart.toSeconds.toFixed(3)} s`;
    const junctions: uPlot.Series = { label: 'junction speed', stroke: PALETTE.onlySecond, paths: () => null, points: { show: true, size: 7, fill: PALETTE.onlySecond } };
    // Corners: one line. Buckets: the greatest and least in each, a band between.
    const speedSeries: uPlot.Series[] = chart.exact
      ? [{ label: 'planned speed', stroke: PALETTE.visited, width: 2 }, junctions]
      : [{ label: 'greatest', stroke: PALETTE.visited, width: 2 }, { label: 'least', stroke: PALETTE.visited, width: 1 }, junctions];
    this.#charts.push(
      new StepChart(
        this.#chartsBox,
        {
          title: `Tool speed along the path, mm/s, ${window} (${bucketNote}; dots: junction speeds, the planned speed where a move starts after another)`,
          xLabel: 'time (s)',
          xRange: [chart.fromSeconds, chart.toSeconds],
          yLabel: 'mm/s',
          series: speedSeries,
          bands: chart.exact ? undefined : [{ series: [1, 2], fill: 'rgba(86, 180, 233, 0.25)' }],
          pickX: pick,
        },
        chart.exact ? [chart.seconds, chart.speedMax, chart.junctionSpeed] : [chart.seconds, chart.speedMax, chart.speedMin, chart.junctionSpeed],
        () => undefined,
      ),
    );
    // The axes the program steps at all (a flat line at 0 says nothing).
    const axes = AXIS_NAMES.slice(0, 3).flatMap((name, axis) => ((program.program.pulses[axis] ?? 0) > 0 ? [{ name, axis }] : []));
    if (axes.length === 0) return;
    const perAxis = chart.exact ? 1 : 2;
    const rateSeries: uPlot.Series[] = axes.flatMap(({ name, axis }) =>
      chart.exact
        ? [{ label: name, stroke: AXIS_COLOURS[axis], width: 2 }]
        : [
            { label: `${name} greatest`, stroke: AXIS_COLOURS[axis], width: 2 },
            { label: `${name} least`, stroke: AXIS_COLOURS[axis], width: 1 },
          ],
    );
    this.#charts.push(
      new StepChart(
        this.#chartsBox,
        {
          title: `Step rate per axis, Hz (steps/s), ${window}: the speed times the axis's share of the move times its steps/mm`,
          xLabel: 'time (s)',
          xRange: [chart.fromSeconds, chart.toSeconds],
          yLabel: 'Hz',
          series: rateSeries,
          bands: chart.exact ? undefined : axes.map(({ axis }, i) => ({ series: [perAxis * i + 1, perAxis * i + 2] as [number, number], fill: `${AXIS_COLOURS[axis]}33` })),
          pickX: pick,
        },
        [chart.seconds, ...axes.flatMap(({ axis }) => (chart.exact ? [chart.stepRateMax[axis]!] : [chart.stepRateMax[axis]!, chart.stepRateMin[axis]!]))],
        () => undefined,
      ),
    );
    this.#chartsBox.dataset.drawn = 'true';
  }
}
