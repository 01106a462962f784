/**
 * Command-line flags, shared by every command: read by Node's own
 * `util.parseArgs`, and checked against the catalogue's OptionSpecs, from
 * which they are made (an option `maxSteps` is the flag `--max-steps`). A
 * new option or machine setting declared in the core is a flag here, with
 * its help line, without code in the CLI.
 */
import { parseArgs } from 'node:util';
import { AXIS_NAMES } from '../core/axes.js';
import { inexactWholeRefusal, quoted, readDecimal } from '../core/guard.js';
import { axesRefusal, perAxisRefusal, rangeRefusal } from '../core/ranges.js';
import type { Catalogue, OptionSpec } from '../core/index.js';

/** A command-line mistake: reported in one line plus usage, exit code 2. */
export class UsageError extends Error {}

export const FORMATS = ['json', 'csv', 'table'] as const;

/** The flag of an option: maxSteps -> --max-steps. */
export function flagOf(option: string): string {
  return '--' + option.replace(/[A-Z]/g, (c) => '-' + c.toLowerCase());
}

/**
 * The core's message in the command line's words: an option it names by
 * its API name in camelCase (segmentLength, maxSteps) is named by its flag
 * (--segment-length, --max-steps), and so is a one-word option listed with
 * one ("give segmentLength or tolerance" is "give --segment-length or
 * --tolerance"); elsewhere a one-word name (from, to, count) is a word of
 * the sentence, and stays. A point given as an example in JSON (e.g.
 * [0, 0, 0]) is written as a flag takes it (e.g. 0,0,0).
 */
