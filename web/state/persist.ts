/**
 * Keeps the state in the URL (the permalink) and in localStorage, both in the
 * query format of state/query.ts, so nothing a user typed is lost on reload.
 * On load a URL describing a state wins over localStorage.
 */
import { grouped, listed } from '../format.js';
import {
  ANOTHER_TABS_POINTS,
  ANOTHER_TABS_PROGRAM,
  type AppState,
  type Catalogue,
  comparableWith,
  DEFAULT_GCODE,
  defaultAlgorithm,
  defaultState,
  MODES,
  pointsReplaced,
  programReplaced,
} from './app-state.js';
import { draftedHere } from './drafts.js';
import { storage, tabStorage } from './storage-areas.js';
import { GCODE_URL_LIMIT, type LinkNotes, stateFromQuery, stateToQuery } from './query.js';
import type { Store } from './store.js';

const STORAGE_KEY = 'voxpath.state';

/**
 * The texts longer than a link holds (GCODE_URL_LIMIT), a program, the
 * programs it replaced (kept to bring back), a learner's points and the
 * points replaced (the same), are kept
 * as typed, under keys of their own: KEY holds how many pieces of
 * LONG_TEXT_PIECE characters the text is cut into, and KEY.0, KEY.1, ...
 * the pieces. They are written with the rest of the state
 * (throttled, WRITE_DELAY_MS), each piece only when it changed: inside the
 * state's parts they were URL-encoded, quoted and written out again at
 * every write, 0.1 to 0.6 s of the main thread after pasting 200,000 points
 * (3.7 MB) and after each keystroke in them; written whole under one key,
 * 15 to 55 ms.
 */
const LONG_TEXT_KEYS = {
  gcode: 'voxpath.gcode',
  replacedProgram: 'voxpath.replaced',
  secondReplacedProgram: 'voxpath.secondReplaced',
  learnerPoints: 'voxpath.points',
  replacedPoints: 'voxpath.replacedPoints',
  secondReplacedPoints: 'voxpath.secondReplacedPoints',
} as const;

/** Characters per stored piece of a long text: a keystroke rewrites one piece. */
const LONG_TEXT_PIECE = 65_536;

type LongText = keyof typeof LONG_TEXT_KEYS;

/** The query key that holds each long text's field when it is short enough, and a link's program or points (a link never holds a replaced program or points). */
const LONG_TEXT_PARAMS: Record<LongText, string> = {
  gcode: 'gcode',
  replacedProgram: 'replaced',
  secondReplacedProgram: 'secondReplaced',
  learnerPoints: 'points',
  replacedPoints: 'replacedPoints',
  secondReplacedPoints: 'secondReplacedPoints',
};

/** The field that names what replaced each first kept text, stored in its part under a query key of its own name. */
const REPLACED_BY = { replacedProgram: 'replacedBy', replacedPoints: 'replacedPointsBy' } as const;

/**
 * Writes are throttled to one per WRITE_DELAY_MS: playback changes the step
 * many times a second, and browsers throttle (and warn about) rapid
 * history.replaceState calls.
 */
const WRITE_DELAY_MS = 400;

/**
 * The state to start from: the URL's, else the last visit's, else the
 * defaults. The parts of the page the URL does not describe (another mode's
 * move, program, machine or experiment; a program or a learner's points too
 * long for a link) come from the last visit, kept whole in localStorage, so
 * what was typed anywhere survives a reload.
 */
export function loadState(catalogue: Catalogue, notes?: LinkNotes): AppState {
  const address = addressAfterReload();
  // What the address says that the page cannot read (an unknown algorithm, a
  // point with a letter in it), each at its default, and its points fitted
  // to the axes shown: said by the page.
  const linked = stateFromQuery(address, catalogue, notes);
  // An embedded view (in a course page) shows what its link says and nothing
  // of the reader's own last visit: it drew the reader's saved points beside
  // its move and ran the reader's program instead of the sample.
  if (linked?.embed) return linked;
  const stored = storedState(catalogue);
  return linkedState(catalogue, stored, address, linked) ?? stored ?? defaultState(defaultAlgorithm(catalogue.algorithms), catalogue.algorithms);
}

/** The address the last page of this tab had when it left (sessionStorage: this tab's only), for a reload to come back to. */
const RELOAD_KEY = 'voxpath.reload';

/**
 * The address's query, as this tab's page last had it when this load is a
 * reload. The page replaces its address as the state changes (write), and
 * Chromium may reload the address as it was before the last replacement: a
 * reload asked for within WRITE_DELAY_MS of a change (the throttled write
 * comes at pagehide, too late for the request), or while the replacement is
 * on its way to the browser (measured: 6 reloads in 300 asked for right
 * after a replacement requested the address before it). A link's keys win
 * over storage, so what was just typed was lost, and taken for a link's
 * program replacing it. The page leaving notes its address (persistState's
 * pagehide), which a reload takes, once. Not in a frame (an embedded view):
 * two views of one course page share this storage.
 */
