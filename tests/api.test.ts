// The headless API against the real built wasm package (web/core/pkg).
// Golden values: Wang et al. 2020 eq. (6), (8), (10) for (0,0,0)->(10,7,6),
// as worked out in SEED-NOTES.md (they equal Liu's Table 1 point for point).
import { describe, expect, it } from 'vitest';
import { algorithms, catalogue, NO_VALUE, randomLines, readDecision, runGcode, trace, traceToCsv, traceToJson, traceToTable, VoxpathError } from '../web/core/index.js';
import type { TraceOptions } from '../web/core/index.js';
import { distanceToLine, labelsOf, rejection } from './helpers.js';

const LINE = { algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] } satisfies TraceOptions;

describe('trace (regions)', () => {
  it('reproduces the discriminants and points of eq. (6)-(10)', async () => {
    const t = await trace(LINE);
    expect(t.dims).toBe(3);
    expect(t.steps).toBe(10);
    expect(Array.from(t.points)).toEqual(
      [[0, 0, 0], [1, 1, 1], [2, 1, 1], [3, 2, 2], [4, 3, 2], [5, 4, 3], [6, 4, 4], [7, 5, 4], [8, 6, 5], [9, 6, 5], [10, 7, 6]].flat(),
    );
    expect(Array.from(t.decisions.M!)).toEqual([4, -2, 12, 6, 0, -6, 8, 2, -4, 10]);
    expect(Array.from(t.decisions.N!)).toEqual([2, -6, 6, -2, 10, 2, -6, 6, -2, 10]);
    const region = t.columns.find((c) => c.name === 'region')!;
    expect(Array.from(t.decisions.region!, (v) => labelsOf(region)[v])).toEqual(['d', 'b', 'd', 'a', 'g', 'c', 'a', 'd', 'b', 'd']);
    expect(t.decisions.region).toBeInstanceOf(Uint8Array);
    expect(Array.from(t.decisions.tie!)).toEqual([0, 0, 0, 0, 1, 0, 0, 0, 0, 0]);
  });

  it("gives where the ideal line crosses each step's exit face, from eq. (2)", async () => {
    const t = await trace(LINE);
    // x is active: the line is at y = 0.7 (x_i + 1), z = 0.6 (x_i + 1) on the
    // exit plane x = x_i + 1, and the face's center at (y_i + 1/2, z_i + 1/2),
    // (x_i, y_i, z_i) being the point before the step.
    const before = Array.from({ length: t.steps }, (_, k) => t.point(k));
    const u = Array.from(t.decisions.faceU!);
    const v = Array.from(t.decisions.faceV!);
    before.forEach(([x, y, z], k) => {
      expect(u[k]).toBeCloseTo(0.7 * (x! + 1) - (y! + 0.5), 12);
      expect(v[k]).toBeCloseTo(0.6 * (x! + 1) - (z! + 0.5), 12);
    });
    // Step 3 crosses 0.6 along y, off the face but in region d (M = 12); step 5 (M = 0) on segment g.
    expect([u[2], v[2], u[4], v[4]]).toEqual([0.6, 0.3, 0, 0.5]);
    const axis = (name: string) => {
      const column = t.columns.find((c) => c.name === name)!;
      return Array.from(t.decisions[name]!, (i) => labelsOf(column)[i]);
    };
    expect(new Set(axis('faceUAxis'))).toEqual(new Set(['+y']));
    expect(new Set(axis('faceVAxis'))).toEqual(new Set(['+z']));
    // Mirrored, the coordinates are the same and the axes point the way the line goes.
    const mirrored = await trace({ ...LINE, to: [-10, 7, -6] });
    expect(Array.from(mirrored.decisions.faceU!)).toEqual(u);
    expect(Array.from(mirrored.decisions.faceV!)).toEqual(v);
    const vAxis = mirrored.columns.find((c) => c.name === 'faceVAxis')!;
    expect(labelsOf(vAxis)[mirrored.decisions.faceVAxis![0]!]).toBe('-z');
  });

  it('has one face coordinate with one passive axis, and none on a type ② line', async () => {
    // (0,0,0)->(7,7,3): x and y active, z passive; the crossing is N/(2·7) along the exit edge.
    const one = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [7, 7, 3] });
    expect(one.decisions.faceU![0]).toBeCloseTo((2 * 3 - 7) / 14, 15);
    expect(Number.isNaN(one.decisions.faceV![0])).toBe(true);
    const diagonal = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [4, 4, 4] });
    expect(Array.from(diagonal.decisions.faceU!).every(Number.isNaN)).toBe(true);
    expect(diagonal.decisions.faceUAxis![0]).toBe(NO_VALUE);
  });

  it('states the deviation bound its algorithm guarantees, and none where it guarantees none', async () => {
    // Wang section 3.2, Fig. 6b: with y and z passive every point is within √2/2.
    const wang = await trace(LINE);
    expect(wang.deviationBound!.value).toBe(Math.SQRT1_2);
    expect(wang.deviationBound!.why).toMatch(/2 passive axes stays within 1\/2 cell/);
    expect(wang.metrics.maxDeviation).toBeLessThanOrEqual(wang.deviationBound!.value);
    // Bresenham in the plane: one passive axis, half a cell.
    expect((await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [9, 4] })).deviationBound!.value).toBe(0.5);
    // walk6: half a cell's diagonal, √3/2 in 3D.
    expect((await trace({ ...LINE, algorithm: 'walk6' })).deviationBound!.value).toBe(Math.sqrt(3) / 2);
    // Greedy strays with length, and the printed Saleem pseudo-code runs ahead: no promise.
    expect((await trace({ ...LINE, algorithm: 'greedy' })).deviationBound).toBeNull();
    expect((await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [9, 4], variant: 'printed' })).deviationBound).toBeNull();
  });

  it('measures each point against the ideal line and sums up the path', async () => {
    const t = await trace(LINE);
    expect(t.deviation).toHaveLength(11);
    for (let k = 0; k <= t.steps; k++) {
      expect(t.deviation[k]).toBeCloseTo(distanceToLine(t.point(k), LINE.from, LINE.to), 12);
    }
    const m = t.metrics;
    expect(m.steps).toBe(10);
    expect(m.pulsesByAxis).toEqual([10, 7, 6]);
    expect(m.stepsMovingAxes).toEqual([2, 3, 5]);
    expect(m.ties).toBe(1);
    expect(m.maxDeviation).toBe(Math.max(...t.deviation));
    expect(m.meanDeviation).toBeCloseTo(t.deviation.reduce((s, v) => s + v, 0) / 11, 12);
    expect(m.maxDeviation).toBeLessThanOrEqual(Math.SQRT1_2);
    // Eq. (11): x is active, so its error is 0; y and z lag by up to 0.5 and 0.4.
    expect(m.maxAxisError[0]).toBe(0);
    expect(m.maxAxisError[1]).toBeCloseTo(0.5, 12);
    expect(m.maxAxisError[2]).toBeCloseTo(0.4, 12);
  });

  it('gives any range on demand, equal to the whole', async () => {
    const t = await trace(LINE);
    const part = t.decisionsInRange(3, 7);
    expect(Array.from(part.M!)).toEqual(Array.from(t.decisions.M!.subarray(3, 7)));
    expect(Array.from(t.deviationInRange(2, 5))).toEqual(Array.from(t.deviation.subarray(2, 5)));
    expect(Array.from(t.pointsInRange(10, 11))).toEqual([10, 7, 6]);
    expect(() => t.decisionsInRange(5, 11)).toThrow(VoxpathError);
  });

  it("gives one point's detail from one replay: the step's decision read, its explanation, deviation, segment and exit face", async () => {
    const t = await trace(LINE);
    // Point 3, made by step index 2 from (2,1,1): M = 12, N = 6, region d, corner D.
    const d = t.stepDetail(3);
    expect(d).toMatchObject({ pointIndex: 3, stepIndex: 2, point: [3, 2, 2], pointBefore: [2, 1, 1], explanation: t.explain(2), segmentIndex: 0 });
    expect(d.deviation).toBe(t.deviation[3]);
    expect(d.segment!.note).toBe(t.segments[0]!.note);
    const cell = (name: string) => d.decision.find((c) => c.name === name)!;
    expect(d.decision.map((c) => c.name)).toEqual(t.columns.map((c) => c.name));
    expect(cell('M')).toEqual({ name: 'M', kind: 'int', value: 12, reading: 12 });
    expect(cell('region')).toMatchObject({ kind: 'category', reading: 'd' });
    expect(cell('tie')).toEqual({ name: 'tie', kind: 'flag', value: 0, reading: false });
    // The line crosses x = 3 at y = 2.1, z = 1.8 (eq. 2): 0.6 and 0.3 cells from the face's center (3, 1.5, 1.5).
    expect(d.figure).toMatchObject({ kind: 'exitFace', region: 'd', corner: 'D', center: [3, 1.5, 1.5], cell: [[2, 1, 1], [3, 2, 2]] });
    if (d.figure?.kind !== 'exitFace') throw new Error('expected an exit face');
    expect(d.figure.crossing[0]).toBeCloseTo(0.6, 12);
    expect(d.figure.crossing[1]).toBeCloseTo(0.3, 12);
    // The start point: no step, every cell empty.
    const start = t.stepDetail(0);
    expect(start).toMatchObject({ stepIndex: null, pointBefore: null, explanation: null, figure: null, segmentIndex: 0 });
    expect(start.decision.every((c) => c.value === null && c.reading === null)).toBe(true);
    expect(() => t.stepDetail(11)).toThrow(VoxpathError);
  });

  it("gives a chart's rows in one call: every point, or buckets keeping each one's largest and smallest deviation", async () => {
    const t = await trace({ algorithm: 'regions', from: [0, 0, 0], to: [100, 37, -20] });
    const all = t.chartSeries(1000);
    expect(all.bucketed).toBe(false);
    expect(Array.from(all.pointIndex)).toEqual(Array.from({ length: 101 }, (_, k) => k));
    expect(Array.from(all.deviationMax)).toEqual(Array.from(t.deviation));
    for (let a = 0; a < 3; a++) {
      expect(Array.from(all.position[a]!)).toEqual(Array.from({ length: 101 }, (_, k) => t.points[k * 3 + a]));
      expect(Array.from(all.ideal[a]!)).toEqual(Array.from({ length: 101 }, (_, k) => t.points[k * 3 + a]! - t.axisError[k * 3 + a]!));
    }
    // 101 points in at most 10 rows: buckets of 11, the last of 2.
    const some = t.chartSeries(10);
    expect(some.bucketed).toBe(true);
    expect(Array.from(some.pointIndex)).toEqual([0, 11, 22, 33, 44, 55, 66, 77, 88, 99]);
    expect(some.deviationMax[9]).toBe(Math.max(t.deviation[99]!, t.deviation[100]!));
    expect(some.deviationMin[1]).toBe(Math.min(...t.deviation.subarray(11, 22)));
    expect(() => t.chartSeries(0)).toThrow(VoxpathError);
  });

  // The page's deviation chart marks the path's largest deviation as the
  // largest of its series' bucket peaks, and asks no program for its metrics.
  it("keeps the path's largest deviation among a chart's bucket peaks: a line, a circle and a program", async () => {
    const program = await runGcode('G1 X12.3 Y4.5 F600\nG2 X15.3 Y7.5 I0 J3\nG1 X1 Y-2 Z0.7\n', { stepsPerMm: 80 });
    const traces = [
      await trace({ algorithm: 'regions', from: [0, 0, 0], to: [123457, 34567, -9101] }),
      await trace({ algorithm: 'circle', from: [3000, 0, 0], to: [3000, 0, 0], center: [0, 0, 0] }),
      program.trace,
    ];
    for (const t of traces) {
      for (const rows of [7, 2000, t.steps + 1]) {
        expect(t.chartSeries(rows).deviationMax.reduce((a, b) => Math.max(a, b), 0)).toBe(t.metrics.maxDeviation);
      }
    }
    traces[0]!.free();
    traces[1]!.free();
    program.free();
  });

  // The page frames a path with the core's bounds instead of scanning its
  // points; here they are held to the points' own extremes, on paths whose
  // box is not their ends' (a circle, a program that comes back).
  it('bounds every point: per axis, the smallest and largest coordinate, for a line, a circle, a 2D line and a program', async () => {
    const program = await runGcode('G1 X12.3 Y4.5 F600\nG2 X15.3 Y7.5 I0 J3\nG1 X1 Y-2 Z0.7\nG1 X0 Y0 Z0\n', { stepsPerMm: 80 });
    const traces = [
      await trace({ algorithm: 'regions', from: [5, -3, 2], to: [-123457, 34567, -9101] }),
      await trace({ algorithm: 'circle', from: [3000, 0, 0], to: [3000, 0, 0], center: [0, 0, 0] }),
      await trace({ algorithm: 'bresenham2d', from: [2 ** 30, -(2 ** 30)], to: [2 ** 30 - 977, -(2 ** 30) + 45] }),
      program.trace,
    ];
    for (const t of traces) {
      const { points, dims } = t;
      const axis = (a: number) => points.filter((_, i) => i % dims === a);
      const extremes = { min: [] as number[], max: [] as number[] };
      for (let a = 0; a < dims; a++) {
        extremes.min.push(axis(a).reduce((x, y) => Math.min(x, y)));
        extremes.max.push(axis(a).reduce((x, y) => Math.max(x, y)));
      }
      expect(t.bounds).toEqual(extremes);
    }
    // A circle's box is its radius either side of its center, not its ends.
    expect(traces[1]!.bounds).toEqual({ min: [-3000, -3000, 0], max: [3000, 3000, 0] });
    for (const t of traces.slice(0, 3)) t.free();
    program.free();
  });

  it('packs each step as step/direction bits that match the points', async () => {
    const t = await trace({ algorithm: 'regions', from: [5, 5, 5], to: [-3, 9, 2] });
    const codes = t.stepCodes(0, t.steps);
    for (let k = 0; k < t.steps; k++) {
      for (let axis = 0; axis < 3; axis++) {
        const moved = (codes[k]! >> axis) & 1;
        const negative = (codes[k]! >> (8 + axis)) & 1;
        const delta = t.points[(k + 1) * 3 + axis]! - t.points[k * 3 + axis]!;
        expect(delta).toBe(moved ? (negative ? -1 : 1) : 0);
      }
    }
    expect(t.point(t.steps)).toEqual([-3, 9, 2]);
  });

  it('explains a step in one sentence and describes the line', async () => {
    const t = await trace(LINE);
    expect(t.explain(0)).toBe(
      'x is the active axis; M = 4 > 0 and N = 2 > 0, so the line leaves the cell through region d, and the step goes to D (x+1, y+1, z+1).',
    );
    expect(t.segments[0]!.note).toContain('Line type ①');
    expect(Array.from(t.idealPolyline())).toEqual([0, 0, 0, 10, 7, 6]);
  });

  it('holds on ties when asked (Saleem), marking the tie', async () => {
    const t = await trace({ ...LINE, tie: 'hold' });
    expect(t.point(5)).toEqual([5, 3, 3]);
    expect(t.decisions.tie![4]).toBe(1);
  });

  it('treats a zero-length line as an empty trace', async () => {
    const t = await trace({ algorithm: 'regions', from: [1, 2, 3], to: [1, 2, 3] });
    expect(t.steps).toBe(0);
    expect(Array.from(t.points)).toEqual([1, 2, 3]);
    expect(t.decisions.M).toHaveLength(0);
  });

  it('accepts typed arrays as points', async () => {
    const t = await trace({ algorithm: 'regions', from: new Int32Array([0, 0, 0]), to: new Int32Array([3, 2, 1]) });
    expect(t.steps).toBe(3);
  });
});

