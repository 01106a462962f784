/**
 * Long work in the core, run a slice at a time: a G-code program (slices of
 * lines) and the random-lines experiment (slices of lines). Between slices
 * this yields to the event loop, so a worker stays responsive: it can post
 * progress and take a cancel (an AbortSignal) while the work runs.
 */
import { argumentError, describeValue, optionalFunction, quoted } from './guard.js';

/** Options of a call that runs in slices (runGcode, randomLines). */
export interface SliceOptions<Progress> {
  /** Called after every slice, and once at the end with done = true. */
  onProgress?: (progress: Progress) => void;
  /** Stops the work between slices, or once its last slice has run, before the result is made; the call then rejects with the signal's reason. */
  signal?: AbortSignal;
  /** Time one slice aims at, ms (default 20): the slices' sizes adapt to it. */
  sliceMs?: number;
}

/** The keys SliceOptions has. */
const SLICE_OPTION_KEYS: readonly (keyof SliceOptions<unknown>)[] = ['onProgress', 'signal', 'sliceMs'];

/**
 * The options of `call` checked (each named when it is wrong); returns
 * sliceMs. A key it does not know is refused, as the core refuses a trace's:
 * a misspelt `onprogress` would otherwise run without a report.
 */
export function checkSliceOptions(call: string, options: unknown): number {
  if (typeof options !== 'object' || options === null) throw argumentError('options', `expected an object, got ${describeValue(options)}`);
  for (const key of Object.keys(options)) {
    if ((SLICE_OPTION_KEYS as readonly string[]).includes(key)) continue;
    const meant = SLICE_OPTION_KEYS.find((known) => known.toLowerCase() === key.toLowerCase());
    const hint = meant === undefined ? `it takes ${SLICE_OPTION_KEYS.join(', ')}` : `did you mean ${meant}?`;
    throw argumentError(quoted(key), `${call} does not take this option (${hint})`);
  }
  const { onProgress, signal, sliceMs = 20 } = options as Record<string, unknown>;
  optionalFunction('onProgress', onProgress);
  if (signal !== undefined && !(signal instanceof AbortSignal)) throw argumentError('signal', `expected an AbortSignal, got ${describeValue(signal)}`);
  if (typeof sliceMs !== 'number' || !(sliceMs > 0) || !Number.isFinite(sliceMs)) {
    throw argumentError('sliceMs', `expected a number of milliseconds above 0, got ${describeValue(sliceMs)}`);
  }
  return sliceMs;
}

/**
 * Lets the event loop run the tasks waiting (a cancel, a progress report)
 * before the next slice: a message posted to a channel of its own, which
 * comes back as a task with no delay, where a timer would wait its clamp
 * (a nested setTimeout(0) waits 4 ms in a browser, 1 ms in Node, which a
 * run of 20 ms slices would spend idle a fifth or a twentieth of its time).
 */
export function yieldToEventLoop(): Promise<void> {
  return new Promise((resolve) => {
    const { port1, port2 } = new MessageChannel();
    port1.onmessage = () => {
      port1.close();
      resolve();
    };
    port2.postMessage(null);
  });
}

/** How many units (lines) the first slice takes, and the fewest any slice takes. */
export interface SliceSizes {
  first: number;
  least: number;
}

/**
 * Calls `advance(units)` until it reports done, each call aimed at
 * `sliceMs` (the units per slice grow at most 4 times a slice), reporting
 * each progress and yielding to the event loop between slices. Rejects with
 * the signal's reason when it is aborted before a slice.
 */
export async function advanceInSlices<Progress extends { done: boolean }>(
  advance: (units: number) => Progress,
  options: SliceOptions<Progress>,
  sliceMs: number,
  sizes: SliceSizes,
): Promise<void> {
  let units = sizes.first;
  for (;;) {
    options.signal?.throwIfAborted();
    const started = performance.now();
    const progress = advance(units);
    const elapsed = performance.now() - started;
    options.onProgress?.(progress);
    if (progress.done) return;
    units = Math.max(sizes.least, Math.min(units * 4, Math.round((units * sliceMs) / Math.max(elapsed, 0.5))));
    await yieldToEventLoop();
  }
}

/**
 * Calls `advance()` until it reports done, as many calls a slice as fit in
 * `sliceMs` (at least one), reporting each slice's progress and yielding to
 * the event loop between slices; rejects with the signal's reason when it
 * is aborted before a slice. For work whose calls vary in cost far more
 * than advanceInSlices's units can follow: a check's option combinations
 * took 0.05 to 9 ms each along the same 1,500,000 points, and slices sized
 * by the cheap ones grew to 60 combinations, 0.1 to 0.4 s.
 */
export async function advanceForTime<Progress extends { done: boolean }>(advance: () => Progress, options: SliceOptions<Progress>, sliceMs: number): Promise<void> {
  for (;;) {
    options.signal?.throwIfAborted();
    const until = performance.now() + sliceMs;
    let progress: Progress;
    do progress = advance();
    while (!progress.done && performance.now() < until);
    options.onProgress?.(progress);
    if (progress.done) return;
    await yieldToEventLoop();
  }
}

/**
 * Frees the core's object of work that stopped before its end (a cancel, an
 * error). One the core trapped in stays borrowed and cannot be freed: that
 * must not hide the error that stopped it (the instance's memory is lost
 * with the trap, and that error says so).
 */
export function freeStopped(run: { free(): void }): void {
  try {
    run.free();
  } catch {
    // See above: the error already thrown is the one to report.
  }
}
