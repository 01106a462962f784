/**
 * AppState <-> URL query, the permalink format, also used for localStorage:
 *
 *   ?mode=trace&algorithm=regions&from=0,0,0&to=10,7,6&tie=advance&step=3&speed=2&view=3d
 *   ?mode=compare&algorithm=regions&other=greedy&layout=side&from=0,0,0&to=10,7,6
 *   ?mode=gcode&gcode=G1%20X10&stepsPerMm=80&lineAlgorithm=regions&arcAlgorithm=circle&slowdown=10
 *   ?mode=experiment&algorithm=regions&count=100&seed=1&maxCoordinate=100
 *   ...&decision3d=1&camera=12.5,-30,20,5,3.5,3,1&follow=1&legend=folded&embed=1&explain=0
 *
 * Option keys are the API's option names, so a link reads like the CLI's
 * flags (--from 0,0,0); a mode writes only its own keys. `step` is the point
 * index shown (steps taken); `camera` is position x,y,z, target x,y,z and
 * zoom, absent while the page frames the path itself; `decision3d` (1 or 0)
 * is the view's decision overlay (an exit face, a circle's candidates);
 * `slowdown` (G-code mode) plays in machine time that many times slower
 * than real time, absent when playback counts steps per second.
 * `follow=1` keeps the camera on the current cell (written only when on);
 * `legend=folded` shows the view's legend as its one line (only when folded);
 * `explain=0` leaves the step's reason out of an embedded view.
 * `points` (trace mode) is the learner's points of Check points, as pasted.
 * `playing` is left out on purpose: a page opened from a link starts
 * paused, as moving content should not start by itself.
 */
import { inexactWholeRefusal, quoted, readDecimal } from '../core/guard.js';
import type { AlgorithmInfo, OptionSpec } from '../core/types.js';
import { AXIS_NAMES, countOf, listed } from '../format.js';
import {
  type AppState,
  type CameraState,
  type Catalogue,
  COMPARE_LAYOUTS,
  DRIVE_KEYS,
  EXCLUSIVE_OPTIONS,
  MODES,
  type OptionValue,
  PAGE_OPTIONS,
  PROJECTIONS,
  SLOWDOWNS,
  SPEEDS_STEPS_PER_SECOND,
  defaultAlgorithm,
  comparableWith,
  defaultOptions,
  defaultProjection,
  defaultState,
  axisChoices,
  axisCount,
  machineSpecs,
  randomLinesExperiment,
  sharedOptionSpecs,
  tracedAlgorithms,
  withAxes,
} from './app-state.js';

/**
 * A program, or a learner's points, longer than this many characters stays
 * out of the URL (links get unwieldy, and servers refuse long ones);
 * localStorage keeps it.
 */
export const GCODE_URL_LIMIT = 2000;

/**
 * A number of a value of whole numbers as its query text says it, or
 * undefined when the text is no number, or a number the double does not
 * say (inexactWholeRefusal: 9007199254740993 would be read as
 * 9007199254740992, 1e-400 as 0, and the form and the core would speak of
 * that number, not of the link's).
 */
function readWhole(text: string): number | undefined {
  const value = readDecimal(text);
  return value === undefined || inexactWholeRefusal(text, value) !== undefined ? undefined : value;
}

/**
 * An option's value from its query text, or undefined when the text cannot be
 * that kind of value. Numbers are kept as given (even out of range or
 * fractional): the core judges them and the form shows its verdict; but a
 * value of whole numbers must be the number its text says (readWhole).
 */
function parseOption(spec: OptionSpec, text: string): OptionValue | undefined {
  switch (spec.kind.type) {
    case 'point': {
      const coords = text.split(',').map(readWhole);
      return coords.every((c) => c !== undefined) ? (coords as number[]) : undefined;
    }
    case 'choice':
      return spec.kind.values.includes(text) ? text : undefined;
    case 'number':
      return readDecimal(text);
    case 'integer':
      return readWhole(text);
    case 'perAxis': {
      const values = text.split(',').map(spec.kind.notWhole === undefined ? readDecimal : readWhole);
      if (values.some((v) => v === undefined)) return undefined;
      return values.length === 1 ? values[0]! : (values as number[]);
    }
    case 'boolean':
      return text === 'true' ? true : text === 'false' ? false : undefined;
  }
}

function formatOption(value: OptionValue): string {
  return Array.isArray(value) ? value.join(',') : String(value);
}

