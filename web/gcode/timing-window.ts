/**
 * Which steps the timing diagram (timing-diagram.ts) draws around the
 * current one. The window is counted in steps, about a third of them before
 * the current one, but a program's steps are drawn at their instants: a
 * pause inside the window (a G4 dwell, a stop, the one slow step before a
 * fast move) made it span seconds while the steps beside the pause take
 * milliseconds, and pressed their pulses into two bars at its edges. So the
 * window ends (or starts) at a pause much longer than the steps' own spacing
 * around the current step, and the steps it loses there are taken on the
 * other side; the diagram shows the pause at that edge, labelled. Stepping
 * past it moves the window to its other side. A dwell after the program's
 * last step is a pause at the window's end too, to the program's end. The
 * steps of a much faster move are pressed the same way beside slow ones
 * (drawn at the slow steps' spacing, a fast move's steps were a bar at the
 * window's edge): the window is cut where they start, as at a pause. A move
 * less than that faster (3 to 9 times) is drawn beside the slow one, in a
 * window of fewer steps where the counted one would draw a gap under half a
 * tick (NARROWEST_GAP_TICKS) of the width the steps get, the plot's less
 * the boxes of the pauses at its edges (PlotWidths, which the diagram
 * draws them over): the most steps around the current one that leave each
 * pulse apart from the next.
 */
import { drawnFromZero, LONE_STEP_SECONDS } from './pulse-edges.js';

/**
 * A gap between two steps is a pause when it is longer than this many times
 * the steps' own spacing around the current step: a window of 40 steps at
 * that spacing then gives a pause at least a fifth of its width, pressing
 * the steps beside it by as much, which is where a pulse starts to blur.
 * The window is cut alike where the steps past a gap come this many times
 * faster than the current step's: at its scale they were under a tenth of a
 * tick apart.
 */
export const PAUSE_FACTOR = 10;

/**
 * A tick's width, CSS pixels: the diagram shows as many steps as its plot
 * has ticks, so that a STEP pulse (half a tick) stays apart from the next.
 */
export const TICK_PX = 14;

/**
 * The narrowest gap between two steps drawn, in ticks (TICK_PX each) of the
 * width the steps get (the plot's, less the boxes of the pauses drawn at its
 * edges, stepsWidthPx): a STEP pulse is drawn half its gap wide, so half
 * a tick leaves its rise and fall 3.5 px apart; where a move 3 to 9 times
 * faster came beside a slow one's steps (under PAUSE_FACTOR, no cut) its
 * pulses were a third to a tenth of a tick apart, a bar. A window of steps
 * speeding up from rest, whose gaps shrink as 1/√k (s = ½at²), spans about
 * twice its count in its last gap, so it stays whole at half a tick; one
 * across a stop, slowing to rest and speeding up again, gives up a few
 * steps (at most 8 of 90 in the sample programs at 80 steps/mm).
 */
const NARROWEST_GAP_TICKS = 0.5;

/** The widths of the boxes of the pauses drawn before and after a window's steps, CSS pixels: 0 where none is drawn. */
export interface PauseBoxesPx {
  beforePx: number;
  afterPx: number;
}

/**
 * The widths a window of steps is drawn over, CSS pixels: the plot's, and
 * the boxes of the pauses it can start and end at (edgePauses'), by which of
 * them the window is drawn with: the boxes are sized for the pauses drawn
 * together, so that a pause drawn alone can have a wider box (a fuller
 * label) than beside another.
 */
export interface PlotWidths {
  plotPx: number;
  pausesPx(pauseBefore: boolean, pauseAfter: boolean): PauseBoxesPx;
}

/**
 * The width the steps drawn get, CSS pixels: the plot's less the boxes of
 * the pauses drawn before and after them; a tick's at least, for boxes
 * wider than the plot (the timing diagram's take 70% of it at most, their
 * labels shortened to fit: PAUSES_SHARE).
 */
export function stepsWidthPx(widths: PlotWidths, pauseBefore: boolean, pauseAfter: boolean): number {
  const { beforePx, afterPx } = widths.pausesPx(pauseBefore, pauseAfter);
  return Math.max(TICK_PX, widths.plotPx - beforePx - afterPx);
}

/** Steps each side of a step whose gaps, with its own, have the median that is the steps' own spacing there (one long gap among them does not move it). */
const SPACING_GAPS = 4;

/** A stretch with no step, between two instants, seconds. */
export interface Pause {
  fromSeconds: number;
  toSeconds: number;
  /** Set when the gap is no pause but where the steps past it start to come PAUSE_FACTOR times faster than the current step's, or more: the window is cut there all the same. */
  faster?: true;
}

