/**
 * `voxpath gcode FILE|- --steps-per-mm 80[,80,400] [--acceleration A --max-rate R
 * --junction-deviation D --max-step-rate S ...] [--step-times] [--format json|csv|table|vcd]`
 * (the settings are the catalogue's gcodeSettings, each a flag):
 * runs a G-code program on the modelled machine, plans its motion (Grbl 1.1's
 * planner) and prints its steps, their instants, or its STEP/DIR wires as VCD.
 *
 * Exit codes: 0 the program ran; 1 it has errors (printed to stderr, after
 * the output of the moves before the first one); 2 a bad command line or
 * setting (main.ts prints those).
 */
import { readFile } from 'node:fs/promises';
import { runGcode } from '../core/index.js';
import type { GcodeProgram, GcodeProgramInfo, GcodeSettings, OptionSpec } from '../core/index.js';
import { FORMATS, UsageError, describeOption, optionsFromFlags, parseFlags, pickFormat } from './flags.js';

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

/** The text of FILE, or of standard input for '-'. */
export async function readSource(file: string): Promise<string> {
  if (file === '-') {
    const chunks: Buffer[] = [];
    for await (const chunk of process.stdin) chunks.push(chunk as Buffer);
    return Buffer.concat(chunks).toString('utf8');
  }
  try {
    return await readFile(file, 'utf8');
  } catch (error) {
    throw new UsageError(`cannot read ${file}: ${error instanceof Error ? error.message : String(error)}`);
  }
}

function pointRows(program: GcodeProgram): number[][] {
  const flat = program.trace.points;
  const rows: number[][] = [];
  for (let k = 0; k <= program.steps; k++) rows.push(Array.from(flat.subarray(3 * k, 3 * k + 3)));
  return rows;
}

/** The program's own record (the core's ProgramInfo), without its trace. */
function record(program: GcodeProgram): GcodeProgramInfo {
  const { trace: _trace, ...info } = program;
  return info;
}

function toJson(program: GcodeProgram, stepTimes: boolean): string {
  return (
    JSON.stringify({
      // The program's record as the core declares it, then the per-step arrays.
      ...record(program),
      moves: program.moves,
      points: pointRows(program),
      lineByStep: Array.from(program.lineByStepInRange(0, program.steps)),
      ...(stepTimes ? { stepTimes: Array.from(program.stepTimes(0, program.steps)) } : {}),
    }) + '\n'
  );
}

/** Row k: point k and the line and move of the step that reached it (empty on row 0). */
function toCsv(program: GcodeProgram): string {
  const lines = program.lineByStepInRange(0, program.steps);
  const out = ['k,x,y,z,line,move'];
  pointRows(program).forEach((p, k) => {
    const source = k === 0 ? ['', ''] : [String(lines[k - 1]), String(program.moveOfStep(k - 1))];
    out.push([k, ...p, ...source].join(','));
  });
  return out.join('\n') + '\n';
}

function toTable(program: GcodeProgram): string {
  const header = ['move', 'line', 'code', 'kind', 'to (mm)', 'to (steps)', 'first step', 'steps', 'algorithm', 'start (s)', 'end (s)', 'mm/s in, top, out'];
  const body = program.moves.map((m, i) => [
    String(i),
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
  const widths = header.map((h, c) => Math.max(h.length, ...body.map((r) => r[c]!.length)));
  const row = (r: string[]) => r.map((cell, c) => cell.padStart(widths[c]!)).join('  ');
  const diagnostics = (title: string, list: { line: number; column: number; message: string }[]) =>
    list.length === 0 ? [] : ['', `${title}:`, ...list.map((d) => `  line ${d.line}, column ${d.column}: ${d.message}`)];
  return [
    `gcode: ${program.lines} lines, ${program.moveCount} moves, ${program.steps} steps; ${program.stepsPerMm.join(', ')} steps/mm (x, y, z); lines: ${program.lineAlgorithm}, arcs: ${program.arcAlgorithm}`,
    '',
    row(header),
    ...body.map(row),
    '',
    `pulses per axis (x, y, z): ${program.pulses.join(', ')}`,
    `duration on the planned profile: ${program.durationSeconds} s`,
    ...diagnostics('warnings', program.warnings),
    ...(program.warningsOmitted > 0 ? [`  ... and ${program.warningsOmitted} more`] : []),
    ...diagnostics('errors', program.errors),
    '',
  ].join('\n');
}

/** Runs `gcode` with its arguments (after the command); resolves to what to print and the exit code. */
export async function gcodeCommand(args: string[], settingSpecs: readonly OptionSpec[]): Promise<{ stdout: string; stderr: string; code: number }> {
  const [file, ...rest] = args;
  if (file === undefined || (file.startsWith('--') && file !== '-')) {
    throw new UsageError('gcode needs a FILE (or - for standard input) before its flags');
  }
  const flags = parseFlags(rest, [STEP_TIMES_FLAG]);
  const stepTimes = flags.has(STEP_TIMES_FLAG);
  const format = pickFormat(flags, GCODE_FORMATS);
  if (stepTimes && format !== 'json') throw new UsageError(`${STEP_TIMES_FLAG} adds stepTimes to the json format`);
  const settings: GcodeSettings = optionsFromFlags(flags, settingSpecs, 'gcode', ['--format', STEP_TIMES_FLAG]);
  const program = await runGcode(await readSource(file), settings);
  try {
    const stdout =
      format === 'vcd'
      ? new TextDecoder().decode(program.vcd())
      : format === 'csv'
        ? toCsv(program)
        : format === 'table'
          ? toTable(program)
          : toJson(program, stepTimes);
    const stderr = program.errors.map((e) => `voxpath: ${file}:${e.line}:${e.column}: ${e.message}\n`).join('');
    return { stdout, stderr, code: program.errors.length > 0 ? 1 : 0 };
  } finally {
    program.free();
  }
}