/** Values of `specs` read from `params` over `into` (which holds the defaults). */
function readOptions(params: URLSearchParams, specs: readonly OptionSpec[], into: Record<string, OptionValue>, unread?: string[]): Record<string, OptionValue> {
  for (const spec of specs) {
    const text = params.get(spec.name);
    if (text === null || spec.name in PAGE_OPTIONS) continue;
    const value = parseOption(spec, text);
    if (value !== undefined) into[spec.name] = value;
    else unread?.push(unreadKey(spec.name, text));
  }
  return into;
}

/** What a link says that the page does not take as it is, said in a note over the view. */
export interface LinkNotes {
  /** Keys it cannot read, each left at its default, as "tie=sideways". */
  unread: string[];
  /** Its points of another coordinate count than the page's axes, as fitted: "from and to had 2 coordinates; regions takes 3: z = 0 added". */
  fitted: string[];
  /** Keys it gives more than once with another value, each read by its first ("to=5,5,5 (not 9,9,9)"); absent when none is. */
  repeated?: string[];
  /** The point index its `step` names, as read: one past the path's end is shown at the end, which only the trace knows (its step count), so the note says it once traced. */
  step?: number;
}

/** A key of a link the page could not read, as the page says it: "tie=sideways". */
function unreadKey(key: string, text: string): string {
  return `${key}=${quoted(text)}`;
}

/** Camera numbers are written to this many decimals: far below a pixel, and a link stays short. */
const CAMERA_DECIMALS = 4;

/** A camera rounded as the URL writes it, so the state and its link agree exactly. */
export function roundCamera(camera: CameraState): CameraState {
  const r = (v: number) => Number(v.toFixed(CAMERA_DECIMALS));
  return {
    position: camera.position.map(r) as CameraState['position'],
    target: camera.target.map(r) as CameraState['target'],
    zoom: r(camera.zoom),
  };
}

/**
 * Farthest a camera may stand from the origin, grid units, and its largest
 * zoom: past any path (coordinates are within ±2^30) by far, and short of
 * where 32-bit floats, which WebGL draws with, lose the picture (a link's
 * camera at 1e308 drew a blank view).
 */
const CAMERA_REACH = 2 ** 40;
const MAX_ZOOM = 1e6;

/** A link's camera, or null (framed by the page) when it is malformed or out of reach. */
function parseCamera(text: string | null): CameraState | null {
  const v = (text ?? '').split(',').map(readDecimal);
  if (v.length !== 7 || v.some((c) => c === undefined)) return null;
  const n = v as number[];
  const [position, target, zoom] = [n.slice(0, 3), n.slice(3, 6), n[6]!];
  const reachable = n.slice(0, 6).every((c) => Math.abs(c) <= CAMERA_REACH) && zoom > 0 && zoom <= MAX_ZOOM;
  // The camera looks from its position at its target: one point is no direction.
  if (!reachable || position.every((c, i) => c === target[i])) return null;
  return { position: position as CameraState['position'], target: target as CameraState['target'], zoom };
}

export interface QueryOptions {
  /** Programs and learner's points longer than this many characters are left out (the URL, and storage's parts: persist.ts keeps longer ones apart); Infinity keeps any. */
  gcodeLimit: number;
}

/** Query text (without '?') for a state; commas are left readable. */
export function stateToQuery(state: AppState, { gcodeLimit }: QueryOptions): string {
  const pairs: [string, string][] = [['mode', state.mode]];
  const options = (values: Record<string, OptionValue>) => {
    for (const [name, value] of Object.entries(values)) pairs.push([name, formatOption(value)]);
  };
  if (state.mode !== 'gcode') pairs.push(['algorithm', state.algorithm]);
  if (state.mode === 'compare') pairs.push(['other', state.other], ['layout', state.layout]);
  if (state.mode === 'trace' || state.mode === 'compare') options(state.options);
  if (state.mode === 'trace' && state.learnerPoints !== '' && state.learnerPoints.length <= gcodeLimit) pairs.push(['points', state.learnerPoints]);
  if (state.mode === 'gcode') {
    if (state.gcode.length <= gcodeLimit) pairs.push(['gcode', state.gcode]);
    options(state.machine);
    if (state.slowdown !== null) pairs.push(['slowdown', String(state.slowdown)]);
  }
  if (state.mode === 'experiment') options(state.experiment);
  else {
    pairs.push(['step', String(state.pointIndex)], ['speed', String(state.speed)], ['view', state.projection], ['decision3d', state.decision3d ? '1' : '0']);
    if (state.camera) {
      const c = state.camera;
      pairs.push(['camera', [...c.position, ...c.target, c.zoom].map(formatOption).join(',')]);
    }
    if (state.follow) pairs.push(['follow', '1']);
    if (state.legendFolded) pairs.push(['legend', 'folded']);
  }
  if (state.embed) pairs.push(['embed', '1']);
  if (!state.explain) pairs.push(['explain', '0']);
  return pairs.map(([k, v]) => `${encodeURIComponent(k)}=${encodeURIComponent(v).replaceAll('%2C', ',')}`).join('&');
}

