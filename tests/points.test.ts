// Reading a trace through the real wasm core: the points the core decodes
// into the array it returns (a chunk at a time through one buffer in wasm
// memory) are the points its step codes add up to, whatever the range,
// the number of axes, the length or the place in the grid; reading them
// grows wasm memory by that buffer, not by the points; and what trace()
// no longer computes up front (metrics, segments) is there when read.
import { describe, expect, it } from 'vitest';
import { algorithms, heapBytes, memoryBytes, runGcode, trace } from '../web/core/index.js';
import type { Trace, TraceOptions } from '../web/core/index.js';
import { randomLines } from './helpers.js';

/**
 * The points of steps `from..to` replayed in plain JS from point `from`:
 * each step code moves axis a by +1 (bit a) or -1 (bits a and 8 + a).
 */
function replayed(t: Trace, from: number, to: number): Int32Array {
  const out = new Int32Array((to - from) * t.dims);
  if (to <= from) return out;
  const p = t.point(from);
  const codes = t.stepCodes(from, to - 1);
  out.set(p, 0);
  for (let k = 0; k < codes.length; k++) {
    for (let a = 0; a < t.dims; a++) {
      if ((codes[k]! >> a) & 1) p[a] += (codes[k]! >> (8 + a)) & 1 ? -1 : 1;
      out[(k + 1) * t.dims + a] = p[a]!;
    }
  }
  return out;
}

/**
 * Values the core decodes into its buffer at a time (rust/src/wasm.rs,
 * POINTS_CHUNK_VALUES): a path of `dims` axes crosses from one chunk to the
 * next every chunkRows(dims) points.
 */
const CHUNK_VALUES = (1 << 18) + (1 << 13);
const chunkRows = (dims: number) => Math.floor(CHUNK_VALUES / dims);

/** Every case but the grid's edge and the helix crosses at least one chunk's end. */
const CASES: [string, TraceOptions][] = [
  ['a 3D line over several chunks', { algorithm: 'regions', from: [0, 0, 0], to: [300_000, -210_001, 180_003] }],
  ['a 2D line', { algorithm: 'bresenham2d', from: [5, -5], to: [-437_000, 12_345] }],
  ['a 6D line', { algorithm: 'nd', from: [0, 0, 0, 0, 0, 0], to: [150_000, -8000, 7000, -6000, 5000, 1] }],
  ['a 4D line by one axis a step', { algorithm: 'greedy', from: [0, 0, 0, 0], to: [60_000, -40_000, 20_000, 7] }],
  ['a line at the edge of the grid', { algorithm: 'bresenham3d', from: [2 ** 30, -(2 ** 30), 2 ** 30 - 5], to: [2 ** 30 - 20_000, -(2 ** 30) + 13_001, 2 ** 30] }],
  // Over 1 MiB of points: in Node its array comes from Buffer.allocUnsafeSlow,
  // not zeroed, so every value in it is one the core wrote.
  ['a 3D line past a megabyte of points', { algorithm: 'bresenham3d', from: [7, -3, 0], to: [-150_000, 98_765, -43_210] }],
  ['a circle', { algorithm: 'circle', from: [30_000, 0, 0], to: [30_000, 0, 0], center: [0, 0, 0] }],
  ['a helix in chords', { algorithm: 'helix', method: 'segments', from: [-2000, 0, 50], to: [-2000, 0, 1050], center: [0, 0, 0], turns: 2 }],
];

/**
 * `got` has `want`'s values, compared one by one: vitest's deep equality
 * of arrays of hundreds of thousands of values takes seconds.
 */
function expectValues(got: Int32Array, want: Int32Array, label: string): void {
  expect(got.length, label).toBe(want.length);
  expect(
    got.findIndex((v, i) => v !== want[i]),
    `${label}: first wrong value`,
  ).toBe(-1);
}