describe('bad input', () => {
  const rejected = (options: Record<string, unknown>) => rejection(trace(options as typeof LINE));

  it('names the option at fault', async () => {
    expect((await rejected({ algorithm: 'regions', from: [0, 0], to: [1, 1] })).field).toBe('from');
    expect((await rejected({ algorithm: 'regions', from: [0, 0, 0], to: [1, 1] })).field).toBe('to');
    const outside = await rejected({ algorithm: 'regions', from: [0, 0, 0], to: [0, 2 ** 31, 0] });
    expect(outside.message).toBe('to: y must be -1073741824 to 1073741824, got 2147483648');
    expect(outside.axis).toBe(1);
    expect((await rejected({ algorithm: 'nope', from: [0, 0, 0], to: [1, 1, 1] })).field).toBe('algorithm');
    expect((await rejected({ ...LINE, tie: 'maybe' })).field).toBe('tie');
    expect((await rejected({ ...LINE, center: [1, 1, 1] })).field).toBe('center');
    expect((await rejected({ ...LINE, from: [0, Number.NaN, 0] })).message).toBe('from: y must be a number, got NaN');
    const long = await rejected({ ...LINE, to: [100000, 0, 0], maxSteps: 1000 });
    expect(long.field).toBe('maxSteps');
  });

  it("says a whole number outside its declared range in the words the catalogue gives the page's form", async () => {
    // The form checks each field as it is typed and says mustBe: one statement of the words, the core's.
    const { algorithms, experiments } = await catalogue();
    const cases = [
      ...algorithms.flatMap((a) => a.options.map((spec) => ({ spec, run: (v: number) => trace({ ...a.example.options, algorithm: a.id, [spec.name]: v } as TraceOptions) }))),
      ...experiments.flatMap((e) => e.options.map((spec) => ({ spec, run: (v: number) => randomLines({ algorithm: 'regions', [spec.name]: v }) }))),
    ];
    const said: string[] = [];
    for (const { spec, run } of cases) {
      if (spec.kind.type !== 'integer') continue;
      const { min, max, mustBe } = spec.kind;
      if (min === undefined && max === undefined) {
        expect(mustBe, spec.name).toBeUndefined();
        continue;
      }
      for (const outside of [min === undefined ? undefined : min - 1, max === undefined ? undefined : max + 1]) {
        if (outside === undefined) continue;
        const error = await rejection(run(outside));
        expect([error.field, error.message]).toEqual([spec.name, `${spec.name}: ${mustBe}, got ${outside}`]);
        said.push(error.message);
      }
    }
    // Both bounds (liu-float's decimals; random-lines' count, maxCoordinate and seed, whose upper bound is the
    // largest whole number the core reads exactly); maxSteps and an arc's turns, which the core held to ranges
    // their specs did not declare.
    expect(said).toEqual(
      expect.arrayContaining([
        'decimals: must be 0 to 10, got 11',
        'count: must be 1 to 100000, got 0',
        'seed: must be 0 to 8999999999999999, got -1',
        'seed: must be 0 to 8999999999999999, got 9000000000000000',
        'maxSteps: must be 0 to 1000000000, got 1000000001',
        'turns: must be 0 to 1000000, got -1',
      ]),
    );
  });

  it('keeps working after an error', async () => {
    await rejected({ algorithm: 'regions', from: [0], to: [1] });
    expect((await trace(LINE)).steps).toBe(10);
  });
});

