// Where the G-code timing diagram draws STEP pulses (web/gcode/pulse-edges.ts).
// Steps 10 ms apart, a 1 s dwell, then 10 ms apart again: each pulse is drawn
// 5 ms wide, half the 10 ms gap beside it; the pulse before the dwell was
// drawn high for half a second (half-way to the next step), the one after it
// as wide as its neighbours already.
import { describe, expect, it } from 'vitest';
import { pulseEdges } from '../web/gcode/pulse-edges.js';

describe('pulse edges of the timing diagram', () => {
  it('draws each pulse half the shorter gap beside it wide, so a dwell does not hold STEP high', () => {
    const times = Float64Array.from([0, 0.01, 0.02, 1.02, 1.03]);
    const x = Array.from(pulseEdges(times), (v) => Math.round(v * 1e6) / 1e6);
    expect(x).toEqual([0, 0.005, 0.01, 0.015, 0.02, 0.025, 1.02, 1.025, 1.03, 1.035, 1.04]);
  });

  it('gives a single step 1 ms and the right edge one gap past the last', () => {
    expect(Array.from(pulseEdges(Float64Array.from([2])), (v) => Math.round(v * 1e6) / 1e6)).toEqual([2, 2.0005, 2.001]);
    expect(Array.from(pulseEdges(new Float64Array(0)))).toEqual([0]);
  });
});
