/**
 * Saleem & Saleem (2004), section 4: the integer circle, stepping only:
 * rust/src/arc/circle_saleem.rs in plain TypeScript (any plane, either
 * direction, extra turns), counted first by a step-by-step dry run, the
 * paper's dummy procedure (the core skips it when a bound shows the circle
 * fits maxSteps, and counts by leaps along the closed form when it runs it).
 */
import { Circle, moveCodes, readArc } from './arc.js';
import { onlyOptions, type ReferenceOptions } from './common.js';

export function circle(options: ReferenceOptions): Uint16Array {
  onlyOptions(options, ['center', 'dir', 'plane', 'turns'], 'circle');
  const arc = readArc(options);
  if (arc.rise !== 0) throw new RangeError('circle: from and to differ on the normal axis');
  const stepper = new Circle(arc);
  const codes = moveCodes(arc);
  const out = new Uint16Array(stepper.count());
  for (let k = 0; k < out.length; k++) out[k] = codes[stepper.next()]!;
  return out;
}
