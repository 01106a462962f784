/**
 * `voxpath gcode FILE|- --steps-per-mm 80[,80,400] [--acceleration A --max-rate R
 * --junction-deviation D --max-step-rate S ...] [--step-times] [--format json|csv|table|vcd]`
 * (the settings are the catalogue's gcodeSettings, each a flag):
 * runs a G-code program on the modelled machine, plans its motion (Grbl 1.1's
 * planner) and prints its steps, their instants, or its STEP/DIR wires as VCD.
 *
 * Exit codes: 0 the program ran; 1 it has errors (printed to stderr, after
 * the output of the moves before the first one); 2 a bad command line or
 * setting (main.ts prints those). Warnings are in the JSON and the table,
 * and on stderr for CSV and VCD.
 */
import { readFile } from 'node:fs/promises';
import { runGcode, VoxpathError } from '../core/index.js';
import type { Catalogue, GcodeProgram, GcodeProgramInfo, GcodeSettings, OptionSpec } from '../core/index.js';
import { alignedTable, countOf, indexChunks, jsonListChunks, pointsJsonChunks } from '../core/export.js';
import { quoted } from '../core/guard.js';
import { FORMATS, UsageError, describeOption, inFlagWords, optionsFromFlags, parseCommandLine, pickFormat } from './flags.js';
import { writeAll } from './output.js';

/** A flag without a value: adds stepTimes to the JSON. */
const STEP_TIMES_FLAG = '--step-times';

const GCODE_FORMATS = [...FORMATS, 'vcd'] as const;

export const GCODE_USAGE = `voxpath gcode FILE|- SETTINGS [${STEP_TIMES_FLAG}] [--format ${GCODE_FORMATS.join('|')}]`;

/** The gcode command's help text; its flags are the core's machine settings (`settings`, the catalogue's gcodeSettings). */
export function gcodeHelp(settings: readonly OptionSpec[]): string {
  return [
    `  ${GCODE_USAGE}`,
    '    Runs a G-code program (FILE, or - for standard input) on a machine with the given',
    '    steps per mm, or the steps per mm of a stepper drive (Wang 3.3: 360 / step angle',
    '    · microsteps pulses per turn, over the pitch), and plans its motion as Grbl 1.1 does',
    '    (its look-ahead over the whole program, where the buffer of Grbl holds 15 blocks).',
    '    Per-axis settings take one value for all axes or x,y,z. SETTINGS:',
    ...settings.map(describeOption),
    '    json prints { points (machine position in steps after every step, as trace),',
    '    lineByStep (the source line of every step), moves (each with its line and timing),',
    '    pulses (per axis), durationSeconds, warnings, errors ([{ line, column, message }]), ... };',
    `    ${STEP_TIMES_FLAG} adds stepTimes (seconds, one per step). csv: one row per point with its`,
    '    line and move; table: the moves and totals. vcd writes the STEP and DIR wires of every',
    '    axis as an IEEE 1364 Value Change Dump (PulseView, GTKWave, sigrok).',
  ].join('\n');
}

/** Bytes of UTF-16 text decoded at once by readSource: 64 MiB, an even count. */
const UTF16_PIECE_BYTES = 1 << 26;

/**
 * The text of FILE, or of standard input for '-': its bytes as they are,
 * for the core to read as UTF-8 (which refuses bytes that are not UTF-8 at
 * their line and column, as `runGcode` and `checkPoints` refuse them: decoded
 * here, a Latin-1 "café" in a comment ran as U+FFFD without a word), or the
 * text decoded from UTF-16 where the bytes start with its byte order mark,
 * as a browser reads a file (the Encoding Standard's BOM sniffing), and
 * handed over as UTF-8. A program or points file saved as "Unicode" by
 * Windows Notepad is UTF-16 with a mark; read as UTF-8 its first line was
 * "'��' is not G-code" and every character a NUL beside it.
 */