function addressAfterReload(): string {
  const search = window.location.search;
  if (window.self !== window.top) return search;
  const note = tabStorage()?.getItem(RELOAD_KEY);
  tabStorage()?.removeItem(RELOAD_KEY);
  const [navigation] = performance.getEntriesByType('navigation') as PerformanceNavigationTiming[];
  // A note from before this format (JSON) is not an address.
  if (navigation?.type !== 'reload' || note === null || note === undefined || note === search || !(note === '' || note.startsWith('?'))) return search;
  window.history.replaceState(window.history.state, '', `${window.location.pathname}${note}${window.location.hash}`);
  return note;
}

/**
 * What localStorage keeps: the permalink of what is shown (the mode, the
 * view, the step), and one of each mode for the part of the page it holds:
 * trace (the algorithm, its move, the learner's points), compare (the
 * second algorithm and the layout), gcode (the program and the machine),
 * experiment (its options); the gcode part also holds the program a sample
 * or a link replaced, kept to bring back, and the trace part the points
 * another tab's replaced. A permalink holds only its own
 * mode's keys, so one alone lost every other mode's input on a reload. The program and the
 * points are written once, in their parts as a link holds them, never in
 * `shown`; longer ones under LONG_TEXT_KEYS (a visit from before those keys
 * kept them whole in their parts, which are read as before).
 */
interface StoredParts {
  shown: string;
  trace: string;
  compare: string;
  gcode: string;
  experiment: string;
  /**
   * Which write last changed an input (EDIT_STAMP and a count), so that
   * another tab follows (followOtherTabs) only a write that changed one, and
   * hears of a long text's edit: its pieces are written apart, before this
   * key, whose parts do not change with them.
   */
  edit?: string;
}

/** This page's part of each StoredParts.edit it writes (the rest counts its writes): tells its writes from another tab's. */
const EDIT_STAMP = Math.random().toString(36).slice(2);
let editsWritten = 0;

/** StoredParts.shown of `state`: the permalink of what it shows, without a program or points. */
function shownOf(state: AppState): string {
  return stateToQuery(state, { gcodeLimit: 0 });
}

/**
 * Whether two queries hold the same keys and values, in any order: a
 * machine read back from storage lists its settings in another order than
 * the default machine's.
 */
function sameQuery(a: string | undefined, b: string | undefined): boolean {
  if (a === b) return true;
  if (a === undefined || b === undefined) return false;
  const [first, second] = [new URLSearchParams(a), new URLSearchParams(b)];
  first.sort();
  second.sort();
  return first.toString() === second.toString();
}

/** What storage keeps of `state`, `shown` its shownOf (a write has it already, to tell whether to write). */
function storedParts(state: AppState, shown: string): StoredParts {
  const part = (mode: AppState['mode']) => stateToQuery({ ...state, mode }, { gcodeLimit: GCODE_URL_LIMIT });
  return {
    shown,
    trace: withReplaced(withReplaced(part('trace'), 'replacedPoints', state), 'secondReplacedPoints', state),
    compare: part('compare'),
    gcode: withReplaced(withReplaced(part('gcode'), 'replacedProgram', state), 'secondReplacedProgram', state),
    experiment: part('experiment'),
  };
}

/**
 * The part `query` with the replaced text `field` of `state` (when short
 * enough: longTextPieces), and for the first one kept what replaced it, added after
 * the part's own keys, which are left as stateToQuery wrote them.
 */
function withReplaced(query: string, field: 'replacedProgram' | 'secondReplacedProgram' | 'replacedPoints' | 'secondReplacedPoints', state: AppState): string {
  const text = state[field];
  if (text === '') return query;
  const by = field === 'replacedProgram' || field === 'replacedPoints' ? REPLACED_BY[field] : undefined;
  const added = new URLSearchParams(by ? { [by]: state[by] } : {});
  if (text.length <= GCODE_URL_LIMIT) added.set(LONG_TEXT_PARAMS[field], text);
  return added.toString() === '' ? query : `${query}&${added}`;
}

/**
 * The mode whose part holds each long text when it is short (and says, when
 * it is long, that it is kept apart). Each is typed apart from the rest of
 * its part (the points beside the move, the program beside the machine),
 * and so written or kept on its own (partsToStore).
 */
const LONG_TEXT_MODES: Record<LongText, AppState['mode']> = { gcode: 'gcode', replacedProgram: 'gcode', secondReplacedProgram: 'gcode', learnerPoints: 'trace', replacedPoints: 'trace', secondReplacedPoints: 'trace' };

/** The input each mode's part keeps for a visit in another mode (storedState takes these of it). */
const PART_INPUTS: Record<AppState['mode'], readonly (keyof AppState)[]> = {
  trace: ['algorithm', 'options', 'learnerPoints', 'replacedPoints', 'replacedPointsBy', 'secondReplacedPoints'],
  compare: ['other', 'layout'],
  gcode: ['gcode', 'replacedProgram', 'replacedBy', 'secondReplacedProgram', 'machine', 'slowdown'],
  experiment: ['experiment'],
};

