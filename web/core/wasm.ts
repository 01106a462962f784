/**
 * Loads the wasm core once. This module and the files it imports are the only
 * importers of the generated package in ./pkg.
 */
import init, * as bindings from './pkg/voxpath.js';
import { encodeUtf8Into } from './utf8.js';

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
  // The room last made (a first one too small for a string is freed).
  const made: { bytes?: bindings.TextBytes } = {};
  const room = (length: number) => {
    made.bytes?.free();
    made.bytes = new core.TextBytes(length);
    return made.bytes.view();
  };
  try {
    if (typeof text !== 'string') room(text.length).set(text);
    else {
      const written = encodeUtf8Into(text, room);
      made.bytes!.truncate(written);
    }
    return use(made.bytes!);
  } finally {
    made.bytes?.free();
  }
}
