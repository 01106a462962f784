/**
 * The voxpath command line: `voxpath trace --algorithm regions --from 0,0,0
 * --to 10,7,6 --format json`, `voxpath compare --algorithms regions,greedy
 * --from 0,0,0 --to 10,7,6`, `voxpath check --algorithm regions --from 0,0,0
 * --to 10,7,6 student.csv`. Flags are generated from the algorithm
 * catalogue: an option `maxSteps` is the flag `--max-steps`.
 *
 * Exit codes: 0 success, 1 failure while running, 2 bad command line or
 * rejected input (a one-line error naming the flag, then usage; a file's
 * error names its line and column, without the usage), 3 the output could
 * not be written (a full disk: one line saying so).
 */
import { readFile } from 'node:fs/promises';
import {
  catalogue as coreCatalogue,
  checkPoints,
  checkToTable,
  compare,
  comparisonToCsv,
  comparisonToTable,
  randomLines,
  randomLinesToCsv,
  randomLinesToTable,
  trace,
  traceCsvChunks,
  traceJsonChunks,
  traceTableChunks,
  VoxpathError,
} from '../core/index.js';
import type { AlgorithmInfo, Catalogue, Trace } from '../core/index.js';
import { quoted } from '../core/guard.js';
import { FORMATS, type Flags, UsageError, describeOption, flagOf, flagText, inFlagWords, optionsFromFlags, parseCommandLine, parseFlags, pickFormat } from './flags.js';
import { GCODE_USAGE, gcodeCommand, gcodeHelp, readSource } from './gcode.js';
import { OUTPUT_FAILED, OutputError, listenForWriteErrors, write, writeAll } from './output.js';

function shortUsage(): string {
  return [
    'usage: voxpath trace --algorithm ID --from X,Y,Z --to X,Y,Z [options] [--format json|csv|table]',
    '       voxpath compare --algorithms A,B --from X,Y,Z --to X,Y,Z [options of A or B] [--format json|csv|table]',
    '       voxpath experiment random-lines [--count N] [--seed N] [--algorithm ID] [options] [--format ...]',
    `       ${GCODE_USAGE}`,
    `       ${CHECK_USAGE}`,
    '       voxpath algorithms',
    '       voxpath --help (-h) | --version (-V)',
  ].join('\n');
}

function fullUsage({ algorithms: catalogue, experiments: experimentList, gcodeSettings }: Catalogue): string {
  const lines = [
    shortUsage(),
    '',
    'voxpath computes the single-axis steps a CNC controller (or a line renderer) takes,',
    'and why it takes each one. Coordinates are integer grid units (one unit = one step).',
    '',
    'Exit status: 0 done; 1 check: the points differ, gcode: the program has errors (or its VCD cannot be made);',
    '2 a bad command line (one line naming the flag, then usage) or a bad points file (one line',
    'naming its line and column); 3 the output could not be written (a full disk).',
    '',
    'trace prints, for --format json, one object:',
    '  { algorithm, dims, steps, points: [[x,y,z], ...] (steps + 1 of them),',
    '    decisions: { <column>: [...] } (decisions.C[k] produced points[k + 1]; null where',
    '    the column does not apply to that step),',
    '    deviation: [...] (deviation[k] belongs to points[k]), metrics: {...}, notes: [...] }',
    'and for csv / table one row per point with the decision that produced it (a column',
    'that does not apply: empty in csv, - in the table).',
    '',
    'compare traces the same move with two algorithms; each option goes to every one of',
    'the two that takes it. The helix against itself runs the --method given (else saleem)',
    'on a and the other on b, its chord options on the chords\' side only.',
    '--format json prints { a, b (steps, metrics, comparedValue), firstDifference:',
    '{ pointIndex, a, b, aWhy, bWhy (explanation, decisions) }, onlyInA, onlyInB (cells) };',
    'table puts both side by side with both explanations; csv has one row per quantity.',
    '',
    'check reads a learner\'s points (FILE, or - for standard input: CSV or blank-separated',
    'rows with an optional header whose x,y,z columns are read, or a printed list such as',
    '[(0, 0, 0), (1, 1, 1)]) and replays the rule of --algorithm on the move. Exit 0 when',
    'the points are its path; 1 with the first difference, the rule\'s reason and decisions,',
    'the points around it side by side and the rules the points do follow (table, the',
    'default), or for json { matches, steps, yourSteps, firstDifference: { kind, pointIndex,',
    'stepIndex, expected, got, message, why, decisions, around }, alsoMatches: [{ label,',
    'options }] };',
    '2 for bad input (a point that is not a path is named with its line and column).',
    '',
    'algorithms and their options:',
  ];
  for (const a of catalogue) {
    lines.push('', `  ${a.id}: ${a.title}`, `    ${a.citation}`);
    for (const o of a.options) lines.push(describeOption(o));
  }
  lines.push('', 'gcode:', gcodeHelp(gcodeSettings));
  lines.push('', 'experiments (any option of --algorithm, except --from and --to, applies to every line):');
  for (const e of experimentList) {
    lines.push('', `  ${e.id}: ${e.title}`, `    ${e.citation}`);
    lines.push(describeOption({ name: 'algorithm', kind: { type: 'choice', values: catalogue.filter((a) => a.family === e.family).map((a) => a.id) }, required: false, default: 'regions', appliesWith: null, doc: 'Algorithm that traces every line.' }));
    for (const o of e.options) lines.push(describeOption(o));
  }
  return lines.join('\n') + '\n';
}

