/**
 * The page's one state: the mode, which algorithm(s), their options as the
 * user typed them, the G-code program and machine, the experiment, the view
 * (projection, camera), the point shown and the playback. Every view reads
 * it; inputs change it through the Store; state/persist.ts keeps it in the
 * URL and localStorage.
 */
import type { ExperimentInfo } from '../core/experiment.js';
import type { AlgorithmInfo, Catalogue, OptionSpec, TraceOptions } from '../core/types.js';

/** What the core offers: its algorithms, its experiments and the G-code machine's settings. */
export type { Catalogue };

/** An option's value: a point as integers per axis, a choice as its word, a number, a yes/no. */
export type OptionValue = number[] | number | string | boolean;

/**
 * trace: one algorithm on one move; compare: two algorithms on the same
 * move; gcode: a program on a modelled machine; experiment: Wang's batch of
 * random lines (Figure 9).
 */
export const MODES = ['trace', 'compare', 'gcode', 'experiment'] as const;
export type Mode = (typeof MODES)[number];

/** overlay: both paths in one view; side: one view each, cameras linked. */
export const COMPARE_LAYOUTS = ['overlay', 'side'] as const;
export type CompareLayout = (typeof COMPARE_LAYOUTS)[number];

/** 3d: perspective, orbiting; 2d: orthographic, looking down a planar path's normal, with the pixel grid. */
export const PROJECTIONS = ['3d', '2d'] as const;
export type Projection = (typeof PROJECTIONS)[number];

/** Where the camera is: position and orbit target in grid units, and the zoom of the 2D (orthographic) view. */
export interface CameraState {
  position: [number, number, number];
  target: [number, number, number];
  zoom: number;
}

export interface AppState {
  mode: Mode;
  /** Algorithm id from the catalogue (compare mode: the first, a). */
  algorithm: string;
  /**
   * Compare mode: the second algorithm, b. It takes the options it declares
   * from `options`; the first algorithm again when it is compared with
   * itself by an option (the catalogue's comparedBy), whose other value it runs.
   */
  other: string;
  layout: CompareLayout;
  /** The algorithm's options, by OptionSpec name (from, to, tie...); absent ones take the core's default. */
  options: Record<string, OptionValue>;
  /** G-code mode: the program's text. */
  gcode: string;
  /**
   * G-code mode: the user's own program (typed or pasted, not a sample as
   * loaded) that the page replaced with another (a sample picked, a link's
   * program), kept so that it can be brought back; '' for none. The page
   * offers it until it is brought back or the user types a program again.
   */
  replacedProgram: string;
  /** What replaced `replacedProgram`, as the offer names it ("the sample 'Helix'"); '' with no replaced program. */
  replacedBy: string;
  /**
   * G-code mode: the second program offered back, beside replacedProgram:
   * of two programs typed in two tabs at the same time, the one written over
   * (persist.ts's otherTabEdits kept it as replacedProgram), once the one
   * kept over it was replaced in turn (a sample picked, a link opened) and
   * became replacedProgram; '' for none. Each is the other's "another tab's
   * program, typed at the same time": bringing one back offers the other as
   * after the clash (programBroughtBack).
   */
  secondReplacedProgram: string;
  /** Trace mode: a learner's points as pasted into Check points (CSV, rows or a printed list), checked against the rule; '' for none. */
  learnerPoints: string;
  /**
   * Trace mode: the learner's points another tab had, changed there at the
   * same time as here and written over by this tab's (persist.ts), or the
   * points typed here that a link's replaced, kept so that they can be
   * brought back, as replacedProgram is; '' for none. Offered until brought
   * back or the points are changed again.
   */
  replacedPoints: string;
  /** What replaced `replacedPoints`, as the offer names it ("the link's points", ANOTHER_TABS_POINTS); '' with none. */
  replacedPointsBy: string;
  /** Trace mode: the second points offered back, beside replacedPoints, as secondReplacedProgram is for programs; '' for none. */
  secondReplacedPoints: string;
  /** G-code mode: the machine, by GcodeSettings name (stepsPerMm or stepAngle + microsteps + pitch, line/arc algorithm). */
  machine: Record<string, OptionValue>;
  /** Experiment mode: the random-lines options (count, seed, maxCoordinate, dims); the algorithm is `algorithm`. */
  experiment: Record<string, OptionValue>;
  projection: Projection;
  /** null: framed by the page (the whole path from the default direction). */
  camera: CameraState | null;
  /** Draw the current step's decision in the view (scene/decision-overlay.ts: an exit face, a circle's candidates), for traces that have one. */
  decision3d: boolean;
  /** The camera follows the current cell at a readable zoom (scene/follow.ts), instead of staying where it is. */
  follow: boolean;
  /** The view's legend folded to one line, its button (a short view's legend covered the axes' names). */
  legendFolded: boolean;
  /** Point index shown: the position after this many steps (0..=steps). */
  pointIndex: number;
  playing: boolean;
  /** Playback speed in steps per second, one of SPEEDS_STEPS_PER_SECOND. */
  speed: number;
  /**
   * G-code mode: play in machine time, the program's planned instants
   * slowed down this many times (one of SLOWDOWNS); null: `speed` steps per
   * second, every step alike.
   */
  slowdown: number | null;
  /** Chrome-less view for an iframe (?embed=1). */
  embed: boolean;
  /** Embedded, the current step's reason under the timeline (off with ?explain=0). */
  explain: boolean;
}

