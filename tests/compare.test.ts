// compare(): two algorithms on one move, through the built wasm package and
// the CLI. Golden values: SEED-NOTES (Saleem holds the tie of step 5 on
// (0,0,0)->(10,7,6) and goes to (5,3,3) where Wang's M = 0 advances to
// (5,4,3)); the circle r = 5 quarter of Saleem eq. 7-11 against its single
// chord, as worked in rust/src/compare.rs.
import { describe, expect, it } from 'vitest';
import { compare, comparisonToCsv, trace, VoxpathError } from '../web/core/index.js';
import type { AlgorithmId } from '../web/core/index.js';
import { rejection, voxpath } from './helpers.js';

const LINE = { from: [0, 0, 0], to: [10, 7, 6] };
const QUARTER = { from: [5, 0, 0], to: [0, 5, 0], center: [0, 0, 0] };

/** `voxpath compare ...args`. */
const voxpathCompare = (...args: string[]) => voxpath(['compare', ...args]);

describe('compare()', () => {
  it('finds where Wang and Saleem part, and why each stepped as it did', async () => {
    const c = await compare({ algorithms: ['regions', 'bresenham3d'], ...LINE });
    expect([c.a.algorithm, c.b.algorithm]).toEqual(['regions', 'bresenham3d']);
    expect([c.a.steps, c.b.steps]).toEqual([10, 10]);
    const d = c.firstDifference!;
    expect(d.pointIndex).toBe(5);
    expect([d.a, d.b]).toEqual([
      [5, 4, 3],
      [5, 3, 3],
    ]);
    expect(d.aWhy!.stepIndex).toBe(4);
    expect(d.aWhy!.decisions).toEqual({ M: 0, N: 10, region: 'g', corner: 'D', tie: true, faceU: 0, faceV: 0.5, faceUAxis: '+y', faceVAxis: '+z' });
    expect(Object.keys(d.aWhy!.decisions)).toEqual(['M', 'N', 'region', 'corner', 'tie', 'faceU', 'faceV', 'faceUAxis', 'faceVAxis']);
    expect(d.bWhy!.decisions).toMatchObject({ errorX: null, errorY: 10, errorZ: 20, threshold: 10, major: 'x', tie: true });
    // The explanations are the traces' own.
    const [a, b] = await Promise.all([trace({ algorithm: 'regions', ...LINE }), trace({ algorithm: 'bresenham3d', ...LINE })]);
    expect(d.aWhy!.explanation).toBe(a.explain(4));
    expect(d.bWhy!.explanation).toBe(b.explain(4));
    expect(d.bWhy!.explanation).toContain("errorY = 10 = 10 (a tie), and the tie policy 'hold' says y holds");
    expect(c.onlyInA).toEqual({ count: 1, cells: [[5, 4, 3]] });
    expect(c.onlyInB).toEqual({ count: 1, cells: [[5, 3, 3]] });
    expect(c.a.metrics).toEqual(a.metrics);
  });

  it('gives each shared option to the algorithms that declare it', async () => {
    // tie: both declare it, so both hold and the paths agree.
    expect((await compare({ algorithms: ['regions', 'bresenham3d'], ...LINE, tie: 'hold' })).firstDifference).toBeNull();
    // segmentLength: only arc-segments declares it. One chord of the quarter
    // circle against the circle itself: 5 diagonal steps against 7.
    const c = await compare({ algorithms: ['circle', 'arc-segments'], ...QUARTER, segmentLength: 100 });
    expect([c.a.steps, c.b.steps]).toEqual([7, 5]);
    expect(c.firstDifference!.pointIndex).toBe(1);
    expect([c.firstDifference!.a, c.firstDifference!.b]).toEqual([
      [5, 1, 0],
      [4, 1, 0],
    ]);
    expect(c.firstDifference!.aWhy!.decisions).toMatchObject({ octant: '1', fast: 'y', residualStay: 1, residualMove: -8, otherCandidate: '-x' });
    expect(c.onlyInA.cells).toEqual([
      [5, 1, 0],
      [5, 2, 0],
      [4, 3, 0],
      [3, 4, 0],
      [2, 5, 0],
      [1, 5, 0],
    ]);
    expect(c.onlyInB.cells).toEqual([
      [4, 1, 0],
      [3, 2, 0],
      [2, 3, 0],
      [1, 4, 0],
    ]);
    // Largest radial error: circle (5,2), sqrt(29) - 5; chord (3,2), 5 - sqrt(13).
    expect(c.a.metrics.maxDeviation).toBeCloseTo(Math.sqrt(29) - 5, 12);
    expect(c.b.metrics.maxDeviation).toBeCloseTo(5 - Math.sqrt(13), 12);
  });

  it('names the option at fault', async () => {
    const rejected = (options: Record<string, unknown>) => rejection(compare(options as Parameters<typeof compare>[0]));
    const neither = await rejected({ algorithms: ['circle', 'arc-segments'], ...QUARTER, gcd: true });
    expect(neither.field).toBe('gcd');
    expect(neither.detail).toMatch(/^neither circle nor arc-segments takes this option/);
    const missing = await rejected({ algorithms: ['circle', 'arc-segments'], from: [5, 0, 0], to: [0, 5, 0] });
    expect([missing.field, missing.detail]).toEqual(['center', 'circle: missing: give one integer per axis, e.g. [0, 0, 0]']);
    expect((await rejected({ algorithms: ['regions'], ...LINE })).field).toBe('algorithms');
    expect((await rejected({ algorithms: ['regions', 'nope'], ...LINE })).field).toBe('algorithms');
  });

  it('compares traces already computed, with every differing cell', async () => {
    // The same answer as compare() for the same two moves, from the traces
    // the page's worker holds; and the full cell lists, here past the 1000
    // compare() lists: regions takes 3000 steps of up to three axes on
    // (0,0,0)->(3000,2000,1000), greedy 6000 of one axis.
    const [a, b] = await Promise.all([trace({ algorithm: 'regions', ...LINE }), trace({ algorithm: 'bresenham3d', ...LINE })]);
    expect(a.compareWith(b)).toEqual(await compare({ algorithms: ['regions', 'bresenham3d'], ...LINE }));
    expect(Array.from(a.cellsOnlyIn(b))).toEqual([5, 4, 3]);

    const LONG = { from: [0, 0, 0], to: [3000, 2000, 1000] };
    const [r, g] = await Promise.all([trace({ algorithm: 'regions', ...LONG }), trace({ algorithm: 'greedy', ...LONG })]);
    const c = r.compareWith(g);
    const onlyInGreedy = g.cellsOnlyIn(r);
    expect(c.onlyInB.count).toBeGreaterThan(1000);
    expect(onlyInGreedy.length).toBe(3 * c.onlyInB.count);
    expect(Array.from(onlyInGreedy.subarray(0, 3000))).toEqual(c.onlyInB.cells.flat());
    // Checked against the points themselves: no listed cell is on the regions path.
    const onRegions = new Set<string>();
    for (let k = 0; k <= r.steps; k++) onRegions.add(r.point(k).join(','));
    let listedOnRegions = 0;
    for (let i = 0; i < onlyInGreedy.length; i += 3) if (onRegions.has(onlyInGreedy.subarray(i, i + 3).join(','))) listedOnRegions++;
    expect(listedOnRegions).toBe(0);
    const flat = await trace({ algorithm: 'bresenham2d', from: [0, 0], to: [5, 3] });
    expect(() => r.compareWith(flat)).toThrow(VoxpathError);
  });

  it('refuses traces on different axes, naming other (cellsOnlyIn read 2-axis cells with stride 3)', async () => {
    const [line3, line2] = await Promise.all([trace({ algorithm: 'nd', from: [0, 0, 0], to: [4, 0, 0] }), trace({ algorithm: 'nd', from: [0, 0], to: [6, 0] })]);
    for (const [a, b, message] of [
      [line3, line2, 'other: has 2 axes but this trace has 3'],
      [line2, line3, 'other: has 3 axes but this trace has 2'],
    ] as const) {
      for (const call of [() => a.compareWith(b), () => a.cellsOnlyIn(b)]) {
        expect(call).toThrow(VoxpathError);
        expect(call).toThrow(expect.objectContaining({ field: 'other', message }));
      }
    }
  });
});

