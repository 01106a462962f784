/**
 * Wang et al. (2020), method of discriminate regions, stepping only:
 * rust/src/line/regions_wang.rs in plain TypeScript, ties advance (the
 * core's default). The active axes step every time; each passive axis
 * steps when its discriminant (eq. 10 start, eq. 8 recurrence) is >= 0.
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function regions(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'regions');
  const m = mirror(options.from, options.to);
  if (m.dims !== 3) throw new RangeError('regions takes 3 axes');
  let active = 0;
  const passive: number[] = [];
  for (let a = 0; a < 3; a++) {
    if (m.magnitude[a] === m.longest) active |= m.unit[a]!;
    else passive.push(a);
  }
  // Two discriminant slots; an absent passive axis never steps.
  const code = passive.map((a) => m.unit[a]!);
  const increment = passive.map((a) => 2 * m.magnitude[a]!);
  const decrement = 2 * m.longest;
  let M = passive.length > 0 ? increment[0]! - m.longest : -1;
  let N = passive.length > 1 ? increment[1]! - m.longest : -1;
  const [codeM, codeN] = [code[0] ?? 0, code[1] ?? 0];
  const [incM, incN] = [increment[0] ?? 0, increment[1] ?? 0];
  const out = new Uint16Array(m.longest);
  for (let k = 0; k < out.length; k++) {
    let step = active;
    if (M >= 0) {
      step |= codeM;
      M += incM - decrement;
    } else {
      M += incM;
    }
    if (N >= 0) {
      step |= codeN;
      N += incN - decrement;
    } else {
      N += incN;
    }
    out[k] = step;
  }
  return out;
}