/** Every input storage keeps: what a tab writes when it changed it, and follows when another tab did. */
const INPUTS = MODES.flatMap((mode) => PART_INPUTS[mode]);

/**
 * The state this tab last wrote (before its first write, the state it
 * loaded with the inputs storage held then: undefined when storage held
 * none), with the inputs it followed since from another tab: an input of
 * the state that is not this one's is an edit of this tab's.
 */
let lastWritten: AppState | undefined;

/** The inputs as storage held them when this tab last wrote or followed them, read as a reload reads them: what another tab's write is told from. */
let storedSeen: AppState | undefined;

/** The StoredParts.edit of storedSeen. */
let editSeen: string | undefined;

/**
 * The StoredParts.shown this tab last wrote (storage's, when this tab
 * loaded, until it writes), with the inputs it followed since: a state
 * whose shown differs has a step, a view or a mode of this tab's to write.
 */
let shownWritten: string | undefined;

/**
 * Every StoredParts.edit storage held before one this tab wrote or followed
 * since: storage holding one of them again went back (followOtherTabs).
 */
const editsSuperseded = new Set<string>();

/**
 * The inputs (of PART_INPUTS) this tab changed since it last wrote (at its
 * first write, those unlike storage's when it loaded; every one when storage
 * held none), an edit undone not among them: only they are written. Each tab wrote every
 * mode's part as it held it, so a program typed in one tab was replaced by
 * another tab's old one as soon as that tab changed anything (a step, a
 * point), and lost at the next reload of the first tab outside G-code mode.
 * An input another tab changed is followed, or, changed in both, said
 * (followOtherTabs).
 */
function changedInputs(state: AppState): Set<keyof AppState> {
  const last = lastWritten;
  return new Set(INPUTS.filter((key) => !last || !sameInput(state[key], last[key])));
}

/** `query` with the value `from` has for `key` (none when it has none). */
function withParamOf(query: string, key: string, from: string): string {
  const params = new URLSearchParams(query);
  const value = new URLSearchParams(from).get(key);
  params.delete(key);
  if (value !== null) params.set(key, value);
  return params.toString();
}

/**
 * `parts`, but with the inputs not `changed` as stored (another tab's, if
 * it wrote them since): a part of which this tab changed nothing is kept
 * whole; one of which it changed only a long text, or all but it, takes
 * that text's parameter from the other (a program too long for the part has
 * none: it is in its keys). Its edit is `edit`, else the stored one.
 */
function partsToStore(parts: StoredParts, changed: Set<keyof AppState>, edit: string | undefined, stored: Partial<StoredParts> | undefined): StoredParts {
  if (!stored) return { ...parts, edit };
  const merged = { ...parts, edit: edit ?? stored.edit };
  for (const mode of MODES) {
    const theirs = stored[mode];
    if (typeof theirs !== 'string') continue;
    const texts = (Object.keys(LONG_TEXT_MODES) as LongText[]).filter((field) => LONG_TEXT_MODES[field] === mode);
    const restChanged = PART_INPUTS[mode].some((key) => !(texts as (keyof AppState)[]).includes(key) && changed.has(key));
    merged[mode] = texts
      .filter((text) => changed.has(text) !== restChanged)
      .reduce((query, text) => withParamOf(query, LONG_TEXT_PARAMS[text], restChanged ? theirs : parts[mode]), restChanged ? parts[mode] : theirs);
  }
  return merged;
}

/**
 * The last visit's state, or undefined when there is none (or it cannot be
 * read). A visit from before the parts were kept stored one permalink.
 */
function storedState(catalogue: Catalogue): AppState | undefined {
  const text = storage()?.getItem(STORAGE_KEY) ?? '';
  const parts = partsOf(text);
  if (!parts) return stateFromQuery(text, catalogue);
  const read = readParts(catalogue, parts);
  if (read?.typed) readAtLoad = { parts, typed: read.typed };
  return read?.typed ? withOtherModes(catalogue, read.shown, new URLSearchParams(parts.shown), read.typed) : read?.shown;
}

/**
 * Storage's parts as loadState read them, and the inputs they keep: what
 * persistState's first write starts from (loaded). Undefined when storage
 * held none (or none this page reads), and in an embedded view, which does
 * not read storage.
 */
let readAtLoad: { parts: Partial<StoredParts>; typed: AppState } | undefined;

/** The parts stored as `text`; undefined when it is not theirs (a visit from before them stored one permalink). */
function partsOf(text: string): Partial<StoredParts> | undefined {
  try {
    const parts: unknown = JSON.parse(text);
    return typeof parts === 'object' && parts !== null ? (parts as Partial<StoredParts>) : undefined;
  } catch {
    return undefined;
  }
}

