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
 *
 * A program's window stops at a pause (timing-window.ts): a dwell, a stop,
 * a slow step before fast ones, much longer than the steps' spacing around
 * the current step, would press their pulses into bars. The pause is drawn
 * at that edge, not to scale, hatched and labelled with its length and the
 * dwell in it (the core's dwellSeconds); the signals hold through it, DIR
 * set half-way across it for the step on its other side, as the VCD sets it.
 * The wait before the program's first step and after its last (a closing
 * dwell, to the program's end) are drawn so too, and so is the edge where
 * a much faster move starts, where the window is cut as well (the steps
 * past it ten times faster than the current step's, or more), labelled so.
 * Beside a move less than that faster, the window holds fewer steps where
 * it must, so that the narrowest gap it draws stays half a tick wide of the
 * width its steps get: the plot's less the pauses' boxes, each as wide as
 * its label (#pauseBoxChoices), measured before the window is chosen, and
 * chosen for the pauses the window is drawn with (choosePauseBoxes). In a
 * narrow plot a label takes a shorter form ('dwell 2 s', '+2 s'; '+2 s'),
 * or none, so that the boxes leave the steps 30% of it; the labels so
 * shortened are written whole under the chart. The window and the boxes
 * are chosen again when the plot is resized.
 */
import uPlot from 'uplot';
import { breakLabelWidthsPx, StepChart, type XBreak } from '../charts/chart.js';
import { AXIS_NAMES } from '../format.js';
import { AXIS_COLOURS } from '../scene/palette.js';
import type { PulseWindow } from '../worker/protocol.js';
import { drawnFromZero, pulseEdges, ROWS_PER_STEP } from './pulse-edges.js';
import { formatSeconds, formatSecondsBrief, timeUnit } from './time-format.js';
import {
  type EdgePause,
  edgePauses,
  neededSteps,
  PAUSE_FACTOR,
  type Pause,
  type PlotWidths,
  type StepWindow,
  stepsWidthPx,
  stepWindow,
  TICK_PX,
  windowHolds,
} from './timing-window.js';

/** Fewest ticks shown (TICK_PX each), however narrow the plot. */
const MIN_WINDOW_TICKS = 12;
/**
 * The panel's width less the plot's, CSS pixels, until a chart is drawn:
 * the lane labels' axis (62 px in the page's font), uPlot's room for its
 * (empty) y title (30), its padding at the right (25) and the chart's 4 px
 * inside the panel; 122 of a 296 px panel beside a 1280 px view. The plot's
 * own width is read once a chart is drawn.
 */
const LABELS_PX = 122;
/** Height per lane, CSS pixels, and for the title and the step axis. */
const LANE_PX = 26;
const FRAME_PX = 64;
/** Lane pitch and signal swing, in lane units. */
const LANE = 1.5;
const SWING = 1;
/**
 * A pause drawn at an edge is a box as wide as its label's longest line, up
 * to this share of the plot (two such boxes leave the steps 55% of it);
 * narrower, its lines wrap, to its widest word's width and no narrower, so
 * the label stays whole: beside a 1280 px view the panel is some 300 px
 * wide, its plot 174 px, where boxes of 76 px, or two of 45% of the plot,
 * cut 'program ends' (79 px of text) to 'rogram end' and 'st step'.
 */
const PAUSE_LINE_SHARE = 0.225;
/**
 * The share of the plot the pauses' boxes may take together, their labels
 * wrapped to their widest words: past it a label takes a shorter form
 * (pauseLabel's), the wider box's first, so that the steps keep 30% of the
 * plot. Without it, in a page under some 300 px wide (the chart's plot 79 px
 * at its narrowest, in a page of 240 px) the two boxes of a program of
 * one step needed 107 px for their words, and were drawn narrower than their
 * labels ('rogram', '.100 s', '2.000').
 */
const PAUSES_SHARE = 0.7;
/** A pause's box with no label in it (the label under the chart), CSS pixels: a tick of hatching between its dashed edges. */
const BARE_PAUSE_PX = TICK_PX;

export interface PulsedTrace {
  dims: number;
  steps: number;
  pulseTrains(fromStep: number, toStep: number): Promise<PulseWindow>;
  /** A program's record (GcodeProgramInfo): its duration is its end, seconds, after its last step when it ends with a dwell. */
  readonly program?: { readonly durationSeconds: number };
  /** A program's seconds of G4 dwell between two instants (GcodeProgram.dwellSeconds). */
  dwellSeconds?(fromSeconds: number, toSeconds: number): Promise<number>;
}

/** A pause's label: the lines its box can show, fullest first, and all it says as one sentence. */
interface PauseLabel {
  /** Each a form of the label, a line each: the full one, then shorter ones for a narrow box. */
  forms: string[][];
  description: string;
}

/** A pause at an edge of the window, as drawn: each axis's DIR on its far side, and its label (pauseLabel). */
interface LabelledPause {
  /** Per axis, +1 or -1: DIR for the step after the pause (a pause after the window), or before it (one before). */
  farDir: number[];
  label: PauseLabel;
}

/** A pause's box as drawn: its width, CSS pixels, and the form of its label it shows (none: the label is under the chart). */
interface PauseBox {
  px: number;
  lines: string[];
}

/** A pause drawn at an edge of the window, in its box. */
type DrawnPause = LabelledPause & { box: PauseBox };

/** A pause's full label as a phrase: 'dwell 2 s, program ends +2.000 s'. */
function fullLabel({ forms: [[title, ...rest]] }: PauseLabel): string {
  return `${title}, ${rest.join(' ')}`;
}

/** The signals of steps fromStep..toStep of a window fetched from step `first`. */
function slicePulses({ trains, stepSeconds }: PulseWindow, first: number, fromStep: number, toStep: number): PulseWindow {
  const [from, to] = [fromStep - first, toStep - first];
  return {
    trains: trains.map((t) => ({ step: t.step.subarray(from, to), dir: t.dir.subarray(from, to) })),
    stepSeconds: stepSeconds?.subarray(from, to) ?? null,
  };
}

/** A dwell's seconds as G4 gives them: "2 s", "0.5 s". */
function dwellText(seconds: number): string {
  return `${Number(seconds.toFixed(6))} s`;
}

/** `text` with its spaces no-break ones: a value and its unit, kept on one line of a pause's label. */
function whole(text: string): string {
  return text.replaceAll(' ', '\u00a0');
}

/**
 * The label of a pause at the window's edge `side`: what it is (a dwell of
 * `dwellSeconds` in it, a pause, or faster steps past it), and the time to
 * the step across it, or at the program's edge (`programEdge`) from its
 * start (0 s) to the first step and from the last step to its end. Its
 * forms, for narrower boxes: the full one ('dwell 2 s', 'program ends',
 * '+2.000 s'), what it is and the time in two digits ('dwell 2 s', '+2 s'),
 * then that time alone ('+2 s').
 */
function pauseLabel(pause: Pause, dwellSeconds: number, programEdge: boolean, side: 'before' | 'after'): PauseLabel {
  const title = pause.faster ? 'faster steps' : dwellSeconds > 0 ? `dwell ${whole(dwellText(dwellSeconds))}` : 'pause';
  const seconds = pause.toSeconds - pause.fromSeconds;
  const gap = formatSeconds(seconds);
  // The time's sign: + after the window, − before it, none from the program's start (an instant).
  const sign = side === 'after' ? '+' : programEdge ? '' : '−';
  const [gapLine, briefLine] = [whole(`${sign}${gap}`), whole(`${sign}${formatSecondsBrief(seconds)}`)];
  const kind = pause.faster
    ? `a faster move, its steps at least ${PAUSE_FACTOR} times as fast as the current step's`
    : dwellSeconds > 0
      ? `a pause with a G4 dwell of ${dwellText(dwellSeconds)} in it`
      : 'a pause';
  const forms = (across: string) => [[title, across, gapLine], [title, briefLine], [briefLine]];
  if (side === 'after') {
    return programEdge
      ? { forms: forms('program ends'), description: `${kind}: the program ends ${gap} after its last step (not to scale)` }
      : { forms: forms('next step'), description: `${kind}: the next step comes ${gap} after the last one drawn (not to scale)` };
  }
  return {
    forms: forms(programEdge ? 'first step at' : 'step before'),
    description: `${kind}: the first step drawn comes ${gap} after the ${programEdge ? "program's start" : 'step before it'} (not to scale)`,
  };
}

/**
 * The boxes of the pauses drawn together over a plot `plotPx` wide, from
 * each one's `choices` (#pauseBoxChoices', fullest first; none: no pause
 * there, null). Each takes its fullest, but while the boxes take more than
 * PAUSES_SHARE of the plot together, the widest of them that can takes its
 * next narrower one, and past its last, none (a bare box, the label under
 * the chart).
 */
function choosePauseBoxes(choices: PauseBox[][], plotPx: number): (PauseBox | null)[] {
  const chosen = choices.map(() => 0);
  const boxPx = (i: number) => choices[i]![chosen[i]!]?.px ?? 0;
  for (;;) {
    const totalPx = choices.reduce((sum, _, i) => sum + boxPx(i), 0);
    if (totalPx <= PAUSES_SHARE * plotPx) break;
    const narrowable = choices.map((_, i) => i).filter((i) => chosen[i]! < choices[i]!.length - 1);
    if (narrowable.length === 0) break;
    const widest = narrowable.reduce((a, b) => (boxPx(b) > boxPx(a) ? b : a));
    chosen[widest]!++;
  }
  return choices.map((boxes, i) => boxes[chosen[i]!] ?? null);
}

export class TimingDiagram {
  readonly #container: HTMLElement;
  readonly #onPick: (pointIndex: number) => void;
  #trace: PulsedTrace | undefined;
  #chart: StepChart | undefined;
  /** The steps shown (a trace's fromStep..fromStep + #windowTicks; a program's up to a pause), null until a trace's first window is drawn. */
  #window: StepWindow | null = null;
  #windowTicks = MIN_WINDOW_TICKS;
  /** Where a pause before the window is drawn from, in the axis's unit: the cursor of point 0 then. */
  #pauseBeforeX: number | null = null;
  #request = 0;
  /** A program's window: its steps' instants, seconds, and the axis unit's factor from seconds. */
  #stepSeconds: Float64Array | null = null;
  #perSecond = 1;
  /** The x axis's label, to know when the chart must be made again (the unit changed). */
  #xLabel = '';
  /** The point shown, and the plot's width its window and pauses' boxes were chosen for, CSS pixels: chosen again when the plot is resized. */
  #pointIndex = 0;
  #windowPlotPx = 0;

  constructor(container: HTMLElement, onPick: (pointIndex: number) => void) {
    this.#container = container;
    this.#onPick = onPick;
  }

  setTrace(trace: PulsedTrace | undefined, pointIndex: number): void {
    this.#trace = trace;
    this.#window = null;
    // The old chart stays until the new trace's first window replaces it
    // (#draw makes a new chart for a new label), so the box never empties
    // for the moment the window is fetched; none stays for no steps.
    this.#xLabel = '';
    if (!trace || trace.steps === 0) {
      this.#chart?.destroy();
      this.#chart = undefined;
      delete this.#container.dataset.fromStep;
      delete this.#container.dataset.toStep;
    }
    void this.showPoint(pointIndex);
  }

  /**
   * Moves the cursor to `pointIndex`, fetching a new window of ticks when it
   * leaves the one shown. `relayout`: once drawn, whether to choose the window
   * again if its plot came out of another width than it was chosen for.
   */
  async showPoint(pointIndex: number, relayout = true): Promise<void> {
    const trace = this.#trace;
    this.#pointIndex = pointIndex;
    if (!trace || trace.steps === 0) return;
    const inside = this.#window !== null && windowHolds(this.#window, pointIndex, this.#windowTicks, trace.steps, this.#stepSeconds !== null);
    if (!inside) {
      const request = ++this.#request;
      // The plot's width: the chart's as last drawn, or before the first the panel's less the lane labels.
      const plotPx = this.#chart?.plotWidthPx ?? this.#container.clientWidth - LABELS_PX;
      const ticks = Math.max(MIN_WINDOW_TICKS, Math.floor(plotPx / TICK_PX));
      // The steps any window for this point can hold, and those past its
      // edges (neededSteps): a program's window is chosen from their instants.
      const needed = neededSteps(pointIndex, ticks, trace.steps);
      let window: StepWindow;
      let pulses: PulseWindow;
      let widths: PlotWidths;
      const pauses: { before: DrawnPause | null; after: DrawnPause | null } = { before: null, after: null };
      try {
        const fetched = await trace.pulseTrains(needed.fromStep, needed.toStep);
        const endSeconds = trace.program?.durationSeconds;
        // The pauses a window can start and end at, labelled, and their boxes' widths: what the
        // window is chosen over (stepWindow), as the steps are drawn (#draw).
        const edges = edgePauses(pointIndex, ticks, trace.steps, needed.fromStep, fetched.stepSeconds, endSeconds);
        // Before the program's first step DIR is + (the VCD's level before any step); after its last, it holds.
        const dirAt = (k: number) => fetched.trains.map((t) => (k < 0 ? 1 : t.dir[Math.min(k, trace.steps - 1) - needed.fromStep]!));
        const labelled = async (edge: EdgePause | null, side: 'before' | 'after'): Promise<LabelledPause | null> => {
          if (!edge) return null;
          const dwellSeconds = (await trace.dwellSeconds?.(edge.pause.fromSeconds, edge.pause.toSeconds)) ?? 0;
          // The wait before the program's first step or after its last: no step on its far side.
          const programEdge = edge.farStep < 0 || edge.farStep >= trace.steps;
          return { farDir: dirAt(edge.farStep), label: pauseLabel(edge.pause, dwellSeconds, programEdge, side) };
        };
        const before = await labelled(edges.before, 'before');
        const after = await labelled(edges.after, 'after');
        // The boxes each label can take, then those chosen for each set of the pauses a window is drawn with:
        // a pause drawn alone keeps the fuller label it has room for beside the steps.
        const [choicesBefore, choicesAfter] = [before, after].map((pause) => (pause ? this.#pauseBoxChoices(pause.label, plotPx) : []));
        const boxesFor = [false, true].map((withBefore) =>
          [false, true].map((withAfter) => choosePauseBoxes([withBefore ? choicesBefore! : [], withAfter ? choicesAfter! : []], plotPx)),
        );
        widths = {
          plotPx,
          pausesPx: (withBefore, withAfter) => {
            const [b, a] = boxesFor[Number(withBefore)]![Number(withAfter)]!;
            return { beforePx: b?.px ?? 0, afterPx: a?.px ?? 0 };
          },
        };
        window = stepWindow(pointIndex, ticks, trace.steps, needed.fromStep, fetched.stepSeconds, endSeconds, widths);
        const [boxBefore, boxAfter] = boxesFor[Number(window.pauseBefore !== null)]![Number(window.pauseAfter !== null)]!;
        pauses.before = window.pauseBefore && before && { ...before, box: boxBefore! };
        pauses.after = window.pauseAfter && after && { ...after, box: boxAfter! };
        pulses = slicePulses(fetched, needed.fromStep, window.fromStep, window.toStep);
      } catch (error) {
        // The last trace's chart, kept until this window came, must not stay.
        if (request === this.#request && this.#window === null) {
          this.#chart?.destroy();
          this.#chart = undefined;
        }
        throw error;
      }
      if (request !== this.#request || trace !== this.#trace) return;
      this.#windowTicks = ticks;
      this.#window = window;
      this.#windowPlotPx = plotPx;
      // The steps drawn, for a reader (and a test) of the page.
      this.#container.dataset.fromStep = String(window.fromStep);
      this.#container.dataset.toStep = String(window.toStep);
      this.#draw(pulses, pauses, widths);
      // A plot of another width than the window was chosen for (a first chart, whose lane labels'
      // axis is measured as it is made, or one resized): the window once more, at the plot's own
      // width, so that the steps' gaps drawn are those stepWindow kept.
      if (relayout && this.#chart && Math.abs(this.#chart.plotWidthPx - plotPx) > 0.5) {
        this.#window = null;
        await this.showPoint(pointIndex, false);
        return;
      }
    }
    this.#chart?.showX(this.#xOfPoint(pointIndex));
  }

  /** The x of point index k: k ticks, or (a program) the instant of the step that reached it. */
  #xOfPoint(pointIndex: number): number {
    const times = this.#stepSeconds;
    if (!times) return pointIndex;
    // At the start, in a wait drawn as a pause: the pause's start.
    if (pointIndex === 0) return this.#pauseBeforeX ?? 0;
    const i = Math.max(0, Math.min(times.length - 1, pointIndex - 1 - this.#window!.fromStep));
    return times[i]! * this.#perSecond;
  }

  /** The point index reached at x (a program: the steps of the window at or before that instant). */
  #pointOfX(x: number): number {
    const times = this.#stepSeconds!;
    let k = 0;
    while (k < times.length && times[k]! * this.#perSecond <= x) k++;
    return this.#window!.fromStep + k;
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
    if (!times) return { x: pulseEdges(Float64Array.from({ length: ticks }, (_, i) => this.#window!.fromStep + i)), unit: 'tick' };
    const edges = pulseEdges(times.subarray(0, ticks));
    // The span drawn: from 0 s when the window starts there (#draw).
    const { unit, perSecond } = timeUnit(edges[edges.length - 1]! - (fromZero ? 0 : edges[0]!));
    this.#perSecond = perSecond;
    return { x: edges.map((t) => t * perSecond), unit };
  }

  /**
   * The boxes a pause's `label` can take over a plot `plotPx` wide, fullest
   * first (choosePauseBoxes' choices): with each form of its label, as wide
   * as its longest line, up to PAUSE_LINE_SHARE of the plot, but never under
   * its widest word's, so that its text is whole; then bare. A form no
   * narrower than a fuller one before it is left out, of no use.
   */
  #pauseBoxChoices(label: PauseLabel, plotPx: number): PauseBox[] {
    const boxes: PauseBox[] = [];
    for (const lines of [...label.forms, []]) {
      const { wrappedPx, unwrappedPx } = lines.length ? breakLabelWidthsPx(this.#container, lines) : { wrappedPx: BARE_PAUSE_PX, unwrappedPx: BARE_PAUSE_PX };
      const px = Math.max(wrappedPx, Math.min(unwrappedPx, PAUSE_LINE_SHARE * plotPx));
      if (boxes.length === 0 || px < boxes[boxes.length - 1]!.px) boxes.push({ px, lines });
    }
    return boxes;
  }

  /** The plot resized: its window and pauses' boxes chosen again for its width, when it is on screen (a hidden chart is drawn at its least width). */
  #resized(): void {
    if (!this.#chart || !this.#container.checkVisibility() || Math.abs(this.#chart.plotWidthPx - this.#windowPlotPx) <= 0.5) return;
    this.#window = null;
    void this.showPoint(this.#pointIndex);
  }

  #draw({ trains, stepSeconds }: PulseWindow, pauses: { before: DrawnPause | null; after: DrawnPause | null }, widths: PlotWidths): void {
    const ticks = trains[0]!.step.length;
    this.#stepSeconds = stepSeconds;
    this.#perSecond = 1;
    const idle = stepSeconds !== null && drawnFromZero(stepSeconds.subarray(0, ticks), this.#window!.fromStep === 0);
    const { x, unit } = this.#rowsX(ticks, stepSeconds, idle);
    // The x the pauses take, out of scale: each its box's width (choosePauseBoxes')
    // of the plot's, the steps the rest (stepsWidthPx, as stepWindow took it).
    const [startX, endX] = [idle ? 0 : x[0]!, x[x.length - 1]!];
    const xPerPx = (endX - startX) / stepsWidthPx(widths, pauses.before !== null, pauses.after !== null);
    const [beforeX, afterX] = [(pauses.before?.box.px ?? 0) * xPerPx, (pauses.after?.box.px ?? 0) * xPerPx];
    this.#pauseBeforeX = pauses.before ? startX - beforeX : null;
    const breaks: XBreak[] = [];
    if (pauses.before) breaks.push({ fromX: startX - beforeX, toX: startX, lines: pauses.before.box.lines, description: pauses.before.label.description });
    if (pauses.after) breaks.push({ fromX: endX, toX: endX + afterX, lines: pauses.after.box.lines, description: pauses.after.label.description });
    // The labels shortened to fit their boxes (or left out), whole under the chart.
    const shortened = (
      [
        ['at the left', pauses.before],
        ['at the right', pauses.after],
      ] as const
    ).flatMap(([edge, pause]) => (pause && pause.box.lines !== pause.label.forms[0] ? [`${edge}, ${fullLabel(pause.label)}`] : []));
    const caption = shortened.length ? `Hatched, not to scale: ${shortened.join('; ')}.` : '';
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
    // A pause at an edge: two rows more, at its far end and half-way, where
    // DIR is set for the step across it (lane i / 2's axis); STEP low.
    const dirLevel = (i: number, dir: number) => laneBase(i) + (dir < 0 ? SWING : 0);
    const withPauses = (values: Float64Array, before: [number, number] | null, after: [number, number] | null) =>
      Float64Array.of(...(before ?? []), ...values, ...(after ?? []));
    const before = pauses.before;
    const after = pauses.after;
    const data: uPlot.AlignedData = [
      withPauses(withStart(x, 0, x[0]! / 2), before && [startX - beforeX, startX - beforeX / 2], after && [endX + afterX / 2, endX + afterX]),
      ...lanes.map((values, i) => {
        const isStep = i % 2 === 0;
        const axis = Math.floor(i / 2);
        return withPauses(
          withStart(values, laneBase(i), isStep ? laneBase(i) : values[0]!),
          before && (isStep ? [laneBase(i), laneBase(i)] : [dirLevel(i, before.farDir[axis]!), values[0]!]),
          after && (isStep ? [laneBase(i), laneBase(i)] : [dirLevel(i, after.farDir[axis]!), dirLevel(i, after.farDir[axis]!)]),
        );
      }),
    ];
    const xLabel = stepSeconds ? `planned instant (${unit})` : 'step';
    if (this.#chart && xLabel === this.#xLabel) {
      this.#chart.setBreaks(breaks);
      this.#chart.setCaption(caption);
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
        pickX: stepSeconds ? (at) => this.#window !== null && this.#onPick(this.#pointOfX(at)) : undefined,
        yLabel: '',
        series,
        yRange: [-0.3, count * LANE],
        legend: false,
        heightPx: count * LANE_PX + FRAME_PX,
        // A label per STEP lane and per DIR level, naming the signal and what the level means.
        yValues: (_u, splits) => splits.map((v) => labels.find((l) => Math.abs(l.at - v) < 1e-9)?.text ?? ''),
        ySplits: labels.map((l) => l.at).sort((a, b) => a - b),
        xBreaks: breaks,
        caption,
        onResize: () => this.#resized(),
      },
      data,
      this.#onPick,
    );
  }
}
