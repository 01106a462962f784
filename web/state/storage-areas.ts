/**
 * The browser's two storage areas, each undefined where it is blocked (some
 * privacy settings throw on access): localStorage, shared by the tabs
 * (persist.ts keeps the state there, drafts.ts a copy of each draft), and
 * this tab's sessionStorage.
 */

/**
 * `area()`, or undefined when reaching it throws, or reading it does: Firefox
 * throws NS_ERROR_FILE_CORRUPTED from every getItem of a damaged store, which
 * left the page blank at load. A write that throws (storage full) is each
 * writer's to handle.
 */
function readable(area: () => Storage): Storage | undefined {
  try {
    const store = area();
    store.getItem('');
    return store;
  } catch {
    return undefined;
  }
}

/** localStorage, or undefined where it is blocked. */
export function storage(): Storage | undefined {
  return readable(() => window.localStorage);
}

/** This tab's sessionStorage, or undefined where it is blocked. */
export function tabStorage(): Storage | undefined {
  return readable(() => window.sessionStorage);
}
