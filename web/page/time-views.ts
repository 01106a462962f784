/**
 * The page's views of time (issue 14), in one place so the page wires them
 * with a few lines:
 * - G-code mode: the total time, the speed and step-rate charts
 *   (gcode/motion-charts.ts), machine-time playback (the timeline follows
 *   the program's planned instants);
 * - trace mode, for a line: the speed per step at one tick a step and at a
 *   constant feed (charts/step-clocks-chart.ts).
 * The timing diagram (gcode/timing-diagram.ts) takes its clock from the
 * worker's pulses: ticks for a trace, planned instants for a program.
 */
import { StepClocksChart } from '../charts/step-clocks-chart.js';
import { MotionCharts } from '../gcode/motion-charts.js';
import type { Catalogue, Mode } from '../state/app-state.js';
import type { Timeline } from '../timeline/timeline.js';
import type { RemoteProgram, RemoteTrace } from '../worker/client.js';

export interface TimeViewElements {
  /** G-code mode: where the total time and the motion charts go. */
  motion: HTMLElement;
  /** Trace mode: where the speed-per-step chart goes. */
  stepClocks: HTMLElement;
}

export class TimeViews {
  readonly #catalogue: Catalogue;
  readonly #timeline: Timeline;
  readonly #motion: MotionCharts;
  readonly #stepClocks: StepClocksChart;
  #program: RemoteProgram | undefined;
  /** The line whose speed per step is charted. */
  #clocked: RemoteTrace | undefined;

  constructor(elements: TimeViewElements, catalogue: Catalogue, timeline: Timeline, onPick: (pointIndex: number) => void) {
    this.#catalogue = catalogue;
    this.#timeline = timeline;
    this.#motion = new MotionCharts(elements.motion, onPick);
    this.#stepClocks = new StepClocksChart(elements.stepClocks, onPick);
  }

  /** Shows the time of what is on screen: `program` in G-code mode, `trace` (when a line) in trace mode. */
  show(mode: Mode, program: RemoteProgram | undefined, trace: RemoteTrace | undefined, pointIndex: number): void {
    if (program !== this.#program) {
      this.#program = program;
      void this.#motion.setProgram(program, pointIndex);
      this.#timeline.setClock(
        program && {
          durationSeconds: program.program.durationSeconds,
          secondsAtPoint: (k) => program.secondsAtPoint(k),
          pointAtSeconds: (seconds) => program.pointAtSeconds(seconds),
        },
      );
    }
    const line = mode === 'trace' && trace !== undefined && this.#catalogue.algorithms.find((a) => a.id === trace.algorithm)?.family === 'line';
    const clocked = line ? trace : undefined;
    if (clocked !== this.#clocked) {
      this.#clocked = clocked;
      void this.#stepClocks.setTrace(clocked);
    }
    this.showPoint(pointIndex);
  }

  /** Moves every time view's cursor to point index k. */
  showPoint(pointIndex: number): void {
    this.#motion.showPoint(pointIndex);
    this.#stepClocks.showPoint(pointIndex);
  }
}
