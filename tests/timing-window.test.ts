// Which steps the G-code timing diagram draws (web/gcode/timing-window.ts).
// A program of 160 steps 1 ms apart with a 2 s dwell between steps 79 and
// 80 (as G1 X2, G4 P2, G1 X4 at 40 steps/mm would be, less the ramps): a
// window of 60 steps counted around the current one spanned the dwell, 2 s,
// and pressed its 60 ms of pulses into bars at its edges.
import { describe, expect, it } from 'vitest';
import { runGcode } from '../web/core/index.js';
import { drawnFromZero, pulseEdges } from '../web/gcode/pulse-edges.js';
import { neededSteps, PAUSE_FACTOR, stepWindow, windowHolds } from '../web/gcode/timing-window.js';

const STEPS = 160;
const TICKS = 60;
/** Step k's instant: 1 ms apart from 10 ms, the second move's 2.05 s after the first's last step. */
const dwellAt = (k: number) => 0.01 + k * 1e-3 + (k >= 80 ? 2.05 : 0);
const times = Float64Array.from({ length: STEPS }, (_, k) => dwellAt(k));

/** stepWindow for point p, given the instants of the steps neededSteps asks for (as the diagram fetches them), and the program's end. */
function windowFor(p: number, all: Float64Array = times, ticks = TICKS, endSeconds = all[all.length - 1]) {
  const { fromStep, toStep } = neededSteps(p, ticks, all.length);
  return stepWindow(p, ticks, all.length, fromStep, all.subarray(fromStep, toStep), endSeconds);
}

