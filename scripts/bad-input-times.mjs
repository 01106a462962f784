#!/usr/bin/env node
// Times the bad and huge inputs of issue 15 (items 1, 2, 4, 7 and 9) from
// a user's side: through the built library (lib/core, as `import 'voxpath'`
// runs it) and, for flags, through the CLI (bin/voxpath.js, Node's start
// included). Each case runs several rounds; the median and the slowest are
// printed with the answer the user gets. The issue's bound is 2 s per input.
//
//   node scripts/setup.mjs lib && node scripts/bad-input-times.mjs [rounds]
//
// Exit status 1 when a median is past the bound. Timings depend on the
// machine and its load, so they are printed here, never asserted in a test.
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const LIB = new URL('../lib/core/index.js', import.meta.url);
const BIN = fileURLToPath(new URL('../bin/voxpath.js', import.meta.url));
const BOUND_MS = 2000;
const ROUNDS = Number.parseInt(process.argv[2] ?? '3', 10);

if (!existsSync(LIB)) {
  console.error('bad-input-times: lib/ is not built; run `node scripts/setup.mjs lib` first');
  process.exit(2);
}
/** @type {typeof import('../web/core/index.js')} */
const api = await import(LIB.href);
const { runGcode, trace, VoxpathError } = api;

/**
 * The answer to a G-code program: its first error, else its steps (and first warning).
 * @param {string} source @param {object} [settings]
 */
async function gcode(source, settings = { stepsPerMm: 80 }) {
  const program = await runGcode(source, settings);
  try {
    const error = program.errors[0];
    if (error) return `error ${error.line}:${error.column} ${error.message}`;
    const warning = program.warnings[0];
    return `${program.steps} steps${warning ? `; warning ${warning.line}:${warning.column} ${warning.message}` : ''}`;
  } finally {
    program.free();
  }
}

/**
 * The VoxpathError `call` ends in (or what it returned, if it did not).
 * @param {() => unknown} call
 */
async function refusal(call) {
  try {
    const result = await call();
    return `returned ${typeof result === 'object' ? result?.constructor?.name : result}`;
  } catch (error) {
    if (!(error instanceof VoxpathError)) return `threw ${String(error)}`;
    return `VoxpathError field=${error.field}: ${error.detail}`;
  }
}

/**
 * The CLI's exit status and first line of stderr (or how much it printed).
 * @param {string[]} args
 */
function cli(...args) {
  const r = spawnSync(process.execPath, [BIN, ...args], { encoding: 'utf8', maxBuffer: 1 << 28 });
  return `exit ${r.status}: ${r.stderr.split('\n')[0] || `${r.stdout.length} characters out`}`;
}

/** A value of the wrong type, as a careless caller passes it (the type checker is told so). */
const wrong = (/** @type {unknown} */ value) => /** @type {never} */ (value);

const MB = 1_000_000;
const words = (/** @type {number} */ count) => `G1${' X1'.repeat(count)}`;
/** @type {import('../web/core/index.js').TraceOptions} */
const line = { algorithm: 'regions', from: [0, 0, 0], to: [10, 7, 6] };

