// The ideal polyline in the form the scene draws it (IdealLine): every
// vertex's x, y, z as the 32-bit float WebGL reads, and the box of those
// vertices. The core makes it for a trace (Trace.idealLine(), which the
// worker sends the page); web/ideal-line.ts for lines the page makes itself.
import { describe, expect, it } from 'vitest';
import { idealLineOf } from '../web/ideal-line.js';
import { runGcode, trace } from '../web/core/index.js';

/** The line as a plain per-vertex loop over the polyline gives it. */
function expected(polyline: Float64Array | Int32Array, dims: number) {
  const xyz: number[] = [];
  for (let k = 0; k < polyline.length / dims; k++) {
    for (let a = 0; a < 3; a++) xyz.push(a < dims ? Math.fround(polyline[k * dims + a]!) : 0);
  }
  const axis = (a: number) => xyz.filter((_, i) => i % 3 === a);
  return {
    xyz,
    min: [0, 1, 2].map((a) => Math.min(...axis(a))),
    max: [0, 1, 2].map((a) => Math.max(...axis(a))),
  };
}

describe('idealLineOf', () => {
  it("holds a G-code program's polyline vertex for vertex, as 32-bit floats, with its box", async () => {
    const program = await runGcode('G21 G90\nG1 X10 Y-4 F500\nG2 X-2 Y-4 I-6 J0 Z3\nG3 X1 Y1 R7\n', { stepsPerMm: 80 });
    const polyline = program.trace.idealPolyline();
    expect(polyline.length / 3).toBeGreaterThan(20);
    const line = idealLineOf(polyline, 3);
    expect(line.xyz).toBeInstanceOf(Float32Array);
    expect({ xyz: Array.from(line.xyz), min: line.min, max: line.max }).toEqual(expected(polyline, 3));
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
      expect({ xyz: Array.from(line.xyz), min: line.min, max: line.max }).toEqual(expected(points, t.dims));
      t.free();
    }
  });

  it('gives an empty line a zero box', () => {
    expect(idealLineOf(new Float64Array(0), 3)).toEqual({ xyz: new Float32Array(0), min: [0, 0, 0], max: [0, 0, 0] });
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
      const polyline = t.idealPolyline();
      const want = polyline.length === 0 ? { xyz: [], min: [0, 0, 0], max: [0, 0, 0] } : expected(polyline, t.dims);
      expect({ xyz: Array.from(line.xyz), min: line.min, max: line.max }, `${t.dims} axes`).toEqual(want);
    }
    expect(program.trace.idealPolyline().length / 3).toBeGreaterThan(20);
    expect(empty.trace.idealLine().xyz.length).toBe(0);
    for (const t of [program, empty, line2, line4]) t.free();
  });
});
