/**
 * The two charts of a trace, after Wang et al. (2020) Figure 6: each axis's
 * position against the step (6a: the point as stepped, and the ideal path at
 * the same progress), and each point's distance from the ideal path (6b's
 * straightness error) with the largest one marked. Their cursor is the
 * page's step. The rows come from the core through the worker, in one
 * request for the whole path (ChartSeries), made a slice of points at a
 * time with a bar and a Cancel: every point, or buckets of points on a
 * long path, where the deviation chart shows each bucket's range as a band.
 */
import type uPlot from 'uplot';
import type { ChartSeries, PointsProgress, TraceLegend, TraceSummary } from '../core/types.js';
import { pointsBar, RunProgress, type RunProgressElements, throttled } from '../form/run-progress.js';
import { AXIS_NAMES } from '../format.js';
import { afterNextFrame } from '../main-thread.js';
import { AXIS_COLOURS, PALETTE } from '../scene/palette.js';
import { Cancelled, type Running } from '../worker/client.js';
import { StepChart } from './chart.js';

/** Rows the charts ask for: about one per pixel of a wide chart. */
const CHART_POINTS = 2000;

export interface ChartedTrace extends Pick<TraceSummary, 'dims'>, Pick<TraceLegend, 'deviationBound'> {
  series(maxPoints: number, onProgress: (progress: PointsProgress) => void): Running<ChartSeries>;
}

/** What the charts show while their rows are made, and after a Cancel. */
export interface ChartsRunElements extends RunProgressElements {
  /** Says the charts were cancelled, with a button (`start`) that draws them. */
  cancelled: HTMLElement;
  start: HTMLButtonElement;
}

/** What the charts ask of the page: stop their rows (their Cancel), draw them (Draw charts). The page keeps a Cancel standing until Draw charts. */
export interface ChartsActions {
  cancel: () => void;
  draw: () => void;
}

