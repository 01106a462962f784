// Where the G-code timing diagram draws STEP pulses (web/gcode/pulse-edges.ts).
// Steps 10 ms apart, a 1 s dwell, then 10 ms apart again: each pulse is drawn
// 5 ms wide, half the 10 ms gap beside it; the pulse before the dwell was
// drawn high for half a second (half-way to the next step), the one after it
// as wide as its neighbours already. DIR is set for a step half-way from the
// step before, as the VCD sets it.
import { describe, expect, it } from 'vitest';
import { drawnFromZero, pulseEdges } from '../web/gcode/pulse-edges.js';

describe('pulse edges of the timing diagram', () => {
  it('draws each pulse half the shorter gap beside it wide, so a dwell does not hold STEP high', () => {
    const times = Float64Array.from([0, 0.01, 0.02, 1.02, 1.03]);
    const x = Array.from(pulseEdges(times), (v) => Math.round(v * 1e6) / 1e6);
    // Each step: its rise, its fall and the midpoint to the next step (where DIR is set for it, as the VCD does).
    expect(x).toEqual([0, 0.005, 0.005, 0.01, 0.015, 0.015, 0.02, 0.025, 0.52, 1.02, 1.025, 1.025, 1.03, 1.035, 1.035, 1.04]);
  });

  it('gives a single step 1 ms and the right edge one gap past the last', () => {
    expect(Array.from(pulseEdges(Float64Array.from([2])), (v) => Math.round(v * 1e6) / 1e6)).toEqual([2, 2.0005, 2.0005, 2.001]);
    expect(Array.from(pulseEdges(new Float64Array(0)))).toEqual([0]);
  });

  it('draws a first window from 0 s when the wait before its steps is no longer than they take', () => {
    // From rest: 50 ms before steps spread over 250 ms.
    expect(drawnFromZero(Float64Array.from([0.05, 0.1, 0.3]), true)).toBe(true);
    // After a 2 s dwell, steps over 100 ms: drawn from the first step.
    expect(drawnFromZero(Float64Array.from([2, 2.05, 2.1]), true)).toBe(false);
    // A window later in the program, or starting at 0 s.
    expect(drawnFromZero(Float64Array.from([0.05, 0.1, 0.3]), false)).toBe(false);
    expect(drawnFromZero(Float64Array.from([0, 0.1]), true)).toBe(false);
  });
});
