/**
 * The 2009 blog's greedy rule, stepping only: rust/src/line/greedy.rs in
 * plain TypeScript (ties to the lower axis, the default). Each step tries a
 * unit move toward the goal on every axis not yet there and takes the one
 * that leaves the smallest squared distance to the goal. As in the core's
 * recording loop, that is the axis with the most units left: a step along
 * it turns l^2 into (l - 1)^2, changing the sum by 1 - 2l.
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function greedy(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'greedy');
  const m = mirror(options.from, options.to);
  const left = [...m.magnitude];
  const total = left.reduce((s, v) => s + v, 0);
  const out = new Uint16Array(total);
  for (let k = 0; k < total; k++) {
    let chosen = 0;
    let mostLeft = 0;
    for (let a = 0; a < m.dims; a++) {
      const l = left[a]!;
      if (l > mostLeft) {
        mostLeft = l;
        chosen = a;
      }
    }
    left[chosen]!--;
    out[k] = m.unit[chosen]!;
  }
  return out;
}