export interface StepWindow {
  /** The steps drawn: fromStep..toStep. */
  fromStep: number;
  toStep: number;
  /** The pause the window starts at: from the instant of step fromStep - 1 (0 s before the program's first step) to that of step fromStep. */
  pauseBefore: Pause | null;
  /** The pause the window ends at: from the instant of step toStep - 1 to that of step toStep (to the program's end after its last step). */
  pauseAfter: Pause | null;
}

/** The window counted in steps alone: `ticks` steps, a third before point `pointIndex`, within the program's `steps`. */
function countedWindow(pointIndex: number, ticks: number, steps: number): { fromStep: number; toStep: number } {
  const fromStep = Math.max(0, Math.min(pointIndex - Math.floor(ticks / 3), steps - ticks));
  return { fromStep, toStep: Math.min(steps, fromStep + ticks) };
}

/**
 * The step whose instant point `pointIndex` is reached at (step k reaches
 * point k + 1; point 0, the start, is the first step's window).
 */
function currentStep(pointIndex: number, steps: number): number {
  return Math.max(0, Math.min(steps - 1, pointIndex - 1));
}

/**
 * The steps whose instants `stepWindow` needs for point `pointIndex`: any
 * window of at most `ticks` steps holding its step, one step more on each
 * side, to see a pause at either edge, and the steps past that whose
 * spacing tells whether a faster move starts there (spacingAround's, about
 * the (SPACING_GAPS + 1)th step past it).
 */
export function neededSteps(pointIndex: number, ticks: number, steps: number): { fromStep: number; toStep: number } {
  const c = currentStep(pointIndex, steps);
  const past = 2 * SPACING_GAPS + 1;
  return { fromStep: Math.max(0, c - ticks - past), toStep: Math.min(steps, c + ticks + 1 + past) };
}

/**
 * The cuts nearest the current step of point `pointIndex` (stepWindow's
 * arguments): the window stays between them, steps lo..hi at most, and the
 * pauses it can start and end at there.
 */
function cutsAround(pointIndex: number, ticks: number, steps: number, firstStep: number, times: Float64Array, endSeconds: number | undefined) {
  const at = (k: number) => times[k - firstStep]!;
  const first = firstStep;
  const last = firstStep + times.length - 1;
  const c = currentStep(pointIndex, steps);
  // A lone step (or steps all at one instant) has no gap to space it: its scale is the time the
  // diagram runs after it, so that the wait before it and a dwell after it are pauses as other steps'.
  const spacingSeconds = spacingAround(times, c - firstStep) || LONE_STEP_SECONDS;
  // The gap after step k; NaN past the steps fetched, which no comparison cuts at.
  const gapAt = (k: number) => (k >= first && k + 1 <= last ? at(k + 1) - at(k) : Number.NaN);
  const pauseAt = (k: number) => gapAt(k) > PAUSE_FACTOR * spacingSeconds;
  // A faster move past the gap after step k, on side `side` of it (+1 after, -1 before): the spacing of
  // the steps past it (spacingAround the (SPACING_GAPS + 1)th) PAUSE_FACTOR times shorter than the current
  // step's or more (to a rounding: F60 then F600 is ten times faster, whichever way its instants round),
  // and the gap itself under half of it, the change under way there. A single gap that short comes after
  // the first steps of a move speeding up from the slow one's speed, which the window would have kept,
  // pressed, at its edge.
  const fasterAt = (k: number, side: 1 | -1) =>
    gapAt(k) < spacingSeconds / 2 &&
    PAUSE_FACTOR * spacingAround(times, (side > 0 ? k + 1 + SPACING_GAPS : k - SPACING_GAPS) - firstStep) <= spacingSeconds * (1 + 1e-9);
  const cutAt = (k: number, side: 1 | -1) => pauseAt(k) || fasterAt(k, side);
  const cut = (k: number): Pause => (pauseAt(k) ? { fromSeconds: at(k), toSeconds: at(k + 1) } : { fromSeconds: at(k), toSeconds: at(k + 1), faster: true });
  let lo = c;
  while (lo > first && lo > c - ticks + 1 && !cutAt(lo - 1, -1)) lo--;
  let hi = c;
  while (hi < last && hi < c + ticks - 1 && !cutAt(hi, 1)) hi++;
  // The steps between lo and hi have no cut between them: a window starts at a pause only at lo
  // (the wait before the program's first step when lo is 0, where it is not drawn from 0 s), and
  // ends at one only after hi (a dwell after the program's last step when that is hi).
  let before: EdgePause | null = null;
  if (lo > 0 && cutAt(lo - 1, -1)) before = { pause: cut(lo - 1), farStep: lo - 1 };
  else if (lo === 0 && at(0) > PAUSE_FACTOR * spacingSeconds) before = { pause: { fromSeconds: 0, toSeconds: at(0) }, farStep: -1 };
  let after: EdgePause | null = null;
  if (hi + 1 < steps && cutAt(hi, 1)) after = { pause: cut(hi), farStep: hi + 1 };
  else if (hi + 1 === steps && endSeconds !== undefined && endSeconds - at(steps - 1) > PAUSE_FACTOR * spacingSeconds) {
    after = { pause: { fromSeconds: at(steps - 1), toSeconds: endSeconds }, farStep: steps };
  }
  return { at, c, lo, hi, before, after };
}

