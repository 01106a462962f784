// checkPoints, `voxpath check` and the voxpath/vitest matcher against the
// real wasm core: the done-when case (bresenham3d with tie = hold,
// checked against regions), the exercise's deliberate bug, and bad input.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';
import { expect as jestExpect } from 'expect';
import { describe, expect, it } from 'vitest';
import { checkPoints, checkToTable, readAndCheckPoints, readPoints, trace } from '../web/core/index.js';
import type { TraceOptions } from '../web/core/index.js';
import { voxpathMatchers } from '../web/core/vitest.js';
import type { VoxpathMatchers } from '../web/core/vitest.js';
import { bresenham3d } from '../examples/exercise-bresenham3d/bresenham3d.js';
import { pointsOf, rejection, voxpath } from './helpers.js';

declare module 'vitest' {
  // eslint-disable-next-line @typescript-eslint/no-empty-object-type
  interface Matchers<T = any> extends VoxpathMatchers {}
}

expect.extend(voxpathMatchers);
jestExpect.extend(voxpathMatchers);

const MOVE = { from: [0, 0, 0], to: [10, 7, 6] };
const REGIONS = { algorithm: 'regions', ...MOVE } satisfies TraceOptions;

/** The bresenham3d (tie = hold) path as the core traces it, as CSV text. */
async function holdPath(): Promise<{ rows: number[][]; csv: string }> {
  const t = await trace({ algorithm: 'bresenham3d', ...MOVE, tie: 'hold' });
  const rows = pointsOf(t);
  t.free();
  return { rows, csv: 'x,y,z\n' + rows.map((r) => r.join(',')).join('\n') + '\n' };
}