/**
 * Why a link's points get `axes` coordinates: the only count the algorithms
 * take ("regions takes 3"), else the count of from, which the page shows
 * ("from has 2"), else the page's choice (nd's from=0,0,0,0: "the page shows 3").
 */
function axesReason(infos: readonly AlgorithmInfo[], from: OptionValue | undefined, axes: number): string {
  if (axisChoices(infos).length === 1) return `${listed(infos.map((a) => a.id))} ${infos.length === 1 ? 'takes' : 'take'} ${axes}`;
  if (Array.isArray(from) && from.length === axes) return `from has ${axes}`;
  return `the page shows ${axes}`;
}

/**
 * What fitting the points of `options` to `axes` coordinates (withAxes)
 * changes, one note per change with the points it is made to: "from and to
 * had 2 coordinates; regions takes 3: z = 0 added", "to had 4 coordinates;
 * from has 2: z and a dropped".
 */
function fittingNotes(options: Readonly<Record<string, OptionValue>>, axes: number, reason: string): string[] {
  const axisName = (axis: number) => AXIS_NAMES[axis] ?? `coordinate ${axis + 1}`;
  const pointsByChange = new Map<string, string[]>();
  for (const [name, value] of Object.entries(options)) {
    if (!Array.isArray(value) || value.length === axes) continue;
    const count = value.length;
    const change =
      count < axes
        ? `${listed(Array.from({ length: axes - count }, (_, i) => `${axisName(count + i)} = 0`))} added`
        : `${listed(Array.from({ length: count - axes }, (_, i) => axisName(axes + i)))} dropped`;
    const note = `had ${countOf(count, 'coordinate')}; ${reason}: ${change}`;
    pointsByChange.set(note, [...(pointsByChange.get(note) ?? []), name]);
  }
  return [...pointsByChange].map(([note, names]) => `${listed(names)} ${note}`);
}

/** Keys that say a query describes a state (any option name counts too). */
export const STATE_KEYS = ['mode', 'algorithm', 'other', 'step', 'speed', 'slowdown', 'view', 'decision3d', 'camera', 'follow', 'legend', 'gcode', 'points', 'embed', 'explain'];

/**
 * The state a query describes, or undefined when it has none of the state's
 * keys. Keys it lacks, or whose text is unusable, take their defaults: a link
 * shows what its sender saw, not a mix with the reader's last visit (the
 * parts of other modes aside: see persist.ts). Without `algorithm` (or with
 * an id the catalogue does not have) it is the default algorithm; an
 * `other` that cannot be compared with it gives way to its default partner.
 * What the page does not take as the link says it is told in `notes`.
 */