/** A pause a window can start or end at, and the step on its far side: -1 before the program's first step, the program's steps after its last. */
export interface EdgePause {
  pause: Pause;
  farStep: number;
}

/**
 * The pauses a window for point `pointIndex` can start and end at (one at
 * most each side; stepWindow's arguments): the diagram labels them, and
 * sizes their boxes (PlotWidths) before the window is chosen with them.
 * None for a trace.
 */
export function edgePauses(pointIndex: number, ticks: number, steps: number, firstStep: number, times: Float64Array | null, endSeconds?: number): { before: EdgePause | null; after: EdgePause | null } {
  if (!times || steps === 0) return { before: null, after: null };
  const { before, after } = cutsAround(pointIndex, ticks, steps, firstStep, times, endSeconds);
  return { before, after };
}

/**
 * The steps to draw for point `pointIndex`, at most `ticks` of a program of
 * `steps`, and the pauses it starts or ends at. `times`: the instants of
 * steps firstStep..firstStep + times.length, seconds (at least
 * `neededSteps`); null for a trace (one tick a step, no pause): the window
 * counted in steps. `endSeconds`: the program's end (its duration), later
 * than its last step's instant when it ends with a dwell. `widths`: what
 * the steps are drawn over (by default `ticks` ticks, no pause box), where
 * no gap between two steps may come under NARROWEST_GAP_TICKS of a tick.
 */
export function stepWindow(
  pointIndex: number,
  ticks: number,
  steps: number,
  firstStep: number,
  times: Float64Array | null,
  endSeconds?: number,
  widths: PlotWidths = { plotPx: ticks * TICK_PX, pausesPx: () => ({ beforePx: 0, afterPx: 0 }) },
): StepWindow {
  const counted = countedWindow(pointIndex, ticks, steps);
  if (!times || steps === 0) return { ...counted, pauseBefore: null, pauseAfter: null };
  const { at, c, lo, hi, before, after } = cutsAround(pointIndex, ticks, steps, firstStep, times, endSeconds);
  const drawn = (from: number, to: number) => times.subarray(from - firstStep, to - firstStep);
  // The pauses window from..to - 1 is drawn with: its first steps drawn from 0 s instead of after a pause.
  const pausesOf = (from: number, to: number) => {
    const idle = drawnFromZero(drawn(from, to), from === 0);
    return { idle, before: from === lo && before !== null && !idle ? before.pause : null, after: to === hi + 1 && after !== null ? after.pause : null };
  };
  /**
   * Whether steps from..to - 1, of narrowest gap `narrowestSeconds` (none for steps with no gap between
   * them), leave it NARROWEST_GAP_TICKS of a tick drawn as the diagram draws them: from their first
   * step (from 0 s when drawn so) to the last and the last gap again (pulseEdges' right edge), over
   * the plot less their pauses' boxes.
   */
  const readable = (from: number, to: number, narrowestSeconds: number) => {
    const { idle, before: pauseBefore, after: pauseAfter } = pausesOf(from, to);
    const lastGap = to - from > 1 ? at(to - 1) - at(to - 2) : 0;
    const spanSeconds = at(to - 1) - (idle ? 0 : at(from)) + lastGap;
    return spanSeconds * NARROWEST_GAP_TICKS * TICK_PX <= stepsWidthPx(widths, pauseBefore !== null, pauseAfter !== null) * narrowestSeconds;
  };
  let fromStep = Math.max(counted.fromStep, lo);
  let toStep = Math.min(counted.toStep, hi + 1);
  // The steps cut off on one side are taken on the other.
  if (toStep < counted.toStep) fromStep = Math.max(lo, toStep - ticks);
  else if (fromStep > counted.fromStep) toStep = Math.min(hi + 1, fromStep + ticks);
  // Where that window presses its narrowest gap under NARROWEST_GAP_TICKS of a tick (a move some
  // times faster than the one beside it, under PAUSE_FACTOR, or the width pauses' boxes take), another
  // between the same cuts is drawn: of the windows that are readable, one that holds its step
  // (windowHolds: it is not fetched again at once, nor its step drawn at an edge past which there are
  // steps not shown), then the one of most steps, then the one whose step is nearest a third in, as
  // the counted window's.
  if (!readable(fromStep, toStep, narrowestGap(at, fromStep, toStep))) {
    const wantBefore = c - counted.fromStep;
    const margin = edgeMargin(ticks);
    let best: { holds: boolean; steps: number; offThird: number } | null = null;
    for (let from = Math.max(lo, c - ticks + 1); from <= c; from++) {
      // Steps from..to - 1 and the narrowest gap between them, one step more at a time.
      let narrowestSeconds = Number.POSITIVE_INFINITY;
      for (let to = from + 1; to <= Math.min(hi + 1, from + ticks); to++) {
        const lastGap = to - from > 1 ? at(to - 1) - at(to - 2) : 0;
        if (lastGap > 0) narrowestSeconds = Math.min(narrowestSeconds, lastGap);
        if (to <= c || !readable(from, to, narrowestSeconds)) continue;
        const candidate = {
          holds: (c - from >= margin || from === lo) && (to - 1 - c >= margin || to === hi + 1),
          steps: to - from,
          offThird: Math.abs(c - from - wantBefore),
        };
        const better =
          !best ||
          (candidate.holds !== best.holds ? candidate.holds : candidate.steps !== best.steps ? candidate.steps > best.steps : candidate.offThird < best.offThird);
        if (better) [best, fromStep, toStep] = [candidate, from, to];
      }
    }
  }
  const { before: pauseBefore, after: pauseAfter } = pausesOf(fromStep, toStep);
  return { fromStep, toStep, pauseBefore, pauseAfter };
}