/** Points from, from + every, ... below `to` of `all` (stride dims), in one array. */
function everyNth(all: Int32Array, dims: number, from: number, to: number, every: number): Int32Array {
  const out = new Int32Array(Math.ceil((to - from) / every) * dims);
  for (let k = from, r = 0; k < to; k += every, r++) out.set(all.subarray(k * dims, (k + 1) * dims), r * dims);
  return out;
}

describe('points', () => {
  it.each(CASES)('of %s are the step codes replayed, for the whole path and any range', async (_, options) => {
    const t = await trace(options);
    const n = t.steps + 1;
    const rows = chunkRows(t.dims);
    expectValues(t.points, replayed(t, 0, n), 'all points');
    expect(Array.from(t.points.subarray(0, t.dims))).toEqual(Array.from(options.from));
    for (const [a, b] of [
      [0, 1],
      [n - 1, n],
      [1, Math.min(n, rows + 1)],
      [Math.floor(n / 3), Math.floor((2 * n) / 3)],
      [rows - 1, Math.min(n, 3 * rows + 5)],
    ] as const) {
      if (a > b || b > n) continue;
      expectValues(t.pointsInRange(a, b), replayed(t, a, b), `points ${a}..${b}`);
      expectValues(t.pointsInRange(a, b), t.points.subarray(a * t.dims, b * t.dims), `points ${a}..${b} of all`);
    }
    expect(t.pointsInRange(n, n)).toHaveLength(0);
    t.free();
  });

  it.each(CASES)('of %s, every n-th only, are those rows of all the points', async (_, options) => {
    const t = await trace(options);
    const n = t.steps + 1;
    const rows = chunkRows(t.dims);
    const all = t.points;
    const rowsOf = (from: number, to: number, every: number) => everyNth(all, t.dims, from, to, every);
    // Every spacing against the chunk's rows: below them, a chunk's rows and
    // more, ranges starting inside a chunk and on its edge.
    for (const every of [1, 2, 3, 277, rows - 1, rows, rows + 1, 3 * rows + 7, n, n + 5]) {
      for (const [a, b] of [
        [0, n],
        [1, n],
        [Math.floor(n / 3), Math.floor((2 * n) / 3)],
        [rows - 1, n],
        [rows, n],
        [n - 1, n],
        [n, n],
      ] as const) {
        if (a > b) continue;
        expectValues(t.pointsInRange(a, b, every), rowsOf(a, b, every), `every ${every} of ${a}..${b}`);
      }
    }
    t.free();
  });

  it('past a megabyte, and the deviations and axis errors beside them, are what smaller reads give', async () => {
    // 150,001 points: 1.8 MB of points, 1.2 MB of deviations, 3.6 MB of axis
    // errors, each array made without zeroing in Node; the reads of a few
    // thousand points each are made zeroed, as every small array is.
    const t = await trace(CASES.find(([name]) => name.startsWith('a 3D line past'))![1]);
    const n = t.steps + 1;
    expect(t.points.byteLength).toBeGreaterThan(1 << 20);
    const [deviation, axisError] = [t.deviation, t.axisError];
    expect(deviation.byteLength).toBeGreaterThan(1 << 20);
    for (let k = 0; k < n; k += 4999) {
      const to = Math.min(n, k + 4999);
      expect(deviation.subarray(k, to)).toEqual(t.deviationInRange(k, to));
      expect(axisError.subarray(k * 3, to * 3)).toEqual(t.axisErrorInRange(k, to));
    }
    t.free();
  });

  it('of a G-code program are its moves replayed', async () => {
    const program = await runGcode('G21 G90\nG1 X10 Y5 F600\nG2 X20 Y5 I5 J0\nG1 X-3 Y-7 Z2\n', { stepsPerMm: 80 });
    const t = program.trace;
    expect(t.points).toEqual(replayed(t, 0, t.steps + 1));
    program.free();
  });

  it('are refused outside the path, naming the range', async () => {
    const t = await trace(CASES[0]![1]);
    expect(() => t.pointsInRange(0, t.steps + 2)).toThrow(/^to: point index \d+ is outside 0\.\.\d+$/);
    expect(() => t.pointsInRange(0, 2, 0)).toThrow(/^every: every \(points apart\) 0 is outside 1\.\.4294967295$/);
    expect(() => t.pointsInRange(0, 2, 1.5)).toThrow(/^every: every \(points apart\) must be a whole number, got 1\.5$/);
    t.free();
  });

  it('grow wasm memory by one chunk buffer at most, however many are read', async () => {
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [3_000_000, 2_100_001, 1_800_003] });
    t.pointsInRange(0, 2); // the buffer for a small read, and anything the first read allocates
    const before = memoryBytes();
    const points = t.points;
    expect(points.length).toBe(3 * (t.steps + 1));
    // 36 MB of points read; the core's buffer is 1 MiB and 32 KiB.
    const bound = CHUNK_VALUES * Int32Array.BYTES_PER_ELEMENT + (1 << 16);
    expect(memoryBytes() - before).toBeLessThanOrEqual(bound);
    // Every 7th point: the buffer, and the chosen points of one chunk beside it.
    expect(t.pointsInRange(0, t.steps + 1, 7).length).toBe(3 * Math.ceil((t.steps + 1) / 7));
    expect(memoryBytes() - before).toBeLessThanOrEqual(bound + Math.ceil(bound / 7));
    t.free();
  });
});

