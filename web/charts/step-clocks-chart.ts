/**
 * Trace mode, for a line: the tool's speed per step under two clocks, the
 * 2009 line-following blog's point about Bresenham's steps. At one tick a
 * step, a step moving m axes covers √m of a cell in the tick, so the speed
 * jumps between 1, √2 and √3 cells a tick; at a constant feed (1 cell a
 * tick) a step takes √m ticks and the speed holds. The values are the
 * core's (Trace.stepClocks, in the worker), one row a step, or the least and
 * greatest of a run of steps on a long line; asked after the path's first
 * frame. Its cursor is the page's step.
 */
import uPlot from 'uplot';
import type { StepClocks } from '../core/types.js';
import { afterNextFrame } from '../main-thread.js';
import { PALETTE } from '../scene/palette.js';
import { StepChart } from './chart.js';

/** The blog's sentence, as it wrote it (shared/seeds/cnc-line-following-blog-2009.md). */
const BLOG_2009_SENTENCE = 'This means the speed would not be constant if I applied this algorithm directly.';

/** Most rows asked for: about a pixel each on a wide screen. */
const MAX_ROWS = 2000;

export interface ClockedTrace {
  stepClocks(maxRows: number): Promise<StepClocks>;
}

export class StepClocksChart {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  #chart: StepChart | undefined;
  #request = 0;
  #pointIndex = 0;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
  }

  /** Charts `trace` (undefined: none) once the worker sends its rows. */
  async setTrace(trace: ClockedTrace | undefined): Promise<void> {
    const request = ++this.#request;
    this.#chart?.destroy();
    this.#chart = undefined;
    this.#container.hidden = !trace;
    if (!trace) return;
    await afterNextFrame();
    if (request !== this.#request) return;
    const clocks = await trace.stepClocks(Math.max(1, Math.min(MAX_ROWS, this.#container.clientWidth || MAX_ROWS)));
    if (request !== this.#request) return;
    const rows = clocks.equalTickMax.length;
    if (rows === 0) return;
    // Stepped: row r holds from rowEdges[r] to rowEdges[r + 1]; the last value again at the right edge.
    const hold = (values: number[]) => [...values, values[rows - 1]!];
    const bucketed = clocks.rowEdges[1]! - clocks.rowEdges[0]! > 1;
    const stepped = uPlot.paths.stepped!({ align: 1 });
    const feed: uPlot.Series = { label: `constant feed, ${clocks.feedCellsPerTick} cell a tick`, stroke: PALETTE.second, width: 2, dash: [6, 4], paths: stepped };
    const feedRow = clocks.rowEdges.map(() => clocks.feedCellsPerTick);
    // One step a row: one line. Runs of steps: the greatest and least in each, a band between.
    const series: uPlot.Series[] = bucketed
      ? [{ label: 'one tick a step, greatest', stroke: PALETTE.current, width: 2, paths: stepped }, { label: 'one tick a step, least', stroke: PALETTE.current, width: 1, paths: stepped }, feed]
      : [{ label: 'one tick a step', stroke: PALETTE.current, width: 2, paths: stepped }, feed];
    const ticks = clocks.feedTotalTicks.toFixed(2);
    this.#chart = new StepChart(
      this.#container,
      {
        title: `Tool speed per step, cells per tick: one tick a step (the line takes ${clocks.equalTickTotalTicks} ticks) or a constant feed (${ticks} ticks)`,
        xLabel: 'step',
        yLabel: 'cells/tick',
        series,
        bands: bucketed ? [{ series: [1, 2], fill: 'rgba(213, 94, 0, 0.2)' }] : undefined,
        // From 0, so the jumps read as ratios (a √6 step of six axes fits too).
        yRange: [0, Math.max(2, ...clocks.equalTickMax) * 1.1],
        caption:
          `“${BLOG_2009_SENTENCE}” (“CNC Line Following Algorithm”, blog post, 6 July 2009, on Bresenham's steps.) ` +
          'A step moving one axis covers 1 cell, two axes √2, three √3: at one tick a step the tool runs that much faster on a diagonal step. ' +
          'At a constant feed along the path (1 cell a tick) a diagonal step takes √2 or √3 ticks instead, and the speed holds.',
      },
      bucketed ? [clocks.rowEdges, hold(clocks.equalTickMax), hold(clocks.equalTickMin), feedRow] : [clocks.rowEdges, hold(clocks.equalTickMax), feedRow],
      this.#onPick,
    );
    this.#chart.showPoint(this.#pointIndex);
  }

  /** Moves the cursor to `pointIndex`. */
  showPoint(pointIndex: number): void {
    this.#pointIndex = pointIndex;
    this.#chart?.showPoint(pointIndex);
  }
}
