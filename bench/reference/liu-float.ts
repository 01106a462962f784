/**
 * Liu's decimal discriminant kept to d places (Wang eq. 14-15, Fig. 10),
 * stepping only: rust/src/line/liu_float.rs in plain TypeScript with its
 * defaults (1 decimal, ties advance), the same float operations in the
 * same order, and the same finish rule.
 */
import { guard, mirror, onlyOptions, roundHalfAway, type ReferenceOptions } from './common.js';

/** Rounds to `decimals` places as the core does: (v * 10^d).round() / 10^d. */
function roundDecimals(v: number, decimals: number): number {
  const scale = 10 ** decimals;
  return roundHalfAway(v * scale) / scale;
}

export function liuFloat(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'liu-float');
  const decimals = 1;
  const m = mirror(options.from, options.to);
  if (m.dims !== 3) throw new RangeError('liu-float takes 3 axes');
  const active = m.magnitude.map((v) => v === m.longest);
  const slope = m.magnitude.map((v) => roundDecimals(v / m.longest, decimals));
  // Eq. (14)-(15): epsilon(y_1) = k_yx - 0.5.
  const epsilon = slope.map((k) => roundDecimals(k - 0.5, decimals));
  const left = [...m.magnitude];
  let remaining = m.longest;
  const out = new Uint16Array(m.longest);
  for (let i = 0; i < out.length; i++) {
    let step = 0;
    for (let a = 0; a < 3; a++) {
      if (active[a]) {
        step |= m.unit[a]!;
        left[a]!--;
        continue;
      }
      const e = epsilon[a]!;
      const moves = guard(e >= 0, left[a]!, remaining);
      let next = e;
      if (moves) {
        step |= m.unit[a]!;
        left[a]!--;
        next -= 1;
      }
      epsilon[a] = roundDecimals(next + slope[a]!, decimals);
    }
    remaining--;
    out[i] = step;
  }
  return out;
}
