// The page's time units (web/gcode/time-format.ts): the G-code timing
// diagram's axis is in ms, or in µs when the steps it shows span less than a
// millisecond (issue 14: "the timing diagram's axis is in ms or µs"). The
// diagram shows a step every 14 px, at least 12 (timing-diagram.ts): some
// dozens a window. The spans below are 50 steps' 49 gaps at a step rate:
// 8 kHz (X at 100 mm/s and 80 steps/mm) and 100 kHz.
import { describe, expect, it } from 'vitest';
import { formatSeconds, formatSecondsBrief, timeUnit } from '../web/gcode/time-format.js';

describe('time units for people', () => {
  it('puts a window of steps on an ms axis, or a µs one under a millisecond', () => {
    expect(timeUnit(49 / 8000)).toEqual({ unit: 'ms', perSecond: 1e3 });
    expect(timeUnit(49 / 100_000)).toEqual({ unit: 'µs', perSecond: 1e6 });
    // The boundary: exactly 1 ms is still read in ms.
    expect(timeUnit(1e-3).unit).toBe('ms');
    expect(timeUnit(0.999e-3).unit).toBe('µs');
    // A millisecond as a difference of two instants: (t + 1e-3) - t.
    expect(timeUnit(12.345 + 1e-3 - 12.345).unit).toBe('ms');
    expect(12.345 + 1e-3 - 12.345).toBeLessThan(1e-3);
  });

  it('writes an instant in s, ms or µs', () => {
    expect(formatSeconds(3)).toBe('3.000 s');
    expect(formatSeconds(0)).toBe('0.000 s');
    expect(formatSeconds(Math.sqrt((2 * 5) / 100))).toBe('316.228 ms');
    expect(formatSeconds(1 / 8000)).toBe('125.0 µs');
  });

  it('writes a time briefly, to two significant digits in the same unit', () => {
    // The timing diagram's pause label in a narrow box: "+2 s" for "+2.000 s".
    expect(formatSecondsBrief(2)).toBe('2 s');
    expect(formatSecondsBrief(1.1)).toBe('1.1 s');
    expect(formatSecondsBrief(0.004099)).toBe('4.1 ms');
    expect(formatSecondsBrief(1 / 8000)).toBe('130 µs');
    expect(formatSecondsBrief(0)).toBe('0 s');
    // Rounded up into the next unit, read in it (formatSeconds: "999.600 ms").
    expect(formatSecondsBrief(0.9996)).toBe('1 s');
    expect(formatSecondsBrief(0.0009996)).toBe('1 ms');
  });
});
