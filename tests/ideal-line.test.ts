// The ideal polyline in the form the scene draws it (IdealLine): every
// vertex's x, y, z less an origin near the path, as the 32-bit float WebGL
// reads, what that float left of each, and the box of those vertices. The core makes it for a trace (Trace.idealLine(), which the
// worker sends the page); web/ideal-line.ts for lines the page makes itself.
import { describe, expect, it } from 'vitest';
import type { IdealLine } from '../web/core/types.js';
import { REBASE_CELLS, dashDistances, idealLineOf, verticesFrom } from '../web/ideal-line.js';
import { runGcode, trace } from '../web/core/index.js';

/** The line as a plain per-vertex loop over the polyline gives it, from `origin`. */
function expected(polyline: Float64Array | Int32Array, dims: number, origin: number[]) {
  const [xyz, rest]: number[][] = [[], []];
  for (let k = 0; k < polyline.length / dims; k++) {
    for (let a = 0; a < 3; a++) {
      const exact = a < dims ? polyline[k * dims + a]! - origin[a]! : 0;
      xyz.push(Math.fround(exact));
      rest.push(Math.fround(exact - Math.fround(exact)));
    }
  }
  const axis = (a: number) => xyz.filter((_, i) => i % 3 === a);
  return {
    xyz,
    rest,
    min: [0, 1, 2].map((a) => Math.min(...axis(a))),
    max: [0, 1, 2].map((a) => Math.max(...axis(a))),
  };
}

/** What `expected` compares of a line. */
const compared = (line: IdealLine) => ({ xyz: Array.from(line.xyz), rest: Array.from(line.rest), min: line.min, max: line.max });

describe('idealLineOf', () => {
  it("holds a G-code program's polyline vertex for vertex, as 32-bit floats, with its box", async () => {
    const program = await runGcode('G21 G90\nG1 X10 Y-4 F500\nG2 X-2 Y-4 I-6 J0 Z3\nG3 X1 Y1 R7\n', { stepsPerMm: 80 });
    const polyline = program.trace.idealPolyline();
    expect(polyline.length / 3).toBeGreaterThan(20);
    const line = idealLineOf(polyline, 3);
    expect(line.xyz).toBeInstanceOf(Float32Array);
    // From its first vertex, rounded to the grid.
    expect(line.origin).toEqual([0, 0, 0]);
    expect(compared(line)).toEqual(expected(polyline, 3, line.origin));
    program.free();
  });

  it('puts a 2-axis path at z = 0 and leaves axes past the third out', async () => {
    const line2 = await trace({ algorithm: 'bresenham2d', from: [-3, 5], to: [40, -17] });
    const cells4 = await trace({ algorithm: 'nd', from: [1, -2, 3, -4], to: [9, 7, -5, 6] });
    for (const [t, points] of [
      [line2, line2.idealPolyline()],
      [cells4, cells4.points],
    ] as const) {
      const line = idealLineOf(points, t.dims);
      expect(line.origin).toEqual([points[0], points[1], t.dims > 2 ? points[2] : 0]);
      expect(compared(line)).toEqual(expected(points, t.dims, line.origin));
      t.free();
    }
  });

  it('gives an empty line a zero box', () => {
    expect(idealLineOf(new Float64Array(0), 3)).toEqual({ xyz: new Float32Array(0), rest: new Float32Array(0), min: [0, 0, 0], max: [0, 0, 0], origin: [0, 0, 0] });
  });
});