/** The version of package.json, beside web/ and lib/ (this file runs as lib/cli/main.js). */
async function packageVersion(): Promise<string> {
  const text = await readFile(new URL('../../package.json', import.meta.url), 'utf8');
  return (JSON.parse(text) as { version: string }).version;
}

/**
 * `sentence` ("--algorithm is required"), naming also a flag given that no
 * algorithm of `command` takes: a misspelt --algoritm left --algorithm
 * missing, and the error named only the flag it had not been given.
 */
function missingFlag(sentence: string, flags: Flags, catalogue: AlgorithmInfo[], command: string): UsageError {
  const known = new Set(['--format', ...catalogue.flatMap((a) => a.options.map((o) => flagOf(o.name)))]);
  const stray = [...flags.keys()].find((flag) => !known.has(flag));
  return new UsageError(stray === undefined ? sentence : `${sentence}; ${quoted(stray)} is not a flag of ${command}`);
}

/** The algorithm a command names with --algorithm (or `fallback`). */
function pickAlgorithm(flags: Flags, catalogue: AlgorithmInfo[], command: string, fallback?: string): AlgorithmInfo {
  const id = flagText(flags, '--algorithm') ?? fallback;
  if (id === undefined) throw missingFlag('--algorithm is required', flags, catalogue, command);
  const info = catalogue.find((a) => a.id === id);
  if (!info) throw new UsageError(`--algorithm: unknown algorithm '${quoted(id)}' (known: ${catalogue.map((a) => a.id).join(', ')})`);
  return info;
}

/** JSON text of a trace and its line end, in pieces. */
function* traceJsonLine(result: Trace): Generator<string> {
  yield* traceJsonChunks(result);
  yield '\n';
}

/** Traces and writes the trace as it is read, a chunk of rows at a time, so any trace the API accepts prints. */
async function runTrace(flags: Flags, catalogues: Catalogue): Promise<void> {
  const info = pickAlgorithm(flags, catalogues.algorithms, 'trace');
  const format = pickFormat(flags, FORMATS);
  const options = optionsFromFlags(flags, info.options, info.id);
  const result = await trace({ ...options, algorithm: info.id } as Parameters<typeof trace>[0]);
  try {
    await writeAll(format === 'csv' ? traceCsvChunks(result) : format === 'table' ? traceTableChunks(result) : traceJsonLine(result));
  } finally {
    result.free();
  }
}

