/**
 * The 2009 blog's greedy rule, stepping only: rust/src/line/greedy.rs in
 * plain TypeScript (ties to the lower axis, the default). Each step tries a
 * unit move toward the goal on every axis not yet there and takes the one
 * that leaves the smallest squared distance to the goal.
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function greedy(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'greedy');
  const m = mirror(options.from, options.to);
  const left = [...m.magnitude];
  const total = left.reduce((s, v) => s + v, 0);
  let now = left.reduce((s, v) => s + v * v, 0);
  const out = new Uint16Array(total);
  for (let k = 0; k < total; k++) {
    let chosen = -1;
    let best = Infinity;
    for (let a = 0; a < m.dims; a++) {
      const l = left[a]!;
      if (l === 0) continue;
      // Take a fake step: (l - 1)^2 replaces l^2 in the sum.
      const after = now - l * l + (l - 1) * (l - 1);
      if (after < best) {
        best = after;
        chosen = a;
      }
    }
    left[chosen]!--;
    now = best;
    out[k] = m.unit[chosen]!;
  }
  return out;
}