/** The state's keys whose change means the core must run again, by mode: a mode's inputs. */
export const MODE_INPUT_KEYS: Record<Mode, readonly (keyof AppState)[]> = {
  trace: ['algorithm', 'options'],
  compare: ['algorithm', 'other', 'options'],
  gcode: ['gcode', 'machine'],
  experiment: ['algorithm', 'experiment'],
};

export const SPEEDS_STEPS_PER_SECOND = [0.5, 1, 2, 4, 8, 16, 32, 64, 256, 1024, 8192] as const;

const DEFAULT_SPEED = 2;

/** Machine-time playback: real time (1), or 10, 100 or 1000 times slower (a corner of a fast move lasts milliseconds). */
export const SLOWDOWNS = [1, 10, 100, 1000] as const;

/** The algorithm a first visit shows: DEFAULT_ALGORITHM, or the catalogue's first. */
export function defaultAlgorithm(catalogue: readonly AlgorithmInfo[]): AlgorithmInfo {
  const info = catalogue.find((a) => a.id === DEFAULT_ALGORITHM) ?? catalogue[0];
  if (!info) throw new Error('the core lists no algorithms');
  return info;
}

const DEFAULT_ALGORITHM = 'regions';

/**
 * The second algorithm compare mode starts with for `info`: greedy against
 * a line algorithm (the lesson of the 2009 blog: greedy strays from the
 * line), arc-segments against circle (direct arc stepping against chords),
 * for those two their natural partners, and the helix against itself by its
 * other method (its comparedBy: no other algorithm takes a move that rises).
 */
export function defaultOther(info: AlgorithmInfo, catalogue: readonly AlgorithmInfo[]): AlgorithmInfo {
  const partner: Record<string, string> = { greedy: 'walk6', circle: 'arc-segments', 'arc-segments': 'circle', helix: 'helix' };
  const wanted = partner[info.id] ?? (info.family === 'arc' ? 'arc-segments' : 'greedy');
  const found = catalogue.find((a) => a.id === wanted && (a !== info || comparedBy(a))) ?? catalogue.find((a) => a.family === info.family && a !== info);
  return found ?? info;
}

/** The choice option `info` is compared with itself by (the catalogue's comparedBy: the helix's method), if any. */
function comparedBy(info: AlgorithmInfo): (OptionSpec & { kind: { type: 'choice' } }) | undefined {
  const spec = info.options.find((o) => o.name === info.comparedBy);
  return spec?.kind.type === 'choice' ? (spec as OptionSpec & { kind: { type: 'choice' } }) : undefined;
}

/** What tells the two sides of an algorithm compared with itself apart: the option, and the value each side runs. */
export interface ComparedValues {
  option: string;
  values: [string, string];
}

/**
 * In compare mode with an algorithm against itself: the value of its
 * compared option (comparedBy) each side runs, the first's as chosen (else
 * its default) and the second's the first other one; else undefined.
 */