describe('Trace.idealLine', () => {
  it("is the trace's ideal polyline as 32-bit floats with its box: a program, 2 axes, 4 axes, none", async () => {
    const program = await runGcode('G21 G90\nG1 X10 Y-4 F500\nG2 X-2 Y-4 I-6 J0 Z3\nG3 X1 Y1 R7\n', { stepsPerMm: 80 });
    const empty = await runGcode('G21 G90\n', { stepsPerMm: 80 });
    const line2 = await trace({ algorithm: 'bresenham2d', from: [-3, 5], to: [40, -17] });
    const line4 = await trace({ algorithm: 'nd', from: [1, -2, 3, -4], to: [9, 7, -5, 6] });
    // 20,001 vertices, past the core's pieces of 8,192 (two full, one not), and 120 KiB of floats.
    const zigzag = await runGcode(Array.from({ length: 20_000 }, (_, k) => `G1 X${k + 1} Y${(k + 1) % 2}\n`).join(''), { stepsPerMm: 1 });
    expect(zigzag.trace.idealLine().xyz.length).toBe(3 * 20_001);
    for (const t of [program.trace, empty.trace, line2, line4, zigzag.trace]) {
      const line = t.idealLine();
      expect(line.xyz).toBeInstanceOf(Float32Array);
      expect(line.origin).toEqual([t.start[0], t.start[1], t.start[2] ?? 0]);
      const polyline = t.idealPolyline();
      const want = polyline.length === 0 ? { xyz: [], rest: [], min: [0, 0, 0], max: [0, 0, 0] } : expected(polyline, t.dims, line.origin);
      expect(compared(line), `${t.dims} axes`).toEqual(want);
    }
    expect(program.trace.idealPolyline().length / 3).toBeGreaterThan(20);
    expect(empty.trace.idealLine().xyz.length).toBe(0);
    for (const t of [program, empty, line2, line4, zigzag]) t.free();
  });

  it('keeps each vertex exact near 2^30, where a 32-bit float of the coordinate is a multiple of 64', async () => {
    // A line's ideal path is its two ends: from the start, the end is 24,
    // 10, 5 exactly; as floats of their own, 1,073,741,800 and 1,073,741,824
    // are one value (2^30), and the line was drawn as a point.
    const far = await trace({ algorithm: 'regions', from: [1073741800, 1073741800, 1073741800], to: [1073741824, 1073741810, 1073741805] });
    const line = far.idealLine();
    expect(line.origin).toEqual([1073741800, 1073741800, 1073741800]);
    expect(Array.from(line.xyz)).toEqual([0, 0, 0, 24, 10, 5]);
    expect(Math.fround(1073741800)).toBe(Math.fround(1073741824));
    far.free();
  });
});