export function inFlagWords(message: string, catalogue: Catalogue): string {
  // What a message quotes ('maxRate' read from a file) is the user's, kept as it is.
  return message
    .split(/('[^']*')/)
    .map((part, i) => (i % 2 === 1 ? part : partInFlagWords(part, catalogue)))
    .join('');
}

/** The patterns inFlagWords finds a catalogue's option names by. */
interface OptionNamePatterns {
  /** A camelCase name standing alone, or undefined when the catalogue has none. */
  camel: RegExp | undefined;
  /** A one-word name after a flag in a list, and before one. */
  besideFlag: [RegExp, RegExp];
}

/** Each catalogue's patterns, made once: a G-code run says up to 1,000 warnings, each through inFlagWords. */
const patternsByCatalogue = new WeakMap<Catalogue, OptionNamePatterns>();

function optionNamePatterns(catalogue: Catalogue): OptionNamePatterns {
  const known = patternsByCatalogue.get(catalogue);
  if (known) return known;
  const specs = [...catalogue.algorithms.flatMap((a) => a.options), ...catalogue.experiments.flatMap((e) => e.options), ...catalogue.gcodeSettings];
  const names = [...new Set(specs.map((o) => o.name))];
  // A name standing alone: not a part of a flag already written (--microsteps).
  const alternatives = (list: string[]) => `(?<![\\w-])(${list.join('|')})\\b`;
  const camel = names.filter((name) => /[A-Z]/.test(name));
  // Beside a flag in a list (", ", " or ", " and ").
  const word = alternatives(names.filter((name) => !camel.includes(name)));
  const patterns: OptionNamePatterns = {
    camel: camel.length === 0 ? undefined : new RegExp(alternatives(camel), 'g'),
    besideFlag: [new RegExp(`(--[a-z-]+(?:, | or | and ))${word}`, 'g'), new RegExp(`${word}((?:, | or | and )--[a-z-]+)`, 'g')],
  };
  patternsByCatalogue.set(catalogue, patterns);
  return patterns;
}

/** inFlagWords for a part of a message that quotes nothing. */
function partInFlagWords(message: string, catalogue: Catalogue): string {
  const { camel, besideFlag } = optionNamePatterns(catalogue);
  let text = camel === undefined ? message : message.replace(camel, (name) => flagOf(name));
  // A one-word name beside a flag is a flag too, until none is left.
  // Each pass turns at least one name into a flag, and a flag is never a name again: it ends.
  for (let before = ''; before !== text; ) {
    before = text;
    text = text.replace(besideFlag[0], (_, list: string, name: string) => `${list}${flagOf(name)}`).replace(besideFlag[1], (_, name: string, list: string) => `${flagOf(name)}${list}`);
  }
  return text.replace(/e\.g\. \[([-\d, ]+)\]/g, (_, point: string) => `e.g. ${point.replace(/ /g, '')}`);
}

/** A value after its flag, even a negative number (`--from -3,0,0`), which parseArgs alone would take for a flag. */
function isValue(arg: string | undefined): arg is string {
  return arg !== undefined && (!arg.startsWith('--') || /^--?\d/.test(arg)) && arg !== '--';
}

/**
 * Flags by their `--name`, in order, each with its text ('' for a switch),
 * or null for a flag given without one: last on the line, or before
 * another flag. Whether that is a flag that needs a value or no flag at all
 * is known only against the command's names, so it is said there
 * (`flagText`, `optionsFromFlags`): `--bogus` given last was told it
 * "needs a value".
 */
export type Flags = Map<string, string | null>;

/** The text of `flag`, undefined when it is not given; refused when it is given without a value. */
export function flagText(flags: Flags, flag: string): string | undefined {
  const text = flags.get(flag);
  return text === undefined ? undefined : givenText(flag, text);
}

/** A given flag's text, refused when it has none. */
function givenText(flag: string, text: string | null): string {
  if (text === null) throw new UsageError(`${quoted(flag)} needs a value`);
  return text;
}

/**
 * Flags by their `--name`, in order: `--name value`, `--name=value`, and the
 * `switches` (such as --help), which take no value. Which names a command
 * takes depends on what it names (`--algorithm` picks the options), so the
 * names are checked afterwards, against the specs (`optionsFromFlags`).
 */
export function parseFlags(args: readonly string[], switches: readonly string[] = []): Flags {
  const { flags, operands } = parseCommandLine(args, switches);
  if (operands.length > 0) throw new UsageError(`unexpected argument '${quoted(operands[0]!)}'`);
  return flags;
}

/**
 * The flags of parseFlags and, in `operands`, the arguments that are not
 * flags nor their values (a FILE, or - for standard input), in order.
 */
export function parseCommandLine(args: readonly string[], switches: readonly string[] = []): { flags: Flags; operands: string[] } {
  const allSwitches = ['--help', ...switches];
  // Each value joined to its flag (--name=value), so that parseArgs reads
  // negative numbers as values and every flag unambiguously.
  const joined: string[] = [];
  const operands: string[] = [];
  for (let i = 0; i < args.length; i++) {
    const arg = args[i]!;
    // As POSIX utilities: after --, every argument is an operand, so that a
    // file whose name starts with - or -- can be named.
    if (arg === '--') {
      operands.push(...args.slice(i + 1));
      break;
    }
    if (!arg.startsWith('--')) operands.push(arg);
    else if (arg.includes('=') || allSwitches.includes(arg)) joined.push(arg);
    else if (isValue(args[i + 1])) joined.push(`${arg}=${args[++i]}`);
    // Without a value: read as given, and refused once its name is checked.
    else joined.push(arg);
  }
  const options = Object.fromEntries(allSwitches.map((flag) => [flag.slice(2), { type: 'boolean' as const }]));
  const { tokens } = parseArgs({ args: joined, options, strict: false, tokens: true });
  const flags: Flags = new Map();
  for (const token of tokens) {
    if (token.kind !== 'option') continue;
    const flag = token.rawName.split('=')[0]!;
    if (flags.has(flag)) throw new UsageError(`${quoted(flag)} is given twice`);
    const isSwitch = allSwitches.includes(flag);
    if (isSwitch && token.value !== undefined) throw new UsageError(`${quoted(flag)} takes no value`);
    flags.set(flag, isSwitch ? '' : (token.value ?? null));
  }
  return { flags, operands };
}

/** A flag's number: a finite decimal number, else refused naming the flag. */
function numberOf(flag: string, part: string): number {
  const v = readDecimal(part);
  if (v === undefined) throw new UsageError(`${quoted(flag)}: '${quoted(part)}' is not a finite decimal number (such as 12, -3.5 or 1e6)`);
  return v;
}

/** A number as the user wrote it, for a message: its text, blanks around it left out. */
function written(part: string): string {
  return quoted(part.trim());
}

/** Refuses `refusal` (a value's range, from the catalogue, in the core's words, or inexactWholeRefusal's), naming the flag; nothing when undefined. */
function refuse(flag: string, refusal: string | undefined): void {
  if (refusal !== undefined) throw new UsageError(`${quoted(flag)}: ${refusal}`);
}

/**
 * A flag's text as the option's value, checked against its declared kind
 * and range: a value out of range is refused here in the core's words
 * (the catalogue's, as the page's form says them), quoting what was typed,
 * where the core would quote the double it was handed; then a value of
 * whole numbers whose text the double does not say (inexactWholeRefusal),
 * after the range, as the core checks, so that a value past 2^53 that the
 * range refuses is told its range.
 */
function optionValue(spec: OptionSpec, flag: string, text: string): unknown {
  switch (spec.kind.type) {
    case 'point': {
      const parts = text.split(',');
      const values = parts.map((part) => numberOf(flag, part));
      // The core tells a count of coordinates it does not take before any coordinate.
      if (values.length <= AXIS_NAMES.length) refuse(flag, axesRefusal(spec.kind, values, parts.map(written)));
      parts.forEach((part, i) => refuse(flag, inexactWholeRefusal(part, values[i]!)));
      return values;
    }
    case 'number': {
      const value = numberOf(flag, text);
      refuse(flag, rangeRefusal(spec.kind, value, written(text)));
      return value;
    }
    case 'integer': {
      const value = numberOf(flag, text);
      refuse(flag, rangeRefusal(spec.kind, value, written(text)));
      refuse(flag, inexactWholeRefusal(text, value));
      return value;
    }
    case 'perAxis': {
      const parts = text.split(',');
      const values = parts.map((part) => numberOf(flag, part));
      // The count and its wording are the core's (the catalogue's), as the page's form says them.
      refuse(flag, perAxisRefusal(spec.kind, values.length === 1 ? values[0]! : values, parts.map(written)));
      if (spec.kind.notWhole !== undefined) parts.forEach((part, i) => refuse(flag, inexactWholeRefusal(part, values[i]!)));
      return values.length === 1 ? values[0] : values;
    }
    case 'choice':
      if (!spec.kind.values.includes(text)) {
        throw new UsageError(`${quoted(flag)}: expected one of ${spec.kind.values.join(', ')}, got '${quoted(text)}'`);
      }
      return text;
    case 'boolean':
      if (text !== 'true' && text !== 'false') throw new UsageError(`${quoted(flag)}: expected true or false, got '${quoted(text)}'`);
      return text === 'true';
  }
}

/** How the value of a flag is written, in usage lines. */
function valueHint(spec: OptionSpec): string {
  const kind = spec.kind;
  switch (kind.type) {
    case 'point':
      return 'X,Y[,Z...]';
    case 'choice':
      return kind.values.join('|');
    case 'boolean':
      return 'true|false';
    case 'perAxis':
      return 'N[,N,N]';
    case 'number':
    case 'integer':
      return 'N';
  }
}

/** One help line: the flag, its value, its doc and its default. */
export function describeOption(spec: OptionSpec): string {
  const flag = `${flagOf(spec.name)} ${valueHint(spec)}`;
  const extra = spec.required ? ' (required)' : spec.default !== null ? ` (default ${spec.default})` : '';
  const condition = spec.appliesWith ? ` (with ${flagOf(spec.appliesWith.option)} ${spec.appliesWith.value} only)` : '';
  return `    ${flag.padEnd(30)} ${spec.doc}${extra}${condition}`;
}

/** The --format of a command, one of `formats` (json when absent). */
export function pickFormat<F extends string>(flags: Flags, formats: readonly F[]): F {
  const text = flagText(flags, '--format') ?? 'json';
  const format = formats.find((f) => f === text);
  if (format === undefined) {
    const listed = `${formats.slice(0, -1).join(', ')} or ${formats.at(-1)}`;
    throw new UsageError(`--format: expected ${listed}, got '${quoted(text)}'`);
  }
  return format;
}

/** Options from flags, each checked against its spec; the `own` flags are the command's, not options. */
export function optionsFromFlags(
  flags: Flags,
  specs: readonly OptionSpec[],
  what: string,
  own: readonly string[] = ['--algorithm', '--format'],
): Record<string, unknown> {
  const options: Record<string, unknown> = {};
  for (const [flag, text] of flags) {
    if (own.includes(flag)) continue;
    const spec = specs.find((o) => flagOf(o.name) === flag);
    if (!spec) throw new UsageError(`unknown flag ${quoted(flag)} for ${what} (it takes ${specs.map((o) => flagOf(o.name)).join(', ')})`);
    options[spec.name] = optionValue(spec, flag, givenText(flag, text));
  }
  return options;
}