/** The two algorithms of --algorithms A,B. */
function pickPair(flags: Flags, catalogue: AlgorithmInfo[]): [AlgorithmInfo, AlgorithmInfo] {
  const text = flagText(flags, '--algorithms');
  if (text === undefined) throw missingFlag('--algorithms is required (two ids, for example --algorithms regions,greedy)', flags, catalogue, 'compare');
  const ids = text.split(',');
  if (ids.length !== 2) throw new UsageError(`--algorithms: expected two ids separated by a comma, got '${quoted(text)}'`);
  const find = (id: string) => {
    const info = catalogue.find((a) => a.id === id);
    if (!info) throw new UsageError(`--algorithms: unknown algorithm '${quoted(id)}' (known: ${catalogue.map((a) => a.id).join(', ')})`);
    return info;
  };
  return [find(ids[0]!), find(ids[1]!)];
}

async function runCompare(flags: Flags, catalogues: Catalogue): Promise<string> {
  const [a, b] = pickPair(flags, catalogues.algorithms);
  const format = pickFormat(flags, FORMATS);
  // The union of both option lists; an option both take is parsed once.
  const specs = [...a.options, ...b.options.filter((o) => !a.options.some((p) => p.name === o.name))];
  const options = optionsFromFlags(flags, specs, `compare ${a.id},${b.id}`, ['--algorithms', '--format']);
  const result = await compare({ ...options, algorithms: [a.id, b.id] });
  if (format === 'csv') return comparisonToCsv(result);
  if (format === 'table') return comparisonToTable(result);
  return JSON.stringify(result) + '\n';
}

async function runExperiment(args: string[], catalogues: Catalogue): Promise<string> {
  const [id, ...rest] = args;
  const experiment = catalogues.experiments.find((e) => e.id === id);
  if (!experiment) {
    throw new UsageError(`experiment: expected one of ${catalogues.experiments.map((e) => e.id).join(', ')}, got '${quoted(id ?? '')}'`);
  }
  const flags = parseFlags(rest);
  const info = pickAlgorithm(flags, catalogues.algorithms, experiment.id, 'regions');
  const format = pickFormat(flags, FORMATS);
  const specs = [...experiment.options, ...info.options.filter((o) => o.name !== 'from' && o.name !== 'to')];
  const options = optionsFromFlags(flags, specs, `${experiment.id} with ${info.id}`);
  const result = await randomLines({ ...options, algorithm: info.id });
  if (format === 'csv') return randomLinesToCsv(result);
  if (format === 'table') return randomLinesToTable(result);
  return JSON.stringify(result) + '\n';
}

const CHECK_USAGE = 'voxpath check --algorithm ID --from X,Y,Z --to X,Y,Z [options] FILE|- [--format table|json]';

/** `check`: exit 0 when the points follow the rule, 1 with the difference, 2 for bad input. */
async function runCheck(args: string[], catalogues: Catalogue): Promise<{ stdout: string; code: number }> {
  const { flags, operands } = parseCommandLine(args);
  const [file, ...extra] = operands;
  if (file === undefined) throw new UsageError('check needs a FILE (or - for standard input)');
  if (extra.length > 0) throw new UsageError(`check reads one FILE, got '${quoted(file)}' and '${quoted(extra[0]!)}'`);
  const info = pickAlgorithm(flags, catalogues.algorithms, 'check');
  const format = flagText(flags, '--format') ?? 'table';
  if (format !== 'table' && format !== 'json') throw new UsageError(`--format: expected table or json, got '${quoted(format)}'`);
  const options = optionsFromFlags(flags, info.options, info.id);
  const result = await checkPoints({ ...options, algorithm: info.id } as Parameters<typeof checkPoints>[0], await readSource(file));
  const stdout = format === 'json' ? JSON.stringify(result) + '\n' : checkToTable(result);
  return { stdout, code: result.matches ? 0 : 1 };
}

