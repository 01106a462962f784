/**
 * Keeps the state in the URL (the permalink) and in localStorage, both in the
 * query format of state/query.ts, so nothing a user typed is lost on reload.
 * On load a URL describing a state wins over localStorage.
 */
import { type AppState, type Catalogue, defaultAlgorithm, defaultState } from './app-state.js';
import { GCODE_URL_LIMIT, stateFromQuery, stateToQuery } from './query.js';
import type { Store } from './store.js';

const STORAGE_KEY = 'voxpath.state';

/**
 * Writes are throttled to one per WRITE_DELAY_MS: playback changes the step
 * many times a second, and browsers throttle (and warn about) rapid
 * history.replaceState calls.
 */
const WRITE_DELAY_MS = 400;

/** localStorage, or undefined where it is blocked (some privacy settings throw on access). */
export function storage(): Storage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/**
 * The state to start from: the URL's, else the last visit's, else the
 * defaults. A program or a learner's points too long for the URL come from
 * localStorage, which keeps them whole, so the text typed survives a reload.
 */
export function loadState(catalogue: Catalogue): AppState {
  const stored = stateFromQuery(storage()?.getItem(STORAGE_KEY) ?? '', catalogue);
  return linkedState(catalogue, stored) ?? stored ?? defaultState(defaultAlgorithm(catalogue.algorithms), catalogue.algorithms);
}

/**
 * The address's state, if it describes one, with the program and the
 * learner's points it leaves out (too long for a URL) taken from `typed`:
 * the texts as typed, kept whole elsewhere.
 */
function linkedState(catalogue: Catalogue, typed: AppState | undefined): AppState | undefined {
  const linked = stateFromQuery(window.location.search, catalogue);
  const params = new URLSearchParams(window.location.search);
  if (linked && typed && !params.has('gcode')) linked.gcode = typed.gcode;
  if (linked && typed && !params.has('points')) linked.learnerPoints = typed.learnerPoints;
  return linked;
}

/** The page's address for `state`: the permalink. */
function urlOf(state: AppState): string {
  return `${window.location.pathname}?${stateToQuery(state, { gcodeLimit: GCODE_URL_LIMIT })}${window.location.hash}`;
}

function write(state: AppState): void {
  window.history.replaceState(window.history.state, '', urlOf(state));
  // An embedded view (say in a course page) must not replace the reader's own last visit.
  if (state.embed) return;
  try {
    storage()?.setItem(STORAGE_KEY, stateToQuery(state, { gcodeLimit: Infinity }));
  } catch {
    // Storage full or blocked: the URL still holds the state.
  }
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
 * Persists every change of `store`, throttled, and any pending change when
 * the page is hidden or closed; Back and Forward between the entries
 * newHistoryEntry made bring back their states.
 */
export function persistState(store: Store<AppState>, catalogue: Catalogue): void {
  let timer: ReturnType<typeof setTimeout> | undefined;
  const flush = () => {
    clearTimeout(timer);
    timer = undefined;
    write(store.state);
  };
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
  });
  write(store.state);
}
