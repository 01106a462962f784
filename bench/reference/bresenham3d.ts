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
  const [minorA, minorB] = [0, 1, 2].filter((a) => a !== big) as [number, number];
  // Scalars rather than arrays of two, as in regions.ts: what V8 optimises
  // best, so the wasm/TS ratio compares the core with a tight loop.
  const [twoA, twoB] = [2 * m.magnitude[minorA]!, 2 * m.magnitude[minorB]!];
  const [codeA, codeB] = [m.unit[minorA]!, m.unit[minorB]!];
  const codeMajor = m.unit[big]!;
  const threshold = m.longest;
  const drop = 2 * m.longest;
  let errorA = 0;
  let errorB = 0;
  const out = new Uint16Array(m.longest);
  for (let k = 0; k < out.length; k++) {
    let step = codeMajor;
    errorA += twoA;
    if (errorA > threshold) {
      step |= codeA;
      errorA -= drop;
    }
    errorB += twoB;
    if (errorB > threshold) {
      step |= codeB;
      errorB -= drop;
    }
    out[k] = step;
  }
  return out;
}
