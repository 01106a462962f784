/**
 * Saleem & Saleem (2004), section 5: the helix as a Bresenham line between
 * the arc's n_c steps (counted by a dry run of the circle) and the linear
 * axis's n_z, stepping only: rust/src/arc/helix.rs in plain TypeScript,
 * method saleem, ties held (the defaults).
 */
import { Circle, moveCodes, readArc } from './arc.js';
import { onlyOptions, stepCode, type ReferenceOptions } from './common.js';

export function helix(options: ReferenceOptions): Uint16Array {
  const { method, ...rest } = options;
  if (method !== undefined && method !== 'saleem') throw new RangeError('the helix reference is method saleem');
  onlyOptions(rest, ['center', 'dir', 'plane', 'turns'], 'helix');
  const arc = readArc(rest);
  const circle = new Circle(arc);
  const codes = moveCodes(arc);
  const nc = circle.count();
  const nz = Math.abs(arc.rise);
  const linearCode = stepCode(arc.axes[2], Math.sign(arc.rise));
  const arcMajor = nc >= nz;
  const [majorCount, minorCount] = arcMajor ? [nc, nz] : [nz, nc];
  let error = 0;
  const out = new Uint16Array(Math.max(nc, nz));
  for (let k = 0; k < out.length; k++) {
    error += 2 * minorCount;
    const minorSteps = error > majorCount;
    if (minorSteps) error -= 2 * majorCount;
    let step = 0;
    if (arcMajor || minorSteps) step = codes[circle.next()]!;
    if (!arcMajor || minorSteps) step |= linearCode;
    out[k] = step;
  }
  return out;
}
