// The scale rule of the issues, through the real wasm core: a 10,000,000-step
// line and a 1,000,000-step helix trace in Node holding no more than about
// 16 bytes per step, counting both the growth of wasm linear memory (which
// never shrinks, so its growth is the most the core needed at once) and
// the JS arrays read out of it; and a long G-code program holding no more
// than 200 bytes of the core's heap per line. Timings are the bench's
// business (`npm run bench`); here only the test timeout bounds them.
import { beforeAll, describe, expect, it } from 'vitest';
import { generateProgram } from '../bench/programs.js';
import { heapBytes, memoryBytes, runGcode, trace } from '../web/core/index.js';
import type { DecisionColumns } from '../web/core/index.js';
import { rejection } from './helpers.js';

/** The budget of the issues: "not more than about 16 bytes per step". */
const BYTES_PER_STEP = 16;
/** Steps read back from the middle of each path, as a page's inspector would. */
const RANGE = 10_000;

/** Wasm memory once the core is loaded, before any long trace. */
let baseline = 0;

beforeAll(async () => {
  (await trace({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1] })).free();
  baseline = memoryBytes();
  expect(baseline).toBeGreaterThan(0);
});

function bytesOf(columns: DecisionColumns): number {
  return Object.values(columns).reduce((sum, column) => sum + column.byteLength, 0);
}

describe('maxSteps is refused before anything large is allocated', () => {
  it('a line of 2^31 steps against maxSteps 10^9 costs no wasm memory', async () => {
    const before = memoryBytes();
    const error = await rejection(trace({ algorithm: 'regions', from: [-(2 ** 30), 0, 0], to: [2 ** 30, 3, 4], maxSteps: 1e9 }));
    expect(error.field).toBe('maxSteps');
    expect(memoryBytes() - before).toBeLessThan(1 << 20);
  });

  it('an arc of 3 * 10^9 steps in chords is refused from its chord lengths', async () => {
    const before = memoryBytes();
    const r = 2 ** 29;
    const error = await rejection(
      trace({
        algorithm: 'arc-segments',
        from: [r, 0, 0],
        to: [r, 0, 0],
        center: [0, 0, 0],
        segmentLength: 2 ** 20,
        maxSteps: 1e9,
      }),
    );
    expect(error.field).toBe('maxSteps');
    expect(memoryBytes() - before).toBeLessThan(1 << 20);
  });
});

describe('long paths within 16 bytes per step', () => {
  // Wasm memory is reused once freed but never returned, so each path's
  // growth is measured from the same baseline: the helix first (smaller),
  // then the line, whose growth then includes anything the helix left.

  it('a helix of 1,000,000 steps', { timeout: 120_000 }, async () => {
    // Nine turns of r = 20000 (the circle takes about 4·sqrt(2)·r = 113,000
    // steps per turn) rising 9000: the arc is the major axis.
    const t = await trace({ algorithm: 'helix', from: [20000, 0, 0], to: [20000, 0, 9000], center: [0, 0, 0], turns: 8 });
    expect(t.steps).toBeGreaterThanOrEqual(1_000_000);
    const points = t.points;
    expect(Array.from(points.subarray(points.length - 3))).toEqual([20000, 0, 9000]);
    const middle = Math.floor(t.steps / 2);
    const decisions = t.decisionsInRange(middle, middle + RANGE);
    const deviation = t.deviationInRange(middle, middle + RANGE);
    expect(decisions.arcSteps).toHaveLength(RANGE);
    // Saleem's circle rule keeps every point within 0.5 of the circle; the
    // height differs from the ideal helix's by up to about 0.5% of a turn's
    // rise (1000) for a helix that starts on an axis, as this one (about 1%
    // from other angles): the largest of sin θ/(4√2) - θ/2π is 0.0053.
    expect(Math.max(...deviation)).toBeLessThan(0.5 + 0.0054 * 1000 + 1);
    const held = points.byteLength + bytesOf(decisions) + deviation.byteLength;
    const perStep = (memoryBytes() - baseline + held) / t.steps;
    expect(perStep).toBeLessThan(BYTES_PER_STEP);
    t.free();
  });

  it('a 3D line of 10,000,000 steps', { timeout: 120_000 }, async () => {
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10_000_000, 7_000_001, 6_000_003] });
    expect(t.steps).toBe(10_000_000);
    const points = t.points;
    expect(points.length).toBe(3 * (t.steps + 1));
    expect(Array.from(points.subarray(points.length - 3))).toEqual([10_000_000, 7_000_001, 6_000_003]);
    const middle = t.steps / 2;
    const decisions = t.decisionsInRange(middle, middle + RANGE);
    const deviation = t.deviationInRange(middle, middle + RANGE);
    // Eq. (6) in closed form at the first step of the range: M from the
    // point alone (x active, |Δx| = 10^7, |Δy| = 7,000,001).
    const [x, y] = [points[3 * middle]!, points[3 * middle + 1]!];
    expect(decisions.M![0]).toBe(2 * 7_000_001 * x - 2 * 10_000_000 * y + 2 * 7_000_001 - 10_000_000);
    expect(Math.max(...deviation)).toBeLessThanOrEqual(Math.SQRT1_2);
    expect(t.metrics.maxDeviation).toBeLessThanOrEqual(Math.SQRT1_2);
    const held = points.byteLength + bytesOf(decisions) + deviation.byteLength;
    const perStep = (memoryBytes() - baseline + held) / t.steps;
    expect(perStep).toBeLessThan(BYTES_PER_STEP);
    t.free();
  });
});

describe('a 200,000-line G-code program', () => {
  it("holds at most 200 bytes of the core's heap a line, and gives all of it back when freed", { timeout: 60_000 }, async () => {
    // The bench's program (short G1 moves, a quarter arc every tenth line)
    // at its 1 step/mm: what a finished run keeps, its steps included
    // (the bound: "at most 200 bytes of retained state per source line").
    const lines = 200_000;
    const source = generateProgram(lines);
    const before = heapBytes();
    const program = await runGcode(source, { stepsPerMm: 1 });
    expect(program.errors).toEqual([]);
    expect(program.moveCount).toBe(lines - 1);
    const perLine = (heapBytes() - before) / lines;
    program.free();
    expect(perLine).toBeGreaterThan(50);
    expect(perLine).toBeLessThanOrEqual(200);
    expect(heapBytes()).toBe(before);
  });
});

describe("a G-code program's reads past the core's memory", () => {
  // A read the core made whole in its own memory before handing it over
  // trapped when that memory had no room ("RuntimeError: unreachable",
  // naming nothing): the instants of 540,000,000 steps are 4.32 GB, past the
  // 4 GiB a wasm memory holds. Run last: the program's 1.1 GB of steps stay
  // in this worker's wasm memory, which never shrinks.
  it('names to, and the program still answers a range at a time', { timeout: 120_000 }, async () => {
    const p = await runGcode('G1 X540000 F1000', { stepsPerMm: 1000, maxSteps: 1e9 });
    try {
      expect(p.trace.steps).toBe(540_000_000);
      let error: unknown;
      try {
        p.stepTimes(0, p.trace.steps);
      } catch (e) {
        error = e;
      }
      expect(error).toMatchObject({
        name: 'VoxpathError',
        field: 'to',
        message: "to: the instants of steps 0..540000000 take 4320000000 bytes, more than the core's memory has room for: read them a range at a time",
      });
      expect(p.stepTimes(p.trace.steps - 2, p.trace.steps)[1]).toBe(p.durationSeconds);
    } finally {
      p.free();
    }
  });
});
