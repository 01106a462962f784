// The CLI as users run it: `node bin/voxpath.js ...` (the compiled lib/, built by setup).
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { EXPORT_CHUNK_ROWS } from '../web/core/index.js';
import { BIN, voxpath, voxpathPipedInto } from './helpers.js';

const TRACE = ['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6'];

describe('voxpath trace', () => {
  it('prints one JSON object in the documented shape', () => {
    const r = voxpath([...TRACE, '--format', 'json']);
    expect(r.code).toBe(0);
    const out = JSON.parse(r.stdout);
    expect(out.algorithm).toBe('regions');
    expect(out.dims).toBe(3);
    expect(out.points).toHaveLength(11);
    expect(out.points[4]).toEqual([4, 3, 2]);
    // Wang eq. (8) from eq. (10)'s start: decisions.M[k] produced points[k + 1].
    expect(out.decisions.M).toEqual([4, -2, 12, 6, 0, -6, 8, 2, -4, 10]);
    expect(out.decisions.N).toEqual([2, -6, 6, -2, 10, 2, -6, 6, -2, 10]);
    expect(out.decisions.region).toEqual(['d', 'b', 'd', 'a', 'g', 'c', 'a', 'd', 'b', 'd']);
    expect(out.deviation).toHaveLength(11);
    expect(out.deviation[0]).toBe(0);
    expect(out.metrics.steps).toBe(10);
    expect(out.metrics.maxDeviation).toBe(Math.max(...out.deviation));
    expect(out.metrics.meanDeviation).toBeGreaterThan(0);
  });

  it('defaults to JSON and prints CSV and a table for people', () => {
    expect(JSON.parse(voxpath(TRACE).stdout).steps).toBe(10);
    const csv = voxpath([...TRACE, '--format', 'csv']).stdout.trim().split('\n');
    expect(csv[0]).toBe('k,x,y,z,M,N,region,corner,tie,faceU,faceV,faceUAxis,faceVAxis,deviation');
    expect(csv).toHaveLength(12);
    expect(csv[5]).toBe('4,4,3,2,6,-2,a,A,0,0.3,-0.1,+y,+z,0.441129');
    const table = voxpath([...TRACE, '--format', 'table']).stdout;
    expect(table).toContain('Line type ①');
    expect(table).toMatch(/deviation: max 0\.441129/);
  });

  it('passes algorithm options through generated flags', () => {
    const r = voxpath([...TRACE, '--tie', 'hold', '--max-steps', '100']);
    expect(JSON.parse(r.stdout).points[5]).toEqual([5, 3, 3]);
    // The cap reaches the core too: the 10-step line under 5 is refused, the flag named.
    const capped = voxpath([...TRACE, '--max-steps', '5']);
    expect(capped.code).toBe(2);
    expect(capped.stderr).toMatch(/^voxpath: --max-steps: the path needs more than 5 steps \(at least 10\)/);
  });

  it.each([
    [['trace', '--algorithm', 'regions', '--from', '0,0,0'], /^voxpath: --to: missing/],
    [[...TRACE, '--fro', '1'], /^voxpath: unknown flag --fro for regions/],
    [[...TRACE, '--format', 'xml'], /^voxpath: --format: expected json, csv or table, got 'xml'/],
    [['trace', '--algorithm', 'regions', '--from', '0,x,0', '--to', '1,1,1'], /^voxpath: --from: 'x' is not a finite decimal number/],
    [['trace', '--algorithm', 'regions', '--from', '0,0', '--to', '1,1'], /^voxpath: --from: regions takes 3 coordinates, got 2/],
    [['trace', '--algorithm', 'bogus', '--from', '0,0,0', '--to', '1,1,1'], /^voxpath: --algorithm: unknown algorithm 'bogus'/],
    [[...TRACE, '--tie'], /^voxpath: --tie needs a value/],
    // An unknown flag is told so wherever it stands: given last, or before another flag, it "needed a value".
    [[...TRACE, '--bogus'], /^voxpath: unknown flag --bogus for regions \(it takes --from, --to, /],
    [[...TRACE, '--bogus', '--tie', 'hold'], /^voxpath: unknown flag --bogus for regions/],
    [[...TRACE, '--format'], /^voxpath: --format needs a value/],
    [['trace', '--from', '0,0,0', '--to', '1,1,1', '--algorithm'], /^voxpath: --algorithm needs a value/],
    [['compare', '--algorithms', 'regions,greedy', '--from', '0,0,0', '--to', '1,1,1', '--bogus'], /^voxpath: unknown flag --bogus for compare regions,greedy/],
    [['experiment', 'random-lines', '--bogus'], /^voxpath: unknown flag --bogus for random-lines with regions/],
    [['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '1,1,1', '-', '--bogus'], /^voxpath: unknown flag --bogus for regions/],
    [['frobnicate'], /^voxpath: unknown command 'frobnicate'/],
    [['algorithms', '--format', 'json'], /^voxpath: algorithms takes no arguments, got '--format' 'json'/],
    [['experiment', 'random-lines', '--from', '1,1,1'], /^voxpath: unknown flag --from for random-lines with regions/],
    // What the user typed is quoted by its start when long (a 100 KB flag was said back whole).
    [[...TRACE, `--${'x'.repeat(100_000)}`, '1'], /^voxpath: unknown flag --xxxxxxxxxxxxxx\.\.\. \(100002 characters\) for regions \(it takes/],
    [['trace', '--algorithm', 'y'.repeat(100_000), '--from', '0,0,0', '--to', '1,1,1'], /^voxpath: --algorithm: unknown algorithm 'y{16}\.\.\. \(100000 characters\)' \(known: /],
  ])('rejects %j with a one-line error and usage, exit 2', (args, message) => {
    const r = voxpath(args);
    expect(r.code).toBe(2);
    expect(r.stdout).toBe('');
    const [first, second] = r.stderr.split('\n');
    expect(first).toMatch(message);
    expect(second).toMatch(/^usage: voxpath trace/);
  });

  it('prints the usage on stderr, status 2, without a command, and the version for --version and -V', () => {
    // It printed the whole --help text on stdout, with status 2.
    const none = voxpath([]);
    expect({ code: none.code, stdout: none.stdout }).toEqual({ code: 2, stdout: '' });
    expect(none.stderr).toMatch(/^voxpath: a command is needed \(voxpath --help describes each\)\nusage: voxpath trace/);
    const { version } = JSON.parse(readFileSync(new URL('../package.json', import.meta.url), 'utf8')) as { version: string };
    for (const flag of ['--version', '-V']) expect(voxpath([flag])).toEqual({ code: 0, stdout: `voxpath ${version}\n`, stderr: '' });
    expect(voxpath(['--help']).stdout).toContain('voxpath --help (-h) | --version (-V)');
    // -h was "unknown command '-h'", status 2.
    for (const args of [['-h'], ['trace', '-h']]) expect(voxpath(args)).toEqual(voxpath(['--help']));
  });

  it('documents every algorithm and option in --help', () => {
    const r = voxpath(['--help']);
    expect(r.code).toBe(0);
    expect(r.stdout).toContain('regions: Method of discriminate regions');
    expect(r.stdout).toContain('--max-steps N');
    expect(r.stdout).toContain('--tie advance|hold');
  });

  // A misspelt --algoritm was not named: the error said only '--algorithm is required'.
  it.each([
    [['trace', '--algoritm', 'regions', '--from', '0,0,0', '--to', '1,1,1'], 'voxpath: --algorithm is required; --algoritm is not a flag of trace'],
    [['check', '--algoritm', 'regions', '--from', '0,0,0', '--to', '1,1,1', 'points.csv'], 'voxpath: --algorithm is required; --algoritm is not a flag of check'],
    [['trace', '--from', '0,0,0', '--to', '1,1,1', '--tolerance', '1'], 'voxpath: --algorithm is required'],
  ])('names beside a missing --algorithm a flag no algorithm takes: %j', (args, first) => {
    const r = voxpath(args);
    expect(r.code).toBe(2);
    expect(r.stderr.split('\n')[0]).toBe(first);
  });
});

describe('voxpath reading numbers (issue 15 item 4)', () => {
  // Number() read '0x10' as 16, '0b11' as 3, '0o7' as 7 and ' ' as 0; a
  // number flag now takes decimal numbers only, and names the flag otherwise.
  it.each([
    [['--to', '0x10,0b11,0o7'], "--to: '0x10'"],
    [['--to', '10,0b11,6'], "--to: '0b11'"],
    [['--to', '10,7,0o7'], "--to: '0o7'"],
    [['--to', '10,7, '], "--to: ' '"],
    [['--to', '10,,6'], "--to: ''"],
    [['--to', 'Infinity,7,6'], "--to: 'Infinity'"],
    [['--to', '1e400,7,6'], "--to: '1e400'"],
    [['--to', '10,7,6', '--max-steps', '0x100'], "--max-steps: '0x100'"],
    [['--to', '10,7,6', '--max-steps='], "--max-steps: ''"],
    [['--to', '10,7,6', '--max-steps', '1_000'], "--max-steps: '1_000'"],
  ])('refuses %j, naming the flag', (args, named) => {
    const r = voxpath(['trace', '--algorithm', 'regions', '--from', '0,0,0', ...args]);
    expect([r.code, r.stdout]).toEqual([2, '']);
    expect(r.stderr.split('\n')[0]).toBe(`voxpath: ${named} is not a finite decimal number (such as 12, -3.5 or 1e6)`);
  });

  it('takes every argument after -- as a file, as POSIX utilities do (-- was an unexpected argument)', () => {
    const dir = mkdtempSync(join(tmpdir(), 'voxpath-cli-'));
    try {
      writeFileSync(join(dir, '--points.csv'), '0,0,0\n1,1,1\n');
      const run = (args: string[]) => spawnSync(process.execPath, [BIN, ...args], { encoding: 'utf8', cwd: dir });
      const check = ['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '1,1,1'];
      const named = run([...check, '--', '--points.csv']);
      expect([named.status, named.stderr]).toEqual([0, '']);
      expect(named.stdout).toBe(voxpath([...check, '-'], '0,0,0\n1,1,1\n').stdout);
      // Without --, the name is read as a flag; after it, -h is a file too.
      expect(run([...check, '--points.csv']).status).toBe(2);
      expect(run([...check, '--', '-h']).stderr.split('\n')[0]).toBe("voxpath: cannot read -h: ENOENT: no such file or directory, open '-h'");
      // gcode's FILE too, which before had to come first and so could not start with --.
      writeFileSync(join(dir, '--x.gcode'), 'G1 X1 F100\n');
      const gcode = run(['gcode', '--steps-per-mm', '80', '--format', 'json', '--', '--x.gcode']);
      expect([gcode.status, gcode.stderr, JSON.parse(gcode.stdout).pulses]).toEqual([0, '', [80, 0, 0]]);
    } finally {
      rmSync(dir, { recursive: true });
    }
  });

  it('refuses a machine setting written in hex as well', () => {
    const r = voxpath(['gcode', '-', '--steps-per-mm', '0x50'], 'G1 X1 F100\n');
    expect(r.code).toBe(2);
    expect(r.stderr.split('\n')[0]).toBe("voxpath: --steps-per-mm: '0x50' is not a finite decimal number (such as 12, -3.5 or 1e6)");
  });

  // Each of these reads as a whole number (1, 0, 8) that its text does not
  // write, and was traced from or stepped as that number.
  it.each([
    [['--from', '0.99999999999999999,0,0'], "--from: '0.99999999999999999' is not a whole number (as a double it rounds to 1)"],
    [['--from', '0,0,1e-400'], "--from: '1e-400' is not a whole number (as a double it rounds to 0)"],
    [['--from', '0,0,0', '--max-steps', '7.9999999999999999'], "--max-steps: '7.9999999999999999' is not a whole number (as a double it rounds to 8)"],
  ])('refuses %j, a whole number only as a double rounds it', (args, message) => {
    const r = voxpath(['trace', '--algorithm', 'regions', '--to', '10,7,6', ...args]);
    expect([r.code, r.stdout, r.stderr.split('\n')[0]]).toEqual([2, '', `voxpath: ${message}`]);
  });

  it('refuses a whole-number machine setting that only rounds to one, and takes a real one that does', () => {
    const bad = voxpath(['gcode', '-', '--step-angle', '1.8', '--microsteps', '8.0000000000000001', '--pitch', '2'], 'G1 X1 F100\n');
    expect([bad.code, bad.stderr.split('\n')[0]]).toEqual([2, "voxpath: --microsteps: '8.0000000000000001' is not a whole number (as a double it rounds to 8)"]);
    const real = voxpath(['gcode', '-', '--steps-per-mm', '80.0000000000000001', '--format', 'json'], 'G1 X1 F100\n');
    expect([real.code, JSON.parse(real.stdout).pulses]).toEqual([0, [80, 0, 0]]);
  });

  it('reads every decimal form exactly: signs, points, exponents, blanks around', () => {
    const r = voxpath(['trace', '--algorithm', 'regions', '--from', '-0,+0,0.', '--to', ' .1e2, 7.0 ,6e0', '--max-steps', '1e3']);
    expect(r.code).toBe(0);
    expect(JSON.parse(r.stdout).points.at(-1)).toEqual([10, 7, 6]);
    // A whole number written with an exponent is whole; out of its range, it is told so as typed.
    const big = voxpath(['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '--max-steps', '1e20']);
    expect(big.stderr.split('\n')[0]).toBe('voxpath: --max-steps: must be 0 to 1000000000, got 1e20');
  });

  // Each was told the double the core was handed (9.007199254740992e15 for
  // 9007199254740993, 100000000000000000000 for 1e20), not what was typed.
  it.each([
    [['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '9007199254740993,0,0'], '--to: x must be -1073741824 to 1073741824, got 9007199254740993'],
    [['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '0, 2e9 ,0'], '--to: y must be -1073741824 to 1073741824, got 2e9'],
    [['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '0,2.50,0'], '--to: y must be an integer number of grid units, got 2.50'],
    [['trace', '--algorithm', 'circle', '--from', '1,0', '--to', '1,0', '--center', '0,0', '--turns', '9007199254740993'], '--turns: must be 0 to 1000000, got 9007199254740993'],
    [['experiment', 'random-lines', '--seed', '18446744073709551615'], '--seed: must be 0 to 8999999999999999, got 18446744073709551615'],
    [['trace', '--algorithm', 'arc-segments', '--from', '1,0', '--to', '1,0', '--center', '0,0', '--tolerance', '-0.0'], '--tolerance: must be more than 0 grid units, got -0.0'],
    [['gcode', '-', '--steps-per-mm', '1,9007199254740993,1'], '--steps-per-mm: y must be 0.001 to 1000000 steps per mm, got 9007199254740993'],
    [['gcode', '-', '--steps-per-mm', '1e7'], '--steps-per-mm: must be 0.001 to 1000000 steps per mm, got 1e7'],
  ])('refuses %j out of its declared range, quoting the number as typed', (args, message) => {
    const r = voxpath(args, 'G1 X1 F100\n');
    expect([r.code, r.stdout, r.stderr.split('\n')[0]]).toEqual([2, '', `voxpath: ${message}`]);
  });

  // Where the range lets it through (dims has none; microsteps none above),
  // the core was handed 9007199254740992 and judged that, or took it.
  it.each([
    [['experiment', 'random-lines', '--dims', '9007199254740993'], '--dims'],
    [['experiment', 'random-lines', '--dims', '-1e16'], '--dims'],
    [['gcode', '-', '--step-angle', '1.8', '--pitch', '2', '--microsteps', '9007199254740993'], '--microsteps'],
  ])('refuses %j, a whole number past 2^53 - 1, which a double may not hold', (args, flag) => {
    const r = voxpath(args, 'G1 X1 F100\n');
    const typed = args.at(-1)!;
    const read = Number(typed);
    expect([r.code, r.stdout, r.stderr.split('\n')[0]]).toEqual([2, '', `voxpath: ${flag}: '${typed}' is past ±9007199254740991 (2^53 - 1), beyond which a double does not hold every whole number (it reads as ${read})`]);
  });
});

describe('voxpath writing into a pipe', () => {
  it('stops quietly, with status 0, when the reader closes the pipe early (| head)', () => {
    // 200,000 rows of CSV: far more than a pipe holds, so the CLI is still
    // writing when head has its two lines and exits.
    const r = voxpathPipedInto(['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '200000,7,6', '--format', 'csv'], 'head -n 2');
    expect(r).toEqual({ code: 0, stderr: '' });
  });

  it('keeps its exit status when stderr cannot be written (2 for a usage error, 1 for a program error)', () => {
    const run = (args: string, input = '') =>
      spawnSync('bash', ['-c', `'${process.execPath}' '${BIN}' ${args} 2> /dev/full`], { encoding: 'utf8', input }).status;
    expect(run('trace --bogus')).toBe(2);
    expect(run('gcode - --steps-per-mm 1 --format csv', 'G1 X1..5\n')).toBe(1);
  });

  it('says in one line that the output could not be written, with status 3, when the disk is full', () => {
    // The stream's 'error' event was rethrown outside main: a stack trace, status 1.
    const r = spawnSync('bash', ['-c', `'${process.execPath}' '${BIN}' ${TRACE.join(' ')} > /dev/full`], { encoding: 'utf8' });
    expect({ code: r.status, stderr: r.stderr }).toEqual({ code: 3, stderr: 'voxpath: cannot write the output: ENOSPC: no space left on device\n' });
  });
});

describe('voxpath trace: decision values that do not apply', () => {
  // Wang's type ② line (0,0,0) -> (3,3,3), section 2.2: every axis is
  // active, so no discriminant, region or corner decides a step.
  const TYPE_2 = ['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '3,3,3'];

  /**
   * The CLI on a V8 heap of 48 MB, its output counted by `wc`: a 2,000,000
   * step trace is about 90 MB of CSV and 50 MB of JSON text, so only output
   * written as it is read fits (built whole, the CSV's strings alone took
   * gigabytes for 10,000,000 steps).
   */
  function streamedLines(format: string, steps: number): { code: number; lines: number; stderr: string } {
    const args = ['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', `${steps},${Math.floor(steps * 0.7)},${Math.floor(steps * 0.6)}`, '--format', format];
    const quoted = [process.execPath, '--max-old-space-size=48', BIN, ...args].map((a) => `'${a}'`).join(' ');
    const r = spawnSync('bash', ['-c', `${quoted} | wc -l; echo "\${PIPESTATUS[0]}"`], { encoding: 'utf8' });
    const [lines, code] = r.stdout.trim().split('\n').map(Number);
    return { code: code!, lines: lines!, stderr: r.stderr };
  }

  it('streams a 2,000,000-step CSV and JSON in a heap smaller than either', { timeout: 120_000 }, () => {
    expect(streamedLines('csv', 2_000_000)).toEqual({ code: 0, lines: 2_000_002, stderr: '' });
    expect(streamedLines('json', 2_000_000)).toEqual({ code: 0, lines: 1, stderr: '' });
  });

  it('prints a table of any length, each block of rows aligned under its own header', () => {
    // Past 125,000 rows the table writer once overflowed the stack (Math.max(...rows)).
    const steps = 2 * EXPORT_CHUNK_ROWS + 10;
    const r = voxpath(['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', `${steps},0,0`, '--format', 'table']);
    expect(r.code).toBe(0);
    const lines = r.stdout.split('\n');
    const headers = lines.filter((l) => /^ *k +x +y +z +M /.test(l));
    expect(headers).toHaveLength(Math.ceil((steps + 1) / EXPORT_CHUNK_ROWS));
    expect(lines.filter((l) => /^ *\d+ +\d+ +0 +0 /.test(l))).toHaveLength(steps + 1);
    expect(r.stdout).toContain(`\nsteps moving: ${steps} x 1-axis`);
  });

  it('prints null in JSON, an empty cell in CSV and - in the table', () => {
    const json = JSON.parse(voxpath(TYPE_2).stdout);
    const none = [null, null, null];
    expect(json.decisions).toEqual({ M: none, N: none, region: none, corner: none, tie: [false, false, false], faceU: none, faceV: none, faceUAxis: none, faceVAxis: none });
    const csv = voxpath([...TYPE_2, '--format', 'csv']).stdout.trim().split('\n');
    expect(csv.slice(1)).toEqual(['0,0,0,0,,,,,,,,,,0.000000', '1,1,1,1,,,,,0,,,,,0.000000', '2,2,2,2,,,,,0,,,,,0.000000', '3,3,3,3,,,,,0,,,,,0.000000']);
    const table = voxpath([...TYPE_2, '--format', 'table']).stdout.split('\n');
    expect(table).toContainEqual(expect.stringMatching(/^1 +1 +1 +1 +- +- +- +- +0 +- +- +- +- +0\.000000$/));
    // Row 0 has no decision yet: blank, not '-'.
    expect(table).toContainEqual(expect.stringMatching(/^0 +0 +0 +0 +0\.000000$/));
  });
});

describe("voxpath's messages in the command line's words", () => {
  it('names the options a message names by their flags, and writes an example point as a flag takes it', () => {
    const first = (args: string[], input?: string) => {
      const r = spawnSync(process.execPath, [BIN, ...args], { encoding: 'utf8', input, timeout: 20_000 });
      expect(r.status, r.stderr).toBe(2);
      return r.stderr.split('\n')[0];
    };
    // The core's words are the API's: "give segmentLength or tolerance", "raise maxSteps", "e.g. [0, 0, 0]".
    expect(first(['trace', '--algorithm', 'arc-segments', '--from', '20,0,0', '--to', '-20,0,0', '--center', '0,0,0', '--dir', 'ccw', '--segment-length', '8', '--tolerance', '0.1'])).toBe(
      'voxpath: --tolerance: give --segment-length or --tolerance, not both',
    );
    expect(first(['trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '100000000,0,0', '--max-steps', '10'])).toBe(
      'voxpath: --max-steps: the path needs more than 10 steps (at least 100000000); raise --max-steps (up to 1000000000) or shorten the move',
    );
    expect(first(['trace', '--algorithm', 'regions', '--to', '5,5,5'])).toBe('voxpath: --from: missing: give one integer per axis, e.g. 0,0,0');
    // A list of names, camelCase and one-word, all flags (this one looped for ever on its first try).
    expect(first(['gcode', '-', '--steps-per-mm', '80', '--step-angle', '1.8'], 'G1 X1\n')).toBe(
      'voxpath: --step-angle: give --steps-per-mm or --step-angle, --microsteps and --pitch, not both',
    );
    // A message that names no other option is as the core says it.
    expect(first(['experiment', 'random-lines', '--count', '0'])).toBe('voxpath: --count: must be 1 to 100000, got 0');
  });
});

describe("voxpath's messages about a program or a file", () => {
  it('keeps what a message quotes of the input, says a points file error without the usage (status 2) and a program error without it (status 1)', () => {
    // The learner's file says maxRate: it is quoted as written, not as a flag.
    const check = voxpath(['check', '--algorithm', 'regions', '--from', '0,0,0', '--to', '3,1,0', '-'], 'x,y,z\n0,0,maxRate\n');
    expect(check.code).toBe(2);
    // The file's error alone: the command line was right, so no usage after it.
    expect(check.stderr).toBe("voxpath: line 2, column 5: point 0: z = 'maxRate' is not a number\n");
    // Steps too close for a VCD's pulses, past two of its parts: refused before any of it is written.
    const vcd = voxpath(['gcode', '-', '--steps-per-mm', '100000', '--max-rate', '1000000000', '--acceleration', '14000000', '--format', 'vcd'], 'G1 X0.5 F60\nG1 X2.5 F1000000000\n');
    expect(vcd.code).toBe(1);
    expect(vcd.stdout).toBe('');
    expect(vcd.stderr).toMatch(/^voxpath: program: steps \d+ and \d+ come .* too close for a pulse between them in a VCD of 1 ns ticks; lower --max-rate or the feed\n$/);
  });
});
