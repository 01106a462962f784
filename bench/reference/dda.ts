/**
 * The floating-point DDA, stepping only: rust/src/line/dda.rs in plain
 * TypeScript, the same float operations in the same order (JS numbers are
 * the same IEEE doubles), and the same finish rule.
 */
import { guard, mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function dda(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'dda');
  const { from, to } = options;
  const m = mirror(from, to);
  const n = m.longest;
  const acc = from.map((v) => v);
  const inc = from.map((v, a) => (n > 0 ? (to[a]! - v) / n : 0));
  const at = [...from];
  let remaining = n;
  const out = new Uint16Array(n);
  for (let k = 0; k < n; k++) {
    let step = 0;
    for (let a = 0; a < m.dims; a++) {
      acc[a]! += inc[a]!;
      // Round half up: floor(acc + 0.5), the textbook int(x + 0.5).
      const rounded = Math.floor(acc[a]! + 0.5);
      const sign = m.sign[a]!;
      const wants = (rounded - at[a]!) * sign > 0;
      const unitsLeft = m.magnitude[a]! - (at[a]! - from[a]!) * sign;
      // Each axis reads only its own position, so it may move at once.
      if (guard(wants, unitsLeft, remaining)) {
        step |= m.unit[a]!;
        at[a]! += sign;
      }
    }
    remaining--;
    out[k] = step;
  }
  return out;
}