describe('checkPoints', () => {
  it('finds regions parting from bresenham3d with tie = hold at point 5, with regions\' reason', async () => {
    const { rows, csv } = await holdPath();
    const regions = await trace(REGIONS);
    const why = regions.explain(4);
    regions.free();
    for (const points of [rows, csv, { points: Int32Array.from(rows.flat()), dims: 3 }]) {
      const c = await checkPoints(REGIONS, points);
      expect(c.matches).toBe(false);
      expect(c.firstDifference?.pointIndex).toBe(5);
      expect(c.firstDifference?.why).toBe(why);
      expect(c.firstDifference?.decisions.region).toBe('g');
      expect(c.firstDifference?.decisions.tie).toBe(true);
      expect(c.alsoMatches.map((m) => m.label)).toContain('bresenham3d with tie = hold');
    }
  });

  it('checks an Int32Array as the same values in a Float64Array, to the ends of int32', async () => {
    // A path from int32's largest x, past the grid's +-2^30: the core reads
    // an Int32Array's values as they are, not widened to numbers first.
    const far = [2 ** 31 - 1, -(2 ** 31), 0];
    const rows = [far, [far[0]! - 1, far[1]! + 1, 1], [far[0]! - 2, far[1]! + 1, 2]];
    for (const path of [rows, (await holdPath()).rows]) {
      const values = path.flat();
      const asInts = await checkPoints(REGIONS, { points: Int32Array.from(values), dims: 3 });
      expect(asInts).toEqual(await checkPoints(REGIONS, { points: Float64Array.from(values), dims: 3 }));
      expect(asInts.matches).toBe(false);
    }
  });

  it('matches the rule\'s own path, and reports a short tail', async () => {
    const t = await trace(REGIONS);
    const rows = pointsOf(t);
    t.free();
    expect((await checkPoints(REGIONS, rows)).matches).toBe(true);
    const short = await checkPoints(REGIONS, rows.slice(0, 8));
    expect(short.firstDifference?.message).toBe(`your path stops at step 7 of ${rows.length - 1}`);
  });

  it('reads a spreadsheet\'s quoted label column, line breaks inside it included, and counts in words', async () => {
    const one = { algorithm: 'regions', from: [0, 0, 0], to: [1, 1, 1] } satisfies TraceOptions;
    const c = await checkPoints(one, 'x,y,z,note\n0,0,0,"start,\nthen ""up"""\n1,1,1,end\n');
    expect(c.matches).toBe(true);
    expect(checkToTable(c)).toMatch(/^regions: your 2 points follow the rule \(1 step\)\.\n/);
    expect((await rejection(checkPoints(one, 'x,y,z,note\n0,0,0,"start\n1,1,1,end\n'))).message).toBe(
      'line 2, column 7: a quote that is not closed: a quoted cell ends at its closing quote, which may stand on a later line',
    );
  });

  it('names the row of malformed input', async () => {
    const text = await rejection(checkPoints(REGIONS, '0,0,0\n1,1.5,1\n'));
    expect(text.message).toBe('line 2, column 3: point 1: y = 1.5 is not a whole number');
    // The argument is named whichever way the points came (a text's error had no field).
    expect([text.field, text.line, text.column]).toEqual(['points', 2, 3]);
    expect((await rejection(checkPoints(REGIONS, [[0, 0, 0], [1, 1]]))).field).toBe('points');
    expect((await rejection(readPoints('0,0,0\n1,1\n', 3))).field).toBe('text');
  });

  it('names a hole in a sparse array, row or coordinate, where it read 0', async () => {
    // Rows (0, _, 0), (1, _, 1), (2, _, 2), y missing, matched (0,0,0) -> (2,0,2).
    const row = (x: number, z: number) => {
      const p = new Array<number>(3);
      p[0] = x;
      p[2] = z;
      return p;
    };
    const request = { algorithm: 'regions', from: [0, 0, 0], to: [2, 0, 2] } satisfies TraceOptions;
    expect((await rejection(checkPoints(request, [row(0, 0), row(1, 1), row(2, 2)]))).message).toBe(
      'points: point 0: y must be a number, got an empty slot (a hole in a sparse array)',
    );
    // eslint-disable-next-line no-sparse-arrays
    const holed = [[0, 0, 0], [1, 1, 1], , [3, 3, 3]] as number[][];
    expect((await rejection(checkPoints({ algorithm: 'regions', from: [0, 0, 0], to: [3, 3, 3] }, holed))).message).toBe(
      'points: point 2 is an empty slot (a hole in a sparse array); expected an array of coordinates',
    );
  });

  it('names rows of no coordinates, which read as no points at all', async () => {
    for (const rows of [[[]], [[], []], [[], [0, 0, 0]]]) {
      expect((await rejection(checkPoints(REGIONS, rows))).message).toBe('points: point 0 has no coordinates (an empty array); a point has one per axis');
    }
    expect((await rejection(checkPoints(REGIONS, []))).message).toBe('points: there are no points');
  });

  it('says to await points handed over as a Promise', async () => {
    const error = await rejection(checkPoints(REGIONS, Promise.resolve([[0, 0, 0]]) as unknown as number[][]));
    expect(error.message).toBe('points: got a Promise, not the points: await it first (checkPoints(request, await points))');
  });

  it('reads text beyond ASCII as it reads ASCII (more UTF-8 bytes than characters)', async () => {
    const { rows, csv } = await holdPath();
    // A comment of 2-, 3- and 4-byte characters (the last two UTF-16 units) first.
    const text = '# pointés → 🎯\n' + csv;
    const plain = await checkPoints(REGIONS, csv);
    expect(await checkPoints(REGIONS, text)).toEqual(plain);
    expect(await readPoints(text, 3)).toEqual(Float64Array.from(rows.flat()));
    // A cell beyond ASCII is named with its line and column, in characters as written.
    expect((await rejection(checkPoints(REGIONS, '0,0,0\n1,é,1\n'))).message).toBe("line 2, column 3: point 1: y = 'é' is not a number");
    // Its UTF-8 bytes, as a file holds them, read as the text; bytes that
    // are not UTF-8 refused at their line and column, as runGcode's are.
    expect(await checkPoints(REGIONS, new TextEncoder().encode(text))).toEqual(plain);
    const latin1 = Uint8Array.from(Buffer.from('0,0,0\n1,1,1 \xe9\n', 'latin1'));
    const error = await rejection(checkPoints(REGIONS, latin1));
    expect([error.line, error.column]).toEqual([2, 7]);
    expect(error.message).toMatch(/not UTF-8 text/);
  });
});