describe('points of random lines anywhere in the grid', () => {
  // The wasm build's own decode (four-lane vectors for 2 to 4 axes, a bit
  // at a time past them), which the Rust tests, built natively, never run:
  // lines from seeded random starts anywhere within +-2^30, in every
  // direction, by every line algorithm that takes their axis count.
  const LINES = [2, 3, 4, 5, 6].flatMap((dims) => randomLines(101 + dims, 6, dims, 3000));
  it('are their step codes replayed, read first from the plan and again from the recorded trace', async () => {
    const lineAlgorithms = (await algorithms()).filter((a) => a.family === 'line');
    let traced = 0;
    for (const { from, to } of LINES) {
      for (const { id, minDims, maxDims } of lineAlgorithms) {
        if (from.length < minDims || from.length > maxDims) continue;
        const t = await trace({ algorithm: id, from, to });
        const n = t.steps + 1;
        const planned = t.points;
        const third = Math.floor(n / 3);
        // A range records the trace; its codes replayed are the points.
        const again = t.pointsInRange(third, n);
        const replay = replayed(t, 0, n);
        expectValues(planned, replay, `${id} ${JSON.stringify({ from, to })}, read first`);
        expectValues(again, replay.subarray(third * t.dims), `${id} ${JSON.stringify({ from, to })}, from point ${third}, recorded`);
        t.free();
        traced++;
      }
    }
    expect(traced).toBeGreaterThan(LINES.length * 2);
  });
});