describe('algorithms()', () => {
  it('describes regions with its citation, columns and options', async () => {
    const regions = (await algorithms()).find((a) => a.id === 'regions')!;
    expect(regions.citation).toContain('Wang');
    expect(regions.columns.map((c) => c.name)).toEqual(['M', 'N', 'region', 'corner', 'tie', 'faceU', 'faceV', 'faceUAxis', 'faceVAxis']);
    expect(regions.options.map((o) => o.name)).toEqual(['from', 'to', 'tie', 'gcd', 'maxSteps']);
    expect(regions.family).toBe('line');
    expect(regions.defaultTie).toBe('advance');
    expect(regions.errata.some((e) => e.includes('Table 2'))).toBe(true);
  });
});

describe('column names (README, Conventions)', () => {
  // A column name is camelCase, a per-axis quantity ends in its axis in
  // upper case, and a single capital letter is a paper's symbol (Wang's M, N).
  const CAMEL = /^([a-z][a-zA-Z0-9]*|[A-Z])$/;

  it('every column and option of every algorithm follows the convention', async () => {
    for (const a of await algorithms()) {
      for (const c of a.columns) expect(c.name, `${a.id}: ${c.name}`).toMatch(CAMEL);
      for (const o of a.options) expect(o.name, `${a.id}: ${o.name}`).toMatch(CAMEL);
    }
  });

  it('a renamed column declares its former name, and decisions still answer to it, deprecated', async () => {
    const regions = (await algorithms()).find((a) => a.id === 'regions')!;
    expect(regions.columns.filter((c) => c.formerName).map((c) => [c.formerName, c.name])).toEqual([
      ['face_u', 'faceU'],
      ['face_v', 'faceV'],
      ['face_u_axis', 'faceUAxis'],
      ['face_v_axis', 'faceVAxis'],
    ]);
    const t = await trace(LINE);
    expect(t.decisions.face_u).toBe(t.decisions.faceU);
    const range = t.decisionsInRange(2, 5);
    expect(Array.from(range.face_v_axis!)).toEqual(Array.from(range.faceVAxis!));
    // The old names are read, never listed: JSON and CSV carry the new ones only.
    expect(Object.keys(range)).toEqual(regions.columns.map((c) => c.name));
    expect(Object.keys(traceToJson(t).decisions)).not.toContain('face_u');
    expect(traceToCsv(t).split('\n')[0]).not.toContain('face_u');
    // A column that was never renamed has no former name, and no alias.
    expect(regions.columns.find((c) => c.name === 'M')!.formerName).toBeUndefined();
    const nd = await trace({ algorithm: 'nd', from: [0, 0, 0, 0], to: [9, 4, 2, 1] });
    expect(Array.from(nd.decisions.Dy!)).toEqual(Array.from(nd.decisions.discriminantY!));
  });

  it('the columns a figure draws as error terms and threshold say so by role', async () => {
    const roles = Object.fromEntries(
      (await algorithms()).map((a) => [a.id, a.columns.filter((c) => c.role).map((c) => `${c.name}:${c.role}`)]),
    );
    expect(roles.bresenham3d).toEqual(['errorX:errorTerm', 'errorY:errorTerm', 'errorZ:errorTerm', 'threshold:threshold']);
    expect(roles.bresenham2d).toEqual(['error:errorTerm', 'threshold:threshold']);
    expect(roles.regions).toEqual([]);
  });
});

