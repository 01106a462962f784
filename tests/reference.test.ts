// The bench's plain TypeScript references (bench/reference) take exactly the
// core's steps, so `npm run bench` compares like with like: on lines of every
// direction and type, and on arcs and helices in every plane and direction.
import { readdirSync, readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { REFERENCES } from '../bench/reference/index.js';
import type { ReferenceOptions } from '../bench/reference/index.js';
import { algorithms, trace } from '../web/core/index.js';
import type { AlgorithmId } from '../web/core/index.js';
import { everyDirection, inPlane, PLANES, randomLines } from './helpers.js';

/** Every sign pattern of `magnitudes`, as moves from `from`. */
const moves = (from: number[], magnitudes: number[]): ReferenceOptions[] => everyDirection(from, magnitudes).map((to) => ({ from, to }));

// Lines of all seven of Wang's types (ties included: (10,7,6) has M = 0 at
// step 5; (6,4,2) repeats with GCD 2), long ones crossing checkpoints, and
// zero-length and axis-parallel moves.
const LINES_3D = [
  [10, 7, 6],
  [6, 4, 2],
  [4, 4, 4],
  [5, 5, 1],
  [0, 3, 3],
  [1, 6, 2],
  [2, 3, 7],
  [9, 0, 0],
  [0, 0, 0],
  [12345, 6789, 2345],
].flatMap((m) => moves([3, -2, 5], m));
const LINES_2D = [
  [8, 3],
  [3, 8],
  [5, 5],
  [7, 0],
  [10, 3],
  [9999, 4321],
].flatMap((m) => moves([-4, 1], m));
const LINES_ND = [
  [7, 3, 5, 1],
  [6, 6, 2, 0, 9],
  [3, 1, 4, 1, 5, 9],
].flatMap((m) => moves(m.map(() => 0), m).slice(0, 8));

const RANDOM_3D = randomLines(13, 24, 3, 20_000);
const RANDOM_2D = randomLines(17, 24, 2, 20_000);
const RANDOM_ND = [4, 5, 6].flatMap((dims) => randomLines(19 + dims, 8, dims, 5_000));

/** An arc given in plane coordinates, in every plane and both directions. */
function everyPlane(from: number[], to: number[], center: number[], extra: Record<string, unknown> = {}): ReferenceOptions[] {
  return PLANES.flatMap((plane) =>
    ['ccw', 'cw'].map((dir) => ({
      from: inPlane(plane, from),
      to: inPlane(plane, to),
      center: inPlane(plane, center),
      plane,
      dir,
      ...extra,
    })),
  );
}

const ARCS: ReferenceOptions[] = [
  // Saleem's r = 5 quarter.
  ...everyPlane([5, 0, 0], [0, 5, 0], [0, 0, 0]),
  // r = 207 around (100, -41); the end (-146, 147) from the center is
  // 207.18 away, off the circle: correction steps close the gap.
  ...everyPlane([307, -41, 12], [-46, 106, 12], [100, -41, 0]),
  // One full turn of r = sqrt(1300) (end = start, as the bench's circle),
  // and two.
  ...everyPlane([40, 20, 30], [40, 20, 30], [10, 0, 0]),
  ...everyPlane([40, 20, 30], [40, 20, 30], [10, 0, 0], { turns: 1 }),
  // A full turn of r = 3000: long enough to cross the core's checkpoints.
  ...everyPlane([3000, 0, 7], [3000, 0, 7], [0, 0, 7]),
];
const HELICES: ReferenceOptions[] = [
  ...everyPlane([300, 0, 0], [0, 300, 77], [0, 0, 0]),
  ...everyPlane([20, 0, 0], [20, 0, 900], [0, 0, 0], { turns: 2 }),
  ...everyPlane([50, 0, 10], [0, -50, -40], [0, 0, 10]),
];

const CASES: [AlgorithmId, ReferenceOptions[]][] = [
  ['regions', [...LINES_3D, ...RANDOM_3D]],
  ['bresenham3d', [...LINES_3D, ...RANDOM_3D]],
  ['nd', [...LINES_3D, ...LINES_2D, ...LINES_ND, ...RANDOM_3D, ...RANDOM_2D, ...RANDOM_ND]],
  ['liu-float', LINES_3D],
  ['greedy', [...LINES_3D, ...LINES_2D, ...LINES_ND]],
  ['walk6', [...LINES_3D, ...LINES_2D, ...LINES_ND]],
  ['dda', [...LINES_3D, ...LINES_2D, ...LINES_ND]],
  ['bresenham2d', [...LINES_2D, ...RANDOM_2D]],
  ['circle', ARCS],
  ['arc-segments', [...ARCS, ...ARCS.map((a) => ({ ...a, segmentLength: 3 }))]],
  ['helix', [...HELICES, ...HELICES.map((h) => ({ ...h, method: 'segments', tolerance: 0.25 }))]],
];

/** Steps compared per algorithm, at least: the moves above give far more. */
const MIN_STEPS_COMPARED = 10_000;

describe('bench references take the core\'s steps', () => {
  it.each(CASES)('%s', async (algorithm, moves) => {
    const reference = REFERENCES[algorithm]!;
    let stepsCompared = 0;
    for (const options of moves) {
      const t = await trace({ algorithm, ...options });
      const core = t.stepCodes(0, t.steps);
      t.free();
      const mine = reference(options);
      expect(mine.length, JSON.stringify(options)).toBe(core.length);
      // Compared as one value per array: a failure names the move, not a step.
      const firstDifference = mine.findIndex((code, k) => code !== core[k]);
      expect(firstDifference, JSON.stringify(options)).toBe(-1);
      stepsCompared += core.length;
    }
    // Not vacuous: many moves, and paths long enough to say something.
    expect(moves.length).toBeGreaterThanOrEqual(18);
    expect(stepsCompared).toBeGreaterThanOrEqual(MIN_STEPS_COMPARED);
  });

  it('covers every algorithm of the catalogue, each checked above', async () => {
    const ids = (await algorithms()).map((a) => a.id).sort();
    expect(Object.keys(REFERENCES).sort()).toEqual(ids);
    expect(CASES.map(([id]) => id).sort()).toEqual(ids);
  });

  it('are independent of the core: no reference imports it', () => {
    const folder = new URL('../bench/reference/', import.meta.url);
    const files = readdirSync(folder).filter((f) => f.endsWith('.ts'));
    expect(files.length).toBeGreaterThanOrEqual(Object.keys(REFERENCES).length);
    for (const file of files) {
      const imports = [...readFileSync(new URL(file, folder), 'utf8').matchAll(/from '([^']+)'/g)].map((m) => m[1]);
      // Only one another: './common.js', './arc.js', ...
      expect(imports.filter((path) => !path!.startsWith('./')), file).toEqual([]);
    }
  });

  it('refuses options it does not implement instead of stepping another path', () => {
    expect(() => REFERENCES.regions!({ from: [0, 0, 0], to: [1, 2, 3], tie: 'hold' })).toThrow(/does not take tie/);
    expect(() => REFERENCES.circle!({ from: [2 ** 25, 0, 0], to: [2 ** 25, 0, 0], center: [0, 0, 0] })).toThrow(/below 2\^25/);
  });
});