export function stateFromQuery(query: string, catalogue: Catalogue, notes?: LinkNotes): AppState | undefined {
  const params = new URLSearchParams(query);
  const unread = notes?.unread;
  // What the link says that the page cannot read, each left at its default (into `unread`).
  const taken = (key: string, read: boolean) => {
    const text = params.get(key);
    if (text !== null && !read) unread?.push(unreadKey(key, text));
  };
  const { algorithms } = catalogue;
  const optionNames = algorithms.flatMap((a) => a.options.map((o) => o.name));
  if (![...STATE_KEYS, ...optionNames].some((k) => params.has(k))) return undefined;
  // A key given again with another value (a link edited by hand, "&to=9,9,9"
  // added at its end) is read by its first value, and said so: the later
  // value was dropped without a word.
  const experiment = randomLinesExperiment(catalogue);
  const readKeys = new Set([...STATE_KEYS, 'layout', ...optionNames, ...machineSpecs(catalogue).map((s) => s.name), ...(experiment?.options.map((o) => o.name) ?? [])]);
  for (const key of readKeys) {
    const [first, ...later] = params.getAll(key);
    const others = [...new Set(later.filter((text) => text !== first))];
    if (notes && others.length > 0) (notes.repeated ??= []).push(`${unreadKey(key, first!)} (not ${others.map(quoted).join(', ')})`);
  }
  const mode = MODES.find((m) => m === params.get('mode')) ?? 'trace';
  taken('mode', mode === params.get('mode'));
  // Any algorithm in any mode: experiment mode runs a line algorithm of its
  // own choosing (experimentAlgorithm) when this one is an arc.
  const info = algorithms.find((a) => a.id === params.get('algorithm')) ?? defaultAlgorithm(algorithms);
  taken('algorithm', info.id === params.get('algorithm'));
  const state = defaultState(info, algorithms);
  state.mode = mode;
  // Only an algorithm that can be compared with the first one (else the default partner).
  const other = comparableWith(info, algorithms).find((a) => a.id === params.get('other'));
  if (other) state.other = other.id;
  taken('other', other !== undefined);
  state.layout = COMPARE_LAYOUTS.find((l) => l === params.get('layout')) ?? state.layout;
  taken('layout', state.layout === params.get('layout'));

  const infos = tracedAlgorithms(state, algorithms);
  state.options = readOptions(params, sharedOptionSpecs(infos), defaultOptions(infos), unread);
  // A link naming one of two options the core takes only apart leaves out
  // the other's default (the example's segmentLength beside a link's
  // tolerance was refused: "give segmentLength or tolerance, not both").
  for (const pair of EXCLUSIVE_OPTIONS) {
    for (const [named, other] of [pair, [pair[1], pair[0]]] as const) {
      if (params.has(named) && !params.has(other)) delete state.options[other];
    }
  }
  // The page shows 2 or 3 axes (axisCount): points of another count (nd's
  // from=0,0,0,0) are fitted to the axes its form shows, as the axis control
  // fits them, rather than traced in 4D behind 3 fields (the axes' hint
  // says the CLI and the API take them all); and said in the link's note
  // (regions' from=0,0 was traced with z = 0 without a word).
  const axes = axisCount(infos, state.options);
  if (Object.values(state.options).some((v) => Array.isArray(v) && v.length !== axes)) {
    // Of the points the link gives: a default point fitted too (nd's to
    // beside a link's from=1,2) is no news of the link's.
    const linked = Object.fromEntries(Object.entries(state.options).filter(([name]) => params.has(name)));
    notes?.fitted.push(...fittingNotes(linked, axes, axesReason(infos, state.options.from, axes)));
    state.options = withAxes(state.options, axes);
  }
  // A link that names any drive setting names all it uses: a cleared
  // steps/mm (to use the motor's) stays cleared. Named with a value the page
  // cannot read (stepsPerMm=80,abc), it is as if not named: the default
  // stays, not a machine the core calls "stepsPerMm: missing".
  const linkedMachine = readOptions(params, machineSpecs(catalogue), {}, unread);
  if (DRIVE_KEYS.some((k) => k in linkedMachine)) delete state.machine.stepsPerMm;
  state.machine = { ...state.machine, ...linkedMachine };
  if (experiment) state.experiment = readOptions(params, experiment.options, state.experiment, unread);
  state.gcode = params.get('gcode') ?? state.gcode;
  state.learnerPoints = params.get('points') ?? state.learnerPoints;

  const step = readWhole(params.get('step') ?? '');
  if (step !== undefined && Number.isSafeInteger(step) && step >= 0) state.pointIndex = step;
  taken('step', state.pointIndex === step);
  if (notes && state.pointIndex === step) notes.step = step;
  const speed = readDecimal(params.get('speed') ?? '');
  if (SPEEDS_STEPS_PER_SECOND.some((s) => s === speed)) state.speed = speed!;
  taken('speed', state.speed === speed);
  const slowdown = readDecimal(params.get('slowdown') ?? '');
  if (SLOWDOWNS.some((s) => s === slowdown)) state.slowdown = slowdown!;
  taken('slowdown', state.slowdown === slowdown);
  state.projection = PROJECTIONS.find((p) => p === params.get('view')) ?? defaultProjection(axisCount(infos, state.options));
  taken('view', state.projection === params.get('view'));
  state.decision3d = params.get('decision3d') === '1';
  state.follow = params.get('follow') === '1';
  state.legendFolded = params.get('legend') === 'folded';
  state.camera = parseCamera(params.get('camera'));
  taken('camera', state.camera !== null);
  state.embed = params.get('embed') === '1';
  state.explain = params.get('explain') !== '0';
  return state;
}