describe('decision values that do not apply to a step', () => {
  // A G-code program's trace has the columns of its line and its arc
  // algorithm. G1 to (4, 2) steps at 4 steps/mm, then G2 about (4, 0) to
  // (4, -2): steps 0-3 are regions' (no octant: NO_VALUE, not octant "1"),
  // steps 4-9 Saleem's circle's (no region: NO_VALUE, not region "a").
  const PROGRAM = 'G21 G90\nG1 X1 Y0.5\nG2 X1 Y-0.5 I0 J-0.5\n';

  it('hold NO_VALUE in category and flag columns, NaN in number columns', async () => {
    const t = (await runGcode(PROGRAM, { stepsPerMm: 4 })).trace;
    expect(t.steps).toBe(10);
    expect(Array.from(t.decisions.octant!.subarray(0, 4))).toEqual([NO_VALUE, NO_VALUE, NO_VALUE, NO_VALUE]);
    expect(Array.from(t.decisions.slowSteps!.subarray(0, 4))).toEqual([NO_VALUE, NO_VALUE, NO_VALUE, NO_VALUE]);
    expect(Array.from(t.decisions.region!.subarray(4))).toEqual(Array(6).fill(NO_VALUE));
    expect(Array.from(t.decisions.tie!.subarray(4))).toEqual(Array(6).fill(NO_VALUE));
    expect(Array.from(t.decisions.M!.subarray(4)).every(Number.isNaN)).toBe(true);
    // Where a column does apply, its values are labels and flags as usual.
    const octant = t.columns.find((c) => c.name === 'octant')!;
    expect(readDecision(octant, t.decisions.octant![4]!)).toBe('2');
    expect(readDecision(octant, NO_VALUE)).toBeNull();
  });

  it('read as null in JSON, empty in CSV and - in a table', async () => {
    const t = (await runGcode(PROGRAM, { stepsPerMm: 4 })).trace;
    const json = traceToJson(t).decisions;
    expect(json.octant!.slice(0, 5)).toEqual([null, null, null, null, '2']);
    expect(json.region!.slice(3, 5)).toEqual(['b', null]);
    expect(json.tie!.slice(3, 5)).toEqual([false, null]);
    const csv = traceToCsv(t).split('\n');
    expect(csv[0]).toBe('k,x,y,z,M,N,region,corner,tie,faceU,faceV,faceUAxis,faceVAxis,octant,fast,residualStay,residualMove,slowSteps,correction,otherCandidate,deviation');
    // Row 0 has no decision yet; row 1 is regions' step, row 5 the circle's
    // first. Regions on (0,0,0)->(4,2,0): M = 2·2 - 4 = 0 and N = 2·0 - 4 = -4
    // (eq. 10), so the line crosses the exit face at (0, -4/8) (M and N over 2|Δx|).
    expect(csv[1]).toBe('0,0,0,0,,,,,,,,,,,,,,,,,0.000000');
    expect(csv[2]).toBe('1,1,1,0,0,-4,e,A,1,0,-0.5,+y,+z,,,,,,,,0.447214');
    // The circle's first step, G2 about (4, 0) from (4, 2): x
    // steps to (5, 2), residual 1 + 4 - 4 = 1, rather than on to (5, 1),
    // 1 + 1 - 4 = -2 (Saleem eq. 6-7), which is one cell toward -y.
    expect(csv[6]).toBe('5,5,2,0,,,,,,,,,,2,x,1,-2,0,0,-y,0.236068');
    const table = traceToTable(t).split('\n');
    expect(table.find((row) => /^ *1 +1 +1 +0 /.test(row))).toMatch(/ 0 +-4 +e +A +1 +0 +-0\.5 +\+y +\+z +- +- +- +- +- +- +- +0\.447214$/);
    expect(table.find((row) => /^ *5 +5 +2 +0 /.test(row))).toMatch(/ - +- +- +- +- +- +- +- +- +2 +x +1 +-2 +0 +0 +-y +0\.236068$/);
  });
});
