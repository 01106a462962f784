/**
 * Saleem & Saleem (2004), section 2: Bresenham's line in the plane, all
 * eight octants, stepping only: rust/src/line/bresenham2d.rs in plain
 * TypeScript with its defaults (variant corrected, ties held). The major
 * axis steps every time; the minor axis's error grows by 2|Δminor| and the
 * axis steps when the error exceeds |Δmajor|, then drops by 2|Δmajor|.
 */
import { mirror, onlyOptions, type ReferenceOptions } from './common.js';

/** Saleem Fig. 1: octant of a direction, counter-clockwise from +x (rust/src/line/bresenham2d.rs). */
function octant(dx: number, dy: number): number {
  if (dx === 0 && dy === 0) return 0;
  if (dy >= 0 && dy < dx) return 1;
  if (dx > 0 && dy >= dx) return 2;
  if (dx <= 0 && dy > -dx) return 3;
  if (dy > 0) return 4;
  if (-dy < -dx) return 5;
  if (dx < 0) return 6;
  if (dx < -dy) return 7;
  return 8;
}

export function bresenham2d(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, [], 'bresenham2d');
  const { from, to } = options;
  const m = mirror(from, to);
  if (m.dims !== 2) throw new RangeError('bresenham2d takes 2 axes');
  const k = octant(to[0]! - from[0]!, to[1]! - from[1]!);
  const big = [2, 3, 6, 7].includes(k) ? 1 : 0;
  const [majorLength, minorLength] = [m.magnitude[big]!, m.magnitude[1 - big]!];
  const [majorCode, minorCode] = [m.unit[big]!, m.unit[1 - big]!];
  let error = 0;
  const out = new Uint16Array(majorLength);
  for (let i = 0; i < out.length; i++) {
    error += 2 * minorLength;
    let step = majorCode;
    if (error > majorLength) {
      step |= minorCode;
      error -= 2 * majorLength;
    }
    out[i] = step;
  }
  return out;
}