/** Runs the CLI with `args` (without node and script); resolves to the exit code. */
export async function main(args: string[]): Promise<number> {
  listenForWriteErrors();
  const [command, ...rest] = args;
  try {
    // As git and cargo do: no command is a usage error, on stderr; the full text is --help's.
    if (command === undefined) throw new UsageError('a command is needed (voxpath --help describes each)');
    if (command === '--version' || command === '-V') {
      await write(`voxpath ${await packageVersion()}\n`);
      return 0;
    }
    const catalogues = await coreCatalogue();
    // -h as --help, as -V is --version: what most CLIs take for help.
    // Not after --, where every argument is an operand (parseCommandLine).
    const flagged = rest.includes('--') ? rest.slice(0, rest.indexOf('--')) : rest;
    if (command === '--help' || command === '-h' || command === 'help' || flagged.includes('--help') || flagged.includes('-h')) {
      await write(fullUsage(catalogues));
      return 0;
    }
    if (command === 'algorithms') {
      // Nothing to read after it: `algorithms --format json` printed the table and exited 0.
      if (rest.length > 0) throw new UsageError(`algorithms takes no arguments, got ${rest.map((a) => `'${quoted(a)}'`).join(' ')}`);
      await write(catalogues.algorithms.map((a) => `${a.id.padEnd(14)} ${a.title}\n${' '.repeat(15)}${a.citation}\n`).join(''));
      return 0;
    }
    if (command === 'trace') {
      await runTrace(parseFlags(rest), catalogues);
    } else if (command === 'compare') {
      await write(await runCompare(parseFlags(rest), catalogues));
    } else if (command === 'experiment') {
      await write(await runExperiment(rest, catalogues));
    } else if (command === 'check') {
      const result = await runCheck(rest, catalogues);
      await write(result.stdout);
      return result.code;
    } else if (command === 'gcode') {
      return await gcodeCommand(rest, catalogues);
    } else {
      throw new UsageError(`unknown command '${quoted(command)}'`);
    }
    return 0;
  } catch (error) {
    if (error instanceof OutputError) {
      process.stderr.write(`voxpath: ${error.message}\n`);
      return OUTPUT_FAILED;
    }
    if (error instanceof UsageError) {
      process.stderr.write(`voxpath: ${error.message}\n${shortUsage()}\n`);
      return 2;
    }
    if (error instanceof VoxpathError) {
      // A learner's points are the FILE of check and a G-code program the FILE of gcode, not
      // flags; text errors carry their line and column.
      // A FILE that is not text (`source`, from readSource) is named in the message itself.
      const where =
        error.line !== undefined
          ? `line ${error.line}, column ${error.column}: `
          : error.field === 'source'
            ? ''
            : error.field === 'points' || error.field === 'program'
            ? `${error.field}: `
            : error.field !== undefined
              ? `${flagOf(error.field)}: `
              : '';
      // Options named by their flags, a text's errors too ("raise --max-steps"); what a
      // message quotes of the text is kept as it is (inFlagWords).
      const detail = inFlagWords(error.detail, await coreCatalogue());
      // What the program asks of the machine (steps too close for its VCD) is the program's
      // fault, as its errors are (status 1), not the command line's: no usage.
      if (error.field === 'program') {
        process.stderr.write(`voxpath: ${where}${detail}\n`);
        return 1;
      }
      // A learner's file is bad input (status 2), but the command line was right: the usage
      // would bury the line and column that say what to mend.
      if (error.line !== undefined || error.field === 'points' || error.field === 'source') {
        process.stderr.write(`voxpath: ${where}${detail}\n`);
        return 2;
      }
      process.stderr.write(`voxpath: ${where}${detail}\n${shortUsage()}\n`);
      return 2;
    }
    process.stderr.write(`voxpath: ${error instanceof Error ? (error.stack ?? error.message) : String(error)}\n`);
    return 1;
  }
}