export class PathCharts {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  readonly #progress: RunProgress;
  readonly #cancelledNote: HTMLElement;
  #charts: StepChart[] = [];
  #request = 0;
  #pointIndex = 0;
  /** The trace charted (or to chart), and its rows on their way from the worker. */
  #trace: ChartedTrace | undefined;
  #running: Running<ChartSeries> | undefined;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void, run: ChartsRunElements, actions: ChartsActions) {
    this.#container = container;
    this.#onPick = onPick;
    // The rows of every point of a long path take a while (a helix's 1,500,000 about a second): a bar and a Cancel.
    this.#progress = new RunProgress({ ...run, start: undefined }, actions.cancel);
    this.#cancelledNote = run.cancelled;
    run.start.addEventListener('click', actions.draw);
  }

  /** The rows of the trace charted are on their way from the worker (its Cancel stops them). */
  get drawing(): boolean {
    return this.#running !== undefined;
  }

  /** Draws the charts of the trace last given (Draw charts, after a Cancel). */
  draw(): void {
    void this.setTrace(this.#trace, this.#pointIndex);
  }

  /**
   * Charts `trace` (undefined: none) once the worker sends its rows, its
   * cursor at point index `pointIndex` (a link's step: the cursor stayed at
   * 0 until the step changed). The rows asked for before are cancelled.
   */
  async setTrace(trace: ChartedTrace | undefined, pointIndex: number): Promise<void> {
    const request = this.#replace(trace, pointIndex);
    // The new path is drawn first: the worker builds the series after that frame.
    await afterNextFrame();
    if (request !== this.#request) return;
    let series: ChartSeries | undefined;
    if (trace) {
      const current = () => request === this.#request;
      this.#running = trace.series(
        CHART_POINTS,
        throttled(current, (progress) => this.#progress.set(pointsBar(progress))),
      );
      try {
        // Cancelled, even when the rows were made before the Cancel reached the worker (Running.cancel).
        series = await this.#running.result;
      } catch (error) {
        // Rows asked for a trace no longer charted: dropped (its trace may be freed meanwhile).
        if (!current()) return;
        this.#running = undefined;
        this.#progress.set(undefined);
        if (!(error instanceof Cancelled)) throw error;
        this.#destroy();
        this.#cancelledNote.hidden = false;
        return;
      }
      if (!current()) return;
      this.#running = undefined;
      this.#progress.set(undefined);
    }
    this.#destroy();
    if (!trace || !series) return;
    const axes = AXIS_NAMES.slice(0, trace.dims);
    const x = series.pointIndex;
    const positions: uPlot.Series[] = axes.flatMap((axis, a) => [
      { label: `${axis}`, stroke: AXIS_COLOURS[a], width: 2 },
      { label: `${axis} ideal`, stroke: AXIS_COLOURS[a], width: 1, dash: [5, 4] },
    ]);
    const bucketNote = series.bucketed ? ` (${x.length} buckets of ${x[1]} points)` : '';
    this.#charts.push(
      new StepChart(
        this.#container,
        { title: `Axis position per step, grid units${bucketNote}`, xLabel: 'step', yLabel: 'position', series: positions },
        [x, ...axes.flatMap((_, a) => [series.position[a]!, series.ideal[a]!])],
        this.#onPick,
      ),
    );
    const deviationSeries: uPlot.Series[] = [{ label: series.bucketed ? 'largest in bucket' : 'distance', stroke: PALETTE.visited, width: 2, fill: series.bucketed ? undefined : 'rgba(86, 180, 233, 0.15)' }];
    const deviationData = [x, series.deviationMax];
    if (series.bucketed) {
      deviationSeries.push({ label: 'smallest in bucket', stroke: PALETTE.visited, width: 1 });
      deviationData.push(series.deviationMin);
    }
    // The series keeps every bucket's peak (ChartSeries), so the largest of
    // them is the path's largest deviation: a program's metrics, which make
    // each of its segments again, are not asked for to draw it.
    const largest = series.deviationMax.reduce((a, b) => Math.max(a, b), 0);
    // The algorithm's promise, as Wang's maximum theoretical error (√2/2, his Figure 8): the core states it.
    const bound = trace.deviationBound;
    this.#charts.push(
      new StepChart(
        this.#container,
        {
          title: `Distance from the ideal path, grid units${bucketNote}`,
          xLabel: 'step',
          yLabel: 'distance',
          series: deviationSeries,
          bands: series.bucketed ? [{ series: [1, 2], fill: 'rgba(86, 180, 233, 0.25)' }] : undefined,
          references: [
            { value: largest, label: `largest ${largest.toFixed(4)}`, colour: PALETTE.current },
            ...(bound ? [{ value: bound.value, label: `bound ${bound.value.toFixed(4)} (the rule's)`, colour: PALETTE.ideal, labelAtRight: true }] : []),
          ],
          yRange: [0, Math.max(largest * 1.15, (bound?.value ?? 0) * 1.15, 0.1)],
        },
        deviationData,
        this.#onPick,
      ),
    );
    for (const chart of this.#charts) chart.showPoint(this.#pointIndex);
  }

  /**
   * Takes `trace` (its cursor at `pointIndex`) without charting it, as its
   * Cancel leaves it: the charts say they are not drawn, with Draw charts
   * (the page's Cancel of the same inputs' charts stands).
   */
  setCancelled(trace: ChartedTrace, pointIndex: number): void {
    this.#replace(trace, pointIndex);
    this.#destroy();
    this.#cancelledNote.hidden = false;
  }

  /** Takes `trace` in place of the one charted, whose rows on their way are no longer wanted; returns the new request's number. */
  #replace(trace: ChartedTrace | undefined, pointIndex: number): number {
    const request = ++this.#request;
    this.#running?.cancel();
    this.#running = undefined;
    this.#trace = trace;
    this.#pointIndex = pointIndex;
    this.#progress.set(undefined);
    this.#cancelledNote.hidden = true;
    return request;
  }

  /** Stops the rows on their way (a Cancel, or new inputs whose path will replace this one): the charts say so, with Draw charts. */
  cancel(): void {
    this.#running?.cancel();
  }

  #destroy(): void {
    for (const chart of this.#charts) chart.destroy();
    this.#charts = [];
  }

  /** Moves the charts' cursor to `pointIndex`. */
  showPoint(pointIndex: number): void {
    this.#pointIndex = pointIndex;
    for (const chart of this.#charts) chart.showPoint(pointIndex);
  }
}
