/**
 * Loads the wasm core once. This module and the files it imports are the only
 * importers of the generated package in ./pkg.
 */
import init, * as bindings from './pkg/voxpath.js';
import { advanceForTime, yieldToEventLoop } from './slices.js';
import { Utf8Encoding } from './utf8.js';

export type CoreBindings = typeof bindings;

let loading: Promise<CoreBindings> | undefined;
/** The core's linear memory, once loaded. */
let memory: WebAssembly.Memory | undefined;

function runningInNode(): boolean {
  return typeof process !== 'undefined' && typeof process.versions?.node === 'string';
}

/**
 * Resolves when the core is ready. In Node the .wasm is read from beside this
 * module; in a browser it is fetched relative to this module's URL, so a site
 * served under any sub-path finds it.
 */
export function loadCore(): Promise<CoreBindings> {
  loading ??= (async () => {
    const wasmUrl = new URL('./pkg/voxpath_bg.wasm', import.meta.url);
    if (runningInNode()) {
      // Kept out of browser bundles: the specifier is not a literal.
      const fsModule = 'node:fs/promises';
      const { readFile } = (await import(/* @vite-ignore */ fsModule)) as typeof import('node:fs/promises');
      memory = (await init({ module_or_path: await readFile(wasmUrl) })).memory;
    } else {
      memory = (await init({ module_or_path: wasmUrl })).memory;
    }
    return bindings;
  })().catch((error: unknown) => {
    loading = undefined; // let a later call try again
    throw error;
  });
  return loading;
}

/**
 * Bytes of linear memory the wasm core has now (0 before it is loaded).
 * Wasm memory grows in 64 KiB pages and never shrinks, so this is the most
 * the core has ever needed at once: what a trace costs inside wasm, besides
 * the arrays copied out of it.
 */
export function memoryBytes(): number {
  return memory?.buffer.byteLength ?? 0;
}

/**
 * Bytes of heap the wasm core holds now (0 before it is loaded): what the
 * results not yet freed retain, where {@link memoryBytes} is the most the
 * core ever needed at once. A finished G-code run holds its move records,
 * its plan and its steps here (135 bytes a line for the bench's program at 1
 * step/mm, README's Limits).
 */
export function heapBytes(): number {
  return memory ? bindings.heapBytes() : 0;
}

/**
 * `text` as UTF-8 in wasm memory, for `use` (which may take the bytes);
 * freed after it. A string is encoded natively straight into wasm memory
 * (`encodeInto` on the core's TextBytes): passing the string itself
 * re-encodes it a character at a time in JavaScript, and `encode` makes a
 * JavaScript array of the bytes that is then copied in (for a 20 MB CSV,
 * each longer than the encoding). Bytes (UTF-8 already: the core checks)
 * are copied in as they are, with no string made of them (a file read into
 * a Buffer, a program the page encoded before sending it to its worker).
 */
export function withTextBytes<T>(core: CoreBindings, text: string | Uint8Array, use: (bytes: bindings.TextBytes) => T): T {
  const writing = new TextBytesWriting(core, text);
  try {
    while (!writing.advance(Infinity).done);
    return use(writing.bytes);
  } finally {
    writing.free();
  }
}

/**
 * UTF-16 units of a string withTextBytesInSlices encodes a call: about 1 to
 * 3 ms in a Chromium worker, a fraction of one in Node.
 */
const TEXT_UNITS_PER_CALL = 262_144;

/**
 * withTextBytes a slice of about `sliceMs` at a time (advanceForTime), the
 * event loop let run between slices and before `use`, stopped by `signal`
 * (rejecting with its reason, the bytes freed): a check's 19 MB of points
 * took 70 to 200 ms to encode into wasm memory in one call in a Chromium
 * worker, which a Cancel waited for.
 */
export async function withTextBytesInSlices<T>(
  core: CoreBindings,
  text: string | Uint8Array,
  use: (bytes: bindings.TextBytes) => T,
  signal: AbortSignal | undefined,
  sliceMs: number,
): Promise<T> {
  const writing = new TextBytesWriting(core, text);
  try {
    await advanceForTime(() => writing.advance(TEXT_UNITS_PER_CALL), signal === undefined ? {} : { signal }, sliceMs);
    await yieldToEventLoop();
    signal?.throwIfAborted();
    return use(writing.bytes);
  } finally {
    writing.free();
  }
}

/** Text being put into wasm memory as UTF-8: a string a part at a time (Utf8Encoding), bytes copied in at once. */
class TextBytesWriting {
  /** The room last made (a first one too small for a string is freed), and its size. */
  #room: bindings.TextBytes | undefined;
  #roomBytes = 0;
  readonly #encoding: Utf8Encoding | undefined;

  constructor(core: CoreBindings, text: string | Uint8Array) {
    const room = (bytes: number) => {
      if (this.#room === undefined || bytes !== this.#roomBytes) {
        this.#room?.free();
        this.#room = new core.TextBytes(bytes);
        this.#roomBytes = bytes;
      }
      return this.#room.view();
    };
    if (typeof text === 'string') this.#encoding = new Utf8Encoding(text, room);
    else room(text.length).set(text);
  }

  /** Writes up to `units` more UTF-16 units of a string; whether the whole text is written now. */
  advance(units: number): { done: boolean } {
    if (this.#encoding === undefined) return { done: true };
    if (!this.#encoding.advance(units)) return { done: false };
    this.#room!.truncate(this.#encoding.written);
    return { done: true };
  }

  /** The text's bytes, once written. */
  get bytes(): bindings.TextBytes {
    return this.#room!;
  }

  free(): void {
    this.#room?.free();
  }
}