describe('readAndCheckPoints', () => {
  it('hands the points read back as an Int32Array of the values in the text, to the ends of the grid and of int32', async () => {
    // A path (one cell or less a step) through the grid's ±2^30 and int32's
    // -2^31 and 2^31 - 1, far from the rule's: the check parts at point 0.
    const rows = [
      [2 ** 30, -(2 ** 30), 0],
      [2 ** 30 - 1, -(2 ** 30) + 1, 1],
      [2 ** 31 - 1, -(2 ** 31), 2 ** 30],
      [2 ** 31 - 2, -(2 ** 31) + 1, 2 ** 30 - 1],
    ];
    for (const text of [rows.slice(0, 2), rows.slice(2)].map((path) => path.map((r) => r.join(',')).join('\n'))) {
      const { check, points } = await readAndCheckPoints(REGIONS, text);
      expect(check.firstDifference?.kind).toBe('start');
      expect(points).toBeInstanceOf(Int32Array);
      expect(Array.from(points!)).toEqual(text.split('\n').flatMap((line) => line.split(',').map(Number)));
    }
  });

  it('gives null for points with a coordinate past int32, and still the check, which names it', async () => {
    for (const far of [2 ** 31, -(2 ** 31) - 1, 2 ** 53]) {
      const { check, points } = await readAndCheckPoints(REGIONS, `0,0,${far}\n1,1,${far - Math.sign(far)}\n`);
      expect(points).toBeNull();
      expect(check.firstDifference).toMatchObject({ kind: 'start', pointIndex: 0, got: [0, 0, far] });
    }
  });
});