export function comparedValues(state: AppState, catalogue: readonly AlgorithmInfo[]): ComparedValues | undefined {
  if (state.mode !== 'compare' || state.other !== state.algorithm) return undefined;
  const info = catalogue.find((a) => a.id === state.algorithm);
  const spec = info && comparedBy(info);
  if (!spec) return undefined;
  const chosen = state.options[spec.name];
  const first = typeof chosen === 'string' ? chosen : (spec.default ?? spec.kind.values[0]!);
  const second = spec.kind.values.find((v) => v !== first) ?? first;
  return { option: spec.name, values: [first, second] };
}

/**
 * Options the page sets itself instead of showing a field. The page caps the
 * path length at what a browser draws and scrubs comfortably (the core's own
 * default, 50,000,000, is for files and the CLI).
 */
export const PAGE_OPTIONS: Readonly<Record<string, OptionValue>> = { maxSteps: 1_500_000 };

/** The experiment of experiment mode: Wang's random lines. */
export function randomLinesExperiment(catalogue: Catalogue): ExperimentInfo | undefined {
  return catalogue.experiments.find((e) => e.id === 'random-lines');
}

/** The algorithms the picker offers in `mode`: in experiment mode those of the family the experiment traces, else all. */
export function offeredAlgorithms(mode: Mode, catalogue: Catalogue): AlgorithmInfo[] {
  const family = mode === 'experiment' ? randomLinesExperiment(catalogue)?.family : undefined;
  return family ? catalogue.algorithms.filter((a) => a.family === family) : catalogue.algorithms;
}

/**
 * The algorithm experiment mode runs: the state's, when the experiment
 * traces its family, else the experiment's default. An arc left in the
 * state stays there for Trace and Compare to come back to (entering the
 * experiment replaced it, and the move typed for it, with regions').
 */
export function experimentAlgorithm(state: AppState, catalogue: Catalogue): AlgorithmInfo {
  const offered = offeredAlgorithms('experiment', catalogue);
  return offered.find((a) => a.id === state.algorithm) ?? defaultAlgorithm(offered);
}

/**
 * Algorithms that can be compared with `info`: the others of its family that
 * take an axis count of the page it takes, and `info` itself when it is
 * compared by an option (comparedBy; else an algorithm against itself
 * draws one path twice).
 */
export function comparableWith(info: AlgorithmInfo, catalogue: readonly AlgorithmInfo[]): AlgorithmInfo[] {
  return catalogue.filter((a) => (a !== info || comparedBy(a)) && a.family === info.family && axisChoices([info, a]).length > 0);
}

/** Axes the page shows: 2 or 3 (a 3D view), within what the algorithm takes. */
const PAGE_AXES = [2, 3] as const;

/** The axis counts of PAGE_AXES that every algorithm of `infos` accepts. */
export function axisChoices(infos: readonly AlgorithmInfo[]): number[] {
  return PAGE_AXES.filter((n) => infos.every((info) => n >= info.minDims && n <= info.maxDims));
}

/**
 * Axes of a point option on the page: the length of the `from` the user
 * has, when the algorithms take it; else the example's (greedy, walk6 and
 * dda open in 2D); else 3 when allowed.
 */
export function axisCount(infos: readonly AlgorithmInfo[], options: Readonly<Record<string, OptionValue>>): number {
  const choices = axisChoices(infos);
  const from = options.from;
  if (Array.isArray(from) && choices.includes(from.length)) return from.length;
  const example = infos[0]?.example.options.from;
  if (Array.isArray(example) && choices.includes(example.length)) return example.length;
  return choices.includes(3) ? 3 : (choices[0] ?? 3);
}

