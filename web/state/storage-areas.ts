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

/**
 * `area` as probed (readable) at its first use, once per page load: the
 * page asks for storage at each of its throttled writes (persist.ts), and a
 * probe at each call read storage once more every time. A store blocked by
 * the browser's settings, or damaged, stays so while the page is open; one
 * whose reads began to throw later would throw at the writer's own read
 * after a probe all the same.
 */
function probedOnce(area: () => Storage): () => Storage | undefined {
  let probed: { area: Storage | undefined } | undefined;
  return () => (probed ??= { area: readable(area) }).area;
}

/** localStorage, or undefined where it is blocked. */
export const storage = probedOnce(() => window.localStorage);

/** This tab's sessionStorage, or undefined where it is blocked. */
export const tabStorage = probedOnce(() => window.sessionStorage);