export async function readSource(file: string): Promise<Uint8Array> {
  let bytes: Buffer;
  if (file === '-') {
    const chunks: Buffer[] = [];
    for await (const chunk of process.stdin) chunks.push(chunk as Buffer);
    bytes = Buffer.concat(chunks);
  } else {
    try {
      bytes = await readFile(file);
    } catch (error) {
      throw new UsageError(`cannot read ${file}: ${error instanceof Error ? error.message : String(error)}`);
    }
  }
  const utf16 = bytes[0] === 0xff && bytes[1] === 0xfe ? 'utf-16le' : bytes[0] === 0xfe && bytes[1] === 0xff ? 'utf-16be' : undefined;
  // TextDecoder drops the mark of its own encoding. UTF-8's mark the core skips.
  if (utf16 === undefined) return bytes;
  // Decoded a piece at a time, each piece encoded as UTF-8 as it comes:
  // decoded whole, a file of more than 2^29 characters (1 GiB of UTF-16)
  // was a string longer than V8 makes, and was said not to be UTF-16.
  const decoder = new TextDecoder(utf16, { fatal: true });
  const encoder = new TextEncoder();
  const pieces: Uint8Array[] = [];
  try {
    for (let at = 0; at < bytes.length; at += UTF16_PIECE_BYTES) {
      const end = Math.min(at + UTF16_PIECE_BYTES, bytes.length);
      pieces.push(encoder.encode(decoder.decode(bytes.subarray(at, end), { stream: end < bytes.length })));
    }
    return Buffer.concat(pieces);
  } catch {
    // The file's fault, as bytes that are not UTF-8 are: one line, no usage.
    const encoding = utf16.toUpperCase();
    throw new VoxpathError(`cannot read ${file}: it starts with the byte order mark of ${encoding} but is not ${encoding} text (an unpaired surrogate, or an odd byte count); save it as UTF-8`, { field: 'source' });
  }
}

/** The program's own record (the core's ProgramInfo), without its trace. */
function record(program: GcodeProgram): GcodeProgramInfo {
  const { trace: _trace, ...info } = program;
  return info;
}

/**
 * The JSON object, in pieces of at most EXPORT_CHUNK_ROWS moves, points or
 * steps: the program's record as the core declares it, then the moves, then
 * the per-step arrays (JSON.stringify of them whole took 5 GB at 25,000,000
 * steps).
 */
function* jsonChunks(program: GcodeProgram, stepTimes: boolean): Generator<string> {
  yield JSON.stringify(record(program)).slice(0, -1) + ',"moves":[';
  yield* jsonListChunks(program.moveCount, (from, to) => program.movesInRange(from, to));
  yield '],"points":[';
  yield* pointsJsonChunks(program.trace);
  yield '],"lineByStep":[';
  yield* jsonListChunks(program.steps, (from, to) => program.lineByStepInRange(from, to));
  if (stepTimes) {
    yield '],"stepTimes":[';
    yield* jsonListChunks(program.steps, (from, to) => program.stepTimes(from, to));
  }
  yield ']}\n';
}

/** Row k: point k and the line and move of the step that reached it (empty on row 0), EXPORT_CHUNK_ROWS rows at a time. */
function* csvChunks(program: GcodeProgram): Generator<string> {
  yield 'k,x,y,z,line,move\n';
  const points = program.trace;
  for (const [from, to] of indexChunks(program.steps + 1)) {
    const flat = points.pointsInRange(from, to);
    // Row k's step is k - 1: steps max(from - 1, 0) .. to - 2.
    const firstStep = Math.max(from - 1, 0);
    const lines = program.lineByStepInRange(firstStep, Math.max(to - 1, firstStep));
    const rows: string[] = [];
    for (let k = from; k < to; k++) {
      const source = k === 0 ? ',' : `${lines[k - 1 - firstStep]},${program.moveOfStep(k - 1)}`;
      rows.push(`${k},${flat.subarray(3 * (k - from), 3 * (k - from) + 3).join(',')},${source}`);
    }
    yield rows.join('\n') + '\n';
  }
}

/**
 * The moves and totals, in pieces: each block of EXPORT_CHUNK_ROWS moves is
 * aligned on its own under its own header, as trace's table is.
 */