/** Every option the algorithms of `infos` declare, each name once (the first declaration), less PAGE_OPTIONS. */
export function sharedOptionSpecs(infos: readonly AlgorithmInfo[]): OptionSpec[] {
  const seen = new Map<string, { spec: OptionSpec; from: AlgorithmInfo }>();
  for (const info of infos) {
    for (const spec of info.options) {
      if (spec.name in PAGE_OPTIONS) continue;
      const first = seen.get(spec.name);
      if (!first) seen.set(spec.name, { spec, from: info });
      else if (first.spec.default !== spec.default && first.spec.default !== null) {
        // Two defaults (regions' tie advance, bresenham3d's hold): the field
        // offers "the algorithm's default" and says each one's, rather than
        // show the first one's while the second ran with its own.
        const own = `${first.from.id}: ${first.spec.default ?? 'none'}, ${info.id}: ${spec.default ?? 'none'}`;
        seen.set(spec.name, { spec: { ...first.spec, default: null, doc: `${first.spec.doc} Left at "the algorithm's default", each algorithm runs with its own (${own}).` }, from: first.from });
      } else if (first.from === info && comparedBy(info) === spec) {
        // Compared with itself, the field is the first side's: say where the second's value comes from.
        seen.set(spec.name, { spec: { ...spec, doc: `${spec.doc} Compared with itself, ${info.id} runs the ${spec.name} chosen here first and the other one second.` }, from: info });
      }
    }
  }
  return [...seen.values()].map((s) => s.spec);
}

/** A point cut or padded with zeros to `axes` coordinates. */
function fitPoint(point: readonly unknown[], axes: number): number[] {
  return Array.from({ length: axes }, (_, a) => (typeof point[a] === 'number' ? (point[a] as number) : 0));
}

/** Every point option of `options` fitted to `axes` coordinates (the axis-count control). */
export function withAxes(options: Readonly<Record<string, OptionValue>>, axes: number): Record<string, OptionValue> {
  const out: Record<string, OptionValue> = {};
  for (const [name, value] of Object.entries(options)) out[name] = Array.isArray(value) ? fitPoint(value, axes) : value;
  return out;
}

/**
 * The options of a first visit for `infos` (one algorithm, or a compared
 * pair): the first one's example move (for regions, Wang et al.'s
 * (0,0,0)->(10,7,6), the line of their Tables 1 and 2, so a learner can
 * check the page against the paper), with points fitted to the axes the
 * page shows. Other options are left out, so the core's default applies
 * (some apply only with others: helix's lineAlgorithm with method segments).
 */
export function defaultOptions(infos: readonly AlgorithmInfo[]): Record<string, OptionValue> {
  const options: Record<string, OptionValue> = {};
  const example = infos[0]?.example.options ?? {};
  const axes = axisCount(infos, {});
  for (const spec of sharedOptionSpecs(infos)) {
    const value = example[spec.name] as OptionValue | undefined;
    if (spec.kind.type === 'point' && Array.isArray(value)) options[spec.name] = fitPoint(value, axes);
    else if (value !== undefined) options[spec.name] = value;
  }
  return options;
}

/** A first visit's machine: 80 steps/mm (a common belt-driven axis), regions for lines, Saleem's circle for arcs. */
const DEFAULT_MACHINE: Readonly<Record<string, OptionValue>> = { stepsPerMm: 80, lineAlgorithm: 'regions', arcAlgorithm: 'circle' };

/**
 * The machine's settings as form fields: the core's catalogue of G-code
 * settings (GcodeSettings), less those the page sets itself. Give steps/mm,
 * or leave it empty and give the step angle, microsteps and pitch (Wang
 * section 3.3); the core names a setting it cannot use.
 */
export function machineSpecs(catalogue: Catalogue): OptionSpec[] {
  return catalogue.gcodeSettings.filter((spec) => !(spec.name in PAGE_OPTIONS));
}

/** Options an algorithm takes one of at most (arc-segments' and a segmented helix's chord rule). */
export const EXCLUSIVE_OPTIONS = [['segmentLength', 'tolerance']] as const;

/** The motor's settings, which give steps per mm together (Wang section 3.3). */
const MOTOR_KEYS = ['stepAngle', 'microsteps', 'pitch'] as const;

/** The machine settings that give steps per mm: directly, or from the motor. */
export const DRIVE_KEYS = ['stepsPerMm', ...MOTOR_KEYS] as const;

