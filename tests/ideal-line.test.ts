// The ideal polyline in the form the scene draws it (IdealLine): every
// vertex's x, y, z less an origin near the path, as the 32-bit float WebGL
// reads, what that float left of each, and the box of those vertices. The core makes it for a trace (Trace.idealLine(), which the
// worker sends the page); web/ideal-line.ts for lines the page makes itself.
import { describe, expect, it } from 'vitest';
import type { IdealLine } from '../web/core/types.js';
import { idealLineOf } from '../web/ideal-line.js';
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
    for (const t of [program.trace, empty.trace, line2, line4]) {
      const line = t.idealLine();
      expect(line.xyz).toBeInstanceOf(Float32Array);
      expect(line.origin).toEqual([t.start[0], t.start[1], t.start[2] ?? 0]);
      const polyline = t.idealPolyline();
      const want = polyline.length === 0 ? { xyz: [], rest: [], min: [0, 0, 0], max: [0, 0, 0] } : expected(polyline, t.dims, line.origin);
      expect(compared(line), `${t.dims} axes`).toEqual(want);
    }
    expect(program.trace.idealPolyline().length / 3).toBeGreaterThan(20);
    expect(empty.trace.idealLine().xyz.length).toBe(0);
    for (const t of [program, empty, line2, line4]) t.free();
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
