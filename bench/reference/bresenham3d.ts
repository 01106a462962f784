/**
 * Saleem & Saleem (2004), section 3: the 3D Bresenham line, stepping only:
 * rust/src/line/bresenham3d.rs in plain TypeScript, ties held (Saleem's
 * strict >, the core's default). The major axis steps every time; each
 * minor axis adds 2|Δminor| to its error and steps when the error exceeds
 * |Δmajor|, then drops by 2|Δmajor|.
 */
import { major, mirror, onlyOptions, type ReferenceOptions } from './common.js';

export function bresenham3d(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'bresenham3d');
  const m = mirror(options.from, options.to);
  if (m.dims !== 3) throw new RangeError('bresenham3d takes 3 axes');
  const big = major(m);
  const minors = [0, 1, 2].filter((a) => a !== big);
  const twoMinor = minors.map((a) => 2 * m.magnitude[a]!);
  const code = minors.map((a) => m.unit[a]!);
  const threshold = m.longest;
  const drop = 2 * m.longest;
  const error = [0, 0];
  const out = new Uint16Array(m.longest);
  for (let k = 0; k < out.length; k++) {
    let step = m.unit[big]!;
    for (let i = 0; i < 2; i++) {
      error[i]! += twoMinor[i]!;
      if (error[i]! > threshold) {
        step |= code[i]!;
        error[i]! -= drop;
      }
    }
    out[k] = step;
  }
  return out;
}