describe('voxpath compare', () => {
  const ARGS = ['--algorithms', 'regions,bresenham3d', '--from', '0,0,0', '--to', '10,7,6'];

  it('prints the comparison as JSON by default', () => {
    const r = voxpathCompare(...ARGS);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out.firstDifference.pointIndex).toBe(5);
    expect(out.firstDifference.aWhy.decisions.region).toBe('g');
    expect(out.onlyInB.count).toBe(1);
  });

  it('prints a table for people and CSV rows per quantity', () => {
    const table = voxpathCompare(...ARGS, '--format', 'table').stdout;
    expect(table).toMatch(/^steps +10 +10$/m);
    expect(table).toContain('First difference: point 5 (after 5 steps): regions (5, 4, 3), bresenham3d (5, 3, 3).');
    expect(table).toContain("the tie policy 'advance' decides");
    expect(table).toContain('M = 0, N = 10, region = g, corner = D, tie = true');
    expect(table).toContain("the tie policy 'hold' says y holds");
    expect(table).toContain('Cells only in bresenham3d (1): (5, 3, 3)');
    const csv = voxpathCompare(...ARGS, '--format', 'csv').stdout.trim().split('\n');
    expect(csv[0]).toBe('quantity,regions,bresenham3d');
    expect(csv).toContain('first difference at point,5,5');
    expect(csv).toContain('point there,"(5, 4, 3)","(5, 3, 3)"');
  });

  it('runs the helix against itself by its other method, the chord flags on the chords only', async () => {
    const helix = ['--from', '30,0,0', '--to', '0,30,20', '--center', '0,0,0'];
    const r = voxpathCompare('--algorithms', 'helix,helix', ...helix, '--method', 'segments', '--segment-length', '10', '--format', 'json');
    expect(r.code).toBe(0);
    const c = JSON.parse(r.stdout) as Awaited<ReturnType<typeof compare>>;
    expect([c.a.comparedValue, c.b.comparedValue]).toEqual(['segments', 'saleem']);
    // Each side as the API traces it alone: chords of length 10 on a (which
    // Saleem's method would refuse), Saleem's rule on b.
    const move = { from: [30, 0, 0], to: [0, 30, 20], center: [0, 0, 0] };
    const [chords, saleem] = await Promise.all([trace({ algorithm: 'helix', ...move, method: 'segments', segmentLength: 10 }), trace({ algorithm: 'helix', ...move })]);
    expect([c.a.steps, c.b.steps]).toEqual([chords.steps, saleem.steps]);
    expect(chords.segments).toHaveLength(4);
    chords.free();
    saleem.free();
    const table = voxpathCompare('--algorithms', 'helix,helix', ...helix, '--format', 'table').stdout;
    expect(table).toMatch(/^compare helix \(saleem\) \(a\) with helix \(segments\) \(b\)/);
    expect(table).toMatch(/^ +helix \(saleem\) +helix \(segments\)$/m);
    // Two algorithms: no value tells the sides apart.
    expect((await compare({ algorithms: ['regions', 'bresenham3d'], ...LINE })).a.comparedValue).toBeNull();
  });

  it('takes the flags of both algorithms', () => {
    const r = voxpathCompare('--algorithms', 'circle,arc-segments', '--from', '5,0,0', '--to', '0,5,0', '--center', '0,0,0', '--segment-length', '100');
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout).b.steps).toBe(5);
  });

  it.each([
    [['--from', '0,0,0', '--to', '1,1,1'], /^voxpath: --algorithms is required/],
    // --algorithm for --algorithms was not named.
    [['--algorithm', 'regions,nd', '--from', '0,0,0', '--to', '1,1,1'], /^voxpath: --algorithms is required \(.*\); --algorithm is not a flag of compare$/],
    [['--algorithms', 'regions', ...ARGS.slice(2)], /^voxpath: --algorithms: expected two ids separated by a comma, got 'regions'/],
    [['--algorithms', 'regions,bogus', ...ARGS.slice(2)], /^voxpath: --algorithms: unknown algorithm 'bogus'/],
    [[...ARGS, '--center', '0,0,0'], /^voxpath: unknown flag --center for compare regions,bresenham3d/],
    [['--algorithms', 'circle,arc-segments', '--from', '5,0,0', '--to', '0,5,0'], /^voxpath: --center: circle: missing/],
    [[...ARGS, '--format', 'xml'], /^voxpath: --format: expected json, csv or table, got 'xml'/],
  ])('rejects %j with a one-line error naming the flag, exit 2', (args, message) => {
    const r = voxpathCompare(...args);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe('');
    const [first, second] = r.stderr.split('\n');
    expect(first).toMatch(message);
    expect(second).toMatch(/^usage: voxpath trace/);
  });
});

describe('comparisonToCsv', () => {
  it('quotes a cell holding a lone CR, as it quotes one holding LF', async () => {
    const c = await compare({ algorithms: ['regions', 'bresenham3d'], from: [0, 0, 0], to: [10, 7, 6] });
    const header = comparisonToCsv({ ...c, a: { ...c.a, algorithm: 'a\rb' as AlgorithmId } }).split('\n')[0];
    expect(header).toBe('quantity,"a\rb",bresenham3d');
  });
});