/**
 * The steps' own spacing around step index `i` of `times`, seconds: the
 * median of the gaps steps i - SPACING_GAPS..i + SPACING_GAPS are reached
 * by, those that are not 0 (steps at one instant); NaN for none. Step i's
 * own gap in the middle of them: at the last step of a slow move, reached
 * by a slow gap before four faster ones, the median is the slow move's
 * spacing (of the eight gaps about the step before, the lower median was
 * the faster move's, and its steps were drawn at that scale).
 */
function spacingAround(times: Float64Array, i: number): number {
  const gaps: number[] = [];
  for (let k = Math.max(0, i - SPACING_GAPS - 1); k < Math.min(times.length - 1, i + SPACING_GAPS); k++) {
    const gap = times[k + 1]! - times[k]!;
    if (gap > 0) gaps.push(gap);
  }
  gaps.sort((a, b) => a - b);
  // The lower median: of 9 gaps with one pause among them, a gap beside it; of fewer (the program's ends) too.
  return gaps.length === 0 ? Number.NaN : gaps[Math.floor((gaps.length - 1) / 2)]!;
}

/** The narrowest gap between steps fromStep..toStep - 1 at instants `at(k)`, seconds; gaps of 0 (steps at one instant, drawn as one) do not count: infinite for none. */
function narrowestGap(at: (k: number) => number, fromStep: number, toStep: number): number {
  let narrowestSeconds = Number.POSITIVE_INFINITY;
  for (let k = fromStep; k + 1 < toStep; k++) {
    const gap = at(k + 1) - at(k);
    if (gap > 0) narrowestSeconds = Math.min(narrowestSeconds, gap);
  }
  return narrowestSeconds;
}

/** Steps a window keeps between its current step and an edge past which there are steps to show: an eighth of it. */
function edgeMargin(ticks: number): number {
  return Math.floor(ticks / 8);
}

/**
 * Whether the window drawn still serves point `pointIndex`, without a new
 * one: its step is in it, and not within an eighth of the window of an edge
 * past which there are steps to show (a pause's edge, or the program's, has
 * none). A trace's window, counted in ticks, follows the point itself.
 */
export function windowHolds(window: StepWindow, pointIndex: number, ticks: number, steps: number, timed: boolean): boolean {
  const margin = edgeMargin(ticks);
  const { fromStep, toStep } = window;
  if (!timed) return pointIndex >= fromStep + margin && pointIndex <= fromStep + ticks - margin;
  const c = currentStep(pointIndex, steps);
  if (c < fromStep || c >= toStep) return false;
  const roomBefore = c >= fromStep + margin || window.pauseBefore !== null || fromStep === 0;
  const roomAfter = c <= toStep - 1 - margin || window.pauseAfter !== null || toStep === steps;
  return roomBefore && roomAfter;
}