/** @type {[item: string, name: string, run: () => Promise<string> | string][]} */
const cases = [
  ['1', 'G2147483649 X10 Y5 F600 (ran as G1)', () => gcode('G2147483649 X10 Y5 F600')],
  ['1', 'G2147483651 X10 Y5 F600 (ran as G3)', () => gcode('G2147483651 X10 Y5 F600')],
  ['1', 'G1999999999', () => gcode('G1999999999')],
  ['1', 'M1000000000', () => gcode('M1000000000')],
  ['1', 'G4294967296 (past u32)', () => gcode('G4294967296')],
  ['2', 'G3 J12345678901234567890 at 1000 steps/mm', () => gcode('G3 J12345678901234567890', { stepsPerMm: 1000 })],
  ['2', 'F1e300 (an infinite feed, then F1 and E300)', () => gcode('G1 X1 F1e300')],
  ['2', 'F of 301 digits', () => gcode(`G1 X1 F1${'0'.repeat(300)}`)],
  ['2', 'R of 201 digits', () => gcode(`G2 X10 Y0 R1${'0'.repeat(200)} F100`)],
  ['4', 'lone CR line endings', () => gcode('G1 X1 F100\rG1 X2\rG1 X3\r')],
  ['4', 'a NUL byte', () => gcode('G1 X1\0 F100\n')],
  ['4', 'stepsPerMm 1e-300', () => refusal(() => runGcode('G1 X1 F100', { stepsPerMm: 1e-300 }))],
  ['4', 'maxSteps 1e20', () => refusal(() => trace({ ...line, maxSteps: 1e20 }))],
  ['4', 'CLI --to 0x10,0b11,0o7', () => cli('trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '0x10,0b11,0o7')],
  ['4', 'CLI --max-steps 1e20', () => cli('trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '--max-steps', '1e20')],
  ['4', 'CLI --max-steps Infinity', () => cli('trace', '--algorithm', 'regions', '--from', '0,0,0', '--to', '10,7,6', '--max-steps', 'Infinity')],
  ['7', 'one line of 100,000 words', () => gcode(words(100_000))],
  ['7', 'one line of 250,000 words', () => gcode(words(250_000))],
  ['7', 'one line of 50 MB of words', () => gcode(words(50 * MB / 3))],
  ['7', 'a 50 MB line with an error at column 10', () => gcode(`G1 X1 Y2 #${' X1'.repeat(50 * MB / 3)}`)],
  ['7', 'a 50 MB line of M3', () => gcode(' M3'.repeat(50 * MB / 3))],
  ['7', 'a 50 MB line of a comment, then a move', () => gcode(`(${'c'.repeat(50 * MB)}) G1 X1 F100`)],
  ['7', '1 MB of 300-digit numbers on one line', () => gcode(`G1 ${`X${'9'.repeat(300)} `.repeat(3300)}`)],
  ['7', '1 MB of 300-digit numbers, one a line', () => gcode(`G1 F100\n${`X${'9'.repeat(300)}\n`.repeat(3300)}`)],
  ['9', 'runGcode(12345)', () => refusal(() => runGcode(wrong(12345), { stepsPerMm: 80 }))],
  ['9', 'runGcode(Buffer)', () => refusal(() => runGcode(wrong(Buffer.from('G1 X1')), { stepsPerMm: 80 }))],
  ['9', 'trace with BigInt coordinates', () => refusal(() => trace({ ...line, from: wrong([0n, 0n, 0n]) }))],
  ['9', 'explain("3") on a trace', async () => refusal(async () => (await trace(line)).explain(wrong('3')))],
];

const median = (/** @type {number[]} */ values) => [...values].sort((a, b) => a - b)[Math.floor(values.length / 2)];
let over = 0;
console.log(`${ROUNDS} rounds a case; median and slowest in ms; bound ${BOUND_MS} ms\n`);
console.log(`${'item'.padEnd(5)}${'case'.padEnd(46)}${'median'.padStart(8)}${'max'.padStart(8)}  answer`);
for (const [item, name, run] of cases) {
  const times = [];
  let answer = '';
  for (let round = 0; round < ROUNDS; round++) {
    const started = performance.now();
    answer = await run();
    times.push(performance.now() - started);
  }
  const mid = median(times);
  if (mid > BOUND_MS) over++;
  const shown = answer.length > 110 ? `${answer.slice(0, 107)}...` : answer;
  console.log(`${item.padEnd(5)}${name.padEnd(46)}${mid.toFixed(0).padStart(8)}${Math.max(...times).toFixed(0).padStart(8)}  ${mid > BOUND_MS ? 'OVER 2 s; ' : ''}${shown}`);
}
console.log(over === 0 ? '\nevery median within 2 s' : `\n${over} case(s) past 2 s`);
process.exitCode = over === 0 ? 0 : 1;
