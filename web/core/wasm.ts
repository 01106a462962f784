/**
 * Loads the wasm core once. This module and the files it imports are the only
 * importers of the generated package in ./pkg.
 */
import init, * as bindings from './pkg/voxpath.js';

export type CoreBindings = typeof bindings;

let loading: Promise<CoreBindings> | undefined;

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
      await init({ module_or_path: await readFile(wasmUrl) });
    } else {
      await init({ module_or_path: wasmUrl });
    }
    return bindings;
  })().catch((error: unknown) => {
    loading = undefined; // let a later call try again
    throw error;
  });
  return loading;
}