/**
 * The state shown of `parts`, and every mode's input as its part keeps it
 * (a long text kept apart as `longText` gives it); no input when a part
 * is missing or unreadable (a visit from before a part).
 */
function readParts(
  catalogue: Catalogue,
  parts: Partial<StoredParts>,
  longText: (field: LongText, query: string) => string | undefined = storedLongText,
): { shown: AppState; typed: AppState | undefined } | undefined {
  const read = (query: unknown) => (typeof query === 'string' ? stateFromQuery(query, catalogue) : undefined);
  const shown = read(parts.shown);
  const [trace, compare, gcode, experiment] = [read(parts.trace), read(parts.compare), read(parts.gcode), read(parts.experiment)];
  if (!shown) return undefined;
  if (!trace || !compare || !gcode || !experiment) return { shown, typed: undefined };
  const [traceParams, gcodeParams] = [new URLSearchParams(parts.trace), new URLSearchParams(parts.gcode)];
  const replacedPoints = longText('replacedPoints', parts.trace!) ?? traceParams.get(LONG_TEXT_PARAMS.replacedPoints) ?? '';
  const typed: AppState = {
    ...trace,
    other: compare.other,
    layout: compare.layout,
    gcode: longText('gcode', parts.gcode!) ?? gcode.gcode,
    replacedProgram: longText('replacedProgram', parts.gcode!) ?? gcodeParams.get(LONG_TEXT_PARAMS.replacedProgram) ?? '',
    replacedBy: gcodeParams.get(REPLACED_BY.replacedProgram) ?? '',
    secondReplacedProgram: longText('secondReplacedProgram', parts.gcode!) ?? gcodeParams.get(LONG_TEXT_PARAMS.secondReplacedProgram) ?? '',
    machine: gcode.machine,
    slowdown: gcode.slowdown,
    experiment: experiment.experiment,
    learnerPoints: longText('learnerPoints', parts.trace!) ?? trace.learnerPoints,
    replacedPoints,
    // Kept before points had more than one way to be replaced: by another tab's.
    replacedPointsBy: traceParams.get(REPLACED_BY.replacedPoints) ?? (replacedPoints === '' ? '' : ANOTHER_TABS_POINTS),
    secondReplacedPoints: longText('secondReplacedPoints', parts.trace!) ?? traceParams.get(LONG_TEXT_PARAMS.secondReplacedPoints) ?? '',
  };
  return { shown, typed };
}

/**
 * The long text kept under its own keys for `field`, when its stored part
 * `query` does not hold the field (a part holds it when it is short, and
 * held it at any length before those keys); undefined when a piece of it
 * is missing.
 */
function storedLongText(field: LongText, query: string): string | undefined {
  const store = storage();
  if (!store || new URLSearchParams(query).has(LONG_TEXT_PARAMS[field])) return undefined;
  const key = LONG_TEXT_KEYS[field];
  const pieces = Array.from({ length: storedPieceCount(store, key) }, (_, i) => store.getItem(`${key}.${i}`));
  if (pieces.length === 0 || pieces.some((piece) => piece === null)) return undefined;
  const text = pieces.join('');
  longTextsWritten.set(field, { text, pieces: pieces as string[], kept: true });
  return text;
}

/**
 * How many pieces storage says the long text under `key` is cut into: 0
 * when the count is not a whole number or is more than the keys storage
 * holds, as no count this page writes can be (storage edited by hand, or
 * by another program on the origin): read as it stood, "1e9" froze the
 * page at load, reading a billion absent pieces, and "Infinity" threw
 * there, leaving it blank.
 */
function storedPieceCount(store: Storage, key: string): number {
  const count = Number(store.getItem(key));
  return Number.isSafeInteger(count) && count >= 0 && count <= store.length ? count : 0;
}

/** `text` cut into the pieces storage keeps of it (none when it is short enough for its part). */
function longTextPieces(text: string): string[] {
  if (text.length <= GCODE_URL_LIMIT) return [];
  return Array.from({ length: Math.ceil(text.length / LONG_TEXT_PIECE) }, (_, i) => text.slice(i * LONG_TEXT_PIECE, (i + 1) * LONG_TEXT_PIECE));
}

/**
 * `described`, the state a query describes, with what it leaves out taken
 * from `typed`: the parts of the page that belong to other modes than its
 * own, and a program or points it does not carry. The algorithm and its move
 * are the query's in Trace, Compare and Experiment mode (an experiment's
 * `algorithm` is its own); a G-code link names none, so they are typed's.
 */