/** What setting option `name` clears: the other of its exclusive pair, or the other way of giving steps per mm. */
function alternativesOf(name: string): readonly string[] {
  const pair = EXCLUSIVE_OPTIONS.find((p) => (p as readonly string[]).includes(name));
  if (pair) return pair.filter((other) => other !== name);
  if (name === 'stepsPerMm') return MOTOR_KEYS;
  return (MOTOR_KEYS as readonly string[]).includes(name) ? ['stepsPerMm'] : [];
}

/**
 * `values` with option `name` set to `value` (undefined: cleared, so the
 * core's default applies). A value given for one of two alternatives the
 * core takes only apart clears the other, as a choice between them would
 * ("give segmentLength or tolerance, not both"; stepsPerMm or the motor's
 * three): a form never holds, nor a link carries, a pair the core refuses
 * together (tolerance typed beside the example's segmentLength went into
 * the link, which then opened to an empty view).
 */
export function withOption(values: Readonly<Record<string, OptionValue>>, name: string, value: OptionValue | undefined): Record<string, OptionValue> {
  const next = { ...values };
  if (value === undefined) delete next[name];
  else {
    next[name] = value;
    for (const other of alternativesOf(name)) delete next[other];
  }
  return next;
}

/**
 * withOption for one form, remembering what each value typed cleared and
 * putting it back once no alternative of it is left: stepAngle typed and
 * cleared again brings back the stepsPerMm it cleared (80,80,400 was lost
 * for good), tolerance cleared the example's segmentLength.
 */
export class OptionSetter {
  /** Values a value typed cleared, by option name. */
  readonly #setAside = new Map<string, OptionValue>();