describe('verticesFrom', () => {
  /** The vertices drawn from `origin` as doubles, one array of x, y, z each. */
  const drawn = (line: IdealLine, origin: [number, number, number]) => {
    const { xyz } = verticesFrom(line, origin);
    return Array.from({ length: xyz.length / 3 }, (_, k) => Array.from(xyz.subarray(k * 3, k * 3 + 3)));
  };

  it("is the line's own vertices from its own origin", () => {
    const line = idealLineOf(new Float64Array([5, 5, 5, 2005, 1405, 1205, 6005, 1405, 1205]), 3);
    expect(verticesFrom(line, line.origin)).toEqual({ xyz: line.xyz, splits: [] });
    expect(verticesFrom(line, line.origin).xyz).toBe(line.xyz);
  });

  it('takes the vertices of a long line from a point near its far end, exactly', async () => {
    // An arc's vertices have fractions, which a float a million cells from the start rounds to an eighth.
    const program = await runGcode('G21 G90\nG2 X20000 Y0 I10000 J0\n', { stepsPerMm: 80 });
    const polyline = program.trace.idealPolyline();
    const line = program.trace.idealLine();
    // The vertex the floats from the start rounded most (a million cells out, to a sixteenth).
    const rounding = (k: number) => Math.max(...line.rest.subarray(k * 3, k * 3 + 3).map(Math.abs));
    const k = Array.from({ length: polyline.length / 3 }, (_, i) => i).reduce((best, i) => (rounding(i) > rounding(best) ? i : best));
    const vertex = [0, 1, 2].map((a) => polyline[k * 3 + a]!);
    expect(Math.hypot(...vertex)).toBeGreaterThan(500_000);
    const origin = vertex.map((c) => Math.round(c) - 3) as [number, number, number];
    const vertices = drawn(line, origin);
    // Nothing is split: the segments near the origin have an end there.
    expect(vertices.length).toBe(polyline.length / 3);
    expect(vertices[k]).toEqual(vertex.map((c, a) => Math.fround(c - origin[a]!)));
    // The float from the start, moved there, was off by a share of a cell.
    expect(rounding(k)).toBeGreaterThan(0.01);
    program.free();
  });

  it('splits a segment whose ends are far, at its point nearest the origin, and only such a segment', () => {
    // Through (0, 5.5, 0.25) from a million cells either side, then off to a far point.
    const line = idealLineOf(new Float64Array([-1e6, 5.5, 0.25, 1e6, 5.5, 0.25, 1e6, 3e6, 0]), 3);
    const vertices = drawn(line, [0, 5, 0]);
    expect(vertices).toEqual([[-1e6, 0.5, 0.25], [0, 0.5, 0.25], [1e6, 0.5, 0.25], [1e6, 3e6 - 5, 0]]);
    // Its middle, from the start, is a float a million cells out: the one the view rounded.
    expect(drawn(line, line.origin)).toHaveLength(3);
    // Nor is a segment split that has an end near the origin: it is off by little near there.
    expect(drawn(line, [999_998, 5, 0])).toHaveLength(3);
  });

  it('leaves a segment passing far beyond the point looked at, seen within a quarter of a pixel at a thousand', () => {
    // 100,000 cells off, its ends at 1,000,000 (off by 2^-24 of that, 0.06 cell): 6e-7 radians.
    const passing = (offset: number) => idealLineOf(new Float64Array([-1e6, offset, 0, 1e6, offset, 0]), 3);
    expect(drawn(passing(100_000), [0, 0, 0])).toHaveLength(2);
    // REBASE_CELLS on each axis is where the view may look from this origin: a segment through there is split.
    expect(drawn(passing(REBASE_CELLS), [0, 0, 0])).toEqual([[-1e6, REBASE_CELLS, 0], [0, REBASE_CELLS, 0], [1e6, REBASE_CELLS, 0]]);
  });
});

describe('dashDistances', () => {
  /** The distances of `line`'s drawn segments from `origin`, two per segment, as doubles. */
  const distances = (line: IdealLine, origin: [number, number, number], periodCells: number) =>
    Array.from(dashDistances(line, origin, verticesFrom(line, origin).splits, periodCells));

  it("adds up the path's length, as three.js does, along a path drawn from its start", () => {
    const line = idealLineOf(new Float64Array([0, 0, 0, 3, 4, 0, 3, 4, 2]), 3);
    expect(distances(line, line.origin, 100)).toEqual([0, 5, 5, 7]);
    // Each segment's from its start, the end nearer the origin, less whole periods.
    expect(distances(line, line.origin, 0.38)).toEqual([0, 5, 5 % 0.38, (5 % 0.38) + 2].map(Math.fround));
  });

  it('gives a segment its distances from its end nearer the origin, small there, a million cells along', () => {
    const line = idealLineOf(new Float64Array([0, 0, 0, 1_000_000, 0.5, 0]), 3);
    const along = Math.hypot(1_000_000, 0.5);
    const [start, end] = distances(line, [999_998, 0, 0], 0.38);
    expect(end).toBe(Math.fround(along % 0.38));
    expect(start).toBe(Math.fround((along % 0.38) - along));
  });

  it('runs on through a split point, from which both halves are given', () => {
    const line = idealLineOf(new Float64Array([-1e6, 5.5, 0.25, 1e6, 5.5, 0.25]), 3);
    const anchor = 1e6 % 0.38;
    expect(distances(line, [0, 5, 0], 0.38)).toEqual([anchor - 1e6, anchor, anchor, anchor + 1e6].map(Math.fround));
  });
});