describe('voxpath check', () => {
  it('exits 1 at point 5 with regions\' reason and names bresenham3d with tie = hold', async () => {
    const { csv } = await holdPath();
    const r = voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '-'], csv);
    expect(r.code).toBe(1);
    expect(r.stdout).toContain('at point 5');
    expect(r.stdout).toMatch(/segment g between C and D \(a tie\); the tie policy 'advance'/);
    expect(r.stdout).toMatch(/your points follow: .*bresenham3d with tie = hold/);
    const json = voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '--format', 'json', '-'], csv);
    expect(json.code).toBe(1);
    expect(JSON.parse(json.stdout).firstDifference.pointIndex).toBe(5);
    expect(r.stdout).toBe(checkToTable(JSON.parse(json.stdout)));
  });

  it('exits 0 on a match and 2 on bad input', async () => {
    const t = await trace(REGIONS);
    const csv = pointsOf(t).map((p) => p.join(' ')).join('\n');
    t.free();
    expect(voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '-'], csv).code).toBe(0);
    const bad = voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '-'], '0,0,0\n2,0,0\n');
    expect(bad.code).toBe(2);
    expect(bad.stderr).toContain('line 2, column 1: point 1 (2, 0, 0) is more than one cell from point 0');
  });

  it('aligns the markers of the points around the difference on their arrows', async () => {
    // The hold path parts at point 5 and rejoins at 6: moved off the rule at 6 too.
    const { rows } = await holdPath();
    const c = await checkPoints(REGIONS, rows);
    const around = c.firstDifference!.around.map((r) => (r.pointIndex === 6 ? { ...r, got: [6, 5, 4] } : r));
    const table = checkToTable({ ...c, firstDifference: { ...c.firstDifference!, around } }).split('\n');
    const marked = table.filter((l) => l.includes('<- '));
    expect(marked.length).toBeGreaterThan(1);
    // '<- differs' sat right-aligned under '<- first difference', its arrow 9 columns further right.
    expect(new Set(marked.map((l) => l.indexOf('<- '))).size).toBe(1);
  });

  it('reads --flag=value as --flag value, and FILE before, between or after the flags', async () => {
    const t = await trace(REGIONS);
    const csv = pointsOf(t).map((p) => p.join(',')).join('\n');
    t.free();
    // An odd count of '=' flags was read as a missing FILE (the arguments were counted in pairs).
    for (const args of [
      ['--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '--format=json', '-'],
      ['--algorithm=regions', '--from=0,0,0', '--to', '10,7,6', '-', '--format', 'json'],
      ['-', '--algorithm', 'regions', '--from', '0,0,0', '--to=10,7,6', '--format=json'],
    ]) {
      const r = voxpath(['check', ...args], csv);
      expect({ code: r.code, stderr: r.stderr }).toEqual({ code: 0, stderr: '' });
      expect(JSON.parse(r.stdout).matches).toBe(true);
    }
    expect(voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6']).stderr).toMatch(/^voxpath: check needs a FILE \(or - for standard input\)\n/);
    expect(voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', 'a.csv', 'b.csv']).stderr).toMatch(/^voxpath: check reads one FILE, got 'a.csv' and 'b.csv'\n/);
  });
});

describe('the voxpath/vitest matcher', () => {
  it('fails the exercise\'s buggy line at point 5 with the CLI\'s table, in vitest and in Jest\'s expect', async () => {
    const points = bresenham3d(MOVE.from, MOVE.to);
    const table = checkToTable(await checkPoints(REGIONS, points));
    expect(table).toContain('at point 5');
    await expect(expect(points).toFollowRule(REGIONS)).rejects.toThrow(table.trimEnd());
    await expect((jestExpect(points) as unknown as VoxpathMatchers).toFollowRule(REGIONS)).rejects.toThrow(/your points follow: .*bresenham3d with tie = hold/);
  });

  it('runs the exercise\'s own test as its README says (npx vitest run in its folder), failing at point 5', () => {
    // The exercise's test itself, not only its function: from the repository's root its folder held
    // no test vitest would find (the root config's projects take tests/ only).
    const folder = fileURLToPath(new URL('../examples/exercise-bresenham3d/', import.meta.url));
    const vitest = fileURLToPath(new URL('../node_modules/vitest/vitest.mjs', import.meta.url));
    // Without this run's VITEST* variables, as a student's shell has none.
    const env = Object.fromEntries(Object.entries(process.env).filter(([k]) => !k.startsWith('VITEST')));
    const run = spawnSync(process.execPath, [vitest, 'run', '--color=false'], { cwd: folder, env: { ...env, NO_COLOR: '1' }, encoding: 'utf8', timeout: 60_000 });
    const out = run.stdout + run.stderr;
    expect(out).not.toContain('No test files found');
    expect(out).toContain('at point 5 your path goes to (5, 3, 3); the rule goes to (5, 4, 3)');
    expect(out).toMatch(/your points follow: .*bresenham3d with tie = hold/);
    expect(run.status, out).toBe(1);
  });

  it('fails points that are not a path, saying why, so that .not passes them; a bad request or a Promise still throws', async () => {
    const skipping = [[0, 0, 0], [2, 2, 2], [10, 7, 6]];
    // It threw the VoxpathError, so .not threw too.
    await expect(expect(skipping).toFollowRule(REGIONS)).rejects.toThrow(
      'regions: your points are not a path, so they cannot follow the rule: points: point 1 (2, 2, 2) is more than one cell from point 0 (0, 0, 0)',
    );
    await expect(skipping).not.toFollowRule(REGIONS);
    await expect('0,0,0\n1,x,1\n').not.toFollowRule(REGIONS);
    const badRequest = expect(skipping).toFollowRule({ ...REGIONS, from: [0, 0] });
    await expect(badRequest).rejects.toThrow('from: regions takes 3 coordinates, got 2');
    await expect(expect(skipping).not.toFollowRule({ ...REGIONS, from: [0, 0] })).rejects.toThrow('from: regions takes 3 coordinates, got 2');
    await expect(expect(Promise.resolve(skipping)).toFollowRule(REGIONS)).rejects.toThrow(
      'points: got a Promise, not the points: await it first (expect(await points).toFollowRule(request))',
    );
    await expect(expect(Promise.resolve(skipping)).not.toFollowRule(REGIONS)).rejects.toThrow('got a Promise');
    // Nothing that could be points at all is a misuse, which throws: .not passed undefined, 5 or a bare
    // Int32Array without testing anything.
    for (const misuse of [undefined, null, 5, new Int32Array([0, 0, 0]), { points: [1] }]) {
      await expect(expect(misuse).not.toFollowRule(REGIONS), String(misuse)).rejects.toThrow(/^points: expected rows of coordinates, text \(a string, or its UTF-8 bytes in a Uint8Array\), or \{ points/);
    }
    // A request carrying an option named points is a bad request, not the learner's points.
    await expect(expect(skipping).not.toFollowRule({ ...REGIONS, points: 1 } as never)).rejects.toThrow(/^points: regions does not take this option/);
  });

  it('passes a fixed line', async () => {
    const t = await trace(REGIONS);
    const rows = pointsOf(t);
    t.free();
    await expect(rows).toFollowRule(REGIONS);
    // And as a file's bytes, as checkPoints takes them (readFileSync's Buffer): they were refused as no points.
    const csv = new TextEncoder().encode(rows.map((r) => r.join(',')).join('\n'));
    await expect(csv).toFollowRule(REGIONS);
    await expect(Buffer.from(csv)).toFollowRule(REGIONS);
  });
});
