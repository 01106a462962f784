/** A value that changes as a whole, with listeners told of each change. */
export class Store<T extends object> {
  #state: T;
  readonly #listeners = new Set<(state: T, previous: T) => void>();

  constructor(initial: T) {
    this.#state = initial;
  }

  get state(): T {
    return this.#state;
  }

  /** Applies `patch`; listeners run only when some key's value changed (compared with ===). */
  update(patch: Partial<T>): void {
    const previous = this.#state;
    const next = { ...previous, ...patch };
    if ((Object.keys(patch) as (keyof T)[]).every((k) => next[k] === previous[k])) return;
    this.#state = next;
    for (const listener of this.#listeners) listener(next, previous);
  }

  /** Calls `listener` after every change; returns the unsubscribe function. */
  subscribe(listener: (state: T, previous: T) => void): () => void {
    this.#listeners.add(listener);
    return () => this.#listeners.delete(listener);
  }
}