describe('the timing diagram window', () => {
  it('ends at a dwell after the current step, with the steps before it, and starts at it once past', () => {
    // Point 80, the last step before the dwell (step 79): the 60 steps up to it, the dwell at the right edge.
    expect(windowFor(80)).toEqual({ fromStep: 20, toStep: 80, pauseBefore: null, pauseAfter: { fromSeconds: times[79], toSeconds: times[80] } });
    // Point 81, the first step after it: 60 steps from it, the dwell at the left edge.
    expect(windowFor(81)).toEqual({ fromStep: 80, toStep: 140, pauseBefore: { fromSeconds: times[79], toSeconds: times[80] }, pauseAfter: null });
    // Further from it, the window counted in steps (a third before) stops at it all the same.
    expect(windowFor(50)).toMatchObject({ fromStep: 20, toStep: 80, pauseBefore: null });
    expect(windowFor(100)).toMatchObject({ fromStep: 80, toStep: 140, pauseAfter: null });
    // Far enough that the window counted in steps does not reach it: that window, no pause.
    expect(windowFor(30)).toEqual({ fromStep: 10, toStep: 70, pauseBefore: null, pauseAfter: null });
    expect(windowFor(150)).toEqual({ fromStep: 100, toStep: 160, pauseBefore: null, pauseAfter: null });
  });

  it('keeps the window counted in steps when no gap is a pause, and for a trace', () => {
    const even = Float64Array.from({ length: STEPS }, (_, k) => k * 1e-3);
    expect(windowFor(80, even)).toEqual({ fromStep: 60, toStep: 120, pauseBefore: null, pauseAfter: null });
    expect(stepWindow(80, TICKS, STEPS, 0, null)).toEqual({ fromStep: 60, toStep: 120, pauseBefore: null, pauseAfter: null });
    // Steps slowing gradually, each gap 5 % longer than the one before: none ten times its neighbours', no
    // pause. But 60 of them span 1.05^59 = 17.8 times their first gap at the end, 353 of it in all (pulseEdges'
    // right edge with it), where 2 × 60 leave it half a tick: the window holds 39, Σ 1.05^j for j < 38 and
    // 1.05^37 again, 113.8 first gaps (40 span 120.5), from step 60 as the counted window, the step a third in.
    const slowing = Float64Array.from({ length: STEPS }, (_, k) => (1.05 ** k - 1) * 1e-3);
    expect(windowFor(80, slowing)).toEqual({ fromStep: 60, toStep: 99, pauseBefore: null, pauseAfter: null });
    // All at one instant (a move that does not take time): nothing to compare a pause with.
    expect(windowFor(5, new Float64Array(20))).toEqual({ fromStep: 0, toStep: 20, pauseBefore: null, pauseAfter: null });
  });

  it('tells a pause by the spacing around the current step: ten times it', () => {
    // Steps 1 ms apart with one gap of 9 ms and one of 11 ms: the window ends at the second, 60 steps up to it.
    const gaps = Array.from({ length: STEPS - 1 }, (_, k) => (k === 70 ? 9e-3 : k === 100 ? 11e-3 : 1e-3));
    const uneven = Float64Array.from({ length: STEPS }, (_, k) => gaps.slice(0, k).reduce((a, b) => a + b, 0));
    expect(PAUSE_FACTOR).toBe(10);
    expect(windowFor(80, uneven)).toMatchObject({ fromStep: 41, toStep: 101, pauseBefore: null, pauseAfter: { fromSeconds: uneven[100], toSeconds: uneven[101] } });
    // A slow move between fast ones, and the current step in it: its own spacing is the measure, the fast
    // steps each side 50 times faster, cut off as at a pause (step 90 comes a slow step after 89).
    const slowMiddle = Float64Array.from({ length: STEPS }, (_, k) => (k < 70 ? k * 1e-3 : k < 90 ? 0.07 + (k - 70) * 0.05 : 1.07 + (k - 90) * 1e-3));
    expect(windowFor(80, slowMiddle)).toEqual({
      fromStep: 70,
      toStep: 91,
      pauseBefore: { fromSeconds: slowMiddle[69], toSeconds: slowMiddle[70], faster: true },
      pauseAfter: { fromSeconds: slowMiddle[90], toSeconds: slowMiddle[91], faster: true },
    });
    // From a fast step, the slow ones after it are a pause.
    expect(windowFor(60, slowMiddle)).toMatchObject({ fromStep: 11, toStep: 71, pauseAfter: { fromSeconds: slowMiddle[70], toSeconds: slowMiddle[71] } });
  });

  it('ends at the steps of a much faster move, with the slow steps before it, and starts at them after a fast one', () => {
    // F60 then F3000 at 80 steps/mm, 1000 mm/s²: 80 steps 12.5 ms apart (1 mm/s), then the fast move's
    // speeding up from 1 mm/s, √(1 + 25 j) mm/s j steps in, to 50 mm/s (0.25 ms a step).
    const speed = (j: number) => Math.min(50, Math.sqrt(1 + 25 * j));
    const gaps = Array.from({ length: STEPS - 1 }, (_, k) => (k < 79 ? 12.5e-3 : 1 / 80 / ((speed(k - 79) + speed(k - 78)) / 2)));
    const slowFast = Float64Array.from({ length: STEPS }, (_, k) => gaps.slice(0, k).reduce((a, b) => a + b, 0));
    // Its steps come over ten times faster than the slow ones from step 84 on (the gap after step 83).
    expect(gaps.findIndex((gap) => gap < 1.25e-3)).toBe(83);
    // Points 78 and 80, among the slow move's last steps (point 80 its last): the window counted in steps
    // ran 37 steps into the fast move, 29 ms of them beside 275 ms of slow steps. Now it ends where the
    // fast move starts, after step 79: the spacing of the steps past it is under a tenth of 12.5 ms,
    // though its first gaps (4.1 to 1.3 ms) are not, which are not left pressed at the edge. The steps
    // lost there are the slow ones before.
    for (const p of [78, 80]) {
      expect(windowFor(p, slowFast), `point ${p}`).toEqual({
        fromStep: 20,
        toStep: 80,
        pauseBefore: null,
        pauseAfter: { fromSeconds: slowFast[79], toSeconds: slowFast[80], faster: true },
      });
    }
    // Reversed, the fast move first: from a slow step after it, the window starts at the cut.
    const fastSlow = slowFast.map((t) => slowFast[STEPS - 1]! - t).reverse();
    expect(windowFor(STEPS - 78, fastSlow)).toMatchObject({ fromStep: STEPS - 80, toStep: STEPS - 20, pauseBefore: { faster: true }, pauseAfter: null });
  });

  describe('beside a move 2 to 10 times faster, G1 X1 F60 then G1 X2 at 2 to 10 times the feed', () => {
    // 80 steps/mm and 10,000 mm/s² (the speed changes within a step): 80 steps 12.5 ms apart, then 80 steps
    // 12.5/r ms apart (the first a little later, the fast move starting at the slow one's speed), from
    // the core's planner. At 3 to 9 times (under PAUSE_FACTOR, no cut) the window counted in steps drew
    // both moves at a scale where the fast pulses were a third to a ninth of a tick apart, pressed into
    // a bar (2 px at the page's 14 px a tick). Now no window draws a gap under half a tick: where the
    // counted one would, the window holds fewer steps, the most that leave each pulse apart.
    async function program(r: number, stepsPerMm = 80) {
      const p = await runGcode(`G1 X1 F60\nG1 X2 F${60 * r}\n`, { stepsPerMm, acceleration: 10000, maxRate: 6000 });
      const all = p.stepTimes(0, p.trace.steps);
      p.free();
      return all;
    }
    /** The narrowest gap drawn in window w, in ticks of a plot TICKS ticks wide spanning the window as pulseEdges draws it. */
    function narrowestTicks(all: Float64Array, w: { fromStep: number; toStep: number }): number {
      const drawn = all.subarray(w.fromStep, w.toStep);
      const x = pulseEdges(drawn);
      const gaps = Array.from(drawn.subarray(1), (t, i) => t - drawn[i]!);
      return (Math.min(...gaps) / (x[x.length - 1]! - x[0]!)) * TICKS;
    }

    for (const r of [2, 3, 5, 9]) {
      it(`draws both moves at ${r} times, each gap at least half a tick`, async () => {
        const all = await program(r);
        expect(all.length).toBe(160);
        // The fast move's steps, from the core: 12.5/r ms apart.
        expect((all[120]! - all[119]!) * r).toBeCloseTo(12.5e-3, 9);
        for (let p = 0; p <= 160; p++) {
          const w = windowFor(p, all);
          const c = Math.max(0, p - 1);
          expect([w.fromStep <= c, c < w.toStep, w.pauseBefore, w.pauseAfter], `point ${p}`).toEqual([true, true, null, null]);
          expect(narrowestTicks(all, w), `point ${p}: ${w.fromStep}..${w.toStep}`).toBeGreaterThanOrEqual(0.5);
        }
        // At the slow move's last step and the fast one's first, steps of both, and the current one at least
        // an eighth of the window (7 steps) from either edge, where windowHolds keeps it.
        for (const p of [80, 81]) {
          const w = windowFor(p, all);
          expect([p - 1 - w.fromStep >= 7, w.toStep - p >= 7], `point ${p}: ${w.fromStep}..${w.toStep}`).toEqual([true, true]);
          expect(windowHolds(w, p, TICKS, 160, true), `point ${p}`).toBe(true);
        }
        // At twice the speed the counted windows leave every gap half a tick already: they are kept.
        if (r === 2) for (let p = 0; p <= 160; p++) expect(windowFor(p, all), `point ${p}`).toMatchObject({ fromStep: Math.min(Math.max(0, p - 20), 100), toStep: Math.min(Math.max(0, p - 20), 100) + 60 });
      });
    }

    it('is cut at 10 times, where the fast move starts, as at a pause, and draws each gap half a tick apart', async () => {
      const all = await program(10);
      // At the slow move's last step: its steps up to the cut, the faster steps past it.
      expect(windowFor(80, all)).toEqual({ fromStep: 20, toStep: 80, pauseBefore: null, pauseAfter: { fromSeconds: all[79], toSeconds: all[80], faster: true } });
      for (let p = 0; p <= 160; p++) expect(narrowestTicks(all, windowFor(p, all)), `point ${p}`).toBeGreaterThanOrEqual(0.5);
      // At 160 steps/mm the fast steps' spacing rounds a little over a tenth of the slow ones' (the window
      // was not cut there, but drew steps 152..207 of both): ten times is ten times, to a rounding.
      const fine = await program(10, 160);
      expect(windowFor(160, fine)).toEqual({ fromStep: 100, toStep: 160, pauseBefore: null, pauseAfter: { fromSeconds: fine[159], toSeconds: fine[160], faster: true } });
    });
  });

  it("shows the wait before the program's first step as a pause where it is not drawn from 0 s", () => {
    // A 2 s dwell first: steps from 2.01 s, 1 ms apart.
    const late = Float64Array.from({ length: STEPS }, (_, k) => 2.01 + k * 1e-3);
    expect(windowFor(0, late)).toEqual({ fromStep: 0, toStep: 60, pauseBefore: { fromSeconds: 0, toSeconds: 2.01 }, pauseAfter: null });
    expect(windowFor(1, late)).toMatchObject({ pauseBefore: { fromSeconds: 0, toSeconds: 2.01 } });
    // From rest, the first steps come slowly (s = ½at²): drawn from 0 s, no pause. Drawn from 0 s, their span
    // is from 0 s: 60 steps, 0.05·√60 s and their last gap again, 0.3905 s, of which the last gap, 0.05·(√60 − √59)
    // = 3.24 ms, came to 6.97 px of 60 ticks' 840 (the span was taken from the first step): 59 steps.
    const fromRest = Float64Array.from({ length: STEPS }, (_, k) => 0.05 * Math.sqrt(k + 1));
    expect(windowFor(0, fromRest)).toEqual({ fromStep: 0, toStep: 59, pauseBefore: null, pauseAfter: null });
  });

  describe("beside a move 3 and 5 times faster, with the pauses' boxes drawn", () => {
    // G1 X1 F60, G1 X1.075 at 3 and 5 times the feed, G4 P2, at 80 steps/mm and 10,000 mm/s²: 80 steps 12.5 ms
    // apart, 6 steps 12.5/r ms apart, the program ending 2 s after its last: a window up to that step ends at
    // the dwell. Over the page's default plot, 174 px for 12 ticks, the dwell's box takes 58 px (its label's
    // widest word, '+2.000 s'), and as much for a box before; the window was chosen for 12 ticks' whole width,
    // 168 px, which left the steps' narrowest gap 5.2 px of the 116 px they get (3 and 5 times, at points 76
    // and 80: steps 74..85 and 76..85, 6 and 4 slow ones beside the 6 fast).
    const widths = { plotPx: 174, pausesPx: (before: boolean, after: boolean) => ({ beforePx: before ? 58 : 0, afterPx: after ? 58 : 0 }) };
    const ticks = 12;
    for (const r of [3, 5]) {
      it(`at ${r} times, draws every gap at least half a tick of the width the steps get`, async () => {
        const p = await runGcode(`G1 X1 F60\nG1 X1.075 F${60 * r}\nG4 P2\n`, { stepsPerMm: 80, acceleration: 10000, maxRate: 6000 });
        const all = p.stepTimes(0, p.trace.steps);
        const end = p.durationSeconds;
        p.free();
        expect(all.length).toBe(86);
        expect(end - all[85]!).toBeCloseTo(2, 9);
        let withPause = 0;
        for (let point = 0; point <= 86; point++) {
          const { fromStep, toStep } = neededSteps(point, ticks, 86);
          const w = stepWindow(point, ticks, 86, fromStep, all.subarray(fromStep, toStep), end, widths);
          const c = Math.max(0, point - 1);
          expect([w.fromStep <= c, c < w.toStep], `point ${point}`).toEqual([true, true]);
          // As the diagram draws it: the steps' span (pulseEdges' right edge; from 0 s where drawn from 0 s)
          // over the plot less the boxes of the pauses drawn.
          const drawn = all.subarray(w.fromStep, w.toStep);
          const x = pulseEdges(drawn);
          const spanSeconds = x[x.length - 1]! - (drawnFromZero(drawn, w.fromStep === 0) ? 0 : x[0]!);
          const stepsPx = widths.plotPx - (w.pauseBefore ? 58 : 0) - (w.pauseAfter ? 58 : 0);
          const gaps = Array.from(drawn.subarray(1), (t, i) => t - drawn[i]!);
          const narrowestPx = (Math.min(...gaps) / spanSeconds) * stepsPx;
          expect(narrowestPx, `point ${point}: ${w.fromStep}..${w.toStep}`).toBeGreaterThanOrEqual(7);
          if (w.pauseAfter) withPause++;
        }
        // The windows up to the last step end at the dwell, with steps of both moves.
        expect(withPause).toBeGreaterThan(0);
        const { fromStep, toStep } = neededSteps(86, ticks, 86);
        const last = stepWindow(86, ticks, 86, fromStep, all.subarray(fromStep, toStep), end, widths);
        expect(last).toMatchObject({ toStep: 86, pauseAfter: { fromSeconds: all[85], toSeconds: end } });
        expect(last.fromStep).toBeLessThan(80);
      });
    }
  });

  it("ends at a dwell after the program's last step, to the program's end", () => {
    // G1 X2, G4 P2: the steps of the first move alone, the program ending 2 s after its last.
    const first = times.subarray(0, 80);
    const end = first[79]! + 2;
    expect(windowFor(80, first, TICKS, end)).toEqual({ fromStep: 20, toStep: 80, pauseBefore: null, pauseAfter: { fromSeconds: first[79], toSeconds: end } });
    // A window away from the last step does not reach it.
    expect(windowFor(30, first, TICKS, end)).toMatchObject({ toStep: 70, pauseAfter: null });
    // Ending at the last step, or a wait after it too short for a pause (under ten times the spacing): none.
    expect(windowFor(80, first)).toMatchObject({ pauseAfter: null });
    expect(windowFor(80, first, TICKS, first[79]! + 9e-3)).toMatchObject({ pauseAfter: null });
  });

  it('gives a program of one step its waits as pauses too: the dwell after it, and the wait before it', async () => {
    // G1 X1 F60 at 1 step/mm, G4 P2: the one step when the move ends (1 mm/s, ramps at Grbl's 10 mm/s²), the
    // program 2 s later. With no gap to give a spacing the window had no pause, and the diagram ended 1 ms
    // after the step (pulseEdges). Its scale is that 1 ms now: the waits either side of it are pauses.
    const program = await runGcode('G1 X1 F60\nG4 P2\n', { stepsPerMm: 1 });
    const [step] = program.stepTimes(0, 1);
    const end = program.durationSeconds;
    // 1 mm/s reached in 0.1 s over 0.05 mm, 0.9 mm at it, 0.1 s to stop: 1.1 s.
    expect(program.trace.steps).toBe(1);
    expect(step).toBeCloseTo(1.1, 12);
    expect(end - step!).toBeCloseTo(2, 12);
    for (const p of [0, 1]) {
      expect(windowFor(p, program.stepTimes(0, 1), TICKS, end), `point ${p}`).toEqual({
        fromStep: 0,
        toStep: 1,
        pauseBefore: { fromSeconds: 0, toSeconds: step },
        pauseAfter: { fromSeconds: step, toSeconds: end },
      });
    }
    // Ending at its step (no dwell), or 5 ms after it (under ten times the 1 ms drawn after it): no pause after it.
    expect(windowFor(1, program.stepTimes(0, 1), TICKS, step)).toMatchObject({ pauseAfter: null });
    expect(windowFor(1, program.stepTimes(0, 1), TICKS, step! + 5e-3)).toMatchObject({ pauseAfter: null });
    program.free();
  });

  it('holds while the current step is in it, away from an edge with steps past it', () => {
    const before = windowFor(80);
    // Up to the dwell at its right edge, and back 45 steps, it holds; past the dwell it does not.
    for (const p of [30, 40, 60, 80]) expect(windowHolds(before, p, TICKS, STEPS, true), `point ${p}`).toBe(true);
    expect(windowHolds(before, 81, TICKS, STEPS, true)).toBe(false);
    // Within an eighth (7 steps) of its left edge, past which there are steps: a new window.
    expect(windowHolds(before, 27, TICKS, STEPS, true)).toBe(false);
    const after = windowFor(81);
    expect(windowHolds(after, 81, TICKS, STEPS, true)).toBe(true);
    expect(windowHolds(after, 80, TICKS, STEPS, true)).toBe(false);
    expect(windowHolds(after, 134, TICKS, STEPS, true)).toBe(false);
    // The program's edges have no steps past them.
    expect(windowHolds(windowFor(0), 1, TICKS, STEPS, true)).toBe(true);
    expect(windowHolds(windowFor(160), 160, TICKS, STEPS, true)).toBe(true);
    // A trace's window of ticks follows the point, an eighth from its edges.
    const ticks = stepWindow(80, TICKS, STEPS, 0, null);
    expect(windowHolds(ticks, 67, TICKS, STEPS, false)).toBe(true);
    expect(windowHolds(ticks, 66, TICKS, STEPS, false)).toBe(false);
  });
});