function* tableChunks(program: GcodeProgram, said: (message: string) => string): Generator<string> {
  const header = ['move', 'line', 'code', 'kind', 'to (mm)', 'to (steps)', 'first step', 'steps', 'algorithm', 'start (s)', 'end (s)', 'mm/s in, top, out'];
  yield `gcode: ${countOf(program.lines, 'line')}, ${countOf(program.moveCount, 'move')}, ${countOf(program.steps, 'step')}; ${program.stepsPerMm.join(', ')} steps/mm (x, y, z); lines: ${program.lineAlgorithm}, arcs: ${program.arcAlgorithm}\n\n`;
  for (const [from, to] of indexChunks(program.moveCount)) {
    const body = program.movesInRange(from, to).map((m, i) => [
      String(from + i),
      String(m.line),
      m.code,
      m.kind,
      m.toMm.map((v) => String(Math.round(v * 1e6) / 1e6)).join(' '),
      m.toSteps.join(' '),
      String(m.firstStep),
      String(m.steps),
      m.algorithm,
      m.timing.startSeconds.toFixed(4),
      m.timing.endSeconds.toFixed(4),
      [m.timing.entrySpeed, m.timing.cruiseSpeed, m.timing.exitSpeed].map((v) => v.toFixed(2)).join(' '),
    ]);
    yield (from > 0 ? '\n' : '') + alignedTable(header, body).join('\n') + '\n';
  }
  // No move (an empty program, or one that stops at its first line): the header, over no rows.
  if (program.moveCount === 0) yield alignedTable(header, []).join('\n') + '\n';
  const diagnostics = (title: string, list: { line: number; column: number; message: string }[]) =>
    list.length === 0 ? [] : ['', `${title}:`, ...list.map((d) => `  line ${d.line}, column ${d.column}: ${said(d.message)}`)];
  yield [
    '',
    `pulses per axis (x, y, z): ${program.pulses.join(', ')}`,
    `duration on the planned profile: ${program.durationSeconds} s`,
    ...diagnostics('warnings', program.warnings),
    ...(program.warningsOmitted > 0 ? [`  ... and ${program.warningsOmitted} more`] : []),
    ...diagnostics('errors', program.errors),
    '',
  ].join('\n');
}

/**
 * Runs `gcode` with its arguments (after the command) and writes its output
 * as it is read, a chunk at a time (whatever the length of the program, as
 * trace's), then the program's errors to stderr; resolves to the exit code.
 */
export async function gcodeCommand(args: string[], catalogue: Catalogue): Promise<number> {
  // FILE is an operand, as check's: before or after the flags, and after --
  // when its name starts with -- (`gcode -- --x.gcode`).
  const { flags, operands } = parseCommandLine(args, [STEP_TIMES_FLAG]);
  const [file, ...extra] = operands;
  if (file === undefined) throw new UsageError('gcode needs a FILE (or - for standard input)');
  if (extra.length > 0) throw new UsageError(`gcode reads one FILE, got '${quoted(file)}' and '${quoted(extra[0]!)}'`);
  const stepTimes = flags.has(STEP_TIMES_FLAG);
  const format = pickFormat(flags, GCODE_FORMATS);
  if (stepTimes && format !== 'json') throw new UsageError(`${STEP_TIMES_FLAG} adds stepTimes to the json format`);
  const settings: GcodeSettings = optionsFromFlags(flags, catalogue.gcodeSettings, 'gcode', ['--format', STEP_TIMES_FLAG]);
  // What people read (the table, stderr) names a setting by its flag ("raise --max-rate");
  // the JSON keeps the core's words, as the API gives them.
  const said = (message: string) => inFlagWords(message, catalogue);
  let program: GcodeProgram;
  try {
    program = await runGcode(await readSource(file), settings);
  } catch (error) {
    // Bytes of the program that are not text (UTF-8, or UTF-16 after its
    // mark) are an error of the program, at its line and column as its
    // other errors are (status 1), not of the command line.
    if (error instanceof VoxpathError && error.field === 'source') {
      // readSource's own error names the file.
      const at = error.line === undefined ? '' : `${file}:${error.line}:${error.column}: `;
      process.stderr.write(`voxpath: ${at}${error.detail}\n`);
      return 1;
    }
    throw error;
  }
  try {
    await writeAll(
      format === 'vcd'
        ? program.vcdChunks()
        : format === 'csv'
          ? csvChunks(program)
          : format === 'table'
            ? tableChunks(program, said)
            : jsonChunks(program, stepTimes),
    );
    // CSV and VCD have no place for them: the warnings go to stderr, before the errors, as
    // compilers print theirs (the JSON and the table hold them; none is dropped silently).
    const placed = (d: { line: number; column: number; message: string }, kind = '') => `voxpath: ${file}:${d.line}:${d.column}: ${kind}${said(d.message)}\n`;
    const warnings =
      format === 'csv' || format === 'vcd'
        ? [
            ...program.warnings.map((w) => placed(w, 'warning: ')),
            ...(program.warningsOmitted > 0 ? [`voxpath: ${file}: ... and ${program.warningsOmitted} more warnings\n`] : []),
          ]
        : [];
    process.stderr.write([...warnings, ...program.errors.map((e) => placed(e))].join(''));
    return program.errors.length > 0 ? 1 : 0;
  } finally {
    program.free();
  }
}