function withOtherModes(catalogue: Catalogue, described: AppState, params: URLSearchParams, typed: AppState): AppState {
  const state = { ...described };
  for (const [field, param] of Object.entries(LONG_TEXT_PARAMS) as [LongText, string][]) {
    if (!params.has(param)) state[field] = typed[field];
  }
  // A link's program replacing the one typed keeps it, to bring back (a
  // link never holds a replaced program: the one kept stays). Not the
  // default program; the page withdraws the offer of another sample as
  // loaded (their texts are the site's to fetch).
  Object.assign(state, programReplaced(typed, state.gcode, "the link's program", typed.gcode !== DEFAULT_GCODE));
  // A link's points replacing the ones typed keep them, as its program does.
  Object.assign(state, pointsReplaced(typed, state.learnerPoints, "the link's points"));
  if (state.mode !== 'gcode') Object.assign(state, { machine: typed.machine, slowdown: typed.slowdown });
  if (state.mode !== 'experiment') state.experiment = typed.experiment;
  if (state.mode === 'gcode' || (state.mode === 'experiment' && typed.algorithm === state.algorithm)) {
    Object.assign(state, { algorithm: typed.algorithm, options: typed.options });
  }
  if (state.mode !== 'compare') {
    const info = catalogue.algorithms.find((a) => a.id === state.algorithm);
    if (info && comparableWith(info, catalogue.algorithms).some((a) => a.id === typed.other)) state.other = typed.other;
    state.layout = typed.layout;
  }
  return state;
}

/** The state `query` (the address's) describes (`linked`, when already read), if any, with what it leaves out taken from `typed` (withOtherModes). */
function linkedState(
  catalogue: Catalogue,
  typed: AppState | undefined,
  query = window.location.search,
  linked = stateFromQuery(query, catalogue),
): AppState | undefined {
  if (!linked || !typed) return linked;
  return withOtherModes(catalogue, linked, new URLSearchParams(query), typed);
}

/** The page's address for `state`: the permalink. */
function urlOf(state: AppState): string {
  return `${window.location.pathname}?${stateToQuery(state, { gcodeLimit: GCODE_URL_LIMIT })}${window.location.hash}`;
}

/**
 * Each long text's field: the text last written under its keys, its pieces
 * (none: the field is short, kept in its part) or read from them, and
 * whether the browser's storage took them (it holds a few MB). A refused
 * text is not tried again until it changes: it failed at every try (a
 * 1,000,000-line program took 200 to 800 ms of the main thread a write).
 * Forgotten when another tab writes the field's keys (persistState's
 * storage listener): this tab's next write then rewrites every piece, so
 * the keys never hold pieces of two tabs' texts, nor a part that points at
 * pieces another tab removed.
 */
const longTextsWritten = new Map<LongText, { text: string; pieces: string[]; kept: boolean }>();

/** Told whether the program and the points as they are now are kept in storage (persistState's `onKept`). */
let reportKept: (kept: boolean) => void = () => {};

/** The page's state and what it is told of another tab's edits (persistState's), for followOtherTabs. */
let tab: { store: Store<AppState>; catalogue: Catalogue; onOtherTab: (note: string) => void } | undefined;

function write(given: AppState): void {
  // Another tab's edits first, so that this write neither undoes them nor,
  // where this tab edited the same input, erases them unsaid.
  followOtherTabs();
  const state = tab?.store.state ?? given;
  // Replaced only when it changes (typing in a program or points too long
  // for it does not change it): with 200,000 points pasted in Check points,
  // each replacement took 30 to 70 ms of the main thread (once 0.6 s) in
  // Chromium's handling of the navigation, which visits the page's form
  // fields.
  const url = urlOf(state);
  if (url !== `${window.location.pathname}${window.location.search}${window.location.hash}`) window.history.replaceState(window.history.state, '', url);
  // An embedded view (say in a course page) must not replace the reader's own last visit.
  const store = storage();
  if (state.embed || !store) return;
  const changed = changedInputs(state);
  const shown = shownOf(state);
  lastWritten = state;
  // The long texts before the part that says where they are: a page closed
  // between the two writes leaves the text before, not a part pointing at
  // pieces not yet written. One this tab did not change is another tab's to
  // write, and kept as far as this tab knows.
  let kept = (Object.keys(LONG_TEXT_KEYS) as LongText[])
    .map((field) => (changed.has(field) ? writeLongText(store, field, state[field]) : (longTextsWritten.get(field)?.kept ?? true)))
    .every(Boolean);
  const before = partsOf(store.getItem(STORAGE_KEY) ?? '');
  // Nothing this tab holds changed since it last wrote, followed or loaded
  // storage, which still holds that write (as this tab reads it): written,
  // it only put back this tab's copy of storage, which another tab's write
  // may have reached a moment later. Written after following that write
  // (this tab's inputs as storage had them), it took storage back to an
  // older write when it landed after the other tab's next one.
  if (changed.size === 0 && sameQuery(shown, shownWritten) && before !== undefined && before.edit === editSeen) {
    reportKept(kept);
    return;
  }
  const edit = changed.size > 0 ? `${EDIT_STAMP}.${++editsWritten}` : undefined;
  const parts = partsToStore(storedParts(state, shown), changed, edit, before);
  try {
    store.setItem(STORAGE_KEY, JSON.stringify(parts));
    shownWritten = parts.shown;
    if (edit && tab) {
      // The write this one goes over, as this tab read it (another tab's,
      // at this tab's first write), is older than this one.
      for (const older of [editSeen, before?.edit]) if (older !== undefined) editsSuperseded.add(older);
      editSeen = edit;
      // The long texts as written (this tab's) or as last read (another's): not read back.
      const text = (field: LongText, query: string) => (new URLSearchParams(query).has(LONG_TEXT_PARAMS[field]) ? undefined : changed.has(field) ? state[field] : storedSeen?.[field]);
      storedSeen = readParts(tab.catalogue, parts, text)?.typed;
    }
  } catch {
    // Storage blocked or full: the URL still holds the state, and the page
    // says what a reload loses.
    kept = false;
  }
  reportKept(kept);
}

