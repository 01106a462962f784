/**
 * The core's catalogue: every algorithm, experiment and G-code machine
 * setting, with its options (name, kind, default, doc). The CLI's flags, the
 * page's forms and its URL keys are made from it, so nothing here or there
 * restates an option.
 */
import type { Catalogue } from './pkg/voxpath.js';
import { loadCore } from './wasm.js';

let cached: Catalogue | undefined;

/** Everything the core offers (read once: the catalogue never changes). */
export async function catalogue(): Promise<Catalogue> {
  const core = await loadCore();
  cached ??= core.catalogue();
  return cached;
}