  /** `values` with `name` set to `value` (undefined: cleared), as withOption, with the values set aside put back when they fit again. */
  set(values: Readonly<Record<string, OptionValue>>, name: string, value: OptionValue | undefined): Record<string, OptionValue> {
    // A value set aside that has come back by other means (Back, a link)
    // is the one to keep: clearing it must not bring the old one back.
    for (const other of this.#setAside.keys()) if (other in values) this.#setAside.delete(other);
    const next = withOption(values, name, value);
    if (value !== undefined) {
      // A value typed for an option supersedes what was set aside of it.
      this.#setAside.delete(name);
      for (const other of alternativesOf(name)) if (values[other] !== undefined) this.#setAside.set(other, values[other]);
      return next;
    }
    for (const [other, kept] of this.#setAside) {
      if (alternativesOf(other).some((alternative) => alternative in next)) continue;
      next[other] = kept;
      this.#setAside.delete(other);
    }
    return next;
  }
}

/** What replaced a program of a tab that another tab changed at the same time, as the offer to bring it back says ("Your program (3 lines) was replaced by ..."). */
export const ANOTHER_TABS_PROGRAM = "another tab's program, typed at the same time";

/** The same for points ("Your points (3 lines) were replaced by ..."). */
export const ANOTHER_TABS_POINTS = "another tab's, typed at the same time";

/**
 * A text the user types (a program, points), the one kept to bring back
 * once the page replaced it, what replaced that one, and the second one
 * kept (AppState's secondReplacedProgram); `clash` is what names another
 * tab's text typed at the same time (ANOTHER_TABS_PROGRAM, ANOTHER_TABS_POINTS).
 */
interface KeptTexts {
  text: string;
  replaced: string;
  by: string;
  second: string;
  clash: string;
}

/**
 * `kept` once its text is replaced by `text`, which the page put in (`by`
 * names it, as the offer to bring the replaced one back says): the
 * replaced text is kept when it was `typed` (the user's, not a sample as
 * loaded), else the one kept before, if any, stays (with an offer standing,
 * the text shown is what replaced the user's: typing withdraws the offer).
 * But an offer standing since two tabs typed at the same time (`clash`)
 * holds the text written over, and the one shown is the one kept over it,
 * typed too: both are kept, the one shown first (the tab that kept it
 * typed it, and a tab sees the text it shows as its own), the other second.
 */
function textReplaced(kept: KeptTexts, text: string, by: string, typed: boolean): KeptTexts {
  const { replaced } = kept;
  if (text === kept.text) return kept;
  if (replaced !== '' && kept.by === kept.clash && typed) return { ...kept, text, replaced: kept.text, by, second: replaced };
  if (replaced !== '') return { ...kept, text, by };
  return typed ? { ...kept, text, replaced: kept.text, by, second: '' } : { ...kept, text, replaced: '', by: '', second: '' };
}

/**
 * `kept` once its kept text `which` is brought back (the text shown, a
 * sample's or a link's, dropped): with two kept, the other stays offered
 * as it was after the two tabs' clash, the other tab's text replaced by
 * the one brought back; else none is.
 */
function textBroughtBack(kept: KeptTexts, which: 'replaced' | 'second'): KeptTexts {
  const { replaced, second } = kept;
  if (second === '') return { ...kept, text: replaced, replaced: '', by: '', second: '' };
  const [back, other] = which === 'replaced' ? [replaced, second] : [second, replaced];
  return { ...kept, text: back, replaced: other, by: kept.clash, second: '' };
}

/** AppState's program and the programs kept to bring back. */
export type ProgramFields = Pick<AppState, 'gcode' | 'replacedProgram' | 'replacedBy' | 'secondReplacedProgram'>;

const programTexts = (state: ProgramFields): KeptTexts => ({ text: state.gcode, replaced: state.replacedProgram, by: state.replacedBy, second: state.secondReplacedProgram, clash: ANOTHER_TABS_PROGRAM });
const programFields = (kept: KeptTexts): ProgramFields => ({ gcode: kept.text, replacedProgram: kept.replaced, replacedBy: kept.by, secondReplacedProgram: kept.second });

/** The program fields once `state`'s program is replaced by `program` (textReplaced). */
export function programReplaced(state: ProgramFields, program: string, by: string, typed: boolean): ProgramFields {
  return programFields(textReplaced(programTexts(state), program, by, typed));
}

/** The program fields once the kept program `which` is brought back (textBroughtBack). */
export function programBroughtBack(state: ProgramFields, which: 'replacedProgram' | 'secondReplacedProgram'): ProgramFields {
  return programFields(textBroughtBack(programTexts(state), which === 'replacedProgram' ? 'replaced' : 'second'));
}

/** AppState's points and the points kept to bring back. */
export type PointsFields = Pick<AppState, 'learnerPoints' | 'replacedPoints' | 'replacedPointsBy' | 'secondReplacedPoints'>;

const pointsTexts = (state: PointsFields): KeptTexts => ({ text: state.learnerPoints, replaced: state.replacedPoints, by: state.replacedPointsBy, second: state.secondReplacedPoints, clash: ANOTHER_TABS_POINTS });
const pointsFields = (kept: KeptTexts): PointsFields => ({ learnerPoints: kept.text, replacedPoints: kept.replaced, replacedPointsBy: kept.by, secondReplacedPoints: kept.second });

/** The points fields once `state`'s points are replaced by `points` (a link's: textReplaced); points are the user's unless none. */
export function pointsReplaced(state: PointsFields, points: string, by: string): PointsFields {
  return pointsFields(textReplaced(pointsTexts(state), points, by, state.learnerPoints !== ''));
}

/** The points fields once the kept points `which` are brought back (textBroughtBack). */
export function pointsBroughtBack(state: PointsFields, which: 'replacedPoints' | 'secondReplacedPoints'): PointsFields {
  return pointsFields(textBroughtBack(pointsTexts(state), which === 'replacedPoints' ? 'replaced' : 'second'));
}

/** The program a first visit to the G-code mode shows (public/samples/square.gcode's moves). */
export const DEFAULT_GCODE = '(A 20 mm square, absolute coordinates)\nG21 G90 G17\nG0 X0 Y0 Z0\nG1 X20 Y0 F500\nY20\nX0\nY0\n';

/** Wang's experiment: 100 lines to points in 0..100, seed 1. */
const DEFAULT_EXPERIMENT: Readonly<Record<string, OptionValue>> = { count: 100, seed: 1, maxCoordinate: 100 };

export function defaultState(info: AlgorithmInfo, catalogue: readonly AlgorithmInfo[]): AppState {
  return {
    mode: 'trace',
    algorithm: info.id,
    other: defaultOther(info, catalogue).id,
    layout: 'overlay',
    options: defaultOptions([info]),
    gcode: DEFAULT_GCODE,
    replacedProgram: '',
    replacedBy: '',
    secondReplacedProgram: '',
    learnerPoints: '',
    replacedPoints: '',
    replacedPointsBy: '',
    secondReplacedPoints: '',
    machine: { ...DEFAULT_MACHINE },
    experiment: { ...DEFAULT_EXPERIMENT },
    projection: defaultProjection(axisCount([info], {})),
    camera: null,
    decision3d: false,
    follow: false,
    legendFolded: false,
    pointIndex: 0,
    playing: false,
    speed: DEFAULT_SPEED,
    slowdown: null,
    embed: false,
    explain: true,
  };
}

/** 2D paths open in the 2D view. */
export function defaultProjection(axes: number): Projection {
  return axes === 2 ? '2d' : '3d';
}

/** The algorithms the mode traces: one, or the compared pair (a then b). */
export function tracedAlgorithms(state: AppState, catalogue: readonly AlgorithmInfo[]): AlgorithmInfo[] {
  const find = (id: string) => catalogue.find((a) => a.id === id) ?? defaultAlgorithm(catalogue);
  return state.mode === 'compare' ? [find(state.algorithm), find(state.other)] : [find(state.algorithm)];
}

/**
 * The request the core receives for `info` in this state: the options it
 * declares, as typed and unchecked (the core validates each and names the
 * one at fault), plus the page's own. An option
 * typed where it does not apply (a chord option beside the helix's method
 * saleem) is sent, and the core's refusal names it on its field. In compare
 * mode see comparedRequests.
 */
export function traceOptions(state: AppState, info: AlgorithmInfo): TraceOptions {
  const options: Record<string, unknown> = { algorithm: info.id };
  for (const spec of info.options) if (spec.name in state.options) options[spec.name] = state.options[spec.name];
  return { ...options, ...PAGE_OPTIONS } as TraceOptions;
}

/**
 * The options of `info` in `options` given where they do not apply: with
 * the option their appliesWith names at another value, given or by its
 * default (as the core's Request::inapplicable reads them).
 */
function inapplicable(info: AlgorithmInfo, options: TraceOptions): string[] {
  const given = options as Record<string, unknown>;
  const valueOf = (name: string) => given[name] ?? info.options.find((o) => o.name === name)?.default;
  return info.options
    .filter(({ name, appliesWith }) => appliesWith !== null && given[name] !== undefined && valueOf(appliesWith.option) !== appliesWith.value)
    .map((spec) => spec.name);
}

/** One side of a comparison: its request, and the value that tells it from the other side of an algorithm compared with itself. */
export interface ComparedSide {
  options: TraceOptions;
  distinction: string | undefined;
}

/**
 * Compare mode's two requests (traceOptions), a then b; an algorithm
 * compared with itself runs its compared option's value on each side
 * (comparedValues): the helix's method as chosen, then the other one.
 */
export function comparedRequests(state: AppState, catalogue: readonly AlgorithmInfo[]): [ComparedSide, ComparedSide] {
  const compared = comparedValues(state, catalogue);
  const infos = tracedAlgorithms(state, catalogue);
  const requests = infos.map((info, i) => {
    const options = traceOptions(state, info);
    return compared ? { ...options, [compared.option]: compared.values[i] } : options;
  });
  // One set of fields serves both sides: an option a side declares but
  // where it does not apply (the chord options beside the helix's method
  // saleem) goes to the other side alone where that one takes it, and is
  // left to the core's refusal, which names it, where neither does, as the
  // core's compare() gives options.
  const off = requests.map((options, i) => inapplicable(infos[i]!, options));
  const takes = (i: number, name: string) => name in requests[i]! && !off[i]!.includes(name);
  const [a, b] = requests.map((options, i): ComparedSide => {
    const dropped = off[i]!.filter((name) => takes(1 - i, name));
    const kept = Object.entries(options).filter(([name]) => !dropped.includes(name));
    return { options: Object.fromEntries(kept) as TraceOptions, distinction: compared?.values[i] };
  });
  return [a!, b!];
}