/**
 * Writes the pieces of `field`'s text that changed since this tab wrote or
 * read them (all of them after a refusal, which left none, or after
 * another tab wrote them); says whether storage kept them. Unchanged text
 * costs nothing: the state keeps the same string until it is typed in.
 */
function writeLongText(store: Storage, field: LongText, text: string): boolean {
  const written = longTextsWritten.get(field);
  if (written?.text === text) return written.kept;
  const pieces = longTextPieces(text);
  const key = LONG_TEXT_KEYS[field];
  const before = written?.kept ? written.pieces : [];
  // Pieces past the new end: those this tab knows of, and those the keys
  // count (another tab's, or a visit's whose part now holds a short text).
  const stale = Math.max(before.length, storedPieceCount(store, key));
  try {
    pieces.forEach((piece, i) => {
      if (piece !== before[i]) store.setItem(`${key}.${i}`, piece);
    });
    for (let i = pieces.length; i < stale; i++) store.removeItem(`${key}.${i}`);
    if (pieces.length > 0) store.setItem(key, String(pieces.length));
    else store.removeItem(key);
    longTextsWritten.set(field, { text, pieces, kept: true });
    return true;
  } catch {
    // Too large: nothing is kept rather than part of the text, and the page
    // says what a reload loses (the rest of the state is kept).
    for (let i = 0; i < Math.max(pieces.length, stale); i++) store.removeItem(`${key}.${i}`);
    store.removeItem(key);
    longTextsWritten.set(field, { text, pieces, kept: false });
    return false;
  }
}

/** Whether two values of an input are the same (an object's keys in any order). */
function sameInput(a: unknown, b: unknown): boolean {
  if (a === b) return true;
  if (typeof a !== 'object' || typeof b !== 'object' || a === null || b === null) return false;
  const keys = Object.keys(a);
  return keys.length === Object.keys(b).length && keys.every((key) => sameInput((a as Record<string, unknown>)[key], (b as Record<string, unknown>)[key]));
}

/** What another tab's write means to this one (otherTabEdits). */
export interface OtherTabEdits {
  /** The inputs another tab changed that this one had not: taken as they are stored. */
  followed: Partial<AppState>;
  /** The inputs both tabs changed: this tab's stays, and is written over the other's. */
  both: (keyof AppState)[];
  /**
   * The other tab's program or points, written over, kept to bring back:
   * the program fields (programReplaced; not the default program), and
   * the points fields (not none).
   */
  kept: Partial<AppState>;
  /** The inputs this tab writes again, storage having gone back to an older write: those it holds otherwise. */
  rewritten: (keyof AppState)[];
}

/**
 * What this tab takes of another tab's write: storage held `seen` when this
 * tab last wrote or followed it, and holds `stored` now (both as a reload
 * reads them); the state was `written` then and is `current` now. An input
 * the other tab changed (stored unlike seen) is followed where this tab had
 * not changed it since (current is written, and it is not of `drafted`, the
 * inputs with a text refused here) or has the same; else both changed it,
 * and this tab's wins (the state's, about to be written, or the draft's,
 * over the value a reload of it shows), but the other's program or points
 * are kept to bring back.
 *
 * Unless storage `wentBack`: it holds a write older than one this tab wrote
 * or followed, written again by a tab that wrote back the inputs as it had
 * read them before the newer write reached it (each tab reads its own copy
 * of storage, which another tab's write reaches a little later). Nothing is
 * followed of it: the inputs this tab holds otherwise are written again
 * (`rewritten`). Followed, the newer write was lost in both tabs, its
 * writer's text box showing the older program again.
 */
