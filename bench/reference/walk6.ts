/**
 * The 6-connected walk along the line, stepping only: rust/src/line/walk6.rs
 * in plain TypeScript (ties to the lower axis, the default). The segment
 * between the two cell centers crosses one cell face per step; each step
 * goes through the face it reaches first, at fraction (2c + 1) / (2|Δ|)
 * for an axis that has crossed c faces, compared exactly by
 * cross-multiplication.
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function walk6(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'walk6');
  const m = mirror(options.from, options.to);
  const crossed = new Array<number>(m.dims).fill(0);
  const total = m.magnitude.reduce((s, v) => s + v, 0);
  const out = new Uint16Array(total);
  for (let k = 0; k < total; k++) {
    let first = -1;
    let firstNum = 0;
    let firstDen = 1;
    for (let a = 0; a < m.dims; a++) {
      const den = 2 * m.magnitude[a]!;
      if (crossed[a]! * 2 >= den) continue;
      const num = 2 * crossed[a]! + 1;
      if (first < 0 || num * firstDen < firstNum * den) {
        first = a;
        firstNum = num;
        firstDen = den;
      }
    }
    crossed[first]!++;
    out[k] = m.unit[first]!;
  }
  return out;
}