describe('what trace() leaves until it is read', () => {
  // Lines, circles, helices and arcs in chords are planned (rust/src/plan.rs):
  // their steps are recorded only when something needs them, and points
  // read first come straight from their steppers.
  it.each([
    ['a 3D line', { algorithm: 'bresenham3d', from: [2 ** 30 - 5, 0, -9], to: [2 ** 30 - 400_000, 123_457, 5] }],
    ['a 5D line by one axis a step', { algorithm: 'walk6', from: [0, 0, 0, 0, 0], to: [-9000, 7000, 1, 0, 30_000] }],
    ['a circle in x and y', { algorithm: 'circle', from: [300_000, 0], to: [0, -300_000], center: [0, 0], dir: 'cw' }],
    ['a helix', { algorithm: 'helix', from: [0, 500, 40_000], to: [0, -60_000, 40_000], center: [0, 0, 0], plane: 'zx', turns: 1 }],
    ['an arc in chords', { algorithm: 'arc-segments', from: [90_000, 5, 0], to: [-7, 90_005, 0], center: [0, 5, 0], lineAlgorithm: 'greedy' }],
  ] as [string, TraceOptions][])('of %s: records its steps only when read past its points, which are the same', async (_, options) => {
    const heap = heapBytes();
    const t = await trace(options);
    const first = t.points;
    // Neither the summary nor the points held its steps: 2 bytes a step.
    expect(heapBytes() - heap).toBeLessThan(t.steps);
    // Every n-th point of the whole path comes from the plan too (the core
    // gathers the chosen points of each chunk it decodes), across the
    // chunks' ends: those rows of the points, and still nothing recorded.
    const [n, rows] = [t.steps + 1, chunkRows(t.dims)];
    for (const every of [2, 3, 277, rows - 1, rows, rows + 1, 3 * rows + 7, n, n + 5]) {
      expectValues(t.pointsInRange(0, n, every), everyNth(first, t.dims, 0, n, every), `every ${every}th point, planned`);
    }
    expect(heapBytes() - heap).toBeLessThan(t.steps);
    expect(first.length).toBe((t.steps + 1) * t.dims);
    expect(Array.from(first.subarray(-t.dims))).toEqual(t.end);
    // A range reads the recorded trace: its codes replayed are those points.
    expectValues(first, replayed(t, 0, t.steps + 1), 'points read first');
    expect(heapBytes() - heap).toBeGreaterThan(2 * t.steps);
    expectValues(t.pointsInRange(0, t.steps + 1), first, 'points read again, recorded');
    t.free();
    expect(heapBytes()).toBe(heap);
  });

  it('gives the metrics the points have, when first read', async () => {
    const t = await trace({ algorithm: 'dda', from: [0, 0, 0], to: [5000, 3001, -1999] });
    expect(Object.keys(t)).not.toContain('metrics');
    const m = t.metrics;
    expect(m.steps).toBe(t.steps);
    expect(m.maxDeviation).toBe(Math.max(...t.deviation));
    expect(m.meanDeviation).toBeCloseTo(t.deviation.reduce((s, v) => s + v, 0) / (t.steps + 1), 12);
    expect(m.pulsesByAxis).toEqual([5000, 3001, 1999]);
    expect(t.metrics).toBe(m);
    t.free();
  });

  it('gives the legend (columns, figures, deviation bound) of its algorithm, when first read', async () => {
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] });
    expect(Object.keys(t).sort()).toEqual(['algorithm', 'dims', 'end', 'start', 'steps']);
    const legend = t.legend;
    expect(t.legend).toBe(legend);
    expect(t.columns).toBe(legend.columns);
    expect(t.figures).toEqual(['exitFace']);
    expect(t.deviationBound!.value).toBeCloseTo(Math.SQRT1_2, 15);
    // What the catalogue says the algorithm decides, column for column.
    const info = (await algorithms()).find((a) => a.id === 'regions')!;
    expect(t.columns.map((c) => c.name)).toEqual(info.columns.map((c) => c.name));
    // The summary's fields and the legend's, as the worker hands them to the page.
    expect(Object.keys({ ...t, ...t.legend }).sort()).toEqual(['algorithm', 'columns', 'deviationBound', 'dims', 'end', 'figures', 'start', 'steps']);
    t.free();
    // Read once, it is the trace's own, as its metrics are.
    expect(t.columns).toBe(legend.columns);
  });

  it('gives the segments with their notes, when first read', async () => {
    const t = await trace({ algorithm: 'arc-segments', from: [1000, 0, 0], to: [0, 1000, 0], center: [0, 0, 0] });
    expect(Object.keys(t)).not.toContain('segments');
    const segments = t.segments;
    expect(segments.length).toBeGreaterThan(10);
    expect(segments[0]!.firstStep).toBe(0);
    expect(segments.at(-1)!.firstStep + segments.at(-1)!.steps).toBe(t.steps);
    expect(segments[1]!.note).toMatch(/^Chord 2 of /);
    t.free();
  });
});