export function otherTabEdits(
  seen: AppState,
  stored: AppState,
  written: AppState,
  current: AppState,
  drafted: ReadonlySet<keyof AppState> = new Set(),
  wentBack = false,
): OtherTabEdits {
  if (wentBack) return { followed: {}, both: [], kept: {}, rewritten: INPUTS.filter((key) => !sameInput(current[key], stored[key])) };
  const followed: Partial<AppState> = {};
  const both: (keyof AppState)[] = [];
  for (const key of INPUTS) {
    if (sameInput(stored[key], seen[key])) continue;
    if ((current[key] === written[key] && !drafted.has(key)) || sameInput(current[key], stored[key])) Object.assign(followed, { [key]: stored[key] });
    else both.push(key);
  }
  const replaced = both.includes('gcode') ? programReplaced({ gcode: stored.gcode, replacedProgram: '', replacedBy: '', secondReplacedProgram: '' }, current.gcode, ANOTHER_TABS_PROGRAM, stored.gcode !== DEFAULT_GCODE) : undefined;
  const kept: Partial<AppState> = replaced && replaced.replacedProgram !== '' ? { replacedProgram: replaced.replacedProgram, replacedBy: replaced.replacedBy } : {};
  if (both.includes('learnerPoints') && stored.learnerPoints !== '') Object.assign(kept, { replacedPoints: stored.learnerPoints, replacedPointsBy: ANOTHER_TABS_POINTS });
  return { followed, both, kept, rewritten: [] };
}

/**
 * The inputs whose forms keep a text typed and refused (drafts.ts), by the
 * prefix of their fields' ids: the move's form (OptionsForm's default), the
 * machine's (GcodePanel) and the experiment's (main.ts).
 */
const DRAFT_PREFIXES: Partial<Record<keyof AppState, string>> = { options: 'option-', machine: 'machine-', experiment: 'experiment-' };

/** How the note names each input another tab changed; the offer of a replaced program or points goes with them, unnamed. */
const INPUT_NAMES: Partial<Record<keyof AppState, string>> = {
  algorithm: 'the algorithm',
  options: 'the move',
  learnerPoints: 'your points',
  other: 'the compared algorithm',
  layout: 'the layout',
  gcode: 'the program',
  machine: 'the machine',
  slowdown: 'the machine-time playback',
  experiment: 'the experiment',
};

/** What the page says of another tab's edits (otherTabEdits): '' when it changed nothing this tab shows. */
export function otherTabNote({ followed, both, kept }: OtherTabEdits): string {
  const names = (keys: (keyof AppState)[]) => keys.flatMap((key) => INPUT_NAMES[key] ?? []);
  const shown = names(Object.keys(followed) as (keyof AppState)[]);
  const ours = names(both);
  const sentences = shown.length > 0 ? [`Another tab changed ${listed(shown)}: shown here as there.`] : [];
  if (ours.length > 0) {
    const offered = [
      ...('replacedProgram' in kept ? [" The other tab's program is offered back beside the editor."] : []),
      ...('replacedPoints' in kept ? [" The other tab's points are offered back in Check points."] : []),
    ].join('');
    sentences.push(`Another tab changed ${listed(ours)} at the same time as this one: what this tab has is kept, and is what a reload shows.${offered}`);
  }
  return sentences.join(' ');
}

/**
 * Takes what another tab wrote since this tab last wrote or followed
 * storage (its StoredParts.edit differs): the inputs this tab had not
 * changed since are followed, the form and views updated as if typed
 * (lastWritten too, so they are not written back); an input both changed
 * is this tab's, said in a note, the other's program or points kept to
 * bring back. Each tab wrote only what it changed, but the last writer of an
 * input both changed erased the other's without a word, and a tab showed
 * what a reload of it no longer gave. Storage gone back to an older write
 * (otherTabEdits' wentBack) is followed in nothing: true when this tab is to
 * write its inputs again (lastWritten holds them as stored, so the next
 * write takes them as changed).
 */
function followOtherTabs(): boolean {
  const store = storage();
  if (!tab || !store || !lastWritten || !storedSeen || tab.store.state.embed) return false;
  const parts = partsOf(store.getItem(STORAGE_KEY) ?? '');
  if (!parts || parts.edit === editSeen) return false;
  const stored = readParts(tab.catalogue, parts)?.typed;
  if (!stored) return false;
  const wentBack = parts.edit !== undefined && editsSuperseded.has(parts.edit);
  if (editSeen !== undefined) editsSuperseded.add(editSeen);
  editSeen = parts.edit;
  const drafted = new Set((Object.keys(DRAFT_PREFIXES) as (keyof AppState)[]).filter((key) => draftedHere(DRAFT_PREFIXES[key]!)));
  const edits = otherTabEdits(storedSeen, stored, lastWritten, tab.store.state, drafted, wentBack);
  storedSeen = stored;
  if (wentBack) {
    // Seen as this tab is about to write them: another tab writing them
    // again too (it had seen them, as this one) changed none of them.
    const rewritten = (from: AppState) => Object.fromEntries(edits.rewritten.map((key) => [key, from[key]]));
    storedSeen = { ...stored, ...rewritten(tab.store.state) };
    lastWritten = { ...lastWritten, ...rewritten(stored) };
    return edits.rewritten.length > 0;
  }
  lastWritten = { ...lastWritten, ...edits.followed };
  // What this tab shows of the inputs followed is storage's already: not its own to write.
  const shownBefore = shownOf(tab.store.state);
  tab.store.update({ ...edits.followed, ...edits.kept });
  if (sameQuery(shownWritten, shownBefore)) shownWritten = shownOf(tab.store.state);
  tab.onOtherTab(otherTabNote(edits));
  return false;
}

