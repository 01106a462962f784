/**
 * Wang et al. (2020), section 3.4: one discriminant per passive axis, 2 to
 * 6 axes, stepping only: rust/src/line/nd.rs in plain TypeScript, ties
 * advance (the core's default).
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function nd(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'nd');
  const m = mirror(options.from, options.to);
  let active = 0;
  const passive: number[] = [];
  for (let a = 0; a < m.dims; a++) {
    if (m.magnitude[a] === m.longest) active |= m.unit[a]!;
    else passive.push(a);
  }
  const code = passive.map((a) => m.unit[a]!);
  const increment = passive.map((a) => 2 * m.magnitude[a]!);
  // Eq. (17): H_1 = 2ΔA - Δx.
  const discriminant = increment.map((inc) => inc - m.longest);
  const decrement = 2 * m.longest;
  const out = new Uint16Array(m.longest);
  for (let k = 0; k < out.length; k++) {
    let step = active;
    for (let i = 0; i < passive.length; i++) {
      if (discriminant[i]! >= 0) {
        step |= code[i]!;
        discriminant[i]! += increment[i]! - decrement;
      } else {
        discriminant[i]! += increment[i]!;
      }
    }
    out[k] = step;
  }
  return out;
}
