/**
 * The browser's two storage areas, each undefined where it is blocked (some
 * privacy settings throw on access): localStorage, shared by the tabs
 * (persist.ts keeps the state there, drafts.ts a copy of each draft), and
 * this tab's sessionStorage.
 */

/** localStorage, or undefined where it is blocked. */
export function storage(): Storage | undefined {
  try {
    return window.localStorage;
  } catch {
    return undefined;
  }
}

/** This tab's sessionStorage, or undefined where it is blocked. */
export function tabStorage(): Storage | undefined {
  try {
    return window.sessionStorage;
  } catch {
    return undefined;
  }
}