/**
 * Takes storage as this tab loaded it for its last write: the first write
 * then writes only what `state` changed of it (a link's program replacing
 * the one typed, its kept program; the step, the view or the mode shown),
 * and nothing when it changed nothing. Each tab wrote every input as it
 * loaded it, under a new StoredParts.edit: landing just after another tab's
 * write, which this tab's copy of storage had not reached yet, it took
 * storage back to the older inputs, and the other tab followed them, its
 * edit lost in both tabs.
 */
function loaded(state: AppState): void {
  // As loadState read them, in the same task: read again, a long text kept
  // (a learner's points, up to 19 MB) was read and parsed twice at start-up.
  if (!readAtLoad) return;
  const { parts, typed: stored } = readAtLoad;
  const unlike = INPUTS.filter((key) => !sameInput(state[key], stored[key]));
  lastWritten = { ...state, ...Object.fromEntries(unlike.map((key) => [key, stored[key]])) };
  storedSeen = stored;
  editSeen = parts.edit;
  shownWritten = parts.shown;
}

/**
 * Makes what is shown now an entry of the browser's history, so that Back
 * comes back to it after the change that follows (an experiment's line
 * opened in Trace mode: Back left the site). Every other change replaces
 * the entry it is in. Not in an embedded view, whose entries would be the
 * host page's history too.
 */
export function newHistoryEntry(state: AppState): void {
  if (state.embed) return;
  write(state);
  window.history.pushState(null, '', urlOf(state));
}

/**
 * What the page says where the browser blocks its storage (storage():
 * undefined): the address, which write keeps as the state changes, is then
 * all that a reload reads. It holds the mode shown, and a program or points
 * no longer than a link holds; every other input is lost with no word.
 */
export const STORAGE_BLOCKED_NOTE =
  "Your browser blocks this page's storage, so what you type is not kept for a reload or a new visit, except what the page's address holds: " +
  `the inputs of the mode shown, with a program or points of up to ${grouped(GCODE_URL_LIMIT)} characters. Bookmark or copy the address to keep them.`;

/**
 * Persists every change of `store`, throttled, and any pending change when
 * the page is hidden or closed; Back and Forward between the entries
 * newHistoryEntry made bring back their states. `onKept` is told at every
 * write whether the program and the learner's points fitted in storage;
 * `onOtherTab`, what another tab's write changed here (otherTabNote);
 * `onBlocked`, once, STORAGE_BLOCKED_NOTE where storage is blocked (not in
 * an embedded view, which never writes it).
 */
export function persistState(
  store: Store<AppState>,
  catalogue: Catalogue,
  notes: { onKept: (kept: boolean) => void; onOtherTab: (note: string) => void; onBlocked: (note: string) => void },
): void {
  reportKept = notes.onKept;
  tab = { store, catalogue, onOtherTab: notes.onOtherTab };
  if (!store.state.embed && !storage()) notes.onBlocked(STORAGE_BLOCKED_NOTE);
  let timer: ReturnType<typeof setTimeout> | undefined;
  const flush = () => {
    clearTimeout(timer);
    timer = undefined;
    write(store.state);
  };
  window.addEventListener('storage', ({ key, storageArea }) => {
    if (storageArea !== storage()) return;
    // Another tab wrote a long text's keys (key null: the storage was cleared).
    for (const [field, fieldKey] of Object.entries(LONG_TEXT_KEYS) as [LongText, string][]) {
      if (key === null || key === fieldKey || key.startsWith(`${fieldKey}.`)) longTextsWritten.delete(field);
    }
    // Its parts, written after its long texts: its write is whole.
    if (key === STORAGE_KEY && followOtherTabs()) timer ??= setTimeout(flush, WRITE_DELAY_MS);
  });
  // Back to a page kept in the browser's cache, which heard no other tab meanwhile.
  window.addEventListener('pageshow', ({ persisted }) => {
    if (persisted && followOtherTabs()) timer ??= setTimeout(flush, WRITE_DELAY_MS);
  });
  // A page hidden may be discarded without a pagehide (mobile browsers).
  document.addEventListener('visibilitychange', () => {
    if (document.visibilityState === 'hidden' && timer !== undefined) flush();
  });
  window.addEventListener('popstate', () => {
    clearTimeout(timer);
    timer = undefined;
    const state = linkedState(catalogue, store.state);
    if (state) store.update(state);
  });
  store.subscribe(() => {
    timer ??= setTimeout(flush, WRITE_DELAY_MS);
  });
  window.addEventListener('pagehide', () => {
    if (timer !== undefined) flush();
    if (store.state.embed || window.self !== window.top) return;
    try {
      tabStorage()?.setItem(RELOAD_KEY, window.location.search);
    } catch {
      // Storage full or blocked: a reload comes back to the address it asks for.
    }
  });
  loaded(store.state);
  write(store.state);
}
